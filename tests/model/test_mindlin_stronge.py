"""Where the time-domain model and Stronge's impulse-space model are the same system.

With a linear elastic normal spring (kappa = 1) and a constant tangential stiffness ratio,
simulate(..., tangential=Mindlin(stiffness_ratio=r)) integrates in time the two-spring
contact that spinimpact.Stronge(stiffness_ratio=r) solves piecewise in closed form; the two
routes are independent, so their agreement checks both."""

import numpy as np
import pytest

from spinimpact import Body, Stronge, solve
from spinimpact.dynamics import LinearContact, Mindlin, simulate


def test_linear_elastic_time_domain_equals_stronge():
    ball = Body.solid_sphere(mass=0.01, radius=0.01)
    rng = np.random.default_rng(11)
    switches = set()
    for _ in range(40):
        vx, vy = rng.uniform(-3, 3), -rng.uniform(0.5, 3)
        omega, mu, ratio = rng.uniform(-300, 300), rng.uniform(0.05, 0.6), rng.uniform(0.3, 2)
        imp = solve(
            ball, vx, vy, omega, mu=mu, kappa=1.0, tangential=Stronge(stiffness_ratio=ratio)
        )
        sim = simulate(
            ball,
            vx,
            vy,
            omega,
            mu=mu,
            contact=LinearContact(1e6),
            tangential=Mindlin(stiffness_ratio=ratio),
            rtol=1e-12,
        )
        scale = abs(vx) + abs(vy) + abs(0.01 * omega)
        assert float(sim.after.vx) == pytest.approx(float(imp.after.vx), abs=1e-9 * scale)
        assert float(sim.after.vy) == pytest.approx(float(imp.after.vy), abs=1e-9 * scale)
        assert 0.01 * float(sim.after.omega) == pytest.approx(
            0.01 * float(imp.after.omega), abs=1e-9 * scale
        )
        switches.add(sim.switches)
    assert {0, 1, 2} <= switches  # full stick, one switch, and slip-stick-slip all covered


def test_hertz_normal_force_changes_the_answer():
    """Theory says they differ with Hertz's force (the normal motion is not harmonic, so the
    tangential spring turns through another phase): at this sticking incidence (6 degrees,
    elastic) e_t is 0.853 in time with Hertz and 0.789 with Stronge's linear springs."""
    from spinimpact.dynamics import HertzContact

    ball = Body.solid_sphere(mass=2.618e-4, radius=0.0025)
    law = HertzContact(3.8e11, 0.23, 0.0025)
    vx, vy = 0.4, -3.8
    sim = simulate(ball, vx, vy, 0.0, mu=0.092, contact=law, tangential=Mindlin())
    imp = solve(ball, vx, vy, 0.0, mu=0.092, kappa=1.0, tangential=Stronge(poisson_ratio=0.23))
    assert float(sim.after.vx) / vx == pytest.approx(0.853, abs=5e-4)
    assert float(imp.after.vx) / vx == pytest.approx(0.789, abs=5e-4)
