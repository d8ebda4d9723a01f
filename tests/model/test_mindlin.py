"""simulate(..., tangential=Mindlin()): the law, the result, the rigid limit, bad input."""

import math

import numpy as np
import pytest

from spinimpact import Body
from spinimpact.dynamics import (
    HertzContact,
    LinearContact,
    Mindlin,
    Simulation,
    TangentialSimulation,
    simulate,
)

BALL = Body.solid_sphere(mass=2.618e-4, radius=0.0025)
HERTZ = HertzContact(youngs_modulus=3.8e11, poisson_ratio=0.23, radius=0.0025)


def test_without_tangential_simulate_is_unchanged():
    plain = simulate(BALL, 1.0, -3.0, 20.0, mu=0.3, contact=HERTZ)
    assert type(plain) is Simulation
    again = simulate(BALL, 1.0, -3.0, 20.0, mu=0.3, contact=HERTZ, tangential=None)
    assert float(again.after.vx) == float(plain.after.vx)


@pytest.mark.parametrize("omega", [0.0, -300.0, 900.0])
@pytest.mark.slow
def test_stiff_tangential_spring_gives_todays_simulation(omega):
    """The rigid limit: a tangential spring 1e6 times stiffer than Mindlin's reproduces
    simulate() without tangential compliance (the paper's stick: F = 0) to 1e-5."""
    law = HertzContact.calibrated(
        youngs_modulus=3.8e11,
        poisson_ratio=0.23,
        radius=0.0025,
        kappa=0.9,
        mass=2.618e-4,
        speed=3.0,
    )
    plain = simulate(BALL, 0.8, -3.0, omega, mu=0.1, contact=law)
    stiff = simulate(
        BALL, 0.8, -3.0, omega, mu=0.1, contact=law, tangential=Mindlin(stiffness_ratio=1e6)
    )
    scale = 0.8 + 3.0 + abs(omega) * 0.0025
    for a, b in (
        (stiff.after.vx, plain.after.vx),
        (stiff.after.vy, plain.after.vy),
        (0.0025 * stiff.after.omega, 0.0025 * plain.after.omega),
    ):
        assert abs(float(a) - float(b)) < 1e-5 * scale


def test_result_fields_and_columns():
    sim = simulate(BALL, 1.334, -3.665, 0.0, mu=0.092, contact=HERTZ, tangential=Mindlin())
    assert isinstance(sim, TangentialSimulation)
    assert sim.stiffness_ratio == pytest.approx(2 * 0.77 / 1.77, rel=1e-15)
    assert sim.shape == sim.t.shape and sim.switches == 2
    cols = sim.columns()
    assert {"tangential_force", "spring_displacement", "slip", "energy", "after_vx"} <= set(cols)
    assert all(c.shape == sim.t.shape for c in cols.values())
    assert sim.to_dict()["tangential"] == {
        "law": "Mindlin",
        "poisson_ratio": None,
        "stiffness_ratio": None,
        "spring": "scaled",
    }
    # the impulse-momentum bookkeeping: vx+ - vx- = f/m
    assert float(sim.after.vx - sim.before.vx) == pytest.approx(
        sim.tangential_impulse / 2.618e-4, rel=1e-9
    )
    # grip: the slip reversed, so beta > 0 and the ball spins faster than the rigid law says
    assert sim.tangential_restitution > 0
    assert abs(float(sim.after.omega)) > abs(float(sim.rigid().after.omega))
    with pytest.raises(TypeError):
        sim[0]


def test_linear_contact_takes_a_stiffness_ratio():
    law = LinearContact.calibrated(stiffness=1e7, kappa=0.8, mass=2.618e-4)
    sim = simulate(
        BALL, 0.5, -2.0, 0.0, mu=0.2, contact=law, tangential=Mindlin(stiffness_ratio=0.8)
    )
    assert sim.newton_restitution == pytest.approx(0.8, abs=1e-6)
    with pytest.raises(ValueError, match="poisson_ratio or stiffness_ratio"):
        simulate(BALL, 0.5, -2.0, 0.0, mu=0.2, contact=law, tangential=Mindlin())


def test_bad_input():
    with pytest.raises(ValueError, match="poisson_ratio must be in"):
        Mindlin(poisson_ratio=0.7)
    with pytest.raises(ValueError, match="stiffness_ratio must be in"):
        Mindlin(stiffness_ratio=0.0)
    with pytest.raises(ValueError, match="not both"):
        Mindlin(poisson_ratio=0.3, stiffness_ratio=1.0)
    with pytest.raises(TypeError):
        Mindlin(poisson_ratio="0.3")
    with pytest.raises(ValueError, match="spring must be one of"):
        Mindlin(spring="plastic")
    with pytest.raises(TypeError, match="spring must be one of"):
        Mindlin(spring=1)
    with pytest.raises(TypeError, match="tangential must be a Mindlin law"):
        simulate(BALL, 1.0, -3.0, 0.0, mu=0.1, contact=HERTZ, tangential="mindlin")
    with pytest.raises(ValueError, match="vy"):
        simulate(BALL, 1.0, 3.0, 0.0, mu=0.1, contact=HERTZ, tangential=Mindlin())
    with pytest.raises(ValueError, match="single number"):
        simulate(BALL, [1.0, 2.0], -3.0, 0.0, mu=0.1, contact=HERTZ, tangential=Mindlin())


def test_energy_series_never_increases():
    sim = simulate(BALL, 1.0, -3.0, 400.0, mu=0.2, contact=HERTZ, tangential=Mindlin())
    assert np.diff(sim.energy).max() <= 1e-8 * sim.energy[0]
    assert sim.dissipated_energy >= 0
    assert math.isfinite(sim.tangential_restitution)
