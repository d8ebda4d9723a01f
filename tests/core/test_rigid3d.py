"""The integration of a turning slip in ``spinimpact.core.scalar_rigid``: its order, its
precision against a tighter run, and the two places where a plain integration in the
normal impulse went wrong or crawled (a stop near the stick boundary, a slip that passes
close to zero without stopping)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from spinimpact.core import rigid3d, rigid_slide, scalar_rigid

from tests.rigid_reference import reference_impact


def _random(n: int, seed: int):
    rng = np.random.default_rng(seed)
    a = rng.normal(size=(n, 3, 3))
    w = a @ np.swapaxes(a, 1, 2) + 0.05 * np.eye(3)
    v = rng.normal(size=(n, 3))
    v[:, 2] = -np.abs(v[:, 2]) - 0.05
    return w, v, rng.uniform(0.05, 1.2, n), rng.uniform(0.0, 1.0, n)


def _one(w, v, mu, kappa, law, rtol=rigid3d.RTOL):
    args = (w[0, 0], w[0, 1], w[0, 2], w[1, 1], w[1, 2], w[2, 2], *v, mu, kappa)
    return scalar_rigid.rigid_impact(*args, law, rtol, math.inf)


def test_the_generated_step_is_of_eighth_order():
    # fixed steps over the same stretch of a turning slip: halving the step divides the
    # error by about 2^8 = 256 while it stays above rounding
    w = np.array([2.0, 0.3, 0.4, 1.2, -0.5, 1.5])
    c = np.array([0.8, -0.6, -1.0, 0.0, 0.0])

    def run(steps, span=2.0):
        z, out, k = np.zeros(4), np.empty(4), np.empty((15, 4))
        for _ in range(steps):
            rigid_slide._slide_rate(w, 0.6, c, z, k, 0)
            rigid_slide._step(w, 0.6, c, z, span / steps, k, out)
            z[:] = out
        return z

    exact = run(2000)
    errors = [np.abs(run(n) - exact).max() for n in (3, 6, 12)]
    ratios = [errors[0] / errors[1], errors[1] / errors[2]]
    assert all(150 < r < 400 for r in ratios), (errors, ratios)


@pytest.mark.parametrize("law", ["newton", "poisson", "energetic"])
def test_the_default_precision_holds_against_a_run_a_hundred_times_tighter(law):
    # measured on 10,000 such cases: at most 3.6e-13 of the speed scale
    pytest.importorskip("numba")
    w, v, mu, kappa = _random(3000, 3)
    loose = rigid3d.contact_impact(w, v, mu, kappa, law)
    tight = rigid3d.contact_impact(w, v, mu, kappa, law, rtol=1e-15)
    speed = np.linalg.norm(v, axis=1)
    moved = np.einsum("nij,nj->ni", w, loose.impulse - tight.impulse)
    assert (np.abs(loose.velocity - tight.velocity).max(-1) / speed).max() <= 1e-12
    assert (np.abs(moved).max(-1) / speed).max() <= 1e-12
    assert np.array_equal(loose.sequence, tight.sequence)


def test_a_stop_near_the_stick_boundary_settles_in_few_steps():
    # |W_tt^-1 W_tn| is 9.3e-4 below mu: the slip's direction settles fast, its speed
    # falls slowly, and an explicit integration in the normal impulse took 4,239 steps
    w = np.array([[18.25016255, 1.25042084, 4.79814457],
                  [1.25042084, 13.54961562, -5.13304844],
                  [4.79814457, -5.13304844, 7.86703223]])  # fmt: skip
    v = np.array([-12.05610311, 10.75917763, -9.9967223])
    c = np.linalg.solve(w[:2, :2], w[:2, 2])
    assert -1e-3 < np.linalg.norm(c) - 0.5 < 0.0
    got = _one(w, v, 0.5, 0.8, 2)
    ref = reference_impact(w, v, 0.5, 0.8, "stronge")
    assert scalar_rigid.SEQUENCES[got[12]] == "slide-stick" and ref.sequence == ("slide", "stick")
    assert got[13] < 150
    speed = np.linalg.norm(v)
    assert np.abs(np.array(got[:3]) - ref.velocity).max() <= 1e-10 * speed


def test_a_slip_passing_close_to_zero_is_not_taken_for_a_stop():
    # the slip comes within 1e-11 of the speed scale of zero along a direction that
    # repels it, swings past and goes on: one slide, as the reference finds
    w = np.array([[3.3157710333293875, -0.7792465187599071, 0.12784483303200964],
                  [-0.7792465187599071, 1.3379485604007133, 1.0014253699960352],
                  [0.12784483303200964, 1.0014253699960352, 1.1154235016531653]])  # fmt: skip
    v = np.array([-0.19960946076112507, -0.677672007178726, -0.6691064067475041])
    mu, kappa = 0.5828729260447647, 0.44414126927989617
    got = _one(w, v, mu, kappa, 1)
    ref = reference_impact(w, v, mu, kappa, "poisson", rtol=1e-13)
    assert scalar_rigid.SEQUENCES[got[12]] == "slide" and ref.sequence == ("slide",)
    assert np.abs(np.array(got[:3]) - ref.velocity).max() <= 1e-12 * np.linalg.norm(v)


@pytest.mark.parametrize("law", ["newton", "poisson", "energetic"])
def test_friction_work_in_compression_is_the_work_up_to_the_compression_impulse(law):
    # the split by phase against a run stopped part-way at p_c, whose friction work
    # is all of it done by then
    pytest.importorskip("numba")
    w, v, mu, kappa = _random(400, 11)
    whole = rigid3d.contact_impact(w, v, mu, kappa, law)
    part = rigid3d.contact_impact(w, v, mu, kappa, law, p_max=whole.compression_impulse)
    by_then = part.work_compression_tangential + part.work_restitution_tangential
    scale = np.linalg.norm(v, axis=1) ** 2 / np.linalg.eigvalsh(w)[:, -1]
    assert np.all(whole.work_compression_tangential <= 0.0)
    assert np.all(whole.work_restitution_tangential <= 1e-15 * scale)
    assert np.abs(by_then - whole.work_compression_tangential).max() <= 1e-11 * scale.max()
    assert np.any(whole.work_restitution_tangential < -1e-3 * scale)
