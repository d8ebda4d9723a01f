"""spinimpact.flight refuses a step that is large against the air's time scales: the limit
from the ball's energy bound, its message, the accuracy at the limit, the divergence it
prevents, and the bound on speed and spin it rests on."""

import math
import re

import numpy as np
import pytest

import spinimpact.model.flight as model_flight
from spinimpact import Stronge, Walton
from spinimpact.core.flight import STEP_FRACTION
from spinimpact.model.flight import AIR_DENSITY, GRAVITY, flight, launch
from spinimpact.model.presets import BALLS, Wall

CASES = {
    "serve": ("tennis", "hard", dict(speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0)),
    "lob": ("tennis", "clay", dict(speed=20.0, angle=50.0, height=1.0, spin_rpm=3000.0)),
    "drive": ("golf", "green", dict(speed=70.0, angle=12.0, height=0.05, spin_rpm=2800.0,
                                    spin_axis="backspin")),
    "smash": ("table-tennis", "table", dict(speed=30.0, angle=-10.0, height=0.5,
                                            spin_rpm=6000.0)),
    "free kick": ("soccer", "pitch", dict(speed=30.0, angle=25.0, height=0.11, spin_rpm=600.0,
                                          spin_axis="sidespin")),
}  # fmt: skip


def _limit(ball_name, speed, angle, height, spin_rpm=0.0, spin_axis="topspin"):
    """The largest step, computed here from the ball's numbers and the formulas."""
    b = BALLS[ball_name]
    m, r, rho_g = b.mass, b.radius, b.gyration
    j = m * rho_g**2
    area = math.pi * r * r
    k_d = AIR_DENSITY * area * b.drag_coefficient / (2 * m)
    k_l = AIR_DENSITY * area * r * b.lift_slope / (2 * m)
    k_s = AIR_DENSITY * area * r * r * b.spin_decay / (2 * j)
    v, w = launch(speed, angle, 0.0, spin_rpm, spin_axis)
    energy = v @ v + (j / m) * (w @ w) + 2 * GRAVITY * (height - r)  # per half mass
    v_max, w_max = math.sqrt(energy), math.sqrt(energy * m / j)
    scales = {"drag": 1 / (k_d * v_max), "spin decay": 1 / (k_s * v_max),
              "Magnus lift": 1 / (k_l * w_max)}  # fmt: skip
    which = min(scales, key=scales.get)
    return STEP_FRACTION * scales[which], which, v_max, w_max


def test_a_step_of_seconds_is_refused_with_the_limit_named():
    limit, which, _, _ = _limit("tennis", 30.0, 0.0, 1.0)
    text = (
        f"dt must be <= {limit:.3g} s for this flight, got 10.0: a step may be at most "
        f"{STEP_FRACTION:g} of the shortest time scale of the air, here that of {which}"
    )
    with pytest.raises(ValueError, match=re.escape(text)):
        flight("tennis", "hard", speed=30.0, angle=0.0, dt=10.0, max_bounces=3)
    assert 0.1 < limit < 0.2  # for the command line's default launch; its 5 ms passes


@pytest.mark.parametrize("name", list(CASES))
def test_the_limit_is_the_boundary(name):
    ball, ground, kw = CASES[name]
    limit = _limit(ball, **kw)[0]
    flight(ball, ground, **kw, dt=limit * (1 - 1e-12), max_bounces=1)
    with pytest.raises(ValueError, match="dt must be <="):
        flight(ball, ground, **kw, dt=limit * (1 + 1e-9), max_bounces=1)


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.slow
def test_at_the_limit_the_bounces_are_those_of_a_fine_step(name):
    ball, ground, kw = CASES[name]
    limit = _limit(ball, **kw)[0] * (1 - 1e-12)
    coarse = flight(ball, ground, **kw, dt=limit, max_bounces=3).bounces
    fine = flight(ball, ground, **kw, dt=limit / 16, max_bounces=3).bounces
    assert np.isfinite(coarse.time).all()
    for a, b, tol in ((coarse.position.x, fine.position.x, 1e-3),
                      (coarse.position.z, fine.position.z, 1e-3),
                      (coarse.time, fine.time, 1e-4),
                      (coarse.speed_after, fine.speed_after, 1e-4)):  # fmt: skip
        np.testing.assert_allclose(a, b, rtol=0, atol=tol)


def test_without_the_check_such_a_step_diverges(monkeypatch):
    """What the check prevents: the default launch with dt = 10 s bounces faster than any
    speed its energy allows."""
    v_max = _limit("tennis", 30.0, 0.0, 1.0)[2]
    monkeypatch.setattr(model_flight, "STEP_FRACTION", np.inf)
    f = flight("tennis", "hard", speed=30.0, angle=0.0, dt=10.0, max_bounces=3)
    assert np.nanmax(f.bounces.speed_before) > 100 * v_max


def test_without_air_the_step_is_unused_and_any_step_is_accepted():
    kw = dict(speed=30.0, angle=20.0, spin_rpm=3000.0, air_density=0.0, max_bounces=3)
    a, b = flight("tennis", "hard", dt=100.0, **kw), flight("tennis", "hard", **kw)
    np.testing.assert_array_equal(a.bounces.position.x, b.bounces.position.x)


@pytest.mark.slow
def test_no_ball_outruns_the_energy_bound_the_limit_rests_on():
    """|v| <= v_max and |w| <= w_max at every bounce and at the end, for scattered launches
    of every ball on every ground, with a wall; the bound the limit is computed from."""
    rng = np.random.default_rng(7)
    n = 40
    for ball in BALLS:
        for ground in ("hard", "green"):
            speed, angle = rng.uniform(0, 40, n), rng.uniform(-30, 60, n)
            height = rng.uniform(0.1, 3.0, n) + BALLS[ball].radius
            spin, direction = rng.uniform(-8000, 8000, n), rng.uniform(-40, 40, n)
            f = flight(ball, ground, speed=speed, angle=angle, height=height, spin_rpm=spin,
                       direction=direction, spin_axis=[0.2, 0.5, -1.0], max_bounces=5,
                       t_stop=4.0, wall=Wall(12.0, mu=0.6, kappa=0.9))  # fmt: skip
            b = BALLS[ball]
            ratio = b.gyration**2
            v0, w0 = launch(speed, angle, direction, spin, [0.2, 0.5, -1.0])
            e = np.sum(v0 * v0, -1) + ratio * np.sum(w0 * w0, -1) + 2 * GRAVITY * (
                height - b.radius)  # fmt: skip
            final = np.stack([f.final_velocity.x, f.final_velocity.y, f.final_velocity.z], -1)
            final_w = np.stack([f.final_spin.x, f.final_spin.y, f.final_spin.z], -1)
            states = [(s.velocity, s.spin) for s in (f.bounces.before, f.bounces.after)]
            for v, w in [*states, (final[:, None], final_w[:, None])]:
                total = np.sum(v**2, -1) + ratio * np.sum(w**2, -1)
                assert np.all(np.isnan(total) | (total <= e[:, None] * (1 + 1e-12)))
            assert np.any(f.bounces.surface == "wall")


@pytest.mark.parametrize(
    "law", [Walton(1.0), Walton(-1.0), Stronge(poisson_ratio=0.3), Stronge(poisson_ratio=-0.9)]
)
@pytest.mark.slow
def test_the_energy_bound_holds_with_compliance_laws(law):
    """A tangential law keeps |beta| <= 1, so no bounce gains energy either."""
    rng = np.random.default_rng(3)
    n, b = 40, BALLS["tennis"]
    speed, angle, spin = rng.uniform(0, 40, n), rng.uniform(-30, 60, n), rng.uniform(-8e3, 8e3, n)
    height = rng.uniform(0.1, 3.0, n) + b.radius
    f = flight(b, "hard", speed=speed, angle=angle, height=height, spin_rpm=spin,
               spin_axis=[0.2, 0.5, -1.0], max_bounces=5, t_stop=4.0, tangential=law)  # fmt: skip
    v0, w0 = launch(speed, angle, 0.0, spin, [0.2, 0.5, -1.0])
    ratio = b.gyration**2
    e = np.sum(v0 * v0, -1) + ratio * np.sum(w0 * w0, -1) + 2 * GRAVITY * (height - b.radius)
    after = f.bounces.after
    total = np.sum(after.velocity**2, -1) + ratio * np.sum(after.spin**2, -1)
    assert np.isfinite(total[:, 0]).sum() > n // 2
    assert np.all(np.isnan(total) | (total <= e[:, None] * (1 + 1e-12)))
