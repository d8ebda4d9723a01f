"""The explorer's settings: text in, the library's solver called, messages keyed by field.

Nothing here needs Dash: the settings are plain Python over the library's public solvers.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import BALLS, GROUNDS, Body, PlanarBody, solve, solve_planar, solve_sphere
from spinimpact.explore import settings as st


def test_every_problem_solves_with_its_defaults():
    for kind in st.PROBLEMS:
        found = st.evaluate({"problem": kind})
        assert found.errors == {}, kind
        assert found.setting.problem == kind
        assert found.setting.command.startswith("spinimpact ")


def test_the_paper_body_is_the_solver_of_the_speed_angle_and_spin_typed():
    found = st.evaluate(
        {
            "problem": "paper",
            "speed": "18",
            "speed_unit": "km/h",
            "angle": "30",
            "spin": "-600",
            "mu": "0.3",
            "kappa": "0.6",
            "body": "solid-disk",
            "mass": "2",
            "radius": "0.05",
        }
    )
    speed = 18 / 3.6  # m/s
    vx, vy = speed * math.cos(math.radians(30)), -speed * math.sin(math.radians(30))
    omega = -600 * 2 * math.pi / 60
    expected = solve(Body.solid_disk(mass=2.0, radius=0.05), vx, vy, omega, mu=0.3, kappa=0.6)
    got = found.setting.result
    # the same solver on the same inputs up to the conversion's rounding (1e-15 of 5 m/s)
    np.testing.assert_allclose(
        [found.setting.inputs[k] for k in ("vx", "vy", "omega")], [vx, vy, omega], rtol=1e-14
    )
    np.testing.assert_allclose(float(got.after.vx), float(expected.after.vx), rtol=1e-13)
    assert str(got.regime) == str(expected.regime)


def test_a_ball_takes_its_preset_and_the_surface_its_mu_and_kappa():
    found = st.evaluate(
        {
            "problem": "sphere",
            "ball": "golf",
            "surface": "green",
            "speed": "10",
            "angle": "20",
            "spin": "2000",
            "spin_axis": "backspin",
        }
    )
    s = found.setting
    assert s.inputs["mu"] == GROUNDS["green"].mu and s.inputs["kappa"] == GROUNDS["green"].kappa
    velocity = 10 * np.array([math.cos(math.radians(20)), -math.sin(math.radians(20)), 0.0])
    spin = np.array([0.0, 0.0, 2000 * 2 * math.pi / 60])  # backspin along +x is about +z
    expected = solve_sphere(
        BALLS["golf"].body, velocity, spin, mu=GROUNDS["green"].mu, kappa=GROUNDS["green"].kappa
    )
    np.testing.assert_allclose(float(s.result.after.wz), float(expected.after.wz), rtol=1e-13)
    typed_mu = st.evaluate({"problem": "sphere", "surface": "green", "mu": "0.05"})
    assert typed_mu.setting.inputs["mu"] == 0.05  # a typed value wins over the preset


def test_a_rod_is_the_planar_solver_of_the_rod_preset():
    found = st.evaluate(
        {
            "problem": "planar",
            "shape": "rod",
            "length": "0.8",
            "orientation": "60",
            "speed": "3",
            "angle": "70",
            "spin": "0",
            "law": "newton",
            "mu": "0.4",
        }
    )
    rod = PlanarBody.rod(mass=1.0, length=0.8, angle=math.radians(60))
    v = 3 * np.array([math.cos(math.radians(70)), -math.sin(math.radians(70))])
    expected = solve_planar(rod, v[0], v[1], 0.0, mu=0.4, kappa=0.8, law="newton")
    np.testing.assert_allclose(
        float(found.setting.result.after.vx), float(expected.after.vx), rtol=1e-13
    )


@pytest.mark.parametrize(
    ("given", "field", "words"),
    [
        ({"mu": "-1"}, "mu", "mu must be >= 0"),
        ({"kappa": "1.5"}, "kappa", "kappa"),
        ({"speed": "abc"}, "speed", "speed must be a number, got 'abc'"),
        ({"speed": "-3"}, "speed", "speed must be >= 0"),
        ({"speed": "0"}, "speed", "--speed must be a finite number > 0"),
        ({"angle": "91"}, "angle", "--incidence-from-surface-deg must be in [0, 90]"),
        ({"mass": "0"}, "mass", "mass"),
        ({"problem": "sphere", "spin_axis": "sideways"}, "spin_axis", "--spin-axis"),
        ({"problem": "sphere", "ball": "custom", "radius": "nan"}, "radius", "radius"),
        ({"problem": "pendulum", "spin": "30"}, "spin", "must approach the surface"),
        ({"problem": "planar", "orientation": "200"}, "orientation", "orientation-deg"),
        ({"problem": "marble"}, "problem", "problem must be one of"),
        ({"problem": "pair", "normal": "1,2"}, "normal", "three finite numbers"),
        ({"problem": "pair", "normal": "1,0,0"}, "normal", "must approach each other"),
    ],
)
def test_a_bad_field_gets_the_librarys_message_beside_it(given, field, words):
    found = st.evaluate(given)
    assert found.setting is None
    assert list(found.errors) == [field]
    assert words in found.errors[field]


def test_the_address_round_trips():
    values = st.defaults("sphere") | {"speed": "12.5", "speed_unit": "mph", "spin_axis": "1,2,3"}
    query = st.to_query(values)
    back = st.from_query(query)
    assert {n: back[n] for n in st.relevant(values)} == {n: values[n] for n in st.relevant(values)}
    assert st.from_query("?problem=sphere&nonsense=1")["problem"] == "sphere"
    assert "body" not in st.relevant(values)  # a ball preset fills the body
    assert "body" in st.relevant(values | {"ball": "custom"})


@pytest.mark.slow
@pytest.mark.parametrize(
    "given",
    [
        {"problem": "paper", "speed": "7", "angle": "35", "spin": "-250", "body": "ring"},
        {
            "problem": "sphere",
            "ball": "tennis",
            "surface": "clay",
            "speed": "60",
            "speed_unit": "km/h",
            "angle": "17",
            "heading": "30",
            "spin": "2500",
            "spin_axis": "topspin+sidespin",
        },
        {"problem": "planar", "shape": "block", "speed": "2", "angle": "80", "law": "energetic"},
        {"problem": "pendulum", "spin": "-40", "law": "newton", "mu": "0.5"},
        {
            "problem": "pair",
            "ball": "soccer",
            "speed": "3",
            "heading": "10",
            "spin": "400",
            "spin_axis": "topspin",
            "normal": "-1,0,0.3",
        },
    ],
)
def test_the_command_line_shown_computes_the_same_impact(given):
    s = st.evaluate(given).setting
    args = [sys.executable, "-m", "spinimpact", *s.command.split()[1:]]
    out = json.loads(subprocess.run(args, capture_output=True, text=True, check=True).stdout)
    after = out["after1" if s.problem == "pair" else "after"]
    exact = s.result.after1 if s.problem == "pair" else s.result.after
    for key in ("vx", "vy", "omega") if "omega" in after else ("vx", "vy", "vz", "wx", "wz"):
        # the command converts the same text the same way: the same numbers to rounding
        np.testing.assert_allclose(after[key], float(getattr(exact, key)), rtol=1e-12, atol=1e-12)
