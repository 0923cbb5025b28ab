"""ellvor.distributed: the Delaunay graph built in tiles on dask.distributed.

    import ellvor.distributed
    d = ellvor.distributed.build("big.ell", tiles=(4, 4))            # a LocalCluster, one worker per core
    d = ellvor.distributed.build(sites, client="tcp://host:8786")    # a running scheduler
    d.edges, d.faces, d.hidden, d.hull                                 # as ellvor.build(sites) gives them
    d.tiles                                                            # per tile: sites, halo, faces kept, ...
    for path, d in ellvor.distributed.map(snapshots):                  # one whole diagram per file, as they finish
        ...
    c = ellvor.distributed.cells(sites, box=(0, 0, 100, 100))         # the Cells of ellvor.build(sites).cells(...)
    with ellvor.distributed.local_cluster(2) as cluster, Client(cluster) as client:   # Client of distributed
        d = ellvor.distributed.build(sites, client=client)             # one cluster for many calls

Each tile builds the diagram of the sites near it (its own and a halo) and keeps
only the faces it can prove are faces of the whole diagram; the seam argument,
the ownership and the retry rules are in docs/DESIGN.md §8 ("The tiled build").
Where the faces do not close up, patches around the sites concerned are built
with doubling halos; a region that would hold every site, or too many open
sites, fall back to one build of the whole set (``stats["fallback"]`` says why).
The cells are computed per tile too, each kept when a disk about its site twice its
extent lies in the tile's region (§8, "The tiled cells").
"""

import functools
import math
import os
import re
import time
import warnings
from fractions import Fraction

import numpy as np

from . import _ellvor
from ._cells import Cells, _number as _cell_number
from ._diagram import _frozen
from ._errors import Error, InputError

# Coordinates or semi-axes beyond these (in magnitude; nonzero) leave the doubles' comfortable range:
# such a set is built as one tile.
_TINY, _HUGE = 1e-280, 1e280


def _sites_of(sites, fmt):
    """The input as an ellvor.Sites, checked as ellvor.build checks it (InputError), on the client."""
    if isinstance(sites, _ellvor.Sites):
        return sites
    if isinstance(sites, (str, bytes, os.PathLike)):
        return _ellvor.read_sites(sites, fmt)
    return _ellvor.Sites(sites)


def _in_double_range(params):
    """Every parameter 0 or of magnitude in (_TINY, _HUGE) (a NaN or an infinity fails)."""
    m = np.abs(params)
    return bool(m.max(initial=0.0) < _HUGE and np.min(m, where=m != 0, initial=np.inf) > _TINY)   # NaN: max is NaN


class _Grid:
    """nx x ny half-open tiles [x_i, x_(i+1)) x [y_j, y_(j+1)) covering the plane: the inner lines split the
    centers' bounding box evenly, the outer tiles reach infinity."""

    def __init__(self, centers, nx, ny):
        # Column by column: numpy reduces a strided (n, 2) view along axis 0 several times slower.
        lo = np.array([centers[:, 0].min(), centers[:, 1].min()])
        hi = np.array([centers[:, 0].max(), centers[:, 1].max()])
        self.lo, self.hi = lo, hi
        self.nx, self.ny = nx, ny
        self.xs = np.concatenate([[-np.inf], lo[0] + (hi[0] - lo[0]) * np.arange(1, nx) / nx, [np.inf]])
        self.ys = np.concatenate([[-np.inf], lo[1] + (hi[1] - lo[1]) * np.arange(1, ny) / ny, [np.inf]])

    def tile_of(self, points):
        """The flat tile index (i * ny + j) of each point."""
        i = np.searchsorted(self.xs, points[:, 0], side="right") - 1
        j = np.searchsorted(self.ys, points[:, 1], side="right") - 1
        return i * self.ny + j

    def rect(self, t):
        i, j = divmod(t, self.ny)
        return self.xs[i], self.xs[i + 1], self.ys[j], self.ys[j + 1]

    def region(self, t, halo):
        """T expanded by the halo (closed), in doubles rounded outward; the outer tiles' stay infinite."""
        x0, x1, y0, y1 = self.rect(t)
        return (float(np.nextafter(x0 - halo, -np.inf)), float(np.nextafter(x1 + halo, np.inf)),
                float(np.nextafter(y0 - halo, -np.inf)), float(np.nextafter(y1 + halo, np.inf)))


def _meets(boxes, r):
    """Sites whose (closed) bounding box meets the closed rectangle r."""
    return (boxes[:, 1] >= r[0]) & (boxes[:, 0] <= r[1]) & (boxes[:, 3] >= r[2]) & (boxes[:, 2] <= r[3])


def _inside(boxes, r):
    """Sites whose bounding box lies inside the closed rectangle r."""
    return (boxes[:, 0] >= r[0]) & (boxes[:, 1] <= r[1]) & (boxes[:, 2] >= r[2]) & (boxes[:, 3] <= r[3])


def _rss_mb():
    """This process's resident memory now (Linux's /proc/self/statm; 0 elsewhere). Taken with a tile's graph
    alive: its peak, near enough (ru_maxrss would count what a forked worker inherited)."""
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2 ** 20
    except (OSError, ValueError):
        return 0.0


def _site_arrays(sites):
    """(params, fractions, boxes) in one pass over the sites (C++): their nearest doubles
    (n, 5) as ``Sites.to_array`` gives them; their numerators and denominators (n, 10), what _payload sends
    of them, in the narrowest of int16, int32 and int64 that holds them all (None when one needs more than
    64 bits: sending a byte costs the client ~15 ns, copies at both ends of two sockets, and random sites'
    fractions fit in int16); per site (xlo, xhi, ylo, yhi), a box containing the exact ellipse (outward by
    2^-40 of its magnitude)."""
    return sites._tiling_arrays()


def _payload(sites, fractions, ids):
    """What a worker is sent of the sites ``ids``: their rows of ``fractions`` (_site_arrays), or (when
    that is None) their .ell lines."""
    return sites._lines(ids) if fractions is None else fractions[ids]


def _local_sites(payload):
    """A tile's sites from what _payload made of them (lines are parsed in C++, as a file's)."""
    if isinstance(payload, str):
        return _ellvor._sites_from_text(payload)
    return _ellvor._sites_from_fractions(payload)


def _local_build(payload):
    """The graph of a tile's sites (what _payload made of them): from fractions, the sites go straight to the
    graph (no Sites object whose sites the graph would copy)."""
    if isinstance(payload, str):
        return _ellvor._build(_ellvor._sites_from_text(payload), "ell", None, 0.1)
    return _ellvor._build_fractions(payload)


def _in_curve_order(ids, points):
    """``ids`` along a Z-order curve through their ``points`` (a 2^16 x 2^16 grid on their bounding box): a
    tile's sites stored in that order lie in memory near their neighbours in the plane, where its graph
    reads them (a 66 000-site tile builds ~6% faster than in the order of the ids)."""
    xy = points[ids]
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    side = float(max(hi - lo))
    if not (len(ids) > 1 and 0 < side < np.inf):
        return ids
    cells = np.minimum(((xy - lo) * (65535 / side)).astype(np.uint64), np.uint64(65535))  # NaN-free: 0 <= xy - lo <= side
    for shift, mask in ((8, 0x00FF00FF), (4, 0x0F0F0F0F), (2, 0x33333333), (1, 0x55555555)):
        cells = (cells | (cells << np.uint64(shift))) & np.uint64(mask)
    return ids[np.argsort(cells[:, 0] | (cells[:, 1] << np.uint64(1)), kind="stable")]


def _disk_misses_outside(circles, r, everything, optimistic=False):
    """Faces whose closed disk (radius max(rho, 0): a circle with rho <= 0 is its center) misses the closure
    of B minus R, B = ``everything`` the box of all sites, R = ``r`` the tile's region, for every center and
    radius in the face's box; in doubles rounded the safe way. B minus R is covered by four closed slabs.
    ``optimistic``: for some center and radius in the box instead, with a relative slack for rounding: a
    superset of the faces that a narrower box of the same circle could prove (no proof of anything)."""
    bx0, bx1, by0, by1 = everything
    slabs = [(bx0, r[0], by0, by1), (r[1], bx1, by0, by1), (bx0, bx1, by0, r[2]), (bx0, bx1, r[3], by1)]
    rho = np.maximum(circles[:, 4 if optimistic else 5], 0.0)
    rho2 = (1 - 1e-9) * rho * rho if optimistic else np.nextafter(rho * rho, np.inf)
    ok = np.ones(len(circles), dtype=bool)
    with np.errstate(invalid="ignore", over="ignore"):
        for x0, x1, y0, y1 in slabs:
            if not (x0 <= x1 and y0 <= y1):
                continue  # empty: R covers B on that side
            if optimistic:  # the farthest corner of the center box, per axis
                dx = np.maximum(np.maximum(x0 - circles[:, 0], circles[:, 1] - x1), 0.0)
                dy = np.maximum(np.maximum(y0 - circles[:, 2], circles[:, 3] - y1), 0.0)
                ok &= dx * dx + dy * dy >= rho2
                continue
            # A lower bound of the distance from the center box to the slab, per axis and squared.
            dx = np.maximum(np.maximum(np.nextafter(x0 - circles[:, 1], -np.inf),
                                       np.nextafter(circles[:, 0] - x1, -np.inf)), 0.0)
            dy = np.maximum(np.maximum(np.nextafter(y0 - circles[:, 3], -np.inf),
                                       np.nextafter(circles[:, 2] - y1, -np.inf)), 0.0)
            d2 = np.nextafter(np.nextafter(dx * dx, -np.inf) + np.nextafter(dy * dy, -np.inf), -np.inf)
            ok &= d2 > rho2   # NaN (an overflow) compares False: not certified
    return ok


def _disks_settled(boxes, region):
    """Per site A (``boxes``: the tile's held sites, all of them): whether every empty disk touching A lies
    in the interior of the closed rectangle ``region``, so that a face of A needs no circle for its seam test
    (docs/DESIGN.md §8, "Faces far from the seam"). A grid of g x g cells (g the held sites' spacing) marks
    the cells whose interior certainly holds a site's center: an interior point of a site. With r0 = 2.9 g
    (> 2 sqrt(2) g), when every cell meeting A's box widened by r0 (one cell more each way, for rounding) has
    a marked cell among its 3 x 3 block, an empty disk touching A has radius rho <= r0: were rho > r0, the
    disk of radius r0 inside it tangent at its touching point a in A has its center V' within r0 of the box;
    the square of half-side 2 g about V' lies in that smaller disk (2 sqrt(2) g < r0) and holds the closed
    3 x 3 block of cells about V''s cell, so the disk would hold a site's interior point. Then the disk lies
    in A's box widened by 2 r0, and that is tested inside the region, in doubles rounded the safe way."""
    m = len(boxes)
    settled = np.zeros(m, dtype=bool)
    if m < 16:
        return settled
    mid_x, mid_y = 0.5 * (boxes[:, 0] + boxes[:, 1]), 0.5 * (boxes[:, 2] + boxes[:, 3])
    # A box is the extent about the rounded center widened alike both ways (Sites._tiling_arrays): its middle
    # is within a few ulps of the exact center, far within this bound.
    error_x = 2.0 ** -44 * (np.abs(boxes[:, 0]) + np.abs(boxes[:, 1]))
    error_y = 2.0 ** -44 * (np.abs(boxes[:, 2]) + np.abs(boxes[:, 3]))
    lo = np.array([mid_x.min(), mid_y.min()])
    hi = np.array([mid_x.max(), mid_y.max()])
    extent = hi - lo
    g = float(math.sqrt(extent[0] * extent[1] / m)) if extent.min() > 0 else 0.0
    # Rounding (2^-52 of the coordinates) moves a computed cell index by less than a cell: the padding.
    if not (np.all(np.isfinite(boxes)) and g > 2.0 ** -30 * float(np.abs(boxes).max())):
        return settled
    x0, y0 = float(lo[0] - g), float(lo[1] - g)
    nx, ny = int(extent[0] / g) + 3, int(extent[1] / g) + 3
    if nx * ny > 4 * m + 1024:   # a thin strip of sites: its cells' frame would outnumber them
        return settled
    i = np.floor((mid_x - x0) / g).astype(np.int64)
    j = np.floor((mid_y - y0) / g).astype(np.int64)
    # The center certainly in the open cell: its error and the cell walls' rounding (2^-50 of their size) inside.
    wall_x = 2.0 ** -50 * (abs(x0) + (i + 1) * g)
    wall_y = 2.0 ** -50 * (abs(y0) + (j + 1) * g)
    sure = ((mid_x - error_x - wall_x > x0 + i * g) & (mid_x + error_x + wall_x < x0 + (i + 1) * g) &
            (mid_y - error_y - wall_y > y0 + j * g) & (mid_y + error_y + wall_y < y0 + (j + 1) * g) &
            (i >= 0) & (i < nx) & (j >= 0) & (j < ny))
    marked = np.zeros((nx + 2, ny + 2), dtype=bool)   # a frame of unmarked cells about the grid
    marked[i[sure] + 1, j[sure] + 1] = True
    block = np.zeros((nx, ny), dtype=bool)
    for di in range(3):
        for dj in range(3):
            block |= marked[di:di + nx, dj:dj + ny]
    # Uncovered cells counted over rectangles of cells: a summed-area table.
    table = np.zeros((nx + 1, ny + 1), dtype=np.int64)
    table[1:, 1:] = np.cumsum(np.cumsum(~block, axis=0), axis=1)
    r0 = 2.9 * g
    i0 = np.floor((boxes[:, 0] - r0 - x0) / g).astype(np.int64) - 1
    i1 = np.floor((boxes[:, 1] + r0 - x0) / g).astype(np.int64) + 1
    j0 = np.floor((boxes[:, 2] - r0 - y0) / g).astype(np.int64) - 1
    j1 = np.floor((boxes[:, 3] + r0 - y0) / g).astype(np.int64) + 1
    in_grid = (i0 >= 0) & (i1 < nx) & (j0 >= 0) & (j1 < ny)
    a0, a1 = np.clip(i0, 0, nx - 1), np.clip(i1, 0, nx - 1) + 1
    b0, b1 = np.clip(j0, 0, ny - 1), np.clip(j1, 0, ny - 1) + 1
    uncovered = table[a1, b1] - table[a0, b1] - table[a1, b0] + table[a0, b0]
    reach = 2.0 * r0
    with np.errstate(invalid="ignore", over="ignore"):
        inside = ((np.nextafter(boxes[:, 0] - reach, -np.inf) > region[0]) &
                  (np.nextafter(boxes[:, 1] + reach, np.inf) < region[1]) &
                  (np.nextafter(boxes[:, 2] - reach, -np.inf) > region[2]) &
                  (np.nextafter(boxes[:, 3] + reach, np.inf) < region[3]))
    return in_grid & (uncovered == 0) & inside


def _submit(client, fn, *args):
    """client.submit(fn, *args), not pure (each call runs). The sites go in the task itself, not scattered:
    the scheduler keeps a task's arguments, so a task whose worker dies runs again elsewhere (scattered data
    would die with the worker); Dask's warning about large arguments is silenced for that."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Large object", category=UserWarning)
        return client.submit(fn, *args, pure=False)


def _tile_task(payload, ids, region, rect, everything, whole, n):
    """Builds one tile's diagram and returns what it proves about the whole one (global ids below ``n``;
    the faces as _faces_out gives them, but for the whole set's, which are rows)."""
    start, cpu = time.perf_counter(), time.process_time()
    if not (whole or isinstance(payload, str)):   # the sites stored in Z order (here, not on the busy client)
        centers = np.stack([payload[:, 6] / payload[:, 7], payload[:, 8] / payload[:, 9]], axis=1)  # near enough
        order = _in_curve_order(np.arange(len(ids)), centers)
        payload, ids = payload[order], ids[order]
    build_cpu = time.process_time()
    try:
        d = _local_build(payload)
    except InputError as e:
        return _error_result(e, ids)
    build_cpu = time.process_time() - build_cpu
    faces = d.faces()
    hidden = d.hidden()
    if whole:  # every face is the whole graph's: no circle needed
        certified = owned = np.ones(len(faces), dtype=bool)
        visible_sure = np.ones(len(ids), dtype=bool)
    else:
        boxes = d._site_boxes()   # made here, not sent: the client's boxes, from the same sites
        # Faces with a site whose empty disks all lie inside the region need no circle box for the disk test;
        # the neighbours' test asks only for the boxes it needs (docs/DESIGN.md §8).
        settled = _disks_settled(boxes, region)[faces].any(axis=1)
        circle, may_share, wide = d.seam_circles(~settled)
        unsettled = np.nonzero(~settled)[0]   # the disk test for these only
        inside = np.zeros(len(faces), dtype=bool)
        inside[unsettled] = _disk_misses_outside(circle[unsettled], region, everything)
        # A wide double box (beyond 2^-40 of its circle: ~1% of the faces) made tight (Arb) only where that
        # might prove its disk inside.
        retry = unsettled[wide[unsettled] & ~inside[unsettled]]
        retry = retry[_disk_misses_outside(circle[retry], region, everything, True)]
        if len(retry):
            circle[retry] = d.circle_boxes(retry)
            inside[retry] = _disk_misses_outside(circle[retry], region, everything)
        certified = (settled | inside) & ~may_share
        visible_sure = _inside(boxes, region)
        # Which tile keeps a face (a count only): its circle's center where the box is at hand, else the mean
        # of its sites' box middles.
        kept, kept_circle = faces[certified], circle[certified]
        centers = np.stack([kept_circle[:, 0] + kept_circle[:, 1], kept_circle[:, 2] + kept_circle[:, 3]], axis=1) / 2
        unknown = np.nonzero(np.isnan(centers[:, 0]))[0]
        middles = np.stack([boxes[:, 0] + boxes[:, 1], boxes[:, 2] + boxes[:, 3]], axis=1) / 2
        centers[unknown] = sum(middles[kept[unknown, k]] for k in range(3)) / 3
        owned = ((centers[:, 0] >= rect[0]) & (centers[:, 0] < rect[1]) & (centers[:, 1] >= rect[2]) &
                 (centers[:, 1] < rect[3]))
    visible_sure[hidden[:, 0]] = False
    out = {
        "faces": _faces_in_order(ids[faces]) if whole else _faces_out(ids[kept], n), "hidden": ids[hidden],
        "visible": ids[np.nonzero(visible_sure)[0]],
        "tile_faces": len(faces), "certified": int(certified.sum()), "owned_faces": int(owned.sum()),
        "seconds": time.perf_counter() - start, "cpu_seconds": time.process_time() - cpu,
        "build_cpu_seconds": build_cpu, "rss_mb": _rss_mb(),
    }
    if whole:  # the whole set: the single build's own arrays
        out.update(edges=ids[d.edges()], hull=ids[d.hull()])
    return out


def _patches_task(jobs):
    """_tile_task for each job, the results merged (the retry round's patches of one tile)."""
    results = [_tile_task(*job) for job in jobs]
    for r in results:
        if "error" in r:
            return r
    merged = {key: np.concatenate([r[key] for r in results]) for key in ("faces", "hidden", "visible")}
    for key in ("tile_faces", "certified", "owned_faces", "seconds", "cpu_seconds", "build_cpu_seconds"):
        merged[key] = sum(r[key] for r in results)
    merged["rss_mb"] = max(r["rss_mb"] for r in results)
    return merged


_EPS = 2.0 ** -52


def _outer_polygon(params):
    """A convex polygon Q inside the convex hull K of all sites, counter-clockwise: the hull of the rounded
    centers of the sites extreme in 32 directions, each kept only where that double is certainly inside
    its site (within half an ulp a coordinate of the center; the site holds the disk of radius min(a, b)).
    Returns (Q's corners, the sites giving them)."""
    a, b, _, xc, yc = params.T
    angles = 2 * np.pi * np.arange(32) / 32
    directions = np.stack([np.cos(angles), np.sin(angles)])
    # The extreme site in each direction, a block of sites at a time (one product, no pass a direction);
    # any choice of them would do (the test below makes Q's corners safe), so rounding does not matter.
    best, best_value = np.zeros(32, dtype=np.int64), np.full(32, -np.inf)
    for start in range(0, len(params), 4096):   # blocks of 1 MB of products: malloc reuses them
        values = params[start:start + 4096, 3:5] @ directions
        k = np.argmax(values, axis=0)
        better = values[k, np.arange(32)] > best_value
        best[better], best_value[better] = start + k[better], values[k, np.arange(32)][better]
    chosen = sorted(set(best.tolist()))
    ok = [k for k in chosen if np.spacing(abs(xc[k])) + np.spacing(abs(yc[k])) < 0.5 * min(a[k], b[k])]
    return _convex_hull([(float(xc[k]), float(yc[k])) for k in ok]), ok


def _beyond_edges(polygon, px, py, depth):
    """Per point, per edge of the polygon (counter-clockwise): the point is certainly more than ``depth``
    inside that edge's line (a boolean per edge), in doubles with a forward error bound (as Shewchuk's
    orient2d filter): cross(e, x - p) > bound + depth |e| (_beyond_edges_varying with one margin)."""
    return _beyond_edges_varying(polygon, px, py, depth, 0.0)


def _hull_candidates(params, boxes, depth):
    """The sites that may come within ``depth`` of the convex hull K's boundary: all but those whose
    bounding box lies more than ``depth`` inside every edge of the polygon Q of _outer_polygon (not one of
    Q's own sites). Q lies in K, so the others lie in Q's interior: their union has the hull of the
    candidates' union. Returns (candidates, Q)."""
    n = len(params)
    polygon, corner_sites = _outer_polygon(params)
    if len(polygon) < 3:
        return np.arange(n), polygon
    # Most boxes lie in a rectangle R whose corners are more than ``depth`` inside every edge: then all of
    # R is (those points form a convex set), and so are they; only the others are tested edge by edge.
    inside = _inside(boxes, _inner_rectangle(polygon, depth))
    rest = np.nonzero(~inside)[0]
    rest_inside = np.ones(len(rest), dtype=bool)
    for a, b in zip(polygon, polygon[1:] + polygon[:1]):
        # The box's corner least inside this edge (cross(e, x - a) smallest; the signs of the rounded
        # differences are the exact ones): the box is inside when that corner is.
        ex, ey = b[0] - a[0], b[1] - a[1]
        cx = boxes[rest, 1] if ey > 0 else boxes[rest, 0]
        cy = boxes[rest, 2] if ex > 0 else boxes[rest, 3]
        rest_inside &= _beyond_edge(a, b, cx, cy, depth, 0.0)
    inside[rest] = rest_inside
    inside[corner_sites] = False
    return np.nonzero(~inside)[0], polygon


def _inner_rectangle(polygon, depth):
    """A rectangle (x0, x1, y0, y1) whose four corners are more than ``depth`` inside every edge of the
    convex polygon (by _beyond_edges), as large as one of a few shrinkings of the polygon's bounding box
    about its middle gives; an empty one when none is."""
    corners = np.array(polygon, dtype=float)
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    middle, half = (lo + hi) / 2, (hi - lo) / 2
    for shrink in (0.99, 0.95, 0.85, 0.7, 0.5, 0.25):
        x0, y0 = middle - shrink * half
        x1, y1 = middle + shrink * half
        px, py = np.array([x0, x1, x0, x1]), np.array([y0, y0, y1, y1])
        if all(edge.all() for edge in _beyond_edges(polygon, px, py, depth)):
            return float(x0), float(x1), float(y0), float(y1)
    return math.inf, -math.inf, math.inf, -math.inf


def _disk_outside_polygon(circles, polygon, depth):
    """Faces whose closed disk (radius max(rho, 0)) lies outside some edge line of the polygon moved
    ``depth`` inward, for every center and radius in the face's box: the non-candidates' region misses it."""
    rho = np.maximum(circles[:, 5], 0.0)
    ok = np.zeros(len(circles), dtype=bool)
    corners = [(circles[:, 0], circles[:, 2]), (circles[:, 1], circles[:, 2]), (circles[:, 0], circles[:, 3]),
               (circles[:, 1], circles[:, 3])]
    # Mirror the test of _beyond_edges: the center box more than rho outside the moved line, i.e. every
    # corner more than (rho - depth) outside the edge's line; the reversed edge (q -> p) says "outside".
    reversed_polygon = polygon[::-1]
    with np.errstate(invalid="ignore", over="ignore"):
        per_corner = [_beyond_edges_varying(reversed_polygon, cx, cy, rho, -depth) for cx, cy in corners]
    for k in range(len(polygon)):
        ok |= per_corner[0][k] & per_corner[1][k] & per_corner[2][k] & per_corner[3][k]
    return ok


def _disk_misses_shrunk_polygon(circles, polygon, depth):
    """Faces whose closed disk (radius max(rho, 0)) misses Q_depth, the points more than ``depth`` inside
    every edge of the polygon Q (where the non-candidates lie), for every center in the face's box. Q_depth
    lies in P = c0 + lam (Q - c0) (c0 the mean of Q's corners, lam = 1 - depth / r, r >= c0's distance to
    every edge line: each edge of P is at most depth inside Q's), and the disk misses P when its center is
    outside P and farther than rho from each of P's edges. Unlike _disk_outside_polygon this certifies the
    huge disks of nearly collinear hull triples, which cross a moved edge line far from the polygon. Doubles
    with forward error bounds: P's corners within `slack` of the computed ones, the distances within
    64 eps of their operands."""
    n = len(circles)
    corners = np.array(polygon, dtype=float)
    c0 = corners.mean(axis=0)
    following = np.roll(corners, -1, axis=0)
    edges = following - corners
    lengths = np.hypot(edges[:, 0], edges[:, 1])
    r = np.abs(edges[:, 0] * (c0[1] - corners[:, 1]) - edges[:, 1] * (c0[0] - corners[:, 0])) / lengths
    lam = 1.0 - depth / (r.max() * (1 + 1e-9) + 1e-300)
    if not lam > 0:
        return np.zeros(n, dtype=bool)
    shrunk = c0 + lam * (corners - c0)
    scale = np.abs(c0).sum() + np.abs(corners).sum(axis=1).max()
    slack = 16 * _EPS * scale
    rho = np.maximum(circles[:, 5], 0.0)
    cx, cy = 0.5 * (circles[:, 0] + circles[:, 1]), 0.5 * (circles[:, 2] + circles[:, 3])
    half_diagonal = np.hypot(circles[:, 1] - circles[:, 0], circles[:, 3] - circles[:, 2]) * (0.5 + 4 * _EPS)
    outside = np.zeros(n, dtype=bool)
    nearest = np.full(n, np.inf)
    shrunk_list = [tuple(p) for p in shrunk]
    box_corners = [(circles[:, 0], circles[:, 2]), (circles[:, 1], circles[:, 2]), (circles[:, 0], circles[:, 3]),
                   (circles[:, 1], circles[:, 3])]
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        for a, b in zip(shrunk_list, shrunk_list[1:] + shrunk_list[:1]):
            # Every corner of the center box strictly outside this edge (the reversed edge: "inside" it).
            beyond = np.ones(n, dtype=bool)
            for px, py in box_corners:
                beyond &= _beyond_edge(b, a, px, py, slack, 0.0)
            outside |= beyond
            ex, ey = b[0] - a[0], b[1] - a[1]
            t = np.clip(((cx - a[0]) * ex + (cy - a[1]) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
            dist = np.hypot(cx - (a[0] + t * ex), cy - (a[1] + t * ey))
            error = 64 * _EPS * (np.abs(cx) + np.abs(cy) + abs(a[0]) + abs(a[1]) + abs(b[0]) + abs(b[1]))
            nearest = np.minimum(nearest, dist - error)
        return outside & (nearest - half_diagonal - slack > rho * (1 + 4 * _EPS))


def _beyond_edges_varying(polygon, px, py, rho, shift):
    """As _beyond_edges, with a per-point margin: cross(e, x - p) > bound + (rho + shift) |e| (|e| rounded
    up), for polygon edges given clockwise (so "inside" is outside the counter-clockwise polygon)."""
    return [_beyond_edge(a, b, px, py, rho, shift) for a, b in zip(polygon, polygon[1:] + polygon[:1])]


def _beyond_edge(a, b, px, py, rho, shift):
    """_beyond_edges_varying for the one edge a -> b."""
    (ax, ay), (bx, by) = a, b
    ex, ey = bx - ax, by - ay
    left, right = ex * (py - ay), ey * (px - ax)
    bound = 4 * _EPS * (np.abs(left) + np.abs(right)) + 4 * _EPS * (abs(ex) + abs(ey)) * (
        np.abs(px - ax) + np.abs(py - ay))
    length = math.hypot(ex, ey) * (1 + 4 * _EPS)
    margin = np.nextafter(np.maximum(rho + shift, 0.0) * length, np.inf) * (1 + 4 * _EPS)
    return left - right > bound + margin


def _convex_hull(points):
    """Counter-clockwise hull of a few double points, exactly (Fractions), without collinear points."""
    from fractions import Fraction
    pts = sorted(set((Fraction(x), Fraction(y)) for x, y in points))
    if len(pts) < 3:
        return [(float(x), float(y)) for x, y in pts]

    def cross(o, p, q):
        return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return [(float(x), float(y)) for x, y in lower[:-1] + upper[:-1]]


def _hull_task(payload, ids, polygon, depth, n):
    """The candidates' graph: its hull faces are those of the whole graph, and so are its finite faces whose
    disk misses the non-candidates' region (docs/DESIGN.md §8); its hidden sites are hidden."""
    start, cpu = time.perf_counter(), time.process_time()
    try:
        d = _local_build(payload)
    except InputError as e:
        return _error_result(e, ids)
    faces = d.faces()
    if len(polygon) >= 3:
        def beyond(c):
            return _disk_outside_polygon(c, polygon, depth) | _disk_misses_shrunk_polygon(c, polygon, depth)
        circles, may_share, wide = d.seam_circles(np.ones(len(faces), dtype=bool))
        certified = beyond(circles)
        retry = np.nonzero(wide & ~certified)[0]   # a wide double box made tight (Arb) where it fails
        if len(retry):
            circles[retry] = d.circle_boxes(retry)
            certified[retry] = beyond(circles[retry])
        certified &= ~may_share
    else:
        certified = np.ones(len(faces), dtype=bool)   # every site is a candidate
    return {"hull": ids[d.hull()], "faces": _faces_out(ids[faces[certified]], n), "hidden": ids[d.hidden()],
            "visible": np.zeros(0, dtype=np.int64), "tile_faces": len(faces), "certified": int(certified.sum()),
            "owned_faces": 0, "seconds": time.perf_counter() - start, "cpu_seconds": time.process_time() - cpu,
            "rss_mb": _rss_mb()}


def _local_ids_to_global(message, ids):
    """A worker's error names sites by their ids in the tile: name them by their global ids."""
    return re.sub(r"\b(sites?|and) (\d+)\b", lambda m: f"{m.group(1)} {int(ids[int(m.group(2))])}", message)


def _error_result(e, ids):
    """A worker's InputError ``e`` about its sites, whose global ids are ``ids``: the reason with global ids,
    the pair of sites (global ids), and for crossing sites how they cross."""
    pair = None if e.sites is None else tuple(int(ids[k]) for k in e.sites)
    return {"error": (_local_ids_to_global(e.reason, ids), pair, e.why)}


def _raise_worker_error(result, sites):
    """Raises what a worker's _error_result says, as ``ellvor.build(sites)`` would: crossing sites at the
    later one's line when the sites are a file's."""
    reason, pair, why = result["error"]
    if pair is not None and why is not None:
        _ellvor._raise_crossing_sites(sites, pair[0], pair[1], why)
    if pair is not None:
        pair = tuple(sorted(pair))
        raise InputError(reason, sites=pair, reason=reason)
    raise InputError(reason)


def _directed_keys(src, dst, m):
    """The directed edges src -> dst (ids below m), loops left out (a loop is its own twin), sorted: each as its
    undirected key (i < j) and a bit for its direction (1: from j to i)."""
    src, dst = src.astype(np.int64), dst.astype(np.int64)
    x = np.minimum(src, dst)
    x *= m
    x += np.maximum(src, dst)
    x *= 2
    x += src > dst
    loop = src == dst
    if loop.any():
        x = x[~loop]
    x.sort(kind="stable")
    return x


def _merged(*arrays):
    """Sorted arrays as one (numpy's stable sort, a timsort, merges sorted runs)."""
    x = np.concatenate(arrays)
    x.sort(kind="stable")
    return x


class _FaceUnion:
    """The distinct faces the tiles certified so far, the sites on them, and their directed edges' keys
    (_directed_keys, ids below n), sorted: grown as results come, so that most of the merge runs while the
    last tiles still build. Faces come as _faces_out sends them: int64 keys (a n + b) n + c where n^3
    fits (kept as such), else rows."""

    def __init__(self, n):
        self.n = n
        self.wide = not _keys_fit(n)
        self.face_keys = np.zeros(0, dtype=np.int64)
        self.rows = np.zeros((0, 3), dtype=np.int64)
        self.keys = np.zeros(0, dtype=np.int64)
        self.visible = np.zeros(n, dtype=bool)

    def __len__(self):
        return len(self.rows) if self.wide else len(self.face_keys)

    def faces(self):
        """The faces found, sorted (rows; each row as a tile gave it, its smallest id first)."""
        return self.rows if self.wide else _face_rows(self.face_keys, self.n)

    def add(self, parts):
        """Adds the tiles' faces ``parts`` (a list of _faces_out's arrays; repeats allowed: sorted runs,
        concatenated, merge fastest)."""
        n = self.n
        if self.wide:
            rows = np.concatenate([np.asarray(p, dtype=np.int64).reshape(-1, 3) for p in parts])
            both, first = np.unique(np.concatenate([self.rows, rows]), axis=0, return_index=True)
            new = both[first >= len(self.rows)]
            self.rows = both
        else:
            k = np.concatenate(parts).astype(np.int64, copy=False)
            k.sort(kind="stable")   # merges sorted runs
            k = k[np.concatenate([[True], k[1:] != k[:-1]])] if len(k) else k
            if len(self.face_keys) and len(k):
                at = np.minimum(np.searchsorted(self.face_keys, k), len(self.face_keys) - 1)
                k = k[self.face_keys[at] != k]
            self.face_keys = _merged(self.face_keys, k)
            new = _face_rows(k, n)
        self.visible[new.ravel()] = True
        # Each part sorted apart, then all merged: for rows in order, each row's smallest id first, the edges
        # a -> b come sorted and c -> a nearly so; only b -> c are in no order.
        parts = [_directed_keys(src, dst, n) for src, dst in ((new[:, 0], new[:, 1]), (new[:, 2], new[:, 0]),
                                                               (new[:, 1], new[:, 2]))]
        self.keys = _merged(self.keys, *parts)


class _DirectedEdges:
    """The directed edges of a _FaceUnion's faces and the hull edges, sorted (_directed_keys)."""

    def __init__(self, union, hull):
        self.m = union.n
        self.sorted = _merged(union.keys, _directed_keys(hull[:, 0], hull[:, 1], self.m))

    def open_sites(self):
        """Sites on directed edges whose count differs from their twin's: where faces are missing. A whole
        graph's keys come in pairs, bit 0 then bit 1, but for its few double edges: the entries are read in
        pairs, and only the keys of pairs that are not such a pair are counted (a run of one key whose
        every pair is such a pair is exactly one pair, balanced)."""
        x = self.sorted
        first, second = x[0:len(x) - 1:2], x[1::2]
        unpaired = ~((second - first == 1) & (first & 1 == 0))
        last = x[len(x) - 1:] if len(x) % 2 else x[:0]   # an entry without a pair
        keys = np.concatenate([first[unpaired] >> 1, second[unpaired] >> 1, last >> 1])
        keys = np.unique(keys)
        zeros = np.searchsorted(x, 2 * keys + 1) - np.searchsorted(x, 2 * keys)
        ones = np.searchsorted(x, 2 * keys + 2) - np.searchsorted(x, 2 * keys + 1)
        bad = keys[zeros != ones]
        return np.unique(np.concatenate([bad // self.m, bad % self.m]))

    def edges(self):
        """Finite Delaunay edges (i < j), sorted: edge {i, j} once per directed occurrence of i -> j."""
        key = self.sorted[(self.sorted & 1) == 0] >> 1
        return np.stack([key // self.m, key % self.m], axis=1)


def _turned(a):
    """The faces ``a`` (rows of three ids, counter-clockwise) each turned to start at its smallest id, as the
    single build gives them (whatever order a tile's ids are in)."""
    return np.take_along_axis(a, (a.argmin(axis=1)[:, None] + np.arange(3)) % 3, axis=1)


def _faces_in_order(a):
    """The faces ``a`` turned (_turned), then sorted (lexicographically, the dtype kept), so that the client
    merges sorted runs (_FaceUnion)."""
    if not len(a):
        return a
    a = _turned(a)
    return a[np.lexsort(a.T[::-1])]


def _keys_fit(n):
    """Whether a face of ids below n fits one int64 key (a n + b) n + c."""
    return n ** 3 < 2 ** 63


def _faces_out(a, n):
    """A tile's faces ``a`` (ids below ``n``) as it sends them: each turned to start at its smallest id, as sorted
    keys (a n + b) n + c where they fit (8 bytes a face, not 12, and no work on the client to make them),
    else as sorted rows (_faces_in_order)."""
    if not _keys_fit(n):
        return _faces_in_order(a)
    a = _turned(a).astype(np.int64)
    k = (a[:, 0] * n + a[:, 1]) * n + a[:, 2]
    k.sort()
    return k


def _face_rows(k, n):
    """Faces from their keys (a n + b) n + c (_faces_out): rows (a, b, c)."""
    return np.stack([k // (n * n), k // n % n, k % n], axis=1)


def _sorted_rows(a, width):
    a = np.asarray(a, dtype=np.int64).reshape(-1, width)
    if len(a) == 0:
        return a
    return a[np.lexsort(a.T[::-1])]


class TiledDiagram:
    """The Delaunay graph from a tiled build: ``hidden``, ``edges``, ``faces``, ``hull`` as ``ellvor.Diagram``
    has them (int64, read-only, the single build's order); ``vertices``, ``vertex_radii``, ``vertex_errors``
    computed on first use, as Diagram's; ``sites``, ``points``. (No ridges, trace or remove: build a Diagram
    for those.) ``tiles``: per tile a dict: index (i, j), sites (held), owned (center in the tile),
    halo_sites, halo (its width), tile_faces (of its graph), certified, faces_kept (certified, circle center
    in the tile), retries (patches built later around its sites, docs/DESIGN.md §8), seconds,
    cpu_seconds and build_cpu_seconds (its tile and patches; the whole task, the graph's build with its sites made),
    rss_mb (its worker's resident memory with the graph built: its peak, near enough). ``stats``: rounds,
    fallback (False, or why one build of the whole set decided), hull_candidates, seconds (wall time of the
    call)."""

    def __init__(self, sites, hidden, edges, faces, hull, tiles, stats):
        """``edges`` and ``faces``: arrays, or functions that make them (called on first use)."""
        self.sites = sites
        self.hidden, self.hull = _frozen(np.asarray(hidden)), _frozen(np.asarray(hull))
        self._makers = {"edges": edges, "faces": faces}
        self.tiles, self.stats = tiles, stats

    def _made(self, name):
        a = self._makers.pop(name)
        return _frozen(np.asarray(a() if callable(a) else a))

    edges = functools.cached_property(lambda self: self._made("edges"))
    faces = functools.cached_property(lambda self: self._made("faces"))

    @functools.cached_property
    def points(self):
        return _frozen(np.ascontiguousarray(self.sites.to_array()[:, 3:5]))

    @functools.cached_property
    def _vertex_arrays(self):
        return tuple(_frozen(a) for a in _ellvor._face_vertices(self.sites, self.faces))

    vertices = property(lambda self: self._vertex_arrays[0])
    vertex_radii = property(lambda self: self._vertex_arrays[1])
    vertex_errors = property(lambda self: self._vertex_arrays[2])

    def __len__(self):
        return len(self.sites)

    def __repr__(self):
        how = "one build (fallback)" if self.stats["fallback"] else f"{len(self.tiles)} tiles"
        return (f"<ellvor.distributed.TiledDiagram: {len(self)} sites ({len(self.hidden)} hidden), "
                f"{len(self.edges)} Delaunay edges, {len(self.faces)} faces, {how}, {self.stats['rounds']} rounds>")


def local_cluster(workers=None):
    """A dask.distributed LocalCluster as ``build`` and ``cells`` start one when not given a client: ``workers``
    worker processes (default: one per core), one thread each, no dashboard, Dask's statistical profiler off
    in the workers (it samples each worker's stack every 10 ms: ~7% of a tile build's CPU on the project's
    machine, experiments/results/distributed.md), and glibc's malloc as in any process: Dask sets
    MALLOC_TRIM_THRESHOLD_=65536 in its workers, which fixes glibc's mmap threshold at 128 kB, so that every
    large numpy temporary is a fresh mmap whose pages fault in (a tile's seam arithmetic 8-10x slower); and a
    scheduler that sends a worker its next task only when its thread is free (worker-saturation 1.0, not
    Dask's 1.1, which gives a one-thread worker two: the last tile then waited behind another while the
    other worker had nothing to do). Use it as a context manager, or close() it."""
    import dask
    from distributed import LocalCluster
    environ = {key: value for key, value in dask.config.get("distributed.nanny.pre-spawn-environ").items()
               if key != "MALLOC_TRIM_THRESHOLD_"}
    # The workers take the configuration in force when the cluster starts them.
    with dask.config.set({"distributed.worker.profile.enabled": False, "distributed.nanny.pre-spawn-environ": environ,
                          "distributed.scheduler.worker-saturation": 1.0}):
        return LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                            dashboard_address=None)


def _client_for(client):
    """(client, close): a Client for the argument; close() ends what was started here."""
    from distributed import Client
    if client is None:
        cluster = local_cluster()
        c = Client(cluster)

        def close():
            c.close()
            cluster.close()
        return c, close
    if isinstance(client, str):
        c = Client(client)
        return c, c.close
    return client, lambda: None


def _tiles_argument(tiles, n, client):
    if isinstance(tiles, str):
        if tiles != "auto":
            raise ValueError(f"tiles: expected (nx, ny) or 'auto', got {tiles!r}")
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        # Eight tiles a worker (experiments/results/distributed.md: at 10^6 sites 4 x 4 tiles on 2 workers
        # beat 2 x 2, smaller graphs cost less a site), at least 20000 sites a tile (halos stay thin).
        count = max(1, min(8 * workers, n // 20000))
        nx = max(1, int(math.sqrt(count)))
        return nx, max(1, count // nx)
    try:
        nx, ny = (int(t) for t in tiles)
    except (TypeError, ValueError):
        raise ValueError(f"tiles: expected (nx, ny) or 'auto', got {tiles!r}") from None
    if not (1 <= nx <= 1024 and 1 <= ny <= 1024):
        raise ValueError(f"tiles: expected 1 <= nx, ny <= 1024, got {tiles!r}")
    return nx, ny


def build(sites, tiles="auto", client=None, *, fmt="ell", halo=None):
    """The Delaunay graph of ``sites`` (as for ``ellvor.build``: a path, an ellvor.Sites or Ellipses),
    built in ``tiles`` = (nx, ny) tiles or "auto" (eight a worker, at least 20000 sites a tile) on Dask.

    ``client``: None starts a LocalCluster (one worker process per core, closed afterwards); a
    ``distributed.Client``; or a scheduler address ("tcp://host:8786"). ``halo``: the first halo width
    (default: four mean site spacings); patches around sites on missing faces double it each round.
    Bad input raises InputError here, before anything is sent. Returns a TiledDiagram whose hidden,
    edges, faces and hull are those of ``ellvor.build(sites)``.
    """
    sites = _sites_of(sites, fmt)
    start = time.perf_counter()
    n = len(sites)
    params, fractions, boxes = _site_arrays(sites)
    c, close = _client_for(client)
    try:
        nx, ny = _tiles_argument(tiles, n, c)
        return _tiled_build(c, sites, params, fractions, boxes, nx, ny, halo, start)
    finally:
        close()


def _tiled_build(client, sites, params, fractions, boxes, nx, ny, halo, start):
    n = len(sites)

    everything = (float(boxes[:, 0].min()), float(boxes[:, 1].max()), float(boxes[:, 2].min()),
                  float(boxes[:, 3].max())) if n else (0.0, 0.0, 0.0, 0.0)

    # Tiles are sent their sites' global ids, and send back faces by them, as int32 where n allows: half
    # the bytes (every large message costs copies at both ends).
    id_type = np.int32 if n < 2 ** 31 else np.int64

    def submit_tile(ids, region, rect, whole):
        return _submit(client, _tile_task, _payload(sites, fractions, ids), ids.astype(id_type), region, rect, everything,
                       whole, n)

    def one_build(reason):
        result = submit_tile(np.arange(n, dtype=np.int64), (-np.inf, np.inf, -np.inf, np.inf), (-np.inf, np.inf, -np.inf, np.inf),
                             True).result()
        if "error" in result:
            _raise_worker_error(result, sites)
        tile = {"index": (0, 0), "sites": n, "owned": n, "halo_sites": 0, "halo": math.inf,
                "tile_faces": result["tile_faces"], "certified": result["certified"],
                "faces_kept": result["certified"], "retries": 0, "seconds": result["seconds"],
                "cpu_seconds": result["cpu_seconds"], "build_cpu_seconds": result["build_cpu_seconds"],
                "rss_mb": result["rss_mb"]}
        return TiledDiagram(sites, _sorted_rows(result["hidden"], 2), result["edges"].astype(np.int64),
                            _sorted_rows(result["faces"], 3), _sorted_rows(result["hull"], 2), [tile],
                            {"rounds": 1, "fallback": reason, "hull_candidates": n,
                             "seconds": time.perf_counter() - start})

    if n < 16 or nx * ny == 1 or not _in_double_range(params):
        return one_build("one tile" if nx * ny == 1 else "too few sites or extreme coordinates")

    grid = _Grid(params[:, 3:5], nx, ny)
    owner = grid.tile_of(params[:, 3:5])
    lo, hi = grid.lo, grid.hi
    area = float((hi[0] - lo[0]) * (hi[1] - lo[1]))
    spacing = math.sqrt(area / n) if area > 0 else float(max(hi - lo)) / n
    halos = np.full(nx * ny, halo if halo is not None else 4 * spacing + 1e-300)
    owned_count = np.bincount(owner, minlength=nx * ny)
    tiles = [{"index": divmod(t, ny), "sites": 0, "owned": int(owned_count[t]), "halo_sites": 0, "halo": 0.0,
              "tile_faces": 0, "certified": 0, "faces_kept": 0, "retries": -1, "seconds": 0.0, "cpu_seconds": 0.0,
              "build_cpu_seconds": 0.0, "rss_mb": 0.0}
             for t in range(nx * ny)]

    union = _FaceUnion(n)
    faces_found, hidden_found, visible_found = [], [np.zeros((0, 2), np.int64)], []

    def covers_everything(region, held):
        return len(held) == n or (region[0] <= everything[0] and region[1] >= everything[1] and
                                  region[2] <= everything[2] and region[3] >= everything[3])

    def collect(t, result):
        if "error" in result:
            _raise_worker_error(result, sites)
        faces_found.append(result["faces"])
        hidden_found.append(result["hidden"])
        visible_found.append(result["visible"])
        tiles[t]["tile_faces"] += result["tile_faces"]
        tiles[t]["certified"] += result["certified"]
        tiles[t]["faces_kept"] += result["owned_faces"]
        tiles[t]["seconds"] += result["seconds"]
        tiles[t]["cpu_seconds"] += result["cpu_seconds"]
        tiles[t]["build_cpu_seconds"] += result["build_cpu_seconds"]
        tiles[t]["rss_mb"] = max(tiles[t]["rss_mb"], result["rss_mb"])

    # Round 1: the tiles, the largest first (the workers take them in that order, so that the last to end are
    # small and the workers end together): by the sides on which a tile has a halo, then by its sites. The hull
    # candidates' graph, smaller than a tile where tiles pay (experiments/results/distributed.md), is sent
    # when the last tiles have started: Dask would start it at once (it queues only tasks of a large group).
    halo_sides = [(0 < i) + (i < nx - 1) + (0 < j) + (j < ny - 1) for i, j in (divmod(t, ny) for t in range(nx * ny))]
    futures = {}
    for t in sorted(range(nx * ny), key=lambda t: (-halo_sides[t], -owned_count[t], t)):
        if not owned_count[t]:
            continue
        region = grid.region(t, halos[t])
        held = np.nonzero(_meets(boxes, region))[0]
        if covers_everything(region, held):
            return one_build(f"the halo of tile {divmod(t, ny)} holds the whole set")
        futures[t] = submit_tile(held, region, grid.rect(t), False)
        tiles[t].update(sites=len(held), halo_sites=len(held) - tiles[t]["owned"], halo=float(halos[t]), retries=0)
    candidates, polygon = _hull_candidates(params, boxes, halos.max())
    from distributed import as_completed
    tile_of = {f: t for t, f in futures.items()}
    workers = max(1, len(client.scheduler_info()["workers"]))
    running = as_completed(futures.values())
    hull_future = None
    outstanding = len(futures) + 1   # the tiles and the hull candidates' graph
    while outstanding:
        if hull_future is None and outstanding <= workers + 1:
            hull_future = _submit(client, _hull_task, _payload(sites, fractions, candidates), candidates.astype(id_type),
                                  polygon, halos.max(), n)
            running.add(hull_future)
        f = next(running)
        if f is hull_future:
            h = f.result()
            if "error" in h:
                _raise_worker_error(h, sites)
            hull = h["hull"]
            faces_found.append(h["faces"])
            hidden_found.append(h["hidden"])
        else:
            collect(tile_of[f], f.result())
        outstanding -= 1
        if len(faces_found) >= 4 or outstanding <= workers:
            # Merged in batches as they come (each batch's merge rewrites the union so far), so that little is
            # left to merge when the last task ends.
            union.add(faces_found)
            faces_found = []

    # Later rounds: a patch around each site on a face that is missing, its halo doubling each round.
    patch_halo = np.full(n, 2.0 * halos.max())
    rounds = 1
    while True:
        if faces_found:
            union.add(faces_found)
            faces_found = []
        hidden_all = np.concatenate(hidden_found)
        is_hidden = np.zeros(n, dtype=bool)
        is_hidden[hidden_all[:, 0]] = True
        is_visible = union.visible.copy()
        for v in visible_found:
            is_visible[v] = True
        if (is_hidden & is_visible).any():
            raise Error(f"tiled build: site {int(np.nonzero(is_hidden & is_visible)[0][0])} both hidden and visible")
        accepted = hull[is_visible[hull[:, 0]] & is_visible[hull[:, 1]]] if len(hull) else hull.reshape(-1, 2)
        unknown = np.nonzero(~is_hidden & ~is_visible)[0]
        directed = _DirectedEdges(union, accepted)
        open_sites = np.union1d(directed.open_sites(), unknown)
        n_visible = int(is_visible.sum())
        if len(open_sites) == 0:
            if len(union) + len(accepted) == 2 * n_visible - 2:
                break
            return one_build("the faces found do not count up to the whole graph")
        if len(open_sites) > max(64, n // 10):
            return one_build(f"{len(open_sites)} sites on faces no tile certified")
        rounds += 1
        batches = {}
        for p in open_sites.tolist():
            r = (float(np.nextafter(boxes[p, 0] - patch_halo[p], -np.inf)),
                 float(np.nextafter(boxes[p, 1] + patch_halo[p], np.inf)),
                 float(np.nextafter(boxes[p, 2] - patch_halo[p], -np.inf)),
                 float(np.nextafter(boxes[p, 3] + patch_halo[p], np.inf)))
            held = np.nonzero(_meets(boxes, r))[0]
            if covers_everything(r, held):
                return one_build(f"the patch around site {p} holds the whole set")
            patch_halo[p] *= 2
            batches.setdefault(int(owner[p]), []).append(
                (_payload(sites, fractions, held), held.astype(id_type), r, (0.0, 0.0, 0.0, 0.0), everything, False, n))
            tiles[int(owner[p])]["retries"] += 1
        futures = {t: _submit(client, _patches_task, jobs) for t, jobs in batches.items()}
        for t, f in futures.items():
            collect(t, f.result())

    # Hidden: one host per hidden site, the first tile's that reported it (sorted by hidden id).
    hidden_all = hidden_all[np.argsort(hidden_all[:, 0], kind="stable")]
    first = np.concatenate([[True], hidden_all[1:, 0] != hidden_all[:-1, 0]]) if len(hidden_all) else []
    hidden = hidden_all[first]
    accepted = _sorted_rows(accepted, 2)
    # The edges and faces are made on first use, as Diagram makes its arrays from its graph.
    faces = union.rows if union.wide else functools.partial(_face_rows, union.face_keys, n)
    return TiledDiagram(sites, hidden, directed.edges, faces, accepted,
                        [t for t in tiles if t["retries"] >= 0],
                        {"rounds": rounds, "fallback": False, "hull_candidates": len(candidates),
                         "seconds": time.perf_counter() - start})


# The tiled cells (docs/DESIGN.md §8, "The tiled cells").

def _reach_disk_inside(boxes, semi_axes, reach, region):
    """Cells whose disk K about the site's center of radius 2 max(reach, larger semi-axis) lies in the closed
    rectangle ``region``, for every center in the site's bounding box; in doubles rounded the safe way. A
    site the tile lacks misses the region, so it misses K: the cell is the whole diagram's (§8)."""
    r2 = 2.0 * np.nextafter(np.maximum(reach, semi_axes), np.inf)
    with np.errstate(invalid="ignore", over="ignore"):
        return ((np.nextafter(boxes[:, 0] - r2, -np.inf) >= region[0]) &
                (np.nextafter(boxes[:, 1] + r2, np.inf) <= region[1]) &
                (np.nextafter(boxes[:, 2] - r2, -np.inf) >= region[2]) &
                (np.nextafter(boxes[:, 3] + r2, np.inf) <= region[3]))


def _vertex_keys(a, ids, copy_shifts):
    """Per vertex of a tile's cells the sites of its face, global: rows (site, wall, shift x, shift y) x 3,
    rotated to start at the least (site, wall), so that the same face from any tile gives the same row."""
    sites, walls = ids[a["vertex_sites"]], a["vertex_walls"]
    shifts = a["vertex_shifts"] + copy_shifts[a["vertex_sites"]]
    rows = np.concatenate([sites[:, :, None], walls[:, :, None], shifts], axis=2)   # (m, 3, 4)
    first = np.argmin(sites * 5 + walls, axis=1)
    order = (first[:, None] + np.arange(3)[None, :]) % 3
    return np.take_along_axis(rows, order[:, :, None], axis=1).reshape(-1, 12)


_CELL_COLUMNS = ("area_lo", "area_hi", "site_area_lo", "site_area_hi", "perimeter_lo", "perimeter_hi",
                 "packing_fraction_lo", "packing_fraction_hi", "centroid_lo", "centroid_hi", "second_moments_lo",
                 "second_moments_hi", "site_area", "visible", "bounded", "precision", "reach")


def _cells_task(payload, ids, shifts, want, boxes, semi_axes, domain, tolerance, boundary_tolerance, rings, region,
                whole):
    """The cells of the held sites ``want`` (local indices) among all held sites (``payload``, global ``ids``;
    a periodic box's copies shifted by ``shifts`` periods, the wanted ones by none); returns those the reach
    certificate proves (all when ``whole``: the whole set), with global ids and vertices keyed by their
    faces' global sites, and the reach of those it does not."""
    start, cpu = time.perf_counter(), time.process_time()
    box, periodic = domain
    try:
        # (Sites without lines: an error names the sites by id, mapped to global ids below.)
        core = _ellvor._cells(_local_sites(payload), box, periodic, tolerance, boundary_tolerance, rings,
                              want.tolist())
    except InputError as e:
        return _error_result(e, ids)
    a = core.arrays()
    if whole:
        certified = np.ones(len(want), dtype=bool)
    else:
        hidden = ~a["visible"][want]
        certified = hidden | (a["bounded"][want] & _reach_disk_inside(boxes[want], semi_axes[want],
                                                                      a["reach"][want], region))
    got = want[certified]
    out = {key: a[key][got] for key in _CELL_COLUMNS}
    out["sites"] = ids[got]
    counts = a["indptr"][got + 1] - a["indptr"][got]
    sides = np.concatenate([np.arange(a["indptr"][k], a["indptr"][k + 1]) for k in got]).astype(np.int64) \
        if len(got) else np.zeros(0, dtype=np.int64)
    indices = a["indices"][sides]
    out["counts"] = counts
    out["indices"] = np.where(indices >= 0, ids[np.maximum(indices, 0)], indices)
    out["shifts"] = a["shifts"][sides] + np.where(indices[:, None] >= 0, shifts[np.maximum(indices, 0)], 0)
    used = np.unique(a["side_vertices"][sides])
    used = used[used >= 0]
    renumber = np.full(len(a["vertices_lo"]) + 1, -1, dtype=np.int64)   # index -1: infinity stays -1
    renumber[used] = np.arange(len(used))
    out["side_vertices"] = renumber[a["side_vertices"][sides]]
    out["vertex_keys"] = _vertex_keys(a, ids, shifts)[used]
    out["vertices_lo"], out["vertices_hi"] = a["vertices_lo"][used], a["vertices_hi"][used]
    out["rings"] = [a["rings"][k] for k in got] if rings else []
    out["open"] = want[~certified]
    out["open_reach"] = np.where(a["visible"][want[~certified]], a["reach"][want[~certified]], np.inf)
    out["open_unbounded"] = a["visible"][want[~certified]] & ~a["bounded"][want[~certified]]
    out["open"] = ids[out["open"]]
    out.update(held=len(ids), seconds=time.perf_counter() - start, cpu_seconds=time.process_time() - cpu,
               rss_mb=_rss_mb())
    return out


def _cell_patches_task(jobs):
    """_cells_task for each job (one site's patch each), the results concatenated."""
    results = [_cells_task(*job) for job in jobs]
    for r in results:
        if "error" in r:
            return r
    return results


class _ArrayCore:
    """The arrays of tiled cells in the shape Cells takes them from its C++ core."""

    def __init__(self, arrays):
        self._arrays = arrays

    def arrays(self):
        return dict(self._arrays)

    def json(self):
        raise Error("tiled cells have no JSON or GeoJSON document yet: "
                    "ellvor.build(sites).cells(...).to_json() writes it in one process")

    geojson = json

    def write(self, path, fmt):
        self.json()


class TiledCells(Cells):
    """Cells computed in tiles on Dask (``ellvor.distributed.cells``): the arrays of ``Cells`` (areas and the
    other measures as certified intervals, visibility, neighbours, rings), each cell computed in one tile and
    proven there to be the whole diagram's (docs/DESIGN.md §8). The vertices are numbered in order of first
    use along the cells' sides, one per face (one process may list a vertex of four cocircular sites twice);
    ``vertex_sites``, ``vertex_walls`` name each vertex's face (global ids). ``reach``: per cell a bound of its boundary's distance from the site's
    center (+inf where not computed). No JSON or GeoJSON (``to_json`` raises Error). ``tiles``: per tile
    index, sites (held), owned, cells (certified there), retries (patches), seconds, cpu_seconds, rss_mb;
    ``stats``: rounds, fallback (False, or why some or all cells were computed in one task of the whole set),
    whole_set_cells (how many), seconds."""

    def __init__(self, arrays, tiles, stats):
        super().__init__(_ArrayCore(arrays))
        self.tiles, self.stats = tiles, stats

    def __repr__(self):
        return super().__repr__()[:-1] + f", {len(self.tiles)} tiles>"


def _double_bounds(x):
    """(lo, hi): doubles around the Fraction x."""
    f = float(x)
    return (f if Fraction(f) <= x else float(np.nextafter(f, -np.inf)),
            f if Fraction(f) >= x else float(np.nextafter(f, np.inf)))


def _mirror_regions(r, walls):
    """The parts of the region r beyond each wall line, reflected across it: a site whose mirror meets r
    meets one of these (``walls``: (lo, hi) doubles of x0, y0, x1, y1)."""
    (x0l, x0h), (y0l, y0h), (x1l, x1h), (y1l, y1h) = walls
    up, down = (lambda v: float(np.nextafter(v, np.inf))), (lambda v: float(np.nextafter(v, -np.inf)))
    out = []
    if r[0] < x0h:
        out.append((x0l, up(2 * x0h - r[0]), r[2], r[3]))
    if r[1] > x1l:
        out.append((down(2 * x1l - r[1]), x1h, r[2], r[3]))
    if r[2] < y0h:
        out.append((r[0], r[1], y0l, up(2 * y0h - r[2])))
    if r[3] > y1l:
        out.append((r[0], r[1], down(2 * y1l - r[3]), y1h))
    return out


def cells(sites, box=None, periodic=None, tolerance=1e-9, tiles="auto", client=None, *, boundary_tolerance=None,
          rings=True, fmt="ell", halo=None):
    """The certified cells of ``sites`` (a path, an ellvor.Sites or Ellipses) computed in ``tiles`` = (nx, ny)
    tiles or "auto" (eight a worker, at least 8 sites a tile) on Dask: the cells ``ellvor.build(sites).
    cells(box=box, periodic=periodic, tolerance=tolerance, boundary_tolerance=..., rings=rings)`` gives
    (every interval containing the exact value, the same neighbours and visibility), as a TiledCells.

    Each tile computes the cells of the sites it owns among the sites near it (docs/DESIGN.md §8); a cell
    it cannot prove is computed again in a patch around its site, with doubling halos, and what is left
    (cells reaching infinity, a patch that would hold every site) in one task of the whole set. With a
    periodic box the tiles wrap: they hold the sites' copies shifted by whole periods that meet them.
    ``client``, ``halo`` as for ``build``. Bad input (arguments, sites outside the box) raises InputError
    here, before anything is sent; sites that cross so deeply that their edge runs through a medial axis raise
    it from the tiles that meet them."""
    sites = _sites_of(sites, fmt)
    t = _cell_number(tolerance, "tolerance")
    b = None if boundary_tolerance is None else _cell_number(boundary_tolerance, "boundary_tolerance")
    if b is not None and math.isnan(b):
        raise InputError("boundary_tolerance: expected a positive number, got nan")
    rectangle = _ellvor._check_cells(sites, box, periodic, t, b)
    start = time.perf_counter()
    c, close = _client_for(client)
    try:
        n = len(sites)
        if isinstance(tiles, str) and tiles == "auto":
            workers = max(1, len(c.scheduler_info().get("workers", {})))
            count = max(1, min(8 * workers, n // 8))
            nx = max(1, int(math.sqrt(count)))
            nx, ny = nx, max(1, count // nx)
        else:
            nx, ny = _tiles_argument(tiles, n, c)
        return _tiled_cells(c, sites, box, periodic, rectangle, t, b, bool(rings), nx, ny, halo, start)
    finally:
        close()


def _tiled_cells(client, sites, box, periodic, rectangle, tolerance, boundary_tolerance, rings, nx, ny, halo,
                 start):
    n = len(sites)
    period = None
    if periodic is not None and n:
        # The tiles wrap: the sites with their centers taken into the box (as one process takes them), and
        # the tiles hold the copies shifted by whole periods that meet their regions.
        x0, y0, x1, y1 = rectangle
        period = (x1 - x0, y1 - y0)
        wrapped = []
        for e in sites:
            kx, ky = math.floor((e.xc - x0) / period[0]), math.floor((e.yc - y0) / period[1])
            wrapped.append(e if kx == 0 and ky == 0 else
                           type(e)(e.a, e.b, e.w, e.xc - kx * period[0], e.yc - ky * period[1]))
        sites = _ellvor.Sites(wrapped)
    params, fractions, boxes = _site_arrays(sites)
    semi_axes = np.nextafter(np.maximum(params[:, 0], params[:, 1]), np.inf) if n else np.zeros(0)
    all_ids = np.arange(n, dtype=np.int64)
    domain = (box, periodic)
    if rings and boundary_tolerance is None and n:   # as one process chooses it: 1e-3 of the median size
        sizes = np.maximum(params[:, 0], params[:, 1])
        boundary_tolerance = 1e-3 * float(np.partition(sizes, n // 2)[n // 2])
    results = []
    tiles = []
    whole_reason = None

    def job(held, want, region, whole, tol):
        """_cells_task's arguments: held = (ids, shifts)."""
        ids, shifts = held
        if period is None or not shifts.any():
            payload, held_boxes = _payload(sites, fractions, ids), boxes[ids]
        else:
            lines = []
            for k, (i, j) in zip(ids.tolist(), shifts.tolist()):
                e = sites[k]
                lines.append(str(e) if i == 0 and j == 0 else
                             str(type(e)(e.a, e.b, e.w, e.xc + i * period[0], e.yc + j * period[1])))
            payload, held_boxes = "\n".join(lines), _shifted_boxes(boxes[ids], shifts, period)
        return (payload, ids, shifts, want, held_boxes, semi_axes[ids], (None, None) if whole is False and period
                else domain, tolerance, tol, rings, region, whole)

    def submit(held, want, region, whole, tol):
        return _submit(client, _cells_task, *job(held, want, region, whole, tol))

    def check(result):
        if "error" in result:
            _raise_worker_error(result, sites)
        return result

    def whole_task(want):
        r = check(submit((all_ids, np.zeros((n, 2), np.int64)), want, None, True, boundary_tolerance).result())
        results.append(r)
        return r

    rounds, whole_set_cells = 1, 0
    # (Cells pay for tiles from a few sites on: no lower count as the build's 16.)
    if n < 4 or nx * ny == 1 or not _in_double_range(params):
        whole_reason = "one tile" if nx * ny == 1 else "too few sites or extreme coordinates"
        r = whole_task(all_ids)
        whole_set_cells = n
        tiles.append({"index": (0, 0), "sites": n, "owned": n, "cells": len(r["sites"]), "retries": 0,
                      "seconds": r["seconds"], "cpu_seconds": r["cpu_seconds"], "rss_mb": r["rss_mb"]})
    else:
        centers = params[:, 3:5]
        grid = _Grid(centers, nx, ny)
        owner = grid.tile_of(centers)
        lo, hi = centers.min(axis=0), centers.max(axis=0)
        area = float((hi[0] - lo[0]) * (hi[1] - lo[1]))
        spacing = math.sqrt(area / n) if area > 0 else float(max(hi - lo)) / n
        h0 = halo if halo is not None else 4 * spacing + 1e-300
        # The areas' quadrature bounds the reach; edge covers where it gives none (Arb's integrator), without rings
        # coarsely (a few per cent of a spacing off is plenty).
        cover = boundary_tolerance if rings else spacing / 8
        walls = None
        if rectangle is not None:
            walls = [_double_bounds(v) for v in rectangle]   # x0, y0, x1, y1
        no_shift = np.zeros((n, 2), np.int64)

        def held_in(r):
            """(ids, shifts) of the sites (a box: or their mirrors; a periodic box: their copies) meeting r."""
            if period is None:
                held = _meets(boxes, r)
                if walls is not None:
                    for m in _mirror_regions(r, walls):
                        held |= _meets(boxes, m)
                ids = np.nonzero(held)[0]
                return ids, no_shift[:len(ids)]
            lx, ly = float(period[0]), float(period[1])
            bx0, bx1, by0, by1 = boxes[:, 0].min(), boxes[:, 1].max(), boxes[:, 2].min(), boxes[:, 3].max()
            out_ids, out_shifts = [], []
            for i in range(math.floor((r[0] - bx1) / lx) - 1, math.ceil((r[1] - bx0) / lx) + 2):
                for j in range(math.floor((r[2] - by1) / ly) - 1, math.ceil((r[3] - by0) / ly) + 2):
                    # A copy shifted by s meets r when the site meets r - s (s rounded: widened).
                    sx, sy = i * lx, j * ly
                    mx, my = abs(sx) * 2.0 ** -50, abs(sy) * 2.0 ** -50
                    moved = (float(np.nextafter(r[0] - sx - mx, -np.inf)), float(np.nextafter(r[1] - sx + mx, np.inf)),
                             float(np.nextafter(r[2] - sy - my, -np.inf)), float(np.nextafter(r[3] - sy + my, np.inf)))
                    ids = np.nonzero(_meets(boxes, moved))[0]
                    out_ids.append(ids)
                    out_shifts.append(np.tile(np.array([[i, j]], np.int64), (len(ids), 1)))
            return np.concatenate(out_ids), np.concatenate(out_shifts)

        def owned_positions(held, own):
            """Where the owned sites, unshifted, are in held."""
            ids, shifts = held
            zero = np.nonzero(~shifts.any(axis=1))[0]
            return zero[np.searchsorted(ids[zero], own)]

        def clipped(x0, x1, y0, y1):
            if walls is None:   # (a periodic box: the grid is in it; its outer tiles are clipped to it too)
                return x0, x1, y0, y1
            return max(x0, walls[0][0]), min(x1, walls[2][1]), max(y0, walls[1][0]), min(y1, walls[3][1])

        futures = {}
        index_of = {}
        for t in range(nx * ny):
            own = np.nonzero(owner == t)[0]
            if len(own) == 0:
                continue
            x0, x1, y0, y1 = clipped(*grid.rect(t))
            region = (float(np.nextafter(x0 - h0, -np.inf)), float(np.nextafter(x1 + h0, np.inf)),
                      float(np.nextafter(y0 - h0, -np.inf)), float(np.nextafter(y1 + h0, np.inf)))
            held = held_in(region)
            futures[t] = submit(held, owned_positions(held, own), region, False, cover)
            index_of[t] = len(tiles)
            tiles.append({"index": divmod(t, ny), "sites": len(held[0]), "owned": len(own), "cells": 0, "retries": 0,
                          "seconds": 0.0, "cpu_seconds": 0.0, "rss_mb": 0.0})

        def collect(t, r):
            tile = tiles[index_of[t]]
            tile["cells"] += len(r["sites"])
            tile["seconds"] += r["seconds"]
            tile["cpu_seconds"] += r["cpu_seconds"]
            tile["rss_mb"] = max(tile["rss_mb"], r["rss_mb"])
            results.append(r)

        open_sites, open_reach, open_unbounded = [], [], []
        for t, f in futures.items():
            r = check(f.result())
            collect(t, r)
            open_sites.append(r["open"]), open_reach.append(r["open_reach"]), open_unbounded.append(r["open_unbounded"])
        pending = np.concatenate(open_sites) if open_sites else np.zeros(0, np.int64)
        reach = np.concatenate(open_reach) if open_reach else np.zeros(0)
        unbounded = np.concatenate(open_unbounded) if open_unbounded else np.zeros(0, bool)
        leftover = []
        if walls is None and unbounded.any():
            # A cell unbounded in its tile is the whole diagram's unbounded cell only on the hull: sites that
            # may touch the hull's boundary go to the whole set at once, the others to patches.
            candidates, _ = _hull_candidates(params, boxes, 0.0)
            hull_side = unbounded & np.isin(pending, candidates)
            leftover.append(pending[hull_side])
            pending, reach = pending[~hull_side], reach[~hull_side]
        patch = np.full(n, 2.0 * h0)
        while len(pending):
            rounds += 1
            if rounds > 8:
                leftover.append(pending)
                break
            batches = {}
            for p, rp in zip(pending.tolist(), reach.tolist()):
                # Wide enough for the cell found (the whole diagram's lies inside it), at least double the last.
                width = max(patch[p], 2.0 * np.nextafter(max(rp, semi_axes[p]), np.inf) * (1 + 1e-9)
                            if math.isfinite(rp) else 0.0)
                patch[p] = 2 * width
                r = (float(np.nextafter(boxes[p, 0] - width, -np.inf)), float(np.nextafter(boxes[p, 1] + width, np.inf)),
                     float(np.nextafter(boxes[p, 2] - width, -np.inf)), float(np.nextafter(boxes[p, 3] + width, np.inf)))
                held = held_in(r)
                if period is None and len(held[0]) == n:
                    leftover.append(np.array([p]))
                    continue
                batches.setdefault(int(owner[p]), []).append(
                    job(held, owned_positions(held, np.array([p])), r, False, cover))
                tiles[index_of[int(owner[p])]]["retries"] += 1
            futures = {t: _submit(client, _cell_patches_task, jobs) for t, jobs in batches.items()}
            next_pending, next_reach = [], []
            for t, f in futures.items():
                rs = f.result()
                if isinstance(rs, dict):
                    check(rs)
                for r in rs:
                    collect(t, r)
                    next_pending.append(r["open"]), next_reach.append(r["open_reach"])
            pending = np.concatenate(next_pending) if next_pending else np.zeros(0, np.int64)
            reach = np.concatenate(next_reach) if next_reach else np.zeros(0)
        leftover = np.unique(np.concatenate(leftover)) if leftover else np.zeros(0, np.int64)
        if len(leftover):
            whole_reason = f"{len(leftover)} cells in one task of the whole set (unbounded, or no tile proved them)"
            whole_task(leftover)
            whole_set_cells = len(leftover)
    stats = {"rounds": rounds, "fallback": whole_reason or False, "whole_set_cells": whole_set_cells}
    arrays = _assemble_cells(results, n, rings)
    arrays["boundary_tolerance"] = boundary_tolerance if rings else 0.0
    arrays["domain"] = "plane" if rectangle is None else ("box" if box is not None else "periodic")
    if rectangle is not None:
        arrays["box"] = tuple(rectangle)
    stats["seconds"] = time.perf_counter() - start
    return TiledCells(arrays, tiles, stats)


def _shifted_boxes(boxes, shifts, period):
    """Bounding boxes moved by whole periods, rounded outward."""
    sx, sy = shifts[:, 0] * float(period[0]), shifts[:, 1] * float(period[1])
    mx, my = np.abs(sx) * 2.0 ** -50, np.abs(sy) * 2.0 ** -50
    return np.stack([np.nextafter(boxes[:, 0] + sx - mx, -np.inf), np.nextafter(boxes[:, 1] + sx + mx, np.inf),
                     np.nextafter(boxes[:, 2] + sy - my, -np.inf), np.nextafter(boxes[:, 3] + sy + my, np.inf)], axis=1)


def _assemble_cells(results, n, rings):
    """Every site's cell from the tasks' certified ones (the first certificate of a site counts), sides in
    CSR form, vertices merged by their faces' keys and numbered in order of first use."""
    sites = np.concatenate([r["sites"] for r in results])
    first_of, where = np.unique(sites, return_index=True)
    if len(first_of) != n:
        raise Error(f"tiled cells: {n - len(first_of)} cells were not computed")
    columns = {key: np.concatenate([r[key] for r in results])[where] for key in _CELL_COLUMNS}
    counts = np.concatenate([r["counts"] for r in results])
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]]).astype(np.int64)
    new_counts = counts[where]
    indptr = np.concatenate([[0], np.cumsum(new_counts)]).astype(np.int64)
    pos = (np.arange(indptr[-1]) - np.repeat(indptr[:-1], new_counts) + np.repeat(starts[where], new_counts))
    # Vertices: each task's local numbers to rows of all keys, then to unique keys.
    offsets = np.cumsum([0] + [len(r["vertex_keys"]) for r in results])
    keys = np.concatenate([r["vertex_keys"] for r in results]).reshape(-1, 12)
    side_vertices = np.concatenate([np.where(r["side_vertices"] >= 0, r["side_vertices"] + off, -1)
                                    for r, off in zip(results, offsets)]).reshape(-1, 2)[pos]
    if len(keys):
        unique_keys, first_row, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
        inverse = inverse.ravel()
    else:
        first_row, inverse = np.zeros(0, np.int64), np.zeros(0, np.int64)
    flat = side_vertices.ravel()
    merged = np.where(flat >= 0, inverse[np.maximum(flat, 0)] if len(inverse) else -1, -1)
    used = merged[merged >= 0]
    _, first_use = np.unique(used, return_index=True)
    order = np.unique(used)[np.argsort(first_use)]         # merged ids in order of first use
    number = np.full(len(first_row) + 1, -1, dtype=np.int64)
    number[order] = np.arange(len(order))
    side_vertices = number[merged].reshape(-1, 2)
    rows = first_row[order]
    vlo = np.concatenate([r["vertices_lo"] for r in results]).reshape(-1, 2)[rows]
    vhi = np.concatenate([r["vertices_hi"] for r in results]).reshape(-1, 2)[rows]
    key_rows = keys[rows].reshape(-1, 3, 4)
    out = dict(columns)
    out.update(indptr=indptr, indices=np.concatenate([r["indices"] for r in results])[pos],
               shifts=np.concatenate([r["shifts"] for r in results]).reshape(-1, 2)[pos],
               side_vertices=side_vertices, vertices_lo=vlo, vertices_hi=vhi,
               vertex_sites=key_rows[:, :, 0], vertex_walls=key_rows[:, :, 1], vertex_shifts=key_rows[:, :, 2:])
    if rings:
        ring_list = [ring for r in results for ring in r["rings"]]
        out["rings"] = [ring_list[k] for k in where]
    else:
        out["rings"] = [np.zeros((0, 2)) for _ in range(n)]
    return out


def _file_task(text, fmt, name, cell_options=None):
    """Builds one file's whole diagram from its text (already checked on the client); with
    ``cell_options``, computes its cells (Cells' arrays)."""
    start, cpu = time.perf_counter(), time.process_time()
    try:
        sites = _ellvor._sites_from_text(text, fmt, name)
        if cell_options is not None:
            o = cell_options
            arrays = _ellvor._cells(sites, o["box"], o["periodic"], o["tolerance"], o["boundary_tolerance"],
                                    o["rings"]).arrays()
            return {"cells": arrays, "seconds": time.perf_counter() - start,
                    "cpu_seconds": time.process_time() - cpu, "rss_mb": _rss_mb()}
        d = _ellvor._build(sites, fmt, None, 0.1)
    except InputError as e:
        return {"error": (str(e), e.sites)}
    return {"hidden": d.hidden(), "edges": d.edges(), "faces": d.faces(), "hull": d.hull(),
            "seconds": time.perf_counter() - start, "cpu_seconds": time.process_time() - cpu, "rss_mb": _rss_mb()}


def map(files, fn="build", client=None, *, fmt="ell", progress=False, box=None, periodic=None, tolerance=1e-9,
        boundary_tolerance=None, rings=True):
    """One diagram per file (a simulation's snapshots), each computed whole on a Dask worker: yields
    ``(file, result)`` as they finish. ``fn="build"``: ``result`` a TiledDiagram of one tile (its
    ``stats["fallback"]`` says "one file"); ``fn="cells"``: a TiledCells of one tile, the cells
    ``ellvor.build(file).cells(box=, periodic=, tolerance=, boundary_tolerance=, rings=)`` gives.
    Every file is read and checked on the client first (InputError, as ``ellvor.build`` and ``cells``
    raise it), then sent as its text. ``client`` as for ``build``. ``progress``: True prints
    "built k of n files" on standard error; the Dask dashboard shows the tasks too."""
    if fn not in ("build", "cells"):
        raise ValueError(f"fn: expected 'build' or 'cells', got {fn!r}")
    cell_options = None
    if fn == "cells":
        t = _cell_number(tolerance, "tolerance")
        b = None if boundary_tolerance is None else _cell_number(boundary_tolerance, "boundary_tolerance")
        cell_options = {"box": box, "periodic": periodic, "tolerance": t, "boundary_tolerance": b,
                        "rings": bool(rings)}
    paths = [os.fspath(f) for f in files]
    checked = []
    for path in paths:  # everything is checked before anything is sent
        sites = _ellvor.read_sites(path, fmt)
        if cell_options is not None:
            _ellvor._check_cells(sites, box, periodic, cell_options["tolerance"], cell_options["boundary_tolerance"])
        with open(path, encoding="utf-8") as f:
            checked.append((path, sites, f.read()))
    return _map_files(checked, fmt, client, progress, cell_options)


def _map_files(checked, fmt, client, progress, cell_options=None):
    from distributed import as_completed
    c, close = _client_for(client)
    try:
        futures = {}
        for path, sites, text in checked:
            futures[_submit(c, _file_task, text, fmt, path, cell_options)] = (path, sites)
        for done, future in enumerate(as_completed(futures), 1):
            path, sites = futures.pop(future)
            result = future.result()
            if "error" in result:
                message, pair = result["error"]
                raise InputError(message, filename=path, sites=None if pair is None else tuple(pair))
            if cell_options is not None:
                tile = {"index": (0, 0), "sites": len(sites), "owned": len(sites), "cells": len(sites),
                        "retries": 0, "seconds": result["seconds"], "cpu_seconds": result["cpu_seconds"],
                        "rss_mb": result["rss_mb"]}
                d = TiledCells(result["cells"], [tile], {"rounds": 1, "fallback": "one file",
                                                         "whole_set_cells": len(sites), "seconds": result["seconds"]})
            else:
                d = _one_file_diagram(sites, result)
            if progress:
                import sys
                what = "cells of" if cell_options is not None else "built"
                sys.stderr.write(f"\r{what} {done} of {len(checked)} files" + ("\n" if done == len(checked) else ""))
                sys.stderr.flush()
            yield path, d
    finally:
        for future in futures:
            future.cancel()
        close()


def _one_file_diagram(sites, result):
    tile = {"index": (0, 0), "sites": len(sites), "owned": len(sites), "halo_sites": 0, "halo": math.inf,
            "tile_faces": len(result["faces"]), "certified": len(result["faces"]),
            "faces_kept": len(result["faces"]), "retries": 0, "seconds": result["seconds"],
            "cpu_seconds": result["cpu_seconds"], "rss_mb": result["rss_mb"]}
    d = TiledDiagram(sites, result["hidden"], result["edges"], result["faces"], result["hull"], [tile],
                     {"rounds": 1, "fallback": "one file", "hull_candidates": len(sites),
                      "seconds": result["seconds"]})
    return d
