"""The predicates of the CLI's ``incircle``, ``voronoi-circle`` and ``side-of-bisector``."""

import types

from . import _ellvor
from ._diagram import VoronoiCircle


class Answer(types.SimpleNamespace):
    """A predicate's answer: ``result`` (the CLI's word), ``sign`` (CGAL's), ``stage``
    (one of ``ellvor.STAGES``: the stage that decided),
    ``precision`` (Arb bits; 0 without Arb) and the time, as the CLI's ``--json``."""


def incircle(e1, e2, e3, q, max_precision=4096):
    """kappa3 (``ellvor incircle``): Q against the Voronoi circle of the ordered triple
    (E1, E2, E3). ``result``: "conflict", "no-conflict", "tangent" or "no-circle".
    ``max_precision``: the Arb precision past which the exact stage takes over."""
    return Answer(**_ellvor._incircle(e1, e2, e3, q, max_precision))


def side_of_bisector(e1, e2, point):
    """kappa1 (``ellvor side-of-bisector``): which site is closer to ``point`` = (x, y),
    exact numbers. ``result``: "first", "second" or "equidistant"."""
    return Answer(**_ellvor._side_of_bisector(e1, e2, point))


def voronoi_circle(e1, e2, e3, bits=53):
    """``ellvor voronoi-circle``: the Voronoi circle of the ordered triple, certified to
    ``bits`` correct bits. ``exists``; ``circles`` ("none", "ccw", "cw", "both":
    which orientations exist); ``stage``, the stage that decided that; ``circle``, a VoronoiCircle or
    None."""
    d = _ellvor._voronoi_circle(e1, e2, e3, bits)
    circle = VoronoiCircle(d) if d["exists"] else None
    return Answer(exists=d["exists"], circles=d["circles"], stage=d["stage"], bits=d["bits"], circle=circle,
                  time_ms=d.get("time_ms"))
