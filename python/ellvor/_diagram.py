"""ellvor.build and the Diagram it returns."""

import functools
import json
import numbers
import operator
import os
import sys
from fractions import Fraction

import numpy as np

from . import _ellvor
from ._cells import cells as _cells


class Ball:
    """A certified enclosure ``[lo, hi]`` of a real number.

    ``lo`` and ``hi`` are exact Fractions (Arb's dyadic endpoints); ``text`` is
    Arb's ``[mid +/- rad]`` as the CLI prints it.
    """

    __slots__ = ("lo", "hi", "text")

    def __init__(self, lo, hi, text=None):
        self.lo, self.hi, self.text = lo, hi, text

    @property
    def mid(self):
        return (self.lo + self.hi) / 2

    @property
    def rad(self):
        return (self.hi - self.lo) / 2

    def __contains__(self, x):
        return self.lo <= Fraction(x) <= self.hi

    def __float__(self):
        return float(self.mid)

    def __repr__(self):
        return f"Ball({float(self.mid)!r} +/- {float(self.rad):.3g})"

    def __str__(self):
        return self.text if self.text is not None else repr(self)


def _ball(t):
    return None if t is None else Ball(*t)


class VoronoiCircle:
    """A certified Voronoi circle: the circle externally tangent to three sites,
    tangency points counter-clockwise in their order.

    ``center`` (Ball, Ball), ``radius`` (Ball); ``tangency``: per site a dict
    with ``t`` (Ball, or None at the site's point t = infinity), ``chart``
    (``"t"`` or ``"-1/t"``) and ``chart_parameter`` (Ball); ``correct_bits``
    (of the least accurate of them), ``precision``, ``newton_steps``,
    ``found_by`` (``"guess"``, ``"tangent-line"``, ``"near-duplicate"``,
    ``"bisector-walk"``, ``"needle-chain"`` or ``"search"``),
    ``search_boxes``; ``face`` for a vertex of a diagram.
    """

    def __init__(self, d):
        self.center = tuple(_ball(b) for b in d["center"])
        self.radius = _ball(d["radius"])
        self.tangency = [{"t": _ball(t["t"]), "chart": t["chart"], "chart_parameter": _ball(t["chart_parameter"])}
                         for t in d["tangency"]]
        for key in ("correct_bits", "precision", "newton_steps", "found_by", "search_boxes"):
            setattr(self, key, d[key])
        self.face = d.get("face")

    def __repr__(self):
        x, y = self.center
        return (f"VoronoiCircle(center=({float(x)!r}, {float(y)!r}), radius={float(self.radius)!r}, "
                f"correct_bits={self.correct_bits})")


def _frozen(a):
    a.flags.writeable = False
    return a


class Trace:
    """The Voronoi edges of a diagram traced as polylines (floating point, for
    drawing: nothing here decides anything).

    All arcs' points are in one array: arc ``k`` is ``points[offsets[k]:offsets[k+1]]``
    (``polylines`` lists them), each point equidistant from the arc's two sites
    (``rho``: that distance). Per arc: ``sites[k] = (p, q)``, the Delaunay edge
    p -> q; ``faces[k]``, the Voronoi vertices at its start and end (indices
    into ``Diagram.vertices``, -1 at infinity; ``infinite[k]`` says the same
    as booleans). Unbounded arcs are traced until well outside ``box``
    (xmin, ymin, xmax, ymax), the sites' bounding box plus a margin.
    ``tolerance``: the largest gap between consecutive points inside the box.
    """

    def __init__(self, d):
        for key in ("points", "rho", "offsets", "sites", "faces", "infinite"):
            setattr(self, key, _frozen(d[key]))
        self.box = d["box"]
        self.tolerance = d["tolerance"]
        self.failed_edges = d["failed_edges"]
        self.misordered_edges = d["misordered_edges"]

    def __len__(self):
        return len(self.sites)

    def __getitem__(self, k):
        return self.points[self.offsets[k]:self.offsets[k + 1]]

    @property
    def polylines(self):
        """One (k, 2) view of ``points`` per arc."""
        return np.split(self.points, self.offsets[1:-1])

    def __repr__(self):
        return f"<ellvor.Trace: {len(self)} Voronoi edges, {len(self.points)} points>"


def _core_arrays(method, k=None):
    """A read-only property: the array the core's ``method`` returns (its ``k``-th one
    when it returns several), computed once per diagram and shared by its siblings."""

    def get(self):
        cache = self.__dict__.setdefault("_arrays", {})
        if method not in cache:
            made = getattr(self._core, method)()
            cache[method] = tuple(map(_frozen, made)) if isinstance(made, tuple) else _frozen(made)
        return cache[method] if k is None else cache[method][k]

    return property(get)


class Diagram:
    """The Delaunay graph of a site set and its Voronoi diagram (see ``build``).

    Integer arrays (int64, read-only), site ids 0-based in input order:
        hidden (k, 2)          [hidden, hiding]: sites without a cell, inside the hiding site or
                               (an ellipse in a union of crossing sites) crossing it
        edges (m, 2)           finite Delaunay edges (i < j), sorted; listed twice when two
                               Voronoi edges separate the same two sites
        faces (f, 3)           finite faces, counter-clockwise, smallest id first, sorted;
                               face k is Voronoi vertex k
        hull (h, 2)            the infinite faces (i, j, infinity), counter-clockwise pairs
        removed (r,)           the sites ``remove`` took out, in that order
        ridge_points (m, 2)    per Voronoi edge, the two sites it separates (scipy's meaning),
                               in the order of ``edges``
        ridge_vertices (m, 2)  its two Voronoi vertices (indices into ``vertices``, -1 at
                               infinity): ridge_vertices[k][0] is the face on the left of
                               the Delaunay edge ridge_points[k][0] -> ridge_points[k][1]
    Voronoi vertices, as the JSON gives them (computed on first use):
        vertices (f, 2), vertex_radii (f,)   centers and signed radii of the Voronoi circles, the
                                             midpoints of their certified boxes, rounded
                                             (a negative radius: inside three crossing sites)
        vertex_errors (f,)                   every exact value is within this of the double given
                                             (at most about 2^-40 of |center| + |radius|)
    Cells, as scipy.spatial.Voronoi: ``regions`` (per site the Voronoi vertices of its cell
    counter-clockwise, -1 at infinity, [] when hidden) and ``point_region`` (site k's region is
    regions[k]); ``cells()`` computes the certified cells (areas, packing fractions).
    ``vertex(i, bits)`` refines one circle to exact bounds; ``trace()`` draws the
    Voronoi edges; ``to_json()`` is ``ellvor build --json``'s document; ``stats``
    the build's figures; ``remove(sites)`` takes sites out (``ellvor build --remove``).
    """

    def __init__(self, core):
        self._core = core

    @functools.cached_property
    def sites(self):
        """The sites (an ellvor.Sites)."""
        return self._core.sites

    @functools.cached_property
    def points(self):
        """The sites' centers, (n, 2) float64 (scipy's ``points``)."""
        return _frozen(np.ascontiguousarray(self.sites.to_array()[:, 3:5]))

    # The arrays, made in C++ on first use and kept (read-only); see the class's docstring.
    hidden = _core_arrays("hidden")
    edges = _core_arrays("edges")
    faces = _core_arrays("faces")
    hull = _core_arrays("hull")
    removed = _core_arrays("removed")
    ridge_points = _core_arrays("ridges", 0)
    ridge_vertices = _core_arrays("ridges", 1)
    vertices = _core_arrays("vertices", 0)
    vertex_radii = _core_arrays("vertices", 1)
    vertex_errors = _core_arrays("vertices", 2)

    @functools.cached_property
    def stats(self):
        """The build's figures, as in the JSON: seconds (wall time of the insertions),
        inserted, per predicate its calls and the calls each stage decided; after
        ``remove``, also removed and removal_seconds."""
        return json.loads(self._core.stats_json())

    @property
    def regions(self):
        """scipy.spatial.Voronoi's ``regions``: per site (in site order) the indices of the
        Voronoi vertices of its cell counter-clockwise, -1 where it reaches infinity; [] for a
        hidden or removed site."""
        cache = self.__dict__.setdefault("_arrays", {})
        if "regions" not in cache:
            cache["regions"] = self._core.regions()
        return [list(r) for r in cache["regions"]]

    @property
    def point_region(self):
        """scipy.spatial.Voronoi's ``point_region``: site k's region is ``regions[k]``."""
        return _frozen(np.arange(len(self), dtype=np.int64))

    def cells(self, box=None, periodic=None, tolerance=1e-9, boundary_tolerance=None, rings=True, threads=1):
        """The certified Voronoi cells (a Cells), as ``ellvor cells``: every area an interval
        with hi - lo <= tolerance * area, the site's own area included. ``box`` or
        ``periodic``: (x0, y0, x1, y1), exact numbers (a box clips the cells; a periodic
        box tiles the torus); ``boundary_tolerance``: the rings' certified distance to the
        boundaries (default 1e-3 of the median larger semi-axis); ``rings=False`` skips the
        rings (about three quarters of the time; ``rings()`` is then empty); ``threads``: threads
        measuring the areas (0: one per core; the result does not depend on it). The cells are computed
        anew from the sites (their vertices are numbered as ``vertices``). Sites may touch or
        cross (signed distances), but not so deeply that an edge runs through a site's medial
        axis. Raises InputError with ``ellvor cells``'s message for bad arguments and sites at
        fault (such a deep crossing too); ValueError after ``remove``."""
        if len(self.removed):
            raise ValueError("cells: not available after remove(); build the remaining sites")
        return _cells(self.sites, box=box, periodic=periodic, tolerance=tolerance,
                      boundary_tolerance=boundary_tolerance, rings=rings, threads=threads)

    def vertex(self, i, bits=53):
        """The Voronoi circle of face ``i`` refined to ``bits`` correct bits (a VoronoiCircle
        with exact Fraction bounds)."""
        return VoronoiCircle(self._core.vertex(i, bits))

    def trace(self, tolerance=0.005, margin=0.08):
        """The Voronoi edges as polylines (a Trace). ``tolerance`` and ``margin`` are fractions
        of the larger side of the sites' bounding box (as for ``ellvor build --svg``)."""
        return Trace(self._core.trace(tolerance, margin))

    def to_json(self, path=None):
        """The document of ``ellvor build --json``, byte for byte (its stats are this
        build's). With ``path``, also writes it there."""
        text = self._core.json()
        if path is not None:
            with open(os.fspath(path), "w", encoding="utf-8") as f:
                f.write(text)
        return text

    def remove(self, sites):
        """Removes a site, or several in the given order, as ``ellvor build --remove IDS``
        (CGAL's remove: the sites a removed site hid come back). Ids stay: a removed site
        appears only in ``removed`` (and as null in the JSON's sites). Ctrl-C stops between
        two removals. The arrays and ``stats`` are those of the graph afterwards; ``stats``
        counts the removals' predicate calls, as the CLI's, and those of any ``validate()``
        called before."""
        ids = [sites] if isinstance(sites, numbers.Integral) else list(sites)
        try:
            self._core.remove([operator.index(i) for i in ids])
        finally:
            # Whatever was removed (all, or up to an interruption) is the diagram now.
            self.__dict__.pop("_arrays", None)
            self.__dict__.pop("stats", None)

    def validate(self, brute_force=None):
        """``ellvor build --validate``: "" when the graph is valid, else the problem.
        ``brute_force`` (default: at most 300 sites, as the CLI) also tests every Voronoi
        circle against every site."""
        if brute_force is None:
            brute_force = self._core.number_of_sites <= 300
        return self._core.validate(bool(brute_force))

    def __len__(self):
        return self._core.number_of_sites

    def __repr__(self):
        removed = f", {len(self.removed)} removed" if len(self.removed) else ""
        return (f"<ellvor.Diagram: {len(self)} sites ({len(self.hidden)} hidden{removed}), {len(self.edges)} "
                f"Delaunay edges, {len(self.faces)} faces, built in {self.stats['seconds']:.3g} s>")


class _StderrProgress:
    """progress=True: the CLI's "inserted N of M" line on standard error."""

    def __call__(self, done, total):
        sys.stderr.write(f"\rinserted {done} of {total}" + ("\n" if done == total else ""))
        sys.stderr.flush()


def build(sites, progress=False, *, fmt="ell", progress_interval=0.1):
    """The Delaunay graph of ``sites``: a path (read as ``fmt``, "ell" or "cin"), an
    ellvor.Sites, or an iterable of ellvor.Ellipse. Returns a Diagram.

    The build runs without the GIL. Ctrl-C stops it between two insertions
    (KeyboardInterrupt). ``progress``: False; True for a line on standard error;
    or a callable ``progress(done, total)``, called after the first and the last
    insertion and every ``progress_interval`` seconds between; an exception it
    raises stops the build and propagates.
    Raises InputError for bad input (two sites whose boundaries meet in three or four points
    carry ``sites=(i, j)``).
    """
    if progress is True:
        progress = _StderrProgress()
    elif progress is False:
        progress = None
    return Diagram(_ellvor._build(sites, fmt, progress, float(progress_interval)))
