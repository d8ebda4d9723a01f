"""Properties of spinimpact.flight over random launches (hypothesis): no bounce creates
energy, the air only takes energy away between bounces, and many balls at once give each
ball's own numbers."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from spinimpact.model.flight import flight
from spinimpact.model.presets import BALLS, GROUNDS

#: Hypothesis flies a few hundred balls a test: run by `make test` only.
pytestmark = pytest.mark.slow

G = 9.80665
launches = st.fixed_dictionaries({
    "speed": st.floats(1.0, 60.0), "angle": st.floats(-60.0, 60.0),
    "direction": st.floats(-180.0, 180.0), "height": st.floats(0.0, 3.0),
    "spin_rpm": st.floats(-5000.0, 5000.0),
    "spin_axis": st.sampled_from(["topspin", "backspin", "sidespin", (1.0, 2.0, -0.5)]),
})  # fmt: skip


def _energy(ball, velocity, spin, height):
    inertia = ball.mass * ball.gyration**2
    return (0.5 * ball.mass * np.sum(velocity**2, -1) + 0.5 * inertia * np.sum(spin**2, -1)
            + ball.mass * G * height)  # fmt: skip


@settings(max_examples=25, deadline=None)
@given(launch=launches, name=st.sampled_from(sorted(BALLS)),
       ground=st.sampled_from(sorted(GROUNDS)))  # fmt: skip
def test_energy_never_rises(launch, name, ground):
    ball = BALLS[name]
    launch = {**launch, "height": ball.radius + launch["height"]}  # above the ground
    f = flight(ball, ground, max_bounces=3, **launch)
    b = f.bounces
    k = int(f.bounce_count)
    y = np.full(k, ball.radius)
    e_before = _energy(ball, b.before.velocity[:k], b.before.spin[:k], y)
    e_after = _energy(ball, b.after.velocity[:k], b.after.spin[:k], y)
    scale = e_before.max(initial=0.0)
    assert np.all(e_after <= e_before + 1e-12 * scale)  # the impact dissipates
    # between bounces the air only takes energy away
    e0 = _energy(ball, f.launch.velocity, f.launch.spin, launch["height"])
    arrivals = np.concatenate([[e0], e_after[:-1]]) if k else np.array([e0])
    assert np.all(e_before <= arrivals[: len(e_before)] + 1e-9 * max(scale, e0))


@settings(max_examples=10, deadline=None)
@given(st.lists(launches, min_size=2, max_size=4), st.sampled_from(sorted(GROUNDS)))
def test_many_balls_give_each_balls_numbers(launch_list, ground):
    launch_list = [{**d, "height": d["height"] + 0.05} for d in launch_list]  # above R
    columns = {k: [d[k] for d in launch_list] for k in ("speed", "angle", "direction",
                                                        "height", "spin_rpm")}  # fmt: skip
    many = flight("tennis", ground, max_bounces=2, spin_axis="topspin", **columns)
    for i, launch in enumerate(launch_list):
        one = flight("tennis", ground, max_bounces=2, **{**launch, "spin_axis": "topspin"})
        k = int(one.bounce_count)
        assert int(many.bounce_count[i]) == k
        np.testing.assert_array_equal(many.bounces.time[i, :k], one.bounces.time[:k])
        np.testing.assert_array_equal(many[i].final_position.array, one.final_position.array)
