"""The module's answers equal the CLI's on every command the two share:
build --json (byte for byte but the build's time), generate, incircle,
voronoi-circle and side-of-bisector (answers and deciding stages)."""

import re

import pytest

import ellvor

SECONDS = re.compile(r'"(removal_)?seconds":[-+0-9.eE]+')


def same_document(python_json, cli_json):
    # The two builds' wall times differ; every other byte must not.
    assert SECONDS.search(python_json) and SECONDS.search(cli_json)
    assert SECONDS.sub('"seconds":T', python_json) == SECONDS.sub('"seconds":T', cli_json)


def cli_build_json(cli, path, *extra):
    return cli("build", path, "--json", "-", *extra)[1].splitlines(keepends=True)[-1]  # after the summary


@pytest.mark.parametrize("name", ["example.ell", "example-300.ell"])
def test_build_json_of_the_bundled_data(cli, root, name):
    path = root / "data" / name
    d = ellvor.build(path)
    same_document(d.to_json(), cli_build_json(cli, path))


GENERATED = [("ellipses", 60, 1, 8), ("ellipses", 200, 7, 20), ("circles", 150, 3, 4), ("nested", 120, 11, 8),
             ("circles", 40, 5, 1), ("ellipses", 1500, 21, 8), ("nested", 800, 5, 12), ("circles", 1000, 9, 2)]


@pytest.mark.parametrize("kind, count, seed, bits", GENERATED)
def test_generate_and_build_of_random_sets(cli, tmp_path, kind, count, seed, bits):
    path = tmp_path / f"{kind}-{seed}.ell"
    cli("generate", kind, "--count", count, "--seed", seed, "--bits", bits, "--box", 60, "-o", path)
    sites = ellvor.generate(kind, count=count, seed=seed, bits=bits, box=60)
    file_lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    assert [str(e) for e in sites] == file_lines
    # Built from the generated list (no file) and from the file: both the CLI's document.
    expected = cli_build_json(cli, path)
    same_document(ellvor.build(sites).to_json(), expected)
    same_document(ellvor.build(path).to_json(), expected)


@pytest.mark.parametrize("kind, count, seed", [("nested", 200, 4), ("circles", 150, 6)])
def test_removals_as_the_cli(cli, tmp_path, kind, count, seed):
    path = tmp_path / "sites.ell"
    cli("generate", kind, "--count", count, "--seed", seed, "-o", path)
    d = ellvor.build(path)
    # Hidden sites, the sites hiding them, and others, in one order; removed in two calls.
    ids = [int(x) for x in d.hidden[:3].ravel()] + [7, 0, count - 1]
    ids = list(dict.fromkeys(ids))
    d.remove(ids[:2])
    d.remove(ids[2:])
    assert d.removed.tolist() == ids
    same_document(d.to_json(), cli_build_json(cli, path, "--remove", ",".join(map(str, ids))))
    assert d.validate() == ""
    removal = re.compile(r'"removal_seconds":[-+0-9.eE]+')
    assert removal.search(d.to_json())


def test_build_of_a_cin_file(cli, tmp_path):
    path = tmp_path / "circles.cin"
    cli("generate", "circles", "--count", 80, "--seed", 2, "--cin", "-o", path)
    d = ellvor.build(path, fmt="cin")
    same_document(d.to_json(), cli_build_json(cli, path, "--cin"))
    assert ellvor.read_sites(path, fmt="cin").filename == str(path)


def test_to_json_writes_the_file(cli, root, tmp_path):
    d = ellvor.build(root / "data" / "example.ell")
    out = tmp_path / "graph.json"
    assert d.to_json(out) == out.read_text()
    assert out.read_text().endswith("}\n")


def test_diagram_summary_matches_the_cli(cli, root):
    path = root / "data" / "example-300.ell"
    d = ellvor.build(path)
    summary = cli("build", path)[1].splitlines()[0]
    assert summary.startswith(f"{len(d)} sites ({len(d.hidden)} hidden), {len(d.edges)} Delaunay edges, "
                              f"{len(d.faces)} faces, built in ")
    assert d.validate() == ""
    assert cli("build", path, "--validate")[1].splitlines()[1] == "valid"


def instances(cli, tmp_path, family, set_name, step):
    """Every `step`-th instance file of a paper dataset, with its query point (kappa1)."""
    folder = tmp_path / f"{family}-{set_name}"
    cli("generate", "paper-dataset", family, "--set", set_name, "-o", f"{folder}/")
    manifest = (folder / f"{family}-{set_name}-manifest.txt").read_text().splitlines()
    rows = [line.split() for line in manifest if not line.startswith("#")]
    return [(folder / row[0], row[1:]) for row in rows[::step]]


def drop_time(d):
    return {k: v for k, v in d.items() if k not in ("time_us", "time_ms")}


@pytest.mark.parametrize("set_name, step", [("1", 25), ("2a", 40), ("2c", 40), ("3", 50)])
def test_incircle_answers_and_stages(cli, tmp_path, set_name, step):
    for path, _ in instances(cli, tmp_path, "incircle", set_name, step):
        sites = ellvor.read_sites(path)
        for cap in (4096, 64):
            expected = drop_time(cli.json("incircle", path, "--json", "--max-precision", cap))
            got = ellvor.incircle(*sites, max_precision=cap)
            assert drop_time(vars(got)) == expected, path


def test_incircle_on_ellipses(cli, tmp_path):
    # Four ellipses of a random set: answers from the filter and the Arb stage.
    sites = ellvor.generate("ellipses", count=40, seed=9, bits=8, box=20)
    stages = set()
    for k in range(0, 36, 3):
        quad = [sites[k], sites[k + 1], sites[k + 2], sites[k + 3]]
        path = tmp_path / f"q{k}.ell"
        ellvor.Sites(quad).write(path)
        expected = drop_time(cli.json("incircle", path, "--json", "--max-precision", 64))
        assert drop_time(vars(ellvor.incircle(*quad, max_precision=64))) == expected
        stages.add(expected["stage"])
    assert stages  # at least one answer compared


def test_side_of_bisector_answers_and_stages(cli, tmp_path):
    compared = 0
    for set_name, step in (("1", 20), ("2b", 40), ("3", 50)):
        for path, (x, y) in instances(cli, tmp_path, "kappa1", set_name, step):
            expected = drop_time(cli.json("side-of-bisector", path, x, y, "--json"))
            got = ellvor.side_of_bisector(*ellvor.read_sites(path), (x, y))
            assert drop_time(vars(got)) == expected, path
            compared += 1
    assert compared > 20


def circle_fields(answer):
    c = answer.circle
    return {"exists": True, "bits": answer.bits, "correct_bits": c.correct_bits, "precision": c.precision,
            "newton_steps": c.newton_steps, "found_by": c.found_by, "search_boxes": c.search_boxes,
            "tangency": [{"t": "inf" if t["t"] is None else t["t"].text, "chart": t["chart"],
                          "chart_parameter": t["chart_parameter"].text} for t in c.tangency],
            "center": [b.text for b in c.center], "radius": c.radius.text}


@pytest.mark.parametrize("bits", [53, 300])
def test_voronoi_circle_enclosures(cli, tmp_path, bits):
    # Random triples (some without a counter-clockwise circle) and faces of a diagram (with one).
    triples = [ellvor.generate("ellipses", count=3, seed=s, bits=6, box=10) for s in range(1, 5)]
    d = ellvor.build(ellvor.generate("ellipses", count=30, seed=4, bits=6, box=20))
    triples += [ellvor.Sites([d.sites[i] for i in face]) for face in d.faces[::7]]
    triples.append(ellvor.Sites([ellvor.Ellipse.circle(-3, 0, 2), ellvor.Ellipse.circle("3/2", 0, "1/2"),
                                 ellvor.Ellipse.circle(0, -2, 1)]))
    exists = 0
    for k, triple in enumerate(triples):
        path = tmp_path / f"t{k}.ell"
        triple.write(path)
        expected = drop_time(cli.json("voronoi-circle", path, "--bits", bits))
        got = ellvor.voronoi_circle(*triple, bits=bits)
        if expected["exists"]:
            exists += 1
            assert circle_fields(got) == expected
            for t in got.circle.tangency + [{"t": b} for b in got.circle.center]:
                ball = t["t"]
                assert ball is None or (ball.lo <= ball.hi and ball.mid in ball)
            assert got.circle.correct_bits >= bits
        else:
            assert (got.exists, got.circles, got.circle) == (False, expected["circles"], None)
        assert got.stage in ("filter", "subdivision", "symmetry", "exact")
    assert exists >= 5
