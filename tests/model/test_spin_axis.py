"""Named spin axes and their combinations, and a Ball wherever a Body is accepted."""

from __future__ import annotations

import math

import numpy as np
import pytest

from spinimpact import BALLS, Body, solve, solve_pair, solve_sphere
from spinimpact.dynamics import HertzContact, simulate
from spinimpact.model.body import as_body
from spinimpact.model.flight import RPM, launch
from spinimpact.model.spin_axis import combine_axes, parse_spin_axis

AXES = {"topspin": np.array([0.0, 0.0, -1.0]), "backspin": np.array([0.0, 0.0, 1.0]),
        "sidespin": np.array([0.0, 1.0, 0.0])}  # fmt: skip


def test_one_name_is_its_axis_bit_for_bit():
    for name, axis in AXES.items():
        assert combine_axes(parse_spin_axis(name), AXES) is not None
        assert np.array_equal(combine_axes(parse_spin_axis(name), AXES), axis)


def test_a_combination_is_the_normalised_weighted_sum():
    halfway = combine_axes(parse_spin_axis("topspin+sidespin"), AXES)
    assert halfway == pytest.approx([0.0, math.sqrt(0.5), -math.sqrt(0.5)], abs=1e-15)
    weighted = combine_axes(parse_spin_axis("Topspin:0.8 + sidespin:0.2"), AXES)
    assert weighted == pytest.approx(np.array([0.0, 0.2, -0.8]) / math.hypot(0.2, 0.8), abs=1e-15)
    other_way = combine_axes(parse_spin_axis("sidespin:-1"), AXES)
    assert other_way == pytest.approx([0.0, -1.0, 0.0])


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("wobble", "spin_axis must be topspin, backspin, sidespin, a combination"),
        ("topspin+topspin", "spin_axis names topspin twice"),
        ("topspin:x", "the weight of topspin must be a finite number, got 'x'"),
        ("topspin:inf", "the weight of topspin must be a finite number"),
    ],
)
def test_bad_axes_are_named(text, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(")):
        parse_spin_axis(text)


def test_cancelling_weights_are_refused():
    with pytest.raises(ValueError, match="topspin\\+backspin has no direction"):
        combine_axes(parse_spin_axis("topspin+backspin"), AXES)


def test_flight_launch_takes_combinations():
    _, w = launch(10.0, 0.0, 30.0, spin_rpm=600.0, spin_axis="topspin:3+sidespin:4")
    d = math.radians(30.0)
    top = np.cross([0.0, 1.0, 0.0], [math.cos(d), 0.0, -math.sin(d)])
    expected = 600.0 * RPM * (3 * top + 4 * np.array([0.0, 1.0, 0.0])) / 5
    assert w == pytest.approx(expected, rel=1e-14)
    _, alone = launch(10.0, 0.0, 30.0, spin_rpm=600.0, spin_axis="topspin")
    assert np.array_equal(alone, 600.0 * RPM * top)  # the lone name as before


def test_a_ball_is_a_body_everywhere():
    ball = BALLS["tennis"]
    body = ball.body
    assert as_body(ball) == as_body(body) or as_body(ball).to_dict() == body.to_dict()
    a = solve(ball, 3.0, -4.0, 10.0, mu=0.6, kappa=0.8)
    b = solve(body, 3.0, -4.0, 10.0, mu=0.6, kappa=0.8)
    assert a.after.vx == b.after.vx and a.after.omega == b.after.omega
    s1 = solve_sphere(ball, [3.0, -4.0, 1.0], [0.0, 5.0, 10.0], mu=0.6, kappa=0.8)
    s2 = solve_sphere(body, [3.0, -4.0, 1.0], [0.0, 5.0, 10.0], mu=0.6, kappa=0.8)
    assert s1.after.vx == s2.after.vx and s1.after.wy == s2.after.wy
    kw = dict(velocity1=[1, 0, 0], spin1=[0, 0, 0], velocity2=[0, 0, 0], spin2=[0, 0, 0],
              normal=[-1, 0, 0], mu=0.1, kappa=0.9)  # fmt: skip
    p1 = solve_pair(ball, BALLS["golf"], **kw)
    p2 = solve_pair(body, BALLS["golf"].body, **kw)
    assert p1.after1.vx == p2.after1.vx
    law = HertzContact(youngs_modulus=2e9, poisson_ratio=0.35, radius=ball.radius, alpha=0.05)
    assert (
        simulate(ball, 1.0, -3.0, 20.0, mu=0.3, contact=law).after.vx
        == simulate(body, 1.0, -3.0, 20.0, mu=0.3, contact=law).after.vx
    )


@pytest.mark.parametrize("bad", ["tennis", 3.0, None])
def test_anything_else_is_a_type_error_naming_the_parameter(bad):
    with pytest.raises(TypeError, match="body must be a spinimpact.Body or a spinimpact.Ball"):
        solve_sphere(bad, [1, -1, 0], [0, 0, 0], mu=0.1, kappa=0.5)
    with pytest.raises(TypeError, match="ball2 must be a spinimpact.Body or a spinimpact.Ball"):
        solve_pair(Body.solid_sphere(mass=1, radius=0.1), bad, velocity1=[1, 0, 0],
                   spin1=[0, 0, 0], velocity2=[0, 0, 0], spin2=[0, 0, 0], normal=[-1, 0, 0],
                   mu=0.1, kappa=0.9)  # fmt: skip
