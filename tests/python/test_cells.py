"""Diagram.cells(), regions and point_region: the arrays equal `ellvor cells`'s CSV and JSON,
the intervals are ordered and consistent, the regions agree with the ridges, bad input raises
InputError with the CLI's message, and ellvor.plot fills the cells."""

import csv
import io
import json
import math
from fractions import Fraction

import numpy as np
import pytest

import ellvor

# Seven disjoint sites: two bounded cells, one hidden site (5 inside 1), four unbounded.
SITES = "1 1/2 0 0 0\n1 1 0 4 0\n1/2 1/2 0 2 3\n2 1 1/3 1 -4\n1 1 0 5 5\n1/4 1/4 0 4 0\n3/2 1 0 -4 1\n"


@pytest.fixture(scope="module")
def sites_path(tmp_path_factory):
    path = tmp_path_factory.mktemp("cells") / "sites.ell"
    path.write_text(SITES)
    return path


@pytest.fixture(scope="module")
def computed(sites_path):
    d = ellvor.build(sites_path)
    return d, d.cells()


def csv_rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def close_bound(python_value, printed):
    """A double bound and the CSV's decimal bound of the same ball endpoint, each rounded
    outward from it: equal up to the rounding of each (a few ulps)."""
    if printed in ("inf", "-inf", "nan"):
        return math.isnan(python_value) if printed == "nan" else python_value == float(printed)
    return abs(python_value - float(printed)) <= 4 * math.ulp(python_value)


def test_arrays_equal_the_cli_csv(cli, sites_path, computed):
    _, c = computed
    rows = csv_rows(cli("cells", sites_path)[1])
    assert len(rows) == len(c) == 7
    for k, row in enumerate(rows):
        assert int(row["site"]) == k
        assert bool(int(row["visible"])) == c.visible[k]
        for name in ("area", "perimeter"):
            assert close_bound(c.__dict__[f"{name}_lo"][k], row[f"{name}_lo"]), (k, name)
            assert close_bound(c.__dict__[f"{name}_hi"][k], row[f"{name}_hi"]), (k, name)
        if c.visible[k]:
            assert close_bound(c.packing_fraction_lo[k], row["packing_fraction_lo"])
            assert close_bound(c.packing_fraction_hi[k], row["packing_fraction_hi"])
        else:
            assert row["packing_fraction_lo"] == row["packing_fraction_hi"] == ""
            assert math.isnan(c.packing_fraction_lo[k])
        # site_area: the CSV's certain digits against the Python bounds.
        assert c.site_area_lo[k] <= float(row["site_area"]) * (1 + 1e-15)
        assert float(row["site_area"]) * (1 - 1e-15) <= c.site_area_hi[k]
        assert [int(n) for n in row["neighbors"].split()] == c.neighbors_of(k).tolist()


def test_arrays_equal_the_cli_json_exactly(cli, sites_path, computed):
    _, c = computed
    doc = cli.json("cells", sites_path, "--format", "json")
    assert json.loads(c.to_json()) == doc
    for k, cell in enumerate(doc["cells"]):
        for name in ("area", "site_area"):
            lo, hi = (float(cell[name][e]) for e in ("lo", "hi"))
            assert (c.__dict__[f"{name}_lo"][k], c.__dict__[f"{name}_hi"][k]) == (lo, hi)
        assert cell["sides"] == [{"neighbor": int(n), "wall": None, "shift": [0, 0], "from": int(f), "to": int(t)}
                                 for n, (f, t) in zip(c.neighbors_of(k), c.side_vertices[c.indptr[k]:c.indptr[k + 1]])]
    assert len(doc["vertices"]) == len(c.vertices_lo)


def test_intervals_are_ordered_and_cells_hold_their_sites(computed):
    d, c = computed
    for lo, hi in ((c.area_lo, c.area_hi), (c.site_area_lo, c.site_area_hi),
                   (c.packing_fraction_lo, c.packing_fraction_hi), (c.vertices_lo, c.vertices_hi)):
        known = ~np.isnan(lo)
        assert (lo[known] <= hi[known]).all()
    bounded = c.visible & c.bounded
    assert bounded.sum() == 2
    # Free plane: a bounded cell holds its site, so its area is at least the site's.
    assert (c.area_lo[bounded] >= c.site_area_hi[bounded]).all()
    assert (c.area_hi[bounded] - c.area_lo[bounded] <= 1e-9 * c.area_lo[bounded] * (1 + 1e-12)).all()
    assert np.isinf(c.area_lo[c.visible & ~c.bounded]).all()
    assert (c.area_hi[~c.visible] == 0).all()
    # pi a b enclosed; the packing fraction is site area / area.
    a = np.array([float(Fraction(e.a) * Fraction(e.b)) for e in d.sites]) * math.pi
    assert (np.abs(a - c.site_area) <= 1e-15 * a).all()
    assert (c.packing_fraction_lo[bounded] <= c.site_area_hi[bounded] / c.area_lo[bounded]).all()
    assert (c.packing_fraction_hi[bounded] >= c.site_area_lo[bounded] / c.area_hi[bounded]).all()
    # Neighbourhood is symmetric.
    for k in range(len(c)):
        for n in c.neighbors_of(k):
            assert k in c.neighbors_of(n)


def ridge_pairs_of(d, k):
    return sorted(tuple(sorted(v)) for p, v in zip(d.ridge_points.tolist(), d.ridge_vertices.tolist()) if k in p)


def region_pairs(region):
    return sorted(tuple(sorted((region[i], region[(i + 1) % len(region)]))) for i in range(len(region)))


def test_regions_agree_with_the_ridges(root):
    d = ellvor.build(root / "data" / "example-300.ell")
    regions, point_region = d.regions, d.point_region
    assert len(point_region) == len(d) == 300
    hidden = set(d.hidden[:, 0].tolist())
    for k in range(len(d)):
        region = regions[point_region[k]]
        if k in hidden:
            assert region == []
            continue
        assert region.count(-1) <= 1
        # The region's consecutive vertices are the ridges of site k, each once.
        assert region_pairs(region) == ridge_pairs_of(d, k), k
        assert all(-1 <= v < len(d.faces) for v in region)


def test_cells_regions_are_the_diagrams(computed):
    d, c = computed
    assert c.regions == d.regions
    assert c.point_region.tolist() == d.point_region.tolist()
    assert len(c.vertices_lo) == len(d.vertices)
    # The same Voronoi vertices: the diagram's doubles inside the cells' certified boxes.
    assert (c.vertices_lo <= d.vertices + d.vertex_errors[:, None]).all()
    assert (d.vertices - d.vertex_errors[:, None] <= c.vertices_hi).all()


def test_rings_and_geojson(cli, sites_path, computed, tmp_path):
    _, c = computed
    rings = c.rings()
    assert len(rings) == len(c)
    assert all(r.ndim == 2 and r.shape[1] == 2 for r in rings)
    path = tmp_path / "cells.geojson"
    text = c.to_geojson(path)
    assert path.read_text() == text == cli("cells", sites_path, "--format", "geojson")[1]
    doc = json.loads(text)
    assert doc["type"] == "FeatureCollection"
    assert len(doc["features"]) == sum(1 for r in rings if len(r))


def test_reach_bounds_every_ring_point_with_or_without_rings(computed):
    """A bounded cell's reach (from the areas' quadrature; the rings' covers only lower it) is at least the
    distance of every ring point from the site's center, less the ring's tolerance; hidden and unbounded
    cells have none."""
    d, c = computed
    plain = d.cells(rings=False)
    assert not any(len(r) for r in plain.rings())
    centers = np.array([[float(Fraction(e.xc)), float(Fraction(e.yc))] for e in d.sites])
    bounded = 0
    for k, ring in enumerate(c.rings()):
        if not c.bounded[k]:
            assert math.isinf(c.reach[k]) and math.isinf(plain.reach[k])
            continue
        bounded += 1
        far = np.hypot(*(ring - centers[k]).T).max()
        for reach in (c.reach[k], plain.reach[k]):
            assert far - c.boundary_tolerance <= reach <= 1.1 * far + c.boundary_tolerance
    assert bounded == 2


@pytest.mark.parametrize("kwargs, message", [
    ({"tolerance": 0}, "tolerance: expected a number in (0, 1], got 0"),
    ({"tolerance": 2}, "tolerance: expected a number in (0, 1], got 2"),
    ({"tolerance": float("nan")}, "tolerance: expected a number in (0, 1], got nan"),
    ({"tolerance": "abc"}, "tolerance: expected a number, got 'abc'"),
    ({"boundary_tolerance": 0}, "boundary_tolerance: expected a positive number, got 0"),
    ({"boundary_tolerance": -1}, "boundary_tolerance: expected a positive number, got -1"),
    ({"box": (0, 0, -1, 5)}, "box: an empty box: X0 = 0 is not below X1 = -1"),
    ({"periodic": (0, 3, 1, "3")}, "periodic: an empty box: Y0 = 3 is not below Y1 = 3"),
    ({"box": (0, 0, 1)}, "box: expected four numbers (x0, y0, x1, y1)"),
    ({"box": (0, 0, 1, 1), "periodic": (0, 0, 1, 1)}, "box and periodic exclude each other"),
    ({"threads": -1}, "threads: expected a whole number from 0 to 1024, got -1"),
    ({"threads": 1.5}, "threads: expected a whole number from 0 to 1024, got 1.5"),
    ({"threads": True}, "threads: expected a whole number from 0 to 1024, got True"),
])
def test_bad_arguments_raise_input_error(computed, kwargs, message):
    d, _ = computed
    with pytest.raises(ellvor.InputError) as e:
        d.cells(**kwargs)
    assert str(e.value) == message


def test_threads_give_the_same_cells(cli, tmp_path):
    # 600 sites: three chunks of cells (cells/cell_chunks.hpp), measured by two threads or one.
    path = tmp_path / "sites.ell"
    path.write_text(cli("generate", "ellipses", "--count", "600", "--seed", "4")[1])
    d = ellvor.build(path)
    one, two = d.cells(box=(-101, -101, 101, 101), rings=False), d.cells(box=(-101, -101, 101, 101), rings=False,
                                                                          threads=2)
    for name in ("area_lo", "area_hi", "perimeter_lo", "perimeter_hi"):
        assert np.array_equal(getattr(one, name), getattr(two, name)), name
    assert np.array_equal(one.indices, two.indices)
    assert one.area_lo.sum() <= 202 ** 2 <= one.area_hi.sum()


def test_site_errors_carry_the_cli_message(cli, sites_path, write_sites):
    d = ellvor.build(sites_path)
    with pytest.raises(ellvor.InputError) as e:
        d.cells(box=("-10", -10, 10, "3"))
    status, _, err = cli("cells", sites_path, "--box", -10, -10, 10, 3, check=False)
    assert status == 2
    assert err.strip() == f"ellvor: {e.value}"
    assert (e.value.filename, e.value.lineno) == (str(sites_path), 5)
    # A needle whose tip lies deep in a fatter ellipse: their edge runs
    # through the needle's medial axis (crossing sites are fine otherwise).
    deep = write_sites("993/245 32/75 9/103 3609/52 68\n55/41 349/142 59/101 15621/212 15052/217\n"
                       "1 1 0 60 60\n1 1 0 80 60\n1 1 0 70 80\n", "deep.ell")
    with pytest.raises(ellvor.InputError) as e:
        ellvor.build(deep).cells()
    status, _, err = cli("cells", deep, check=False)
    assert status == 2 and err.strip() == f"ellvor: {e.value}"
    assert "cross so deeply" in str(e.value)
    assert e.value.sites == (0, 1)


def test_cells_after_remove_is_refused(sites_path):
    d = ellvor.build(sites_path)
    d.remove(6)
    with pytest.raises(ValueError, match="remove"):
        d.cells()


def test_plot_fills_cells_with_a_colour_bar(computed):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    d, c = computed
    fig, ax = plt.subplots()
    ellvor.plot(d, ax=ax, cells=c, color="packing_fraction")
    filled = [coll for coll in ax.collections if coll.get_array() is not None]
    assert len(filled) == 1
    values = np.asarray(filled[0].get_array())
    bounded = c.visible & c.bounded
    mid = ((c.packing_fraction_lo + c.packing_fraction_hi) / 2)[bounded]
    assert np.allclose(np.sort(values), np.sort(mid))
    assert len(fig.axes) == 2  # the colour bar
    assert "packing fraction" in fig.axes[1].get_ylabel()
    fig.savefig(io.BytesIO(), format="png")
    plt.close(fig)
    with pytest.raises(ValueError, match="color"):
        ellvor.plot(d, cells=c, color="area")


def test_plot_fills_the_rings_when_there_are_some(computed):
    """The ring branch, on rings made by hand (triangles around the bounded cells' sites)."""
    import copy

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    d, c = computed
    drawn = copy.copy(c)
    bounded = np.flatnonzero(c.visible & c.bounded)
    drawn._rings = [np.array([[x - 2, y - 2], [x + 2, y - 2], [x, y + 2]]) if k in bounded else np.zeros((0, 2))
                    for k, (x, y) in enumerate(d.points)]
    fig, ax = plt.subplots()
    ellvor.plot(d, ax=ax, cells=drawn)
    polys = [coll for coll in ax.collections if isinstance(coll, PolyCollection)]
    assert len(polys) == 1 and len(polys[0].get_paths()) == len(bounded)
    assert "no rings" not in fig.axes[1].get_ylabel()
    plt.close(fig)
