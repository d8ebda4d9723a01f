"""solve_sphere() and solve_pair() against an independent integration of the 3D equations.

:mod:`tests.sphere_reference` integrates, in the normal impulse, the impulse-momentum
equations of the bodies themselves (3-vectors; Coulomb's law re-evaluated from the current
slip at every step; the stop of the slip and the end of compression located as events). It
never uses a collision matrix, ``zeta`` or a closed form, and it does not assume that the
slip keeps its direction (it measures how far the direction turns). The closed forms of
the package are compared with it on 12,000 spheres (a fifth aimed at each regime; a third
on the default plane, a third on tilted planes, a third on tilted moving planes; plane
motions and head-on impacts among them) and 3,000 pairs of spheres of different masses,
radii and gyrations, on random normals.

Tolerances. With the speed scale ``S = sum |v_i| + sum max(R_i, rho_i)|w_i|`` (plus
``|V_s|`` for a moving plane: the magnitudes from which the contact velocity is computed,
so its rounding is ``eps S``), velocities and ``R w`` are compared relative to ``S``,
impulses to ``m S`` (``m`` the sphere's mass, or the pair's reduced mass
``1/(1/m_1 + 1/m_2)``), works to ``m S^2``, the reference's energy change (a difference of
the bodies' kinetic energies) to ``(m_1 + m_2) S^2``, and ``tau_*`` (a slip divided by
``mu``) to ``m S / mu``. The reference lands on every event and advances exactly between
them, so the two routes differ only by rounding: the largest difference measured on these
samples is 15 eps in these units (the dissipated energy against the reference's change of
kinetic energy; 15 eps for ``tau_1`` and ``c_n`` after, 12 for the velocities, 5 for ``R w``,
3 for ``F``). ``TOL = 256 eps`` (5.7e-14) leaves a margin of 17; a relative error of 1e-9
in any compared output fails (checked by perturbing each output in turn in a throwaway
script).
"""

import numpy as np
import pytest

from spinimpact import Body, Surface, solve, solve_pair, solve_sphere

from tests.sphere_reference import (
    REGIMES,
    random_pair_cases,
    random_sphere_cases,
    sphere_on_plane,
    sphere_pair,
)

EPS = np.finfo(float).eps
TOL = 256 * EPS  # rounding only, per unit of scale: see the module docstring
N_SPHERES = 12_000
N_PAIRS = 3_000
WORKS = (
    "work_compression_normal",
    "work_compression_tangential",
    "work_restitution_normal",
    "work_restitution_tangential",
)


def _norm(a):
    return np.linalg.norm(a, axis=-1)


def _dot(a, b):
    return np.sum(a * b, axis=-1)


def _err(x, y, scale):
    """Largest ``|x - y| / scale`` (over the last axis too, for vectors)."""
    d = np.abs(np.asarray(x, dtype=float) - np.asarray(y, dtype=float))
    if d.ndim > np.ndim(scale):
        d = d.max(axis=-1)
    return np.max(d / scale)


class Spheres:
    """The sphere sample: cases, closed forms (``imp``), reference (``ref``), scales."""

    def __init__(self):
        c = random_sphere_cases(N_SPHERES, seed=3)
        self.c = c
        self.body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
        # tilted normals are handed over un-normalised (lengths 0.5 to 2): normalising
        # them is part of what is tested; the reference gets the unit vectors
        length = np.where(c["tilted"], np.random.default_rng(4).uniform(0.5, 2, N_SPHERES), 1.0)
        self.surface = Surface(normal=c["normal"] * length[:, None], velocity=c["surface_velocity"])
        self.imp = solve_sphere(self.body, c["velocity"], c["spin"], mu=c["mu"],
                                kappa=c["kappa"], surface=self.surface)  # fmt: skip
        self.ref = sphere_on_plane(c["mass"], c["radius"], c["gyration"], c["velocity"],
                                   c["spin"], c["normal"], c["surface_velocity"], c["mu"],
                                   c["kappa"], resolution=32)  # fmt: skip
        self.speed = (_norm(c["velocity"]) + _norm(c["surface_velocity"])
                      + np.maximum(c["radius"], c["gyration"]) * _norm(c["spin"]))  # fmt: skip
        self.mass = c["mass"]
        self.impulse = self.mass * self.speed
        self.energy = self.mass * self.speed**2


class Pairs:
    """The pair sample, laid out as :class:`Spheres`."""

    def __init__(self):
        c = random_pair_cases(N_PAIRS, seed=5)
        self.c = c
        self.ball1 = Body(mass=c["mass1"], radius=c["radius1"], gyration=c["gyration1"])
        self.ball2 = Body(mass=c["mass2"], radius=c["radius2"], gyration=c["gyration2"])
        self.imp = solve_pair(self.ball1, self.ball2, velocity1=c["velocity1"],
                              spin1=c["spin1"], velocity2=c["velocity2"], spin2=c["spin2"],
                              normal=c["normal"], mu=c["mu"], kappa=c["kappa"])  # fmt: skip
        self.ref = sphere_pair((c["mass1"], c["radius1"], c["gyration1"]),
                               (c["mass2"], c["radius2"], c["gyration2"]), c["velocity1"],
                               c["spin1"], c["velocity2"], c["spin2"], c["normal"], c["mu"],
                               c["kappa"], resolution=32)  # fmt: skip
        self.speed = (_norm(c["velocity1"]) + _norm(c["velocity2"])
                      + np.maximum(c["radius1"], c["gyration1"]) * _norm(c["spin1"])
                      + np.maximum(c["radius2"], c["gyration2"]) * _norm(c["spin2"]))  # fmt: skip
        self.mass = 1.0 / (1.0 / c["mass1"] + 1.0 / c["mass2"])
        self.impulse = self.mass * self.speed
        self.energy = self.mass * self.speed**2
        self.body_energy = (c["mass1"] + c["mass2"]) * self.speed**2


@pytest.fixture(scope="module")
def sp():
    return Spheres()


@pytest.fixture(scope="module")
def pr():
    return Pairs()


# --- the samples -----------------------------------------------------------------------


@pytest.mark.slow
def test_the_sphere_sample_covers_every_regime_on_every_kind_of_plane(sp):
    """The reference's own events classify the sample: every regime at least 2,000 times;
    every regime but no-slip (built exactly on the default plane) at least 500 times on
    each kind of plane; head-on and plane-motion cases; the slip never turned."""
    ref, c = sp.ref, sp.c
    kinds = {"default": ~c["tilted"], "tilted": c["tilted"] & ~c["moving"], "moving": c["moving"]}
    for name in REGIMES:
        assert np.sum(ref.regime == name) >= 2000, name
        for kind, mask in kinds.items():
            if name != "no-slip":
                assert np.sum(mask & (ref.regime == name)) >= 500, (name, kind)
    assert np.sum(c["head_on"]) >= 200 and np.sum(c["head_on"] & c["moving"]) >= 50
    assert np.sum(c["planar"]) >= 500
    assert np.all(ref.stick_holds)  # a stopped slip never needs more friction than mu
    assert np.max(ref.slip_turn) < 1e-11


def test_the_pair_sample_covers_every_regime(pr):
    for name in REGIMES:
        assert np.sum(pr.ref.regime == name) >= 500, name
    assert np.sum(pr.c["head_on"]) >= 50
    assert np.all(pr.ref.stick_holds)
    assert np.max(pr.ref.slip_turn) < 1e-11
    ratio = pr.c["mass1"] / pr.c["mass2"]
    assert ratio.min() < 1e-2 and ratio.max() > 1e2


def test_the_reference_gives_textbook_answers():
    """The reference on its own, against results derived by hand: a solid sphere that
    grips leaves with 5/7 of its tangential velocity (rolling); without friction the
    tangential velocity and the spin are kept and ``v_n`` is reversed times kappa; a sphere
    that slips throughout gets ``|F| = mu (1 + kappa) m |c_n|`` against its slip. On a
    tilted moving plane, in the plane's frame and axes."""
    rot = np.linalg.qr(np.random.default_rng(7).normal(size=(3, 3)))[0]
    n, V = rot @ [0, 1.0, 0], np.array([0.3, -2.0, 1.5])
    m, R = 0.4, 0.05
    g = np.sqrt(0.4) * R
    v = np.array([[3.0, -2.0, 0.0], [3.0, -2.0, 1.0], [3.0, -1.0, -4.0]])
    w = np.array([[0.0, 0.0, 0.0], [7.0, 5.0, -3.0], [0.0, 0.0, 0.0]])
    mu, kappa = np.array([10.0, 0.0, 0.1]), np.array([0.6, 0.3, 0.8])
    ref = sphere_on_plane(m, R, g, v @ rot.T + V, w @ rot.T, n, V, mu, kappa)
    after = (ref.velocity1 - V) @ rot  # back in the plane's frame and axes
    spin = ref.spin1 @ rot
    np.testing.assert_allclose(after[0], [15 / 7, 1.2, 0.0], atol=1e-14)
    np.testing.assert_allclose(spin[0], [0, 0, -15 / 7 / R], atol=1e-12)
    np.testing.assert_allclose(after[1], [3.0, 0.6, 1.0], atol=1e-14)
    np.testing.assert_allclose(spin[1], w[1], atol=1e-13)
    F = ref.friction[2] @ rot
    np.testing.assert_allclose(F, -0.1 * 1.8 * m * np.array([3.0, 0, -4.0]) / 5, atol=1e-15)
    assert list(ref.regime) == ["stick-compression", "frictionless", "slip"]


# --- sphere on a plane: closed forms vs reference ---------------------------------------


def _regimes_agree(imp, ref, near_rest):
    """Equal everywhere, except where the incident slip is zero only to rounding (head-on
    on a tilted plane or between two balls on a random normal): there a slip of 1e-16 m/s
    that stops at once is the no-slip impact, and either name is right."""
    same = imp.regime == ref.regime
    either = np.isin(imp.regime, ("no-slip", "stick-compression")) & np.isin(
        ref.regime, ("no-slip", "stick-compression")
    )
    assert np.all(same | (near_rest & either)), np.flatnonzero(~same)[:10]
    return same


def test_sphere_regimes_agree(sp):
    same = _regimes_agree(sp.imp, sp.ref, sp.c["near_rest"])
    assert np.mean(same) > 0.98


@pytest.mark.parametrize(
    ("mine", "theirs"), [("velocity", "velocity1"), ("spin", "spin1")]
)  # fmt: skip
def test_sphere_state_after_agrees(sp, mine, theirs):
    scale = sp.c["radius"][:, None] if mine == "spin" else 1.0
    got = getattr(sp.imp.after, mine) * scale
    assert _err(got, getattr(sp.ref, theirs) * scale, sp.speed) < TOL
    # and the state before is the input, untouched
    np.testing.assert_array_equal(getattr(sp.imp.before, mine), sp.c[mine])


def test_sphere_impulses_agree(sp):
    imp, ref = sp.imp, sp.ref
    assert _err(imp.friction_impulse.array, ref.friction, sp.impulse) < TOL
    assert _err(imp.tau0, ref.tau0, sp.impulse) < TOL
    assert _err(imp.tau1, ref.tau1, sp.impulse) < TOL
    np.testing.assert_allclose(imp.impulse_ratio * ref.tau1, _norm(ref.friction),
                               rtol=0, atol=TOL * sp.impulse.max())  # fmt: skip
    assert np.all(_dot(imp.friction_impulse.array, sp.c["normal"]) ** 2 <= (TOL * sp.impulse) ** 2)


def test_sphere_stick_impulse_agrees(sp):
    _stick_impulse_agrees(sp)


def _stick_impulse_agrees(s):
    """``tau_*``: where the slip stopped (0 without incident slip; inf without friction),
    or, past ``tau_1``, where it would stop."""
    imp, ref, mu = s.imp, s.ref, s.c["mu"]
    near = s.c["near_rest"]
    ok = ~near
    np.testing.assert_array_equal(np.isfinite(imp.tau_star[ok]), np.isfinite(ref.tau_slip[ok]))
    fin = ok & np.isfinite(ref.tau_slip)
    scale = np.where(mu > 0, s.impulse / np.where(mu > 0, mu, 1.0), s.impulse)
    assert _err(imp.tau_star[fin], ref.tau_slip[fin], scale[fin]) < TOL
    # a slip at the level of rounding stops at once (or never, without friction)
    tiny = imp.tau_star[near]
    assert np.all((tiny <= TOL * scale[near]) | (np.isinf(tiny) & (mu[near] == 0)))


def test_sphere_works_and_energy_agree(sp):
    _works_and_energy_agree(sp, sp.energy)


def _works_and_energy_agree(s, body_energy):
    imp, ref = s.imp, s.ref
    for name in WORKS:
        assert _err(getattr(imp, name), getattr(ref, name), s.energy) < TOL, name
    total = sum(getattr(ref, name) for name in WORKS)
    # the reference's two routes to the energy: the works and the bodies' kinetic energies
    assert _err(total, ref.energy_change, body_energy) < TOL
    assert _err(imp.dissipated_energy, -ref.energy_change, body_energy) < TOL
    assert _err(imp.dissipated_energy, -total, s.energy) < TOL


def test_sphere_contact_velocities_agree(sp):
    imp, ref = sp.imp, sp.ref
    assert _err(imp.slip_before.array, ref.slip_before, sp.speed) < TOL
    assert _err(imp.slip_after.array, ref.slip_after, sp.speed) < TOL
    assert _err(imp.normal_velocity_before, ref.normal_before, sp.speed) < TOL
    assert _err(imp.normal_velocity_after, ref.normal_after, sp.speed) < TOL
    # the ball grips exactly where the reference's slip stopped (rounding-level slips apart)
    grips = _norm(ref.slip_after) == 0
    ok = ~sp.c["near_rest"]
    np.testing.assert_array_equal(np.asarray(imp.grips)[ok], grips[ok])


def test_sphere_energies_and_coefficients(sp):
    """Kinetic energies in the ground frame from the bodies' velocities; the dissipated
    fraction of the energy in the plane's frame; the three restitution coefficients all
    equal kappa (the normal problem is uncoupled: W_tn = 0)."""
    imp, ref, c = sp.imp, sp.ref, sp.c
    m, J = c["mass"], c["mass"] * c["gyration"] ** 2

    def ground(v, w):
        return 0.5 * m * _dot(v, v) + 0.5 * J * _dot(w, w)

    assert _err(imp.kinetic_energy_before, ground(c["velocity"], c["spin"]), sp.energy) < TOL
    assert _err(imp.kinetic_energy_after, ground(ref.velocity1, ref.spin1), sp.energy) < TOL
    frac = -ref.energy_change / ref.energy_before
    assert _err(imp.dissipated_fraction, frac, sp.energy / ref.energy_before) < TOL
    for name in ("newton_restitution", "poisson_restitution", "energetic_restitution"):
        np.testing.assert_allclose(getattr(imp, name), c["kappa"], rtol=0, atol=1e-12)


def test_sphere_rebound_outputs(sp):
    """Speed and angle above the plane of the rebound (against the reference's state); the
    spin after split about the direction of travel ``e_t`` (tangential part of
    ``v^+ - V_s``; from the result's own state, already checked): topspin about
    ``n x e_t``, sidespin about ``n``, gyrospin about ``e_t``. Where the ball leaves along
    the normal (``|v_t| < 1e-6 S``: head-on) ``e_t`` is ill-conditioned and those cases
    are left out; the rounding of ``e_t`` is ``eps S/|v_t|``, which scales the tolerance."""
    imp, ref, c = sp.imp, sp.ref, sp.c
    n = c["normal"]
    rel = ref.velocity1 - c["surface_velocity"]
    vt = rel - _dot(rel, n)[:, None] * n
    ok = _norm(vt) > 1e-6 * sp.speed
    assert np.mean(ok) > 0.95
    assert _err(imp.rebound_speed, _norm(ref.velocity1), sp.speed) < TOL
    angle = np.arctan2(_dot(rel, n), _norm(vt))
    assert _err(imp.rebound_angle[ok], angle[ok], sp.speed[ok] / _norm(rel[ok])) < TOL
    assert _err(imp.sidespin, _dot(ref.spin1, n), sp.speed / c["radius"]) < TOL
    rel = imp.after.velocity - c["surface_velocity"]
    vt = (rel - _dot(rel, n)[:, None] * n)[ok]
    e_t = vt / _norm(vt)[:, None]
    w = imp.after.spin[ok]
    scale = (sp.speed / c["radius"])[ok] * sp.speed[ok] / _norm(vt)
    assert _err(imp.topspin[ok], _dot(w, np.cross(n[ok], e_t)), scale) < TOL
    assert _err(imp.gyrospin[ok], _dot(w, e_t), scale) < TOL
    # rolling forward is positive topspin: a ball that grips on a plane at rest rolls
    grip = imp.grips & ok & ~c["moving"]
    np.testing.assert_allclose(imp.topspin[grip] * c["radius"][grip],
                               _norm(vt[grip[ok]]), rtol=0, atol=TOL * sp.speed.max())  # fmt: skip


# --- the 3D structure -------------------------------------------------------------------


def test_plane_motion_is_the_2d_solve(sp):
    """Impacts with ``v = (vx, vy, 0)``, ``w = (0, 0, omega)`` on the default plane equal
    ``solve(body, vx, vy, omega)`` (hence also the reference, by the tests above), and
    nothing leaves the plane."""
    c, imp = sp.c, sp.imp
    p = c["planar"]
    body = Body(mass=c["mass"][p], radius=c["radius"][p], gyration=c["gyration"][p])
    v, w = c["velocity"][p], c["spin"][p]
    assert not np.any(v[:, 2]) and not np.any(w[:, :2])
    flat = solve(body, v[:, 0], v[:, 1], w[:, 2], mu=c["mu"][p], kappa=c["kappa"][p])
    np.testing.assert_array_equal(imp.regime[p], flat.regime)
    speed = sp.speed[p]
    assert _err(imp.after.vx[p], flat.after.vx, speed) < TOL
    assert _err(imp.after.vy[p], flat.after.vy, speed) < TOL
    assert _err(c["radius"][p] * imp.after.wz[p], c["radius"][p] * flat.after.omega, speed) < TOL
    assert not np.any(imp.after.vz[p]) and not np.any(imp.after.wx[p])
    assert not np.any(imp.after.wy[p])
    assert _err(imp.friction_impulse.x[p], flat.tangential_impulse, sp.impulse[p]) < TOL
    for name in ("tau0", "tau1"):
        assert _err(getattr(imp, name)[p], getattr(flat, name), sp.impulse[p]) < TOL
    for name in (*WORKS, "dissipated_energy"):
        assert _err(getattr(imp, name)[p], getattr(flat, name), sp.energy[p]) < TOL


def test_spin_about_the_normal_is_unchanged(sp, pr):
    """Friction at ``-R n`` has no moment about ``n`` (for each ball of a pair too); the
    reference finds it from the bodies' equations, the closed forms keep it to rounding."""
    n = sp.c["normal"]
    w0 = _dot(sp.c["spin"], n)
    tol = TOL * sp.speed / sp.c["radius"]  # the spin's scale: the change can exceed |w|
    assert np.all(np.abs(_dot(sp.imp.after.spin, n) - w0) <= tol)
    assert np.all(np.abs(_dot(sp.ref.spin1, n) - w0) <= tol)
    default = ~sp.c["tilted"]
    np.testing.assert_array_equal(sp.imp.after.wy[default], sp.c["spin"][default, 1])
    n = pr.c["normal"]
    for k, after in ((1, pr.imp.after1), (2, pr.imp.after2)):
        w = pr.c[f"spin{k}"]
        tol = TOL * pr.speed / pr.c[f"radius{k}"]
        assert np.all(np.abs(_dot(after.spin, n) - _dot(w, n)) <= tol)


@pytest.mark.parametrize("sample", ["sp", "pr"])
def test_slip_keeps_its_direction(sample, request):
    """``F`` is antiparallel to the incident slip, and the slip after is the incident slip
    scaled by a factor in [0, 1] (never turned, never reversed)."""
    s = request.getfixturevalue(sample)
    before, after = s.imp.slip_before.array, s.imp.slip_after.array
    F = s.imp.friction_impulse.array
    size = _norm(before)
    moving = size > 1e-9 * s.speed
    d = before[moving] / size[moving, None]
    assert np.max(_norm(np.cross(F[moving], d)) / s.impulse[moving]) < TOL
    assert np.all(_dot(F[moving], d) <= 0)
    assert np.max(_norm(np.cross(after[moving], d)) / s.speed[moving]) < TOL
    along = _dot(after[moving], d)
    assert np.all(along >= 0)
    assert np.all(along <= size[moving] + TOL * s.speed[moving])
    # no friction impulse without friction; none without incident slip
    assert not np.any(F[s.c["mu"] == 0])
    assert np.all(_norm(F[size == 0]) == 0)


def test_the_default_plane_is_surface_none(sp):
    c = sp.c
    d = ~c["tilted"] & ~np.any(c["surface_velocity"], axis=-1)
    body = Body(mass=c["mass"][d], radius=c["radius"][d], gyration=c["gyration"][d])
    a = solve_sphere(body, c["velocity"][d], c["spin"][d], mu=c["mu"][d], kappa=c["kappa"][d])
    b = solve_sphere(body, c["velocity"][d], c["spin"][d], mu=c["mu"][d], kappa=c["kappa"][d],
                     surface=Surface())  # fmt: skip
    for name in ("velocity", "spin"):
        np.testing.assert_array_equal(getattr(a.after, name), getattr(b.after, name))
        np.testing.assert_array_equal(getattr(a.after, name), getattr(sp.imp.after, name)[d])
    np.testing.assert_array_equal(a.regime, sp.imp.regime[d])


# --- two spheres: closed forms vs reference ---------------------------------------------


def test_pair_regimes_agree(pr):
    same = _regimes_agree(pr.imp, pr.ref, pr.c["near_rest"])
    assert np.mean(same) > 0.97


@pytest.mark.parametrize("k", [1, 2])
def test_pair_states_after_agree(pr, k):
    after = getattr(pr.imp, f"after{k}")
    R = pr.c[f"radius{k}"][:, None]
    assert _err(after.velocity, getattr(pr.ref, f"velocity{k}"), pr.speed) < TOL
    assert _err(R * after.spin, R * getattr(pr.ref, f"spin{k}"), pr.speed) < TOL
    np.testing.assert_array_equal(getattr(pr.imp, f"before{k}").velocity, pr.c[f"velocity{k}"])
    np.testing.assert_array_equal(getattr(pr.imp, f"before{k}").spin, pr.c[f"spin{k}"])


def test_pair_impulses_and_contact_velocities_agree(pr):
    imp, ref = pr.imp, pr.ref
    assert _err(imp.friction_impulse.array, ref.friction, pr.impulse) < TOL
    assert _err(imp.tau0, ref.tau0, pr.impulse) < TOL
    assert _err(imp.tau1, ref.tau1, pr.impulse) < TOL
    np.testing.assert_allclose(imp.impulse_ratio * ref.tau1, _norm(ref.friction),
                               rtol=0, atol=TOL * pr.impulse.max())  # fmt: skip
    assert _err(imp.slip_before.array, ref.slip_before, pr.speed) < TOL
    assert _err(imp.slip_after.array, ref.slip_after, pr.speed) < TOL
    assert _err(imp.normal_velocity_before, ref.normal_before, pr.speed) < TOL
    assert _err(imp.normal_velocity_after, ref.normal_after, pr.speed) < TOL
    ok = ~pr.c["near_rest"]
    np.testing.assert_array_equal(np.asarray(imp.grips)[ok], (_norm(ref.slip_after) == 0)[ok])
    np.testing.assert_allclose(imp.normal.array, pr.c["normal"], rtol=0, atol=4 * EPS)


def test_pair_stick_impulse_agrees(pr):
    _stick_impulse_agrees(pr)


def test_pair_works_and_energy_agree(pr):
    _works_and_energy_agree(pr, pr.body_energy)


def test_pair_energies_and_coefficients(pr):
    """Kinetic energies of the pair; the dissipated fraction of the energy in the centre
    of mass frame (computed here from the velocities relative to the centre of mass: its
    rounding is ``eps T / T_cm``); restitution coefficients all kappa."""
    imp, ref, c = pr.imp, pr.ref, pr.c
    m1, m2 = c["mass1"], c["mass2"]
    J1, J2 = m1 * c["gyration1"] ** 2, m2 * c["gyration2"] ** 2

    def energy(v1, w1, v2, w2):
        return 0.5 * (m1 * _dot(v1, v1) + J1 * _dot(w1, w1) + m2 * _dot(v2, v2) + J2 * _dot(w2, w2))

    t0 = energy(c["velocity1"], c["spin1"], c["velocity2"], c["spin2"])
    t1 = energy(ref.velocity1, ref.spin1, ref.velocity2, ref.spin2)
    assert _err(imp.kinetic_energy_before, t0, pr.body_energy) < TOL
    assert _err(imp.kinetic_energy_after, t1, pr.body_energy) < TOL
    vc = (m1[:, None] * c["velocity1"] + m2[:, None] * c["velocity2"]) / (m1 + m2)[:, None]
    t_cm = energy(c["velocity1"] - vc, c["spin1"], c["velocity2"] - vc, c["spin2"])
    frac = imp.dissipated_energy / t_cm
    assert _err(imp.dissipated_fraction, frac, pr.body_energy / t_cm) < TOL
    for name in ("newton_restitution", "poisson_restitution", "energetic_restitution"):
        np.testing.assert_allclose(getattr(imp, name), c["kappa"], rtol=0, atol=1e-12)


def _angle(a, b):
    return np.arctan2(_norm(np.cross(a, b)), _dot(a, b))


def test_pair_angle_between_paths(pr):
    """Its cosine is the normalised dot product of the velocities after (to rounding);
    the angle itself, now atan2-based, is checked near 0 below."""
    a, b = pr.ref.velocity1, pr.ref.velocity2
    got = pr.imp.angle_between_paths
    assert np.all((got >= 0) & (got <= np.pi))
    cos = _dot(a, b) / (_norm(a) * _norm(b))
    np.testing.assert_allclose(np.cos(got), cos, rtol=0, atol=TOL)
    np.testing.assert_allclose(got, _angle(a, b), rtol=0, atol=1e-7)


def test_angle_between_nearly_parallel_paths_is_precise():
    """Found by this suite: the angle was arccos of a cosine near 1 (0 instead of 4e-9 rad);
    it is now atan2(|a x b|, a.b)."""
    b = Body.solid_sphere(mass=1.0, radius=0.1)
    imp = solve_pair(b, b, velocity1=[1e-9, 0, -1.0], spin1=[0, 0, 0], velocity2=[0, 0, 0],
                     spin2=[0, 0, 0], normal=[0, 0, 1], mu=0.0, kappa=0.5)  # fmt: skip
    # after: ball 1 (1e-9, 0, -0.25), ball 2 (0, 0, -0.75): the angle is 4e-9 rad
    want = _angle(imp.after1.velocity, imp.after2.velocity)
    assert want == pytest.approx(4e-9, rel=1e-6)
    assert float(imp.angle_between_paths) == pytest.approx(want, rel=1e-6)


def test_pair_from_centres_is_the_pair_from_the_normal(pr):
    c = pr.c
    rng = np.random.default_rng(6)
    centre2 = rng.normal(size=(N_PAIRS, 3))
    centre1 = centre2 + (c["radius1"] + c["radius2"])[:, None] * c["normal"]
    imp = solve_pair(pr.ball1, pr.ball2, velocity1=c["velocity1"], spin1=c["spin1"],
                     velocity2=c["velocity2"], spin2=c["spin2"], centres=(centre1, centre2),
                     mu=c["mu"], kappa=c["kappa"])  # fmt: skip
    # the normal recovered from the centres differs from c["normal"] by a few roundings
    # of the centres (|centre| ~ 1 m against radii down to 3 mm)
    scale = pr.speed * (1 + _norm(centre2) / (c["radius1"] + c["radius2"]))
    assert _err(imp.after1.velocity, pr.ref.velocity1, scale) < TOL
    assert _err(imp.after2.velocity, pr.ref.velocity2, scale) < TOL
    ok = ~c["near_rest"]
    np.testing.assert_array_equal(imp.regime[ok], pr.imp.regime[ok])
