r"""The contact seam: Keller's method at one contact point, in the normal impulse.

Every single-point impact is described by what happens *at the contact point* (Keller
[2]_; Stronge [3]_, ch. 4-5): a contact impulse ``dp = (df, dtau)`` (friction ``f``,
normal ``tau``) changes the slip ``c_t`` and the normal velocity ``c_n < 0`` of the
contact point linearly through the inverse-mass or *collision matrix* ``W``,

.. math:: \begin{pmatrix} dc_t \\ dc_n \end{pmatrix}
    = \begin{pmatrix} W_{tt} & W_{tn} \\ W_{tn} & W_{nn} \end{pmatrix}
    \begin{pmatrix} df \\ d\tau \end{pmatrix} .

Coulomb's law (``df = -mu sign(c_t) dtau`` while slipping, ``df = 0`` with ``c_t = 0``
once stuck) and Poisson's restitution (``tau_1 = (1 + kappa) tau_0``, ``tau_0`` where
``c_n`` vanishes) decide the path of ``p``; ``tau`` is the independent variable and every
velocity is piecewise linear in it. Equation numbers are those of Lubarda [1]_.

The kernels hold for ``W_tn = 0`` (contact on the normal through the centre of mass: the
paper's bodies, a sphere in 3D, two spheres): the normal and tangential problems decouple,
slip never reverses, and Newton's, Poisson's and Stronge's restitution coincide (section
3); ``W_tn != 0`` (a rod or box striking off-centre) needs the general planar kernels
(``docs/architecture.md``). Pure array kernels in SI units (arrays in, arrays or named
tuples of the broadcast shape out, no validation) for any array-API library (:mod:`._xp`).
Arguments, unless a kernel lists its own:

Parameters
----------
slip, vy : float or array
    Slip ``c_t^-`` (the paper's ``u^- = vx + R omega``, eq. 4.4) and normal velocity
    ``c_n^- < 0`` (the paper's ``v^-``) of the contact point before the impact, m/s.
mass, zeta : float or array
    Effective normal mass ``1/W_nn`` (kg; the paper's ``m``) and ``W_tt/W_nn``
    (dimensionless; ``1 + R^2/rho^2`` for the paper's bodies, section 2).
mu, kappa : float or array
    Kinetic friction coefficient ``>= 0`` and normal restitution in ``[0, 1]``.
tau : float or array
    Normal impulse since first contact, ``tau = int N dt`` (eq. 2.6), N s.

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed surface",
   Proceedings of the Section of Natural Sciences, Montenegrin Academy of Sciences and Arts
   (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
.. [2] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
.. [3] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays, quiet
from .restitution import RestitutionCoefficients, restitution_by_definition

__all__ = [
    "REGIMES",
    "CollisionMatrix",
    "ContactParameters",
    "RegimeThresholds",
    "RestitutionCoefficients",
    "planar_collision_matrix",
    "contact_parameters",
    "incidence_ratio",
    "compression_impulse",
    "total_impulse",
    "stick_impulse",
    "sticks",
    "sticks_in_compression",
    "regime_code",
    "regime_thresholds",
    "friction_impulse_at",
    "force_ratio_at",
    "slip_at",
    "tangential_impulse",
    "rebound_normal_velocity",
    "rebound_slip",
    "impulse_ratio",
    "restitution_coefficients",
]

#: Names of the impact regimes, indexed by the codes of :func:`regime_code`.
REGIMES = ("frictionless", "no-slip", "stick-compression", "stick-restitution", "slip")


class CollisionMatrix(NamedTuple):
    """Entries of the symmetric 2x2 collision matrix ``W`` of a planar contact, 1/kg."""

    tt: Any  #: W_tt: tangential velocity change per unit tangential impulse, 1/kg
    tn: Any  #: W_tn = W_nt: the coupling of the two directions, 1/kg
    nn: Any  #: W_nn: normal velocity change per unit normal impulse, 1/kg


class ContactParameters(NamedTuple):
    """The two numbers the kernels of this module need from ``W`` (with ``W_tn = 0``)."""

    mass: Any  #: effective normal mass ``1/W_nn``, kg
    zeta: Any  #: ``W_tt/W_nn``, dimensionless


class RegimeThresholds(NamedTuple):
    """Incidence ratios ``|u^-/v^-|`` that bound the regimes (eqs. 4.6, 4.14, 4.15)."""

    compression: Any  #: ``zeta mu``: at or below it the slip stops during compression
    impact: Any  #: ``(1 + kappa) zeta mu``: above it the contact slips throughout


def planar_collision_matrix(mass, inertia, rx, ry):
    """Collision matrix ``W`` of a free planar rigid body touching at offset ``r``.

    Parameters
    ----------
    mass : float or array
        Mass ``m`` of the body, kg.
    inertia : float or array
        Moment of inertia ``J`` about the centre of mass, kg m^2.
    rx, ry : float or array
        Contact point relative to the centre of mass, m (``x`` tangential, ``y`` normal).

    Returns
    -------
    CollisionMatrix
        ``W_tt = 1/m + ry^2/J``, ``W_tn = -rx ry/J``, ``W_nn = 1/m + rx^2/J``, 1/kg.

    Notes
    -----
    ``c = v + omega e_z x r`` gives ``c_t = vx - omega ry``, ``c_n = vy + omega rx``; an
    impulse ``p = (f, tau)`` changes ``v`` by ``p/m`` and ``omega`` by ``(rx tau - ry f)/J``,
    so ``dc = W dp`` (Stronge 2000, ch. 4). The paper's bodies touch at ``r = (0, -R)``:
    ``W = diag(zeta/m, 1/m)``, ``zeta = 1 + R^2/rho^2``, ``J = m rho^2`` (section 2).
    """
    return CollisionMatrix(
        1.0 / mass + ry * ry / inertia, -rx * ry / inertia, 1.0 / mass + rx * rx / inertia
    )


def contact_parameters(w_tt, w_nn):
    """The kernels' ``(mass, zeta)`` from a collision matrix with ``W_tn = 0``.

    Parameters
    ----------
    w_tt, w_nn : float or array
        Diagonal entries ``W_tt`` and ``W_nn`` of the collision matrix, 1/kg.

    Returns
    -------
    ContactParameters
        ``(1/W_nn, W_tt/W_nn)``: ``(m, zeta)``, to rounding, for ``W = diag(zeta/m, 1/m)``.
    """
    return ContactParameters(1.0 / w_nn, w_tt / w_nn)


def incidence_ratio(slip, vy):
    """Incidence ratio ``|u^-/v^-|``, which selects the regime (eqs. 4.6, 4.14, 4.15).

    Returns
    -------
    ratio : float or array
        ``|u^-|/|v^-|``, dimensionless: the tangent of the contact point's incidence angle.
    """
    xp, (slip, vy) = arrays(slip, vy)
    return xp.abs(slip) / xp.abs(vy)


def compression_impulse(mass, vy):
    r"""Normal impulse at the end of compression, ``tau_0`` (eq. 3.2).

    Returns
    -------
    tau0 : float or array
        :math:`\tau_0 = -m v^-`, N s: where ``v = v^- + tau/m`` (eq. 3.1) vanishes.
    """
    return -mass * vy


def total_impulse(mass, vy, kappa):
    r"""Normal impulse of the whole impact, ``tau_1`` (eq. 3.6).

    Returns
    -------
    tau1 : float or array
        :math:`\tau_1 = (1+\kappa)\tau_0`, N s: Poisson's ``(tau_1 - tau_0)/tau_0 = kappa`` (1.2).
    """
    return (1.0 + kappa) * compression_impulse(mass, vy)


def stick_impulse(mass, slip, zeta, mu):
    r"""Normal impulse at which the contact point stops slipping, ``tau_*`` (eq. 4.3).

    Returns
    -------
    tau_star : float or array
        :math:`\tau_* = m|u^-|/(\zeta\mu)`, N s, from ``m du = zeta (F/N) dtau`` (eq. 4.1)
        with ``F/N = -mu sign(u^-)``: ``0`` where ``u^- = 0`` (no slip to end, whatever
        ``mu``), ``+inf`` where ``mu = 0`` and ``u^- != 0`` (no friction, no sticking).
    """
    xp, (mass, slip, zeta, mu) = arrays(mass, slip, zeta, mu)
    num = mass * xp.abs(slip)
    den = zeta * mu
    with quiet(xp, divide="ignore", invalid="ignore", over="ignore"):  # tiny mu: tau_* -> inf
        tau = xp.where(den > 0, num / xp.where(den > 0, den, 1.0), xp.inf)
    return xp.where(num == 0, 0.0, tau)


def sticks(slip, vy, zeta, mu, kappa):
    r"""Whether the slip stops before the impact ends, ``tau_* <= tau_1`` (eq. 4.6).

    Returns
    -------
    stick : bool array
        :math:`|u^-| \le (1+\kappa)\zeta\mu|v^-|`, free of divisions: the one test of stick
        versus slip behind every result, so they never disagree at the boundary.
    """
    xp, (slip, vy) = arrays(slip, vy)
    return xp.abs(slip) <= (1.0 + kappa) * zeta * mu * xp.abs(vy)


def sticks_in_compression(slip, vy, zeta, mu):
    r"""Whether the slip stops by the end of compression, ``tau_* <= tau_0``.

    Returns
    -------
    early : bool array
        :math:`|u^-| \le \zeta\mu|v^-|`: the complement of eq. (4.14), ``tau_0 <= tau_*``
        (both hold at equality).
    """
    xp, (slip, vy) = arrays(slip, vy)
    return xp.abs(slip) <= zeta * mu * xp.abs(vy)


def regime_code(slip, vy, zeta, mu, kappa):
    """Integer code of the impact regime; ``REGIMES[code]`` names it.

    Returns
    -------
    code : int8 array
        ===  =====================  ==============================================
        0    ``frictionless``       ``mu = 0``
        1    ``no-slip``            ``u^- = 0`` (and ``mu > 0``)
        2    ``stick-compression``  ``tau_* <= tau_0``, i.e. ``|u^-/v^-| <= zeta mu`` (eq. 4.14)
        3    ``stick-restitution``  ``tau_0 < tau_* <= tau_1`` (eqs. 4.6, 4.14)
        4    ``slip``               ``tau_* > tau_1``, i.e. ``|u^-/v^-| > (1+kappa) zeta mu`` (4.15)
        ===  =====================  ==============================================
    """
    xp, (slip, vy, mu) = arrays(slip, vy, mu)
    early = xp.astype(sticks_in_compression(slip, vy, zeta, mu), xp.int8)
    stick = xp.astype(sticks(slip, vy, zeta, mu, kappa), xp.int8)
    code = 4 - stick - early  # 2, 3 or 4: early sticking implies sticking
    code = xp.where(slip == 0, xp.asarray(1, dtype=xp.int8), code)
    return xp.where(mu == 0, xp.asarray(0, dtype=xp.int8), code)


def regime_thresholds(zeta, mu, kappa):
    """Incidence ratios ``|u^-/v^-|`` that bound the regimes (eqs. 4.6, 4.14, 4.15).

    Returns
    -------
    RegimeThresholds
        ``zeta mu`` (eq. 4.14) and ``(1 + kappa) zeta mu`` (eqs. 4.6, 4.15), dimensionless.
    """
    return RegimeThresholds(zeta * mu, (1.0 + kappa) * zeta * mu)


def friction_impulse_at(tau, mass, slip, zeta, mu):
    r"""Friction impulse ``f(tau)`` accumulated up to normal impulse ``tau`` (eqs. 7.1-7.3).

    Returns
    -------
    f : float or array
        :math:`f = -\mu\,\mathrm{sign}(u^-)\min(\tau, \tau_*)`, N s (Routh's diagram,
        Fig. 4), with ``mu tau_*`` evaluated exactly as ``m |u^-|/zeta`` (eq. 4.3).
    """
    xp, (tau, slip, mu) = arrays(tau, slip, mu)
    tau_star = stick_impulse(mass, slip, zeta, mu)
    return xp.where(tau >= tau_star, -mass * slip / zeta, -mu * xp.sign(slip) * tau) + 0.0


def force_ratio_at(tau, mass, slip, zeta, mu):
    """Force ratio ``F/N`` at normal impulse ``tau`` (eq. 6.4, Figs. 2a and 3a).

    Returns
    -------
    ratio : float or array
        ``-mu sign(u^-)`` while slipping (``tau < tau_*``), ``0`` once the contact sticks.
    """
    xp, (tau, slip, mu) = arrays(tau, slip, mu)
    tau_star = stick_impulse(mass, slip, zeta, mu)
    return xp.where(tau < tau_star, -mu * xp.sign(slip), 0.0) + 0.0


def slip_at(tau, mass, slip, zeta, mu):
    r"""Slip velocity ``u(tau)`` of the contact point (eqs. 4.2, 4.5, 4.12).

    Returns
    -------
    u : float or array
        :math:`u = u^- - \zeta\mu\,\mathrm{sign}(u^-)\,\tau/m` up to ``tau_*``, 0 after; m/s.
    """
    xp, (tau, slip, mu) = arrays(tau, slip, mu)
    tau_star = stick_impulse(mass, slip, zeta, mu)
    return xp.where(tau >= tau_star, 0.0, slip - zeta * mu * xp.sign(slip) * tau / mass) + 0.0


def tangential_impulse(mass, slip, vy, zeta, mu, kappa):
    r"""Total friction impulse of the impact, ``f_1`` (eqs. 5.7, 7.6).

    Returns
    -------
    f1 : float or array
        :math:`f_1 = -\mu\,\mathrm{sign}(u^-)\min(\tau_*, \tau_1)`, N s; when the contact
        sticks, ``mu tau_*`` is evaluated exactly as ``m |u^-|/zeta`` (eq. 4.3).
    """
    xp, (slip, vy) = arrays(slip, vy)
    stick = sticks(slip, vy, zeta, mu, kappa)
    slide = -mu * xp.sign(slip) * total_impulse(mass, vy, kappa)
    return xp.where(stick, -mass * slip / zeta, slide) + 0.0


def rebound_slip(slip, vy, zeta, mu, kappa):
    r"""Slip velocity of the contact point after the impact, ``u^+`` (eqs. 4.16, 7.11).

    Returns
    -------
    u_plus : float or array
        ``0`` if it sticks, else :math:`u^- - \mathrm{sign}(u^-)(1+\kappa)\zeta\mu|v^-|` (m/s).
    """
    xp, (slip, vy) = arrays(slip, vy)
    stick = sticks(slip, vy, zeta, mu, kappa)
    return xp.where(stick, 0.0, slip - xp.sign(slip) * (1.0 + kappa) * zeta * mu * xp.abs(vy)) + 0.0


def impulse_ratio(slip, vy, zeta, mu, kappa):
    r"""Tangential impact coefficient ``mu_hat = f_1/tau_1`` (eqs. 7.4, 7.7-7.9).

    Returns
    -------
    mu_hat : float or array
        Dimensionless, in ``[-mu, mu]``.

    Notes
    -----
    .. math::

        \hat\mu = \begin{cases}
            \dfrac{1}{(1+\kappa)\zeta}\dfrac{u^-}{v^-}, & |u^-/v^-| \le (1+\kappa)\zeta\mu
                \quad (7.8)\\
            -\mu\,\mathrm{sign}(u^-), & |u^-/v^-| \ge (1+\kappa)\zeta\mu \quad (7.9)
        \end{cases}

    Both are the identity ``mu_hat = (u^+ - u^-)/((1 + kappa) zeta |v^-|)`` of eqs.
    (2.1)-(2.3). The paper's printed common form (7.10), ``-mu |u^-|/(u^- - u^+)``, swaps
    the two cases and is wrong; see ``docs/errata.md``.
    """
    xp, (slip, vy) = arrays(slip, vy)
    stick = sticks(slip, vy, zeta, mu, kappa)
    return xp.where(stick, slip / ((1.0 + kappa) * zeta * vy), -mu * xp.sign(slip)) + 0.0


def restitution_coefficients(mass, vy, vy_after, work_compression_normal, work_restitution_normal):
    r"""Newton's, Poisson's and Stronge's restitution, each from its own definition.

    Parameters
    ----------
    vy_after : float or array
        Normal velocity after the impact, ``v^+``, m/s.
    work_compression_normal, work_restitution_normal : float or array
        Works of the normal force in compression and restitution, ``W_c^n``, ``W_r^n``, J.

    Returns
    -------
    RestitutionCoefficients
        :math:`\kappa_N = -v^+/v^-` (eq. 1.1); :math:`\kappa_P = (\tau_1-\tau_0)/\tau_0`
        (eq. 1.2) with ``tau_0 = -m v^-`` (eq. 3.2) and ``tau_1 = m (v^+ - v^-)`` (eq.
        2.2); :math:`\eta = \sqrt{-W_r^n/W_c^n}` (eq. 1.3, ``0`` if the ratio is negative).
        For the paper's bodies all three equal ``kappa`` (eqs. 3.4, 3.5, 6.5).
    """
    tau0 = compression_impulse(mass, vy)
    tau1 = mass * (vy_after - vy)
    return restitution_by_definition(
        vy, vy_after, tau0, tau1, work_compression_normal, work_restitution_normal
    )


def rebound_normal_velocity(vy, kappa):
    """Normal velocity of the contact point after the impact, ``c_n^+`` (eqs. 3.4, 3.6).

    Returns
    -------
    vy_after : float or array
        ``c_n^+ = -kappa c_n^-``, m/s: with ``W_tn = 0``, ``c_n`` grows by ``W_nn dtau``
        whatever friction does, so Poisson's restitution gives Newton's rule.
    """
    return -kappa * vy + 0.0
