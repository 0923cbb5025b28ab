"""Errors: InputError carries the CLI's message and its location as fields;
a bad pair of sites carries the pair; everything else is ellvor.Error."""

import os

import pytest

import ellvor

# (file text, line, column) of malformed site files, each as `ellvor check` reports it.
MALFORMED = [
    ("1 1 0 0 0\n2 2 0 10\n", 2, 9),                     # a missing field
    ("1 1 0 0 0 7\n", 1, 11),                            # an extra field
    ("# comment\n\n1 1 0 0 1/0\n", 3, 9),                 # a zero denominator
    ("1 1 0 0 0\n1 -1 0 5 5\n", 2, 3),                   # b <= 0
    ("1 1 0 0 0\n2 1 nan 5 5\n", 2, 5),                   # not finite
    ("1 1 0 0 0\n1 1 0 0 0\n", 2, 1),                     # a duplicate site
    ("1099511627777 1 0 0 0\n", 1, 1),                    # semi-axes beyond 2^40 apart
    ("1 1 0 0 0\n1 1 0 0x10 0\n", 2, 7),                  # not a rational
]


def check_error(cli, path):
    status, _, stderr = cli("check", path, check=False)
    assert status == 2
    prefix = "ellvor: "
    assert stderr.startswith(prefix)
    return stderr[len(prefix):].rstrip("\n")


@pytest.mark.parametrize("text, line, column", MALFORMED)
def test_reading_errors_are_the_clis(cli, write_sites, text, line, column):
    path = write_sites(text)
    with pytest.raises(ellvor.InputError) as err:
        ellvor.read_sites(path)
    e = err.value
    assert str(e) == check_error(cli, path)
    assert (e.filename, e.lineno, e.column) == (str(path), line, column)
    assert str(e) == f"{path}:{line}:{column}: {e.reason}"
    assert isinstance(e, ValueError) and isinstance(e, ellvor.Error) and isinstance(e, RuntimeError)
    # build() reads the same way.
    with pytest.raises(ellvor.InputError, match=f"^{path}:{line}:{column}: "):
        ellvor.build(path)


def test_a_duplicate_names_both_sites(write_sites):
    path = write_sites("1 1 0 0 0\n2 1 0 10 0\n# again\n1 1 0 0 0\n")
    with pytest.raises(ellvor.InputError) as err:
        ellvor.read_sites(path)
    assert err.value.sites == (0, 2)
    assert err.value.reason == ("duplicate site: site 2 (line 4) is the same ellipse as site 0 (line 1); "
                                "sites must be distinct")


def test_a_duplicate_in_a_list_names_the_ids():
    e = ellvor.Ellipse(1, 2, 0, 0, 0)
    with pytest.raises(ellvor.InputError) as err:
        ellvor.build([e, ellvor.Ellipse.circle(10, 0, 1), ellvor.Ellipse(2, 1, 1, 0, 0)])
    assert err.value.sites == (0, 2) and err.value.filename is None
    assert str(err.value) == "duplicate site: site 2 is the same point set as site 0; sites must be distinct"


CROSSING = "# two crossing ellipses among separated circles\n" + "\n".join(
    [f"1 1 0 {10 * k} 0" for k in range(6)] + ["4 1 0 50 20", "1 4 0 52 20"]) + "\n"


def test_crossing_sites_in_a_file_point_at_their_lines(cli, write_sites):
    path = write_sites(CROSSING)
    status, _, stderr = cli("build", path, check=False)
    assert status == 2
    with pytest.raises(ellvor.InputError) as err:
        ellvor.build(path)
    e = err.value
    assert "ellvor: " + str(e) + "\n" == stderr
    assert e.sites == (6, 7) and (e.filename, e.lineno, e.column) == (str(path), 9, 1)
    assert e.reason == ("site 7 crosses site 6 (line 8): their boundaries meet in 4 points "
                        "(sites may cross in at most two)")
    # Read first, then built: the same error, with the lines.
    with pytest.raises(ellvor.InputError) as again:
        ellvor.build(ellvor.read_sites(path))
    assert str(again.value) == str(e) and again.value.sites == (6, 7)


def test_crossing_sites_in_a_list_carry_the_pair(write_sites):
    sites = list(ellvor.read_sites(write_sites(CROSSING)))
    with pytest.raises(ellvor.InputError) as err:
        ellvor.build(sites)
    assert err.value.sites == (6, 7) and err.value.filename is None and err.value.lineno is None
    assert "sites 6 and 7 cross: their boundaries meet in 4 points" in str(err.value)


def test_predicates_refuse_crossing_sites():
    e1, e2 = ellvor.Ellipse(4, 1, 0, 0, 0), ellvor.Ellipse(1, 4, 0, 0, 0)
    with pytest.raises(ellvor.InputError) as err:
        ellvor.side_of_bisector(e1, e2, (10, 10))
    assert err.value.sites == (0, 1)


def test_unreadable_paths(tmp_path):
    missing = tmp_path / "missing.ell"
    with pytest.raises(ellvor.InputError) as err:
        ellvor.read_sites(missing)
    assert str(err.value) == f"{missing}:1:1: cannot open file: No such file or directory"
    with pytest.raises(ellvor.InputError, match="is a directory"):
        ellvor.read_sites(tmp_path)
    with pytest.raises(ValueError, match="fmt"):
        ellvor.read_sites(missing, fmt="svg")


def test_other_failures_are_ellvor_errors(tmp_path):
    if os.geteuid() == 0:
        target = tmp_path / "no-such-dir" / "out.ell"  # root may write anywhere: use a missing folder
    else:
        target = "/proc/out.ell"
    with pytest.raises(ellvor.Error) as err:
        ellvor.Sites([ellvor.Ellipse.circle(0, 0, 1)]).write(target)
    assert not isinstance(err.value, ellvor.InputError) and isinstance(err.value, RuntimeError)
    assert "cannot write" in str(err.value)
    with pytest.raises(ellvor.Error, match="not a circle"):
        ellvor.Sites([ellvor.Ellipse(2, 1, 0, 0, 0)]).write(tmp_path / "x.cin", fmt="cin")
