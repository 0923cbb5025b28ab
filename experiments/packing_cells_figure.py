#!/usr/bin/env python3
"""The README's figure: a dense packing's certified cells in its box, coloured by
local packing fraction (site area / cell area, the midpoint of its interval).

    make build/ellvor python
    PYTHONPATH=build/python /usr/bin/python3 experiments/packing_cells_figure.py [--out docs/packing_cells.png]

About two minutes of CPU (40 cells with their rings). Prints the sum of the
area intervals, which must contain the box's area, 49."""

import argparse
import pathlib
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import ellvor  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
COMMAND = ["generate", "packing", "--count", "40", "--packing-fraction", "0.55", "--seed", "2"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs" / "packing_cells.png"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "packing.ell"
        subprocess.run([str(ROOT / "build" / "ellvor"), *COMMAND, "-o", str(path)], check=True,
                       stdout=subprocess.DEVNULL)
        d = ellvor.build(str(path))
    side = 7  # generate packing's box: [0, ceil(sqrt(40))]^2
    c = d.cells(box=(0, 0, side, side))
    fig = ellvor.plot(d, cells=c, color="packing_fraction")
    ax = fig.axes[0]
    ax.set_xlim(0, side)
    ax.set_ylim(0, side)
    ax.set_title(f"ellvor {' '.join(COMMAND)}:\ncells in the box [0, {side}]² by local packing fraction")
    fig.savefig(args.out, dpi=110, bbox_inches="tight")
    print(f"areas add up to [{c.area_lo.sum()!r}, {c.area_hi.sum()!r}] (box {side * side}); wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
