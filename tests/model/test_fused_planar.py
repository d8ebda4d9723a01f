"""The fused path of ``solve_planar``/``solve_pendulum`` equals their NumPy path bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar
from spinimpact.core.planar import LAWS
from spinimpact.model import _fused_planar

from tests.same_result import array_path, assert_same

pytest.importorskip("numba")

N = 4000


def _numpy_path(monkeypatch, call):
    """``call()`` with the fused path switched off (the NumPy kernels)."""
    return array_path(monkeypatch, _fused_planar, "planar_impact", call)


@pytest.mark.parametrize("law", LAWS)
def test_planar_fused_equals_numpy(monkeypatch, law):
    rng = np.random.default_rng(11)
    angle = rng.uniform(0.05, np.pi - 0.05, N)
    body = PlanarBody.rod(mass=rng.uniform(0.2, 3, N), length=0.5, angle=angle)
    vx = rng.normal(0, 2, N)
    vx[::9] = 0.0
    vy = -rng.uniform(0.2, 5, N)
    omega = rng.normal(0, 10, N)
    omega[::7] = 0.0
    approaching = vy + omega * body.rx < 0
    vx, vy, omega, mu = vx[approaching], vy[approaching], omega[approaching], None
    body = PlanarBody(body.mass[approaching], body.inertia[approaching],
                      body.rx[approaching], body.ry[approaching])  # fmt: skip
    n = vx.size
    mu = rng.uniform(0, 1.5, n)
    mu[::5] = 0.0
    kappa = rng.uniform(0, 1, n)
    kappa[::13] = 0.0
    kappa[::17] = 1.0
    fast = solve_planar(body, vx, vy, omega, mu=mu, kappa=kappa, law=law)
    slow = _numpy_path(monkeypatch, lambda: solve_planar(body, vx, vy, omega, mu=mu,
                                                          kappa=kappa, law=law))  # fmt: skip
    assert_same(fast, slow)
    assert len(np.unique(fast.regime)) >= 4


@pytest.mark.parametrize("law", LAWS)
def test_pendulum_fused_equals_numpy(monkeypatch, law):
    rng = np.random.default_rng(13)
    angle = rng.uniform(0.2, np.pi - 0.2, N)
    pendulum = Pendulum.rod(mass=rng.uniform(0.2, 3, N), length=1.0, angle=angle)
    omega = np.where(pendulum.px > 0, -1.0, 1.0) * rng.uniform(0.5, 8, N)  # towards it
    mu = rng.uniform(0, 1.5, N)
    mu[::5] = 0.0
    kappa = rng.uniform(0, 1, N)
    fast = solve_pendulum(pendulum, omega, mu=mu, kappa=kappa, law=law)
    slow = _numpy_path(monkeypatch, lambda: solve_pendulum(pendulum, omega, mu=mu,
                                                            kappa=kappa, law=law))  # fmt: skip
    assert_same(fast, slow)


def test_planar_broadcast_and_refusal_unchanged(monkeypatch):
    body = PlanarBody.rod(mass=1.0, length=0.5, angle=0.7)
    omega = np.array([0.0, 2.0, -3.0])
    fast = solve_planar(body, 0.5, -2.0, omega, mu=0.3, kappa=0.6)
    slow = _numpy_path(monkeypatch, lambda: solve_planar(body, 0.5, -2.0, omega, mu=0.3,
                                                          kappa=0.6))  # fmt: skip
    assert_same(fast, slow)
    assert omega.flags.writeable
    with pytest.raises(ValueError, match="must approach the surface"):
        solve_planar(body, 0.0, [-1.0, 1.0], 0.0, mu=0.3, kappa=0.5)
