"""ellvor.distributed: the Delaunay graph built in tiles on dask.distributed.

    import ellvor.distributed
    d = ellvor.distributed.build("big.ell", tiles=(4, 4))            # a LocalCluster, one worker per core
    d = ellvor.distributed.build(sites, client="tcp://host:8786")    # a running scheduler
    d.edges, d.faces, d.hidden, d.hull                                 # as ellvor.build(sites) gives them
    d.tiles                                                            # per tile: sites, halo, faces kept, ...
    for path, d in ellvor.distributed.map(snapshots):                  # one whole diagram per file, as they finish
        ...

Each tile builds the diagram of the sites near it (its own and a halo) and keeps
only the faces it can prove are faces of the whole diagram; the seam argument,
the ownership and the retry rules are in docs/DESIGN.md §8 ("The tiled build").
Where the faces do not close up, patches around the sites concerned are built
with doubling halos; a region that would hold every site, or too many open
sites, fall back to one build of the whole set (``stats["fallback"]`` says why).
"""

import functools
import math
import os
import time
import warnings

import numpy as np

from . import _ellvor
from ._diagram import _frozen
from ._errors import Error, InputError

# The sites' bounding boxes are computed in doubles from the rounded parameters and then widened by this
# fraction of their magnitude (and one ulp): at most a few dozen roundings of 2^-53 each precede it.
_BOX_MARGIN = 2.0 ** -40
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


def _bounding_boxes(params):
    """Per site (xlo, xhi, ylo, yhi), containing the exact ellipse (outward, see _BOX_MARGIN)."""
    a, b, w, xc, yc = params.T
    c = (1 - w * w) / (1 + w * w)   # cos and sin of the a-axis' angle, w = tan(angle / 2)
    s = 2 * w / (1 + w * w)
    hx = np.sqrt((a * c) ** 2 + (b * s) ** 2)
    hy = np.sqrt((a * s) ** 2 + (b * c) ** 2)
    mx = _BOX_MARGIN * (np.abs(xc) + a + b) + 5e-324
    my = _BOX_MARGIN * (np.abs(yc) + a + b) + 5e-324
    return np.stack([np.nextafter(xc - hx - mx, -np.inf), np.nextafter(xc + hx + mx, np.inf),
                     np.nextafter(yc - hy - my, -np.inf), np.nextafter(yc + hy + my, np.inf)], axis=1)


def _in_double_range(params):
    m = np.abs(params)
    return bool(np.all(np.isfinite(m)) and np.all((m == 0) | ((m > _TINY) & (m < _HUGE))))


class _Grid:
    """nx x ny half-open tiles [x_i, x_(i+1)) x [y_j, y_(j+1)) covering the plane: the inner lines split the
    centers' bounding box evenly, the outer tiles reach infinity."""

    def __init__(self, centers, nx, ny):
        lo, hi = centers.min(axis=0), centers.max(axis=0)
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


def _local_sites(text):
    """A tile's sites from the .ell lines it was sent (parsed in C++, as a file's)."""
    return _ellvor._sites_from_text(text)


def _possibly_degenerate(faces, boxes):
    """Faces whose circle box meets that of a face across one of their edges: possibly the same circle
    (four or more sites on one empty circle), whose triangulation depends on the insertion order."""
    f = len(faces)
    if f == 0:
        return np.zeros(0, dtype=bool)
    m = int(faces.max()) + 1
    a, b = faces, np.roll(faces, -1, axis=1)          # directed edges a -> b of each face
    keys = (a * m + b).ravel()
    owner = np.repeat(np.arange(f), 3)
    order = np.argsort(keys, kind="stable")
    keys, owner = keys[order], owner[order]
    twins = (b * m + a).ravel()
    lo, hi = np.searchsorted(keys, twins, "left"), np.searchsorted(keys, twins, "right")
    me = np.repeat(np.arange(f), 3)

    def overlap(x, y):
        return ((x[:, 0] <= y[:, 1]) & (y[:, 0] <= x[:, 1]) & (x[:, 2] <= y[:, 3]) & (y[:, 2] <= x[:, 3]) &
                (x[:, 4] <= y[:, 5]) & (y[:, 4] <= x[:, 5]))

    suspect = np.zeros(f, dtype=bool)
    for extra in range(int((hi - lo).max(initial=0))):   # the k-th face across each edge (an edge held twice)
        k = np.nonzero(hi - lo > extra)[0]
        hit = overlap(boxes[me[k]], boxes[owner[lo[k] + extra]])
        suspect[me[k[hit]]] = True
    return suspect


def _disk_misses_outside(circles, r, everything):
    """Faces whose closed disk (radius max(rho, 0): a circle with rho <= 0 is its center) misses the closure
    of B minus R, B = ``everything`` the box of all sites, R = ``r`` the tile's region, for every center and
    radius in the face's box; in doubles rounded the safe way. B minus R is covered by four closed slabs."""
    bx0, bx1, by0, by1 = everything
    slabs = [(bx0, r[0], by0, by1), (r[1], bx1, by0, by1), (bx0, bx1, by0, r[2]), (bx0, bx1, r[3], by1)]
    rho = np.maximum(circles[:, 5], 0.0)
    rho2 = np.nextafter(rho * rho, np.inf)
    ok = np.ones(len(circles), dtype=bool)
    with np.errstate(invalid="ignore", over="ignore"):
        for x0, x1, y0, y1 in slabs:
            if not (x0 <= x1 and y0 <= y1):
                continue  # empty: R covers B on that side
            # A lower bound of the distance from the center box to the slab, per axis and squared.
            dx = np.maximum(np.maximum(np.nextafter(x0 - circles[:, 1], -np.inf),
                                       np.nextafter(circles[:, 0] - x1, -np.inf)), 0.0)
            dy = np.maximum(np.maximum(np.nextafter(y0 - circles[:, 3], -np.inf),
                                       np.nextafter(circles[:, 2] - y1, -np.inf)), 0.0)
            d2 = np.nextafter(np.nextafter(dx * dx, -np.inf) + np.nextafter(dy * dy, -np.inf), -np.inf)
            ok &= d2 > rho2   # NaN (an overflow) compares False: not certified
    return ok


def _tile_task(text, ids, boxes, region, rect, everything, whole):
    """Builds one tile's diagram and returns what it proves about the whole one (global ids)."""
    start, cpu = time.perf_counter(), time.process_time()
    sites = _local_sites(text)
    try:
        d = _ellvor._build(sites, "ell", None, 0.1)
    except InputError as e:
        pair = None if e.sites is None else tuple(int(ids[k]) for k in e.sites)
        return {"error": (e.reason, pair)}
    faces = d.faces()
    hidden = d.hidden()
    circle = d.circle_boxes()
    if whole:
        certified = np.ones(len(faces), dtype=bool)
        visible_sure = np.ones(len(ids), dtype=bool)
    else:
        certified = _disk_misses_outside(circle, region, everything) & ~_possibly_degenerate(faces, circle)
        visible_sure = _inside(boxes, region)
    visible_sure[hidden[:, 0]] = False
    kept = faces[certified]
    centers = np.stack([(circle[:, 0] + circle[:, 1]) / 2, (circle[:, 2] + circle[:, 3]) / 2], axis=1)[certified]
    owned = ((centers[:, 0] >= rect[0]) & (centers[:, 0] < rect[1]) & (centers[:, 1] >= rect[2]) &
             (centers[:, 1] < rect[3]))
    out = {
        "faces": ids[kept], "hidden": ids[hidden], "visible": ids[np.nonzero(visible_sure)[0]],
        "tile_faces": len(faces), "certified": int(certified.sum()), "owned_faces": int(owned.sum()),
        "seconds": time.perf_counter() - start, "cpu_seconds": time.process_time() - cpu, "rss_mb": _rss_mb(),
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
    for key in ("tile_faces", "certified", "owned_faces", "seconds", "cpu_seconds"):
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
    directions = [(math.cos(2 * math.pi * k / 32), math.sin(2 * math.pi * k / 32)) for k in range(32)]
    chosen = sorted({int(np.argmax(dx * xc + dy * yc)) for dx, dy in directions})
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
    inside = np.ones(n, dtype=bool)
    for cx, cy in [(boxes[:, 0], boxes[:, 2]), (boxes[:, 1], boxes[:, 2]), (boxes[:, 0], boxes[:, 3]),
                   (boxes[:, 1], boxes[:, 3])]:
        for edge in _beyond_edges(polygon, cx, cy, depth):
            inside &= edge
    inside[corner_sites] = False
    return np.nonzero(~inside)[0], polygon


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


def _beyond_edges_varying(polygon, px, py, rho, shift):
    """As _beyond_edges, with a per-point margin: cross(e, x - p) > bound + (rho + shift) |e| (|e| rounded
    up), for polygon edges given clockwise (so "inside" is outside the counter-clockwise polygon)."""
    out = []
    for (ax, ay), (bx, by) in zip(polygon, polygon[1:] + polygon[:1]):
        ex, ey = bx - ax, by - ay
        left, right = ex * (py - ay), ey * (px - ax)
        bound = 4 * _EPS * (np.abs(left) + np.abs(right)) + 4 * _EPS * (abs(ex) + abs(ey)) * (
            np.abs(px - ax) + np.abs(py - ay))
        length = math.hypot(ex, ey) * (1 + 4 * _EPS)
        margin = np.nextafter(np.maximum(rho + shift, 0.0) * length, np.inf) * (1 + 4 * _EPS)
        out.append(left - right > bound + margin)
    return out


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


def _hull_task(text, ids, polygon, depth):
    """The candidates' graph: its hull faces are those of the whole graph, and so are its finite faces whose
    disk misses the non-candidates' region (docs/DESIGN.md §8); its hidden sites are hidden."""
    start, cpu = time.perf_counter(), time.process_time()
    try:
        d = _ellvor._build(_local_sites(text), "ell", None, 0.1)
    except InputError as e:
        pair = None if e.sites is None else tuple(int(ids[k]) for k in e.sites)
        return {"error": (e.reason, pair)}
    faces = d.faces()
    circles = d.circle_boxes()
    if len(polygon) >= 3:
        certified = _disk_outside_polygon(circles, polygon, depth) & ~_possibly_degenerate(faces, circles)
    else:
        certified = np.ones(len(faces), dtype=bool)   # every site is a candidate
    return {"hull": ids[d.hull()], "faces": ids[faces[certified]], "hidden": ids[d.hidden()],
            "visible": np.zeros(0, dtype=np.int64), "tile_faces": len(faces), "certified": int(certified.sum()),
            "owned_faces": 0, "seconds": time.perf_counter() - start, "cpu_seconds": time.process_time() - cpu,
            "rss_mb": _rss_mb()}


def _raise_worker_error(result):
    reason, pair = result["error"]
    if pair is not None:
        pair = tuple(sorted(pair))
        raise InputError(f"sites {pair[0]} and {pair[1]}: {reason}", sites=pair, reason=reason)
    raise InputError(reason)


def _edges_of(faces, hull):
    """Finite Delaunay edges (i < j) from the faces: edge {i, j} once per directed occurrence of i -> j."""
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]], hull])
    up = directed[directed[:, 0] < directed[:, 1]]
    return up[np.lexsort((up[:, 1], up[:, 0]))]


def _open_edges(faces, hull):
    """Sites on directed edges whose count differs from their twin's: where faces are missing."""
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]], hull])
    if len(directed) == 0:
        return np.zeros(0, dtype=np.int64)
    m = int(directed.max()) + 1
    keys = np.sort(directed[:, 0] * m + directed[:, 1])
    twins = np.sort(directed[:, 1] * m + directed[:, 0])
    pairs, counts = np.unique(keys, return_counts=True)
    twin_pairs, twin_counts = np.unique(twins, return_counts=True)
    if len(pairs) == len(twin_pairs) and np.array_equal(pairs, twin_pairs) and np.array_equal(counts, twin_counts):
        return np.zeros(0, dtype=np.int64)
    both = np.union1d(pairs, twin_pairs)
    count = np.zeros(len(both), dtype=np.int64)
    count[np.searchsorted(both, pairs)] = counts
    twin_count = np.zeros(len(both), dtype=np.int64)
    twin_count[np.searchsorted(both, twin_pairs)] = twin_counts
    bad = both[count != twin_count]
    return np.unique(np.concatenate([bad // m, bad % m]))


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
    in the tile), retries (patches built later around its sites, docs/DESIGN.md §8), seconds and
    cpu_seconds (its tile and patches), rss_mb (its worker's resident memory with the graph built: its
    peak, near enough). ``stats``: rounds, fallback (False, or why one build of the whole set decided),
    hull_candidates, seconds (wall time of the call)."""

    def __init__(self, sites, hidden, edges, faces, hull, tiles, stats):
        self.sites = sites
        arrays = (hidden, edges, faces, hull)   # (no map(): this module defines its own)
        self.hidden, self.edges, self.faces, self.hull = (_frozen(np.asarray(a)) for a in arrays)
        self.tiles, self.stats = tiles, stats

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


def _client_for(client):
    """(client, close): a Client for the argument; close() ends what was started here."""
    from distributed import Client, LocalCluster
    if client is None:
        cluster = LocalCluster(n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address=None)
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
    params = sites.to_array()
    c, close = _client_for(client)
    try:
        nx, ny = _tiles_argument(tiles, n, c)
        return _tiled_build(c, sites, params, nx, ny, halo, start)
    finally:
        close()


def _tiled_build(client, sites, params, nx, ny, halo, start):
    n = len(sites)
    lines = np.array([str(e) for e in sites], dtype=object)
    boxes = _bounding_boxes(params) if n else np.zeros((0, 4))
    all_ids = np.arange(n, dtype=np.int64)

    everything = (float(boxes[:, 0].min()), float(boxes[:, 1].max()), float(boxes[:, 2].min()),
                  float(boxes[:, 3].max())) if n else (0.0, 0.0, 0.0, 0.0)

    def submit_tile(ids, region, rect, whole):
        # The sites go in the task itself, not scattered: the scheduler keeps a task's arguments, so a
        # tile whose worker dies runs again elsewhere (scattered data would die with the worker).
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message="Large object", category=UserWarning)
            return client.submit(_tile_task, "\n".join(lines[ids]), ids, boxes[ids], region, rect, everything,
                                 whole, pure=False)

    def one_build(reason):
        result = submit_tile(all_ids, (-np.inf, np.inf, -np.inf, np.inf), (-np.inf, np.inf, -np.inf, np.inf),
                             True).result()
        if "error" in result:
            _raise_worker_error(result)
        tile = {"index": (0, 0), "sites": n, "owned": n, "halo_sites": 0, "halo": math.inf,
                "tile_faces": result["tile_faces"], "certified": result["certified"],
                "faces_kept": result["certified"], "retries": 0, "seconds": result["seconds"],
                "cpu_seconds": result["cpu_seconds"], "rss_mb": result["rss_mb"]}
        return TiledDiagram(sites, _sorted_rows(result["hidden"], 2), result["edges"],
                            _sorted_rows(result["faces"], 3), _sorted_rows(result["hull"], 2), [tile],
                            {"rounds": 1, "fallback": reason, "hull_candidates": n,
                             "seconds": time.perf_counter() - start})

    if n < 16 or nx * ny == 1 or not _in_double_range(params):
        return one_build("one tile" if nx * ny == 1 else "too few sites or extreme coordinates")

    grid = _Grid(params[:, 3:5], nx, ny)
    owner = grid.tile_of(params[:, 3:5])
    lo, hi = params[:, 3:5].min(axis=0), params[:, 3:5].max(axis=0)
    area = float((hi[0] - lo[0]) * (hi[1] - lo[1]))
    spacing = math.sqrt(area / n) if area > 0 else float(max(hi - lo)) / n
    halos = np.full(nx * ny, halo if halo is not None else 4 * spacing + 1e-300)
    tiles = [{"index": divmod(t, ny), "sites": 0, "owned": int((owner == t).sum()), "halo_sites": 0, "halo": 0.0,
              "tile_faces": 0, "certified": 0, "faces_kept": 0, "retries": -1, "seconds": 0.0, "cpu_seconds": 0.0, "rss_mb": 0.0}
             for t in range(nx * ny)]

    candidates, polygon = _hull_candidates(params, boxes, halos.max())
    hull_future = client.submit(_hull_task, "\n".join(lines[candidates]), candidates, polygon,
                                halos.max(), pure=False)

    faces_found, hidden_found, visible_found = [np.zeros((0, 3), np.int64)], [np.zeros((0, 2), np.int64)], []

    def covers_everything(region, held):
        return len(held) == n or (region[0] <= everything[0] and region[1] >= everything[1] and
                                  region[2] <= everything[2] and region[3] >= everything[3])

    def collect(t, result):
        if "error" in result:
            _raise_worker_error(result)
        faces_found.append(result["faces"])
        hidden_found.append(result["hidden"])
        visible_found.append(result["visible"])
        tiles[t]["tile_faces"] += result["tile_faces"]
        tiles[t]["certified"] += result["certified"]
        tiles[t]["faces_kept"] += result["owned_faces"]
        tiles[t]["seconds"] += result["seconds"]
        tiles[t]["cpu_seconds"] += result["cpu_seconds"]
        tiles[t]["rss_mb"] = max(tiles[t]["rss_mb"], result["rss_mb"])

    # Round 1: the tiles.
    futures = {}
    for t in range(nx * ny):
        if not (owner == t).any():
            continue
        region = grid.region(t, halos[t])
        held = np.nonzero(_meets(boxes, region))[0]
        if covers_everything(region, held):
            return one_build(f"the halo of tile {divmod(t, ny)} holds the whole set")
        futures[t] = submit_tile(held, region, grid.rect(t), False)
        tiles[t].update(sites=len(held), halo_sites=len(held) - tiles[t]["owned"], halo=float(halos[t]), retries=0)
    for t, f in futures.items():
        collect(t, f.result())
    h = hull_future.result()
    if "error" in h:
        _raise_worker_error(h)
    hull = h["hull"]
    faces_found.append(h["faces"])
    hidden_found.append(h["hidden"])

    # Later rounds: a patch around each site on a face that is missing, its halo doubling each round.
    patch_halo = np.full(n, 2.0 * halos.max())
    rounds = 1
    while True:
        faces = np.unique(np.concatenate(faces_found), axis=0)
        faces_found = [faces]
        hidden_all = np.concatenate(hidden_found)
        is_hidden = np.zeros(n, dtype=bool)
        is_hidden[hidden_all[:, 0]] = True
        is_visible = np.zeros(n, dtype=bool)
        is_visible[faces.ravel()] = True
        for v in visible_found:
            is_visible[v] = True
        if (is_hidden & is_visible).any():
            raise Error(f"tiled build: site {int(np.nonzero(is_hidden & is_visible)[0][0])} both hidden and visible")
        accepted = hull[is_visible[hull[:, 0]] & is_visible[hull[:, 1]]] if len(hull) else hull.reshape(-1, 2)
        unknown = np.nonzero(~is_hidden & ~is_visible)[0]
        open_sites = np.union1d(_open_edges(faces, accepted), unknown)
        n_visible = int(is_visible.sum())
        if len(open_sites) == 0:
            if len(faces) + len(accepted) == 2 * n_visible - 2:
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
                ("\n".join(lines[held]), held, boxes[held], r, (0.0, 0.0, 0.0, 0.0), everything, False))
            tiles[int(owner[p])]["retries"] += 1
        futures = {t: client.submit(_patches_task, jobs, pure=False) for t, jobs in batches.items()}
        for t, f in futures.items():
            collect(t, f.result())

    # Hidden: one host per hidden site, the first tile's that reported it (sorted by hidden id).
    hidden_all = hidden_all[np.argsort(hidden_all[:, 0], kind="stable")]
    first = np.concatenate([[True], hidden_all[1:, 0] != hidden_all[:-1, 0]]) if len(hidden_all) else []
    hidden = hidden_all[first]
    accepted = _sorted_rows(accepted, 2)
    return TiledDiagram(sites, hidden, _edges_of(faces, accepted), _sorted_rows(faces, 3), accepted,
                        [t for t in tiles if t["retries"] >= 0],
                        {"rounds": rounds, "fallback": False, "hull_candidates": len(candidates),
                         "seconds": time.perf_counter() - start})


def _file_task(text, fmt, name):
    """Builds one file's whole diagram from its text (already checked on the client)."""
    start, cpu = time.perf_counter(), time.process_time()
    try:
        d = _ellvor._build(_ellvor._sites_from_text(text, fmt, name), fmt, None, 0.1)
    except InputError as e:
        return {"error": (str(e), e.sites)}
    return {"hidden": d.hidden(), "edges": d.edges(), "faces": d.faces(), "hull": d.hull(),
            "seconds": time.perf_counter() - start, "cpu_seconds": time.process_time() - cpu, "rss_mb": _rss_mb()}


def map(files, fn="build", client=None, *, fmt="ell", progress=False):
    """One diagram per file (a simulation's snapshots), each built whole on a Dask worker: yields
    ``(file, diagram)`` as they finish, ``diagram`` a TiledDiagram of one tile (its ``stats["fallback"]``
    says "one file"). Every file is read and checked on the client first (InputError, as ``ellvor.build``
    raises it), then sent as its text. ``client`` as for ``build``. ``progress``: True prints
    "built k of n files" on standard error; the Dask dashboard shows the tasks too. ``fn``: "build"
    (cells are not available on Dask yet)."""
    if fn != "build":
        raise ValueError(f"fn: expected 'build', got {fn!r} (cells are not available on Dask yet)")
    paths = [os.fspath(f) for f in files]
    checked = []
    for path in paths:  # everything is checked before anything is sent
        sites = _ellvor.read_sites(path, fmt)
        with open(path, encoding="utf-8") as f:
            checked.append((path, sites, f.read()))
    return _map_files(checked, fmt, client, progress)


def _map_files(checked, fmt, client, progress):
    from distributed import as_completed
    c, close = _client_for(client)
    try:
        futures = {}
        for path, sites, text in checked:
            with warnings.catch_warnings():
                warnings.filterwarnings("ignore", message="Large object", category=UserWarning)
                futures[c.submit(_file_task, text, fmt, path, pure=False)] = (path, sites)
        for done, future in enumerate(as_completed(futures), 1):
            path, sites = futures.pop(future)
            result = future.result()
            if "error" in result:
                message, pair = result["error"]
                raise InputError(message, filename=path, sites=None if pair is None else tuple(pair))
            tile = {"index": (0, 0), "sites": len(sites), "owned": len(sites), "halo_sites": 0, "halo": math.inf,
                    "tile_faces": len(result["faces"]), "certified": len(result["faces"]),
                    "faces_kept": len(result["faces"]), "retries": 0, "seconds": result["seconds"],
                    "cpu_seconds": result["cpu_seconds"], "rss_mb": result["rss_mb"]}
            d = TiledDiagram(sites, result["hidden"], result["edges"], result["faces"], result["hull"], [tile],
                             {"rounds": 1, "fallback": "one file", "hull_candidates": len(sites),
                              "seconds": result["seconds"]})
            if progress:
                import sys
                sys.stderr.write(f"\rbuilt {done} of {len(checked)} files" + ("\n" if done == len(checked) else ""))
                sys.stderr.flush()
            yield path, d
    finally:
        for future in futures:
            future.cancel()
        close()
