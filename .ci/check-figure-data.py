#!/usr/bin/env python3
"""Checks that the examples' figures plot the run's own numbers.

Usage: check-figure-data.py RUN.csv coefficients.csv [recording_series.csv]

coefficients.csv (plot_run.py) must hold the run CSV's time, C_L, C_D and C_M row for row;
recording_series.csv (read_recording.py, read back from the .rrd) the same C_L, C_D, C_M and
dθ/dt per step. Both to 1e-12 (the files carry 17 significant digits). Exits 1 on a mismatch.
"""
import sys

import numpy as np
import pandas as pd


def compare(run, other, columns, key, label):
    merged = run.merge(other, on=key, suffixes=("", "_fig"))
    if len(merged) != len(run) or len(other) != len(run):
        return [f"{label}: {len(other)} rows, the run has {len(run)}"]
    bad = []
    for c in columns:
        err = np.abs(merged[c] - merged[f"{c}_fig"]).max()
        if not err <= 1e-12:
            bad.append(f"{label}: {c} differs from the run's CSV by {err:.3g}")
    return bad


def main(argv):
    if len(argv) < 3:
        raise SystemExit(__doc__)
    run = pd.read_csv(argv[1], comment="#")
    failures = compare(run, pd.read_csv(argv[2]), ["C_L", "C_D", "C_M"], "time", argv[2])
    if len(argv) > 3:
        rec = pd.read_csv(argv[3]).drop(columns=["time"], errors="ignore")
        failures += compare(run, rec, ["C_L", "C_D", "C_M", "thetadot"], "step", argv[3])
    for f in failures:
        print(f"check-figure-data: {f}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
