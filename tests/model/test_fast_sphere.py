"""The scalar path of solve_sphere(): the same SphereImpact as the array path, bit for bit."""

import numpy as np
import pytest

from spinimpact import Body, Surface, solve_pair, solve_sphere
from spinimpact.model import _fast_sphere
from spinimpact.model.sphere3d import SphereImpact, State3, Vector

from tests.same_result import array_path, assert_same
from tests.sphere_cases import random_sphere_cases


def _array_path(monkeypatch, *args, **kwargs):
    return array_path(monkeypatch, _fast_sphere, "sphere_impact", solve_sphere, *args, **kwargs)


KINDS = (SphereImpact, State3, Vector, Surface)


@pytest.mark.parametrize(
    "ball",
    [Body.spherical_shell(mass=0.057, radius=0.033), Body(mass=2.0, radius=0.1, gyration=0.05)],
)
@pytest.mark.slow
def test_every_regime_bit_for_bit(ball, monkeypatch):
    n, vs, v, w, mu, kappa = random_sphere_cases(300, seed=21)
    regimes = set()
    for i in range(len(mu)):
        kw = dict(
            mu=float(mu[i]), kappa=float(kappa[i]), surface=Surface(normal=n[i], velocity=vs[i])
        )
        fast = solve_sphere(ball, v[i].tolist(), tuple(w[i]), **kw)
        assert_same(fast, _array_path(monkeypatch, ball, v[i].tolist(), tuple(w[i]), **kw))
        regimes.add(str(fast.regime))
    assert regimes == {"frictionless", "no-slip", "stick-compression", "stick-restitution", "slip"}


def test_defaults_and_array_vectors(monkeypatch):
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    for v, w in [
        ([2.0, -3.0, 0.0], [0, 0, 0]),
        (np.array([1, -2, 3]), np.array([5.0, 0, 1])),
        ((0.0, -1.0, 0.0), (0.0, 7.0, 0.0)),
    ]:
        fast = solve_sphere(ball, v, w, mu=0.3, kappa=0.8)
        assert _fast_sphere.sphere_impact(ball, v, w, 0.3, 0.8, Surface(), KINDS) is not None
        assert_same(fast, _array_path(monkeypatch, ball, v, w, mu=0.3, kappa=0.8))


@pytest.mark.parametrize(
    "bad",
    [
        dict(velocity=[1.0, 2.0, 0.0]),
        dict(velocity=[1.0, -2.0]),
        dict(velocity="up"),
        dict(spin=[0.0, float("inf"), 0.0]),
        dict(spin=[[0.0, 1.0, 0.0]]),
        dict(mu=-1.0),
        dict(kappa=2.0),
        dict(velocity=[True, -1.0, 0.0]),
    ],
)
def test_errors_and_odd_values_are_the_array_paths(bad, monkeypatch):
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    kw = dict(velocity=[1.0, -2.0, 0.0], spin=[0.0, 0.0, 3.0], mu=0.3, kappa=0.8) | bad
    try:
        slow = _array_path(monkeypatch, ball, **kw)
    except (TypeError, ValueError) as err:
        with pytest.raises(type(err)) as fast:
            solve_sphere(ball, **kw)
        assert str(fast.value) == str(err)
    else:
        assert_same(solve_sphere(ball, **kw), slow)


def _pair_array_path(monkeypatch, *args, **kwargs):
    return array_path(monkeypatch, _fast_sphere, "pair_impact", solve_pair, *args, **kwargs)


@pytest.mark.parametrize("given", ["normal", "centres"])
@pytest.mark.slow
def test_pairs_bit_for_bit(given, monkeypatch):
    b1 = Body.solid_sphere(mass=0.17, radius=0.028575)
    b2 = Body(mass=0.3, radius=0.04, gyration=0.02)
    n, vs, v, w, mu, kappa = random_sphere_cases(200, seed=31)
    rng = np.random.default_rng(32)
    regimes = set()
    for i in range(len(mu)):
        v2, w2 = rng.normal(0, 1, 3), rng.normal(0, 20, 3)
        v2 -= np.dot(v2, n[i]) * n[i]  # across the normal only
        if np.array_equal(n[i], [0.0, 1.0, 0.0]) and not w[i].any():
            v2, w2 = np.zeros(3), np.zeros(3)  # head on, no spin: no slip at all
        where = dict(normal=tuple(n[i]))
        if given == "centres":
            c2 = rng.normal(0, 1, 3)
            where = dict(centres=(list(c2 + (b1.radius + b2.radius) * n[i]), c2))
        kw = dict(
            velocity1=list(v[i] - vs[i]),
            spin1=tuple(w[i]),
            velocity2=v2,
            spin2=w2,
            mu=float(mu[i]),
            kappa=float(kappa[i]),
            **where,
        )
        fast = solve_pair(b1, b2, **kw)
        assert_same(fast, _pair_array_path(monkeypatch, b1, b2, **kw))
        regimes.add(str(fast.regime))
    assert len(regimes) == 5


@pytest.mark.parametrize(
    "bad",
    [
        dict(normal=(0.0, 0.0, 0.0)),
        dict(normal=None),
        dict(centres=([0, 0, 0], [0, 0, 0.01])),
        dict(centres=([0, 0, 0], [0, 0, 1.0]), normal=None),
        dict(velocity1=[0.0, 0.0, 1.0]),
        dict(mu=-1.0),
        dict(spin2=[1.0, 2.0]),
    ],
)
def test_pair_errors_are_the_array_paths(bad, monkeypatch):
    ball = Body.solid_sphere(mass=0.17, radius=0.028575)
    kw = (
        dict(
            velocity1=[0.0, 0.0, -2.0],
            spin1=[0.0, 30.0, 0.0],
            velocity2=[0, 0, 0],
            spin2=[0, 0, 0],
            normal=[0, 0, 1],
            mu=0.06,
            kappa=0.93,
        )
        | bad
    )
    try:
        slow = _pair_array_path(monkeypatch, ball, ball, **kw)
    except (TypeError, ValueError) as err:
        with pytest.raises(type(err)) as fast:
            solve_pair(ball, ball, **kw)
        assert str(fast.value) == str(err)
    else:
        assert_same(solve_pair(ball, ball, **kw), slow)
