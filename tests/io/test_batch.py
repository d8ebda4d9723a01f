"""`spinimpact batch`: CSV (and Parquet) files of incidences, solved in chunks."""

import csv
import dataclasses
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.io.batch import RESULT_COLUMNS, BatchError, result_columns, run_batch
from spinimpact.model.impact import Impact
from spinimpact.model.result import Array

DEFAULTS = dict(mu=0.3, kappa=0.8, mass=1.0, radius=0.1, body="solid-sphere", gyration=None)


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "spinimpact", *map(str, args)],
        capture_output=True,
        text=True,
        timeout=120,
    )


@pytest.fixture
def mixed(tmp_path):
    """Rows with per-row mu, kappa, body and a custom gyration."""
    rng = np.random.default_rng(5)
    n = 257
    rows = []
    for i in range(n):
        body = ["", "ring", "solid-disk", "spherical-shell", "solid-sphere"][i % 5]
        gyration = "0.25" if i % 7 == 0 else ""  # a spool: rho > R
        if gyration:
            body = ""  # a row gives a body or a gyration, not both
        rows.append(
            [
                repr(float(rng.normal(0, 3))),
                repr(float(-rng.uniform(0.1, 5))),
                repr(float(rng.normal(0, 60))),
                repr(float(rng.uniform(0, 1))) if i % 3 else "",
                repr(float(rng.uniform(0, 1))),
                body,
                gyration,
            ]
        )
    path = tmp_path / "in.csv"
    write_csv(path, ["vx", "vy", "omega", "mu", "kappa", "body", "gyration"], rows)
    return path, rows


def expected(row):
    vx, vy, omega = (float(row[k]) for k in (0, 1, 2))
    mu = float(row[3]) if row[3] else DEFAULTS["mu"]
    kappa = float(row[4])
    if row[6]:
        body = Body(mass=1.0, radius=0.1, gyration=float(row[6]))
    else:
        body = Body.preset(row[5] or "solid-sphere", mass=1.0, radius=0.1)
    return solve(body, vx, vy, omega, mu=mu, kappa=kappa)


@pytest.mark.slow
def test_csv_round_trip_equals_python_api(mixed, tmp_path):
    path, rows = mixed
    out = tmp_path / "out.csv"
    result = cli("batch", path, "--output", out, "--mu", 0.3, "--chunk-size", 50)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"wrote {len(rows)} rows to {out}"
    got = read_csv(out)
    assert len(got) == len(rows)
    assert list(got[0])[:7] == ["vx", "vy", "omega", "mu", "kappa", "body", "gyration"]
    assert set(RESULT_COLUMNS) <= set(got[0])
    for row, line in zip(rows, got, strict=True):
        imp = expected(row)
        assert line["regime"] == imp.regime
        for name in (
            "after_vx",
            "after_vy",
            "after_omega",
            "dissipated_energy",
            "impulse_ratio",
            "work_restitution_tangential",
            "min_kinetic_energy",
            "tau_star",
        ):
            # shortest round-trip repr: the printed digits give back the same float
            assert float(line[name]) == float(RESULT_COLUMNS[name](imp)), name
        assert line["rolling"] == ("true" if imp.outcome.rolling else "false")


@pytest.mark.slow
def test_bad_row_stops_the_run_and_keeps_the_old_output(tmp_path):
    src, out = tmp_path / "in.csv", tmp_path / "out.csv"
    write_csv(
        src, ["vx", "vy", "omega", "kappa"], [[1, -1, 0, 0.5], [2, -1, 0, 1.5], [3, -1, 0, 0.5]]
    )
    out.write_text("previous results\n")
    result = cli("batch", src, "--output", out)
    assert result.returncode == 2
    assert result.stderr.strip() == (
        "spinimpact: error: row 2 (line 3), column kappa: kappa must be in [0, 1], got 1.5"
    )
    assert out.read_text() == "previous results\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.csv", "out.csv"]


@pytest.mark.parametrize(
    ("header", "row", "message"),
    [
        (["vx", "omega"], [1, 0], "missing column 'vy'"),
        (
            ["vx", "vy", "omega"],
            [1, "fast", 0],
            "row 2 (line 3), column vy: 'fast' is not a number",
        ),
        (["vx", "vy", "omega"], [1, -1], "row 2 (line 3): expected 3 fields, got 2"),
        (["vx", "vy", "omega"], [1, 0.5, 0], "column vy: vy must be < 0"),
        (["vx", "vy", "omega"], ["", -1, 0], "column vx: empty, but vx is required"),
        (["vx", "vy", "omega", "body"], [1, -1, 0, "cube"], "column body: must be one of"),
        (["vx", "vy", "omega", "mass"], [1, -1, 0, -2], "column mass: mass must be > 0"),
        (["vx", "vy", "omega", "mu"], [1, -1, 0, "nan"], "column mu: mu must be finite"),
    ],
)
def test_malformed_rows_name_row_and_column(tmp_path, header, row, message):
    src = tmp_path / "in.csv"
    good = {"vx": 1, "vy": -1, "omega": 0, "body": "ring", "mass": 2, "mu": 0.3}
    write_csv(src, header, [[good[h] for h in header], row])
    with pytest.raises(BatchError, match=message.replace("(", r"\(").replace(")", r"\)")):
        run_batch(src, tmp_path / "out.csv", defaults=DEFAULTS)
    assert not (tmp_path / "out.csv").exists()


@pytest.mark.slow
def test_skip_writes_error_rows_and_counts_them(tmp_path):
    src, out = tmp_path / "in.csv", tmp_path / "out.csv"
    write_csv(src, ["vx", "vy", "omega"], [[1, -1, 0], [2, "x", 0], [3, 1, 0], [4, -2, 0]])
    result = cli("batch", src, "--output", out, "--on-error", "skip", "--chunk-size", 3)
    assert result.returncode == 0, result.stderr
    assert "wrote 4 rows" in result.stdout and "2 with errors" in result.stdout
    got = read_csv(out)
    assert [r["error"] for r in got][0] == "" and got[3]["error"] == ""
    assert "row 2 (line 3), column vy" in got[1]["error"] and got[1]["after_vx"] == ""
    assert "row 3 (line 4), column vy: vy must be < 0" in got[2]["error"]
    assert float(got[3]["after_vx"]) == float(
        solve(Body.solid_sphere(mass=1, radius=0.1), 4.0, -2.0, 0.0, mu=0.2, kappa=0.8).after.vx
    )


@pytest.mark.slow
def test_empty_and_missing_input(tmp_path):
    (tmp_path / "empty.csv").write_text("")
    result = cli("batch", tmp_path / "empty.csv", "--output", tmp_path / "o.csv")
    assert result.returncode == 2 and "is empty" in result.stderr
    result = cli("batch", tmp_path / "nope.csv", "--output", tmp_path / "o.csv")
    assert result.returncode == 2 and "does not exist" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


@pytest.mark.slow
def test_chunking_does_not_change_results(mixed, tmp_path):
    path, _ = mixed
    run_batch(path, tmp_path / "a.csv", defaults=DEFAULTS, chunk_size=1)
    run_batch(path, tmp_path / "b.csv", defaults=DEFAULTS, chunk_size=10_000)
    assert (tmp_path / "a.csv").read_text() == (tmp_path / "b.csv").read_text()


def test_parquet_in_and_out(mixed, tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the [parquet] extra is not installed")
    path, rows = mixed
    run_batch(path, tmp_path / "out.csv", defaults=DEFAULTS, chunk_size=64)
    run_batch(path, tmp_path / "out.parquet", defaults=DEFAULTS, chunk_size=64)
    table = pq.read_table(tmp_path / "out.parquet").to_pydict()
    from_csv = read_csv(tmp_path / "out.csv")
    assert table["regime"] == [r["regime"] for r in from_csv]
    np.testing.assert_array_equal(table["after_vx"], [float(r["after_vx"]) for r in from_csv])
    assert table["rolling"] == [r["rolling"] == "true" for r in from_csv]
    # Parquet input too: numeric columns straight from the file
    pa = pytest.importorskip("pyarrow")
    src = tmp_path / "in.parquet"
    pq.write_table(pa.table({"vx": [1.0, 2.0], "vy": [-1.0, -2.0], "omega": [0.0, 5.0]}), src)
    summary = run_batch(src, tmp_path / "from_parquet.csv", defaults=DEFAULTS)
    assert summary.rows == 2
    got = read_csv(tmp_path / "from_parquet.csv")
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 2.0, -2.0, 5.0, mu=0.3, kappa=0.8)
    assert float(got[1]["after_omega"]) == float(imp.after.omega)


def _run(tmp_path, text, *args, name="in.csv"):
    src = tmp_path / name
    src.write_bytes(text.encode("utf-8") if isinstance(text, str) else text)
    return cli("batch", src, "--output", tmp_path / "out.csv", *args)


@pytest.mark.slow
def test_common_csv_layouts(tmp_path):
    # byte-order mark, CRLF line ends, blank lines, a quoted multi-line field
    text = '\ufeffvx,vy,omega,note\r\n1,-1,0,"two\r\nlines"\r\n\r\n2,-2,5,plain\r\n\r\n'
    result = _run(tmp_path, text)
    assert result.returncode == 0, result.stderr
    got = read_csv(tmp_path / "out.csv")
    assert [r["vx"] for r in got] == ["1", "2"] and got[0]["note"] == "two\r\nlines"
    # line numbers count physical lines, quoted line breaks included
    bad = _run(tmp_path, 'vx,vy,omega,note\n1,-1,0,"a\nb"\n2,1,0,c\n')
    assert "row 2 (line 4), column vy" in bad.stderr


@pytest.mark.parametrize(
    ("header", "message"),
    [
        ("vx,vy,omega,vx", "duplicate column 'vx'"),
        ("vx,vy,omega,zeta", "input column 'zeta' has the name of an output column"),
        ("vx;vy;omega", "missing column 'vx'"),
    ],
)
@pytest.mark.slow
def test_header_problems(tmp_path, header, message):
    result = _run(tmp_path, header + "\n1,-1,0,0\n")
    assert result.returncode == 2 and message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


@pytest.mark.slow
def test_error_column_name_is_reserved_in_skip_mode(tmp_path):
    result = _run(tmp_path, "vx,vy,omega,error\n1,-1,0,x\n", "--on-error", "skip")
    assert result.returncode == 2 and "'error'" in result.stderr


@pytest.mark.slow
def test_body_and_gyration_per_row(tmp_path):
    text = "vx,vy,omega,body,gyration\n1,-1,0,ring,\n1,-1,0,,0.2\n1,-1,0,ring,0.05\n1,-1,0,Ring,\n"
    result = _run(tmp_path, text, "--gyration", "0.3", "--on-error", "skip")
    assert result.returncode == 0, result.stderr
    got = read_csv(tmp_path / "out.csv")
    assert float(got[0]["zeta"]) == 2.0  # the row's body beats the default gyration
    assert float(got[1]["zeta"]) == pytest.approx(1 + (0.1 / 0.2) ** 2)
    assert "either body or gyration" in got[2]["error"]
    assert "got 'Ring'" in got[3]["error"]


@pytest.mark.slow
def test_first_bad_row_is_reported_whatever_the_column(tmp_path):
    result = _run(tmp_path, "vx,vy,omega\n1,-2,x\ny,-2,3\n")
    assert result.returncode == 2 and "row 1 (line 2), column omega" in result.stderr


@pytest.mark.slow
def test_bad_defaults_and_outputs(tmp_path):
    src = tmp_path / "in.csv"
    src.write_text("vx,vy,omega\n1,-1,0\n")
    result = cli("batch", src, "--output", tmp_path / "o.csv", "--mu", "-1")
    assert result.returncode == 2 and "--mu must be >= 0" in result.stderr
    for target, needle in (
        (tmp_path / "o.xlsx", "must end in .csv, .parquet or .pq"),
        (tmp_path / "nodir" / "o.csv", "No such directory"),
        (tmp_path, "must end in"),
    ):
        result = cli("batch", src, "--output", target)
        assert result.returncode == 2 and needle in result.stderr, result.stderr
        assert len(result.stderr.strip().splitlines()) == 1


@pytest.mark.slow
def test_special_file_output_is_not_replaced(tmp_path):
    import os
    import stat

    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    src = tmp_path / "in.csv"
    src.write_text("vx,vy,omega\n1,-1,0\n")
    reader = subprocess.Popen(["cat", str(fifo)], stdout=subprocess.PIPE, text=True)
    result = cli("batch", src, "--output", fifo)
    out, _ = reader.communicate(timeout=60)
    assert result.returncode == 0, result.stderr
    assert next(csv.reader([out.splitlines()[0]]))[:4] == ["vx", "vy", "omega", "regime"]
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)  # still a pipe


def test_parquet_nulls_skip_and_empty(tmp_path):
    pa = pytest.importorskip("pyarrow", reason="the [parquet] extra is not installed")
    import pyarrow.parquet as pq

    src = tmp_path / "in.parquet"
    table = pa.table(
        {
            "vx": [1.0, 2.0, None],
            "vy": [-1.0, -2.0, -1.0],
            "omega": [0.0, 5.0, 0.0],
            "mu": [None, 0.5, 0.1],
            "body": [None, "ring", None],
        }
    )
    pq.write_table(table, src)
    summary = run_batch(
        src, tmp_path / "o.parquet", defaults=DEFAULTS, on_error="skip", chunk_size=1
    )
    got = pq.read_table(tmp_path / "o.parquet").to_pydict()
    assert summary.rows == 3 and summary.skipped == 1
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.3, kappa=0.8)
    assert got["after_vx"][0] == float(imp.after.vx)  # null mu took the default 0.3
    assert got["zeta"][1] == 2.0
    assert got["regime"][2] is None and "row 3, column vx: empty" in got["error"][2]
    assert got["mu"] == [None, 0.5, 0.1]  # input columns keep their values and nulls
    # a first chunk where every row is bad does not fix a wrong schema
    bad_first = tmp_path / "bad_first.csv"
    bad_first.write_text("vx,vy,omega\nq,-1,1\n1,-2,3\n")
    run_batch(bad_first, tmp_path / "b.parquet", defaults=DEFAULTS, on_error="skip", chunk_size=1)
    got = pq.read_table(tmp_path / "b.parquet").to_pydict()
    assert got["regime"][1] == "stick-compression" and got["vx"] == [None, 1.0]
    # no rows: a valid, empty file with the schema
    empty = tmp_path / "empty.csv"
    empty.write_text("vx,vy,omega\n")
    run_batch(empty, tmp_path / "e.parquet", defaults=DEFAULTS)
    assert pq.read_table(tmp_path / "e.parquet").num_rows == 0
    assert "after_vx" in pq.read_table(tmp_path / "e.parquet").column_names


def test_csv_writer_without_pyarrow_gives_the_same_values(mixed, tmp_path, monkeypatch):
    import spinimpact.io.batch as batch

    path, _ = mixed
    run_batch(path, tmp_path / "arrow.csv", defaults=DEFAULTS, on_error="skip", chunk_size=100)
    monkeypatch.setattr(batch, "_have_pyarrow", lambda: False)
    run_batch(path, tmp_path / "plain.csv", defaults=DEFAULTS, on_error="skip", chunk_size=100)

    def value(text):  # Arrow writes 2.0 as "2", Python as "2.0": compare the numbers
        try:
            number = float(text)
        except ValueError:
            return text
        return "nan" if number != number else number

    for a, b in zip(
        read_csv(tmp_path / "arrow.csv"), read_csv(tmp_path / "plain.csv"), strict=True
    ):
        assert {k: value(v) for k, v in a.items()} == {k: value(v) for k, v in b.items()}


INPUT_FIELDS = {
    "mass",
    "radius",
    "gyration",
    "mu",
    "kappa",
    "before_vx",
    "before_vy",
    "before_omega",
}
#: The output columns files had before they were derived from Impact: users' files keep them.
OLD_COLUMNS = (
    "regime zeta after_vx after_vy after_omega slip_before slip_after incidence_ratio tau0 "
    "tau_star tau1 tangential_impulse impulse_ratio kinetic_energy_before kinetic_energy_after "
    "dissipated_energy work_compression_normal work_compression_tangential "
    "work_restitution_normal work_restitution_tangential work_ratio_tangential "
    "min_kinetic_energy tau_min_energy min_energy_case newton_restitution poisson_restitution "
    "energetic_restitution backward reversed_spin vertical spinning rolling"
).split()


def test_batch_columns_are_the_impact_vocabulary():
    names = Impact.column_names()
    assert set(RESULT_COLUMNS) == set(names) - INPUT_FIELDS
    assert list(RESULT_COLUMNS) == ["regime"] + [
        n for n in names if n not in INPUT_FIELDS and n != "regime"
    ]  # the regime leads; the rest in the result's order
    assert set(OLD_COLUMNS) <= set(RESULT_COLUMNS)
    assert [n for n in RESULT_COLUMNS if n in OLD_COLUMNS] == OLD_COLUMNS  # same order
    assert "dissipated_fraction" in RESULT_COLUMNS

    @dataclasses.dataclass(frozen=True, eq=False)
    class Larger(Impact):  # a field added to the result is a column of the file
        spin_energy_after: Array = None

    assert result_columns(Larger) == (*RESULT_COLUMNS, "spin_energy_after")


def test_every_output_column_is_the_impact_column(mixed, tmp_path):
    path, rows = mixed
    rows = rows[:40]
    write_csv(path, ["vx", "vy", "omega", "mu", "kappa", "body", "gyration"], rows)
    run_batch(path, tmp_path / "out.csv", defaults=DEFAULTS, chunk_size=16)
    got = read_csv(tmp_path / "out.csv")
    assert list(got[0]) == ["vx", "vy", "omega", "mu", "kappa", "body", "gyration"] + list(
        RESULT_COLUMNS
    )
    for row, line in zip(rows, got, strict=True):
        want = expected(row).columns()
        for name in RESULT_COLUMNS:
            value = want[name][()]
            if isinstance(value, np.bool_):
                assert line[name] == ("true" if value else "false"), name
            elif isinstance(value, str):
                assert line[name] == value, name
            else:  # shortest round-trip text: the same float, NaN included
                np.testing.assert_array_equal(float(line[name]), value, err_msg=name)


def hide_pyarrow(monkeypatch):
    for name in ("pyarrow", "pyarrow.parquet", "pyarrow.csv"):
        monkeypatch.setitem(sys.modules, name, None)  # any import of pyarrow now fails


@pytest.mark.parametrize(("source", "target"), [("in.csv", "out.parquet"), ("in.pq", "out.csv")])
def test_parquet_without_pyarrow_names_the_extra(tmp_path, monkeypatch, source, target):
    (tmp_path / source).write_text("vx,vy,omega\n1,-1,0\n")
    hide_pyarrow(monkeypatch)
    with pytest.raises(ImportError, match=r"Parquet files needs pyarrow.*spinimpact\[parquet\]"):
        run_batch(tmp_path / source, tmp_path / target, defaults=DEFAULTS)
    assert [p.name for p in tmp_path.iterdir()] == [source]  # nothing written


def test_csv_without_pyarrow_uses_the_csv_module(mixed, tmp_path, monkeypatch):
    path, rows = mixed
    run_batch(path, tmp_path / "arrow.csv", defaults=DEFAULTS)
    hide_pyarrow(monkeypatch)
    summary = run_batch(path, tmp_path / "plain.csv", defaults=DEFAULTS)
    assert summary.rows == len(rows)
    a, b = read_csv(tmp_path / "arrow.csv"), read_csv(tmp_path / "plain.csv")
    assert [r["after_vx"] for r in b] == [repr(float(r["after_vx"])) for r in a]


def test_chunk_size_type_and_value(tmp_path):
    src = tmp_path / "in.csv"
    src.write_text("vx,vy,omega\n1,-1,0\n")
    with pytest.raises(TypeError, match="chunk_size must be a positive integer, got 2.5"):
        run_batch(src, tmp_path / "o.csv", defaults=DEFAULTS, chunk_size=2.5)
    with pytest.raises(ValueError, match="chunk_size must be a positive integer, got 0"):
        run_batch(src, tmp_path / "o.csv", defaults=DEFAULTS, chunk_size=0)
