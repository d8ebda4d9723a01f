r"""The per-contact law on plain numbers: one impact, no arrays (the paper's bodies, the seam).

The array kernels (:mod:`spinimpact.core.impulse`, :mod:`spinimpact.core.works`,
:mod:`spinimpact.core.kinematics`) evaluate each quantity with ``where`` over whole arrays.
The functions here take Python floats and return floats, ints, bools or tuples of them,
performing **the same IEEE operations in the same order** as those kernels, so their results
are equal bit for bit (``tests/core/test_law.py`` checks this on random impacts in every
regime). They are written in the subset of Python that Numba compiles, and
:mod:`spinimpact.core.law` registers them so that a user's ``numba.njit`` code may call
them; called from Python they are plain Python (``solve`` uses them for one impact).

Contact-level functions take the seam's arguments (:mod:`spinimpact.core.impulse`):
``slip = c_t^-`` and ``vy = c_n^- < 0`` (m/s), ``mass = 1/W_nn`` (kg),
``zeta = W_tt/W_nn``, ``mu >= 0``, ``kappa`` in ``[0, 1]``. Body-level functions take the
paper's incidence ``(vx, vy, omega)`` and body ``(mass, radius, zeta)`` and form the slip
``u = vx + R omega`` (eq. 4.4). Nothing is validated: pass what :func:`spinimpact.solve`
accepts. Equation numbers are those of Lubarda [1]_.

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed surface",
   Proceedings of the Section of Natural Sciences, Montenegrin Academy of Sciences and Arts
   (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
"""

from __future__ import annotations

import math

__all__ = [
    "sign",
    "regime_code",
    "stick_impulse",
    "contact_impulses",
    "work_tangential",
    "contact_works",
    "contact_dissipated_energy",
    "contact_min_energy_impulse",
    "min_energy_case",
    "contact_impact",
    "rebound_slip",
    "impulse_ratio",
    "work_ratio_tangential",
    "rebound",
    "regime",
    "impulses",
    "dissipated_energy",
    "kinetic_energy",
    "outcome_flags",
    "approaching",
]

#: Relative tolerance of the outcome flags' equalities (:mod:`spinimpact.core.outcomes`).
_RTOL = 16 * 2.220446049250313e-16


def sign(x):
    """``numpy.sign`` of one float: ``1.0``, ``-1.0`` or ``0.0`` (``NaN`` stays ``NaN``)."""
    if x > 0.0:
        return 1.0
    if x < 0.0:
        return -1.0
    if x == 0.0:
        return 0.0  # +0.0 for -0.0 too, as numpy.sign
    return x  # NaN


def _minimum(a, b):
    return a if a < b else b  # numpy.minimum for non-NaN operands: b when equal (signed zeros)


def _maximum(a, b):
    return a if a > b else b


def regime_code(slip, vy, zeta, mu, kappa):
    """Code of the regime, as :func:`spinimpact.core.impulse.regime_code`.

    Returns
    -------
    int
        ``0`` frictionless, ``1`` no-slip, ``2`` stick-compression, ``3``
        stick-restitution, ``4`` slip (eqs. 4.6, 4.14, 4.15).
    """
    if mu == 0.0:
        return 0
    if slip == 0.0:
        return 1
    speed = abs(slip)
    early = speed <= zeta * mu * abs(vy)
    stick = speed <= (1.0 + kappa) * zeta * mu * abs(vy)
    return 4 - int(stick) - int(early)


def stick_impulse(mass, slip, zeta, mu):
    """Normal impulse ``tau_*`` at which the slip stops (eq. 4.3), N s.

    ``0`` where ``slip = 0``, ``inf`` where ``mu = 0`` and ``slip != 0``.
    """
    num = mass * abs(slip)
    if num == 0.0:
        return 0.0
    den = zeta * mu
    return num / den if den > 0.0 else math.inf


def contact_impulses(slip, vy, mass, zeta, mu, kappa):
    """The impulses of the impact at the contact point (eqs. 3.2, 3.6, 4.3, 5.7).

    Returns
    -------
    tuple of float
        ``(tau0, tau_star, tau1, f1)``, N s: end of compression, end of slip, end of the
        impact, and the friction impulse ``f_1 = -mu sign(u^-) min(tau_*, tau_1)``.
    """
    tau0 = -mass * vy
    tau1 = (1.0 + kappa) * tau0
    if abs(slip) <= (1.0 + kappa) * zeta * mu * abs(vy):  # sticks (eq. 4.6)
        f1 = -mass * slip / zeta + 0.0
    else:
        f1 = -mu * sign(slip) * tau1 + 0.0
    return tau0, stick_impulse(mass, slip, zeta, mu), tau1, f1


def _friction_work(a, b, tau_star, speed, rate, mu):
    lo = _minimum(a, tau_star)
    hi = _minimum(b, tau_star)
    speed_lo = _maximum(speed - rate * lo, 0.0)
    speed_hi = _maximum(speed - rate * hi, 0.0)
    return -mu * (hi - lo) * (speed_lo + speed_hi) / 2.0


def work_tangential(a, b, mass, slip, zeta, mu):
    """Work of friction between the normal impulses ``a <= b`` (eqs. 5.8, 6.1, 6.2), J."""
    tau_star = stick_impulse(mass, slip, zeta, mu)
    return _friction_work(a, b, tau_star, abs(slip), zeta * mu / mass, mu)


def _work_normal(a, b, mass, vy):
    return (b - a) * (2.0 * vy + (a + b) / mass) / 2.0


def contact_works(slip, vy, mass, zeta, mu, kappa):
    """Works of the normal and friction forces by phase (eqs. 6.1, 6.2).

    Returns
    -------
    tuple of float
        ``(W_c^n, W_c^t, W_r^n, W_r^t)``, J.
    """
    tau0 = -mass * vy
    tau1 = (1.0 + kappa) * tau0
    zero = 0.0 * tau0
    return (
        _work_normal(zero, tau0, mass, vy),
        work_tangential(zero, tau0, mass, slip, zeta, mu),
        _work_normal(tau0, tau1, mass, vy),
        work_tangential(tau0, tau1, mass, slip, zeta, mu),
    )


def contact_dissipated_energy(slip, vy, mass, zeta, mu, kappa):
    """Energy lost in the impact, ``Delta E >= 0`` (eqs. 5.1, 5.10), J."""
    tau1 = (1.0 + kappa) * (-mass * vy)
    normal = 0.5 * mass * vy * vy * (1.0 - kappa * kappa)
    return normal - work_tangential(0.0 * tau1, tau1, mass, slip, zeta, mu)


def contact_min_energy_impulse(slip, vy, mass, zeta, mu, kappa):
    """Normal impulse ``tau_m`` of least kinetic energy (eqs. 8.2-8.6), N s."""
    if abs(slip) <= zeta * mu * abs(vy):  # sticks in compression: tau_m = tau_0
        return -mass * vy
    sliding = mass * (abs(vy) + mu * abs(slip)) / (1.0 + zeta * mu * mu)
    return _minimum(sliding, (1.0 + kappa) * (-mass * vy))


def min_energy_case(code, tau_m, tau1):
    """Index into :data:`spinimpact.core.works.MIN_ENERGY_CASES` from the regime ``code``,
    ``tau_m`` and ``tau_1`` (as :func:`spinimpact.core.works.contact_min_energy_case`)."""
    if code == 0:
        return 4
    if code <= 2:
        return 1
    if code == 3:
        return 0
    return 2 if tau_m < tau1 else 3


def rebound_slip(slip, vy, zeta, mu, kappa):
    """Slip after the impact, ``u^+`` (eqs. 4.16, 7.11), m/s."""
    if abs(slip) <= (1.0 + kappa) * zeta * mu * abs(vy):
        return 0.0
    return slip - sign(slip) * (1.0 + kappa) * zeta * mu * abs(vy) + 0.0


def impulse_ratio(slip, vy, zeta, mu, kappa):
    """Tangential impact coefficient ``mu_hat = f_1/tau_1`` (eqs. 7.4, 7.8, 7.9)."""
    if abs(slip) <= (1.0 + kappa) * zeta * mu * abs(vy):
        return slip / ((1.0 + kappa) * zeta * vy) + 0.0
    return -mu * sign(slip) + 0.0


def work_ratio_tangential(ratio, zeta, mu, kappa):
    """``W_r^t/W_c^t`` from the incidence ratio (eqs. 6.15-6.18); NaN without friction work."""
    if not (mu > 0.0 and ratio > 0.0):
        return math.nan
    x = ratio / (zeta * mu)
    if x <= 1.0:
        return 0.0
    if x <= 1.0 + kappa:
        return (x - 1.0) * (x - 1.0) / (2.0 * x - 1.0)
    return kappa * (1.0 - (1.0 + kappa) / (2.0 * x - 1.0))


def contact_impact(slip, vy, mass, zeta, mu, kappa):
    """Everything the seam says about one impact, in one call (for ``solve`` and siblings).

    Returns
    -------
    tuple
        ``(tau0, tau_star, tau1, f1, slip_after, impulse_ratio, regime_code, W_c^n, W_c^t,
        W_r^n, W_r^t, dissipated_energy, tau_m, min_energy_case)``: the values of
        :func:`contact_impulses`, :func:`rebound_slip`, :func:`impulse_ratio`,
        :func:`regime_code`, :func:`contact_works`, :func:`contact_dissipated_energy`,
        :func:`contact_min_energy_impulse` and :func:`min_energy_case`, bit for bit.
    """
    speed = abs(slip)
    w = abs(vy)
    tau0 = -mass * vy
    tau1 = (1.0 + kappa) * tau0
    tau_star = stick_impulse(mass, slip, zeta, mu)
    early = speed <= zeta * mu * w
    stick = speed <= (1.0 + kappa) * zeta * mu * w
    s = sign(slip)
    if stick:
        f1 = -mass * slip / zeta + 0.0
        slip_after = 0.0
        ratio = slip / ((1.0 + kappa) * zeta * vy) + 0.0
    else:
        f1 = -mu * s * tau1 + 0.0
        slip_after = slip - s * (1.0 + kappa) * zeta * mu * w + 0.0
        ratio = -mu * s + 0.0
    code = 0 if mu == 0.0 else (1 if slip == 0.0 else 4 - int(stick) - int(early))
    rate = zeta * mu / mass
    zero = 0.0 * tau0
    wct = _friction_work(zero, tau0, tau_star, speed, rate, mu)
    wrt = _friction_work(tau0, tau1, tau_star, speed, rate, mu)
    normal = 0.5 * mass * vy * vy * (1.0 - kappa * kappa)
    loss = normal - _friction_work(0.0 * tau1, tau1, tau_star, speed, rate, mu)
    if early:
        tau_m = tau0
    else:
        tau_m = _minimum(mass * (w + mu * speed) / (1.0 + zeta * mu * mu), tau1)
    return (
        tau0, tau_star, tau1, f1, slip_after, ratio, code,
        _work_normal(zero, tau0, mass, vy), wct, _work_normal(tau0, tau1, mass, vy), wrt,
        loss, tau_m, min_energy_case(code, tau_m, tau1),
    )  # fmt: skip


def rebound(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Rebound of one of the paper's bodies (eqs. 2.1-2.3, 4.13, 4.16).

    Parameters
    ----------
    vx, vy, omega : float
        Incidence velocity of the centre (m/s, ``vy < 0``) and spin (rad/s, counter-clockwise).
    mass, radius, zeta : float
        Mass (kg), contact radius (m) and ``zeta = 1 + R^2/rho^2``.
    mu, kappa : float
        Coulomb friction (``>= 0``) and normal restitution (in ``[0, 1]``).

    Returns
    -------
    tuple of float
        ``(vx^+, vy^+, omega^+, f_1)``: as :func:`spinimpact.core.kinematics.rebound`.

    Examples
    --------
    >>> vx, vy, omega, f1 = rebound(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8)
    >>> round(vx / 2.0, 12), vy   # the 5/7 rule; vy+ = -kappa vy-
    (0.714285714286, 2.4000000000000004)
    """
    slip = vx + radius * omega
    if abs(slip) <= (1.0 + kappa) * zeta * mu * abs(vy):
        f1 = -mass * slip / zeta + 0.0
    else:
        f1 = -mu * sign(slip) * ((1.0 + kappa) * (-mass * vy)) + 0.0
    return (
        vx + f1 / mass,
        -kappa * vy + 0.0,
        omega + (zeta - 1.0) * f1 / (mass * radius),
        f1,
    )


def regime(vx, vy, omega, radius, zeta, mu, kappa):
    """Regime code of one of the paper's bodies (:func:`regime_code` of ``u = vx + R omega``);
    ``spinimpact.core.REGIMES[code]`` names it."""
    return regime_code(vx + radius * omega, vy, zeta, mu, kappa)


def impulses(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """``(tau0, tau_star, tau1, f1)`` of one of the paper's bodies, N s
    (:func:`contact_impulses` of ``u = vx + R omega``)."""
    return contact_impulses(vx + radius * omega, vy, mass, zeta, mu, kappa)


def dissipated_energy(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Energy one of the paper's bodies loses, J (:func:`contact_dissipated_energy`).

    Examples
    --------
    >>> round(dissipated_energy(1.0, -1.0, 0.0, 1.0, 0.1, 3.0, 0.2, 0.5), 12)  # eq. (5.6)
    0.54
    """
    return contact_dissipated_energy(vx + radius * omega, vy, mass, zeta, mu, kappa)


def kinetic_energy(vx, vy, omega, mass, inertia):
    """``m (vx^2 + vy^2)/2 + J omega^2/2``, J (as :func:`spinimpact.core.kinetic_energy`)."""
    return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * omega * omega


def outcome_flags(vx, vy, omega, radius, zeta, mu, kappa):
    """The rebound outcome flags of :func:`spinimpact.core.outcomes.rebound_outcomes`.

    Returns
    -------
    tuple of bool
        ``(backward, reversed_spin, vertical, spinning, rolling)``.
    """
    a = vx
    b = radius * omega
    w = abs(vy)
    u = a + b
    s = sign(u)
    c = (1.0 + kappa) * mu * w
    stick = abs(u) <= (1.0 + kappa) * zeta * mu * abs(vy)
    za = (zeta - 1.0) * a
    if stick:
        gx = za - b
        gw = b - za
        size_x = abs(za) + abs(b)
        size_w = size_x
    else:
        gx = zeta * (a - s * c)
        gw = zeta * (b - s * (zeta - 1.0) * c)
        size_x = zeta * (abs(a) + c)
        size_w = zeta * (abs(b) + (zeta - 1.0) * c)
    zero_x = abs(gx) <= _RTOL * size_x
    zero_w = abs(gw) <= _RTOL * size_w
    backward = a != 0.0 and not zero_x and sign(gx) == -sign(a)
    reversed_spin = b != 0.0 and not zero_w and sign(gw) == -sign(b)
    return backward, reversed_spin, zero_x, not zero_w, stick


def approaching(vy):
    """Whether the contact point approaches the surface: ``c_n^- < 0`` (the paper's
    ``v^- < 0``, section 3), the condition for an impact to happen at all.

    Parameters
    ----------
    vy : float
        Normal velocity of the contact point, m/s: for the paper's bodies the centre's ``vy``
        (the contact point moves normally with the centre, ``W_tn = 0``); for any contact of
        the seam, its ``c_n``.

    Returns
    -------
    bool
        ``True`` for ``vy < 0``; ``False`` for a contact at rest or separating (and NaN),
        which no law here may be given: :func:`rebound` of ``vy = +2`` would return a
        meaningless ``vy+ < 0``. (:func:`spinimpact.solve` also refuses an approach slower
        than ``1e-50`` m/s as grazing.)

    Examples
    --------
    >>> approaching(-3.0), approaching(2.0), approaching(0.0)
    (True, False, False)
    """
    return vy < 0.0
