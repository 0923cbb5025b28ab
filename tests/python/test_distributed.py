"""ellvor.distributed.build (docs/DESIGN.md §8, the tiled build) against ellvor.build: the same graph after the
canonical sort, on a LocalCluster of two worker processes (started once for the file)."""

import os
import random
import signal
import threading
import time
from fractions import Fraction

import numpy as np
import pytest

import ellvor
import ellvor.distributed as ed

distributed = pytest.importorskip("distributed")

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


@pytest.fixture(scope="module")
def cluster():
    c = ed.local_cluster(2)
    yield c
    c.close()


@pytest.fixture(scope="module")
def client(cluster):
    with distributed.Client(cluster) as c:
        yield c


def test_the_local_cluster_has_its_workers_and_no_profiler(client):
    # Dask samples every worker's stack each 10 ms by default (~7% of a tile's CPU): off in ed.local_cluster.
    settings = client.run(lambda: __import__("dask").config.get("distributed.worker.profile.enabled"))
    assert list(settings.values()) == [False, False]
    # Nor Dask's malloc trim threshold, which makes glibc mmap every large numpy temporary anew.
    trim = client.run(lambda: __import__("os").environ.get("MALLOC_TRIM_THRESHOLD_"))
    assert list(trim.values()) == [None, None]
    assert all(w["nthreads"] == 1 for w in client.scheduler_info()["workers"].values())
    # A worker is given its next task only when its thread is free (Dask's 1.1 gives it two).
    assert client.run_on_scheduler(lambda dask_scheduler: dask_scheduler.WORKER_SATURATION) == 1.0


def same_graph(sites, client, tiles, **kwargs):
    """The tiled build of `sites` equals the single build; returns the tiled diagram."""
    single = ellvor.build(sites)
    tiled = ed.build(sites, tiles=tiles, client=client, **kwargs)
    for name in ("faces", "edges", "hull", "hidden"):
        a, b = getattr(single, name), getattr(tiled, name)
        assert a.shape == b.shape and np.array_equal(a, b), (name, tiles, a.shape, b.shape, tiled.stats)
    assert len(tiled) == len(single)
    return tiled


def circles(centers_radii):
    return ellvor.Sites([ellvor.Ellipse.circle(x, y, r) for x, y, r in centers_radii])


def boxes_meet_across_an_edge(neighbours, boxes):
    """The oracle of seam_circles' degenerate flags: faces whose circle box meets that of a face across one of
    their edges (``neighbours``: the triangulation's adjacency, -1 for infinite faces)."""
    suspect = np.zeros(len(neighbours), dtype=bool)
    for k, row in enumerate(neighbours):
        for j in row[row >= 0]:
            x, y = boxes[k], boxes[j]
            if all(x[2 * i] <= y[2 * i + 1] and y[2 * i] <= x[2 * i + 1] for i in range(3)):
                suspect[k] = suspect[j] = True
    return suspect


def least_passing(passes, lo, hi, steps=60):
    """The least x in [lo, hi] (to (hi - lo) / 2^steps) where the monotone test ``passes(x)`` holds; inf if
    not at hi."""
    if not passes(hi):
        return np.inf
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if passes(mid) else (mid, hi)
    return hi


@pytest.mark.parametrize("tiles", [(1, 1), (2, 2), (3, 2), (8, 8)])
def test_random_ellipses_every_tiling(client, tiles):
    d = same_graph(ellvor.generate("ellipses", 1500, seed=11), client, tiles)
    if tiles == (1, 1):
        assert d.stats["fallback"] == "one tile"
    else:
        assert d.stats["fallback"] is False
        assert len(d.tiles) == tiles[0] * tiles[1]
        assert sum(t["owned"] for t in d.tiles) == 1500
        assert all(t["sites"] == t["owned"] + t["halo_sites"] and t["halo_sites"] > 0 for t in d.tiles)
    assert all(0 < t["build_cpu_seconds"] <= t["cpu_seconds"] for t in d.tiles)


def test_vertices_are_the_single_builds(client):
    sites = ellvor.generate("ellipses", 400, seed=3)
    single, tiled = ellvor.build(sites), ed.build(sites, tiles=(3, 3), client=client)
    assert np.array_equal(single.vertices, tiled.vertices)
    assert np.array_equal(single.vertex_radii, tiled.vertex_radii)
    assert np.array_equal(single.vertex_errors, tiled.vertex_errors)


def test_nested_sets(client):
    d = same_graph(ellvor.generate("nested", 1200, seed=4, nested_fraction="1/3"), client, (3, 3))
    assert len(d.hidden) == 400


def test_crossing_sets(client):
    same_graph(ellvor.generate("ellipses", 1000, seed=7, crossing="1/5"), client, (3, 3))


def test_circles(client):
    same_graph(ellvor.generate("circles", 1500, seed=2), client, (4, 3))


def test_dense_packing(client):
    same_graph(ellvor.generate("packing", 1200, seed=5, packing_fraction="0.6", aspect=(1, 3)), client, (3, 3))


def test_an_ellipse_larger_than_several_tiles(client):
    """One ellipse over most of the 4 x 4 tiles' middle, small circles inside it (hidden) and around it."""
    rng = random.Random(8)
    big = ellvor.Ellipse(40, 25, Fraction(1, 7), 0, 0)
    inside = lambda x, y, m: (x / (40 + m)) ** 2 + (y / (25 + m)) ** 2 < 1  # axis-aligned test, rotated frame
    sites, seen = [big], set()
    while len(sites) < 900:
        x, y = rng.randrange(-600, 601) / 10, rng.randrange(-600, 601) / 10
        # Undo the big ellipse's rotation (w = 1/7: cos = 48/50, sin = 14/50) to place circles clear of it.
        u, v = (48 * x + 14 * y) / 50, (-14 * x + 48 * y) / 50
        if (x, y) in seen or not (inside(u, v, -2) or not inside(u, v, 2)):
            continue
        seen.add((x, y))
        sites.append(ellvor.Ellipse.circle(Fraction(x).limit_denominator(10), Fraction(y).limit_denominator(10),
                                           Fraction(rng.randrange(5, 30), 100)))
    d = same_graph(ellvor.Sites(sites), client, (4, 4))
    assert (d.hidden[:, 1] == 0).sum() > 100          # the big one hides the circles inside it
    assert all(t["sites"] > t["owned"] for t in d.tiles)


def test_all_sites_in_one_tile(client):
    """Every site but the two far corners in one tile of 4 x 4."""
    rng = random.Random(3)
    pts = {(rng.randrange(0, 1000), rng.randrange(0, 1000)) for _ in range(400)}
    sites = [(Fraction(x, 100), Fraction(y, 100), Fraction(rng.randrange(5, 30), 1000)) for x, y in pts]
    sites += [(-1000, -1000, 1), (1000, 1000, 1)]
    d = same_graph(circles(sites), client, (4, 4))
    assert max(t["owned"] for t in d.tiles) == len(sites) - 2


def test_sites_centered_on_tile_boundaries(client):
    """Centers on the integer lattice 0..20; the 4 x 4 tiles' lines x, y = 5, 10, 15 pass through them."""
    # Distinct radii: two equal ones side by side would put four sites on one circle (see the cocircular test).
    radii = random.Random(5).sample(range(1000, 4000), 21 * 21)
    d = same_graph(circles([(x, y, Fraction(radii[21 * x + y], 10000)) for x in range(21) for y in range(21)]),
                   client, (4, 4))
    assert list(d.tiles[0]["index"]) == [0, 0] and d.stats["fallback"] is False


def test_collinear_sets(client):
    rng = random.Random(6)
    same_graph(circles([(x, 0, Fraction(rng.randrange(10, 40), 100)) for x in range(60)]), client, (4, 1))
    # Equal circles on a line: three sites touch each hull line.
    same_graph(circles([(x, 0, Fraction(1, 4)) for x in range(60)]), client, (3, 3))
    # Ellipses with collinear centers and random shapes.
    same_graph(ellvor.Sites([ellvor.Ellipse(Fraction(rng.randrange(10, 40), 100), Fraction(1, 10),
                                            Fraction(rng.randrange(-9, 10), 10), 2 * x, x) for x in range(60)]),
               client, (3, 3))


def test_cocircular_sets_fall_back_and_say_so(client):
    """Equal circles on a lattice: four sites on every Voronoi circle. The triangulation of such a vertex
    depends on the insertion order, so no tile certifies it: the build falls back to one tile."""
    d = same_graph(circles([(x, y, Fraction(1, 5)) for x in range(12) for y in range(12)]), client, (3, 3))
    assert d.stats["fallback"] and d.stats["fallback"] != "one tile"
    ring = [(Fraction(round(1000 * np.cos(2 * np.pi * k / 40))), Fraction(round(1000 * np.sin(2 * np.pi * k / 40))),
             Fraction(1, 2)) for k in range(40)]
    same_graph(circles(ring), client, (2, 2))


def test_patches_retry_until_faces_close(client):
    """A halo far too thin leaves most seam faces uncertified: patches with doubling halos find them."""
    d = same_graph(ellvor.generate("ellipses", 800, seed=9), client, (3, 3), halo=6)
    assert d.stats["rounds"] > 1 and sum(t["retries"] for t in d.tiles) > 0


def test_a_killed_worker_loses_nothing(cluster):
    """One worker process killed in the middle of the build: Dask runs its tiles again elsewhere."""
    sites = ellvor.generate("ellipses", 12000, seed=13)
    single = ellvor.build(sites)
    with distributed.Client(cluster.scheduler_address) as c:
        pids = c.run(os.getpid)
        victim = sorted(pids.values())[0]
        result = {}
        thread = threading.Thread(target=lambda: result.setdefault("d", ed.build(sites, tiles=(4, 4), client=c)))
        thread.start()
        # Kill once the first tasks are running (a tile of 12000 / 16 sites takes well over 0.1 s).
        deadline = time.time() + 60
        while not c.processing() or not any(c.processing().values()):
            assert time.time() < deadline
            time.sleep(0.05)
        os.kill(victim, signal.SIGKILL)
        thread.join(300)
        assert not thread.is_alive()
        c.wait_for_workers(2, timeout=120)   # the nanny starts a new worker for the next tests
    d = result["d"]
    for name in ("faces", "edges", "hull", "hidden"):
        assert np.array_equal(getattr(single, name), getattr(d, name)), name


def test_a_scheduler_address_works(cluster):
    same_graph(ellvor.generate("ellipses", 300, seed=1), cluster.scheduler_address, (2, 2))


def test_auto_tiles(client):
    d = same_graph(ellvor.generate("ellipses", 5000, seed=21), client, "auto")
    assert d.stats["fallback"] == "one tile"     # too few sites to split
    assert ed._tiles_argument("auto", 10 ** 6, client) == (4, 4)   # eight tiles a worker, two workers
    assert ed._tiles_argument("auto", 10 ** 5, client) == (2, 2)   # at least 20000 sites a tile
    with pytest.raises(ValueError, match="tiles"):
        ed.build(ellvor.generate("ellipses", 50), tiles=(0, 2), client=client)
    with pytest.raises(ValueError, match="tiles"):
        ed.build(ellvor.generate("ellipses", 50), tiles="many", client=client)


class _Unreachable:
    """A client that fails any use: bad input must be refused before anything is sent."""

    def __getattr__(self, name):
        raise AssertionError(f"client.{name} used")


def test_bad_input_is_refused_on_the_client():
    e = ellvor.Ellipse(2, 1, 0, 0, 0)
    with pytest.raises(ellvor.InputError) as single:
        ellvor.build([e, e])
    with pytest.raises(ellvor.InputError) as tiled:
        ed.build([e, e], client=_Unreachable())
    assert str(tiled.value) == str(single.value) and tiled.value.sites == single.value.sites
    with pytest.raises(ellvor.InputError):
        ed.build("/nonexistent/sites.ell", client=_Unreachable())


def test_sites_meeting_in_four_points_raise_the_single_builds_error(client, tmp_path):
    rng = random.Random(4)
    sites = [ellvor.Ellipse.circle(rng.randrange(-500, 500), rng.randrange(-500, 500), 1) for _ in range(300)]
    sites += [ellvor.Ellipse(3, Fraction(1, 5), 0, 1000, 1000), ellvor.Ellipse(3, Fraction(1, 5), 1, 1000, 1000)]
    path = tmp_path / "crossing.ell"
    ellvor.Sites(sites).write(str(path))
    for given in (sites, str(path)):   # ids in a tile differ from the global ones; a file's error has its lines
        with pytest.raises(ellvor.InputError) as single:
            ellvor.build(given)
        with pytest.raises(ellvor.InputError) as tiled:
            ed.build(given, tiles=(3, 3), client=client)
        assert str(tiled.value) == str(single.value)
        assert tiled.value.sites == single.value.sites == (300, 301)
        assert tiled.value.lineno == single.value.lineno == (None if given is sites else 302)
        assert "meet in 4 points" in tiled.value.why and tiled.value.why == single.value.why


def test_the_seam_tests_refuse_what_they_cannot_prove():
    everything = (0.0, 10.0, 0.0, 10.0)
    region = (2.0, 6.0, -np.inf, np.inf)
    # Center 4, radius 1.9: clear of the slabs x <= 2 and x >= 6; radius 2: touches them.
    boxes = np.array([[4, 4, 5, 5, 1.9, 1.9], [4, 4, 5, 5, 2, 2], [3.9, 4.1, 5, 5, 1.85, 1.95],
                      [4, 4, 5, 5, -1, -0.5], [1, 1, 5, 5, -1, -0.5]])
    assert ed._disk_misses_outside(boxes, region, everything).tolist() == [True, False, False, True, False]


def test_the_client_merge_against_brute_force():
    # _FaceUnion (sorted runs merged, in steps) and _DirectedEdges (open sites, edges) against counting, on random
    # multisets of faces: a whole graph's faces, duplicates (faces certified by two tiles), missing faces,
    # double edges, loops, int32 hull rows (a tile's ids).
    from collections import Counter
    rng = np.random.default_rng(7)
    graph = ellvor.build(ellvor.generate("ellipses", 300, seed=5))
    cases = [(graph.faces, graph.hull)]
    for _ in range(200):
        n = int(rng.integers(2, 9))
        faces = rng.integers(0, n, size=(int(rng.integers(0, 12)), 3))
        hull = rng.integers(0, n, size=(int(rng.integers(0, 4)), 2)).astype(np.int32)
        cases.append((faces, hull))
    for drop in (0, 1, 17):
        cases.append((np.delete(graph.faces, drop, axis=0), graph.hull))
    for faces, hull in cases:
        n = int(max(faces.max(initial=0), hull.max(initial=0))) + 1
        parts = np.array_split(np.concatenate([faces, faces[::3]]), 3)
        union = ed._FaceUnion(n)   # the tiles' keys added in two steps, as tiles come in
        union.add([ed._faces_out(part, n) for part in parts[:2]])
        union.add([ed._faces_out(parts[2], n)])
        unique = union.faces()
        turned = {tuple(np.roll(r, -int(np.argmin(r))).tolist()) for r in faces}   # smallest id first
        assert unique.tolist() == [list(r) for r in sorted(turned)] and len(union) == len(turned)
        assert np.nonzero(union.visible)[0].tolist() == sorted({int(v) for r in turned for v in r})
        wide = ed._FaceUnion(n)   # the rows path, for n^3 beyond int64: the tiles send rows
        wide.wide = True
        wide.add([ed._faces_in_order(parts[0])])
        wide.add([ed._faces_in_order(part) for part in parts[1:]])
        assert wide.faces().tolist() == unique.tolist() and wide.keys.tolist() == union.keys.tolist()
        assert len(wide) == len(union) and wide.visible.tolist() == union.visible.tolist()
        assert ed._faces_out(parts[0], 2 ** 21).tolist() == ed._faces_in_order(parts[0]).tolist()   # 2^63 <= (2^21)^3
        directed = Counter()
        for row in unique.tolist():
            directed.update((row[k], row[(k + 1) % 3]) for k in range(3))
        directed.update(map(tuple, hull.tolist()))
        open_sites = sorted({s for (i, j), c in directed.items() if i != j and c != directed[(j, i)] for s in (i, j)})
        edges = sorted(e for (i, j), c in directed.items() if i < j for e in [(i, j)] * c)
        d = ed._DirectedEdges(union, hull)
        assert d.open_sites().tolist() == open_sites
        assert d.edges().tolist() == [list(e) for e in edges]
    whole = ed._FaceUnion(len(graph.sites))
    whole.add([ed._faces_out(graph.faces, len(graph.sites))])
    assert ed._DirectedEdges(whole, graph.hull).edges().tolist() == graph.edges.tolist()


def test_face_neighbours_share_an_edge():
    d = ellvor._ellvor._build(ellvor.generate("ellipses", 200, seed=3), "ell", None, 0.1)
    faces, across = d.faces(), d.face_neighbours()
    assert across.shape == faces.shape
    finite = 0
    for k, row in enumerate(across):
        for j in row[row >= 0]:
            finite += 1
            assert len(set(faces[k]) & set(faces[j])) == 2
            assert k in across[j]
    # Every finite face has a finite neighbour; the hull's faces have infinite ones.
    assert finite > 2 * len(faces) and (across < 0).any()


def test_faces_far_from_the_seam_need_no_circle_and_their_disks_lie_inside():
    sites = ellvor.generate("ellipses", 3000, seed=5)
    _, _, boxes = ed._site_arrays(sites)
    d = ellvor._ellvor._build(sites, "ell", None, 0.1)
    faces, precise = d.faces(), d.circle_boxes()
    lo, hi = boxes[:, [0, 2]].min(axis=0), boxes[:, [1, 3]].max(axis=0)
    region = (float(lo[0] + 0.3 * (hi[0] - lo[0])), np.inf, -np.inf, float(hi[1] - 0.2 * (hi[1] - lo[1])))
    settled = ed._disks_settled(boxes, region)[faces].any(axis=1)
    assert 0.3 < settled.mean() < 0.9
    # What the grid proves, the precise boxes confirm: the disk inside the open region.
    rho = np.maximum(precise[:, 5], 0)
    inside = ((precise[:, 0] - rho > region[0]) & (precise[:, 1] + rho < region[1]) &
              (precise[:, 2] - rho > region[2]) & (precise[:, 3] + rho < region[3]))
    assert inside[settled].all()
    # seam_circles: boxes where asked (and where cached), the same neighbour verdicts as all boxes compared;
    # a wide double box (some 2^-30 of the circle: 39 faces here) is kept as it is, and holds the circle.
    circles, may_share, wide = d.seam_circles(~settled)
    assert not np.isnan(circles[~settled]).any() and np.isnan(circles[settled]).any()
    known = ~np.isnan(circles[:, 0])
    assert wide.any() and not wide[~known].any()
    assert np.array_equal(circles[known & ~wide], precise[known & ~wide])
    assert (circles[wide][:, 0::2] <= precise[wide][:, 1::2]).all() and (precise[wide][:, 0::2] <= circles[wide][:, 1::2]).all()
    assert (circles[wide][:, 1::2] - circles[wide][:, 0::2] > precise[wide][:, 1::2] - precise[wide][:, 0::2]).any()
    assert np.array_equal(d.circle_boxes(np.nonzero(wide)[0]), precise[wide])
    for bad in (-1, len(faces)):
        with pytest.raises(IndexError, match="no face"):
            d.circle_boxes(np.array([0, bad]))
    assert np.array_equal(may_share, boxes_meet_across_an_edge(d.face_neighbours(), precise))
    # Four unit circles on one circle: both faces of the square share it, with or without their boxes.
    square = ellvor._ellvor._build([ellvor.Ellipse.circle(x, y, 1) for x, y in ((3, 3), (-3, 3), (-3, -3), (3, -3))],
                                   "ell", None, 0.1)
    for needed in (np.zeros(2, dtype=bool), np.ones(2, dtype=bool)):
        assert square.seam_circles(needed)[1].tolist() == [True, True]


def test_a_wide_circle_box_is_made_tight_where_that_proves_the_disk_inside():
    # A face whose double box is wide (some 2^-30 of the circle) and whose disk ends just inside the region:
    # the wide box cannot prove it, the tight one (Arb) can, and _tile_task asks for it.
    sites = ellvor.generate("ellipses", 3000, seed=5)
    _, fractions, boxes = ed._site_arrays(sites)
    ids = np.arange(len(sites))
    d = ed._local_build(fractions)
    faces = d.faces()
    circles, may_share, wide = d.seam_circles(np.ones(len(faces), dtype=bool))
    everything = (float(boxes[:, 0].min()), float(boxes[:, 1].max()), float(boxes[:, 2].min()), float(boxes[:, 3].max()))
    # The region (-inf, x) x R: per wide face, the least x where its tight box proves the disk inside, and
    # where its wide box does (bisection: both tests are monotone in x); the face where they differ most.
    def threshold(box):
        return least_passing(lambda x: ed._disk_misses_outside(box[None], (-np.inf, x, -np.inf, np.inf), everything)[0],
                             everything[0], everything[1])
    candidates = np.nonzero(wide & ~may_share)[0]
    tight = d.circle_boxes(candidates)
    gap = np.array([threshold(circles[k]) - threshold(t) for k, t in zip(candidates, tight)])
    best = int(np.argmax(np.where(np.isfinite(gap), gap, -1)))
    k, tight = int(candidates[best]), tight[best]
    assert 0 < gap[best] < np.inf
    region = (-np.inf, threshold(tight) + gap[best] / 2, -np.inf, np.inf)
    assert not ed._disk_misses_outside(circles[k:k + 1], region, everything)[0]
    assert ed._disk_misses_outside(tight[None], region, everything)[0]
    result = ed._tile_task(fractions, ids, region, region, everything, False, len(sites))
    rows = ed._face_rows(result["faces"], len(sites))
    assert any(np.array_equal(row, np.sort(faces[k])) for row in np.sort(rows, axis=1))


def test_the_hull_task_makes_a_wide_circle_box_tight_where_that_proves_the_face():
    # As above for the hull candidates' graph: a depth (the test is monotone in it) between what a wide face's
    # wide box and its tight box prove; _hull_task certifies the face.
    sites = ellvor.generate("ellipses", 1500, seed=2)
    params, fractions, boxes = ed._site_arrays(sites)
    candidates, polygon = ed._hull_candidates(params, boxes, 1.0)
    payload = ed._payload(sites, fractions, candidates)
    d = ed._local_build(payload)
    faces = d.faces()
    circles, may_share, wide = d.seam_circles(np.ones(len(faces), dtype=bool))
    def proven(box, depth):
        return bool((ed._disk_outside_polygon(box[None], polygon, depth) |
                     ed._disk_misses_shrunk_polygon(box[None], polygon, depth))[0])
    def threshold(box):
        return least_passing(lambda depth: proven(box, depth), 0.0, 1e3, steps=36)
    candidates_wide = np.nonzero(wide & ~may_share)[0]
    width = (circles[:, 1::2] - circles[:, 0::2]).sum(axis=1)
    candidates_wide = candidates_wide[np.argsort(-width[candidates_wide])][:6]   # the widest: the largest gaps
    tight = d.circle_boxes(candidates_wide)
    gap = [threshold(circles[k]) - threshold(b) for k, b in zip(candidates_wide, tight)]
    best = int(np.argmax([g if np.isfinite(g) else -1 for g in gap]))
    k, tight = int(candidates_wide[best]), tight[best]
    assert 0 < gap[best] < np.inf
    depth = threshold(tight) + gap[best] / 2
    assert proven(tight, depth) and not proven(circles[k], depth)
    result = ed._hull_task(payload, candidates, polygon, depth, len(sites))
    rows = ed._face_rows(result["faces"], len(sites))
    assert any(np.array_equal(row, np.sort(candidates[faces[k]])) for row in np.sort(rows, axis=1))


def test_the_optimistic_disk_test_keeps_every_face_a_narrower_box_proves():
    # _tile_task asks Arb for a tight box only where the wide box passes the optimistic test: that must hold
    # wherever some narrower box of the same circle passes the sure one (else a provable face is lost).
    rng = np.random.default_rng(7)
    m = 20000
    everything = (-100.0, 100.0, -100.0, 100.0)
    region = (-30.0, 40.0, -np.inf, 25.0)
    cx, cy = rng.uniform(-120, 120, m), rng.uniform(-120, 120, m)
    rho = rng.uniform(-5, 60, m)
    def box(width):
        w = width * rng.uniform(0, 1, (m, 6))
        return np.stack([cx - w[:, 0], cx + w[:, 1], cy - w[:, 2], cy + w[:, 3], rho - w[:, 4], rho + w[:, 5]], axis=1)
    narrow, wide = box(1e-9), box(rng.choice([1e-6, 1e-2, 3.0], m)[:, None])
    sure = ed._disk_misses_outside(narrow, region, everything)
    optimistic = ed._disk_misses_outside(wide, region, everything, True)
    assert 0.1 < sure.mean() < 0.9
    assert optimistic[sure].all()
    # And it is a filter: many wide boxes are given up without Arb.
    assert (~optimistic & ~ed._disk_misses_outside(wide, region, everything)).mean() > 0.1


def test_sites_travel_as_fractions_or_as_lines():
    rng = random.Random(5)
    sites = ellvor.generate("nested", 300, seed=4)
    ids = np.array(rng.sample(range(len(sites)), 120), dtype=np.int64)
    params, fractions, boxes = ed._site_arrays(sites)
    assert np.array_equal(params, sites.to_array())
    payload = ed._payload(sites, fractions, ids)
    assert isinstance(payload, np.ndarray) and payload.shape == (120, 10)
    assert list(ed._local_sites(payload)) == [sites[int(k)] for k in ids]
    # In the narrowest integers that hold them (these sites' fit in 16 bits); a tile makes its sites' boxes.
    assert payload.dtype == np.int16
    assert ed._site_arrays(ellvor.Sites([ellvor.Ellipse(1, 1, 0, 2 ** 15, 0), ellvor.Ellipse(1, 1, 0, 0, 0)]))[1].dtype == np.int32
    assert np.array_equal(ed._local_build(payload)._site_boxes(), boxes[ids])
    # Numbers beyond 2^53 (not exact doubles): their fractions travel, their doubles are to_array's.
    wide = ellvor.Sites([ellvor.Ellipse(Fraction(2 ** 60 + 1, 3), Fraction(2 ** 60 - 1, 7), Fraction(-1, 2 ** 55 + 3),
                                        Fraction(2 ** 62 + 5, 2 ** 61 - 1), Fraction(-5, 3)),
                         ellvor.Ellipse(1, 1, 0, 10, 10)])
    params, fractions, boxes = ed._site_arrays(wide)
    assert fractions is not None and fractions.dtype == np.int64 and np.array_equal(params, wide.to_array())
    assert np.array_equal(ed._local_build(fractions)._site_boxes(), boxes)
    assert list(ed._local_sites(ed._payload(wide, fractions, np.array([1, 0])))) == [wide[1], wide[0]]
    # A numerator beyond 64 bits: the lines carry it.
    big = ellvor.Sites([ellvor.Ellipse(2, 1, 0, 0, 0), ellvor.Ellipse(1, 1, 0, Fraction(3 ** 50, 7), 5)])
    params, fractions, _ = ed._site_arrays(big)
    assert fractions is None and np.array_equal(params, big.to_array())
    payload = ed._payload(big, fractions, np.array([1, 0]))
    assert isinstance(payload, str)
    assert list(ed._local_sites(payload)) == [big[1], big[0]]
    assert np.array_equal(ed._local_build(payload)._site_boxes(), ed._site_arrays(big)[2][[1, 0]])
    # Received fractions are checked as Ellipses are.
    with pytest.raises(ellvor.InputError, match="semi-axis a must be positive"):
        ed._local_sites(np.array([[-1, 1, 1, 1, 0, 1, 0, 1, 0, 1]], dtype=np.int64))
    with pytest.raises(ellvor.InputError, match="denominator"):
        ed._local_sites(np.array([[1, 0, 1, 1, 0, 1, 0, 1, 0, 1]], dtype=np.int64))
    with pytest.raises(ellvor.InputError, match="duplicate"):
        ed._local_sites(np.array([[1, 1, 1, 1, 0, 1, 0, 1, 0, 1]] * 2, dtype=np.int64))


def test_without_a_client_a_local_cluster_is_started():
    d = same_graph(ellvor.generate("nested", 300, seed=2), None, (2, 2))
    assert d.stats["fallback"] is False


def test_empty_and_tiny_sets(client):
    for sites in ([], list(ellvor.generate("ellipses", 3, seed=1))):
        d = same_graph(ellvor.Sites(sites), client, (2, 2))
        assert d.stats["fallback"] == "too few sites or extreme coordinates"


def test_the_tiling_takes_only_coordinates_doubles_hold_well():
    # Beyond 1e280 or below 1e-280 in magnitude (zero apart), NaN, infinity: one build, not tiles.
    for row, fine in [([1.0, 0.0, -3.5], True), ([1e-279, -1e279, 0.0], True), ([1e-281, 1.0, 1.0], False),
                      ([1e281, 1.0, 1.0], False), ([np.nan, 1.0, 1.0], False), ([1.0, -np.inf, 1.0], False)]:
        assert ed._in_double_range(np.array([row, [1.0, 2.0, 3.0]])) == fine, row


def test_map_builds_each_file_whole(client, tmp_path):
    paths = []
    for k, kind in enumerate(("ellipses", "nested", "circles")):
        paths.append(tmp_path / f"snapshot-{k}.ell")
        ellvor.generate(kind, 200 + 100 * k, seed=k).write(paths[-1])
    results = dict(ed.map(paths, client=client))
    assert sorted(results) == sorted(map(str, paths))
    for path in paths:
        single, d = ellvor.build(path), results[str(path)]
        for name in ("faces", "edges", "hull", "hidden"):
            assert np.array_equal(getattr(single, name), getattr(d, name)), (path, name)
        assert d.stats["fallback"] == "one file" and d.tiles[0]["sites"] == len(single)


def test_map_checks_every_file_before_sending(tmp_path, write_sites):
    good = tmp_path / "good.ell"
    ellvor.generate("ellipses", 50, seed=1).write(good)
    bad = write_sites("1 1 0 0 0\n1 x 0 5 5\n", "bad.ell")
    with pytest.raises(ellvor.InputError) as single:
        ellvor.build(bad)
    with pytest.raises(ellvor.InputError) as mapped:
        ed.map([good, bad], client=_Unreachable())
    assert str(mapped.value) == str(single.value) and mapped.value.lineno == 2
    with pytest.raises(ValueError, match="fn"):
        ed.map([good], fn="voronoi", client=_Unreachable())


def test_map_raises_the_builds_error_for_sites_meeting_in_four_points(client, write_sites):
    path = write_sites("3 1/5 0 0 0\n3 1/5 1 0 0\n1 1 0 10 10\n", "cross.ell")
    with pytest.raises(ellvor.InputError) as single:
        ellvor.build(path)
    with pytest.raises(ellvor.InputError) as mapped:
        list(ed.map([path], client=client))
    assert str(mapped.value) == str(single.value) and mapped.value.sites == single.value.sites == (0, 1)


def test_bounding_boxes_hold_the_ellipses_tightly():
    # Sites near the origin and far from it (the margin scales with the center), and one whose numbers
    # exceed 2^53 (its doubles rounded, not divided exactly).
    sites = ellvor.Sites(list(ellvor.generate("ellipses", 200, seed=17)) +
                         [ellvor.Ellipse(Fraction(3, 7), Fraction(1, 9), Fraction(5, 11), 10 ** 6 + Fraction(1, 3), -10 ** 5),
                          ellvor.Ellipse(Fraction(2 ** 60 + 1, 3), Fraction(2 ** 60 - 1, 7), Fraction(-1, 2 ** 55 + 3),
                                         Fraction(2 ** 62 + 5, 2 ** 61 - 1), Fraction(-5, 3))])
    _, _, boxes = ed._site_arrays(sites)
    for e, (x0, x1, y0, y1) in zip(sites, boxes):
        a, b, w, xc, yc = (Fraction(v) for v in (e.a, e.b, e.w, e.xc, e.yc))
        c, s = (1 - w * w) / (1 + w * w), 2 * w / (1 + w * w)
        # The exact half-widths squared, compared with the box's in exact arithmetic.
        hx2, hy2 = (a * c) ** 2 + (b * s) ** 2, (a * s) ** 2 + (b * c) ** 2
        for lo, hi, center, h2 in ((x0, x1, xc, hx2), (y0, y1, yc, hy2)):
            assert center - Fraction(lo) > 0 and (center - Fraction(lo)) ** 2 >= h2
            assert Fraction(hi) - center > 0 and (Fraction(hi) - center) ** 2 >= h2
            assert float(Fraction(hi) - center) < float(h2) ** 0.5 * (1 + 1e-9) + 1e-9 * abs(float(center))


def test_hull_candidates_are_the_sites_near_the_hull():
    """A 30 x 30 lattice of small circles: the candidates are those within the depth of the border."""
    sites = circles([(x, y, Fraction(1, 10)) for x in range(30) for y in range(30)])
    params, _, boxes = ed._site_arrays(sites)
    candidates, polygon = ed._hull_candidates(params, boxes, 2.5)
    border = {k for k, (x, y) in enumerate(params[:, 3:5]) if min(x, y, 29 - x, 29 - y) <= 2}
    assert border <= set(candidates.tolist())
    assert len(candidates) < 900 // 2 and all(min(x, y, 29 - x, 29 - y) <= 4 for x, y in params[candidates, 3:5])
    # Disks left of the polygon's edge x = 0, reaching x = 1 (short of the non-candidates, beyond x = 2.5),
    # x = 3 (into them) and, centered inside, x = 2 (their center inside the polygon: refused, conservative).
    boxes = np.array([[-5, -5, 15, 15, 6, 6], [-5, -5, 15, 15, 8, 8], [1, 1, 15, 15, 1, 1]], dtype=float)
    assert ed._disk_outside_polygon(boxes, polygon, 2.5).tolist() == [True, False, False]


def _clearance_squared(box, x0, y0, x1, y1):
    """Exactly (Fractions): the squared distance from the box's middle to the rectangle [x0, x1] x [y0, y1]
    (0 inside), and the box's half-diagonal bound 2e-9 (its sides are 2e-9 wide)."""
    cx, cy = (Fraction(box[0]) + Fraction(box[1])) / 2, (Fraction(box[2]) + Fraction(box[3])) / 2
    dx = max(x0 - cx, Fraction(0), cx - x1)
    dy = max(y0 - cy, Fraction(0), cy - y1)
    return dx * dx + dy * dy, Fraction(2, 10 ** 9)


def test_huge_hull_disks_are_certified_when_they_miss_the_shrunk_polygon():
    """Random huge disks nearly tangent to a rectangle's side, tilted, some reaching into Q_depth: every
    disk the certificate accepts misses Q_depth (exactly), none that reaches in is accepted, and it accepts
    disks the one-edge-line test refuses."""
    polygon = [(0.0, 0.0), (100.0, 0.0), (100.0, 60.0), (0.0, 60.0)]
    rng = random.Random(3)
    boxes, expect_clear = [], []
    for _ in range(300):
        R = 10 ** rng.uniform(2, 4)
        tilt = rng.uniform(-3, 3) / R ** 0.5
        x0 = rng.uniform(10, 90)
        gap = rng.uniform(-2.0, 3.0)  # depth of the disk's deepest point below the side y = 0 moved in by 2
        # The circle tangent to the line y = 2 - gap ... tilted: center below, at distance R from the touch point.
        cx, cy = x0 + R * tilt, (2 - gap) - R * (1 - tilt * tilt / 2)
        boxes.append([cx - 1e-9, cx + 1e-9, cy - 1e-9, cy + 1e-9, R - 1e-9, R + 1e-9])
    boxes = np.array(boxes)
    certified = ed._disk_misses_shrunk_polygon(boxes, polygon, 2.0)
    line_test = ed._disk_outside_polygon(boxes, polygon, 2.0)
    assert certified.sum() >= 50
    # Q_2 is the open rectangle (2, 98) x (2, 58): a disk misses it when its center is at least rho from it.
    reaching = []
    for k, (box, ok) in enumerate(zip(boxes, certified)):
        d2, half_diagonal = _clearance_squared(box, 2, 2, 98, 58)
        rho = Fraction(box[5])
        if ok:
            assert d2 >= (rho + half_diagonal) ** 2
        elif d2 < (rho - half_diagonal) ** 2:
            reaching.append(k)
    assert len(reaching) >= 20 and not certified[reaching].any()
    # the huge tilted disks the edge-line test cannot certify
    assert (certified & ~line_test).sum() >= 10


def test_a_dense_packing_needs_one_round(client):
    """The straight sides of a packing give nearly collinear hull triples whose huge disks the hull task
    certifies (_disk_misses_shrunk_polygon): no patches."""
    sites = ellvor.generate("packing", 3000, seed=1, packing_fraction="0.6")
    tiled = same_graph(sites, client, (2, 2))
    assert tiled.stats["rounds"] == 1


# The tiled cells (docs/DESIGN.md §8, "The tiled cells"): small sets, cells cost ~0.1 s each.

def _overlap(lo1, hi1, lo2, hi2):
    both_nan = np.isnan(lo1) & np.isnan(lo2)
    return bool(np.all(both_nan | ((lo1 <= hi2) & (lo2 <= hi1))))


def same_cells(sites, client, tiles, single=None, **kwargs):
    """The tiled cells of `sites` are the single process's: the same visibility, neighbours (walls, shifts)
    and every interval overlapping its counterpart (both contain the exact value); each vertex of a side
    overlaps the single's. Returns the tiled cells."""
    if single is None:
        single = ellvor.build(sites).cells(**kwargs)
    tiled = ed.cells(sites, tiles=tiles, client=client, **kwargs)
    assert isinstance(tiled, ellvor.Cells) and len(tiled) == len(single)
    for name in ("visible", "bounded", "indptr"):
        assert np.array_equal(getattr(single, name), getattr(tiled, name)), (name, tiles, tiled.stats)
    # Each cell's sides counter-clockwise, from wherever its graph starts: the same cycle.
    rotated = []
    for k in range(len(single)):
        lo, hi = single.indptr[k], single.indptr[k + 1]
        ours = [(i, *s) for i, s in zip(single.indices[lo:hi], single.shifts[lo:hi].tolist())]
        theirs = [(i, *s) for i, s in zip(tiled.indices[lo:hi], tiled.shifts[lo:hi].tolist())]
        turn = next((r for r in range(len(ours)) if theirs[r:] + theirs[:r] == ours), None) if ours else 0
        assert turn is not None, (k, ours, theirs, tiles)
        rotated.extend(lo + (np.arange(hi - lo) + turn) % max(hi - lo, 1))
    rotated = np.array(rotated, dtype=np.int64)
    for name in ("area", "site_area", "perimeter", "packing_fraction", "centroid", "second_moments"):
        assert _overlap(getattr(single, name + "_lo"), getattr(single, name + "_hi"),
                        getattr(tiled, name + "_lo"), getattr(tiled, name + "_hi")), name
    finite = np.isfinite(tiled.area_hi) & (tiled.area_hi > 0)
    tol = kwargs.get("tolerance", 1e-9)
    assert np.all(tiled.area_hi[finite] - tiled.area_lo[finite] <= tol * tiled.area_lo[finite] * (1 + 1e-9))
    ours, theirs = single.side_vertices, tiled.side_vertices[rotated]
    assert np.array_equal(ours >= 0, theirs >= 0)
    a, b = ours[ours >= 0], theirs[theirs >= 0]
    assert np.all((single.vertices_lo[a] <= tiled.vertices_hi[b]) & (tiled.vertices_lo[b] <= single.vertices_hi[a]))
    assert sum(t["owned"] for t in tiled.tiles) == len(sites)
    return tiled


def box_around(sites, margin):
    p = sites.to_array()
    return (int(p[:, 3].min() - margin), int(p[:, 4].min() - margin), int(p[:, 3].max() + margin) + 1,
            int(p[:, 4].max() + margin) + 1)


def test_cells_in_a_box_every_tiling(client):
    sites = ellvor.generate("ellipses", 10, seed=7)
    kwargs = dict(box=box_around(sites, 15), tolerance=1e-3, rings=False)
    single = ellvor.build(sites).cells(**kwargs)
    for tiles in ((2, 2), (4, 4)):
        tiled = same_cells(sites, client, tiles, single, **kwargs)
        assert len(tiled.tiles) > 1 and sum(t["cells"] for t in tiled.tiles) + tiled.stats["whole_set_cells"] >= 10
        assert all(t["sites"] >= t["owned"] for t in tiled.tiles)
        # Reach: computed for the cells proven in tiles (not in one task of the whole set).
        assert int(np.isinf(tiled.reach).sum()) <= tiled.stats["whole_set_cells"] < 10 // 2


def test_cells_of_nested_sites_in_a_box(client):
    sites = ellvor.generate("nested", 12, seed=3)
    tiled = same_cells(sites, client, (3, 3), box=box_around(sites, 10), tolerance=1e-3, rings=False)
    assert (~tiled.visible).sum() > 0   # hidden sites: hidden in a subset is hidden


def test_cells_in_the_plane_send_the_hull_to_the_whole_set(client):
    sites = ellvor.generate("ellipses", 10, seed=2)
    tiled = same_cells(sites, client, (2, 2), tolerance=1e-3, rings=False)
    unbounded = int((tiled.visible & ~tiled.bounded).sum())
    assert unbounded > 0 and tiled.stats["whole_set_cells"] >= unbounded


def test_cells_of_sites_on_tile_boundaries_with_rings(client):
    """A 3 x 4 lattice of circles, 2 x 3 tiles: the grid lines run through centers."""
    sites = circles([(3 * x, 3 * y, 1) for x in range(3) for y in range(4)])
    kwargs = dict(box=(-2, -2, 9, 12), tolerance=1e-3, boundary_tolerance=0.3)
    single = ellvor.build(sites).cells(**kwargs)
    tiled = same_cells(sites, client, (2, 3), single, **kwargs)
    assert tiled.boundary_tolerance == single.boundary_tolerance == 0.3
    for a, b in zip(single.rings(), tiled.rings()):
        # Both within 0.3 of the same boundary: every tiled ring point within 0.6 of the single ring's
        # polyline, so within 0.6 and half its longest segment of one of its points.
        assert len(b) >= 3
        d = np.hypot(b[:, None, 0] - a[None, :, 0], b[:, None, 1] - a[None, :, 1]).min(axis=1)
        longest = np.hypot(*(np.roll(a, -1, axis=0) - a).T).max()
        assert d.max() <= 0.6 + longest / 2 + 1e-9
    assert tiled.area_lo.sum() <= 11 * 14 <= tiled.area_hi.sum() * (1 + 1e-12)   # the cells tile the box


def test_cells_in_a_periodic_box_wrap_the_tiles(client):
    sites = ellvor.generate("ellipses", 6, seed=4)
    x0, y0, x1, y1 = box_around(sites, 5)
    # The box as it is, and moved by half its size: centers outside it are wrapped in.
    for periodic in ((x0, y0, x1, y1), (x0 + (x1 - x0) // 2, y0 - (y1 - y0) // 2, x1 + (x1 - x0) // 2,
                                        y1 - (y1 - y0) // 2)):
        tiled = same_cells(sites, client, (2, 2), periodic=periodic, tolerance=1e-3, rings=False)
        assert tiled.domain == "periodic" and tiled.stats["fallback"] is False
        assert np.any(tiled.shifts != 0) and max(t["sites"] for t in tiled.tiles) > len(sites)   # copies held


def test_cells_one_tile_and_tiny_sets(client):
    sites = ellvor.generate("ellipses", 4, seed=1)
    tiled = same_cells(sites, client, (1, 1), box=box_around(sites, 40), tolerance=1e-3, rings=False)
    assert tiled.stats["fallback"] == "one tile" and tiled.stats["whole_set_cells"] == 4
    with pytest.raises(ellvor.Error, match="JSON"):
        tiled.to_json()


def test_cells_bad_input_is_refused_on_the_client():
    sites = ellvor.generate("ellipses", 20, seed=1)
    for kwargs in (dict(tolerance=0), dict(tolerance=2), dict(box=(0, 0, 1, 1)), dict(box=(5, 0, 1, 1)),
                   dict(box=(0, 0, 1, 1), periodic=(0, 0, 1, 1)), dict(boundary_tolerance=-1),
                   dict(tolerance="x")):
        with pytest.raises(ellvor.InputError) as single:
            ellvor.build(sites).cells(**kwargs)
        with pytest.raises(ellvor.InputError) as tiled:
            ed.cells(sites, client=_Unreachable(), **kwargs)
        assert str(tiled.value) == str(single.value), kwargs


def test_cells_of_crossing_circles_in_a_box(client):
    # Half of the circles cross another (signed distances): the tiles' cells are the single process's.
    sites = ellvor.generate("circles", 24, seed=6, crossing="1/2")
    same_cells(sites, client, (2, 2), box=box_around(sites, 40), rings=False)


def test_cells_of_a_deep_crossing_raise_the_single_error(client):
    # A needle whose tip lies deep in a fatter ellipse (their edge runs through the needle's
    # medial axis), among three circles and far from the other sites: the same InputError.
    sites = ellvor.generate("ellipses", 30, seed=6)
    deep = [("993/245", "32/75", "9/103", "3609/52", "68"), ("55/41", "349/142", "59/101", "15621/212", "15052/217"),
            ("1", "1", "0", "60", "60"), ("1", "1", "0", "80", "60"), ("1", "1", "0", "70", "80")]
    moved = [ellvor.Ellipse(*(Fraction(v) for v in e[:3]), Fraction(e[3]) + 1000, Fraction(e[4]) + 1000) for e in deep]
    both = list(sites) + moved
    with pytest.raises(ellvor.InputError) as single:
        ellvor.build(both).cells(rings=False)
    with pytest.raises(ellvor.InputError) as tiled:
        ed.cells(both, tiles=(2, 2), client=client, rings=False)
    assert "cross so deeply" in str(single.value)
    assert tiled.value.sites == single.value.sites == (30, 31) and str(tiled.value) == str(single.value)


def test_map_computes_cells_of_each_file(client, tmp_path, write_sites):
    path = tmp_path / "snapshot.ell"
    sites = ellvor.generate("ellipses", 4, seed=9)
    sites.write(path)
    box = box_around(sites, 40)
    (got_path, got), = ed.map([path], fn="cells", client=client, box=box, tolerance=1e-3, rings=False)
    single = ellvor.build(path).cells(box=box, tolerance=1e-3, rings=False)
    assert got_path == str(path) and np.array_equal(single.indices, got.indices)
    assert _overlap(single.area_lo, single.area_hi, got.area_lo, got.area_hi)
    bad = write_sites("1 1 0 0 0\n1 1 0 5000 5000\n", "outside.ell")
    with pytest.raises(ellvor.InputError) as refused:
        ed.map([path, bad], fn="cells", client=_Unreachable(), box=box)
    with pytest.raises(ellvor.InputError) as one:
        ellvor.build(bad).cells(box=box)
    assert str(refused.value) == str(one.value)


def test_the_cell_certificate_refuses_what_it_cannot_prove():
    region = (0.0, 10.0, 0.0, 10.0)
    boxes = np.array([[4.0, 6.0, 4.0, 6.0]] * 4)
    semi = np.array([1.0, 1.0, 1.0, 3.0])
    # K: the box grown by 2 max(reach, semi-axis): 2 + 2 * 1.99 < 10 fits, 2.01 does not, inf never.
    reach = np.array([1.99, 2.01, np.inf, 1.0])
    assert ed._reach_disk_inside(boxes, semi, reach, region).tolist() == [True, False, False, False]
    assert ed._reach_disk_inside(boxes[:1], semi[:1], np.array([np.inf]),
                                 (-np.inf, np.inf, -np.inf, 10.0)).tolist() == [False]
