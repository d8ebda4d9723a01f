"""spinimpact.flight: inputs as a person gives them, every bounce equal to solve_sphere (and
to the planar solve in a vertical plane) without air, many balls in chunks, the result's
shape and columns, and bad input."""

import re

import numpy as np
import pytest

from spinimpact import Body, solve, solve_sphere
from spinimpact.model.flight import flight, launch
from spinimpact.model.presets import BALLS, GROUNDS, Ball

G = 9.80665


def test_launch_turns_degrees_and_rpm_into_vectors():
    v, w = launch(10.0, 30.0, direction=90.0, spin_rpm=600.0, spin_axis="topspin")
    # heading 90 degrees: -z (counter-clockwise seen from above, y up)
    np.testing.assert_allclose(v, [0, 5.0, -10 * np.cos(np.radians(30))], atol=1e-14)
    # topspin about e_y x h = e_y x (-e_z) = -e_x, 600 rpm = 20 pi rad/s
    np.testing.assert_allclose(w, [-20 * np.pi, 0, 0], atol=1e-13)
    _, back = launch(10.0, 0.0, spin_rpm=600.0, spin_axis="backspin")
    _, side = launch(10.0, 0.0, spin_rpm=600.0, spin_axis="sidespin")
    _, vec = launch(10.0, 0.0, spin_rpm=600.0, spin_axis=[0, 0, 2.0])
    np.testing.assert_allclose(back, [0, 0, 20 * np.pi], atol=1e-13)
    np.testing.assert_allclose(side, [0, 20 * np.pi, 0], atol=1e-13)
    np.testing.assert_allclose(vec, back, atol=1e-13)
    speeds, _ = launch(np.array([1.0, 2.0, 3.0]), 0.0)
    assert speeds.shape == (3, 3)


def test_in_a_vacuum_every_bounce_is_solve_sphere_on_the_parabolas_incidence():
    ball = BALLS["tennis"]
    f = flight(ball, "clay", speed=30.0, angle=-8.0, direction=20.0, height=2.5, spin_rpm=1500,
               spin_axis=[1.0, 0.5, -2.0], air_density=0.0, max_bounces=4)  # fmt: skip
    v0, _ = launch(30.0, -8.0, 20.0, 1500, [1.0, 0.5, -2.0])
    g = np.array([0, -G, 0])
    p, v, t = np.array([0, 2.5, 0]), v0, 0.0
    for k in range(4):
        vy, h = v[1], p[1] - ball.radius
        dt = (vy + np.sqrt(vy**2 + 2 * G * h)) / G  # the parabola meets the ground
        p, t = p + v * dt + 0.5 * g * dt**2, t + dt
        v = v + g * dt
        assert f.bounces.time[k] == pytest.approx(t, rel=1e-13)
        np.testing.assert_allclose(f.bounces.position.array[k, [0, 2]], p[[0, 2]], rtol=1e-12)
        np.testing.assert_allclose(f.bounces.before.velocity[k], v, rtol=1e-12, atol=1e-12)
        imp = solve_sphere(ball.body, f.bounces.before.velocity[k], f.bounces.before.spin[k],
                           mu=0.82, kappa=0.75)  # fmt: skip
        np.testing.assert_array_equal(f.bounces.after.velocity[k], imp.after.velocity)
        np.testing.assert_array_equal(f.bounces.after.spin[k], imp.after.spin)
        assert bool(f.bounces.grips[k]) == bool(imp.grips)
        assert f.bounces.regime[k] == imp.regime
        v = imp.after.velocity
        p[1] = ball.radius


def test_a_flight_in_a_vertical_plane_bounces_as_the_planar_solve():
    ball = BALLS["table-tennis"]
    f = flight(ball, "table", speed=8.0, angle=10.0, height=0.3, spin_rpm=3000,
               spin_axis="backspin", air_density=0.0, max_bounces=3)  # fmt: skip
    body = Body(mass=ball.mass, radius=ball.radius, gyration=ball.gyration)
    b = f.bounces
    imp = solve(body, b.before.vx, b.before.vy, b.before.wz, mu=0.25, kappa=GROUNDS["table"].kappa)
    speed = np.abs(b.before.vx) + np.abs(b.before.vy)
    assert np.max(np.abs(b.after.vx - imp.after.vx) / speed) < 1e-15
    assert np.max(np.abs(b.after.vy - imp.after.vy) / speed) < 1e-15
    assert np.max(ball.radius * np.abs(b.after.wz - imp.after.omega) / speed) < 1e-15
    assert not np.any(b.after.vz) and not np.any(b.position.z)


def test_topspin_dips_backspin_floats_and_sidespin_curves_left():
    common = dict(speed=25.0, angle=5.0, height=1.0, max_bounces=1)
    flat = flight("tennis", "hard", **common)
    top = flight("tennis", "hard", spin_rpm=3000, spin_axis="topspin", **common)
    back = flight("tennis", "hard", spin_rpm=3000, spin_axis="backspin", **common)
    side = flight("tennis", "hard", spin_rpm=3000, spin_axis="sidespin", **common)
    x = [float(r.bounces.position.x[0]) for r in (top, flat, back)]
    assert x[0] < x[1] < x[2]
    assert float(side.bounces.position.z[0]) < 0  # left of +x seen from above is -z
    vacuum = flight("tennis", "hard", air_density=0.0, **common)
    assert float(flat.bounces.position.x[0]) < float(vacuum.bounces.position.x[0])


@pytest.mark.slow
def test_many_balls_in_chunks_give_the_same_numbers_as_one_chunk():
    rng = np.random.default_rng(11)
    speed, rpm = rng.normal(45, 3, 23), rng.normal(2500, 400, 23)
    calls = []
    kw = dict(speed=speed, angle=-6.0, height=2.8, spin_rpm=rpm, max_bounces=3)
    small = flight("tennis", "grass", chunk=5, progress=lambda d, n: calls.append((d, n)), **kw)
    whole = flight("tennis", "grass", **kw)
    assert calls == [(5, 23), (10, 23), (15, 23), (20, 23), (23, 23)]
    np.testing.assert_array_equal(small.bounces.time, whole.bounces.time)
    np.testing.assert_array_equal(small.final_position.array, whole.final_position.array)
    one = flight("tennis", "grass", speed=speed[7], angle=-6.0, height=2.8, spin_rpm=rpm[7],
                 max_bounces=3)  # fmt: skip
    np.testing.assert_array_equal(whole[7].bounces.after.velocity, one.bounces.after.velocity)
    assert whole.shape == (23,) and whole.bounces.time.shape == (23, 3)
    assert whole.path_position.shape[1] == 0 and one.path_position.shape[-1] == 3


@pytest.mark.slow
def test_the_result_has_columns_rows_and_a_table():
    f = flight("golf", "green", speed=60.0, angle=12.0, height=0.0214, spin_rpm=2800,
               spin_axis="backspin")  # fmt: skip
    assert f.shape == () and str(f.stop) == "rest"
    cols = f.columns()
    assert tuple(cols)[: len(f.column_names())] == f.column_names()
    assert cols["bounce1_time"] == f.bounces.time[0] == f.flight_time
    rows = f.bounce_rows()
    assert len(rows) == int(f.bounce_count) and rows[0]["bounce"] == 1
    assert "golf ball on green" in repr(f) and "stopped (rest) at" in f.table()
    assert f.apex_height > 10 and f.final_time > f.flight_time
    d = f.to_dict()
    assert d["ball"]["name"] == "golf" and isinstance(d["bounces"]["time"], list)
    with pytest.raises(ValueError, match="one ball"):
        flight("golf", "green", speed=[50.0, 60.0], angle=12.0).bounce_rows()


def test_a_ball_that_settles_slides_and_rolls_to_rest_where_friction_says():
    # dropped with no spin: it bounces in place and comes to rest where it fell
    f = flight("soccer", "pitch", speed=0.0, angle=0.0, height=1.0)
    assert str(f.stop) == "rest"
    np.testing.assert_allclose([f.final_position.x, f.final_position.z], 0.0, atol=1e-12)
    # with no rolling resistance and no time to stop, the run ends at t_stop, rolling
    g = flight(BALLS["soccer"], GROUNDS["pitch"].replace(rolling=0.0), speed=5.0, angle=10.0,
               t_stop=10.0)  # fmt: skip
    assert str(g.stop) == "time" and float(g.final_time) == 10.0
    assert float(g.final_velocity.x) > 0


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        (dict(speed=-1.0, angle=0.0), ValueError, "speed must be >= 0"),
        (dict(speed=[1.0, -2.0], angle=0.0), ValueError, r"first offending index 1"),
        (dict(speed=10.0, angle=0.0, spin_rpm=100, spin_axis=[0, 0, 0]), ValueError,
         "length of spin_axis"),
        (dict(speed=10.0, angle=0.0, spin_axis="wobble"), ValueError, "spin_axis must be topspin"),
        (dict(speed=10.0, angle=0.0, height=0.01), ValueError, "start on or above the ground"),
        (dict(speed=10.0, angle=95.0), ValueError, "angle must be in"),
        (dict(speed="fast", angle=0.0), TypeError, "speed must be a real number"),
        (dict(speed=10.0, angle=0.0, dt=0.0), ValueError, re.escape("dt must be > 0 (s), got 0.0")),
        (dict(speed=10.0, angle=0.0, dt=-1), ValueError, re.escape("dt must be > 0 (s), got -1.0")),
        (dict(speed=10.0, angle=0.0, dt=np.inf), ValueError, "dt must be a finite real number"),
        (dict(speed=10.0, angle=0.0, max_bounces=0), ValueError, "max_bounces"),
        (dict(speed=10.0, angle=0.0, t_stop=-1.0), ValueError, re.escape("t_stop must be > 0 (s)")),
        (dict(speed=10.0, angle=0.0, air_density=-1.0), ValueError,
         re.escape("air_density must be >= 0 (kg/m^3), got -1.0")),
        (dict(speed=10.0, angle=0.0, gravity=0), ValueError,
         re.escape("gravity must be > 0 (m/s^2), got 0.0")),
        (dict(speed=10.0, angle=0.0, gravity=-9.8), ValueError, "gravity must be > 0"),
        (dict(speed=10.0, angle=0.0, settle_speed=-1), ValueError,
         re.escape("settle_speed must be > 0 (m/s), got -1.0")),
        (dict(speed=10.0, angle=0.0, dt="1"), TypeError, "dt must be a finite real number"),
        (dict(speed=10.0), ValueError, "^angle missing: give speed"),
        (dict(angle=10.0), ValueError, "^speed missing: give speed"),
        (dict(), ValueError, "^speed and angle missing"),
        (dict(speed=[1, 2, 3], angle=0.0, spin_rpm=[1, 2]), ValueError,
         re.escape("speed (3,), angle (), direction (), spin_rpm (2,)")),
        (dict(speed=[1, 2, 3], angle=[0.0, 1.0]), ValueError, re.escape("speed (3,), angle (2,)")),
        (dict(speed=[1, 2, 3], angle=0.0, spin_axis=[[0, 0, 1]] * 2), ValueError,
         re.escape("spin_axis of shape (2, 3) (vectors along the last axis) does not broadcast "
                   "with the shape (3,) of speed")),
        (dict(speed=[1, 2, 3], angle=0.0, height=[1, 2]), ValueError,
         re.escape("speed, angle, direction and spin_rpm (3,), height (2,)")),
        (dict(velocity=[[1, 0, 0]] * 3, spin=[[0, 0, 1]] * 2), ValueError,
         re.escape("velocity (3,), spin (2,), height ()")),
        (dict(velocity=[[1, 0, 0]] * 3, position=[[0, 1, 0]] * 2), ValueError,
         re.escape("velocity (3,), spin (), position (2,)")),
        (dict(speed=10.0, angle=0.0, velocity=[1, 0, 0]), ValueError, "not both"),
        (dict(velocity=[1, 0, 0], spin=[0, 0]), ValueError, "spin must be a 3-vector"),
    ],
)  # fmt: skip
def test_bad_input_is_named(kwargs, error, match):
    with pytest.raises(error, match=match):
        flight("tennis", "hard", **kwargs)


def test_bad_balls_and_grounds_are_named():
    with pytest.raises(ValueError, match="ball must be one of"):
        flight("cricket", "hard", speed=1.0, angle=0.0)
    with pytest.raises(ValueError, match="ground must be one of"):
        flight("tennis", "ice", speed=1.0, angle=0.0)
    with pytest.raises(TypeError, match="ground must be a Ground"):
        flight("tennis", 3, speed=1.0, angle=0.0)
    with pytest.raises(ValueError, match="drag_coefficient must be >= 0"):
        Ball("x", 0.1, 0.05, 0.03, drag_coefficient=-0.1)
    with pytest.raises(ValueError, match="kappa must be in"):
        GROUNDS["hard"].replace(kappa=1.5)


def test_a_compliance_law_bounces_as_solve_sphere_with_it():
    from spinimpact.model.compliance import Stronge, Walton

    ball = BALLS["tennis"]
    kw = dict(speed=20.0, angle=-30.0, height=1.5, spin_rpm=500, spin_axis=[0.2, 1.0, -1.0],
              air_density=0.0, max_bounces=3)  # fmt: skip
    rigid = flight(ball, "hard", **kw)
    zero = flight(ball, "hard", tangential=Walton(beta0=0.0), **kw)  # Walton's 0: the rigid law
    np.testing.assert_allclose(zero.bounces.after.velocity, rigid.bounces.after.velocity,
                               rtol=1e-13, atol=1e-13)  # fmt: skip
    for law in (Walton(beta0=0.4), Walton(beta0=-1.0), Stronge(poisson_ratio=0.3)):
        f = flight(ball, "hard", tangential=law, **kw)
        assert f.tangential is law
        b = f.bounces
        imp = solve_sphere(ball.body, b.before.velocity, b.before.spin, mu=0.7, kappa=0.75,
                           tangential=law)  # fmt: skip
        np.testing.assert_allclose(b.after.velocity, imp.after.velocity, rtol=1e-14, atol=1e-14)
        np.testing.assert_allclose(b.after.spin, imp.after.spin, rtol=1e-14, atol=1e-12)
        np.testing.assert_array_equal(b.regime, imp.regime)
    assert "slip-reversal" in set(flight(ball, "hard", tangential=Walton(0.4), **kw).bounces.regime)
    # beta0 = -1 applies no friction: its bounces are mu = 0's, and labelled so
    assert set(flight(ball, "hard", tangential=Walton(-1.0), **kw).bounces.regime) == {
        "frictionless"
    }
    with pytest.raises(TypeError, match="tangential must be"):
        flight(ball, "hard", tangential="walton", **kw)


def test_a_ball_placed_on_the_ground_slides_and_rolls_without_bouncing():
    ball, ground = BALLS["soccer"], GROUNDS["pitch"]
    f = flight(ball, ground, speed=3.0, angle=0.0, height=ball.radius)
    assert int(f.bounce_count) == 0 and str(f.stop) == "rest" and np.isnan(f.flight_time)
    # no spin: the slip is the speed; it stops at mu g zeta, the speed falls at mu g meanwhile
    zeta = ball.body.zeta
    t1 = 3.0 / (ground.mu * G * zeta)
    v1 = 3.0 - ground.mu * G * t1
    x = 3.0 * t1 - 0.5 * ground.mu * G * t1**2 + v1**2 / (2 * ground.rolling * G)
    assert float(f.final_position.x) == pytest.approx(x, rel=1e-13)
    assert float(f.final_time) == pytest.approx(t1 + v1 / (ground.rolling * G), rel=1e-13)


@pytest.mark.slow
def test_bounces_in_air_match_an_independent_integration_with_events():
    # SciPy's DOP853 with event location and solve_sphere at each impact, against flight()
    from scipy.integrate import solve_ivp

    from spinimpact.core.aero import aero_constants

    ball, ground = BALLS["tennis"], GROUNDS["clay"]
    f = flight(ball, ground, speed=45.0, angle=-4.0, direction=10.0, height=2.7,
               spin_rpm=2500, spin_axis=[0.3, 0.5, -1.0], max_bounces=3, dt=2e-3)  # fmt: skip
    c = aero_constants(mass=ball.mass, radius=ball.radius, inertia=ball.body.inertia,
                       density=1.225, drag_coefficient=ball.drag_coefficient,
                       lift_slope=ball.lift_slope, lift_max=ball.lift_max,
                       spin_decay=ball.spin_decay, gravity=G)  # fmt: skip

    def rhs(_, y):
        v, w = y[3:6], y[6:9]
        speed = np.linalg.norm(v)
        lift = c.lift / (1 + c.saturation * ball.radius * np.linalg.norm(w) / speed)
        acc = -c.drag * speed * v + lift * np.cross(w, v) - np.array([0, G, 0])
        return np.concatenate([v, acc, -c.spin_decay * speed * w])

    def ground_hit(_, y):
        return y[1] - ball.radius

    ground_hit.terminal, ground_hit.direction = True, -1
    v0, w0 = launch(45.0, -4.0, 10.0, 2500, [0.3, 0.5, -1.0])
    y, t = np.concatenate([[0, 2.7, 0], v0, w0]), 0.0
    for k in range(3):
        sol = solve_ivp(rhs, (t, t + 10), y, method="DOP853", rtol=1e-12, atol=1e-12,
                        events=ground_hit)  # fmt: skip
        t, y = sol.t_events[0][0], sol.y_events[0][0]
        assert f.bounces.time[k] == pytest.approx(t, abs=1e-9)
        np.testing.assert_allclose(f.bounces.position.array[k], y[:3], atol=1e-8)
        np.testing.assert_allclose(f.bounces.before.velocity[k], y[3:6], atol=1e-8)
        imp = solve_sphere(ball.body, y[3:6], y[6:9], mu=ground.mu, kappa=ground.kappa)
        y = np.concatenate([y[:3], imp.after.velocity, imp.after.spin])
        np.testing.assert_allclose(f.bounces.after.spin[k], y[6:9], rtol=1e-8, atol=1e-6)


def test_a_wall_is_met_on_the_parabola_and_bounces_as_solve_sphere_on_it():
    from spinimpact import Surface
    from spinimpact.model.presets import Wall

    ball = BALLS["tennis"]
    wall = Wall(8.0, direction=20.0, mu=0.4, kappa=0.6)
    kw = dict(speed=15.0, angle=15.0, direction=10.0, height=1.0, spin_rpm=800,
              spin_axis=[0.5, 1.0, 0.0], max_bounces=3, wall=wall)  # fmt: skip
    f = flight(ball, "hard", air_density=0.0, **kw)
    assert list(f.bounces.surface) == ["wall", "ground", "ground"]
    v0, _ = launch(15.0, 15.0, 10.0, 800, [0.5, 1.0, 0.0])
    h = np.array([np.cos(np.radians(20.0)), 0.0, -np.sin(np.radians(20.0))])
    t = (8.0 - ball.radius) / (v0 @ h)  # the gap closes linearly in a vacuum
    assert f.bounces.time[0] == pytest.approx(t, rel=1e-13)
    assert f.bounces.position.array[0] @ h == pytest.approx(8.0 - ball.radius, rel=1e-13)
    b = f.bounces
    imp = solve_sphere(ball.body, b.before.velocity[0], b.before.spin[0], mu=0.4, kappa=0.6,
                       surface=Surface(normal=-h))  # fmt: skip
    np.testing.assert_array_equal(b.after.velocity[0], imp.after.velocity)
    np.testing.assert_array_equal(b.after.spin[0], imp.after.spin)
    vb = b.before.velocity[0]  # the angle is measured from the wall's plane
    assert b.angle_before[0] == pytest.approx(np.arcsin((vb @ h) / np.linalg.norm(vb)), rel=1e-12)
    # in air, the wall is met where the integrator's own path meets it
    a = flight(ball, "hard", **kw)
    assert a.bounces.surface[0] == "wall"
    assert a.bounces.position.array[0] @ h == pytest.approx(8.0 - ball.radius, rel=1e-14)
    with pytest.raises(ValueError, match="in front of the wall"):
        flight(ball, "hard", speed=5.0, angle=0.0, wall=Wall(0.01))
    with pytest.raises(TypeError, match="wall must be"):
        flight(ball, "hard", speed=5.0, angle=0.0, wall=3.0)
