"""Sweeps of a sphere in 3D through the older SphereSweep (an alias of ProblemSweep): every
field is solve_sphere's column of its name, the regimes are counted as the paper sweep
counts them, and ``spinimpact sweep --sphere`` runs them."""

import json
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, core, solve_sphere
from spinimpact.io.sphere_sweep import SphereSweep, sphere_fields
from spinimpact.io.sweep import Sweep, parse_axis, run_sweep
from spinimpact.model.sphere3d import Surface

pytestmark = pytest.mark.filterwarnings(
    "ignore:(SphereSweep|sphere_fields) is deprecated:DeprecationWarning"
)

BALL = Body.solid_sphere(mass=0.2, radius=0.05)
SHELL = Body.spherical_shell(mass=0.057, radius=0.033)
TILTED = Surface(normal=(0.2, 1.0, -0.1), velocity=(1.0, -0.5, 0.3))
# the contact approaches at every point, on either surface: (v - V_s) . n < 0 over the box
RANDOM = dict(vx="uniform:-3:3", vy="uniform:-6:-2", vz="uniform:-3:3", wx="uniform:-80:80",
              wy="uniform:-80:80", wz="uniform:-80:80", mu="uniform:0:1",
              kappa="uniform:0:1")  # fmt: skip
GRID = dict(vx="-2:2:5", vy="-4:-1:3", vz="-1:1:3", wx="-30:30:3", wy="0", wz="-50:50:3",
            mu="0:0.8:3", kappa="0.2:1:2")  # fmt: skip


def axes(spec):
    return {n: parse_axis(n, v) for n, v in spec.items()}


def every_point(sweep, fields):
    parts = [sweep.evaluate(k, fields) for k in range(sweep.chunks)]
    return {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}


@pytest.mark.parametrize("surface", [None, TILTED], ids=["flat", "tilted"])
@pytest.mark.parametrize("body", [BALL, SHELL], ids=["solid", "shell"])
@pytest.mark.parametrize(("spec", "samples"), [(RANDOM, 3000), (GRID, None)], ids=["rand", "grid"])
def test_every_field_is_the_sphere_impact_column_of_its_name(body, surface, spec, samples):
    extra = {} if surface is None else {"surface": surface}
    sweep = SphereSweep(body, axes(spec), samples=samples, chunk_size=701, **extra)
    fields = sphere_fields()
    got = every_point(sweep, fields)
    v = np.stack([got["vx"], got["vy"], got["vz"]], -1)
    w = np.stack([got["wx"], got["wy"], got["wz"]], -1)
    if surface is not None:  # the sweep is given the surface's normal as the Surface holds it
        surface = Surface(normal=surface.normal, velocity=surface.velocity)
    columns = solve_sphere(body, v, w, mu=got["mu"], kappa=got["kappa"], surface=surface).columns()
    for name in fields:
        want = columns[name]
        if name == "regime":
            want = np.array([core.REGIMES.index(r) for r in want])
        # solve_sphere itself on the same numbers: equal to the last bit (NaN where NaN)
        np.testing.assert_array_equal(got[name], want, err_msg=name)
    assert got["grips"].dtype == bool and got["regime"].dtype == np.int8


def test_plane_motion_counts_the_regimes_of_the_paper_sweep():
    """In the x, y plane with spin about z, the sphere's regimes are the paper's."""
    paper = dict(vx="-3:3:41", vy="-4:-0.5:5", omega="-60:60:31", mu="0.3", kappa="0.7")
    sphere = dict(vx=paper["vx"], vy=paper["vy"], vz="0", wx="0", wy="0", wz=paper["omega"],
                  mu="0.3", kappa="0.7")  # fmt: skip
    want = run_sweep(Sweep(BALL, axes(paper)))
    got = run_sweep(SphereSweep(BALL, axes(sphere), chunk_size=997))
    assert got.points == want.points == 41 * 5 * 31
    assert got.regimes == core.REGIMES
    assert got.regime_counts.tolist() == want.regime_counts.tolist()
    assert sum(got.regime_fractions.values()) == pytest.approx(1.0)
    assert got.regime_fractions["slip"] > 0 and got.regime_fractions["stick-restitution"] > 0


def test_random_points_depend_on_the_seed_alone():
    a = every_point(SphereSweep(BALL, axes(RANDOM), samples=1000, seed=5, chunk_size=37), ())
    b = every_point(SphereSweep(BALL, axes(RANDOM), samples=1000, seed=5, chunk_size=1000), ())
    c = every_point(SphereSweep(BALL, axes(RANDOM), samples=1000, seed=6), ())
    for name in RANDOM:
        np.testing.assert_array_equal(a[name], b[name])
    assert not np.array_equal(a["wz"], c["wz"])
    assert len({a[n][0] for n in ("vz", "wx", "wy", "wz")}) == 4  # a stream per input


@pytest.mark.parametrize(
    ("change", "error", "match"),
    [
        ({"vy": "uniform:-1:1"}, ValueError, "must approach the surface"),
        ({"omega": "0"}, ValueError, "problem 'sphere' has no input 'omega'"),
        ({"mu": "-0.5"}, ValueError, "mu"),
    ],
)
def test_bad_sweeps_are_refused(change, error, match):
    spec = {**RANDOM, **change}
    with pytest.raises(error, match=match):
        SphereSweep(BALL, axes(spec), samples=10)


def test_the_default_fields_and_the_npy_description(tmp_path):
    out = tmp_path / "ball"
    run_sweep(SphereSweep(BALL, axes(GRID), surface=TILTED), output=out)
    meta = json.loads((out / "metadata.json").read_text())
    assert meta["regimes"] == list(core.REGIMES)
    assert meta["body"] == BALL.to_dict() and meta["problem"] == "sphere"
    velocity = [meta["fixed"][f"surface_velocity_{k}"] for k in "xyz"]
    assert velocity == [1.0, -0.5, 0.3]
    assert (out / "after_wz.npy").exists() and (out / "regime.npy").exists()


def _cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "spinimpact", "sweep", *map(str, args)],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip


@pytest.mark.slow
def test_cli_sweeps_a_sphere_and_writes_its_fields(tmp_path):
    pa = pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "shell.parquet"
    args = ["--sphere", "spherical-shell", "--mass", "0.057", "--radius", "0.033",
            "--samples", "500", "--seed", "3", "--vx", "uniform:-3:3", "--vy", "uniform:-6:-2",
            "--vz", "uniform:-3:3", "--wx", "uniform:-80:80", "--wy", "10",
            "--wz", "uniform:-80:80",
            "--normal", "0.2,1,-0.1", "--surface-velocity", "1,-0.5,0.3", "--output", out,
            "--fields", "after_vz,after_wx,grips,topspin,energy_loss"]  # fmt: skip
    done = _cli(*args)
    assert done.returncode == 0, done.stderr
    assert "500 points (spherical-shell)" in done.stdout
    table = pa.read_table(out).to_pydict()
    v = np.stack([table["vx"], table["vy"], table["vz"]], -1)
    w = np.stack([table["wx"], table["wy"], table["wz"]], -1)
    imp = solve_sphere(SHELL, v, w, mu=table["mu"], kappa=table["kappa"], surface=TILTED)
    np.testing.assert_array_equal(table["after_vz"], imp.after.vz)
    np.testing.assert_array_equal(table["grips"], imp.grips)
    np.testing.assert_array_equal(table["energy_loss"], imp.dissipated_fraction)
    printed = dict(line.split() for line in done.stdout.splitlines()[1 : 5 + 1])
    assert printed == {r: f"{np.mean(imp.regime == r):.6f}" for r in core.REGIMES}


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--sphere", "solid-sphere", "--vy", "1"], "must approach the surface"),
        (["--sphere", "solid-sphere", "--omega", "3"], "--omega does not apply to --sphere"),
        (["--wx", "3"], "--wx needs --sphere"),
        (["--sphere", "solid-sphere", "--fields", "after_omega"], "got 'after_omega'"),
    ],
)
@pytest.mark.slow
def test_cli_refuses_bad_input_in_one_line_with_exit_2(args, message):
    done = _cli(*args)
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], done.stderr
    assert "Traceback" not in done.stderr
