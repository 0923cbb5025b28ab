#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets: fuzz/corpus/parser/ and fuzz/corpus/build/.

Run from the repository root: python3 fuzz/make_corpus.py. The seeds are the
inputs the issue asks the fuzzers to start from: huge and tiny numbers, values
at and just over the 4096-bit cap, nearly touching, duplicate and
near-duplicate sites, degenerate placements (all on a line, all on a circle),
rotated and nested ellipses, CRLF, comments and blank lines, .cin lines, and
the repository's examples. The build seeds have at most 8 sites and 512 bytes
(the build target's caps); the parser gets all of them plus the long ones.
"""
import os
import shutil

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")

CAP = 2**4096 - 1   # the largest 4096-bit number
OVER = 2**4096      # 4097 bits: just over the cap

# Small files: seeds for both targets.
SMALL = {
    "two-circles.ell": "1 1 0 0 0\n1 1 0 3 0\n",
    "three-ellipses.ell": "2 1 0 0 0\n1 2 0 6 0\n3/2 1/2 1/3 3 5\n",
    "rotated.ell": "3 1 1/2 0 0\n2 1 -2 8 1\n1 3 0.25 0 7\n5/2 1 7 -7 2\n",
    "nested.ell": "10 6 0 0 0\n2 1 1/3 1 1\n1 1 0 -5 0\n3 3 0 20 0\n",
    "nested-deep.ell": "20 20 0 0 0\n10 5 1/2 0 0\n2 1 0 1 0\n1/2 1/4 0 1 0\n30 1 0 60 0\n",
    "collinear.ell": "".join(f"1 1 0 {3 * i} 0\n" for i in range(6)),
    "collinear-diagonal.ell": "".join(f"{1 + i % 2} {1 + i % 2} 0 {7 * i} {7 * i}\n" for i in range(6)),
    "collinear-ellipses.ell": "".join(f"2 1 0 {6 * i} 0\n" for i in range(5)),
    # Rational points on the circle of radius 10 (Pythagorean triples).
    "cocircular.ell": "".join(f"1 1 0 {x} {y}\n" for x, y in [(6, 8), (8, 6), (-6, 8), (10, 0), (0, -10), (-8, -6)]),
    "cocircular-four.ell": "1 1 0 10 0\n1 1 0 0 10\n1 1 0 -10 0\n1 1 0 0 -10\n",
    "touching.ell": "1 1 0 0 0\n1 1 0 2 0\n",
    # Crossing sites (signed distances: an internal Voronoi circle, three boundaries through a point,
    # crossing ellipses, a needle hidden by the union of two disks, four crossing ellipses with an
    # internal circle), and crossings that are rejected (boundaries meeting in 3 and 4 points).
    "crossing-circles.ell": "10 10 0 0 0\n10 10 0 12 0\n10 10 0 6 10\n3 3 0 6 4\n",
    "crossing-through-a-point.ell": "5 5 0 -5 0\n5 5 0 0 -5\n5 5 0 5 0\n5 5 0 0 5\n",
    "crossing-ellipse.ell": "2 1 0 0 0\n2 1 0 1 1\n1 1 0 5 5\n",
    "union-hidden-needle.ell": "10 1/10 0 0 0\n6 6 0 -5 0\n6 6 0 5 0\n2 1 0 20 3\n",
    # An internal circle centered exactly on the ellipse's medial axis, no symmetry (DESIGN §4.2).
    "medial-axis-center.ell": "5 3 1/3 7/3 -11/7\n4 4 0 2171/375 -507/875\n4 4 0 3763/975 3229/2275\n",
    "crossing-ellipses-internal.ell": "47/10 23/5 -47/50 91/5 116/5\n84/5 49/5 1/50 5 137/5\n"
    "92/5 10 -13/50 261/10 58/5\n3 63/10 -7/10 25/2 41/2\n",
    "meeting-in-three-points.ell": "1 1 0 0 0\n1 3/2 0 0 -1/2\n",
    "meeting-in-four-points.ell": "3 1 0 0 0\n1 3 0 0 0\n",
    "nearly-touching.ell": "1 1 0 0 0\n1 1 0 2." + "0" * 39 + "1 0\n",
    "nearly-touching-ellipses.ell": "2 1 0 0 0\n2 1 0 4.000000000000000000000000000000000000001 0\n1 1 0 2 5\n",
    "near-duplicate.ell": "1 1 0 0 0\n1.0000000001 1 0 0 0\n",
    "near-duplicate-shifted.ell": "2 1 0 0 0\n2 1 0 1e-40 0\n",
    "duplicate.ell": "1 2 0 0 0\n3 3 0 9 9\n1 2 0 0 0\n",
    "duplicate-point-set.ell": "2 1 0 5 5\n1 2 1 5 5\n",
    # Three or four sites, so that the build reaches faces and InCircle.
    "huge-center.ell": "1 1 0 0 0\n1 1 0 5 1\n1 1 0 1e300 3\n2 1 0 -7 2\n",
    "huge-axis.ell": "1e300 1 0 0 0\n1 1 0 0 1e301\n1 1 0 5 -1e301\n",
    "huge-axis-999.ell": "1 1 0 0 0\n1 1 0 5 1\n1e999 1 0 0 1e1000\n",
    "tiny-axis.ell": "1e-300 1 0 0 0\n1 1 0 5 0\n1 1 0 2 6\n",
    "tiny-circles.ell": "1e-300 1e-300 0 0 0\n1e-300 1e-300 0 1e-299 0\n1e-300 1e-300 0 0 3e-300\n",
    "translated-1e20.ell": "".join(f"{r} 1 {w} 1000000000000000000{x:02d} {y}\n"
                                   for r, w, x, y in [(1, 0, 0, 0), (1, 0, 5, 1), (1, 0, 2, 6), (2, "1/3", 3, -5)]),
    "just-over-cap.ell": "1 1 0 1e1234 0\n",
    "under-cap.ell": "1 1 0 1e1233 0\n",
    "exponent-huge.ell": "1 1 0 1e99999999 0\n",
    "crlf.ell": "# CRLF\r\n1 1 0 0 0\r\n\r\n1 1 0 4 0\r\n",
    "comments.ell": "# header\n\n   \n1 1 0 0 0 # first\n\t1/2\t1/2\t0\t5\t5\n#\n2 1 0 -5 0#no space\n",
    "blank-lines.ell": "\n\n\n1 1 0 0 0\n\n\n",
    "no-final-newline.ell": "1 1 0 0 0\n2 2 0 10 0",
    "empty.ell": "",
    "decimals.ell": "0.5 .5 0 5. -1.25e-3\n+3 2 -0 1E2 007\n",
    "fractions.ell": "3/4 10/6 -1/7 -100/3 22/7\n",
    "malformed.ell": "1 1.2.3 0 0 0\n0x10 1 0 0 0\nnan 1 0 0 0\n1 1 1/-2 0 0\n",
    "missing-field.ell": "1 1 0 0\n",
    "extra-field.ell": "1 1 0 0 0 9\n",
    "zero-axis.ell": "0 1 0 0 0\n",
    "nul.ell": "1 1 0 0 0\n1 1\0 0 0 0\n",
    "two-circles.cin": "0 0 1\n3 0 1\n",
    "cin-several.cin": "0 0 1\n5 0 2\n0 7 1/2\n-4 -4 1.5\n",
    "cin-nested.cin": "0 0 10\n1 1 1\n30 0 3\n",
    "cin-bad.cin": "1 2\n0 0 0\n",
}

# Nearly coincident crossing pairs (issue 21): a site and a copy moved by 10^-k, which cross in two
# points, among other sites; k from 10 to 100, translated, rotated and scaled copies, circles, the
# whole scene scaled by 10^+-30 or far from the origin, and a copy crossing a third site (an internal
# circle centred near the copy's medial axis).
ISSUE_OTHERS = "1 1 0 6 1\n1 1 0 -5 3\n3/2 1/2 1 1 -6\n"
NEAR_DUPLICATES = {
    **{f"near-copy-shift-1e-{k}.ell": f"2 1 1/3 0 0\n2 1 1/3 1e-{k} 0\n" + ISSUE_OTHERS for k in (10, 20, 30, 40, 60, 100)},
    "near-copy-shift-diagonal.ell": "2 1 1/3 0 0\n2 1 1/3 1e-40 -3e-40\n" + ISSUE_OTHERS,
    # w + 10^-30 (1 + w^2)/2, the center turned about (6, 0) to first order.
    "near-copy-rotated.ell": "2 1 1/3 0 0\n2 1 " + f"{3 * 10**30 + 5}/{9 * 10**30}" + " 0 -6e-30\n" + ISSUE_OTHERS,
    "near-copy-scaled-up.ell": "2 1 1/3 0 0\n2.000000000000000000000000000002 1.000000000000000000000000000001 1/3 "
    "-6e-30 0\n" + ISSUE_OTHERS,
    "near-copy-scaled-down.ell": "2 1 1/3 0 0\n1.999999999999999999999999999998 0.999999999999999999999999999999 1/3 "
    "6e-30 0\n" + ISSUE_OTHERS,
    "near-copy-circles.ell": "1 1 0 0 0\n1 1 0 1e-40 1e-40\n1 1 0 5 1\n2 1 0 -4 3\n1/2 1/2 0 0 -4\n",
    "near-copy-tiny-scene.ell": "2e-30 1e-30 1/3 0 0\n2e-30 1e-30 1/3 1e-70 0\n1e-30 1e-30 0 6e-30 1e-30\n"
    "1e-30 1e-30 0 -5e-30 3e-30\n",
    "near-copy-huge-scene.ell": "2e30 1e30 1/3 0 0\n2e30 1e30 1/3 1 0\n1e30 1e30 0 6e30 1e30\n1e30 1e30 0 -5e30 3e30\n",
    "near-copy-far.ell": "2 1 1/3 1e20 0\n2 1 1/3 100000000000000000000.00000000000000000001 0\n1 1 0 100000000000000000006 1\n"
    "1 1 0 99999999999999999995 3\n",
    "near-copy-crossing-third.ell": "345/127 10/37 -6/35 17909/230 11267/144\n2 363/161 -43/82 9731/121 2128/27\n"
    "345/127 10/37 -6/35 77.8652173913043478260869565217391304347826086956521739130434782608695652173913043478260869565217392 "
    "11267/144\n",
}

# Long files: the parser's seeds only (over the build target's 512 bytes).
LONG = {
    "cap-numerator.ell": f"1 1 0 {CAP} 0\n",
    "cap-denominator.ell": f"1/{CAP} 1 0 0 0\n",
    "cap-fraction.ell": f"{CAP}/{CAP - 2} 1 0 0 0\n",
    "over-cap-numerator.ell": f"1 1 0 {OVER} 0\n",
    "over-cap-denominator.ell": f"1 1/{OVER} 0 0 0\n",
    "cap-after-reduction.ell": f"1 1 0 {2 * CAP}/2 0\n",  # 4097 bits written, 4096 read
    "long-token.ell": "1 1 0 0 " + "1" * 4100 + "\n",
    "long-decimal.ell": "1 1 0 0 0." + "0" * 1300 + "1\n",
}


def write(directory, name, text):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, name), "w", newline="") as f:
        f.write(text)


def main():
    for sub in ("parser", "build"):
        shutil.rmtree(os.path.join(ROOT, sub), ignore_errors=True)
    parser, build = os.path.join(ROOT, "parser"), os.path.join(ROOT, "build")
    for name, text in SMALL.items():
        write(parser, name, text)
        if name.endswith(".ell"):
            write(build, name, text)
    for name, text in NEAR_DUPLICATES.items():
        assert len(text.encode()) <= 512, name
        write(parser, name, text)
        write(build, name, text)
    for name, text in LONG.items():
        write(parser, name, text)
    data = os.path.join(os.path.dirname(ROOT), "..", "data")
    for name in ("example.ell", "example-300.ell"):
        shutil.copyfile(os.path.join(data, name), os.path.join(parser, name))
    # The first 8 sites of the example (no comments): within the build caps.
    with open(os.path.join(data, "example.ell")) as f:
        sites = [line.split("#")[0].strip() for line in f]
    write(build, "example-first8.ell", "".join(s + "\n" for s in [s for s in sites if s][:8]))


if __name__ == "__main__":
    main()
