"""The flight's tables, figure and animation (spinimpact.viz.flight): the numbers shown are the
result's, the paths and bounce marks drawn where the result puts them, the GIF has frames."""

import numpy as np
import pytest

from spinimpact.model.flight import flight
from spinimpact.viz.flight import animate_flight, flight_tables, plot_flight

from tests.viz.test_figure_text import _problems

pytest.importorskip("matplotlib")

SERVE = flight("tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0,
               spin_axis=[0, 0.3, -1], max_bounces=3)  # fmt: skip


@pytest.mark.slow
def test_tables_show_the_results_numbers():
    bounces, summary = flight_tables(SERVE)
    assert len(bounces.rows) == 3
    first = bounces.rows[0]
    assert first[2] == f"{float(SERVE.bounces.position.x[0]):.2f}"
    speed_in, speed_out = (float(s) for s in first[4].split(" / "))
    assert speed_in == pytest.approx(float(SERVE.bounces.speed_before[0]), abs=0.05)
    assert speed_out == pytest.approx(float(SERVE.bounces.speed_after[0]), abs=0.05)
    assert first[7] == ("grips" if SERVE.bounces.grips[0] else "skids")
    assert dict(summary.rows)["bounces"] == "3"
    with pytest.raises(ValueError, match="one ball"):
        flight_tables(flight("tennis", "hard", speed=[30.0, 40.0], angle=5.0))
    with pytest.raises(TypeError, match="Flight"):
        flight_tables("serve")


def test_the_figure_draws_the_path_and_marks_every_bounce():
    fig = plot_flight(SERVE)
    side, top = fig.axes[:2]
    (path,) = side.get_lines()[:1]
    x, y = path.get_data()
    ok = ~np.isnan(SERVE.path_time)
    np.testing.assert_array_equal(x, SERVE.path_position[:, 0])
    np.testing.assert_array_equal(y, SERVE.path_position[:, 1])
    assert ok.all()
    marks = side.collections[0].get_offsets()
    np.testing.assert_allclose(marks[:, 0], SERVE.bounces.position.x)
    top_marks = top.collections[0].get_offsets()
    np.testing.assert_allclose(top_marks[:, 1], SERVE.bounces.position.z)
    assert top.yaxis_inverted()  # seen from above, +z points down the page
    # the side-spin component curves the ball: the top view is not a straight line
    assert np.ptp(SERVE.path_position[:, 2]) > 0.05


def test_many_balls_are_drawn_with_every_bounce():
    rng = np.random.default_rng(2)
    many = flight("table-tennis", "table", speed=rng.normal(8, 0.5, 40), angle=10.0, height=0.3,
                  spin_rpm=rng.normal(3000, 300, 40), max_bounces=2, path=True)  # fmt: skip
    fig = plot_flight(many)
    marks = fig.axes[0].collections[0].get_offsets()
    assert len(marks) == int(np.sum(many.bounce_count))
    assert "40 table-tennis balls" in fig._suptitle.get_text()


@pytest.mark.slow
def test_animation_writes_a_gif_with_frames(tmp_path):
    from PIL import Image

    short = flight("tennis", "clay", speed=10.0, angle=20.0, height=1.0, max_bounces=1)
    target = tmp_path / "a.partial"  # any name: the format is given
    animate_flight(short, target, format="gif", fps=4, dpi=40)
    with Image.open(target) as gif:
        span = float(np.nanmax(short.path_time))
        assert gif.format == "GIF" and gif.n_frames == int(np.ceil(span * 4))
    with pytest.raises(ValueError, match="gif or .mp4"):
        animate_flight(short, tmp_path / "a.avi")
    with pytest.raises(ValueError, match="one ball"):
        animate_flight(flight("tennis", "hard", speed=[1.0, 2.0], angle=5.0), tmp_path / "b.gif")
    with pytest.raises(ValueError, match="no recorded path"):
        animate_flight(flight("tennis", "hard", speed=5.0, angle=5.0, path=False),
                       tmp_path / "c.gif")  # fmt: skip


def test_the_wall_is_drawn_where_it_stands():
    from spinimpact.model.presets import Wall

    f = flight("tennis", "hard", speed=20.0, angle=10.0, max_bounces=2,
               wall=Wall(10.0, direction=15.0))  # fmt: skip
    top = plot_flight(f).axes[1]
    (line,) = [ln for ln in top.get_lines() if ln.get_label() == "wall"]
    x, z = line.get_data()
    d = np.radians(15.0)
    np.testing.assert_allclose(x * np.cos(d) - z * np.sin(d), 10.0, rtol=1e-12)  # h . p = 10
    bounces, _ = flight_tables(f)
    assert bounces.rows[0][0] == "1w" and bounces.rows[1][0] == "2"


@pytest.mark.slow
def test_the_view_frames_the_flight_and_bounces_not_the_roll_out():
    """A ball that bounces to a roll and rolls on (here about 36 m of bounces, then to
    rest 160 m away) once squashed the flight into the first fifth of the picture. The
    view now ends a little after the last airborne point; the roll-out beyond is clipped
    and its end said in words."""
    rolls = flight("tennis", "hard", speed=30.0, angle=0.0, height=1.0)
    assert rolls.stop == "rest" and float(rolls.final_position.x) > 150.0
    fig = plot_flight(rolls)
    side, top = fig.axes[:2]
    x, y = rolls.path_position[:, 0], rolls.path_position[:, 1]
    airborne = x[y > float(rolls.ball.radius) * (1 + 1e-9)]
    last_bounce = float(np.nanmax(rolls.bounces.position.x))
    low, high = side.get_xlim()
    assert low <= x[0] and high >= max(airborne.max(), last_bounce)  # every bounce shown
    assert high < 1.3 * airborne.max()  # ... and not the 160 m roll
    note = side.get_title(loc="right")
    assert f"rest at $x$ = {float(rolls.final_position.x):.4g} m" in note
    assert _problems(fig) == []
    # the top view's scale is the framed part's
    shown = (x >= low) & (x <= high)
    z = rolls.path_position[shown, 2]
    zlow, zhigh = sorted(top.get_ylim())
    assert zlow <= z.min() and zhigh >= z.max() and top.yaxis_inverted()
    assert not [c for c in top.collections if c.get_label() == "at rest"]  # out of view
    # the whole path on request, and no note where nothing is clipped
    whole = plot_flight(rolls, roll=True).axes[0]
    assert whole.get_xlim()[1] >= float(rolls.final_position.x)
    assert whole.get_title(loc="right") == ""
    assert plot_flight(SERVE).axes[0].get_title(loc="right") == ""  # nothing clipped
