#!/usr/bin/env python3
"""Plots a platefall run and a sweep with pandas and matplotlib.

    python plot_run.py --csv RUN.csv --summary RUN.json [--results SWEEP/results.csv] [--out DIR]

Writes into DIR (default: the current directory):
- coefficients.png: C_L, C_D and C_M against convective time, the developed window of the
  summary shaded; coefficients.csv beside it holds the plotted series (time, C_L, C_D, C_M);
- trajectory.png: the centre's path (X, Y), equal axes;
- phase.png (with --results): the sweep's cases over its two swept options (the columns between
  `id` and `status` of results.csv), coloured by --value (default mean_cl), marked by regime;
  phase.csv beside it holds the plotted points.
"""
import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402


def load_run(csv_path, summary_path):
    """The run's steps (the CSV's trailer line is a comment) and its summary."""
    steps = pd.read_csv(csv_path, comment="#")
    with open(summary_path) as f:
        summary = json.load(f)
    return steps, summary


def plot_coefficients(steps, summary, out):
    series = steps[["time", "C_L", "C_D", "C_M"]]
    fig, ax = plt.subplots(figsize=(8, 4))
    for name in ["C_L", "C_D", "C_M"]:
        ax.plot(series["time"], series[name], label=name, lw=0.8)
    lo, hi = summary.get("developed_from"), summary.get("developed_to")
    if lo is not None and hi is not None:
        ax.axvspan(lo, hi, color="0.9", label="developed", zorder=0)
    ax.set_xlabel("t U/c")
    ax.set_ylabel("coefficient")
    ax.set_title(f"{summary['case']}, Re {summary['re']:.0f}, N = {summary['resolution']}")
    ax.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(out / "coefficients.png", dpi=120)
    plt.close(fig)
    series.to_csv(out / "coefficients.csv", index=False, float_format="%.17g")


def plot_trajectory(steps, out):
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.plot(steps["X"], steps["Y"], lw=1)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("X / c")
    ax.set_ylabel("Y / c")
    fig.tight_layout()
    fig.savefig(out / "trajectory.png", dpi=120)
    plt.close(fig)


def plot_phase(results_path, value, out):
    results = pd.read_csv(results_path)
    cols = list(results.columns)
    swept = cols[cols.index("id") + 1: cols.index("status")]
    if not swept:
        raise SystemExit(f"{results_path}: no swept columns between id and status")
    x, y = swept[0], swept[1] if len(swept) > 1 else None
    points = results[[c for c in ["id", x, y, "status", "regime", value] if c and c in cols]]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ys = points[y] if y else pd.Series(0.0, index=points.index)
    markers = {"steady": "o", "fluttering": "s", "tumbling": "^", "chaotic": "x"}
    regimes = points["regime"] if "regime" in points else pd.Series("", index=points.index)
    for regime, group in points.groupby(regimes.astype(object).fillna("")):
        sc = ax.scatter(group[x], ys[group.index], c=group.get(value), cmap="viridis",
                        marker=markers.get(regime, "D"), label=regime or "?", s=60)
    if value in points:
        fig.colorbar(sc, ax=ax, label=value)
    ax.set_xlabel(x)
    ax.set_ylabel(y or "")
    if (regimes.astype(object).fillna("") != "").any():
        ax.legend(title="regime", fontsize="small")
    fig.tight_layout()
    fig.savefig(out / "phase.png", dpi=120)
    plt.close(fig)
    points.to_csv(out / "phase.csv", index=False)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--csv", required=True, help="a run's --csv file")
    ap.add_argument("--summary", required=True, help="the run's --summary JSON")
    ap.add_argument("--results", help="a sweep's results.csv")
    ap.add_argument("--value", default="mean_cl", help="the summary key that colours the phase diagram")
    ap.add_argument("--out", default=".", help="directory of the figures")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    steps, summary = load_run(args.csv, args.summary)
    plot_coefficients(steps, summary, out)
    plot_trajectory(steps, out)
    if args.results:
        plot_phase(args.results, args.value, out)
    print(f"plot_run: figures in {out}")


if __name__ == "__main__":
    main()
