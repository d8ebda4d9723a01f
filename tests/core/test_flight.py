"""Flight kernels against closed forms and an independent integrator: the parabola, the
terminal speed and the fall with quadratic drag, the spin decay along the path, the drag's
work against the energy lost, the event location, the bounce and the roll."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from spinimpact import Body, solve_sphere
from spinimpact.core.aero import aero_constants, derivatives, lift_coefficient, terminal_speed
from spinimpact.core.bounces import fly
from spinimpact.core.flight import integrate_to_ground, parabola_to_ground
from spinimpact.core.ground import ground_bounce, roll_to_rest

G = 9.81
M, R = 0.0577, 0.0335
BODY = Body(mass=M, radius=R, gyration=0.025)


def _aero(density=1.225, cd=0.5, slope=1.0, cmax=0.5, decay=0.02):
    return aero_constants(mass=M, radius=R, inertia=BODY.inertia, density=density,
                          drag_coefficient=cd, lift_slope=slope, lift_max=cmax,
                          spin_decay=decay, gravity=G)  # fmt: skip


def _rows(*values):
    """One ball: a time (if given first, as a number) and 3-vectors, as arrays over one ball."""
    return [np.atleast_1d(np.asarray(v, dtype=float))[None] if np.ndim(v) else np.array([v])
            for v in values]  # fmt: skip


def test_lift_coefficient_is_stepaneks_law_and_saturates():
    s = np.array([0.0, 0.1, 1.0, 1e6])
    assert lift_coefficient(0.0) == 0.0
    np.testing.assert_allclose(lift_coefficient(s[1:]), 1.0 / (2.0 + 1.0 / s[1:]), rtol=1e-15)
    np.testing.assert_allclose(lift_coefficient(s, 1.5, np.inf), 1.5 * s, rtol=0)
    assert not np.any(lift_coefficient(s, 0.0, 0.5))


def test_magnus_force_matches_its_definition():
    # a = -g e_y - k_d |v| v + (rho A / 2m) C_L |v|^2 (w_hat x v_hat), evaluated directly
    rng = np.random.default_rng(3)
    v, w = rng.normal(size=(50, 3)) * 20, rng.normal(size=(50, 3)) * 300
    c = _aero()
    acc, spin_rate = derivatives(v, w, c)
    speed, wsize = np.linalg.norm(v, axis=1), np.linalg.norm(w, axis=1)
    cl = lift_coefficient(R * wsize / speed)
    q = 1.225 * np.pi * R**2 / (2 * M)
    lift = q * cl[:, None] * speed[:, None] ** 2 * np.cross(w / wsize[:, None], v / speed[:, None])
    want = -q * 0.5 * speed[:, None] * v + lift - np.array([0, G, 0])
    np.testing.assert_allclose(acc, want, rtol=1e-12, atol=1e-12)
    k_s = 1.225 * np.pi * R**2 * R**2 * 0.02 / (2 * BODY.inertia)
    np.testing.assert_allclose(spin_rate, -k_s * speed[:, None] * w, rtol=1e-14)


def test_without_air_the_arc_is_the_exact_parabola():
    rng = np.random.default_rng(5)
    n = 200
    p = np.stack([np.zeros(n), rng.uniform(R, 3.0, n), np.zeros(n)], -1)
    v = rng.normal(size=(n, 3)) * 10
    seg = parabola_to_ground(np.zeros(n), p, v, np.zeros((n, 3)), gravity=G, radius=R,
                             t_stop=np.inf, record=True)  # fmt: skip
    h, vy = p[:, 1] - R, v[:, 1]
    t = (vy + np.sqrt(vy**2 + 2 * G * h)) / G  # the textbook root
    np.testing.assert_allclose(seg.time, t, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(seg.position[:, [0, 2]], v[:, [0, 2]] * t[:, None], rtol=1e-13,
                               atol=1e-14)  # fmt: skip
    np.testing.assert_allclose(seg.velocity[:, 1], vy - G * t, rtol=1e-13, atol=1e-13)
    assert np.all(seg.position[:, 1] == R) and np.all(seg.hit)
    up = vy > 0
    np.testing.assert_allclose(seg.apex_height[up], p[up, 1] + vy[up] ** 2 / (2 * G), rtol=1e-14)
    # every recorded point lies on the parabola through the launch point
    _, times, pts = seg.path[0]
    want = p[:, None, 1] + vy[:, None] * times - 0.5 * G * times**2
    np.testing.assert_allclose(pts[..., 1], want, rtol=1e-12, atol=1e-12)


def test_the_integrator_meets_the_parabola_to_rounding_without_air():
    # RK4 is exact for a constant acceleration, so the located impact is the parabola's
    rng = np.random.default_rng(6)
    n = 100
    p = np.stack([np.zeros(n), rng.uniform(R, 3.0, n), np.zeros(n)], -1)
    v = rng.normal(size=(n, 3)) * 10
    w = np.zeros((n, 3))
    exact = parabola_to_ground(np.zeros(n), p, v, w, gravity=G, radius=R, t_stop=np.inf)
    seg = integrate_to_ground(np.zeros(n), p, v, w, _aero(density=0.0), radius=R,
                              t_stop=np.inf, dt=0.01)  # fmt: skip
    np.testing.assert_allclose(seg.time, exact.time, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(seg.velocity, exact.velocity, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(seg.apex_height, exact.apex_height, rtol=1e-12)


@pytest.mark.slow
def test_a_vertical_fall_approaches_the_terminal_speed_as_tanh():
    # dv/dt = g - k v^2 from rest: v = v_t tanh(g t / v_t), fallen v_t^2/g ln cosh(g t / v_t)
    m, r = 0.0027, 0.02
    c = aero_constants(mass=m, radius=r, inertia=m * r**2 * 2 / 3, density=1.225,
                       drag_coefficient=0.5, lift_slope=1.0, lift_max=0.5, spin_decay=0.0,
                       gravity=G)  # fmt: skip
    vt = terminal_speed(mass=m, radius=r, density=1.225, drag_coefficient=0.5, gravity=G)
    assert vt == pytest.approx(np.sqrt(G / c.drag), rel=1e-15)
    t_stop = np.array([0.5, 1.0, 2.0, 4.0])
    top = 200.0
    out = []
    for ts in t_stop:
        seg = integrate_to_ground(*_rows(0.0, [0, top, 0], [0, 0, 0], [0, 0, 0]), c, radius=r,
                                  t_stop=ts, dt=2e-3)  # fmt: skip
        assert not seg.hit[0]
        out.append((seg.velocity[0, 1], top - seg.position[0, 1]))
    speed, fallen = -np.array(out).T
    x = G * t_stop / vt
    np.testing.assert_allclose(speed, vt * np.tanh(x), rtol=1e-10)
    np.testing.assert_allclose(-fallen, vt**2 / G * np.log(np.cosh(x)), rtol=1e-10)
    assert speed[-1] == pytest.approx(vt, rel=1e-3)  # 4 s: within 0.1 % of terminal


@pytest.mark.slow
def test_spin_about_the_path_decays_with_the_distance_travelled():
    # spin along the vertical velocity: no lift; d omega / ds = -k_s omega => exp(-k_s s)
    c = _aero(decay=0.05)
    seg = integrate_to_ground(*_rows(0.0, [0, 50, 0], [0, 0, 0], [0, 400, 0]), c, radius=R,
                              t_stop=2.5, dt=2e-3)  # fmt: skip
    fallen = 50 - seg.position[0, 1]
    assert seg.spin[0, 1] == pytest.approx(400 * np.exp(-c.spin_decay * fallen), rel=1e-10)
    assert seg.position[0, 0] == 0 and seg.position[0, 2] == 0


def _scipy_flight(p0, v0, w0, c, t_end):
    """An independent integration (SciPy's DOP853) of the same equations with the drag's
    work W = integral of -m k_d |v|^3 dt carried along."""

    def rhs(_, y):
        v, w = y[3:6], y[6:9]
        speed = np.linalg.norm(v)
        s = R * np.linalg.norm(w) / speed
        lift = c.lift / (1 + c.saturation * s) * np.cross(w, v)
        acc = -c.drag * speed * v + lift - np.array([0, c.gravity, 0])
        return np.concatenate([v, acc, -c.spin_decay * speed * w, [-M * c.drag * speed**3]])

    y0 = np.concatenate([p0, v0, w0, [0.0]])
    return solve_ivp(rhs, (0, t_end), y0, method="DOP853", rtol=1e-12, atol=1e-12).y[:, -1]


def test_energy_lost_in_flight_is_the_work_of_the_drag():
    c = _aero()
    p0, v0, w0 = np.array([0, 1.0, 0]), np.array([30.0, 8.0, 2.0]), np.array([30.0, 50.0, -250])
    seg = integrate_to_ground(*_rows(0.0, p0, v0, w0), c, radius=R, t_stop=np.inf, dt=1e-3)
    assert seg.hit[0]
    t_hit = seg.time[0]
    ref = _scipy_flight(p0, v0, w0, c, t_hit)
    np.testing.assert_allclose(seg.position[0], ref[:3], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(seg.velocity[0], ref[3:6], rtol=1e-9, atol=1e-9)

    def energy(p, v):  # translational + potential: lift does no work, spin is separate
        return 0.5 * M * v @ v + M * G * p[1]

    lost = energy(seg.position[0], seg.velocity[0]) - energy(p0, v0)
    assert lost < 0 and lost == pytest.approx(ref[9], rel=1e-8)


@pytest.mark.slow
def test_impacts_are_located_to_the_integrators_precision():
    c = _aero()
    args = _rows(0.0, [0, 1.0, 0], [30.0, 8.0, 2.0], [30.0, 50.0, -250])
    fine = integrate_to_ground(*args, c, radius=R, t_stop=np.inf, dt=2.5e-4)
    errors = []
    for dt in (8e-3, 1.6e-2, 3.2e-2):
        seg = integrate_to_ground(*args, c, radius=R, t_stop=np.inf, dt=dt)
        assert seg.position[0, 1] == R
        errors.append(abs(seg.time[0] - fine.time[0]))
    # the impact time is the RK4 solution's own: its error falls as dt^4 (16 per halving;
    # a located event with an error of its own would not follow the integrator's order)
    ratios = np.array(errors[1:]) / errors[:-1]
    assert np.all((ratios > 12) & (ratios < 20)), ratios
    # the apex, bracketed on the cubic interpolant, to the same order of magnitude
    assert abs(seg.apex_height[0] - fine.apex_height[0]) < 1e-6


def test_ground_bounce_is_solve_sphere():
    rng = np.random.default_rng(8)
    v = rng.normal(size=(500, 3)) * 10
    v[:, 1] = -np.abs(v[:, 1]) - 0.1
    w = rng.normal(size=(500, 3)) * 300
    b = ground_bounce(v, w, mass=M, radius=R, inertia=BODY.inertia, zeta=BODY.zeta, mu=0.6,
                      kappa=0.75)  # fmt: skip
    imp = solve_sphere(BODY, v, w, mu=0.6, kappa=0.75)
    np.testing.assert_array_equal(b.velocity, imp.after.velocity)
    np.testing.assert_array_equal(b.spin, imp.after.spin)
    np.testing.assert_array_equal(b.grips, imp.grips)


def test_roll_slides_then_rolls_to_rest_in_closed_form():
    # along x with backspin: slip u = v + R w3... falls at mu g zeta, then rolls at mu_r g
    v0, w0 = 5.0, 40.0  # omega_z > 0 is backspin for motion along +x
    roll, _ = roll_to_rest(*_rows(0.0, [0, R, 0], [v0, 0, 0], [0, 0, w0]), mass=M, radius=R,
                           inertia=BODY.inertia, zeta=BODY.zeta, mu=0.5, rolling=0.05,
                           gravity=G, t_stop=100.0)  # fmt: skip
    u = v0 + R * w0
    t_slide = u / (0.5 * G * BODY.zeta)
    v_roll = v0 - 0.5 * G * t_slide
    assert roll.slide_end[0] == pytest.approx(t_slide, rel=1e-14)
    x = v0 * t_slide - 0.25 * G * t_slide**2 + v_roll**2 / (2 * 0.05 * G)
    assert roll.at_rest[0] and roll.position[0, 0] == pytest.approx(x, rel=1e-13)
    assert roll.time[0] == pytest.approx(t_slide + v_roll / (0.05 * G), rel=1e-13)
    np.testing.assert_array_equal(roll.velocity[0], 0.0)


@pytest.mark.slow
def test_fly_stops_at_max_bounces_and_settles_to_rest():
    c = _aero()
    args = _rows([0, 1.0, 0], [10.0, 3.0, 0.0], [0, 0, 0])
    common = dict(mass=M, radius=R, inertia=BODY.inertia, zeta=BODY.zeta, mu=0.6, kappa=0.7,
                  rolling=0.05, aero=c, t_stop=60.0, dt=1e-3)  # fmt: skip
    three = fly(*args, max_bounces=3, settle_speed=0.05, **common)
    assert three.bounces[0] == 3 and three.stop[0] == 2
    many = fly(*args, max_bounces=60, settle_speed=0.05, **common)
    assert many.stop[0] == 0 and many.bounces[0] < 60
    np.testing.assert_array_equal(many.velocity_after[0, :3], three.velocity_after[0])
    # the bounces settle: each rebound is kappa times the incidence along the normal
    k = many.bounces[0]
    np.testing.assert_allclose(many.velocity_after[0, :k, 1], -0.7 * many.velocity_before[0, :k, 1],
                               rtol=1e-14)  # fmt: skip
