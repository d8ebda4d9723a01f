"""ProblemSweep: a sweep of any registered problem, built from its declaration."""

import json

import numpy as np
import pytest

from spinimpact import Body, solve_pair
from spinimpact.io.problem_sweep import ProblemSweep, problem_fields
from spinimpact.io.sweep import Axis, run_sweep
from spinimpact.model.registry import Input, Problem, register, unregister
from spinimpact.model.result import Result

#: Two balls: ball 1 flies along -x into ball 2 at rest, with topspin; the axis is vx.
PAIR = dict(vy=0.2, vz=-0.1, wx=0, wy=0, wz=30, vx2=0, vy2=0, vz2=0, wx2=0, wy2=0, wz2=0,
            normal_x=-1, normal_y=0, normal_z=0)  # fmt: skip


@pytest.mark.slow
def test_a_pair_sweep_equals_solve_pair_bit_for_bit():
    sweep = ProblemSweep(
        problem="pair",
        axes={"vx": "0.5:6:37", **PAIR, "mu": 0.3, "radius2": 0.12},
        text={"body2": "spherical-shell"},
        chunk_size=10,  # four chunks
    )
    fields = problem_fields("pair")
    got = {n: np.concatenate([sweep.evaluate(k, fields)[n] for k in range(sweep.chunks)])
           for n in fields}  # fmt: skip
    vx = np.linspace(0.5, 6, 37)
    one = np.ones_like(vx)
    imp = solve_pair(
        Body.solid_sphere(mass=1.0, radius=0.1),
        Body.spherical_shell(mass=1.0, radius=0.12),
        velocity1=np.stack([vx, 0.2 * one, -0.1 * one], -1),
        spin1=(0.0, 0.0, 30.0),
        velocity2=(0.0, 0.0, 0.0),
        spin2=(0.0, 0.0, 0.0),
        normal=(-1.0, 0.0, 0.0),
        mu=0.3,
        kappa=0.8,
    ).columns()
    regimes = np.asarray(sweep.regimes)
    for name in fields:
        want = imp[name]
        have = regimes[got[name]] if name == "regime" else got[name]
        np.testing.assert_array_equal(have, np.broadcast_to(want, vx.shape), err_msg=name)
    assert set(regimes[got["regime"]]) >= {"slip"}


@pytest.mark.slow
def test_a_body_given_whole_or_by_its_inputs_gives_the_same_numbers():
    """The body's inputs as axes (the command line's --problem) or a Body held fixed: the
    same points, the same fields; only the columns and the description differ."""
    spec = dict(vx="uniform:-5:5", vy="uniform:-4:-0.5", vz="uniform:-1:1", wx="uniform:-30:30",
                wy="0", wz="uniform:-50:50", mu="uniform:0:1", kappa="0.8")  # fmt: skip
    ball = Body.preset("spherical-shell", mass=0.057, radius=0.033)
    held = ProblemSweep(problem="sphere", body=ball, axes=spec, samples=3000, seed=3,
                        chunk_size=1000)  # fmt: skip
    given = ProblemSweep(problem="sphere", axes={**spec, "mass": 0.057, "radius": 0.033},
                         text={"body": "spherical-shell"}, samples=3000, seed=3,
                         chunk_size=700)  # fmt: skip
    assert given.regimes == held.regimes
    assert set(given.inputs) - set(held.inputs) == {"mass", "radius"}  # in "body" instead
    fields = problem_fields("sphere", body=ball)
    a = {n: np.concatenate([held.evaluate(k, fields)[n] for k in range(held.chunks)])
         for n in fields}  # fmt: skip
    b = {n: np.concatenate([given.evaluate(k, fields)[n] for k in range(given.chunks)])
         for n in fields}  # fmt: skip
    for name in fields:
        np.testing.assert_array_equal(a[name], b[name], err_msg=name)
    np.testing.assert_array_equal(run_sweep(held).regime_counts, run_sweep(given).regime_counts)


def test_random_points_depend_on_the_seed_alone():
    def points(chunk_size, seed=7, samples=500):
        axes = {**PAIR, "vx": "uniform:1:3", "vx2": "uniform:-1:0"}
        sweep = ProblemSweep(problem="pair", axes=axes, samples=samples, seed=seed,
                             chunk_size=chunk_size)  # fmt: skip
        got = [sweep.evaluate(k, ()) for k in range(sweep.chunks)]
        return np.concatenate([g["vx"] for g in got]), np.concatenate([g["vx2"] for g in got])

    a, b = points(500), points(33)
    np.testing.assert_array_equal(a[0], b[0])
    np.testing.assert_array_equal(a[1], b[1])
    assert not np.array_equal(a[0], points(500, seed=8)[0])
    assert not np.array_equal(a[0], a[1] + 2)  # vx2 draws from its own stream
    np.testing.assert_array_equal(points(500, samples=200)[0], a[0][:200])


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        (
            dict(problem="pair", axes={"speed": "1"}),
            ValueError,
            "problem 'pair' has no input 'speed'; its inputs are vx, vy, vz",
        ),
        (
            dict(problem="pair", axes={"mu": 0.3}),
            ValueError,
            "problem 'pair' needs a value or range for vx, vy, vz, wx",
        ),
        (dict(problem="nope"), ValueError, "problem must be one of paper, planar"),
        (dict(problem=3), TypeError, "problem must be a name"),
        (
            dict(problem="sphere", axes=dict(vx=1, vy=-1, vz=0, wx=0, wy=0, wz=0, normal_x=0.5)),
            ValueError,
            "normal of problem 'sphere' is given in part: normal_x without normal_y, normal_z",
        ),
        (
            dict(problem="paper", axes={"vx": 1, "vy": -1, "omega": 0, "mu": "-1:1:3"}),
            ValueError,
            "mu must be >= 0",
        ),
        (
            dict(problem="paper", axes={"vx": 1, "vy": -1, "omega": 0, "body": 2}),
            TypeError,
            "body must be one of",
        ),
        (
            dict(problem="paper", axes={"vx": 1, "vy": -1, "omega": 0, "body": "cube"}),
            ValueError,
            "body must be one of",
        ),
        (
            dict(problem="paper", axes={"vx": 1, "vy": -1, "omega": [0]}),
            TypeError,
            "omega must be a number, an Axis",
        ),
        (
            dict(problem="paper", axes={"vx": 1, "vy": "-1:1:3", "omega": 0}),
            ValueError,
            "vy must be < 0",
        ),
        (
            dict(problem="pair", axes={**PAIR, "vx": "-1:1:3"}),
            ValueError,
            "cannot be solved at the corner vx = -1",
        ),
        (
            dict(problem="planar", axes={"vx": 1}, tangential=object()),
            ValueError,
            "a tangential law does not apply to problem 'planar'",
        ),
        (
            dict(problem="paper", axes={"vx": Axis("omega", "fixed", 1.0)}),
            ValueError,
            "axes['vx'] is an axis of omega",
        ),
    ],
)
def test_bad_sweeps_are_named(kwargs, error, message):
    with pytest.raises(error, match=message.replace("(", r"\(").replace("[", r"\[")):
        ProblemSweep(**kwargs)


def test_bad_fields_list_the_valid_ones():
    sweep = ProblemSweep(problem="pair", axes={**PAIR, "vx": 1.0})
    with pytest.raises(
        ValueError, match="fields must be among ball1_mass, .*after1_vx.*; got 'after_omega'"
    ):
        run_sweep(sweep, fields=("after_omega",))


def test_parquet_fields_carry_the_declared_units(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the [parquet] extra is not installed")
    sweep = ProblemSweep(problem="pair", axes={**PAIR, "vx": "1:2:5"})
    run_sweep(sweep, output=tmp_path / "s.parquet", fields=("after1_vx", "after2_wz",
              "dissipated_energy", "grips", "regime"))  # fmt: skip
    schema = pq.read_schema(tmp_path / "s.parquet")
    units = {f.name: (f.metadata or {}).get(b"unit", b"").decode() for f in schema}
    assert units["vx"] == units["after1_vx"] == "m/s" and units["after2_wz"] == "rad/s"
    assert units["dissipated_energy"] == "J" and units["normal_x"] == "1"
    assert units["grips"] == units["regime"] == ""
    table = pq.read_table(tmp_path / "s.parquet")
    assert set(table["regime"].to_pylist()) <= set(sweep.regimes)
    assert schema.metadata[b"problem"] == b"pair"


# -- a problem registered by a test gets a sweep without any other change -------------------
class ToyImpact(Result):
    """A bead on a spring: it leaves at kappa times its speed, the spring stores the rest."""

    def __init__(self, speed, kappa, stiffness):
        self.after_speed = -kappa * speed
        self.stored_energy = 0.5 * (1 - kappa**2) * speed**2
        self.ringing = np.sqrt(stiffness)
        self.regime = np.where(speed < -1, "hard", "soft")

    @classmethod
    def column_names(cls):
        return ("after_speed", "stored_energy", "ringing", "regime")

    def columns(self):
        return {n: getattr(self, n) for n in self.column_names()}


def _solve_toy(c, tangential=None):
    if (c["speed"] >= 0).any():
        raise ValueError("speed must be < 0 (approaching)")
    return ToyImpact(c["speed"], c["kappa"], c["stiffness"])


@pytest.fixture
def toy():
    declared = register(
        Problem(
            "toy-bead",
            "a bead on a spring (a test's problem)",
            (
                Input("speed", "m/s", "speed toward the wall", rule="vy"),
                Input("kappa", "1", "restitution", 0.5, rule="kappa"),
                Input("stiffness", "N/m", "spring stiffness", 4.0, rule="mass"),
            ),
            _solve_toy,
            ToyImpact,
            marks=("stiffness",),
            units={"stored_energy": "J/kg", "ringing": "rad/s"},
            example={"speed": -2.0},
            regimes=("soft", "hard"),
        )
    )
    yield declared
    unregister(declared.name)


def test_a_problem_registered_later_is_swept(toy, tmp_path):
    sweep = ProblemSweep(problem="toy-bead", axes={"speed": "-3:-0.5:6", "stiffness": 9})
    assert sweep.inputs == ("speed", "kappa", "stiffness")
    assert sweep.default_fields == ("after_speed", "regime")
    result = run_sweep(sweep, output=tmp_path / "toy/", fields=("after_speed", "stored_energy",
                       "regime"), histogram=("after_speed", 0, 2, 4))  # fmt: skip
    assert result.regimes == ("soft", "hard") and result.regime_counts.tolist() == [2, 4]
    speed = np.linspace(-3, -0.5, 6)
    np.testing.assert_array_equal(np.load(tmp_path / "toy" / "after_speed.npy"), -0.5 * speed)
    meta = json.loads((tmp_path / "toy" / "metadata.json").read_text())
    assert meta["problem"] == "toy-bead" and meta["regimes"] == ["soft", "hard"]
    assert meta["columns"]["stored_energy"]["unit"] == "J/kg"
    assert meta["columns"]["stiffness"]["unit"] == "N/m"
    assert result.histogram.tolist() == [1, 2, 2, 1]
    with pytest.raises(ValueError, match=r"speed must be < 0 .*, got 1.0"):
        ProblemSweep(problem="toy-bead", axes={"speed": "-1:1:3"})


@pytest.mark.slow
def test_the_dask_path_gives_the_same_numbers():
    distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed")
    sweep = ProblemSweep(problem="pair", axes={**PAIR, "vx": "uniform:0.5:4", "wz": "uniform:-9:9"},
                         samples=3000, chunk_size=500)  # fmt: skip
    local = run_sweep(sweep, histogram=("after1_vx", -1, 4, 10))
    with distributed.Client(processes=False, n_workers=2, threads_per_worker=1,
                            dashboard_address=":0") as client:  # fmt: skip
        remote = run_sweep(sweep, histogram=("after1_vx", -1, 4, 10), client=client)
    np.testing.assert_array_equal(local.regime_counts, remote.regime_counts)
    np.testing.assert_array_equal(local.histogram, remote.histogram)
    assert local.histogram.sum() == 3000
