"""The fused path of ``solve_sphere``/``solve_pair`` equals their NumPy path bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Body, Surface, solve_pair, solve_sphere
from spinimpact.model import _fused_sphere

from tests.same_result import array_path, assert_same

pytest.importorskip("numba")

N = 4000


def _numpy_path(monkeypatch, call, hook="sphere_impact"):
    """``call()`` with the fused path switched off (the NumPy kernels)."""
    return array_path(monkeypatch, _fused_sphere, hook, call)


def _incidences(rng, n=N):
    v = rng.normal(size=(n, 3)) * 5
    v[:, 1] = -np.abs(v[:, 1]) - 0.05
    w = rng.normal(size=(n, 3)) * 60
    w[::7] = 0.0  # no spin
    v[::11, [0, 2]] = 0.0  # head on
    mu = rng.uniform(0, 1, n)
    mu[::5] = 0.0  # frictionless
    kappa = rng.uniform(0, 1, n)
    kappa[::13] = 0.0
    kappa[::17] = 1.0
    return v, w, mu, kappa


@pytest.mark.parametrize("moving", [False, True])
def test_sphere_fused_equals_numpy(monkeypatch, moving):
    rng = np.random.default_rng(3)
    v, w, mu, kappa = _incidences(rng)
    ball = Body.spherical_shell(mass=rng.uniform(0.05, 2, N), radius=rng.uniform(0.01, 0.2, N))
    surface = None
    if moving:  # a tilted, moving plane (a racket): every row its own
        normal = np.column_stack([rng.normal(0, 0.2, N), np.ones(N), rng.normal(0, 0.2, N)])
        surface = Surface(normal=normal, velocity=rng.normal(size=(N, 3)))
        v = v - 20.0 * surface.normal  # approaches it
    fast = solve_sphere(ball, v, w, mu=mu, kappa=kappa, surface=surface)
    slow = _numpy_path(monkeypatch, lambda: solve_sphere(ball, v, w, mu=mu, kappa=kappa,
                                                          surface=surface))  # fmt: skip
    assert_same(fast, slow)
    assert set(np.unique(fast.regime)) >= {"slip", "stick-compression", "stick-restitution"}


def test_sphere_fused_broadcasts_and_keeps_inputs_writable(monkeypatch):
    ball = Body.solid_sphere(mass=0.5, radius=0.1)
    v = np.array([[1.0, -2.0, 0.5], [0.0, -1.0, 0.0], [3.0, -0.5, -1.0]])
    w = np.array([0.0, 0.0, 40.0])
    fast = solve_sphere(ball, v, w, mu=0.4, kappa=[0.9, 0.5, 0.1])
    slow = _numpy_path(monkeypatch, lambda: solve_sphere(ball, v, w, mu=0.4,
                                                          kappa=[0.9, 0.5, 0.1]))  # fmt: skip
    assert_same(fast, slow)
    assert v.flags.writeable and w.flags.writeable
    v[0, 0] = 99.0  # the result holds its own copy of the inputs
    assert fast.before.vx[0] == 1.0


def test_sphere_refusals_unchanged():
    ball = Body.solid_sphere(mass=0.5, radius=0.1)
    with pytest.raises(ValueError, match="must approach the surface"):
        solve_sphere(ball, [[1.0, -1.0, 0.0], [1.0, 1.0, 0.0]], [0.0, 0.0, 0.0],
                     mu=0.3, kappa=0.5)  # fmt: skip
    with pytest.raises(ValueError, match="kappa"):
        solve_sphere(ball, [[1.0, -1.0, 0.0]] * 2, [0.0, 0.0, 0.0], mu=0.3, kappa=[0.5, 1.5])


def test_sphere_callable_kappa_takes_numpy_path(monkeypatch):
    ball = Body.solid_sphere(mass=0.5, radius=0.1)
    v = np.array([[1.0, -2.0, 0.5], [0.0, -1.0, 0.0]])

    def model(speed):
        return 0.9 - 0.05 * speed

    fast = solve_sphere(ball, v, [0.0, 0.0, 10.0], mu=0.3, kappa=model)
    slow = _numpy_path(monkeypatch, lambda: solve_sphere(ball, v, [0.0, 0.0, 10.0], mu=0.3,
                                                          kappa=model))  # fmt: skip
    assert_same(fast, slow)


def test_pair_fused_equals_numpy(monkeypatch):
    rng = np.random.default_rng(5)
    v1, w1, mu, kappa = _incidences(rng)
    v2 = rng.normal(size=(N, 3))
    v2[:, 1] = np.abs(v2[:, 1])  # towards ball 1, or at rest along the normal
    w2 = rng.normal(size=(N, 3)) * 30
    v2[::9] = 0.0  # a ball at rest: the angle between paths is NaN where ball 1 stops too
    w2[::9] = 0.0
    ball1 = Body.solid_sphere(mass=rng.uniform(0.1, 1, N), radius=0.03)
    ball2 = Body.spherical_shell(mass=0.2, radius=rng.uniform(0.02, 0.05, N))
    normal = np.array([0.0, 1.0, 0.0])
    fast = solve_pair(ball1, ball2, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2,
                      normal=normal, mu=mu, kappa=kappa)  # fmt: skip
    slow = _numpy_path(monkeypatch, lambda: solve_pair(
        ball1, ball2, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, normal=normal, mu=mu,
        kappa=kappa), "pair_impact")  # fmt: skip
    assert_same(fast, slow)


def test_pair_refusal_unchanged():
    ball = Body.solid_sphere(mass=0.2, radius=0.03)
    with pytest.raises(ValueError, match="must approach each other"):
        solve_pair(ball, ball, velocity1=[[0.0, 1.0, 0.0]] * 2, spin1=[0, 0, 0],
                   velocity2=[0, 0, 0], spin2=[0, 0, 0], normal=[0, 1, 0], mu=0.2,
                   kappa=0.9)  # fmt: skip
