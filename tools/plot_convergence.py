#!/usr/bin/env python3
"""Plots relMSE against wall time, log-log, from the CSV of `mvpl convergence`.

usage: plot_convergence.py CONVERGENCE.csv OUT.png [--title TEXT]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {"pt": "path tracer", "mc": "Monte Carlo VPLs", "metropolis": "Metropolis VPLs"}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    series = {}
    with open(args.csv, newline="") as f:
        for row in csv.DictReader(f):
            t, e = float(row["seconds"]), float(row["rel_mse"])
            if t > 0 and e > 0:
                series.setdefault(row["method"], []).append((t, e))
    if not series:
        print(f"plot_convergence: {args.csv}: no points", file=sys.stderr)
        return 1

    fig, ax = plt.subplots(figsize=(6, 4.2), dpi=120)
    for method, points in series.items():
        points.sort()
        ax.loglog([p[0] for p in points], [p[1] for p in points], marker="o", markersize=3,
                  label=LABELS.get(method, method))
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("relMSE against the reference")
    if args.title:
        ax.set_title(args.title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
