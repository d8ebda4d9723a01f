"""Impossible or degenerate input on the command line: one line on stderr naming the option
and the value, exit status 2, no traceback."""

import io

import pytest

from tests.cli.test_errors import assert_one_line


@pytest.mark.parametrize("args, option", [
    (("sphere", "--gyration", 0.5), "--gyration must be <= sqrt(2/3) * radius"),
    (("pair", "--gyration2", 0.5), "--gyration2 must be <= sqrt(2/3) * radius"),
])  # fmt: skip
def test_a_gyration_no_sphere_has_is_refused(cli, args, option):
    status, out, err = cli(*args)
    assert_one_line(status, out, err, option)
    assert "0.5" in err and "0.0816497" in err


def test_a_grazing_sphere_is_refused_as_solve_refuses_vy(cli):
    status, out, err = cli("sphere", "--velocity", "1,-1e-300,0")
    assert_one_line(status, out, err, "normal velocity must be <= -1e-50")
    assert "division" not in err


@pytest.mark.slow
def test_a_map_of_a_tiny_body_is_drawn(cli, tmp_path):
    """The maps are dimensionless: a body of 1e-49 m gets the same map as any other (its
    spins R omega/|vy| = 3 used to overflow a float32 cast)."""
    target = tmp_path / "map.png"
    status, out, err = cli("map", "--radius", 1e-49, "--output", target, "--resolution", 20,
                           "--dpi", 50)  # fmt: skip
    assert status == 0, err
    assert target.stat().st_size > 0


def _parquet(path, **columns):
    pa = pytest.importorskip("pyarrow")
    pq = pytest.importorskip("pyarrow.parquet")
    pq.write_table(pa.table(columns), path)
    return path


INCIDENCE = dict(vx=[1.0, 2.0], vy=[-1.0, -1.0], omega=[0.0, 0.0])


def test_a_list_column_cannot_go_to_csv(cli, tmp_path):
    """A Parquet column of lists passes through to Parquet, but a CSV cell cannot hold a
    list: the column is named (it was "Unsupported Type: list<element: int64>")."""
    source = _parquet(tmp_path / "in.parquet", **INCIDENCE, tags=[[1, 2], [3]])
    status, out, err = cli("batch", source, "--output", tmp_path / "out.csv")
    assert_one_line(status, out, err, "column 'tags' holds lists (list<element: int64>)")
    assert ".parquet" in err and not (tmp_path / "out.csv").exists()
    status, _, err = cli("batch", source, "--output", tmp_path / "out.parquet")
    assert status == 0, err


def test_bytes_that_are_not_text_cannot_go_to_csv(cli, tmp_path):
    """It was "Invalid UTF8 payload"."""
    source = _parquet(tmp_path / "in.parquet", **INCIDENCE, note=[b"ok", b"\xff\xfe"])
    status, out, err = cli("batch", source, "--output", tmp_path / "out.csv")
    assert_one_line(status, out, err, "column 'note' holds bytes that are not UTF-8 text")
    assert not (tmp_path / "out.csv").exists()
    text = _parquet(tmp_path / "text.parquet", **INCIDENCE, note=[b"ok", b"fine"])
    status, _, err = cli("batch", text, "--output", tmp_path / "out.csv")
    assert status == 0, err


def test_a_huge_csv_field_names_its_row_and_the_limit(cli, tmp_path, monkeypatch):
    """A field longer than Python's csv module takes (often a quote left open) names the
    row, its line and the limit (it was "field larger than field limit (131072)")."""
    text = 'vx,vy,omega,note\n1,-1,0,short\n2,-1,0,"' + "x" * 200_000 + "\n"
    monkeypatch.setattr("sys.stdin", io.StringIO(text))  # read by the csv module
    status, out, err = cli("batch", "-", "--output", tmp_path / "out.csv")
    assert_one_line(status, out, err, "row 2 (line 3)")
    assert "131,072 characters" in err and "quote" in err
    header = 'vx,vy,omega,"' + "x" * 200_000 + "\n"
    monkeypatch.setattr("sys.stdin", io.StringIO(header))
    status, out, err = cli("batch", "-", "--output", tmp_path / "out.csv")
    assert_one_line(status, out, err, "the header (line 1): a field longer than")


def test_simulate_names_the_options_behind_a_tiny_inertia(cli):
    """It said "inertia must be >= 1e-50", which is no option of simulate."""
    status, out, err = cli("simulate", "--mass", 1e-50, "--radius", 1e-49)
    assert_one_line(status, out, err, "the moment of inertia mass * gyration**2 must be")
    assert "mass 1e-50 kg, radius 1e-49 m" in err
