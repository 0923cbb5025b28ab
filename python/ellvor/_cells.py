"""Diagram.cells() and the Cells it returns: certified Voronoi cells as NumPy arrays."""

import math
import numbers
import os

import numpy as np

from . import _ellvor
from ._errors import InputError

# A wall in ``indices``: minus its number.
WALLS = {-1: "left", -2: "bottom", -3: "right", -4: "top"}


def _frozen(a):
    a = np.asarray(a)
    a.flags.writeable = False
    return a


class Cells:
    """The certified Voronoi cells of a site set (see ``Diagram.cells``).

    Every ``*_lo`` / ``*_hi`` pair is an interval that provably contains the exact value:
    the certified ball's ends rounded outward to doubles (``ellvor cells --format json``
    gives the same doubles; its CSV more digits). Per site, in site order (n,):
        visible, bounded        bool: hidden sites have no cell; an unbounded cell reaches
                                infinity (free plane only)
        area_lo, area_hi        the cell's area, the site's own included (inf: unbounded; 0: hidden)
        site_area_lo, site_area_hi   pi a b;  site_area: the double nearest the ball's midpoint
                                (an approximation, for plotting; the bounds are the proof)
        packing_fraction_lo, packing_fraction_hi   site area / cell area (0: unbounded;
                                NaN: hidden)
        perimeter_lo, perimeter_hi   the boundary's length (walls included)
        centroid_lo, centroid_hi (n, 2), second_moments_lo, second_moments_hi (n, 3): about
                                the centroid, xx, xy, yy (NaN: not computed or not defined)
        precision               Arb bits that met the tolerance
    Neighbours, CSR (as scipy.sparse): the sides of cell k counter-clockwise are
    ``indptr[k]:indptr[k+1]`` of ``indices`` (the site across; a wall as -1 left, -2 bottom,
    -3 right, -4 top), ``shifts`` (periodic: the neighbour's image is shifted by that many box
    sizes) and ``side_vertices`` (the side's two vertices, -1 at infinity).
    ``vertices_lo``, ``vertices_hi`` (m, 2): the Voronoi vertices; ``vertex_sites``, ``vertex_walls``
    (m, 3), ``vertex_shifts`` (m, 3, 2): the three sites of each vertex's face (a mirror's wall 1-4,
    a periodic copy's shift). ``reach``: per cell a bound of its boundary's distance from its site's
    center (inf for unbounded and hidden cells). ``regions``, ``point_region``:
    scipy.spatial.Voronoi's shape. ``rings()``: the boundaries as polylines.
    """

    def __init__(self, core):
        self._core = core
        a = core.arrays()
        self._rings = [_frozen(r) for r in a.pop("rings")]
        self.boundary_tolerance = a.pop("boundary_tolerance")
        self.domain = a.pop("domain")
        self.box = a.pop("box", None)
        for key, value in a.items():
            setattr(self, key, _frozen(value))

    def __len__(self):
        return len(self.visible)

    @property
    def neighbors(self):
        """(indptr, indices): the CSR arrays of the neighbour lists."""
        return self.indptr, self.indices

    def neighbors_of(self, k):
        """The sites (or walls, negative) across the sides of cell k, counter-clockwise."""
        return self.indices[self.indptr[k]:self.indptr[k + 1]]

    @property
    def regions(self):
        """Per site the indices of its Voronoi vertices counter-clockwise, -1 where the cell
        reaches infinity; [] for a hidden site (scipy.spatial.Voronoi's ``regions``)."""
        starts = self.side_vertices[:, 0]
        return [starts[self.indptr[k]:self.indptr[k + 1]].tolist() for k in range(len(self))]

    @property
    def point_region(self):
        """The region of each site: site k's is ``regions[k]``."""
        return _frozen(np.arange(len(self), dtype=np.int64))

    def rings(self):
        """Each cell's boundary as a (k, 2) array (not closed; empty when the cell is hidden,
        unbounded, or rings are not computed), within ``boundary_tolerance`` of the boundary."""
        return list(self._rings)

    def to_json(self, path=None):
        """``ellvor cells --format json``'s document; with ``path``, written there atomically."""
        if path is not None:
            self._core.write(os.fspath(path), "json")
        return self._core.json()

    def to_geojson(self, path=None):
        """``ellvor cells --format geojson``'s FeatureCollection; with ``path``, written there
        atomically."""
        if path is not None:
            self._core.write(os.fspath(path), "geojson")
        return self._core.geojson()

    def __repr__(self):
        return (f"<ellvor.Cells: {len(self)} sites ({int((~self.visible).sum())} hidden, "
                f"{int((self.visible & ~self.bounded).sum())} unbounded), {self.domain}>")


def _number(value, name):
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected a number, got {value!r}") from None
    if isinstance(value, bool):
        raise InputError(f"{name}: expected a number, got {value!r}")
    return x


def cells(sites, box=None, periodic=None, tolerance=1e-9, boundary_tolerance=None, rings=True, threads=1):
    """The certified cells of ``sites`` (a path, Sites or Ellipses); see Diagram.cells."""
    t = _number(tolerance, "tolerance")
    b = None if boundary_tolerance is None else _number(boundary_tolerance, "boundary_tolerance")
    if b is not None and math.isnan(b):
        raise InputError("boundary_tolerance: expected a positive number, got nan")
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or not 0 <= threads <= 1024:
        raise InputError(f"threads: expected a whole number from 0 to 1024, got {threads!r}")
    return Cells(_ellvor._cells(sites, box, periodic, t, b, bool(rings), threads=int(threads)))
