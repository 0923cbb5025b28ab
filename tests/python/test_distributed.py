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
    c = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    yield c
    c.close()


@pytest.fixture(scope="module")
def client(cluster):
    with distributed.Client(cluster) as c:
        yield c


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


def test_sites_meeting_in_four_points_raise_the_single_builds_error(client):
    rng = random.Random(4)
    sites = [ellvor.Ellipse.circle(rng.randrange(-500, 500), rng.randrange(-500, 500), 1) for _ in range(300)]
    sites += [ellvor.Ellipse(3, Fraction(1, 5), 0, 1000, 1000), ellvor.Ellipse(3, Fraction(1, 5), 1, 1000, 1000)]
    with pytest.raises(ellvor.InputError) as single:
        ellvor.build(sites)
    with pytest.raises(ellvor.InputError) as tiled:
        ed.build(sites, tiles=(3, 3), client=client)
    assert tiled.value.sites == single.value.sites == (300, 301)


def test_the_seam_tests_refuse_what_they_cannot_prove():
    everything = (0.0, 10.0, 0.0, 10.0)
    region = (2.0, 6.0, -np.inf, np.inf)
    # Center 4, radius 1.9: clear of the slabs x <= 2 and x >= 6; radius 2: touches them.
    boxes = np.array([[4, 4, 5, 5, 1.9, 1.9], [4, 4, 5, 5, 2, 2], [3.9, 4.1, 5, 5, 1.85, 1.95],
                      [4, 4, 5, 5, -1, -0.5], [1, 1, 5, 5, -1, -0.5]])
    assert ed._disk_misses_outside(boxes, region, everything).tolist() == [True, False, False, True, False]
    # Two faces across an edge with overlapping circle boxes: possibly one circle (degenerate).
    faces = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 4]])
    c = np.array([[0, 1, 0, 1, 1, 2], [0.5, 1.5, 0.5, 1.5, 1.5, 3], [5, 6, 5, 6, 1, 2]], dtype=float)
    assert ed._possibly_degenerate(faces, c).tolist() == [True, True, False]


def test_without_a_client_a_local_cluster_is_started():
    d = same_graph(ellvor.generate("nested", 300, seed=2), None, (2, 2))
    assert d.stats["fallback"] is False


def test_empty_and_tiny_sets(client):
    for sites in ([], list(ellvor.generate("ellipses", 3, seed=1))):
        d = same_graph(ellvor.Sites(sites), client, (2, 2))
        assert d.stats["fallback"] == "too few sites or extreme coordinates"


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
        ed.map([good], fn="cells", client=_Unreachable())


def test_map_raises_the_builds_error_for_sites_meeting_in_four_points(client, write_sites):
    path = write_sites("3 1/5 0 0 0\n3 1/5 1 0 0\n1 1 0 10 10\n", "cross.ell")
    with pytest.raises(ellvor.InputError) as single:
        ellvor.build(path)
    with pytest.raises(ellvor.InputError) as mapped:
        list(ed.map([path], client=client))
    assert str(mapped.value) == str(single.value) and mapped.value.sites == single.value.sites == (0, 1)


def test_bounding_boxes_hold_the_ellipses_tightly():
    sites = ellvor.generate("ellipses", 200, seed=17)
    boxes = ed._bounding_boxes(sites.to_array())
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
    params = sites.to_array()
    candidates, polygon = ed._hull_candidates(params, ed._bounding_boxes(params), 2.5)
    border = {k for k, (x, y) in enumerate(params[:, 3:5]) if min(x, y, 29 - x, 29 - y) <= 2}
    assert border <= set(candidates.tolist())
    assert len(candidates) < 900 // 2 and all(min(x, y, 29 - x, 29 - y) <= 4 for x, y in params[candidates, 3:5])
    # Disks left of the polygon's edge x = 0, reaching x = 1 (short of the non-candidates, beyond x = 2.5),
    # x = 3 (into them) and, centered inside, x = 2 (their center inside the polygon: refused, conservative).
    boxes = np.array([[-5, -5, 15, 15, 6, 6], [-5, -5, 15, 15, 8, 8], [1, 1, 15, 15, 1, 1]], dtype=float)
    assert ed._disk_outside_polygon(boxes, polygon, 2.5).tolist() == [True, False, False]
