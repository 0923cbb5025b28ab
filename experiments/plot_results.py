#!/usr/bin/env python3
"""Draws the charts of experiments/results/ from their CSV files with matplotlib.

    /usr/bin/python3 experiments/plot_results.py [--dir DIR] [NAME ...]

NAME is one of the charts below (default: all of them); each reads DIR/NAME.csv
(DIR defaults to experiments/results) and writes DIR/NAME.png: time against a
size on logarithmic axes, one line per series, the paper's figures (Emiris,
Tsigaridas and Tzoumas 2007, Table 1) as squares. Rows whose x or y is not a
positive number are left out (a logarithmic axis cannot show them). The
benchmark programs run it after writing their CSV.
"""
import argparse
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RESULTS = pathlib.Path(__file__).resolve().parent / "results"

# name: (x column, y column, series column, title, x label, y label, (label, [(x, y), ...]) of the paper)
CHARTS = {
    "build_scaling": ("n", "cpu_seconds", "set", "Delaunay graph build time", "n (sites)", "CPU time (s)",
                      ("paper (Table 1, insertion)", [(5, 0.752), (10, 5.916), (15, 13.0), (20, 19.2), (25, 25.602)])),
    "precision_vs_time": ("bits", "seconds", "triple", "Certified Voronoi circle: time vs precision",
                          "b (correct bits)", "wall time (s)",
                          ("paper (Table 1, s)", [(53, 0.20), (900, 0.58), (2000, 1.06), (12000, 10.65),
                                                  (24000, 31.61)])),
    "degeneracy_stress": ("e", "seconds", "series", "Degenerate InCircle inputs: time vs perturbation 10^-e",
                          "e (perturbation 10^-e)", "wall time (s)",
                          ("paper Table 1 (resultant)", [(4, 25.12), (8, 57.24), (12, 102.63), (16, 160.44),
                                                         (20, 231.19)])),
}


def read_series(path, x, y, series):
    lines = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            try:
                vx, vy = float(row[x]), float(row[y])
            except (KeyError, ValueError):
                continue
            if vx > 0 and vy > 0:
                lines.setdefault(row[series], []).append((vx, vy))
    return {name: sorted(points) for name, points in lines.items()}


def draw(name, folder):
    x, y, series, title, xlabel, ylabel, (paper_label, paper) = CHARTS[name]
    lines = read_series(folder / f"{name}.csv", x, y, series)
    if not lines:
        sys.exit(f"plot_results.py: nothing to plot in {folder / name}.csv")
    fig, ax = plt.subplots(figsize=(8, 5), dpi=100)
    # More series than the default cycle's ten colours: twenty.
    colors = plt.get_cmap("tab20" if len(lines) > 10 else "tab10").colors
    for k, (label, points) in enumerate(lines.items()):
        ax.plot(*zip(*points), marker="o", markersize=3, linewidth=1.5, color=colors[k % len(colors)], label=label)
    ax.plot(*zip(*paper), linestyle="none", marker="s", markersize=8, markerfacecolor="none",
            markeredgecolor="black", markeredgewidth=1.5, label=paper_label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.grid(True, which="major", color="0.8")
    ax.grid(True, which="minor", color="0.93")
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8, frameon=False)
    fig.tight_layout()
    out = folder / f"{name}.png"
    fig.savefig(out)
    plt.close(fig)
    print(f"wrote {out}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dir", type=pathlib.Path, default=RESULTS, help="folder of the CSV files and charts")
    ap.add_argument("names", nargs="*", metavar="NAME", help="one of " + ", ".join(CHARTS))
    args = ap.parse_args()
    for name in args.names:
        if name not in CHARTS:
            ap.error(f"unknown chart '{name}': expected one of " + ", ".join(CHARTS))
    for name in args.names or CHARTS:
        draw(name, args.dir)


if __name__ == "__main__":
    main()
