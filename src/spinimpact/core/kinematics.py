"""Impulses, regimes and rebound velocities (paper sections 2-4 and 7).

All functions are pure NumPy kernels: arrays in, arrays out, broadcasting
over any number of impacts, no validation (the model layer validates).

Notation (SI units)
-------------------
``vx, vy, omega``
    Incidence velocity of the centre (``vy < 0``) and spin (counter-clockwise
    positive); the paper's ``u_C^-``, ``v^-``, ``omega^-``.
``mass, radius, zeta``
    Mass ``m``, contact radius ``R`` and ``zeta = 1 + R**2/rho**2``.
``mu, kappa``
    Kinetic Coulomb friction coefficient and coefficient of normal restitution.
``slip``
    Horizontal velocity of the contact point, ``u = vx + R*omega`` (eq. 4.4).
"""

from __future__ import annotations

from ._xp import arrays, quiet

__all__ = [
    "REGIMES",
    "slip_velocity",
    "incidence_ratio",
    "compression_impulse",
    "total_impulse",
    "stick_impulse",
    "sticks",
    "sticks_in_compression",
    "regime_code",
    "regime_thresholds",
    "rebound_slip",
    "friction_impulse_at",
    "force_ratio_at",
    "slip_at",
    "state_at",
    "tangential_impulse",
    "rebound",
    "impulse_ratio",
    "restitution_coefficients",
    "velocity_ratios",
]

#: Names of the impact regimes, indexed by the codes of :func:`regime_code`.
REGIMES = ("frictionless", "no-slip", "stick-compression", "stick-restitution", "slip")


def slip_velocity(vx, omega, radius):
    """Horizontal velocity of the contact point, ``u = u_C + R*omega`` (eq. 4.4)."""
    return vx + radius * omega


def incidence_ratio(slip, vy):
    """The incidence ratio ``|u^-/v^-|`` that selects the regime (eqs. 4.6, 4.14, 4.15)."""
    xp, (slip, vy) = arrays(slip, vy)
    return xp.abs(slip) / xp.abs(vy)


def compression_impulse(mass, vy):
    """Normal impulse at the end of compression, ``tau_0 = -m v^-`` (eq. 3.2)."""
    return -mass * vy


def total_impulse(mass, vy, kappa):
    """Total normal impulse, ``tau_1 = (1 + kappa) tau_0`` (eq. 3.6).

    Poisson's restitution ``(tau_1 - tau_0)/tau_0 = kappa`` (eq. 1.2) fixes the end
    of the impact.
    """
    return (1.0 + kappa) * compression_impulse(mass, vy)


def stick_impulse(mass, slip, zeta, mu):
    """Normal impulse at which the contact point stops slipping (eq. 4.3).

    ``tau_* = m |u^-| / (zeta mu)``, from integrating ``m du = zeta (F/N) dtau``
    (eq. 4.1) with ``F/N = -mu sign(u^-)`` until ``u = 0``.

    Returns ``0`` where ``u^- = 0`` (there is no slip to end, whatever ``mu``) and
    ``+inf`` where ``mu = 0`` and ``u^- != 0`` (a frictionless contact never sticks).
    """
    xp, (mass, slip, zeta, mu) = arrays(mass, slip, zeta, mu)
    num = mass * xp.abs(slip)
    den = zeta * mu
    with quiet(xp, divide="ignore", invalid="ignore", over="ignore"):  # tiny mu: tau_* -> inf
        tau = xp.where(den > 0, num / xp.where(den > 0, den, 1.0), xp.inf)
    return xp.where(num == 0, 0.0, tau)


def sticks(slip, vy, zeta, mu, kappa):
    """True where the slip stops before the impact ends, ``tau_* <= tau_1`` (eq. 4.6).

    Evaluated as ``|u^-| <= (1 + kappa) zeta mu |v^-|``, free of the mass and of
    divisions. This one comparison decides stick versus slip for every result
    (regime, rebound, ``u^+``, outcome flags), so they never disagree at the
    boundary, where the two closed forms coincide anyway.
    """
    xp, (slip, vy) = arrays(slip, vy)
    return xp.abs(slip) <= (1.0 + kappa) * zeta * mu * xp.abs(vy)


def sticks_in_compression(slip, vy, zeta, mu):
    """True where the slip stops by the end of compression, ``tau_* <= tau_0`` (eq. 4.14).

    Evaluated as ``|u^-| <= zeta mu |v^-|``.
    """
    xp, (slip, vy) = arrays(slip, vy)
    return xp.abs(slip) <= zeta * mu * xp.abs(vy)


def regime_code(slip, vy, zeta, mu, kappa):
    """Integer code of the impact regime; ``REGIMES[code]`` names it.

    ===  =====================  ==============================================
    0    ``frictionless``       ``mu = 0``
    1    ``no-slip``            ``u^- = 0`` (and ``mu > 0``)
    2    ``stick-compression``  ``tau_* <= tau_0``, i.e. ``|u^-/v^-| <= zeta mu`` (eq. 4.14)
    3    ``stick-restitution``  ``tau_0 < tau_* <= tau_1`` (eqs. 4.6, 4.14)
    4    ``slip``               ``tau_* > tau_1``, i.e. ``|u^-/v^-| > (1+kappa) zeta mu`` (eq. 4.15)
    ===  =====================  ==============================================
    """
    xp, (slip, vy, mu) = arrays(slip, vy, mu)
    early = xp.astype(sticks_in_compression(slip, vy, zeta, mu), xp.int8)
    stick = xp.astype(sticks(slip, vy, zeta, mu, kappa), xp.int8)
    code = 4 - stick - early  # 2, 3 or 4: early sticking implies sticking
    code = xp.where(slip == 0, xp.asarray(1, dtype=xp.int8), code)
    return xp.where(mu == 0, xp.asarray(0, dtype=xp.int8), code)


def regime_thresholds(zeta, mu, kappa):
    """Incidence ratios ``|u^-/v^-|`` that bound the regimes: ``zeta mu`` (eq. 4.14)
    and ``(1 + kappa) zeta mu`` (eqs. 4.6, 4.15)."""
    return zeta * mu, (1.0 + kappa) * zeta * mu


def friction_impulse_at(tau, mass, slip, zeta, mu):
    """Friction impulse ``f(tau)`` accumulated up to normal impulse ``tau`` (eqs. 7.1-7.3).

    ``f = -mu sign(u^-) tau`` while slipping (``tau < tau_*``) and
    ``f = -mu sign(u^-) tau_* = -m u^-/zeta`` afterwards, the last form being the
    exact value of ``mu tau_*`` (eq. 4.3), independent of ``mu``. This is Routh's
    impact diagram (Fig. 4).
    """
    xp, (tau, slip, mu) = arrays(tau, slip, mu)
    tau_star = stick_impulse(mass, slip, zeta, mu)
    return xp.where(tau >= tau_star, -mass * slip / zeta, -mu * xp.sign(slip) * tau) + 0.0


def force_ratio_at(tau, mass, slip, zeta, mu):
    """Force ratio ``F/N`` at normal impulse ``tau`` (eq. 6.4, Figs. 2a and 3a).

    ``-mu sign(u^-)`` while slipping, ``0`` once the contact point sticks.
    """
    xp, (tau, slip, mu) = arrays(tau, slip, mu)
    tau_star = stick_impulse(mass, slip, zeta, mu)
    return xp.where(tau < tau_star, -mu * xp.sign(slip), 0.0) + 0.0


def slip_at(tau, mass, slip, zeta, mu):
    """Slip velocity ``u(tau)`` of the contact point (eqs. 4.2, 4.5, 4.12).

    ``u = u^- - zeta mu sign(u^-) tau/m`` up to ``tau_*``, exactly ``0`` after.
    """
    xp, (tau, slip, mu) = arrays(tau, slip, mu)
    tau_star = stick_impulse(mass, slip, zeta, mu)
    return xp.where(tau >= tau_star, 0.0, slip - zeta * mu * xp.sign(slip) * tau / mass) + 0.0


def state_at(tau, vx, vy, omega, mass, radius, zeta, mu):
    """Velocities ``(vx, vy, omega)`` at normal impulse ``tau`` during the impact.

    Integrals of eqs. (2.7): ``vx = vx^- + f/m`` (eq. 4.11, 4.12),
    ``vy = vy^- + tau/m`` (eq. 3.1) and ``omega = omega^- + (zeta - 1) f/(m R)``
    (eq. 4.7, 4.9), with ``f = f(tau)`` of :func:`friction_impulse_at`.
    """
    f = friction_impulse_at(tau, mass, slip_velocity(vx, omega, radius), zeta, mu)
    return vx + f / mass, vy + tau / mass, omega + (zeta - 1.0) * f / (mass * radius)


def tangential_impulse(mass, slip, vy, zeta, mu, kappa):
    """Total friction impulse ``f_1 = -mu sign(u^-) min(tau_*, tau_1)`` (eqs. 5.7, 7.6).

    When the contact sticks, ``mu tau_*`` is evaluated exactly as ``m |u^-|/zeta``
    (eq. 4.3), independent of ``mu``.
    """
    xp, (slip, vy) = arrays(slip, vy)
    stick = sticks(slip, vy, zeta, mu, kappa)
    slide = -mu * xp.sign(slip) * total_impulse(mass, vy, kappa)
    return xp.where(stick, -mass * slip / zeta, slide) + 0.0


def rebound_slip(slip, vy, zeta, mu, kappa):
    """Rebound slip velocity of the contact point ``u^+`` (eq. 7.11).

    ``0`` when the contact sticks; ``u^- - sign(u^-) (1+kappa) zeta mu |v^-|``,
    i.e. ``u^- (1 - (1+kappa) zeta mu/|u^-/v^-|)``, when it slips throughout.
    """
    xp, (slip, vy) = arrays(slip, vy)
    stick = sticks(slip, vy, zeta, mu, kappa)
    return xp.where(stick, 0.0, slip - xp.sign(slip) * (1.0 + kappa) * zeta * mu * xp.abs(vy)) + 0.0


def rebound(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Rebound velocities ``(vx+, vy+, omega+)`` and the friction impulse ``f_1``.

    From the impulse equations (2.1)-(2.3) with ``f_1`` of :func:`tangential_impulse`:
    ``vx+ = vx + f_1/m``, ``vy+ = vy + tau_1/m = -kappa vy`` (eq. 3.4) and
    ``omega+ = omega + R f_1 / J = omega + (zeta - 1) f_1 / (m R)``.
    This reproduces eq. (4.13) (``vx+ = vx - u^-/zeta``, ``omega+ = -vx+/R``) when
    the contact sticks and eq. (4.16) when it slips throughout.

    Returns
    -------
    vx_after, vy_after, omega_after, f1 : ndarray
    """
    f1 = tangential_impulse(mass, slip_velocity(vx, omega, radius), vy, zeta, mu, kappa)
    vx_after = vx + f1 / mass
    omega_after = omega + (zeta - 1.0) * f1 / (mass * radius)
    return vx_after, -kappa * vy + 0.0, omega_after, f1


def restitution_coefficients(mass, vy, vy_after, work_compression_normal, work_restitution_normal):
    """Newton's, Poisson's and Stronge's restitution, each from its own definition.

    ``kappa_N = -v^+/v^-`` (eq. 1.1); ``kappa_P = (tau_1 - tau_0)/tau_0`` (eq. 1.2)
    with ``tau_0 = -m v^-`` where ``v(tau)`` vanishes (eq. 3.2) and the total
    impulse ``tau_1 = m (v^+ - v^-)`` (eq. 2.2); ``eta = sqrt(-W_r^n/W_c^n)``
    (eq. 1.3). For the disk all three equal ``kappa`` (eqs. 3.4, 3.5, 6.5).
    """
    tau0 = compression_impulse(mass, vy)
    tau1 = mass * (vy_after - vy)
    eta2 = -work_restitution_normal / work_compression_normal
    xp, (eta2,) = arrays(eta2)
    return -vy_after / vy, (tau1 - tau0) / tau0, xp.sqrt(xp.maximum(eta2, 0.0))


def impulse_ratio(slip, vy, zeta, mu, kappa):
    """Tangential impact coefficient ``mu_hat = f_1 / tau_1`` (eqs. 7.4, 7.7-7.9).

    Notes
    -----
    .. math::

        \\hat\\mu = \\begin{cases}
            \\dfrac{1}{(1+\\kappa)\\zeta}\\dfrac{u^-}{v^-}, & |u^-/v^-| \\le (1+\\kappa)\\zeta\\mu
                \\quad (7.8)\\\\
            -\\mu\\,\\mathrm{sign}(u^-), & |u^-/v^-| \\ge (1+\\kappa)\\zeta\\mu \\quad (7.9)
        \\end{cases}

    Both cases are the single identity
    ``mu_hat = (u^+ - u^-) / ((1 + kappa) zeta |v^-|)`` that follows from eqs.
    (2.1)-(2.3). The paper's printed common form (7.10),
    ``-mu |u^-| / (u^- - u^+)``, swaps the two cases and is wrong; see
    ``docs/errata.md``.
    """
    xp, (slip, vy) = arrays(slip, vy)
    stick = sticks(slip, vy, zeta, mu, kappa)
    return xp.where(stick, slip / ((1.0 + kappa) * zeta * vy), -mu * xp.sign(slip)) + 0.0


def velocity_ratios(vx, vy, omega, radius, zeta, mu, kappa):
    """Ratios ``vx+/vx-`` and ``omega+/omega-`` (the two equations after eq. 4.17).

    .. math::

        \\frac{u_C^+}{u_C^-} = 1 - \\begin{cases}
            \\zeta^{-1}\\, u^-/u_C^-, & |u^-/v^-| \\le (1+\\kappa)\\zeta\\mu\\\\
            \\dfrac{(1+\\kappa)\\mu}{|u^-/v^-|}\\, u^-/u_C^-, & \\text{otherwise}
        \\end{cases}
        \\qquad
        \\frac{\\omega^+}{\\omega^-} = 1 - \\begin{cases}
            (1-\\zeta^{-1})\\, u^-/(R\\omega^-), & |u^-/v^-| \\le (1+\\kappa)\\zeta\\mu\\\\
            (\\zeta-1)\\dfrac{(1+\\kappa)\\mu}{|u^-/v^-|}\\, u^-/(R\\omega^-), & \\text{otherwise}
        \\end{cases}

    NaN where the incidence component is zero (the ratio is undefined).
    """
    xp, (vx, vy, omega) = arrays(vx, vy, omega)
    slip = slip_velocity(vx, omega, radius)
    stick = sticks(slip, vy, zeta, mu, kappa)
    # Every divisor is guarded (replaced by 1 where its branch is discarded), so no
    # branch divides by zero: lazy libraries such as Dask evaluate where() outside
    # any error-state context, and would otherwise warn.
    ratio = incidence_ratio(slip, vy)
    factor = xp.where(stick, 1.0 / zeta, (1.0 + kappa) * mu / xp.where(stick, 1.0, ratio))
    rvx = xp.where(vx != 0, 1.0 - factor * slip / xp.where(vx != 0, vx, 1.0), xp.nan)
    spin = xp.where(omega != 0, radius * omega, 1.0)
    rom = xp.where(omega != 0, 1.0 - (zeta - 1.0) * factor * slip / spin, xp.nan)
    return rvx, rom
