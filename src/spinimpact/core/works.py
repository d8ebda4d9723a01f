r"""Works and energy at the contact point (paper sections 5, 6 and 8).

By the work principle, what the contact forces do to the bodies is the integral of the
contact velocity against the contact impulse, ``dE = c . dp = (c_n + c_t F/N) dtau``: the
works of the normal and friction forces, the energy dissipated and the minimum of the
kinetic energy during the impact are all properties of the contact point alone. This
module computes them from the contact seam's quantities (:mod:`spinimpact.core.impulse`:
``slip = c_t^-``, ``vy = c_n^- < 0``, ``mass = 1/W_nn``, ``zeta = W_tt/W_nn``, ``W_tn = 0``),
so the paper's bodies, a sphere in 3D and two colliding spheres share them.

The normal velocity is ``c_n = c_n^- + tau/m`` (eq. 3.1) and the slip speed
``|c_t| = max(|c_t^-| - zeta mu tau/m, 0)`` (eqs. 4.2, 4.12), with the force ratio
``F/N = -mu sign(c_t^-)`` while slipping and ``0`` once stuck (eq. 6.4). Integrals of
linear pieces are evaluated exactly by the trapezoid rule over the pieces, so no formula
below divides by ``mu`` or by ``c_t^-``. Equation numbers are those of Lubarda [1]_. The
arguments ``slip, vy`` (m/s), ``mass`` (kg), ``zeta, mu, kappa`` (dimensionless) are those
of :mod:`spinimpact.core.impulse`; results are in J and N s; a kernel lists only its others.

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed surface",
   Proceedings of the Section of Natural Sciences, Montenegrin Academy of Sciences and Arts
   (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
.. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays, quiet, result
from .impulse import (
    compression_impulse,
    regime_code,
    stick_impulse,
    sticks_in_compression,
    total_impulse,
)

__all__ = [
    "MIN_ENERGY_CASES",
    "PhaseWorks",
    "WorkRatioBounds",
    "work_normal",
    "work_tangential",
    "contact_phase_works",
    "contact_dissipated_energy",
    "contact_min_energy_impulse",
    "contact_min_energy_case",
    "work_ratio_tangential",
    "work_ratio_tangential_bounds",
    "restitution_work",
    "restitution_work_zero",
]


class PhaseWorks(NamedTuple):
    """Works of the normal and friction forces in each phase of the impact, J."""

    compression_normal: Any  #: ``W_c^n`` (eq. 6.1)
    compression_tangential: Any  #: ``W_c^t`` (eq. 6.1)
    restitution_normal: Any  #: ``W_r^n`` (eq. 6.2)
    restitution_tangential: Any  #: ``W_r^t`` (eq. 6.2)


class WorkRatioBounds(NamedTuple):
    """Bounds on ``W_r^t/W_c^t`` (eqs. 6.15, 6.17, 6.19)."""

    lower: Any
    upper: Any


#: Labels of :func:`contact_min_energy_case`: where the kinetic energy is smallest.
MIN_ENERGY_CASES = (
    "sliding, then stick (Fig. 5a)",  # tau_0 <= tau_m <= tau_* <= tau_1
    "rolling (Fig. 5b)",  # tau_* <= tau_m = tau_0
    "sliding throughout (Fig. 5c)",  # tau_0 <= tau_m < tau_1 < tau_*, eq. (8.5)
    "at rebound",  # slip throughout and tau_m = tau_1 (beyond eq. 8.5)
    "frictionless",  # mu = 0: tau_m = tau_0
)


def work_normal(a, b, mass, vy):
    r"""Work of the normal reaction between the normal impulses ``a`` and ``b``.

    Parameters
    ----------
    a, b : float or array
        Normal impulses bounding the interval, N s.

    Returns
    -------
    work : float or array
        J; negative while the contact approaches (``v < 0``).

    Notes
    -----
    With ``v = v^- + tau/m`` (eq. 3.1),

    .. math:: \int_a^b v\,d\tau = (b - a)\left(v^- + \frac{a + b}{2m}\right):

    ``W_c^n`` on ``[0, tau_0]``, ``W_r^n`` on ``[tau_0, tau_1]`` (eqs. 6.1, 6.2), ``W^n`` on
    ``[0, tau_1]`` (eq. 5.9).
    """
    return (b - a) * (2.0 * vy + (a + b) / mass) / 2.0


def work_tangential(a, b, mass, slip, zeta, mu):
    r"""Work of the friction force between the normal impulses ``a <= b``.

    Parameters
    ----------
    a, b : float or array
        Normal impulses bounding the interval, ``a <= b``, N s.

    Returns
    -------
    work : float or array
        J, always ``<= 0``.

    Notes
    -----
    .. math:: \int_a^b \frac{F}{N}\,u\,d\tau = -\mu \int_a^b |u|\,d\tau ,
        \qquad |u| = \max\left(|u^-| - \zeta\mu\tau/m,\ 0\right)

    (eqs. 5.8, 6.1, 6.2): the slip speed falls linearly to zero at ``tau_*`` (eq. 4.5) and
    stays zero afterwards (eq. 4.12), so the integral is a trapezoid.
    """
    xp, (a, b, slip) = arrays(a, b, slip)
    tau_star = stick_impulse(mass, slip, zeta, mu)
    lo = xp.minimum(a, tau_star)
    hi = xp.minimum(b, tau_star)
    speed0 = xp.abs(slip)
    rate = zeta * mu / mass
    speed_lo = xp.maximum(speed0 - rate * lo, 0.0)
    speed_hi = xp.maximum(speed0 - rate * hi, 0.0)
    return -mu * (hi - lo) * (speed_lo + speed_hi) / 2.0


def contact_phase_works(slip, vy, mass, zeta, mu, kappa):
    r"""Works of the normal and friction forces in compression and restitution.

    Returns
    -------
    PhaseWorks
        ``(W_c^n, W_c^t, W_r^n, W_r^t)`` in J (eqs. 6.1, 6.2).

    Notes
    -----
    .. math:: W_c^n = \tfrac12 \tau_0 v^- = -\tfrac12 m (v^-)^2, \qquad
        W_r^n = \tfrac12 \kappa^2 m (v^-)^2

    (section 6, so that ``eta = kappa``, eq. 6.5); the friction works reduce to eqs.
    (6.6)-(6.11) in each regime.
    """
    tau0 = compression_impulse(mass, vy)
    tau1 = total_impulse(mass, vy, kappa)
    zero = 0.0 * tau0
    return PhaseWorks(
        work_normal(zero, tau0, mass, vy),
        work_tangential(zero, tau0, mass, slip, zeta, mu),
        work_normal(tau0, tau1, mass, vy),
        work_tangential(tau0, tau1, mass, slip, zeta, mu),
    )


def contact_dissipated_energy(slip, vy, mass, zeta, mu, kappa):
    r"""Energy lost in the impact, ``Delta E = -(W^n + W^t) >= 0`` (eqs. 5.1, 5.10).

    Returns
    -------
    energy : float or array
        ``Delta E`` in J, evaluated as ``m (v^-)^2 (1 - kappa^2)/2 - W^t``, a sum of
        non-negative terms, so it never comes out negative by cancellation.

    Notes
    -----
    .. math:: \frac{\Delta E}{\tfrac12 m |v^-|^2} = \begin{cases}
            1 - \kappa^2 + \zeta^{-1} |u^-/v^-|^2, & |u^-/v^-| \le (1+\kappa)\zeta\mu \\
            (1+\kappa)\{1 - \kappa + \mu[2|u^-/v^-| - (1+\kappa)\zeta\mu]\},
                & |u^-/v^-| \ge (1+\kappa)\zeta\mu
        \end{cases}

    the form after eq. (5.4) when the contact sticks and eq. (5.6) when it slips throughout.
    """
    tau1 = total_impulse(mass, vy, kappa)
    normal = 0.5 * mass * vy * vy * (1.0 - kappa * kappa)
    return normal - work_tangential(0.0 * tau1, tau1, mass, slip, zeta, mu)


def contact_min_energy_impulse(slip, vy, mass, zeta, mu, kappa):
    r"""Normal impulse ``tau_m`` at which the kinetic energy is smallest (eqs. 8.2-8.6).

    Returns
    -------
    tau_m : float or array
        N s, in ``[tau_0, tau_1]``.

    Notes
    -----
    ``dE/dtau = c_n + c_t F/N`` is continuous and non-decreasing, so ``E`` is convex in
    ``tau`` and its minimum over ``[0, tau_1]`` is where ``dE/dtau`` vanishes:

    .. math:: \tau_m = \begin{cases}
            \tau_0, & |u^-/v^-| \le \zeta\mu \quad \text{(rolling: Fig. 5b, eq. 8.6)} \\
            \min\left(m \dfrac{|v^-| + \mu|u^-|}{1 + \zeta\mu^2},\ \tau_1\right),
                & |u^-/v^-| > \zeta\mu \quad \text{(sliding: eq. 8.2, Figs. 5a, 5c)}
        \end{cases}

    If slip continues and eq. (8.2) exceeds ``tau_1`` (the right inequality of eq. 8.5
    fails), ``E`` is still decreasing when the impact ends, so the minimum is the rebound
    energy, ``tau_m = tau_1``. The paper does not state this case; see ``docs/errata.md``.
    """
    tau0 = compression_impulse(mass, vy)
    tau1 = total_impulse(mass, vy, kappa)
    xp, (slip, vy) = arrays(slip, vy)
    sliding = mass * (xp.abs(vy) + mu * xp.abs(slip)) / (1.0 + zeta * mu * mu)
    return xp.where(sticks_in_compression(slip, vy, zeta, mu), tau0, xp.minimum(sliding, tau1))


def contact_min_energy_case(slip, vy, mass, zeta, mu, kappa):
    r"""Index into :data:`MIN_ENERGY_CASES` of where ``E(tau)`` is smallest (Fig. 5).

    Returns
    -------
    case : int8 array
        ``MIN_ENERGY_CASES[case]`` names it.

    Notes
    -----
    Decided with the regime (:func:`~spinimpact.core.impulse.regime_code`): stick in
    compression or no slip gives (b); stick in restitution (a); slip throughout (c) or,
    past eq. (8.5), the rebound itself (``tau_m = tau_1``, ``docs/errata.md``); ``mu = 0``
    is labelled ``frictionless`` (``tau_m = tau_0``).
    """
    code = regime_code(slip, vy, zeta, mu, kappa)
    tau_m = contact_min_energy_impulse(slip, vy, mass, zeta, mu, kappa)
    before_end = tau_m < total_impulse(mass, vy, kappa)
    xp, (tau_m,) = arrays(tau_m)

    def c(value):
        return xp.asarray(value, dtype=xp.int8)

    case = xp.where(before_end, c(2), c(3))  # slip throughout: inside (c) or at the rebound
    case = xp.where(code == 3, c(0), case)
    case = xp.where(code <= 2, c(1), case)
    return xp.where(code == 0, c(4), case)


def work_ratio_tangential(ratio, zeta, mu, kappa):
    r"""Ratio of restitution to compression friction work, ``W_r^t/W_c^t`` (eqs. 6.15-6.18).

    Parameters
    ----------
    ratio : float or array
        Incidence ratio ``|u^-/v^-|``, dimensionless.

    Returns
    -------
    work_ratio : float or array
        Dimensionless, in ``[0, kappa]``; NaN where ``mu = 0`` or ``ratio = 0`` (no
        friction work is done at all).

    Notes
    -----
    With ``x = ratio/(zeta mu) = tau_*/tau_0``,

    .. math:: \frac{W_r^t}{W_c^t} = \begin{cases}
            0, & x \le 1 \quad (6.15)\\
            \dfrac{(x-1)^2}{2x-1}, & 1 \le x \le 1+\kappa \quad (6.16)\\
            \kappa\,\dfrac{2x-2-\kappa}{2x-1}, & x \ge 1+\kappa \quad (6.18)
        \end{cases}

    Examples
    --------
    At ``x = 1 + kappa`` it is ``kappa^2/(1 + 2 kappa)``: 1/3 for ``kappa = 1`` (eq. 6.17).

    >>> round(float(work_ratio_tangential(1.2, zeta=3.0, mu=0.2, kappa=1.0)), 12)
    0.333333333333
    """
    xp, (ratio, zeta, mu, kappa) = arrays(ratio, zeta, mu, kappa)
    defined = (mu > 0) & (ratio > 0)
    with quiet(xp, all="ignore"):  # x may overflow for tiny mu; the branches below cope
        x = ratio / xp.where(defined, zeta * mu, 1.0)
        mid = (x - 1.0) ** 2 / (2.0 * x - 1.0)
        high = kappa * (1.0 - (1.0 + kappa) / (2.0 * x - 1.0))  # the printed form of (6.18)
    out = xp.where(x <= 1.0, 0.0, xp.where(x <= 1.0 + kappa, mid, high))
    return result(xp, xp.where(defined, out, xp.nan))


def work_ratio_tangential_bounds(ratio, zeta, mu, kappa):
    r"""Bounds on ``W_r^t/W_c^t`` in the interval of ``|u^-/v^-|`` holding ``ratio``.

    Parameters
    ----------
    ratio : float or array
        Incidence ratio ``|u^-/v^-|``, dimensionless.

    Returns
    -------
    WorkRatioBounds
        ``(lower, upper)``, dimensionless, depending on ``kappa`` only; NaN where ``mu = 0``
        or ``ratio = 0``.

    Notes
    -----
    ``(0, 0)`` for ``ratio <= zeta mu`` (eq. 6.15); ``(0, kappa^2/(1+2 kappa))`` for
    ``zeta mu <= ratio <= (1+kappa) zeta mu`` (eq. 6.17); ``(kappa^2/(1+2 kappa), kappa)``
    beyond (eq. 6.19).
    """
    xp, (ratio, zeta, mu, kappa) = arrays(ratio, zeta, mu, kappa)
    limit = zeta * mu
    mid = kappa * kappa / (1.0 + 2.0 * kappa)
    stick_early = ratio <= limit
    slip = ratio > (1.0 + kappa) * limit
    lower = xp.where(slip, mid, 0.0)
    upper = xp.where(stick_early, 0.0, xp.where(slip, kappa, mid))
    undefined = (mu == 0) | (ratio == 0)  # no friction work: the ratio is NaN
    return WorkRatioBounds(
        result(xp, xp.where(undefined, xp.nan, lower)),
        result(xp, xp.where(undefined, xp.nan, upper)),
    )


def restitution_work(ratio, zeta, mu, kappa):
    r"""Total restitution work ``W_r`` in units of ``tau_0 |v^-|/2 = m (v^-)^2/2``.

    Parameters
    ----------
    ratio : float or array
        Incidence ratio ``r = |u^-/v^-|``, dimensionless.

    Returns
    -------
    work : float or array
        ``W_r/(m (v^-)^2/2)``, dimensionless.

    Notes
    -----
    .. math:: \frac{W_r}{\tfrac12 m (v^-)^2} = \begin{cases}
            \kappa^2, & r \le \zeta\mu \quad (6.7)\\
            \kappa^2 - \zeta\mu^2 (r/(\zeta\mu) - 1)^2,
                & \zeta\mu \le r \le (1+\kappa)\zeta\mu \quad (6.9)\\
            \kappa^2 + \kappa\zeta\mu^2 (2 + \kappa - 2r/(\zeta\mu)),
                & r \ge (1+\kappa)\zeta\mu \quad (6.11)
        \end{cases}
    """
    xp, (ratio, zeta, mu, kappa) = arrays(ratio, zeta, mu, kappa)
    limit = zeta * mu
    excess = xp.maximum(ratio - limit, 0.0)
    mid = kappa**2 - excess**2 / zeta
    high = kappa**2 + kappa * (zeta * mu * mu * (2.0 + kappa) - 2.0 * mu * ratio)
    return result(xp, xp.where(ratio <= (1.0 + kappa) * limit, mid, high))


def restitution_work_zero(zeta, mu, kappa):
    r"""Incidence ratio ``|u^-/v^-|`` above which the restitution work is negative.

    Returns
    -------
    ratio : float or array
        Dimensionless; ``+inf`` when ``mu = 0`` or ``kappa = 0`` (``W_r`` is then never
        negative: without friction it is ``kappa^2 m (v^-)^2/2``, and without restitution
        there is no restitution phase).

    Notes
    -----
    ``W_r >= 0`` exactly when ``|u^-/v^-|`` is at most

    .. math:: \begin{cases}
            \zeta\mu + \sqrt{\zeta}\,\kappa, & \zeta\mu^2 \ge 1 \quad (6.13)\\
            (\kappa + (2 + \kappa)\zeta\mu^2)/(2\mu), & \zeta\mu^2 < 1
        \end{cases}

    The first lies in the stick-restitution interval, and ``W_r <= 0`` throughout the slip
    interval (eq. 6.14, first line); the second lies in the slip interval. The second line
    of the paper's eq. (6.14) claims ``W_r >= 0`` for *all* ``|u^-/v^-| >= (1+kappa) zeta
    mu`` when ``zeta mu^2 <= 1``; eq. (6.11) shows ``W_r`` falls linearly in ``|u^-/v^-|``
    and turns negative at the value above (``docs/errata.md``).

    Examples
    --------
    The case of ``docs/errata.md``: ``W_r`` of a solid disk changes sign at 2.875.

    >>> round(float(restitution_work_zero(zeta=3.0, mu=0.1, kappa=0.5)), 12)
    2.875
    """
    xp, (zeta, mu, kappa) = arrays(zeta, mu, kappa)
    strong = zeta * mu * mu >= 1.0
    with quiet(xp, divide="ignore"):
        weak = xp.where(
            mu > 0,
            (kappa + (2.0 + kappa) * zeta * mu * mu) / (2.0 * xp.where(mu > 0, mu, 1.0)),
            xp.inf,
        )
    value = xp.where(strong, zeta * mu + xp.sqrt(zeta) * kappa, weak)
    return result(xp, xp.where(kappa == 0, xp.inf, value))
