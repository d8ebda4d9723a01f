"""Compact one-line reprs of the time-domain results and of CompliantSphereImpact: the
rebound and a few scalars, never the series or NumPy's ``np.float64(...)`` wrappers."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Body, Walton, solve_sphere
from spinimpact.dynamics import HertzContact, Mindlin, simulate

BALL = Body.solid_sphere(mass=2.618e-4, radius=0.0025)
HERTZ = HertzContact(youngs_modulus=3.8e11, poisson_ratio=0.23, radius=0.0025)


def _one_line(text: str) -> None:
    assert "\n" not in text and len(text) < 400, text
    assert "array(" not in text and "np.float64" not in text, text


@pytest.mark.parametrize("tangential", [None, Mindlin()])
def test_simulation_repr_is_one_line_with_the_rebound(tangential: Mindlin | None) -> None:
    sim = simulate(BALL, 1.334, -3.665, 0.0, mu=0.092, contact=HERTZ, tangential=tangential)
    text = repr(sim)
    _one_line(text)
    name = "TangentialSimulation" if tangential is not None else "Simulation"
    assert text.startswith(f"<{name} (")
    assert f"vx={float(sim.after.vx):.6g} m/s" in text
    assert f"omega={float(sim.after.omega):.6g} rad/s" in text
    assert f"contact {sim.contact_duration:.6g} s, {sim.t.size} samples" in text
    assert sim.t.size > 100  # the series it leaves out are long
    if tangential is not None:
        assert f"beta={sim.tangential_restitution:.6g}" in text
        assert f"{sim.switches} stick/slip switches" in text
        assert str(sim) == text


def test_compliant_sphere_repr_scalar_and_array() -> None:
    ball = Body.solid_sphere(mass=0.057, radius=0.033)
    law = Walton(0.3)
    one = solve_sphere(ball, [1.0, -3.0, 0.5], [0.0, 0.0, 0.0], mu=0.3, kappa=0.8,
                       tangential=law)  # fmt: skip
    text = repr(one)
    _one_line(text)
    v = ", ".join(f"{x:.6g}" for x in one.after.velocity)
    assert text == (
        f"<CompliantSphereImpact {one.regime} (Walton(beta0=0.3)): after v=({v}) m/s, "
        f"spin=({', '.join(f'{x:.6g}' for x in one.after.spin)}) rad/s; "
        f"beta={one.tangential_restitution:.6g}>"
    )
    rng = np.random.default_rng(3)
    v = np.column_stack([rng.uniform(-3, 3, 50), rng.uniform(-5, -0.5, 50), np.zeros(50)])
    many = solve_sphere(ball, v, [0.0, 0.0, 10.0], mu=0.3, kappa=0.8, tangential=law)
    text = repr(many)
    _one_line(text)
    names, counts = np.unique(many.regime, return_counts=True)
    assert text.startswith("<CompliantSphereImpact of shape (50,) (Walton(beta0=0.3)): ")
    for name, count in zip(names, counts, strict=True):
        assert f"{name}: {count}" in text
    assert sum(counts) == 50
