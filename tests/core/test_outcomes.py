"""Rebound outcomes (backward, reversed spin, vertical, spinning, rolling):
the closed-form incidence conditions of spinimpact.core.outcomes against the
signs of the computed rebound velocities."""

import numpy as np
import pytest

from spinimpact import Body, solve

from tests.cases import random_cases


@pytest.fixture(scope="module")
def impacts():
    c = random_cases(20_000, seed=7)
    body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
    return solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"])


def test_flags_match_rebound_signs(impacts):
    b, a, o = impacts.before, impacts.after, impacts.outcome
    scale = np.abs(b.vx) + np.abs(b.vy) + np.abs(impacts.body.radius * b.omega)
    clear_x = np.abs(a.vx) > 1e-9 * scale  # away from the vertical-rebound edge
    clear_w = np.abs(impacts.body.radius * a.omega) > 1e-9 * scale
    assert np.array_equal(o.backward[clear_x], ((b.vx * a.vx) < 0)[clear_x])
    assert np.array_equal(o.reversed_spin[clear_w], ((b.omega * a.omega) < 0)[clear_w])
    assert not o.vertical[clear_x].any()
    assert o.spinning[clear_w].all()
    assert np.array_equal(o.rolling, impacts.slip_after == 0)
    # each flag occurs in the sample, both ways
    for flag in (o.backward, o.reversed_spin, o.rolling):
        assert 0 < flag.sum() < flag.size


BODY = Body.solid_sphere(mass=1.0, radius=0.1)  # zeta = 7/2


def test_non_spinning_vertical_rebound():
    """R omega- = (zeta - 1) vx- and |vx-| <= (1+kappa) mu |vy-|: leaves straight up, no spin."""
    vx = 1.0
    omega = 2.5 * vx / 0.1
    imp = solve(BODY, vx, -2.0, omega, mu=0.3, kappa=0.8)  # (1+kappa) mu |vy| = 1.08 >= 1
    assert imp.outcome.vertical and not imp.outcome.spinning
    assert abs(imp.after.vx) < 1e-15 and abs(imp.after.omega) < 1e-13
    assert not imp.outcome.backward and not imp.outcome.reversed_spin


def test_spinning_vertical_rebound():
    """Slip throughout and vx- = sign(u-)(1+kappa) mu |vy-|: straight up, still spinning."""
    mu, kappa, vy = 0.25, 0.6, -2.0
    vx = (1 + kappa) * mu * abs(vy)  # 0.8, with u- > 0
    omega = 200.0  # u- = 20.8 >> (1+kappa) zeta mu |vy| = 2.8
    imp = solve(BODY, vx, vy, omega, mu=mu, kappa=kappa)
    assert imp.regime == "slip"
    assert imp.outcome.vertical and imp.outcome.spinning
    assert abs(imp.after.vx) < 1e-15
    assert imp.after.omega == pytest.approx(omega - 2.5 * vx / 0.1)


def test_backward_rebound_with_backspin():
    """Stick: backward iff R omega-/vx- > zeta - 1 (the classic backspin bounce)."""
    for ratio, backward in ((2.4, False), (2.6, True)):
        imp = solve(BODY, 1.0, -5.0, ratio / 0.1, mu=0.9, kappa=0.5)
        assert imp.regime.startswith("stick")
        assert bool(imp.outcome.backward) is backward
        assert bool(imp.after.vx < 0) is backward


def test_backward_rebound_while_slipping():
    """Slip: backward iff sign(u-) = sign(vx-) and |vx-| < (1+kappa) mu |vy-|."""
    mu, kappa, vy = 0.2, 1.0, -10.0  # (1+kappa) mu |vy| = 4
    for vx, backward in ((3.9, True), (4.1, False)):
        imp = solve(BODY, vx, vy, 500.0, mu=mu, kappa=kappa)
        assert imp.regime == "slip"
        assert bool(imp.outcome.backward) is backward
