"""spinimpact batch --tangential: every row is solve(..., tangential=law)'s, the columns are
CompliantImpact's, and a law with the wrong parameters or a file of planar bodies is a
one-line error with exit status 2 that leaves an existing output alone."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from spinimpact import Body, CompliantImpact, Stronge, Walton, solve
from spinimpact.io.batch import BatchError, run_batch
from spinimpact.io.batch_columns import column_kinds, result_columns

from tests.cli.test_errors import _keep_sigterm  # noqa: F401 (an autouse fixture)

HEADER = ["vx", "vy", "omega", "mu", "kappa", "mass", "radius", "gyration", "body"]


def _rows(n=60, seed=13):
    """Random rows over every regime: per-row mu and kappa (some left to the defaults),
    presets and custom gyrations, masses and radii."""
    rng = np.random.default_rng(seed)
    rows = []
    for i in range(n):
        preset = ["solid-sphere", "spherical-shell", "solid-disk", "ring", ""][i % 5]
        radius = rng.uniform(0.01, 0.2)
        rows.append({
            "vx": rng.uniform(-3, 3), "vy": -rng.uniform(0.2, 5),
            "omega": rng.uniform(-3, 3) / radius if i % 7 else 0.0,
            "mu": "" if i % 6 == 0 else (0.0 if i % 11 == 0 else rng.uniform(0.05, 0.8)),
            "kappa": "" if i % 4 == 0 else rng.uniform(0.0, 1.0),
            "mass": rng.uniform(0.01, 2), "radius": radius,
            "gyration": "" if preset else rng.uniform(0.3, 1.0) * radius, "body": preset,
        })  # fmt: skip
    return rows


def _write(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, HEADER)
        writer.writeheader()
        writer.writerows(rows)


def _one(row, law, mu=0.2, kappa=0.8):
    """The row solved alone by the library (the CLI's defaults where a cell is empty)."""
    if row["body"]:
        body = Body.preset(row["body"], mass=row["mass"], radius=row["radius"])
    else:
        body = Body(mass=row["mass"], radius=row["radius"], gyration=row["gyration"])
    return solve(body, row["vx"], row["vy"], row["omega"], tangential=law,
                 mu=mu if row["mu"] == "" else row["mu"],
                 kappa=kappa if row["kappa"] == "" else row["kappa"])  # fmt: skip


LAWS = [
    (["--tangential", "walton", "--beta0", "0.35"], Walton(0.35)),
    (["--tangential", "walton", "--beta0", "-1"], Walton(-1.0)),
    (["--tangential", "stronge", "--poisson-ratio", "0.23"], Stronge(poisson_ratio=0.23)),
    (["--tangential", "stronge", "--stiffness-ratio", "3"], Stronge(stiffness_ratio=3.0)),
]


@pytest.mark.parametrize("args, law", LAWS)
@pytest.mark.slow
def test_every_row_is_the_library_result(cli, tmp_path, args, law):
    rows = _rows()
    _write(tmp_path / "in.csv", rows)
    status, _, err = cli("batch", tmp_path / "in.csv", "--output", tmp_path / "out.csv", *args)
    assert status == 0, err
    with open(tmp_path / "out.csv", newline="") as f:
        got = list(csv.DictReader(f))
    names = result_columns(CompliantImpact)
    assert list(got[0]) == HEADER + list(names)
    regimes = set()
    for row, line in zip(rows, got, strict=True):
        columns = _one(row, law).columns()
        for name in names:
            want = columns[name]
            if name == "regime":
                assert line[name] == str(want)
                regimes.add(line[name])
            elif np.isnan(want):
                assert line[name] in ("", "nan", "NaN"), name
            else:
                assert float(line[name]) == pytest.approx(float(want), rel=1e-14, abs=1e-300)
    if law == Walton(-1.0):
        assert regimes == {"frictionless"}
    else:
        assert {"slip", "frictionless"} <= regimes and regimes & {"stick", "slip-reversal"}


def test_parquet_output_carries_the_columns_and_their_units(cli, tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    rows = _rows(20, seed=2)
    _write(tmp_path / "in.csv", rows)
    law = Stronge(poisson_ratio=0.3)
    status, _, err = cli("batch", tmp_path / "in.csv", "--output", tmp_path / "out.parquet",
                         "--tangential", "stronge", "--poisson-ratio", "0.3")  # fmt: skip
    assert status == 0, err
    table = pq.read_table(tmp_path / "out.parquet")
    beta = table.column("tangential_restitution").to_numpy()
    want = np.array([float(_one(r, law).tangential_restitution) for r in rows])
    np.testing.assert_allclose(beta, want, rtol=1e-14)
    units = {f.name: (f.metadata or {}).get(b"unit") for f in table.schema}
    assert units["tangential_restitution"] == units["centre_tangential_restitution"] == b"1"
    assert units["slip_after"] == b"m/s"
    floats = [n for n, kind in column_kinds(law).items() if kind == "float"]
    assert all(units[n] for n in floats), [n for n in floats if not units[n]]


@pytest.mark.parametrize(
    "args, message",
    [
        (["--tangential", "walton"], "--tangential walton needs --beta0"),
        (["--tangential", "stronge"], "needs exactly one of --poisson-ratio and --stiffness-ratio"),
        (["--tangential", "stronge", "--poisson-ratio", "0.3", "--stiffness-ratio", "2"],
         "needs exactly one of --poisson-ratio and --stiffness-ratio"),
        (["--beta0", "0.3"], "--beta0 applies to --tangential walton only"),
        (["--tangential", "stronge", "--beta0", "0.3"], "--beta0 applies to --tangential walton"),
        (["--tangential", "walton", "--beta0", "0.3", "--poisson-ratio", "0.3"],
         "--poisson-ratio applies to --tangential stronge and mindlin-deresiewicz only"),
        (["--stiffness-ratio", "2"],
         "--stiffness-ratio applies to --tangential stronge and mindlin-deresiewicz only"),
        (["--tangential", "walton", "--beta0", "1.5"], "beta0 must be in [-1, 1], got 1.5"),
        (["--tangential", "stronge", "--poisson-ratio", "0.7"], "poisson_ratio must be in"),
        (["--tangential", "stronge", "--stiffness-ratio", "-1"], "stiffness_ratio must be in"),
    ],
)  # fmt: skip
def test_bad_combinations_are_one_line_errors(cli, tmp_path, args, message):
    _write(tmp_path / "in.csv", _rows(3))
    out = tmp_path / "out.csv"
    out.write_text("kept\n")
    status, stdout, err = cli("batch", tmp_path / "in.csv", "--output", out, *args)
    assert status == 2 and stdout == ""
    assert err.count("\n") == 1 and message in err and "Traceback" not in err
    assert out.read_text() == "kept\n"


def test_a_law_does_not_apply_to_planar_bodies(cli, tmp_path):
    (tmp_path / "pl.csv").write_text("mass,inertia,rx,ry,vx,vy,omega\n1,0.01,0,-0.1,1,-2,0\n")
    out = tmp_path / "out.csv"
    status, _, err = cli("batch", tmp_path / "pl.csv", "--output", out, "--tangential",
                         "walton", "--beta0", "0.3")  # fmt: skip
    assert status == 2 and err.count("\n") == 1 and not out.exists()
    assert "--tangential walton applies to the paper's bodies" in err
    status, _, err = cli("batch", tmp_path / "pl.csv", "--output", out, "--tangential", "rigid")
    assert status == 0, err
    with pytest.raises(BatchError, match="a tangential law applies to the paper's bodies"):
        run_batch(tmp_path / "pl.csv", tmp_path / "lib.csv",
                  defaults={"tangential": Walton(0.3)})  # fmt: skip
    assert not (tmp_path / "lib.csv").exists()


def test_the_rigid_law_keeps_the_impact_columns(cli, tmp_path):
    rows = _rows(10)
    _write(tmp_path / "in.csv", rows)
    for extra in ([], ["--tangential", "rigid"]):
        status, _, err = cli("batch", tmp_path / "in.csv", "--output", tmp_path / "out.csv",
                             *extra)  # fmt: skip
        assert status == 0, err
        with open(tmp_path / "out.csv", newline="") as f:
            header = next(csv.reader(f))
        assert header == HEADER + list(result_columns())
