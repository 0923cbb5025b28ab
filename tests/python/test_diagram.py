"""Diagram: arrays (shapes, dtypes, scipy's conventions), certified vertices,
traced edges, threads."""

import threading
from collections import Counter
from fractions import Fraction

import numpy as np
import pytest

import ellvor


@pytest.fixture(scope="module")
def d300(root):
    return ellvor.build(root / "data" / "example-300.ell")


def test_arrays_shapes_and_dtypes(d300):
    d = d300
    n, m, f = len(d), len(d.edges), len(d.faces)
    for name, shape in [("hidden", (30, 2)), ("edges", (m, 2)), ("faces", (f, 3)), ("ridge_points", (m, 2)),
                        ("ridge_vertices", (m, 2)), ("hull", (len(d.hull), 2))]:
        a = getattr(d, name)
        assert a.shape == shape and a.dtype == np.int64, name
        assert not a.flags.writeable, name
    for name, shape in [("vertices", (f, 2)), ("vertex_radii", (f,)), ("vertex_errors", (f,)), ("points", (n, 2))]:
        a = getattr(d, name)
        assert a.shape == shape and a.dtype == np.float64 and np.isfinite(a).all(), name
    with pytest.raises(ValueError):
        d.edges[0, 0] = 5


def test_arrays_match_the_json(d300):
    import json
    j = json.loads(d300.to_json())
    assert d300.hidden.tolist() == j["hidden"] and d300.edges.tolist() == j["edges"]
    assert d300.faces.tolist() == j["faces"]
    assert [v["face"] for v in j["voronoi_vertices"]] == j["faces"]
    assert d300.vertices.tolist() == [v["center"] for v in j["voronoi_vertices"]]
    assert d300.vertex_radii.tolist() == [v["radius"] for v in j["voronoi_vertices"]]
    assert d300.vertex_errors.tolist() == [v["error"] for v in j["voronoi_vertices"]]
    assert d300.stats == {**j["stats"], "seconds": d300.stats["seconds"]}
    # The rows come from the registry (decision/predicate_registry.hpp), the same as the CLI's.
    assert ellvor.PREDICATES == ("is_hidden", "side_of_bisector", "infinite_vertex_conflict", "incircle",
                                 "finite_edge_interior_conflict", "infinite_edge_interior_conflict",
                                 "is_degenerate_edge")
    assert list(d300.stats["predicates"]) == sorted(ellvor.PREDICATES)
    for row in d300.stats["predicates"].values():
        assert list(row) == sorted(("calls",) + ellvor.STAGES)
        assert row["calls"] == sum(row[s] for s in ellvor.STAGES)


def test_hidden_and_faces_conventions(d300):
    d = d300
    hidden = set(d.hidden[:, 0].tolist())
    assert hidden.isdisjoint(d.hidden[:, 1].tolist())  # a hiding site is visible
    assert hidden.isdisjoint(d.edges.ravel().tolist())
    assert (d.edges[:, 0] < d.edges[:, 1]).all()
    assert (d.faces[:, 0] < d.faces[:, 1:].min(axis=1)).all()  # smallest id first
    assert d.faces.tolist() == sorted(d.faces.tolist())


def test_ridges_follow_scipy(d300):
    d = d300
    p, v = d.ridge_points, d.ridge_vertices
    # One ridge per Delaunay edge, in the order of `edges`.
    assert np.sort(p, axis=1).tolist() == d.edges.tolist()
    assert ((v >= -1) & (v < len(d.faces))).all()
    # Each finite end is a face holding both sites; the left face has p -> q counter-clockwise.
    faces = [tuple(f) for f in d.faces.tolist()]
    for (a, b), (left, right) in zip(p.tolist(), v.tolist()):
        for k in (left, right):
            if k >= 0:
                assert {a, b} <= set(faces[k])
        if left >= 0:
            f = faces[left]
            i = f.index(a)
            assert f[(i + 1) % 3] == b
    # One infinite end per hull edge, every face at three ridge ends.
    assert (v == -1).sum() == len(d.hull)
    ends = Counter(v[v >= 0].tolist())
    assert all(ends[k] == 3 for k in range(len(faces)))


def test_vertex_refines_to_exact_bounds(d300):
    d = d300
    for i in (0, 17, len(d.faces) - 1):
        c = d.vertex(i, bits=200)
        assert c.face == tuple(d.faces[i]) and c.correct_bits >= 200
        for ball, approx in ((c.center[0], d.vertices[i, 0]), (c.center[1], d.vertices[i, 1]),
                             (c.radius, d.vertex_radii[i])):
            assert isinstance(ball.lo, Fraction) and ball.lo <= ball.hi
            # Arb's endpoints are dyadic.
            for x in (ball.lo, ball.hi):
                assert x.denominator & (x.denominator - 1) == 0
            # The JSON's double is within `error` of the exact value, which the refined ball holds.
            slack = Fraction(d.vertex_errors[i]) + ball.rad
            assert abs(Fraction(approx) - ball.mid) <= slack
            assert ball.rad < Fraction(1, 2**150) * max(1, abs(ball.mid))
    with pytest.raises(IndexError):
        d.vertex(len(d.faces))
    with pytest.raises(ValueError):
        d.vertex(0, bits=0)


def test_trace_gives_polylines_with_sites_and_faces(d300):
    d = d300
    t = d.trace(tolerance=0.01)
    assert t.failed_edges == 0 and t.misordered_edges == 0
    assert len(t) == len(d.edges)
    assert t.points.dtype == np.float64 and t.points.shape[1] == 2 and np.isfinite(t.points).all()
    assert t.offsets[0] == 0 and t.offsets[-1] == len(t.points) and (np.diff(t.offsets) >= 2).all()
    assert (t.rho >= 0).all() and t.rho.shape == (len(t.points),)
    assert sum(len(pl) for pl in t.polylines) == len(t.points)
    assert (t.infinite == (t.faces == -1)).all()
    ridges = Counter(zip(map(tuple, d.ridge_points.tolist()), map(tuple, d.ridge_vertices.tolist())))
    arcs = Counter(zip(map(tuple, t.sites.tolist()), map(tuple, t.faces.tolist())))
    assert arcs == ridges
    # A finite arc runs between its Voronoi vertices.
    k = int(np.flatnonzero((t.faces >= 0).all(axis=1))[0])
    start, end = t[k][0], t[k][-1]
    assert np.allclose(start, d.vertices[t.faces[k, 0]], atol=1e-6 * t.tolerance * 100)
    assert np.allclose(end, d.vertices[t.faces[k, 1]], atol=1e-6 * t.tolerance * 100)
    xmin, ymin, xmax, ymax = t.box
    assert xmin < d.points[:, 0].min() and d.points[:, 1].max() < ymax


def test_small_diagrams():
    one = ellvor.build([ellvor.Ellipse.circle(0, 0, 1)])
    assert one.edges.shape == (0, 2) and one.faces.shape == (0, 3) and one.ridge_points.shape == (0, 2)
    assert one.vertices.shape == (0, 2) and len(one.trace()) == 0
    two = ellvor.build([ellvor.Ellipse.circle(0, 0, 1), ellvor.Ellipse(2, 1, 0, 5, 0)])
    assert two.edges.tolist() == [[0, 1]] and two.ridge_vertices.tolist() == [[-1, -1]]
    assert len(two.trace()) == 1
    nested = ellvor.build([ellvor.Ellipse.circle(0, 0, 5), ellvor.Ellipse.circle(1, 0, 1)])
    assert nested.hidden.tolist() == [[1, 0]] and len(nested.edges) == 0
    empty = ellvor.build([])
    assert len(empty) == 0 and empty.faces.shape == (0, 3)


def test_sites_and_points(d300, root):
    sites = d300.sites
    assert sites.filename == str(root / "data" / "example-300.ell") and len(sites.lines) == 300
    assert d300.points.tolist() == sites.to_array()[:, 3:].tolist()
    assert repr(d300).startswith("<ellvor.Diagram: 300 sites (30 hidden), ")


def test_builds_in_threads_equal_sequential_builds():
    sets = [ellvor.generate("ellipses", count=150, seed=s) for s in (1, 2, 3)]
    expected = [ellvor.build(s).edges.tolist() for s in sets]
    got = [None] * len(sets)

    def work(k):
        got[k] = ellvor.build(sets[k]).edges.tolist()

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(sets))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert got == expected


def test_one_diagram_shared_by_threads(d300):
    d = ellvor.build(d300.sites)
    results = []

    def work():
        results.append((d.vertices.tolist(), len(d.trace()), d.validate()))

    threads = [threading.Thread(target=work) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(results) == 3 and all(r == results[0] for r in results)
    assert results[0][2] == ""


def test_remove_updates_the_arrays_and_brings_hidden_sites_back():
    host = ellvor.Ellipse.circle(0, 0, 5)
    sites = [host, ellvor.Ellipse.circle(1, 0, 1), ellvor.Ellipse(2, 1, 0, 20, 0), ellvor.Ellipse.circle(0, 20, 2),
             ellvor.Ellipse.circle(-15, -10, 3)]
    d = ellvor.build(sites)
    assert d.hidden.tolist() == [[1, 0]] and len(d.removed) == 0
    before = d.edges.tolist()
    assert [0, 2] in before
    d.remove(0)  # the host goes; the site it hid comes back
    assert d.removed.tolist() == [0] and d.removed.dtype == np.int64
    assert len(d.hidden) == 0 and 0 not in d.edges.ravel() and 1 in d.edges.ravel()
    assert d.stats["removed"] == 1 and d.stats["removal_seconds"] >= 0
    assert d.validate() == "" and "1 removed" in repr(d)
    assert len(d.vertices) == len(d.faces) and len(d.ridge_points) == len(d.edges)
    with pytest.raises(ValueError, match="removed already"):
        d.remove(0)
    with pytest.raises(ValueError, match="listed twice"):
        d.remove([2, 2])
    with pytest.raises(IndexError):
        d.remove(-1)
    assert d.removed.tolist() == [0]  # a refused call removes nothing
    d.remove(np.array([2, 3]))
    assert d.removed.tolist() == [0, 2, 3] and len(d.faces) == 0 and d.edges.tolist() == [[1, 4]]


def test_crossing_circles_have_internal_voronoi_circles():
    # Three pairwise crossing circles of radius 10: the face (0, 1, 2) is the
    # internal circle about (6, 16/5) of signed radius -16/5 (its center lies
    # 34/5 from each center); a fourth circle inside the third is hidden.
    sites = [ellvor.Ellipse.circle(0, 0, 10), ellvor.Ellipse.circle(12, 0, 10), ellvor.Ellipse.circle(6, 10, 10),
             ellvor.Ellipse.circle(6, 4, 3)]
    d = ellvor.build(sites)
    assert d.hidden.tolist() == [[3, 2]]
    assert d.validate() == ""
    (i,) = [k for k, f in enumerate(d.faces.tolist()) if f == [0, 1, 2]]
    c = d.vertex(i, bits=100)
    assert c.radius.lo <= Fraction(-16, 5) <= c.radius.hi
    assert c.center[0].lo <= 6 <= c.center[0].hi and c.center[1].lo <= Fraction(16, 5) <= c.center[1].hi
    assert d.vertex_radii[i] < 0
    # Boundaries meeting in four points are refused, with the reason.
    with pytest.raises(ellvor.InputError, match="their boundaries meet in 4 points"):
        ellvor.build([ellvor.Ellipse(3, 1, 0, 0, 0), ellvor.Ellipse(1, 3, 0, 0, 0)])


def test_an_ellipse_in_the_union_of_two_crossing_disks_is_hidden():
    # The needle a = 10, b = 1/10 between disks of radius 6 at (-5, 0) and
    # (5, 0): each pair crosses in two points, no disk contains the needle,
    # and its cell is empty; it is listed under a disk that crosses it.
    needle = ellvor.Ellipse(10, Fraction(1, 10), 0, 0, 0)
    for order in ([0, 1, 2], [1, 2, 0], [2, 0, 1]):
        sites = [[needle, ellvor.Ellipse.circle(-5, 0, 6), ellvor.Ellipse.circle(5, 0, 6)][k] for k in order]
        d = ellvor.build(sites)
        needle_id = order.index(0)
        assert d.validate() == ""
        assert d.hidden.tolist() in ([[needle_id, order.index(1)]], [[needle_id, order.index(2)]])
        assert d.edges.tolist() == [sorted([order.index(1), order.index(2)])]
    # Without the second disk the needle is visible again.
    d = ellvor.build([needle, ellvor.Ellipse.circle(-5, 0, 6)])
    assert d.hidden.tolist() == [] and d.edges.tolist() == [[0, 1]]
