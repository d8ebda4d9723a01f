"""Compact one-line reprs of the time-domain results and of CompliantSphereImpact: the
rebound and a few scalars, never the series or NumPy's ``np.float64(...)`` wrappers."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Body, Walton, solve_pair, solve_sphere
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


def _xyz(values) -> str:
    return "(" + ", ".join(f"{float(x) + 0.0:.6g}" for x in values) + ")"


@pytest.mark.parametrize("law", [None, Walton(0.3)])
def test_sphere_reprs_scalar_and_array(law: Walton | None) -> None:
    ball = Body.solid_sphere(mass=0.057, radius=0.033)
    name = "SphereImpact" if law is None else "CompliantSphereImpact (Walton(beta0=0.3))"
    one = solve_sphere(ball, [1.0, -3.0, 0.5], [0.0, 0.0, 0.0], mu=0.3, kappa=0.8,
                       tangential=law)  # fmt: skip
    text = repr(one)
    _one_line(text)
    tail = (f"dissipated {one.dissipated_energy:.6g} J" if law is None
            else f"beta={one.tangential_restitution:.6g}")  # fmt: skip
    assert text == (
        f"<{name} {one.regime}: after v={_xyz(one.after.velocity)} m/s, "
        f"spin={_xyz(one.after.spin)} rad/s; {tail}>"
    )
    if law is not None:  # beta0 = 0.3: the slip (1, 0, 0.5) leaves as -0.3 of itself
        assert "v=(0.628571, 2.4, 0.314286) m/s" in text and "beta=0.3>" in text
    rng = np.random.default_rng(3)
    v = np.column_stack([rng.uniform(-3, 3, 50), rng.uniform(-5, -0.5, 50), np.zeros(50)])
    many = solve_sphere(ball, v, [0.0, 0.0, 10.0], mu=0.3, kappa=0.8, tangential=law)
    text = repr(many)
    _one_line(text)
    names, counts = np.unique(many.regime, return_counts=True)
    assert len(names) >= 2 and sum(counts) == 50
    kinds = ", ".join(f"{n}: {c}" for n, c in zip(names, counts, strict=True))
    assert text == f"<{name} of shape (50,): {kinds}>"


def test_pair_repr() -> None:
    ball = Body.solid_sphere(mass=0.17, radius=0.028)
    imp = solve_pair(ball, ball, velocity1=[2.0, 0, 0], spin1=[0, 0, -20.0],
                     velocity2=[0, 0, 0], spin2=[0, 0, 0], mu=0.1, kappa=0.9,
                     normal=[-1.0, 0, 1.0])  # fmt: skip
    text = repr(imp)
    _one_line(text)
    assert text == (
        f"<PairImpact {imp.regime}: after v1={_xyz(imp.after1.velocity)} m/s, "
        f"v2={_xyz(imp.after2.velocity)} m/s; dissipated {imp.dissipated_energy:.6g} J>"
    )
