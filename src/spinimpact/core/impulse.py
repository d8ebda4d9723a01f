"""The contact seam: Keller's method at one contact point, in the normal impulse.

Every single-point impact this package solves is described here by what happens
*at the contact point*, whatever the bodies are (Keller 1986; Stronge 2000,
ch. 4-5). The contact point has a tangential velocity ``c_t`` (the *slip*) and a
normal velocity ``c_n < 0`` (approaching). A contact impulse ``dp = (df, dtau)``
(friction ``f``, normal ``tau``) changes them linearly through the inverse-mass
or *collision matrix* ``W`` of the contact:

.. math::

    \\begin{pmatrix} dc_t \\\\ dc_n \\end{pmatrix}
    = \\begin{pmatrix} W_{tt} & W_{tn} \\\\ W_{tn} & W_{nn} \\end{pmatrix}
      \\begin{pmatrix} df \\\\ d\\tau \\end{pmatrix} .

Coulomb's law (``df = -mu sign(c_t) dtau`` while slipping, ``df = 0`` with
``c_t = 0`` once stuck, as long as the friction needed lies inside the cone) and
Poisson's restitution (``tau_1 = (1 + kappa) tau_0``, ``tau_0`` where ``c_n``
vanishes) decide the path of ``p``; the normal impulse ``tau`` is the
independent variable and every velocity is piecewise linear in it.

Parameters of every kernel here
-------------------------------
``slip``
    Tangential velocity of the contact point before the impact, ``c_t^-`` (m/s).
    For the paper's bodies ``u^- = vx + R omega`` (eq. 4.4).
``vy``
    Normal velocity of the contact point before the impact, ``c_n^- < 0`` (m/s);
    the name follows the paper, whose normal is ``y``. For a contact straight
    below the centre it is the centre's ``vy``.
``mass``
    Effective normal mass ``1/W_nn`` (kg): the body's mass ``m`` for the paper's
    bodies, the reduced mass for two spheres.
``zeta``
    ``W_tt/W_nn`` (dimensionless): ``1 + R^2/rho^2`` for the paper's bodies
    (section 2); for two spheres ``1 + m* (R_1^2/J_1 + R_2^2/J_2)``.
``mu, kappa``
    Kinetic Coulomb friction coefficient and coefficient of restitution.

These kernels hold for ``W_tn = 0``: the contact lies on the normal through the
centre of mass (the paper's bodies, a sphere in 3D, two spheres). Then the normal
and tangential problems decouple, slip never reverses, and Newton's, Poisson's
and Stronge's restitution coincide (paper section 3). :func:`contact_parameters`
maps a collision matrix to ``(mass, zeta)``; a body with ``W_tn != 0`` (a rod or
a box striking at an offset) couples them and needs the general planar kernels
(``docs/architecture.md`` names their home).

All functions are pure array kernels: arrays in, arrays (or named tuples of
arrays) out, broadcasting over any number of impacts, no validation (the model
layer validates). They run on any array-API library (:mod:`._xp`).

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a
   fixed surface", Proceedings of the Section of Natural Sciences, Montenegrin
   Academy of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
.. [2] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
.. [3] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays, quiet

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

    tt: Any  #: W_tt: tangential velocity change per unit tangential impulse
    tn: Any  #: W_tn = W_nt: the coupling of the two directions
    nn: Any  #: W_nn: normal velocity change per unit normal impulse


class ContactParameters(NamedTuple):
    """The two numbers the kernels of this module need from ``W`` (with ``W_tn = 0``)."""

    mass: Any  #: effective normal mass ``1/W_nn``, kg
    zeta: Any  #: ``W_tt/W_nn``, dimensionless


class RegimeThresholds(NamedTuple):
    """Incidence ratios ``|u^-/v^-|`` that bound the regimes (eqs. 4.6, 4.14, 4.15)."""

    compression: Any  #: ``zeta mu``: at or below it the slip stops during compression
    impact: Any  #: ``(1 + kappa) zeta mu``: above it the contact slips throughout


class RestitutionCoefficients(NamedTuple):
    """Newton's, Poisson's and Stronge's coefficients, each by its own definition."""

    newton: Any  #: ``kappa_N = -v^+/v^-`` (eq. 1.1)
    poisson: Any  #: ``kappa_P = (tau_1 - tau_0)/tau_0`` (eq. 1.2)
    energetic: Any  #: ``eta = sqrt(-W_r^n/W_c^n)`` (eq. 1.3)


def planar_collision_matrix(mass, inertia, rx, ry):
    """Collision matrix ``W`` of a free planar rigid body touching at offset ``r``.

    Parameters
    ----------
    mass : array_like
        Mass ``m`` of the body, kg.
    inertia : array_like
        Moment of inertia ``J`` about the centre of mass, kg m^2.
    rx, ry : array_like
        Position of the contact point relative to the centre of mass, m, in the
        contact frame (``x`` tangential, ``y`` along the outward normal of the surface).

    Returns
    -------
    CollisionMatrix
        ``W_tt = 1/m + ry^2/J``, ``W_tn = -rx ry/J``, ``W_nn = 1/m + rx^2/J``.

    Notes
    -----
    The contact point moves with ``c = v + omega e_z x r``, i.e.
    ``c_t = vx - omega ry`` and ``c_n = vy + omega rx``. An impulse ``p = (f, tau)``
    at the contact changes ``v`` by ``p/m`` and ``omega`` by ``(rx tau - ry f)/J``;
    substituting gives ``dc = W dp`` with the entries above [3]_. The paper's
    bodies touch at ``r = (0, -R)``: ``W = diag(zeta/m, 1/m)`` with
    ``zeta = 1 + R^2/rho^2``, ``J = m rho^2`` [1]_.
    """
    return CollisionMatrix(
        1.0 / mass + ry * ry / inertia, -rx * ry / inertia, 1.0 / mass + rx * rx / inertia
    )


def contact_parameters(w_tt, w_nn):
    """``(mass, zeta) = (1/W_nn, W_tt/W_nn)``: a collision matrix with ``W_tn = 0`` in
    the form the kernels of this module take.

    For the paper's bodies (``W = diag(zeta/m, 1/m)``) it gives ``(m, zeta)`` back,
    to rounding; the model layer passes ``(m, zeta)`` directly, so the paper's
    results are computed from the body's own numbers.
    """
    return ContactParameters(1.0 / w_nn, w_tt / w_nn)


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
    return RegimeThresholds(zeta * mu, (1.0 + kappa) * zeta * mu)


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
    return RestitutionCoefficients(
        -vy_after / vy, (tau1 - tau0) / tau0, xp.sqrt(xp.maximum(eta2, 0.0))
    )


def rebound_normal_velocity(vy, kappa):
    """Normal velocity of the contact point after the impact, ``c_n^+ = -kappa c_n^-``.

    With ``W_tn = 0`` the normal velocity grows by ``W_nn dtau`` whatever friction
    does, so Poisson's ``tau_1 = (1 + kappa) tau_0`` gives Newton's
    ``c_n^+ = -kappa c_n^-`` (eqs. 3.4, 3.6).
    """
    return -kappa * vy + 0.0
