"""The ball and ground presets keep the numbers their sources give (docs/flight.md), and the
examples of docs/flight.md run and print what they show."""

import doctest
import math
from pathlib import Path

import pytest

from spinimpact.model.presets import BALLS, GROUNDS, Ball, Ground, thick_shell_gyration

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_the_examples_of_the_flight_page_run():
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    result = doctest.testfile(str(ROOT / "docs" / "flight.md"), module_relative=False,
                              optionflags=flags)  # fmt: skip
    assert result.attempted >= 5 and result.failed == 0


def test_balls_are_within_their_rules():
    tennis, tt, golf, soccer = (BALLS[k] for k in ("tennis", "table-tennis", "golf", "soccer"))
    assert 0.0560 <= tennis.mass <= 0.0594 and 0.06541 <= 2 * tennis.radius <= 0.06858  # ITF
    assert (tt.mass, 2 * tt.radius) == (0.0027, 0.040)  # ITTF
    assert golf.mass <= 0.04593 and 2 * golf.radius >= 0.04267  # Rules of Golf
    assert 0.68 <= 2 * math.pi * soccer.radius <= 0.70 and 0.410 <= soccer.mass <= 0.450
    assert tennis.drag_coefficient == 0.507  # Cross & Lindsey 2014
    # a thick shell lies between the thin shell (2/3) and the solid sphere (2/5)
    assert 0.4 < (tennis.gyration / tennis.radius) ** 2 < 2 / 3
    assert thick_shell_gyration(1.0, 1.0) == pytest.approx(math.sqrt(0.4), rel=1e-15)
    assert thick_shell_gyration(1.0, 1e-6) == pytest.approx(math.sqrt(2 / 3), rel=1e-5)


def test_the_golf_spin_decay_is_smits_and_smith_in_golf_units():
    # 0.0004 x speed (mph) x spin per second  ->  k_s = 0.0004 / 0.44704 per metre
    golf = BALLS["golf"]
    inertia = golf.mass * golf.gyration**2
    k_s = 1.225 * math.pi * golf.radius**4 * golf.spin_decay / (2 * inertia)
    assert k_s == pytest.approx(0.0004 / 0.44704, rel=0.02)


def _court_pace(g: Ground) -> float:
    return 100 * (1 - g.mu) + 150 * (0.81 - g.kappa)  # the ITF's Court Pace Rating


def test_courts_sit_in_the_itf_pace_category_of_their_name():
    assert _court_pace(GROUNDS["clay"]) <= 29  # slow
    assert 35 <= _court_pace(GROUNDS["hard"]) < 40  # medium
    assert _court_pace(GROUNDS["grass"]) >= 45  # fast
    assert GROUNDS["grass"].kappa == 0.70  # the ITF's least bounce on grass


def test_grounds_keep_their_measured_numbers():
    assert GROUNDS["table"].kappa == pytest.approx(math.sqrt(23 / 30), rel=1e-15)  # ITTF
    assert GROUNDS["pitch"].kappa == pytest.approx(math.sqrt(0.8 / 2.0), rel=1e-15)  # FIFA
    # Stimpmeter: 6.00 ft/s rolling 10 ft at a deceleration mu_r g
    v, d = 6 * 0.3048, 10 * 0.3048
    assert GROUNDS["green"].rolling * 9.80665 == pytest.approx(v**2 / (2 * d), rel=1e-15)


def test_custom_balls_and_grounds_are_checked():
    ball = Ball("custom", 0.1, 0.05, 0.03, drag_coefficient=0.3, lift_max=math.inf)
    assert ball.lift_max == math.inf and ball.body.inertia == pytest.approx(0.1 * 0.03**2)
    with pytest.raises(ValueError, match="lift_max must be > 0"):
        Ball("custom", 0.1, 0.05, 0.03, drag_coefficient=0.3, lift_max=0.0)
    with pytest.raises(TypeError, match="lift_max must be a real number"):
        Ball("custom", 0.1, 0.05, 0.03, drag_coefficient=0.3, lift_max="big")
    with pytest.raises(ValueError, match="mass must be > 0"):
        Ball("custom", -0.1, 0.05, 0.03, drag_coefficient=0.3)
    with pytest.raises(ValueError, match="rolling must be >= 0"):
        Ground("ice", mu=0.1, kappa=0.5, rolling=-1.0)
    with pytest.raises(ValueError, match="mu must be >= 0"):
        Ground("ice", mu=-0.1, kappa=0.5)
