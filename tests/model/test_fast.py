"""The scalar path of solve(): the same Impact as the array path, bit for bit, same errors."""

import math
import warnings

import numpy as np
import pytest

from spinimpact import Body, TabulatedRestitution, solve
from spinimpact.model import _fast
from spinimpact.model.impact import Impact, Outcome, State

from tests.cases import random_cases
from tests.same_result import array_path, assert_same


def _array_path(monkeypatch, *args, **kwargs):
    return array_path(monkeypatch, _fast, "paper_impact", solve, *args, **kwargs)


KINDS = (Impact, State, Outcome)


def _body(c, i):
    return Body(
        mass=float(c["mass"][i]), radius=float(c["radius"][i]), gyration=float(c["gyration"][i])
    )


@pytest.fixture(scope="module")
def cases():
    return random_cases(400, seed=14)


@pytest.mark.slow
def test_every_regime_bit_for_bit(cases, monkeypatch):
    c = cases
    seen = set()
    for i in range(len(c["vx"])):
        body = _body(c, i)
        args = (body, float(c["vx"][i]), float(c["vy"][i]), float(c["omega"][i]))
        kw = dict(mu=float(c["mu"][i]), kappa=float(c["kappa"][i]))
        fast = solve(*args, **kw)
        assert_same(fast, _array_path(monkeypatch, *args, **kw))
        seen.add(str(fast.regime))
        seen.add(str(fast.min_energy_case))
    assert {"frictionless", "no-slip", "stick-compression", "stick-restitution", "slip"} <= seen
    assert {"at rebound", "sliding throughout (Fig. 5c)", "rolling (Fig. 5b)"} <= seen


@pytest.mark.parametrize(
    ("vx", "omega", "mu", "kappa"),
    [
        (0.0, 0.0, 0.3, 0.8),  # no slip at all: tau_* = 0, NaN work ratio
        (-0.0, -0.0, 0.0, 0.0),  # signed zeros, frictionless, kappa = 0
        (0.5, 12.5, 0.5, 0.8),  # vertical rebound without spin (outcome tolerance)
        (3.0, 0.0, 0.0, 1.0),  # mu = 0: tau_* = inf
        (1e50, -1e50, 1e6, 1.0),  # the largest accepted magnitudes
        (1e-50, 0.0, 1e-300, 0.5),  # a tiny mu: x = ratio/(zeta mu) overflows
    ],
)
def test_edges_bit_for_bit(vx, omega, mu, kappa, monkeypatch):
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    fast = solve(body, vx, -1.0, omega, mu=mu, kappa=kappa)
    assert_same(fast, _array_path(monkeypatch, body, vx, -1.0, omega, mu=mu, kappa=kappa))


def test_number_kinds_take_the_fast_path(monkeypatch):
    body = Body.solid_disk(mass=2, radius=0.5)
    kinds = [3, np.float32(3.0), np.int64(3), np.float64(3.0), np.array(3.0), np.array(3)]
    for vx in kinds:
        assert _fast.paper_impact(body, vx, -1, 2, 0.2, 0.5, KINDS) is not None
        fast = solve(body, vx, -1, np.float32(2.0), mu=np.array(0.2), kappa=0.5)
        assert_same(
            fast,
            _array_path(monkeypatch, body, vx, -1, np.float32(2.0), mu=np.array(0.2), kappa=0.5),
        )


@pytest.mark.parametrize(
    "value", [np.array([1.0]), [1.0], 2**60, np.longdouble(1.0), True, None, "1", 1j, np.nan]
)
def test_other_values_take_the_array_path(value):
    assert _fast.number(value, "vx") is None


def test_restitution_model_and_array_body_take_the_array_path(monkeypatch):
    model = TabulatedRestitution([0.5, 5.0], [0.9, 0.6])
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    assert _fast.paper_impact(body, 1.0, -2.0, 0.0, 0.3, model, KINDS) is None
    imp = solve(body, 1.0, -2.0, 0.0, mu=0.3, kappa=model)
    assert imp.shape == ()
    spread = Body(mass=np.array([1.0, 2.0]), radius=0.1, gyration=0.05)
    assert _fast.paper_impact(spread, 1.0, -2.0, 0.0, 0.3, 0.5, KINDS) is None


BAD = [
    dict(vy=0.0),
    dict(vy=-1e-51),
    dict(vy=float("nan")),
    dict(vx=math.inf),
    dict(vx=1e51),
    dict(omega="fast"),
    dict(omega=True),
    dict(mu=-0.1),
    dict(mu=1e7),
    dict(kappa=1.5),
    dict(kappa=np.float64(-0.0) - 1e-9),
    dict(kappa=None),
    dict(vx=2**70),
    dict(vy=np.array([0.5])),
    dict(mu=np.array([[-1.0]])),
    dict(kappa=np.array([0.5, 2.0])),
]


@pytest.mark.parametrize("bad", BAD)
def test_errors_are_the_array_paths(bad, monkeypatch):
    body = Body.solid_disk(mass=1.0, radius=0.1)
    kw = dict(vx=1.0, vy=-1.0, omega=0.0, mu=0.3, kappa=0.5) | bad
    with pytest.raises((TypeError, ValueError)) as fast:
        solve(body, **kw)
    with pytest.raises((TypeError, ValueError)) as slow:
        _array_path(monkeypatch, body, **kw)
    assert type(fast.value) is type(slow.value)
    assert str(fast.value) == str(slow.value)


def test_no_warnings_on_scalar_calls():
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for args in [(0.0, -1.0, 0.0), (3.0, -1.0, 0.0), (1e-50, -1.0, 0.0)]:
            solve(body, *args, mu=1e-300, kappa=0.0)
            solve(body, *args, mu=0.0, kappa=1.0)


@pytest.mark.parametrize(
    "shapes",
    [
        dict(vx=(1,)),
        dict(vy=(1, 1), omega=(1,)),
        dict(mu=(1,), kappa=(1, 1, 1)),
        dict(vx=(1,), vy=(1,), omega=(1,), mu=(1,), kappa=(1,)),
    ],
)
@pytest.mark.slow
def test_one_element_arrays_bit_for_bit(shapes, cases, monkeypatch):
    c = cases
    for i in range(0, 400, 7):
        body = _body(c, i)
        kw = {k: float(c[k][i]) for k in ("vx", "vy", "omega", "mu", "kappa")}
        kw |= {k: np.full(shape, kw[k]) for k, shape in shapes.items()}
        fast = solve(body, **kw)
        assert fast.shape == np.broadcast_shapes(*shapes.values())
        assert_same(fast, _array_path(monkeypatch, body, **kw))


def test_longer_arrays_take_the_array_path():
    body = Body.solid_disk(mass=1.0, radius=0.1)
    assert _fast.paper_impact(body, np.array([1.0, 2.0]), -1.0, 0.0, 0.3, 0.5, KINDS) is None
    assert _fast.paper_impact(body, np.array([1.0]), -1.0, np.zeros(0), 0.3, 0.5, KINDS) is None
