"""The Hertz-Mindlin-Deresiewicz impact of spinimpact.core.mdr (method of dimensionality
reduction): resolution, limits, the independent no-slip rule, energy, arrays."""

import numpy as np
import pytest

from spinimpact.core.mdr import (
    HERTZ,
    hunt_crossley_damping,
    mdr_slip,
    mdr_trace,
    normal_history,
    spring_positions,
    spring_update,
)
from spinimpact.core.tangential import integrate_tangential, mindlin_stiffness_ratio

R23 = float(mindlin_stiffness_ratio(0.23))


def _random(n, seed):
    rng = np.random.default_rng(seed)
    return (rng.uniform(-3, 3, n), -rng.uniform(0.5, 2, n), rng.choice([3.5, 2.0, 1.4], n),
            rng.uniform(0.05, 0.8, n), rng.choice([1.0, 0.9, 0.6], n))  # fmt: skip


@pytest.mark.slow
def test_the_default_resolution_is_converged():
    """Defaults (256 springs, 2048 steps) against four times the springs and the steps:
    within 1e-5 of |v_n| (measured 2.2e-6 on these 40 impacts) and the gap falls as the
    resolution grows (3.0e-5 at a quarter of each)."""
    slip, vy, zeta, mu, kappa = _random(40, 3)
    a, _ = mdr_slip(slip, vy, zeta, mu, kappa, R23, springs=64, steps=512)
    b, _ = mdr_slip(slip, vy, zeta, mu, kappa, R23)
    c, _ = mdr_slip(slip, vy, zeta, mu, kappa, R23, springs=1024, steps=8192)
    coarse, fine = np.max(np.abs(a - c) / -vy), np.max(np.abs(b - c) / -vy)
    assert fine < 1e-5
    assert fine < coarse / 10


@pytest.mark.parametrize("kappa", [1.0, 0.8])
@pytest.mark.parametrize("u0", [0.3, -1.0])
@pytest.mark.slow
def test_no_slip_limit_is_the_history_rule(u0, kappa):
    """mu -> infinity: the springs never slip but at the receding edge; the event-driven
    rule F = F_load(delta) + k_t (xi - xi_load(delta)) (integrate_tangential,
    spring="history", DOP853) is the same physics by another route."""
    a = hunt_crossley_damping(kappa)
    run = integrate_tangential(1.0, 1.0, 1 / 2.5, 1e6, u0, -1.0, 0.0, stiffness=HERTZ,
                               exponent=1.5, alpha=a / 1.5, stiffness_ratio=R23,
                               time_scale=3.0, spring="history", rtol=1e-12)  # fmt: skip
    history = run.vx[-1] + run.omega[-1]
    gaps = [abs(float(mdr_slip(u0, -1.0, 3.5, 1e6, kappa, R23, springs=sp, steps=st)[0])
                - history) for sp, st in ((256, 2048), (1024, 16384))]  # fmt: skip
    assert gaps[1] < 1e-5 * abs(u0) and gaps[1] < gaps[0]  # measured <= 2.3e-6 |u0|


def test_sliding_throughout_is_coulomb_over_the_whole_impulse():
    slip, vy, zeta, mu, kappa = 2.0, -1.0, 3.5, 0.1, 0.9
    out, stuck = mdr_slip(slip, vy, zeta, mu, kappa, R23)
    assert not stuck
    assert float(out) == pytest.approx(slip - (1 + kappa) * zeta * mu, abs=2e-5)


@pytest.mark.slow
def test_rigid_limit():
    """A stiff tangential contact sticks as the rigid law does (slip after 0) with an error
    that falls with the stiffness ratio."""
    gaps = []
    for r, steps in ((10.0, 4096), (1e3, 32768)):
        out, stuck = mdr_slip(0.5, -1.0, 3.5, 0.3, 1.0, r, steps=steps)
        assert stuck
        gaps.append(abs(float(out)))
    assert gaps[1] < gaps[0] / 5
    assert gaps[1] < 0.3 * (3.5 / 1e3) ** 0.5  # the stuck spring's amplitude, mu sqrt(zeta/r)


def test_trivial_cases_and_arrays():
    out, stuck = mdr_slip([0.0, 1.0, -1.0], -2.0, 3.5, [0.4, 0.0, 0.4], 1.0, R23)
    assert out[0] == 0.0 and stuck[0]
    assert out[1] == 1.0 and not stuck[1]  # frictionless: unchanged
    slip, vy, zeta, mu, kappa = _random(12, 5)
    together, held = mdr_slip(slip, vy, zeta, mu, kappa, R23, springs=32, steps=256)
    alone = [mdr_slip(*(x[i] for x in (slip, vy, zeta, mu, kappa)), R23, springs=32,
                      steps=256) for i in range(12)]  # fmt: skip
    assert together.tolist() == [float(a[0]) for a in alone]
    assert held.tolist() == [bool(a[1]) for a in alone]
    shaped, _ = mdr_slip(slip.reshape(3, 4), vy.reshape(3, 4), 3.5, 0.3, 1.0, R23, springs=16,
                         steps=128)  # fmt: skip
    assert shaped.shape == (3, 4)


def test_energy_never_rises_and_slip_dissipates_the_rest():
    tr = mdr_trace(0.4, -1.0, 3.5, 0.3, 1.0, R23)
    energy = tr.slip**2 / (2 * 3.5) + tr.spring_energy
    assert np.max(np.diff(energy)) < 1e-8 * energy[0]
    assert energy[0] - energy[-1] == pytest.approx(tr.dissipated[-1], rel=3e-3)
    assert tr.spring_energy[-1] == 0.0 and tr.tangential_force[-1] == 0.0
    # the stuck core shrinks to nothing and the contact ends sliding at its edge
    assert tr.stick_radius.max() > 0.5


def test_normal_history_and_damping():
    assert hunt_crossley_damping(1.0) == 0.0
    for kappa in (0.98, 0.6):
        hist = normal_history(kappa, 512)
        a = hunt_crossley_damping(kappa)
        assert hist.damping == a and hist.delta[0] == 0.0 and hist.force[-1] == 0.0
    with pytest.raises(ValueError, match="kappa"):
        hunt_crossley_damping(0.0)


def test_spring_update_is_coulomb_per_spring():
    s, held = spring_update(np.array([0.0, 0.5, -0.2]), 0.3, np.array([1.0, 0.6, 0.0]))
    assert s.tolist() == [0.3, 0.6, 0.0] and held.tolist() == [True, False, False]
    x = spring_positions(4.0, 4)
    assert x.tolist() == [0.25, 0.75, 1.25, 1.75]


def test_the_compiled_and_numpy_steps_agree():
    """core.mdr_kernel (Numba, springs added in order, bounds computed per step) against
    the NumPy steps (pairwise sums, tabulated bounds): rounding only."""
    pytest.importorskip("numba")
    slip, vy, zeta, mu, kappa = _random(30, 9)
    a, held_a = mdr_slip(slip, vy, zeta, mu, kappa, R23, springs=64, steps=512, engine="numpy")
    b, held_b = mdr_slip(slip, vy, zeta, mu, kappa, R23, springs=64, steps=512, engine="numba")
    assert np.max(np.abs(a - b) / -vy) < 1e-12
    assert held_a.tolist() == held_b.tolist()
    with pytest.raises(ValueError, match="engine must be 'auto', 'numba' or 'numpy', got 'c'"):
        mdr_slip(1.0, -1.0, 3.5, 0.3, 1.0, R23, engine="c")
