"""``spinimpact batch`` over any registered problem (io/problem_batch.py): spheres and pairs
row for row equal to their functions, every feature (fields, units, skip, standard input
and output) for every problem, partial vectors refused, and a toy problem that gets all of
it from its declaration alone."""

import csv
import io
import json
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, problem, solve_pair, solve_sphere
from spinimpact.io._tables import BatchError
from spinimpact.io.batch import run_batch, units_file


def write(path, header, rows):
    path.write_text("\n".join([",".join(header), *(",".join(map(str, r)) for r in rows)]) + "\n")
    return path


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


SPHERE = ["vx", "vy", "vz", "wx", "wy", "wz"]


def sphere_rows(n=30, seed=3):
    rng = np.random.default_rng(seed)
    v = np.c_[rng.uniform(-5, 5, n), rng.uniform(-5, -0.5, n), rng.uniform(-2, 2, n)]
    w = rng.uniform(-80, 80, (n, 3))
    return v, w


def test_a_sphere_file_is_found_by_its_columns_and_equals_solve_sphere(tmp_path):
    v, w = sphere_rows()
    source = write(tmp_path / "in.csv", [*SPHERE, "mu"], [[*a, *b, 0.4] for a, b in zip(
        v.tolist(), w.tolist(), strict=True)])  # fmt: skip
    summary = run_batch(source, tmp_path / "out.csv", defaults={}, chunk_size=7)
    assert (summary.kind, summary.rows) == ("sphere", 30)
    rows = read(tmp_path / "out.csv")
    want = solve_sphere(Body.solid_sphere(mass=1.0, radius=0.1), v, w, mu=0.4, kappa=0.8)
    for name in ("after_vx", "after_vz", "after_wy", "dissipated_energy", "tau1"):
        got = np.array([float(r[name]) for r in rows])
        assert np.array_equal(got, want.columns()[name]), name  # same numbers, bit for bit
    assert [r["regime"] for r in rows] == want.regime.tolist()
    units = json.loads(units_file(tmp_path / "out.csv").read_text())
    assert units["problem"] == "sphere"
    assert units["units"]["after_wy"] == "rad/s" and units["units"]["vz"] == "m/s"
    assert units["units"]["regime"] is None and units["units"]["mu"] == "1"


def test_a_pair_file_equals_solve_pair_and_names_its_fields(tmp_path):
    v, w = sphere_rows(12)
    rows = [[*a, *b, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0] for a, b in zip(v.tolist(), w.tolist(),
                                                                    strict=True)]  # fmt: skip
    header = [*SPHERE, *(f"{c}2" for c in SPHERE)]
    source = write(tmp_path / "in.csv", header, rows)
    out = tmp_path / "out.csv"
    run_batch(source, out, defaults={"normal": (0.0, 1.0, 0.0)}, fields=["after1_vy", "regime"])
    got = read(out)
    assert list(got[0]) == [*header, "after1_vy", "regime"]
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    still = np.zeros((12, 3))
    want = solve_pair(ball, ball, velocity1=v, spin1=w, velocity2=still, spin2=still,
                      normal=[0.0, 1.0, 0.0], mu=0.2, kappa=0.8)  # fmt: skip
    assert [float(r["after1_vy"]) for r in got] == want.columns()["after1_vy"].tolist()
    with pytest.raises(ValueError, match="unknown output field 'after_vy'"):
        run_batch(source, out, defaults={"normal": (0, 1, 0)}, fields=["after_vy"])


@pytest.mark.parametrize("kind", ["paper", "planar", "pendulum", "sphere", "pair"])
def test_every_problem_skips_bad_rows_and_writes_parquet_units(tmp_path, kind):
    pa = pytest.importorskip("pyarrow.parquet")
    declared = problem(kind)
    example = {k: v for k, v in declared.example.items()}
    header = list(example)
    bad = dict(example, mu="x") if "mu" in declared.names else None
    header_bad = [*header, "mu"]
    rows = [[*example.values(), 0.3], [*(bad or example).values()]]
    source = write(tmp_path / "in.csv", header_bad, rows)
    out = tmp_path / "out.parquet"
    defaults = {"mu": 0.2, "kappa": 0.8, "mass": 1.0, "radius": 0.1, "body": "solid-sphere"}
    summary = run_batch(source, out, defaults=defaults, on_error="skip")  # fmt: skip
    assert (summary.kind, summary.rows, summary.skipped) == (kind, 2, 1)
    table = pa.read_table(out)
    assert "is not a number" in table.column("error").to_pylist()[1]
    numeric = [f for f in table.schema if f.name not in header_bad and f.type == "double"]
    assert numeric and all(f.metadata and b"unit" in f.metadata for f in numeric), kind


def test_a_vector_in_part_is_refused_naming_its_columns(tmp_path):
    source = write(tmp_path / "in.csv", [*SPHERE, "normal_x"], [[1, -1, 0, 0, 0, 0, 0.3]])
    with pytest.raises(BatchError, match="columns normal_x give the normal in part: add "
                       "normal_y, normal_z"):  # fmt: skip
        run_batch(source, tmp_path / "out.csv", defaults={})
    assert not (tmp_path / "out.csv").exists()
    source = write(tmp_path / "in.csv", SPHERE, [[1, -1, 0, 0, 0, 0]])
    with pytest.raises(ValueError, match="defaults give the normal in part"):
        run_batch(source, tmp_path / "out.csv", defaults={"normal_y": 1.0})


def test_the_toy_problem_gets_a_batch_from_its_declaration(tmp_path, toy):
    source = write(tmp_path / "in.csv", ["speed", "e"], [[-2, 0.5], [-1, ""], [3, 0.1]])
    out = tmp_path / "out.csv"
    summary = run_batch(source, out, defaults={}, on_error="skip")
    assert (summary.kind, summary.rows, summary.skipped) == ("toy", 3, 1)
    rows = read(out)
    assert [float(r["speed_after"]) for r in rows[:2]] == [1.0, 0.5]  # e's default on row 2
    assert "speed must be < 0, got 3.0" in rows[2]["error"]
    units = json.loads(units_file(out).read_text())["units"]
    assert units["speed_after"] == "m/s" and units["e"] == "1"


def test_the_toy_problem_through_the_command_line(tmp_path, toy):
    from spinimpact.cli import main

    source = write(tmp_path / "in.csv", ["speed"], [[-2], [-4]])
    out = tmp_path / "out.csv"
    main(["batch", str(source), "--output", str(out), "--set", "e=0.25"])
    assert [float(r["speed_after"]) for r in read(out)] == [0.5, 1.0]
    with pytest.raises(SystemExit) as caught:
        main(["batch", str(source), "--output", str(out), "--set", "f=1"])
    assert caught.value.code == 2


@pytest.mark.slow
def test_stdin_to_stdout_for_a_sphere_file(tmp_path):
    text = "vx,vy,vz,wx,wy,wz\n2,-3,0,0,0,30\n"
    run = subprocess.run([sys.executable, "-m", "spinimpact", "batch", "-", "--output", "-",
                          "--fields", "regime,after_vy"], input=text, capture_output=True,
                         text=True, timeout=120)  # fmt: skip
    assert run.returncode == 0, run.stderr
    rows = list(csv.DictReader(io.StringIO(run.stdout)))
    want = solve_sphere(
        Body.solid_sphere(mass=1.0, radius=0.1), [2, -3, 0], [0, 0, 30], mu=0.2, kappa=0.8
    )  # the declared defaults
    assert rows[0]["regime"] == want.regime and float(rows[0]["after_vy"]) == want.after.vy


def test_a_sphere_file_under_a_tangential_law_equals_solve_sphere(tmp_path):
    from spinimpact import Walton

    v, w = sphere_rows(20, seed=5)
    rows = [[*a, *b] for a, b in zip(v.tolist(), w.tolist(), strict=True)]
    source = write(tmp_path / "in.csv", SPHERE, rows)
    law = Walton(beta0=0.3)
    out = tmp_path / "out.csv"
    run_batch(source, out, defaults={"tangential": law, "mu": 0.3})
    rows = read(out)
    want = solve_sphere(Body.solid_sphere(mass=1.0, radius=0.1), v, w, mu=0.3, kappa=0.8,
                        tangential=law)  # fmt: skip
    for name in ("after_vx", "after_wz", "tangential_restitution"):
        got = np.array([float(r[name]) for r in rows])
        assert np.array_equal(got, want.columns()[name]), name
