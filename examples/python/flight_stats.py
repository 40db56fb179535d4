#!/usr/bin/env python3
"""Counts a free fall's half-turns and measures its descent over a time window, from its CSV.

    python flight_stats.py --csv RUN.csv [--summary RUN.json] [--from T0] [--to T1]

A half-turn is the plate passing from one horizontal attitude (θ = kπ) to the next ((k ± 1)π),
counted from the horizontal attitude nearest θ at T0; a swing about horizontal that comes back is
not one. A reversal is a half-turn in the other sense
from the one before it. Prints, over T0 ≤ t ≤ T1 (default: the whole run):
- half-turns, how many of them reversed, and when each ended (+ for θ increasing);
- net turns, (θ(T1) − θ(T0)) / 2π;
- the mean descent and horizontal speeds, the displacement over the window's length, in units of U
  and, with --summary (its `velocity_scale_m_s`), in cm/s.
These are the figures of the falling-plate table in docs/validation.md.
"""
import argparse
import json
import math

import pandas as pd


def window(csv_path, t0, t1):
    """The run's rows with t0 ≤ time ≤ t1 (the CSV's trailer line is a comment)."""
    steps = pd.read_csv(csv_path, comment="#", usecols=["time", "X", "Y", "theta"])
    inside = (steps["time"] >= t0) & (steps["time"] <= t1)
    rows = steps[inside]
    if len(rows) < 2:
        raise SystemExit(f"{csv_path}: fewer than two rows between t = {t0} and {t1}")
    return rows


def half_turns(time, theta):
    """The half-turns as (end time, sense) pairs and the number of reversals among them."""
    level = round(theta[0] / math.pi)
    turns, reversals = [], 0
    for t, th in zip(time, theta):
        for sense in (1, -1):
            while sense * (th - (level + sense) * math.pi) >= 0:
                if turns and turns[-1][1] != sense:
                    reversals += 1
                turns.append((t, sense))
                level += sense
    return turns, reversals


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--csv", required=True, help="the run's CSV (platefall free --csv)")
    p.add_argument("--summary", help="the run's summary (--summary), for speeds in cm/s")
    p.add_argument("--from", dest="t0", type=float, default=0.0, help="window start, c/U")
    p.add_argument("--to", dest="t1", type=float, default=math.inf, help="window end, c/U")
    args = p.parse_args()

    rows = window(args.csv, args.t0, args.t1)
    time, theta = rows["time"].to_numpy(), rows["theta"].to_numpy()
    turns, reversals = half_turns(time, theta)
    span = time[-1] - time[0]
    descent = -(rows["Y"].iloc[-1] - rows["Y"].iloc[0]) / span
    drift = (rows["X"].iloc[-1] - rows["X"].iloc[0]) / span

    print(f"window: t = {time[0]:.2f} to {time[-1]:.2f}")
    print(f"half-turns: {len(turns)} ({reversals} reversed)")
    if turns:
        print("  ended at: " + " ".join(f"{t:.1f}{'+' if s > 0 else '-'}" for t, s in turns))
    print(f"net turns: {(theta[-1] - theta[0]) / (2 * math.pi):+.2f}")
    scale = None
    if args.summary:
        with open(args.summary) as f:
            scale = json.load(f).get("velocity_scale_m_s")
    for name, value in (("descent speed", descent), ("horizontal speed", drift)):
        physical = f" ({value * scale * 100:.2f} cm/s)" if scale else ""
        print(f"mean {name}: {value:.4f} U{physical}")


if __name__ == "__main__":
    main()
