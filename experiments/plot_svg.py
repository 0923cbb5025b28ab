#!/usr/bin/env python3
"""Turns a CSV into an SVG line chart with logarithmic axes (standard library only).

One line per value of the --series column, x and y from the --x and --y columns;
optional extra point sets (drawn as unconnected markers), e.g. a paper's row:

    python3 experiments/plot_svg.py experiments/results/precision_vs_time.csv \\
        experiments/results/precision_vs_time.svg \\
        --points "paper (Table 1)" 53:0.20,900:0.58,2000:1.06,12000:10.65,24000:31.61

Rows whose x or y is not a positive number are skipped (a log axis cannot show them).
"""
import argparse
import csv
import math
import sys
from xml.sax.saxutils import escape

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf", "#7f7f7f"]


def parse_points(spec):
    pts = []
    for item in spec.split(","):
        x, y = item.split(":")
        pts.append((float(x), float(y)))
    return pts


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("svg")
    ap.add_argument("--x", default="bits")
    ap.add_argument("--y", default="seconds")
    ap.add_argument("--series", default="triple")
    ap.add_argument("--title", default="Certified Voronoi circle: time vs precision")
    ap.add_argument("--xlabel", default="b (correct bits)")
    ap.add_argument("--ylabel", default="wall time (s)")
    ap.add_argument("--points", nargs=2, action="append", metavar=("LABEL", "X:Y,..."), default=[])
    args = ap.parse_args()

    series = {}
    with open(args.csv, newline="") as f:
        for row in csv.DictReader(f):
            try:
                x, y = float(row[args.x]), float(row[args.y])
            except (KeyError, ValueError):
                continue
            if x > 0 and y > 0:
                series.setdefault(row[args.series], []).append((x, y))
    points = [(label, parse_points(spec)) for label, spec in args.points]
    allpts = [p for s in series.values() for p in s] + [p for _, s in points for p in s]
    if not allpts:
        sys.exit("plot_svg.py: nothing to plot")

    lx = [math.log10(p[0]) for p in allpts]
    ly = [math.log10(p[1]) for p in allpts]
    x0, x1 = math.floor(min(lx)), math.ceil(max(lx))
    y0, y1 = math.floor(min(ly)), math.ceil(max(ly))
    if x0 == x1:
        x1 += 1
    if y0 == y1:
        y1 += 1

    W, H = 760, 500
    left, right, top, bottom = 80, 190, 40, 60
    pw, ph = W - left - right, H - top - bottom

    def sx(x):
        return left + (math.log10(x) - x0) / (x1 - x0) * pw

    def sy(y):
        return top + ph - (math.log10(y) - y0) / (y1 - y0) * ph

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" '
           'font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{left + pw / 2}" y="22" text-anchor="middle" font-size="15">{escape(args.title)}</text>']
    # grid: decades (solid) and 2..9 (faint)
    for k in range(x0, x1 + 1):
        X = sx(10 ** k)
        out.append(f'<line x1="{X:.1f}" y1="{top}" x2="{X:.1f}" y2="{top + ph}" stroke="#ccc"/>')
        out.append(f'<text x="{X:.1f}" y="{top + ph + 18}" text-anchor="middle">10<tspan dy="-6" font-size="9">{k}'
                   '</tspan></text>')
        if k < x1:
            for m in range(2, 10):
                X = sx(m * 10 ** k)
                out.append(f'<line x1="{X:.1f}" y1="{top}" x2="{X:.1f}" y2="{top + ph}" stroke="#eee"/>')
    for k in range(y0, y1 + 1):
        Y = sy(10 ** k)
        out.append(f'<line x1="{left}" y1="{Y:.1f}" x2="{left + pw}" y2="{Y:.1f}" stroke="#ccc"/>')
        out.append(f'<text x="{left - 8}" y="{Y + 4:.1f}" text-anchor="end">10<tspan dy="-6" font-size="9">{k}'
                   '</tspan></text>')
        if k < y1:
            for m in range(2, 10):
                Y = sy(m * 10 ** k)
                out.append(f'<line x1="{left}" y1="{Y:.1f}" x2="{left + pw}" y2="{Y:.1f}" stroke="#eee"/>')
    out.append(f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="black"/>')
    out.append(f'<text x="{left + pw / 2}" y="{H - 15}" text-anchor="middle">{escape(args.xlabel)}</text>')
    out.append(f'<text x="20" y="{top + ph / 2}" text-anchor="middle" '
               f'transform="rotate(-90 20 {top + ph / 2})">{escape(args.ylabel)}</text>')

    legend_y = top + 10
    for i, (name, pts) in enumerate(series.items()):
        color = COLORS[i % len(COLORS)]
        pts = sorted(pts)
        path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in pts)
        out.append(f'<polyline points="{path}" fill="none" stroke="{color}" stroke-width="2"/>')
        for x, y in pts:
            out.append(f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="3" fill="{color}"/>')
        lx0 = left + pw + 15
        out.append(f'<line x1="{lx0}" y1="{legend_y}" x2="{lx0 + 25}" y2="{legend_y}" stroke="{color}" '
                   'stroke-width="2"/>')
        out.append(f'<text x="{lx0 + 32}" y="{legend_y + 4}">{escape(name)}</text>')
        legend_y += 20
    for j, (label, pts) in enumerate(points):
        color = "black" if j == 0 else COLORS[(len(series) + j) % len(COLORS)]
        for x, y in pts:
            X, Y = sx(x), sy(y)
            out.append(f'<rect x="{X - 5:.1f}" y="{Y - 5:.1f}" width="10" height="10" fill="none" '
                       f'stroke="{color}" stroke-width="2"/>')
        lx0 = left + pw + 15
        out.append(f'<rect x="{lx0 + 7}" y="{legend_y - 5}" width="10" height="10" fill="none" stroke="{color}" '
                   'stroke-width="2"/>')
        out.append(f'<text x="{lx0 + 32}" y="{legend_y + 4}">{escape(label)}</text>')
        legend_y += 20
    out.append("</svg>")
    with open(args.svg, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
