#!/usr/bin/env python3
"""Reads a platefall recording's time series through the Rerun SDK (rerun-sdk 0.36.3).

    python read_recording.py RUN.rrd [--out DIR]

Rerun 0.36 queries recordings through a local server and its catalog (the dataframe API of
earlier versions, `rr.dataframe.load_recording`, is gone): the .rrd becomes a dataset, the
coefficient and motion entities are selected with a content filter, and the reader gives one
row per solver step (the `step` timeline) as a pandas frame. Writes into DIR (default: the
current directory) recording_series.csv (step, time, C_L, C_D, C_M, V, dθ/dt) and
recording_series.png (C_L and dθ/dt against time), and prints the number of steps.
"""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402
import rerun as rr  # noqa: E402

# The recording's entities (platefall's entity layout, crates/platefall-record/src/lib.rs).
SERIES = {
    "C_L": "/coefficients/cl",
    "C_D": "/coefficients/cd",
    "C_M": "/coefficients/cm",
    "V": "/motion/speed",
    "thetadot": "/motion/omega",
}


def load_series(rrd):
    """One row per step: the step, the convective time (seconds of the `time` timeline) and
    each series of SERIES."""
    with rr.server.Server(datasets={"run": [str(rrd)]}) as server:
        dataset = server.client().get_dataset("run")
        view = dataset.filter_contents(["/coefficients/**", "/motion/**"])
        frame = view.reader(index="step").to_pandas()
    out = pd.DataFrame({"step": frame["step"].astype("int64")})
    if "time" in frame:
        out["time"] = pd.to_timedelta(frame["time"]).dt.total_seconds()
    for name, entity in SERIES.items():
        column = frame[f"{entity}:Scalars:scalars"]
        out[name] = column.map(lambda v: float(v[0]) if v is not None and len(v) else float("nan"))
    return out.sort_values("step").reset_index(drop=True)


def plot(series, out):
    x = series["time"] if "time" in series else series["step"]
    fig, (a, b) = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
    a.plot(x, series["C_L"], lw=0.8)
    a.set_ylabel("C_L")
    b.plot(x, series["thetadot"], lw=0.8, color="C3")
    b.set_ylabel("dθ/dt")
    b.set_xlabel("t U/c" if "time" in series else "step")
    fig.suptitle("read back from the .rrd")
    fig.tight_layout()
    fig.savefig(out / "recording_series.png", dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rrd", help="a platefall recording (.rrd)")
    ap.add_argument("--out", default=".", help="directory of the outputs")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    series = load_series(args.rrd)
    series.to_csv(out / "recording_series.csv", index=False, float_format="%.17g")
    plot(series, out)
    print(f"read_recording: {len(series)} steps from {args.rrd}")


if __name__ == "__main__":
    main()
