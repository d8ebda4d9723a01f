"""Energy of a planar impact with coupling (spinimpact.core.planar): Kane's paradox and
which restitution laws can create energy.

Notation (module notes of :mod:`spinimpact.core.planar`): ``W = [[a, b], [b, d]]``, first
slip direction ``sigma = sign(u(0))``, the slip decays at ``alpha = a mu - sigma b`` and stops
at ``tau_s = |u(0)|/alpha``; the normal velocity rises at ``r_1 = d - mu sigma b`` before
``tau_s`` and at ``r_2`` after it (stick: ``(a d - b^2)/a``; reversal: ``d - mu |b|``).
The change of kinetic energy is ``dT = W^n + W^t`` with ``W^n = int v dtau`` and
``W^t = int u s dtau <= 0`` (Coulomb's friction never does positive work).

**Stronge's law** ends the impact where ``W^n_r = -kappa^2 W^n_c``, so
``W^n = (1 - kappa^2) W^n_c <= 0`` and ``dT <= 0``: it never creates energy.

**Poisson's law** (``tau_f = (1 + kappa) tau_c``) never creates energy either, for one contact
of a free planar body on a fixed plane. On paper, case by case:

* one phase up to ``tau_f`` (frictionless, no-slip, slip, slip-from-rest, any
  ``tau_s >= tau_f``): ``v`` is one line of slope ``r``, ``W^n = r tau_c^2 (kappa^2 - 1)/2 <= 0``.
* the normal rate falls at ``tau_s`` (``r_2 <= r_1``: every reversal, since ``r_1 - r_2 =
  2 mu |b|``; and stick with ``sigma b <= 0``). Slip stops in compression (``x = tau_s``,
  ``y = tau_c - tau_s``): ``2 W^n = r_2 kappa^2 (x + y)^2 - (r_1 x^2 + 2 r_2 x y + r_2 y^2)
  <= r_2 (x + y)^2 (kappa^2 - 1) - (r_1 - r_2) x^2 <= 0``; in restitution (``w = tau_f -
  tau_s``): ``2 W^n = r_1 tau_c^2 (kappa^2 - 1) + (r_2 - r_1) w^2 <= 0``.
* stick with ``sigma b > 0``: the rate rises at ``tau_s`` by ``r_2 - r_1 = sigma b alpha / a``
  and ``W^n`` can be positive, but the friction work of the first phase,
  ``-mu |u(0)| tau_s / 2 = -mu alpha x^2 / 2``, pays for it. In compression
  ``2 dT = r_2 kappa^2 (x + y)^2 - r_1 x^2 - 2 r_2 x y - r_2 y^2 - mu alpha x^2`` grows with
  ``kappa`` and at ``kappa = 1`` equals ``(r_2 - r_1 - mu alpha) x^2 = -alpha^2 x^2 / a``:
  ``dT = -u(0)^2 / (2a)`` exactly, whatever ``b``, ``d`` and ``mu``. In restitution
  ``2 dT = r_1 tau_c^2 (kappa^2 - 1) + (sigma b / a) alpha w^2 - mu alpha tau_s^2 < 0``
  because ``sigma b / a < mu`` and ``w <= kappa tau_c < tau_s``.

**Newton's law** (``v(tau_f) = -kappa v(0)``) is where the paradox lives: when the normal
rate falls at ``tau_s`` in compression, the restitution at the slower rate ``r_2`` takes
more impulse than the compression did, ``W^n = (kappa^2 v(0)^2 - v_s^2)/(2 r_2) -
(v(0)^2 - v_s^2)/(2 r_1)``, which for ``kappa`` near 1 exceeds the friction loss (Kane and
Levinson 1985; Stronge 2000, sec. 5.4).

Tolerance: energies relative to ``m (|u(0)| + |v(0)|)^2 cond(W)`` plus the body's kinetic
energy (the reference's energies are differences of it), ``TOL = 256 eps`` as in
``test_planar.py``.
"""

from fractions import Fraction

import numpy as np
import pytest

from spinimpact.core.impulse import planar_collision_matrix
from spinimpact.core.planar import planar_process, planar_work

from tests.planar_reference import integrate, random_planar_cases

EPS = np.finfo(float).eps
TOL = 256 * EPS
N = 12_000
NEWTON, POISSON, STRONGE = 0, 1, 2
BODY = ("mass", "inertia", "rx", "ry", "vx", "vy", "omega")


def _closed(c, law, kappa=None):
    """Closed-form process, normal and friction works in compression and restitution."""
    kappa = c["kappa"] if kappa is None else kappa
    w = planar_collision_matrix(c["mass"], c["inertia"], c["rx"], c["ry"])
    args = (c["slip"], c["vn"], w.tt, w.tn, w.nn, c["mu"])
    p = planar_process(*args, kappa, law)
    comp = planar_work(0.0, p.tau_compression, *args, p.tau_slip)
    rest = planar_work(p.tau_compression, p.tau_end, *args, p.tau_slip)
    return p, comp, rest, w


def _scale(c):
    cond = 1 + c["mass"] * (c["rx"] ** 2 + c["ry"] ** 2) / c["inertia"]
    t0 = 0.5 * (c["mass"] * (c["vx"] ** 2 + c["vy"] ** 2) + c["inertia"] * c["omega"] ** 2)
    return c["mass"] * (np.abs(c["slip"]) + np.abs(c["vn"])) ** 2 * cond + t0


@pytest.fixture(scope="module")
def cases():
    return random_planar_cases(N, seed=77)


# --- (a) Kane's paradox ----------------------------------------------------------------------


def _rod(kappa):
    """A uniform slender rod, m = 1 kg, L = 1 m, at 45 degrees, struck at its lower end."""
    m, length = 1.0, 1.0
    half = length / 2 * np.sqrt(0.5)
    c = dict(mass=m, inertia=m * length**2 / 12, rx=-half, ry=-half, vx=0.5, vy=-1.0, omega=0.0)
    c.update(slip=0.5, vn=-1.0, mu=1.0, kappa=kappa)
    return c


@pytest.mark.parametrize(
    ("kappa_exact", "gain_exact", "tau_f", "friction"),
    [
        (Fraction(1), Fraction(7, 64), Fraction(17, 16), Fraction(7, 16)),
        (Fraction(9, 10), Fraction(1, 20), Fraction(1), Fraction(2, 5)),
    ],
    ids=["kappa=1", "kappa=0.9"],
)
def test_kane_paradox_newton_creates_energy(kappa_exact, gain_exact, tau_f, friction):
    """Kane's paradox, concretely: a uniform slender rod (m = 1 kg, L = 1 m, J = 1/12 kg m^2)
    inclined at 45 degrees, its centre of mass up and to the right of the contact end
    (r = (-sqrt(2)/4, -sqrt(2)/4) m), falls at (vx, vy) = (0.5, -1) m/s without spin onto a
    plane with mu = 1. T(0) = 0.625 J. W = [[2.5, -1.5], [-1.5, 2.5]] 1/kg.

    The contact slides forward (u = 0.5 m/s); sigma b = -1.5 < 0, so the slip decays at
    alpha = a mu - sigma b = 4 and stops at tau_s = 0.125 N s, with v = -0.5 m/s; the cone
    holds it (|b|/a = 0.6 <= 1) and v rises at r_2 = (ad - b^2)/a = 1.6, slower than the
    r_1 = 4 before: tau_c = 0.4375 N s (stick-compression).

    Newton with kappa = 1 ends at v = 1 m/s, tau_f = 1.0625 N s, f = 0.4375 N s (u(tau_f) = 0):
    dT = +0.109375 J (+17.5 % of T(0)); W^n = +0.140625 J, W^t = -0.03125 J. Its Poisson
    coefficient is 1.43 and its energetic one 1.35 (both > 1). With kappa = 0.9: tau_f = 1,
    f = 0.4, dT = +0.05 J (+8 %). The same rod under Poisson's law loses 0.05 J (= u(0)^2/(2a))
    and under Stronge's 0.03125 J (the friction work alone) at kappa = 1.
    """
    kappa, gain = float(kappa_exact), float(gain_exact)
    c = _rod(kappa)
    # the numbers above, in exact arithmetic from the definitions
    a, b, d = Fraction(5, 2), Fraction(-3, 2), Fraction(5, 2)
    u0, v0, mu, k = Fraction(1, 2), Fraction(-1), Fraction(1), kappa_exact
    ts = u0 / (a * mu - b)  # sigma = +1
    vs = v0 + (d - mu * b) * ts
    r2 = (a * d - b * b) / a
    tc = ts - vs / r2
    tf = tc - k * v0 / r2  # Newton: v rises at r_2 to -kappa v(0)
    f = -mu * ts + (-b / a) * (tf - ts)
    dT = ((u0 + 0) * f + (v0 - k * v0) * tf) / 2  # dT = (c(0) + c(tau_f)) . p / 2
    assert (ts, tc) == (Fraction(1, 8), Fraction(7, 16))
    assert (tf, f, dT) == (tau_f, friction, gain_exact)

    p, comp, rest, w = _closed(c, NEWTON)
    np.testing.assert_allclose([w.tt, w.tn, w.nn], [2.5, -1.5, 2.5], rtol=4 * EPS)
    assert p.regime == 2  # stick-compression
    np.testing.assert_allclose([p.tau_slip, p.tau_compression], [0.125, 0.4375], rtol=8 * EPS)
    want = [float(tau_f), float(friction)]
    np.testing.assert_allclose([p.tau_end, p.friction_impulse], want, rtol=8 * EPS)
    closed_gain = comp[0] + comp[1] + rest[0] + rest[1]
    ref = integrate(*(c[k] for k in BODY), c["mu"], kappa, NEWTON)
    t0 = 0.625
    np.testing.assert_allclose(closed_gain, gain, rtol=0, atol=TOL * t0)
    np.testing.assert_allclose(ref.energy_change, gain, rtol=0, atol=TOL * t0)
    assert closed_gain > 0.07 * t0 and ref.energy_change > 0.07 * t0  # energy is created
    # the other two laws dissipate on the same rod
    for law in (POISSON, STRONGE):
        ref = integrate(*(c[k] for k in BODY), c["mu"], kappa, law)
        assert ref.energy_change < -0.04 * t0
    if kappa == 1.0:
        assert float(_closed(c, POISSON)[1][0] + sum(_closed(c, POISSON)[2])) < 0
        ref = integrate(*(c[k] for k in BODY), c["mu"], 1.0, POISSON)
        np.testing.assert_allclose(ref.energy_change, -0.05, rtol=0, atol=TOL * t0)


def test_newton_creates_energy_only_where_the_slip_stops_or_reverses(cases):
    """Over 12,000 random bodies at kappa = 1: Newton's law creates energy in a sizeable
    share of them (closed form and reference agree on the gain), and only in the regimes
    where the slip stops or reverses (2, 3, 5, 6)."""
    c = cases
    p, comp, rest, _ = _closed(c, NEWTON, kappa=1.0)
    dT = comp[0] + comp[1] + rest[0] + rest[1]
    ref = integrate(*(c[k] for k in BODY), c["mu"], 1.0, NEWTON)
    scale = _scale(c)
    assert np.max(np.abs(dT - ref.energy_change) / scale) < TOL
    gain = dT > TOL * scale
    assert gain.sum() > 500, gain.sum()
    assert set(np.unique(p.regime[gain])) <= {2, 3, 5, 6}
    t0 = 0.5 * (c["mass"] * (c["vx"] ** 2 + c["vy"] ** 2) + c["inertia"] * c["omega"] ** 2)
    assert np.max(dT / t0) > 0.1  # not a rounding artefact: tens of percent of T(0)


# --- (b) Poisson and Stronge never create energy ---------------------------------------------


@pytest.mark.parametrize("law", [POISSON, STRONGE], ids=["poisson", "stronge"])
@pytest.mark.parametrize("kappa", ["random", 1.0])
@pytest.mark.slow
def test_poisson_and_stronge_never_create_energy(cases, law, kappa):
    """dT <= 0 on 12,000 random bodies, by the closed form and by the reference (derivation
    in the module docstring). With kappa = 1 the bound is tightest."""
    c = cases
    k = c["kappa"] if kappa == "random" else kappa
    p, comp, rest, _ = _closed(c, law, kappa=k)
    dT = comp[0] + comp[1] + rest[0] + rest[1]
    ref = integrate(*(c[key] for key in BODY), c["mu"], k, law)
    scale = _scale(c)
    assert np.max(dT / scale) < TOL
    assert np.max(ref.energy_change / scale) < TOL
    assert np.max(np.abs(dT - ref.energy_change) / scale) < TOL
    # the same sample is not tame: Newton creates energy on it at kappa = 1
    if kappa == 1.0:
        newton = _closed(c, NEWTON, kappa=1.0)
        assert np.max(sum(newton[1]) + sum(newton[2])) > 0


def test_poisson_normal_work_can_be_positive_but_friction_pays_for_it(cases):
    """Poisson at kappa = 1, stick-compression with sigma b > 0: W^n > 0 occurs, and the
    total is exactly dT = -u(0)^2/(2 a) (the derivation's identity), so the bound in the
    module docstring is not slack by accident."""
    c = cases
    p, comp, rest, w = _closed(c, POISSON, kappa=1.0)
    wn = comp[0] + rest[0]
    dT = wn + comp[1] + rest[1]
    sigma_b = np.sign(c["slip"]) * w.tn
    sel = (p.regime == 2) & (sigma_b > 0)
    assert sel.sum() > 300
    scale = _scale(c)
    assert np.sum(wn[sel] > 1e-6 * scale[sel]) > 50  # the normal impulse does net work
    want = -(c["slip"] ** 2) / (2 * w.tt)
    assert np.max(np.abs(dT - want)[sel] / scale[sel]) < TOL
    # and for any b in stick-compression (the identity did not use the sign of b)
    stick = p.regime == 2
    assert np.max(np.abs(dT - want)[stick] / scale[stick]) < TOL


# --- (c) Stronge's law -----------------------------------------------------------------------


def test_stronge_restitution_work_is_minus_kappa_squared_compression(cases):
    """By definition W^n_r = -kappa^2 W^n_c (closed form and reference), and the total energy
    change (1 - kappa^2) W^n_c + W^t <= 0."""
    c = cases
    p, comp, rest, _ = _closed(c, STRONGE)
    scale = _scale(c)
    assert np.max(np.abs(rest[0] + c["kappa"] ** 2 * comp[0]) / scale) < TOL
    ref = integrate(*(c[k] for k in BODY), c["mu"], c["kappa"], STRONGE)
    resid = ref.work_restitution_normal + c["kappa"] ** 2 * ref.work_compression_normal
    assert np.max(np.abs(resid) / scale) < TOL
    dT = comp[0] + comp[1] + rest[0] + rest[1]
    want = (1 - c["kappa"] ** 2) * comp[0] + comp[1] + rest[1]
    assert np.max(np.abs(dT - want) / scale) < TOL
    assert np.all(dT <= TOL * scale)
    assert np.all(comp[1] <= 0) and np.all(rest[1] <= 0)
    # the minimum of T along the path is not above its end value
    assert np.all(ref.energy_min <= ref.energy_change + TOL * scale)


# --- (d) the paper's bodies: the three coefficients coincide ---------------------------------


def _coefficients(c, law):
    """Newton -v(tau_f)/v(0), Poisson (tau_f - tau_c)/tau_c and energetic^2 -W^n_r/W^n_c."""
    p, comp, rest, _ = _closed(c, law)
    newton = -p.normal_after / c["vn"]
    poisson = (p.tau_end - p.tau_compression) / p.tau_compression
    energetic_sq = -rest[0] / comp[0]
    return newton, poisson, energetic_sq


@pytest.mark.parametrize("law", [NEWTON, POISSON, STRONGE], ids=["newton", "poisson", "stronge"])
def test_paper_body_coefficients_coincide(cases, law):
    """With r = (0, -R) (W_tn = 0) each law gives a process whose Newton, Poisson and
    energetic coefficients all equal kappa (to rounding); on the random coupled bodies they
    do not (the test can tell)."""
    c = dict(cases)
    c["ry"] = -np.hypot(c["rx"], c["ry"])
    c["rx"] = np.zeros(N)
    newton, poisson, energetic_sq = _coefficients(c, law)
    k = c["kappa"]
    cond = 1 + c["mass"] * c["ry"] ** 2 / c["inertia"]
    tol = TOL * cond
    assert np.max(np.abs(newton - k)) < tol.max()
    assert np.max(np.abs(poisson - k) / cond) < TOL
    assert np.max(np.abs(energetic_sq - k**2) / cond) < TOL
    # coupled bodies: the coefficients the other laws would report differ from kappa
    newton, poisson, energetic_sq = _coefficients(cases, law)
    spread = np.abs(newton - k) + np.abs(poisson - k) + np.abs(np.sqrt(energetic_sq) - k)
    assert np.sum(spread > 1e-3) > 1000
