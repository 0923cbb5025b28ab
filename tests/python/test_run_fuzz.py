"""scripts/run-fuzz.sh (`make fuzz`) tells the findings of this run from the
old ones already in the findings directory, and fails only on new ones. Fake
fuzzers stand in for libFuzzer's (no clang needed): each writes the artifact
named in FAKE_FINDINGS (comma-separated) under its -artifact_prefix."""

import os
import re
import subprocess

import pytest

FAKE_FUZZER = """#!/bin/sh
for arg in "$@"; do
    case $arg in -artifact_prefix=*) prefix=${arg#-artifact_prefix=} ;; esac
done
echo "#2: cov: 1 ft: 1 corp: 1/1b exec/s: 1 rss: 1Mb"
for name in $(echo "${FAKE_FINDINGS:-}" | tr , ' '); do
    case $name in "$(basename "$0")"/*) echo input > "$prefix${name#*/}" ;; esac
done
exit 1
"""


def run_fuzz(root, build, findings=""):
    env = dict(os.environ, FUZZ_SECONDS="1", FAKE_FINDINGS=findings)
    p = subprocess.run(["bash", str(root / "scripts" / "run-fuzz.sh"), str(build)],
                       capture_output=True, text=True, env=env)
    return p.returncode, p.stdout


@pytest.fixture
def build(tmp_path):
    for target in ("fuzz_site_parser", "fuzz_build"):
        path = tmp_path / target
        path.write_text(FAKE_FUZZER)
        path.chmod(0o755)
    return tmp_path


def old_finding(build, name, artifact):
    path = build / "findings" / name / artifact
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("old input\n")
    return path


def test_no_findings_passes(root, build):
    status, out = run_fuzz(root, build)
    assert status == 0, out
    assert "parser: 0 new finding(s) in this run" in out
    assert "build: 0 new finding(s) in this run" in out
    assert "old finding" not in out


def test_old_findings_are_listed_apart_and_do_not_fail(root, build):
    a = old_finding(build, "build", "crash-aaa")
    b = old_finding(build, "build", "timeout-bbb")
    status, out = run_fuzz(root, build)
    assert status == 0, out
    assert "build: 0 new finding(s) in this run" in out
    assert "build: 2 old finding(s), there before this run" in out
    assert f"  {a}\n" in out and f"  {b}\n" in out
    assert "parser: 0 new finding(s)" in out and not re.search(r"^parser: \d+ old", out, re.M)


def test_a_new_finding_fails_and_is_told_from_the_old(root, build):
    old = old_finding(build, "build", "crash-aaa")
    status, out = run_fuzz(root, build, "fuzz_site_parser/crash-new")
    assert status == 1, out
    new = build / "findings" / "parser" / "crash-new"
    assert new.exists()
    assert f"parser: 1 new finding(s) in this run\n  {new}\n" in out
    assert "build: 0 new finding(s) in this run" in out
    assert f"build: 1 old finding(s), there before this run (not counted; remove each once fixed)\n  {old}\n" in out
    # The old finding is not reported as new, nor the new one as old.
    assert out.count(str(old)) == 1 and out.count(str(new)) == 1


def test_an_old_finding_found_again_stays_old(root, build):
    # libFuzzer names an artifact by its input's hash: the same input, the same file.
    old = old_finding(build, "build", "crash-aaa")
    status, out = run_fuzz(root, build, "fuzz_build/crash-aaa")
    assert status == 0, out
    assert "build: 0 new finding(s) in this run" in out
    assert f"build: 1 old finding(s), there before this run (not counted; remove each once fixed)\n  {old}\n" in out
