#!/usr/bin/env python3
"""Builds the Voronoi diagram of data/example-300.ell (300 ellipses, 30 of them
hidden inside others), draws it with matplotlib and prints its statistics.

    make python
    PYTHONPATH=build/python /usr/bin/python3 examples/plot_example.py [OUT.png]

The figure (default docs/example-300.png) is the one README.md shows.
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import ellvor  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "example-300.png"
    d = ellvor.build(ROOT / "data" / "example-300.ell")
    problem = d.validate()
    print(d)
    print("valid" if not problem else "INVALID: " + problem)
    print(f"Voronoi vertices: {len(d.faces)}, largest certified error {d.vertex_errors.max():.2g}")
    print("predicate calls (decided by filter / subdivision / exact):")
    for name, row in d.stats["predicates"].items():
        print(f"  {name}: {row['calls']} ({row['filter']} / {row['subdivision']} / {row['exact']})")

    fig, ax = plt.subplots(figsize=(8, 8), dpi=100)
    ellvor.plot(d, ax=ax, show_vertices=True, point_size=2, line_width=0.8)
    ax.set_title(f"Voronoi diagram of {len(d)} ellipses ({len(d.hidden)} hidden, dashed)")
    fig.tight_layout()
    fig.savefig(out)
    print(f"figure written to {out}")


if __name__ == "__main__":
    main()
