#!/usr/bin/env python3
"""Checks flight_stats.py on a motion whose half-turns are known.

Usage: check-flight-stats.py SCRIPT WORKDIR

θ(t) flutters about horizontal (±0.5 rad, no half-turn) until t = 4, rises to 3.5π by t = 10
(three half-turns: through π, 2π, 3π), and falls back to 1.5π by t = 13 (one reversed half-turn,
through 2π; it does not reach π again). The centre moves at X = 0.2 t, Y = −0.5 t. Expected: 4
half-turns, 1 reversed, net turns +0.75, descent 0.5 U, horizontal 0.2 U; from t = 7 (θ = 1.75π),
counted from the horizontal attitude nearest it (2π), 2 half-turns (to 3π, back to 2π), 1 reversed. Exits 1 on a mismatch.
"""
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd

KNOTS = [(0, 0), (1, 0.5), (2, -0.5), (3, 0.5), (4, 0), (10, 3.5 * math.pi), (13, 1.5 * math.pi)]


def run(script, csv, *extra):
    out = subprocess.run(
        [sys.executable, script, "--csv", str(csv), *extra], check=True, capture_output=True, text=True
    ).stdout
    turns = re.search(r"half-turns: (\d+) \((\d+) reversed\)", out)
    net = re.search(r"net turns: ([-+.\d]+)", out)
    descent = re.search(r"mean descent speed: ([-.\d]+) U", out)
    drift = re.search(r"mean horizontal speed: ([-.\d]+) U", out)
    return int(turns[1]), int(turns[2]), float(net[1]), float(descent[1]), float(drift[1])


def main(script, workdir):
    t = np.linspace(0.0, 13.0, 13001)
    kt, kth = zip(*KNOTS)
    theta = np.interp(t, kt, kth)
    csv = Path(workdir) / "flight.csv"
    pd.DataFrame({"time": t, "X": 0.2 * t, "Y": -0.5 * t, "theta": theta}).to_csv(csv, index=False)
    with open(csv, "a") as f:
        f.write("# platefall: status=completed\n")
    bad = []
    got = run(script, csv)
    if got[:2] != (4, 1) or abs(got[2] - 0.75) > 1e-3 or abs(got[3] - 0.5) > 1e-4 or abs(got[4] - 0.2) > 1e-4:
        bad.append(f"whole run: {got}, expected (4, 1, 0.75, 0.5, 0.2)")
    got = run(script, csv, "--from", "7")
    if got[:2] != (2, 1):
        bad.append(f"from t = 7: {got[:2]} half-turns (reversed), expected (2, 1)")
    for b in bad:
        print(b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
