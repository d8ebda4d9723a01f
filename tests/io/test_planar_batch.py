"""Batch files of planar bodies and pendulums: every row equals solve_planar / solve_pendulum,
bad rows are named (row, line, column) or skipped, the header decides the solver."""

import csv

import numpy as np
import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar
from spinimpact.core.planar import LAWS
from spinimpact.io import batch
from spinimpact.io._units import UNITS
from spinimpact.io.batch import BatchError, input_kind, run_batch
from spinimpact.io.planar_batch import PlanarBatch, body_kind

DEFAULTS = dict(mu=0.3, kappa=0.6, law="newton")


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    return path


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def cell(x):
    return "" if x is None else repr(float(x)) if not isinstance(x, str) else x


def planar_rows(n, seed=3):
    """Random rods, blocks and eccentric disks as rows: geometry, incidence, and per-row
    mu, kappa, law with some cells empty (the defaults)."""
    rng = np.random.default_rng(seed)
    m, j = rng.uniform(0.2, 3, n), rng.uniform(0.01, 0.5, n)
    rx, ry = rng.uniform(-0.5, 0.5, n), -rng.uniform(0.05, 0.5, n)
    vx, omega = rng.normal(0, 2, n), rng.normal(0, 5, n)
    vy = -rng.uniform(0.1, 3, n) - np.maximum(omega * rx, 0)  # the contact approaches
    mu = np.where(rng.random(n) < 0.2, np.nan, rng.uniform(0, 1, n))
    kappa = np.where(rng.random(n) < 0.2, np.nan, rng.uniform(0, 1, n))
    law = rng.choice(["", *LAWS, " Newton "], n)
    rows = [
        [cell(x) for x in (m[i], j[i], rx[i], ry[i], vx[i], vy[i], omega[i])]
        + ["" if np.isnan(mu[i]) else cell(mu[i]), "" if np.isnan(kappa[i]) else cell(kappa[i])]
        + [law[i]]
        for i in range(n)
    ]
    return ["mass", "inertia", "rx", "ry", "vx", "vy", "omega", "mu", "kappa", "law"], rows


def solved(values, law, pendulum=False):
    """The Python API on one row's numbers."""
    mu = float(values["mu"]) if values.get("mu") else DEFAULTS["mu"]
    kappa = float(values["kappa"]) if values.get("kappa") else DEFAULTS["kappa"]
    law = law.strip().lower() or DEFAULTS["law"]
    f = {k: float(v) for k, v in values.items() if k not in ("mu", "kappa", "law") and v}
    if pendulum:
        body = Pendulum(f["mass"], f["inertia"], f["gx"], f["gy"], f["px"], f["py"])
        return solve_pendulum(body, f["omega"], mu=mu, kappa=kappa, law=law)
    body = PlanarBody(f["mass"], f["inertia"], f["rx"], f["ry"])
    return solve_planar(body, f["vx"], f["vy"], f["omega"], mu=mu, kappa=kappa, law=law)


def assert_rows_equal_api(path, out, pendulum=False):
    outputs = PlanarBatch("pendulum" if pendulum else "planar", _header(path), False, DEFAULTS)
    got = read_csv(out)
    with open(path, newline="") as f:
        given = list(csv.DictReader(f))
    assert len(got) == len(given)
    for row, line in zip(given, got, strict=True):
        imp = solved(row, row.get("law", ""), pendulum)
        columns = imp.columns() | {"law": imp.law}
        for name, kind in outputs.kinds.items():
            if kind == "float":  # shortest round-trip text: the same double
                assert float(line[name]) == float(columns[name]), name
            elif kind == "flag":
                assert line[name] == ("true" if columns[name] else "false"), name
            else:
                assert line[name] == str(columns[name]), name


def _header(path):
    with open(path, newline="") as f:
        return next(csv.reader(f))


def test_every_output_column_equals_solve_planar(tmp_path):
    header, rows = planar_rows(300)
    src = write_csv(tmp_path / "rods.csv", header, rows)
    summary = run_batch(src, tmp_path / "out.csv", defaults=DEFAULTS, chunk_size=64)
    assert (summary.rows, summary.skipped, summary.kind) == (300, 0, "planar")
    got = read_csv(tmp_path / "out.csv")
    assert list(got[0])[: len(header)] == header
    assert "before_vx" not in got[0] and "inertia" in got[0]  # inputs are not repeated
    assert {"after_vx", "after_vy", "after_omega", "regime", "dissipated_fraction",
            "creates_energy", "newton_restitution"} <= set(got[0])  # fmt: skip
    assert_rows_equal_api(src, tmp_path / "out.csv")
    assert len({r["regime"] for r in got}) >= 4  # the rows reach several regimes


def test_pendulum_rows_equal_solve_pendulum(tmp_path):
    rng = np.random.default_rng(8)
    n = 120
    px, py = rng.uniform(-1, 1, n), -rng.uniform(0.2, 1, n)
    omega = -np.sign(px) * rng.uniform(0.5, 5, n)  # the contact turns toward the surface
    rows = [
        [
            cell(x)
            for x in (
                rng.uniform(0.5, 2),
                rng.uniform(0.01, 0.2),
                px[i] / 2,
                py[i] / 2,
                px[i],
                py[i],
                omega[i],
                rng.uniform(0, 1),
            )
        ]  # fmt: skip
        for i in range(n)
    ]
    header = ["mass", "inertia", "gx", "gy", "px", "py", "omega", "mu"]
    src = write_csv(tmp_path / "p.csv", header, rows)
    summary = run_batch(src, tmp_path / "out.csv", defaults=DEFAULTS)
    assert summary.kind == "pendulum"
    got = read_csv(tmp_path / "out.csv")
    assert list(got[0])[len(header) : len(header) + 4] == ["law", "kappa", "regime", "before_vx"]
    for row in got:  # the settings each row was solved with are written
        assert (row["law"], float(row["kappa"])) == ("newton", DEFAULTS["kappa"])
    assert_rows_equal_api(src, tmp_path / "out.csv", pendulum=True)
    assert {r["regime"] for r in got} == {"locked", "reverse-compression"}


def test_settings_the_file_lacks_are_written(tmp_path):
    src = write_csv(tmp_path / "a.csv", ["mass", "inertia", "rx", "ry", "vx", "vy", "omega"],
                    [[1, 0.1, 0.2, -0.3, 1, -1, 0]])  # fmt: skip
    run_batch(src, tmp_path / "o.csv", defaults=dict(mu=0.4, kappa=0.5))
    (row,) = read_csv(tmp_path / "o.csv")
    assert (row["law"], row["mu"], row["kappa"]) == ("poisson", "0.4", "0.5")
    imp = solve_planar(PlanarBody(1, 0.1, 0.2, -0.3), 1, -1, 0, mu=0.4, kappa=0.5)
    assert float(row["after_omega"]) == float(imp.after.omega)
    with pytest.raises(BatchError, match="no column 'mu' and no default mu"):
        run_batch(src, tmp_path / "o.csv", defaults=dict(kappa=0.5))
    with pytest.raises(ValueError, match="law must be one of"):
        run_batch(src, tmp_path / "o.csv", defaults=dict(mu=0.4, kappa=0.5, law="hooke"))


BAD = [
    ([-1, 0.1, 0.2, -0.3, 1, -1, 0, ""], "column mass: mass must be > 0, got -1.0"),
    ([1, 0.1, 0.2, 0.3, 1, -1, 0, ""], "column ry: ry must be < 0"),
    ([1, 0.1, 0.2, -0.3, "x", -1, 0, ""], "column vx: 'x' is not a number"),
    ([1, 0.1, 0.2, -0.3, 1, -1, 0, "hooke"], "column law: must be one of newton, poisson"),
    ([1, "", 0.2, -0.3, 1, -1, 0, ""], "column inertia: empty, but inertia is required"),
    ([1, 0.1, 0.2, -0.3, 1, 0.5, 0, ""], "columns vy, omega, rx: the contact point must approach"),
    # each number within the accepted range, but W and the impulses span more than a double
    ([1, 1e50, 1e50, -1e50, -1, -1e20, 1e-50, ""], "not a finite number: the row's numbers"),
]


@pytest.mark.parametrize(("row", "message"), BAD, ids=[m[:22] for _, m in BAD])
def test_a_bad_row_is_named_by_row_line_and_column(tmp_path, row, message):
    header = ["mass", "inertia", "rx", "ry", "vx", "vy", "omega", "law"]
    good = [1, 0.1, 0.2, -0.3, 1, -1, 0, "poisson"]
    src = write_csv(tmp_path / "in.csv", header, [good, row])
    with pytest.raises(BatchError, match="^row 2 \\(line 3\\)") as err:
        run_batch(src, tmp_path / "out.csv", defaults=DEFAULTS)
    assert message in str(err.value)
    assert not (tmp_path / "out.csv").exists()


def test_skip_writes_each_bad_row_with_its_message(tmp_path):
    header = ["mass", "inertia", "rx", "ry", "vx", "vy", "omega", "law"]
    good = [1, 0.1, 0.2, -0.3, 1, -1, 0, "poisson"]
    src = write_csv(tmp_path / "in.csv", header, [good, *(r for r, _ in BAD), good])
    summary = run_batch(src, tmp_path / "o.csv", defaults=DEFAULTS, on_error="skip", chunk_size=3)
    assert (summary.rows, summary.skipped) == (len(BAD) + 2, len(BAD))
    got = read_csv(tmp_path / "o.csv")
    for i, (_, message) in enumerate(BAD, start=2):
        assert message in got[i - 1]["error"] and f"row {i} (line {i + 1})" in got[i - 1]["error"]
        assert got[i - 1]["after_vx"] == got[i - 1]["regime"] == got[i - 1]["mu"] == ""
    assert got[0]["error"] == got[-1]["error"] == "" and got[0]["after_vx"] == got[-1]["after_vx"]


@pytest.mark.parametrize(
    ("header", "message"),
    [
        (["mass", "inertia", "rx", "vx", "vy", "omega"], "missing column 'ry': a file of free"),
        (["mass", "inertia", "rx", "ry", "px", "omega"], "do not go together"),
        (["mass", "inertia", "vx", "vy", "omega"], "column 'inertia' describes a planar body"),
        (["mass", "inertia", "rx", "ry", "vx", "vy", "omega", "radius"], "'radius' belongs"),
        (["mass", "inertia", "gx", "gy", "px", "py", "omega", "vx"], "'vx' does not apply"),
        (["mass", "inertia", "rx", "ry", "vx", "omega"], "missing column 'vy'"),
        (["mass", "inertia", "rx", "ry", "vx", "vy", "omega", "tau1"], "name of an output"),
        (["mass", "inertia", "rx", "ry", "vx", "vy", "omega", "rx"], "duplicate column 'rx'"),
    ],
)
def test_header_problems(tmp_path, header, message):
    src = write_csv(tmp_path / "in.csv", header, [[1] * len(header)])
    with pytest.raises(BatchError, match=message):
        run_batch(src, tmp_path / "out.csv", defaults=DEFAULTS)


def test_the_header_decides_the_solver(tmp_path):
    assert body_kind(["vx", "vy", "omega", "mass", "radius"]) == "paper"
    assert body_kind(["ry", "rx", "inertia", "mass"]) == "planar"
    assert body_kind(["px", "py", "gx", "gy", "inertia", "mass", "omega"]) == "pendulum"
    src = write_csv(tmp_path / "p.csv", ["mass", "inertia", "gx", "gy", "px", "py", "omega"], [])
    assert input_kind(src) == "pendulum"
    with pytest.raises(ValueError, match="does not exist"):
        input_kind(tmp_path / "missing.csv")


@pytest.mark.slow
def test_chunks_and_writers_do_not_change_the_file(tmp_path, monkeypatch):
    header, rows = planar_rows(50, seed=11)
    src = write_csv(tmp_path / "in.csv", header, rows)
    run_batch(src, tmp_path / "a.csv", defaults=DEFAULTS, chunk_size=1)
    run_batch(src, tmp_path / "b.csv", defaults=DEFAULTS, chunk_size=1000)
    assert (tmp_path / "a.csv").read_text() == (tmp_path / "b.csv").read_text()
    monkeypatch.setattr(batch, "_have_pyarrow", lambda: False)  # Python's csv module
    run_batch(src, tmp_path / "c.csv", defaults=DEFAULTS)
    a, c = read_csv(tmp_path / "a.csv"), read_csv(tmp_path / "c.csv")
    assert [list(r) for r in a] == [list(r) for r in c]
    for x, y in zip(a, c, strict=True):
        assert all(x[k] == y[k] or float(x[k]) == float(y[k]) for k in x)


def test_parquet_in_and_out_with_units(tmp_path):
    pa = pytest.importorskip("pyarrow", reason="the [parquet] extra is not installed")
    pq = pytest.importorskip("pyarrow.parquet")
    header, rows = planar_rows(40, seed=5)
    src = write_csv(tmp_path / "in.csv", header, rows)
    run_batch(src, tmp_path / "out.parquet", defaults=DEFAULTS, chunk_size=16)
    table = pq.read_table(tmp_path / "out.parquet")
    schema = table.schema
    assert schema.field("vx").type == pa.float64() and schema.field("law").type == pa.string()
    assert schema.field("creates_energy").type == pa.bool_()
    for name in ("rx", "inertia", "after_omega", "tau1", "dissipated_energy", "mu"):
        assert schema.field(name).metadata == {b"unit": UNITS[name].encode()}, name
    assert schema.field("inertia").metadata == {b"unit": b"kg m^2"}
    assert schema.field("regime").metadata is None
    # Parquet in, Parquet out: the same numbers as from the CSV
    pq.write_table(table.select(header), tmp_path / "in.parquet")
    run_batch(tmp_path / "in.parquet", tmp_path / "again.parquet", defaults=DEFAULTS)
    again = pq.read_table(tmp_path / "again.parquet")
    assert again.column("after_vx").equals(table.column("after_vx"))
    assert again.column("regime").equals(table.column("regime"))


def test_every_output_column_has_a_unit_or_is_text():
    files = {
        "planar": ["mass", "inertia", "rx", "ry", "vx", "vy", "omega"],
        "pendulum": ["mass", "inertia", "gx", "gy", "px", "py", "omega"],
    }
    for kind, header in files.items():
        plan = PlanarBatch(kind, header, False, DEFAULTS)
        for name, what in plan.kinds.items():
            assert (name in UNITS) == (what == "float"), name
        assert all(name in UNITS for name in plan.numeric)
    for name, what in batch.column_kinds().items():  # the paper's bodies too
        assert (name in UNITS) == (what == "float"), name
