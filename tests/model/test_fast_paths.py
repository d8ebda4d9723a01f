"""Every solver's scalar path against its array path: one impact of plain numbers and the
same impact with inputs as arrays of one element give the array path's result bit for bit
(every field's type, dtype, shape, read-only flag and bits), and bad input raises the array
path's error (type and message), in both forms."""

import math

import numpy as np
import pytest

from spinimpact import (
    Body,
    MindlinDeresiewicz,
    Pendulum,
    PlanarBody,
    Stronge,
    Surface,
    Walton,
    solve,
    solve_pair,
    solve_pendulum,
    solve_planar,
    solve_sphere,
)
from spinimpact.model import _fast, _fast_planar, _fast_sphere, _fast_tangential
from spinimpact.model._fast_result import Layout
from spinimpact.model.impact import State

from tests.cases import random_cases
from tests.planar_reference import random_planar_cases
from tests.same_result import assert_same
from tests.sphere_cases import random_sphere_cases

HOOKS = [
    (_fast, "paper_impact"),
    (_fast_sphere, "sphere_impact"),
    (_fast_sphere, "pair_impact"),
    (_fast_planar, "planar_impact"),
    (_fast_planar, "pendulum_impact"),
    (_fast_tangential, "plane_impact"),
]


def general(monkeypatch, solver, *args, **kwargs):
    """``solver(*args, **kwargs)`` with every scalar path switched off."""
    with monkeypatch.context() as m:
        for module, name in HOOKS:
            m.setattr(module, name, lambda *a: None)
        return solver(*args, **kwargs)


def check(monkeypatch, solver, *args, **kwargs):
    """The call's result equals the array path's, bit for bit; returns it."""
    fast = solver(*args, **kwargs)
    assert_same(fast, general(monkeypatch, solver, *args, **kwargs))
    return fast


def same_error(monkeypatch, solver, *args, **kwargs):
    """The call raises what the array path raises (the same type and message), or, where
    the array path accepts the input, returns its result bit for bit."""
    try:
        slow = general(monkeypatch, solver, *args, **kwargs)
    except (TypeError, ValueError) as err:
        with pytest.raises(type(err)) as fast:
            solver(*args, **kwargs)
        assert type(fast.value) is type(err)
        assert str(fast.value) == str(err)
        return err
    assert_same(solver(*args, **kwargs), slow)
    return None


def _numba_installed():
    from spinimpact.core.fused import HAVE_NUMBA

    return HAVE_NUMBA


SHAPES = [(1,), (1, 1), (1, 1, 1)]


def _one(x, i):
    """``x`` as an array of one element, of one of :data:`SHAPES` chosen by ``i``."""
    return np.full(SHAPES[i % len(SHAPES)], x)


def _paper_inputs(c, i):
    body = Body(mass=float(c["mass"][i]), radius=float(c["radius"][i]),
                gyration=float(c["gyration"][i]))  # fmt: skip
    kw = {k: float(c[k][i]) for k in ("vx", "vy", "omega", "mu", "kappa")}
    return body, kw


@pytest.mark.slow
def test_paper_bodies_plain_and_one_element(monkeypatch):
    c = random_cases(300, seed=101)
    seen = set()
    for i in range(300):
        body, kw = _paper_inputs(c, i)
        seen.add(str(check(monkeypatch, solve, body, **kw).regime))
        name = ("vx", "vy", "omega", "mu", "kappa")[i % 5]
        one = check(monkeypatch, solve, body, **kw | {name: _one(kw[name], i)})
        assert one.shape == SHAPES[i % 3]
    assert len(seen) == 5


@pytest.mark.parametrize(
    "law",
    [
        Walton(0.35),
        Walton(-1.0),
        Walton(1.0),
        Walton(0.0),
        Stronge(poisson_ratio=0.23),
        Stronge(stiffness_ratio=5.0),
    ],
)
@pytest.mark.slow
def test_tangential_laws_plain_and_one_element(law, monkeypatch):
    c = random_cases(150, seed=102)
    seen = set()
    for i in range(150):
        body, kw = _paper_inputs(c, i)
        seen.add(str(check(monkeypatch, solve, body, **kw, tangential=law).regime))
        name = ("vx", "vy", "omega", "mu", "kappa")[i % 5]
        kw[name] = _one(kw[name], i)
        assert check(monkeypatch, solve, body, **kw, tangential=law).shape == SHAPES[i % 3]
    assert len(seen) >= (1 if law.frictionless else 4)


MICRO_SLIP_ON_FLOATS = pytest.mark.skipif(
    not _numba_installed(), reason="micro-slip's scalar path reads the table with Numba"
)


@MICRO_SLIP_ON_FLOATS
def test_micro_slip_from_the_table_plain_and_one_element(monkeypatch):
    from tests.core.test_law_mdr import _cases

    law = MindlinDeresiewicz(poisson_ratio=0.23)
    c = _cases(100, law.stiffness_ratio, seed=103)
    seen = set()
    for i in range(100):
        body, kw = _paper_inputs(c, i)
        seen.add(str(check(monkeypatch, solve, body, **kw, tangential=law).regime))
        name = ("vx", "vy", "omega", "mu", "kappa")[i % 5]
        kw[name] = _one(kw[name], i)
        assert check(monkeypatch, solve, body, **kw, tangential=law).shape == SHAPES[i % 3]
    assert len(seen) == 5


@MICRO_SLIP_ON_FLOATS
def test_micro_slip_outside_the_table_takes_the_array_path(monkeypatch):
    taken = []
    hook = _fast_tangential.plane_impact
    monkeypatch.setattr(_fast_tangential, "plane_impact",
                        lambda *a: taken.append(hook(*a)) or taken[-1])  # fmt: skip
    law = MindlinDeresiewicz(poisson_ratio=0.23)
    inside = check(monkeypatch, solve, BALL, 1.0, -2.0, 0.0, mu=0.3, kappa=0.9, tangential=law)
    outside = check(monkeypatch, solve, BALL, 1.0, -2.0, 0.0, mu=0.3, kappa=0.7, tangential=law)
    assert taken[0] is not None and taken[1] is None
    assert inside.regime == outside.regime == "slip-reversal"
    fine = MindlinDeresiewicz(poisson_ratio=0.23, springs=128)  # not the table's resolution
    assert fine._on_floats() is None and law._on_floats() is not None


def test_tangential_law_subclasses_and_other_laws_take_the_array_path():
    class Mine(Walton):
        pass

    from spinimpact.model.compliance import _SCALAR

    assert Mine not in _SCALAR and Walton in _SCALAR and Stronge in _SCALAR
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    imp = solve(ball, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, tangential=Mine(0.2))
    assert imp.law == Mine(0.2)


@pytest.mark.slow
def test_spheres_plain_and_one_element(monkeypatch):
    ball = Body(mass=2.0, radius=0.1, gyration=0.05)
    n, vs, v, w, mu, kappa = random_sphere_cases(200, seed=103)
    seen = set()
    for i in range(len(mu)):
        kw = dict(mu=float(mu[i]), kappa=float(kappa[i]),
                  surface=Surface(normal=n[i], velocity=vs[i]))  # fmt: skip
        seen.add(str(check(monkeypatch, solve_sphere, ball, tuple(v[i]), list(w[i]), **kw).regime))
        if i % 3 == 0:
            args = (v[i].reshape(SHAPES[i % 2] + (3,)), w[i])
        elif i % 3 == 1:
            args, kw["mu"] = (list(v[i]), w[i]), _one(kw["mu"], i)
        else:
            args, kw["kappa"] = (v[i], w[i][None]), _one(kw["kappa"], i)
        one = check(monkeypatch, solve_sphere, ball, *args, **kw)
        assert one.shape in SHAPES
    assert len(seen) == 5


@pytest.mark.slow
def test_pairs_plain_and_one_element(monkeypatch):
    b1, b2 = Body.solid_sphere(mass=0.17, radius=0.03), Body(mass=0.3, radius=0.04, gyration=0.02)
    n, vs, v, w, mu, kappa = random_sphere_cases(200, seed=104)
    rng = np.random.default_rng(105)
    seen = set()
    for i in range(len(mu)):
        v2, w2 = rng.normal(0, 1, 3), rng.normal(0, 20, 3)
        v2 -= np.dot(v2, n[i]) * n[i]  # across the normal only
        if np.array_equal(n[i], [0.0, 1.0, 0.0]) and not w[i].any():
            v2, w2 = np.zeros(3), np.zeros(3)  # head on, no spin: no slip at all
        kw = dict(velocity1=list(v[i] - vs[i]), spin1=tuple(w[i]), velocity2=v2, spin2=w2,
                  mu=float(mu[i]), kappa=float(kappa[i]), normal=tuple(n[i]))  # fmt: skip
        seen.add(str(check(monkeypatch, solve_pair, b1, b2, **kw).regime))
        key = ("velocity1", "spin2", "normal", "mu")[i % 4]
        kw[key] = np.asarray(kw[key])[None] if key != "mu" else _one(kw["mu"], i)
        assert check(monkeypatch, solve_pair, b1, b2, **kw).shape in SHAPES
    assert len(seen) == 5


@pytest.mark.parametrize("law", ["newton", "poisson", "energetic"])
@pytest.mark.slow
def test_planar_bodies_plain_and_one_element(law, monkeypatch):
    c = random_planar_cases(200, seed=106)
    for i in np.flatnonzero(c["ry"] < 0):
        body = PlanarBody(mass=float(c["mass"][i]), inertia=float(c["inertia"][i]),
                          rx=float(c["rx"][i]), ry=float(c["ry"][i]))  # fmt: skip
        kw = {k: float(c[k][i]) for k in ("vx", "vy", "omega", "mu", "kappa")}
        check(monkeypatch, solve_planar, body, **kw, law=law)
        name = ("vx", "vy", "omega", "mu", "kappa")[i % 5]
        kw[name] = _one(kw[name], i)
        assert check(monkeypatch, solve_planar, body, **kw, law=law).shape == SHAPES[i % 3]


@pytest.mark.parametrize("law", ["newton", "poisson", "energetic"])
@pytest.mark.slow
def test_pendulums_plain_and_one_element(law, monkeypatch):
    rng = np.random.default_rng(107)
    seen = set()
    for i in range(150):
        angle = rng.uniform(0.05, math.pi - 0.05)
        p = Pendulum.rod(mass=10 ** rng.uniform(-1, 1), length=10 ** rng.uniform(-1, 0.5),
                         angle=angle)  # fmt: skip
        omega = -math.copysign(10 ** rng.uniform(-1, 1), math.cos(angle))
        kw = dict(mu=float(rng.choice([0.0, rng.uniform(0, 2)])), kappa=rng.uniform(0, 1),
                  law=law)  # fmt: skip
        seen.add(str(check(monkeypatch, solve_pendulum, p, omega, **kw).regime))
        if i % 2:
            omega = _one(omega, i)
        else:
            kw["kappa"] = _one(kw["kappa"], i)
        assert check(monkeypatch, solve_pendulum, p, omega, **kw).shape == SHAPES[i % 3]
    assert {"locked", "reverse-compression", "frictionless"} <= seen


BALL = Body.solid_sphere(mass=1.0, radius=0.1)
ROD = PlanarBody.rod(mass=1.0, length=0.5, angle=0.7)
PENDULUM = Pendulum.rod(mass=1.0, length=1.0, angle=1.0)
PAPER = dict(vx=1.0, vy=-2.0, omega=3.0, mu=0.3, kappa=0.8)
BAD = [
    dict(vy=0.0), dict(vy=-1e-51), dict(vy=math.nan), dict(vx=math.inf), dict(vx=-1e51),
    dict(omega="fast"), dict(omega=True), dict(omega=None), dict(omega=1j), dict(mu=-0.1),
    dict(mu=1e7), dict(kappa=1.5), dict(kappa=-1e-300), dict(vx=2**70), dict(vy=np.int64(0)),
    dict(vx=np.array([True])), dict(vx=np.array(["1"])), dict(mu=np.array([1.0, -2.0])),
    dict(vy=np.array([[0.5]])), dict(kappa=np.array([2.0])), dict(mu=np.array([-1.0])),
    dict(vx=np.array([np.nan])), dict(omega=np.array([[np.inf]])),
    dict(vx=np.array([2.0], dtype=object)), dict(kappa=np.array([[0.5]], dtype=object)),
]  # fmt: skip


def _ones(bad):
    """``bad`` with each good number of :data:`PAPER` an array of one element: the errors
    of the one-element form."""
    return {k: np.array([v]) for k, v in PAPER.items()} | bad


@pytest.mark.parametrize("bad", BAD)
@pytest.mark.parametrize("law", [None, Walton(0.3), Stronge(poisson_ratio=0.3)])
def test_paper_errors_are_the_array_paths(bad, law, monkeypatch):
    errors = [same_error(monkeypatch, solve, BALL, **kw, tangential=law)
              for kw in (PAPER | bad, _ones(bad))]  # fmt: skip
    assert errors[0] is not None


@pytest.mark.parametrize("bad", BAD + [dict(law="stronge"), dict(law=2), dict(law=None)])
def test_planar_errors_are_the_array_paths(bad, monkeypatch):
    for kw in (PAPER | bad, _ones(bad)):
        same_error(monkeypatch, solve_planar, ROD, **{"law": "poisson"} | kw)


@pytest.mark.parametrize(
    "bad",
    [dict(omega=0.0), dict(omega=2.0), dict(omega=math.inf), dict(omega="spin"),
     dict(omega=np.array([2.0])), dict(omega=np.array([[True]])), dict(mu=-1.0),
     dict(kappa=np.array([1.5])), dict(law="stronge"), dict(law=1), dict(kappa=None)],
)  # fmt: skip
def test_pendulum_errors_are_the_array_paths(bad, monkeypatch):
    kw = dict(omega=-2.0, mu=0.3, kappa=0.8, law="poisson") | bad
    same_error(monkeypatch, solve_pendulum, PENDULUM, **kw)
    kw["mu"] = np.array([kw["mu"]]) if isinstance(kw["mu"], float) else kw["mu"]
    same_error(monkeypatch, solve_pendulum, PENDULUM, **kw)


SPHERE = dict(velocity=[1.0, -2.0, 0.5], spin=[0.0, 3.0, 3.0], mu=0.3, kappa=0.8)


@pytest.mark.parametrize(
    "bad",
    [dict(velocity=[1.0, 2.0, 0.0]), dict(velocity=[1.0, -2.0]), dict(velocity="up"),
     dict(velocity=np.array([[1.0, 2.0, 0.0]])), dict(spin=[0.0, math.inf, 0.0]),
     dict(spin=np.array([[0.0, 1.0]])), dict(spin=[True, 1.0, 0.0]), dict(mu=-1.0),
     dict(mu=np.array([-1.0])), dict(kappa=np.array([[2.0]])), dict(kappa="1"),
     dict(mu=np.array([0.3], dtype=object)), dict(velocity=np.array([1.0, -2.0, 0], object)),
     dict(velocity=[1e51, -2.0, 0.0]), dict(surface="ground"),
     dict(velocity=np.array([[1.0, -2.0, 0.0], [1.0, -2.0, 0.0]]), mu=np.array([-1.0]))],
)  # fmt: skip
def test_sphere_errors_are_the_array_paths(bad, monkeypatch):
    same_error(monkeypatch, solve_sphere, BALL, **SPHERE | bad)
    one = {"velocity": np.array([SPHERE["velocity"]])} if "velocity" not in bad else {}
    same_error(monkeypatch, solve_sphere, BALL, **SPHERE | one | bad)


PAIR = dict(velocity1=[0.0, 0.0, -2.0], spin1=[0.0, 30.0, 0.0], velocity2=[0, 0, 0],
            spin2=[0, 0, 0], normal=[0, 0, 1], mu=0.06, kappa=0.93)  # fmt: skip


@pytest.mark.parametrize(
    "bad",
    [dict(normal=(0.0, 0.0, 0.0)), dict(normal=None), dict(centres=([0, 0, 0], [0, 0, 0.01])),
     dict(velocity1=[0.0, 0.0, 1.0]), dict(velocity1=np.array([[0.0, 0.0, 1.0]])),
     dict(mu=np.array([-1.0])), dict(spin2=[1.0, 2.0]), dict(kappa=np.array([1.1])),
     dict(normal=np.array([[0.0, 0.0, 0.0]]))],
)  # fmt: skip
def test_pair_errors_are_the_array_paths(bad, monkeypatch):
    ball = Body.solid_sphere(mass=0.17, radius=0.028575)
    same_error(monkeypatch, solve_pair, ball, ball, **PAIR | bad)
    one = {"spin1": np.array([PAIR["spin1"]])}
    same_error(monkeypatch, solve_pair, ball, ball, **PAIR | one | bad)


def test_longer_arrays_and_models_take_the_array_path():
    kinds = (type(solve(BALL, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)), State,
             type(solve(BALL, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5).outcome))  # fmt: skip
    assert _fast.paper_impact(BALL, np.zeros(2) + 1, -1.0, 0.0, 0.3, 0.5, kinds) is None
    assert _fast.paper_impact(BALL, 1.0, -1.0, 0.0, 0.3, lambda v: 0.5, kinds) is None
    assert _fast.numbers((np.array([1.0]), np.ones((1, 1))), ("vx", "mu")) == ([1.0, 1.0],
                                                                              (1, 1))  # fmt: skip
    assert _fast.numbers((1.0, 2.0), ("vx", "kappa")) is None


def test_a_layout_names_every_field_once():
    with pytest.raises(TypeError, match="each of its fields once"):
        Layout(State, ("vx", "vy"))
    with pytest.raises(TypeError, match="each of its fields once"):
        Layout(State, ("vx", "vy", "omega", "vx"))
    layout = Layout(State, ("vx", "vy", "omega"))
    one = layout.scalars((1.0, -0.0, math.nan), (), {})
    assert type(one.vx) is np.float64 and math.copysign(1.0, one.vy) == -1.0
    arrays = layout.arrays((1.0, -0.0, 2.0), (), {}, (1, 1))
    assert arrays.omega.shape == (1, 1) and not arrays.omega.flags.writeable
    assert arrays.vx.dtype == np.float64 and arrays.shape == (1, 1)


def test_plain_numbers_and_one_element_arrays_take_the_scalar_paths(monkeypatch):
    taken = []
    for module, name in HOOKS:
        hook = getattr(module, name)

        def spy(*a, hook=hook, name=name):
            out = hook(*a)
            taken.append((name, out is not None))
            return out

        monkeypatch.setattr(module, name, spy)
    one = np.array([1.0])
    for solver, args, kw in [
        (solve, (BALL,), PAPER), (solve, (BALL,), PAPER | dict(vx=one)),
        (solve, (BALL,), PAPER | dict(tangential=Walton(0.3), kappa=one)),
        (solve, (BALL,), PAPER | dict(tangential=Stronge(poisson_ratio=0.3))),
        *([(solve, (BALL,), PAPER | dict(tangential=MindlinDeresiewicz(poisson_ratio=0.3),
                                         kappa=np.array([0.9])))]
          if _numba_installed() else []),
        (solve_sphere, (BALL,), SPHERE), (solve_sphere, (BALL,), SPHERE | dict(mu=one)),
        (solve_pair, (BALL, BALL), PAIR), (solve_pair, (BALL, BALL), PAIR | dict(mu=one)),
        (solve_planar, (ROD,), PAPER), (solve_planar, (ROD,), PAPER | dict(omega=one)),
        (solve_pendulum, (PENDULUM, -2.0), dict(mu=0.3, kappa=0.5)),
        (solve_pendulum, (PENDULUM, np.array([-2.0])), dict(mu=0.3, kappa=0.5)),
    ]:  # fmt: skip
        taken.clear()
        solver(*args, **kw)
        assert taken and all(ok for _, ok in taken), (solver.__name__, kw, taken)
