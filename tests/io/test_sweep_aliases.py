"""The older per-problem sweeps are aliases of ProblemSweep: each warns once per process,
naming what replaces it, and gives the very sweep ProblemSweep gives."""

import math
import warnings

import numpy as np
import pytest

from spinimpact import Body, Pendulum, PlanarBody, Walton
from spinimpact.io import _deprecated
from spinimpact.io.problem_sweep import ProblemSweep, problem_fields
from spinimpact.io.sweep import parse_axis
from spinimpact.model.sphere3d import Surface

BALL = Body.spherical_shell(mass=0.057, radius=0.033)
ROD = PlanarBody.rod(mass=1.5, length=0.8, angle=math.radians(40))
PENDULUM = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
SPHERE = dict(vx="uniform:-3:3", vy="uniform:-6:-2", vz="0", wx="uniform:-80:80", wy="10",
              wz="uniform:-80:80", mu="uniform:0:1", kappa="0.8")  # fmt: skip
PLANAR = dict(vx="-2:2:9", vy="-2:-0.5:3", omega="-1:1:5", mu="0.3", kappa="0:1:3")
PAPER = dict(vx="-5:5:11", vy="-4:-0.5:3", omega="-50:50:11", mu="0.3", kappa="0.7")
#: A surface whose normal normalises to itself, so the alias's sweep is the one typed here.
FLAT = Surface(normal=(0.0, 2.0, 0.0), velocity=(0.5, 0.0, -0.25))
FLAT_INPUTS = dict(normal_x=0.0, normal_y=1.0, normal_z=0.0, surface_velocity_x=0.5,
                   surface_velocity_y=0.0, surface_velocity_z=-0.25)  # fmt: skip


def axes(spec):
    return {n: parse_axis(n, v) for n, v in spec.items()}


@pytest.fixture
def fresh(monkeypatch):
    """A process in which no alias has warned yet."""
    monkeypatch.setattr(_deprecated, "_WARNED", set())


def called_twice(make):
    """``make()`` twice, and the deprecation warnings it gave."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        first, second = make(), make()
    return first, second, [w for w in caught if issubclass(w.category, DeprecationWarning)]


def assert_same_sweep(a, b):
    assert isinstance(a, ProblemSweep) and a.inputs == b.inputs and a.regimes == b.regimes
    assert a.description() == b.description() and a.size == b.size
    fields = tuple(n for n in problem_fields(a.problem, a.tangential, a.body))
    for k in range(a.chunks):
        got, want = a.evaluate(k, fields), b.evaluate(k, fields)
        assert list(got) == list(want)
        for name in got:
            np.testing.assert_array_equal(got[name], want[name], err_msg=name)


def sphere_sweep():
    from spinimpact.io.sphere_sweep import SphereSweep

    return SphereSweep(BALL, axes(SPHERE), samples=120, seed=4, chunk_size=50, surface=FLAT)


def planar_sweep():
    from spinimpact.io.planar_sweep import PlanarSweep

    return PlanarSweep(ROD, axes(PLANAR), chunk_size=100, law="newton")


def pendulum_sweep():
    from spinimpact.io.planar_sweep import PlanarSweep

    return PlanarSweep(PENDULUM, axes(dict(omega="-6:-0.1:9", mu="0:1:3", kappa="0.5")))


def compliant_sweep():
    from spinimpact.io.compliant_sweep import CompliantSweep

    return CompliantSweep(BALL, axes(PAPER), chunk_size=50, tangential=Walton(0.4))


@pytest.mark.parametrize(
    ("make", "old", "direct"),
    [
        (sphere_sweep, "SphereSweep",
         lambda: ProblemSweep(problem="sphere", body=BALL, axes=SPHERE, fixed=FLAT_INPUTS,
                              samples=120, seed=4, chunk_size=50)),
        (planar_sweep, "PlanarSweep",
         lambda: ProblemSweep(problem="planar", body=ROD, axes=PLANAR, fixed={"law": "newton"},
                              chunk_size=100)),
        (pendulum_sweep, "PlanarSweep",
         lambda: ProblemSweep(problem="pendulum", body=PENDULUM, fixed={"law": "poisson"},
                              axes=dict(omega="-6:-0.1:9", mu="0:1:3", kappa="0.5"))),
        (compliant_sweep, "CompliantSweep",
         lambda: ProblemSweep(problem="paper", body=BALL, axes=PAPER, chunk_size=50,
                              tangential=Walton(0.4))),
    ],
    ids=["sphere", "planar", "pendulum", "compliant"],
)  # fmt: skip
def test_each_alias_warns_once_and_is_the_problem_sweep(fresh, make, old, direct):
    first, second, warned = called_twice(make)
    assert len(warned) == 1, [str(w.message) for w in warned]
    message = str(warned[0].message)
    assert message.startswith(f"{old} is deprecated: use ") and "ProblemSweep(problem=" in message
    assert warned[0].filename == __file__  # it points at the line that built the sweep
    assert_same_sweep(first, direct())
    assert_same_sweep(second, direct())


@pytest.mark.parametrize(
    ("module", "name", "call", "want"),
    [
        ("sphere_sweep", "sphere_fields", (), lambda: problem_fields("sphere", body=Body)),
        ("planar_sweep", "planar_fields", (),
         lambda: problem_fields("planar", body=PlanarBody)),
        ("planar_sweep", "planar_fields", (True,),
         lambda: problem_fields("pendulum", body=Pendulum)),
        ("compliant_sweep", "compliant_fields", (),
         lambda: problem_fields("paper", Walton(0.9), body=Body)),
        ("sphere_sweep", "SPHERE_INPUTS", None,
         lambda: ("vx", "vy", "vz", "wx", "wy", "wz", "mu", "kappa")),
        ("planar_sweep", "PENDULUM_INPUTS", None, lambda: ("omega", "mu", "kappa")),
    ],
)  # fmt: skip
def test_the_old_helpers_warn_once_and_give_the_problem_fields(fresh, module, name, call, want):
    import importlib

    found = importlib.import_module(f"spinimpact.io.{module}")
    first, second, warned = called_twice(
        lambda: getattr(found, name) if call is None else getattr(found, name)(*call)
    )
    assert [str(w.message).split(":")[0] for w in warned] == [f"{name} is deprecated"]
    assert first == second == want()


def test_the_fields_of_the_old_sweeps_are_those_of_the_problems():
    """Their sets as the older sweeps listed them: the result's columns less the inputs and
    the body's own."""
    fields = problem_fields("sphere", body=Body)
    assert fields[0] == "regime" and {"grips", "topspin", "after_wz"} <= set(fields)
    assert not {"mass", "radius", "gyration", "zeta", "normal_x", "before_vx"} & set(fields)
    assert {"before_vx", "before_vy"} <= set(problem_fields("pendulum", body=Pendulum))
    assert "before_vx" not in problem_fields("planar", body=PlanarBody)
    assert "tangential_restitution" in problem_fields("paper", Walton(0.1), body=Body)


def test_the_aliases_keep_their_own_type_checks(fresh):
    from spinimpact.io.compliant_sweep import CompliantSweep
    from spinimpact.io.planar_sweep import PlanarSweep
    from spinimpact.io.sphere_sweep import SphereSweep

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        with pytest.raises(TypeError, match="body must be a spinimpact.Body, got PlanarBody"):
            SphereSweep(ROD, axes(SPHERE), samples=10)
        with pytest.raises(TypeError, match="surface must be a spinimpact.Surface"):
            SphereSweep(BALL, axes(SPHERE), samples=10, surface=(0, 1, 0))
        with pytest.raises(ValueError, match="a single surface"):
            SphereSweep(BALL, axes(SPHERE), samples=10,
                        surface=Surface(normal=[(0, 1, 0), (0, 1, 0)]))  # fmt: skip
        with pytest.raises(TypeError, match="PlanarBody or Pendulum, got Body"):
            PlanarSweep(BALL, axes(PLANAR))
        with pytest.raises(TypeError, match="tangential must be a tangential compliance law"):
            CompliantSweep(BALL, axes(PAPER))
