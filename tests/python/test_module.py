"""The module as a whole: the import line of the README, what build() accepts,
generate()'s checks, writing sites, and the scripts that use the module."""

import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import ellvor

# The children import the same build of the module as this process.
ENV = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(pathlib.Path(ellvor.__file__).resolve().parents[1]))


def run_python(*args, cwd):
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=cwd, env=ENV, check=True)


def test_the_readme_import_line(root):
    out = run_python("-c", "import ellvor, sys; print(ellvor.build('data/example-300.ell')); "
                           "print('matplotlib' in sys.modules)", cwd=root).stdout.splitlines()
    assert out[0].startswith("<ellvor.Diagram: 300 sites (30 hidden), ")
    assert out[1] == "False"  # plotting is imported on use only


def test_build_accepts_paths_sites_and_lists(root):
    path = root / "data" / "example.ell"
    expected = ellvor.build(str(path)).edges.tolist()
    sites = ellvor.read_sites(path)
    for argument in (path, os.fsencode(path), sites, list(sites), tuple(sites)):
        assert ellvor.build(argument).edges.tolist() == expected
    with pytest.raises(TypeError):
        ellvor.build([sites[0], "1 1 0 0 0"])
    with pytest.raises(TypeError):
        ellvor.build(42)


def test_generate_checks_its_arguments(cli, write_sites):
    for kwargs in ({"kind": "squares"}, {"count": -1}, {"count": 10**7}, {"bits": 0}, {"bits": 1001},
                   {"box": 0}, {"box": "-1"}, {"nested_fraction": 1}, {"nested_fraction": "-0.1"},
                   {"count": 5000, "box": "1/100"}, {"crossing": "1/2"}, {"kind": "circles", "crossing": 2},
                   {"kind": "circles", "count": 10, "crossing": "1/10"}):
        with pytest.raises(ValueError):
            ellvor.generate(**kwargs)
    nested = ellvor.generate("nested", count=40, seed=3)
    assert len(ellvor.build(nested).hidden) == 10  # a quarter by default, as the CLI
    assert all(e.is_circle for e in ellvor.generate("circles", count=30))
    # As `ellvor generate circles --crossing 3/10`: exactly 30% cross another circle.
    crossing = ellvor.generate("circles", count=100, seed=4, crossing="3/10")
    _, text, _ = cli("generate", "circles", "--count", 100, "--seed", 4, "--crossing", "3/10")
    assert list(crossing) == list(ellvor.read_sites(write_sites(text)))
    d = ellvor.build(crossing)
    assert d.validate() == ""


@pytest.mark.parametrize("fmt", ["ell", "cin"])
def test_sites_write_and_read_back_exactly(tmp_path, fmt):
    sites = ellvor.generate("circles", count=25, seed=8, bits=30)
    path = tmp_path / f"s.{fmt}"
    sites.write(path, fmt=fmt)
    back = ellvor.read_sites(path, fmt=fmt)
    assert list(back) == list(sites) and back.filename == str(path)
    assert back.lines.tolist() == list(range(1, 26))


def test_the_example_script(root, tmp_path):
    out = tmp_path / "example.png"
    text = run_python(str(root / "examples" / "plot_example.py"), str(out), cwd=tmp_path).stdout
    assert "300 sites (30 hidden)" in text and "\nvalid\n" in text and "incircle:" in text
    assert out.read_bytes()[:4] == b"\x89PNG"


def test_the_results_charts(root, tmp_path):
    for name in ("build_scaling", "precision_vs_time", "degeneracy_stress"):
        shutil.copy(root / "experiments" / "results" / f"{name}.csv", tmp_path)
    run_python(str(root / "experiments" / "plot_results.py"), "--dir", str(tmp_path), cwd=tmp_path)
    for name in ("build_scaling", "precision_vs_time", "degeneracy_stress"):
        assert pathlib.Path(tmp_path / f"{name}.png").read_bytes()[:4] == b"\x89PNG"
