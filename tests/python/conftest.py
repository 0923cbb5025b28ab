"""Fixtures of the Python suite: the ellvor CLI of the same build (the
module's answers are compared with it), the repository's data, sites made
for a test."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("ELLVOR_BINARY", str(ROOT / "build" / "ellvor"))


class Cli:
    """Runs `ellvor ARGS...`; returns (exit status, stdout, stderr)."""

    def __call__(self, *args, check=True):
        p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
        if check and p.returncode != 0:
            raise AssertionError(f"ellvor {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}")
        return p.returncode, p.stdout, p.stderr

    def json(self, *args):
        return json.loads(self(*args)[1])


@pytest.fixture(scope="session")
def cli():
    assert os.access(CLI, os.X_OK), f"no ellvor binary at {CLI} (make builds it)"
    return Cli()


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture
def write_sites(tmp_path):
    """write_sites(text, name) -> path of a site file holding `text`."""
    def write(text, name="sites.ell"):
        path = tmp_path / name
        path.write_text(text)
        return path
    return write
