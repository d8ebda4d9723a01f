"""solve_pendulum(): a rigid pendulum on a fixed frictionless pivot striking the surface.

Its collision matrix has rank one, so the slip and the normal velocity of the contact
vanish together at the end of compression; the published result (Lubarda, J. Appl.
Mech. 77 (2010) 011006: the energetic coefficient is the geometric mean of Newton's and
Poisson's) then follows whenever the slip reverses.
"""

import math

import numpy as np
import pytest

from spinimpact import Pendulum, solve_pendulum


@pytest.fixture(scope="module")
def pendulums():
    rng = np.random.default_rng(41)
    n = 4000
    length = 10 ** rng.uniform(-1, 0.5, n)
    angle = rng.uniform(0.05, math.pi - 0.05, n)
    mass = 10 ** rng.uniform(-1, 1, n)
    omega = -np.sign(np.cos(angle)) * 10 ** rng.uniform(-1, 1, n)  # the tip moves down
    mu = rng.uniform(0.0, 2.0, n)
    kappa = rng.uniform(0.0, 1.0, n)
    return Pendulum.rod(mass=mass, length=length, angle=angle), omega, mu, kappa


@pytest.mark.parametrize("law", ["newton", "poisson", "energetic"])
def test_locks_exactly_when_the_cone_holds_the_contact(pendulums, law):
    p, omega, mu, kappa = pendulums
    imp = solve_pendulum(p, omega, mu=mu, kappa=kappa, law=law)
    ratio = np.abs(p.px / p.py)  # |b|/a: the friction needed to hold the contact
    holds = (ratio <= mu) & (mu > 0)
    locked = imp.regime == "locked"
    near = np.abs(ratio - mu) < 1e-9 * (1 + mu)  # rounding decides on the boundary
    assert np.array_equal(locked[~near], holds[~near])
    # a locked pendulum stops dead and has lost all its energy
    assert np.all(np.abs(imp.after.omega[locked]) <= 1e-12 * np.abs(omega[locked]))
    assert np.allclose(imp.dissipated_fraction[locked], 1.0, rtol=1e-12)
    # otherwise the slip reverses at the end of compression (or there is no friction)
    assert set(np.unique(imp.regime[~locked])) <= {"reverse-compression", "frictionless"}


@pytest.mark.parametrize("law", ["newton", "poisson", "energetic"])
def test_energetic_coefficient_is_the_geometric_mean(pendulums, law):
    """eta^2 = kappa_N kappa_P whenever the pendulum rebounds (the published result)."""
    p, omega, mu, kappa = pendulums
    imp = solve_pendulum(p, omega, mu=mu, kappa=kappa, law=law)
    rebounds = imp.regime != "locked"
    kn, kp, eta = imp.newton_restitution, imp.poisson_restitution, imp.energetic_restitution
    np.testing.assert_allclose(eta[rebounds] ** 2, (kn * kp)[rebounds], rtol=1e-9, atol=1e-12)
    own = {"newton": kn, "poisson": kp, "energetic": eta}[law]
    np.testing.assert_allclose(own[rebounds], kappa[rebounds], rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("law", ["newton", "poisson", "energetic"])
def test_no_law_creates_energy_for_a_pendulum(pendulums, law):
    p, omega, mu, kappa = pendulums
    imp = solve_pendulum(p, omega, mu=mu, kappa=kappa, law=law)
    assert not imp.creates_energy.any()
    # the energy balance: E- - E+ equals minus the works of the contact impulse
    balance = imp.kinetic_energy_before - imp.kinetic_energy_after
    np.testing.assert_allclose(balance, imp.dissipated_energy, rtol=0,
                               atol=1e-10 * np.max(imp.kinetic_energy_before))  # fmt: skip


def test_newton_rebound_spin_ignores_friction():
    """Rank one: Newton's v+ = -kappa v- fixes omega+ = -kappa omega- for any mu that
    lets the pendulum rebound."""
    p = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
    for mu in (0.0, 0.2, 0.5):
        imp = solve_pendulum(p, -2.0, mu=mu, kappa=0.8, law="newton")
        assert float(imp.after.omega) == pytest.approx(1.6, rel=1e-12)


def test_bad_pendulums_are_named():
    with pytest.raises(ValueError, match=r"py must be < 0"):
        Pendulum(1.0, 0.1, 0.0, -0.5, 0.3, 0.0)  # pivot level with the surface contact
    with pytest.raises(ValueError, match=r"inertia must be > 0"):
        Pendulum(1.0, 0.0, 0.0, -0.5, 0.3, -1.0)
    with pytest.raises(TypeError, match=r"pendulum must be a spinimpact.Pendulum"):
        solve_pendulum("rod", -1.0, mu=0.1, kappa=0.5)
    with pytest.raises(ValueError, match=r"must approach the surface"):
        solve_pendulum(Pendulum.rod(mass=1, length=1, angle=1.0), 2.0, mu=0.1, kappa=0.5)
