"""The paper's bodies on a fixed plane: body velocities in, body velocities out
(paper sections 2-4 and 7).

A disk, ring, sphere, shell or spool of mass ``m``, contact radius ``R`` and
radius of gyration ``rho`` touches the plane straight below its centre, at
``r = (0, -R)``. Its contact point moves with the slip ``u = vx + R omega``
(eq. 4.4) and the normal velocity ``vy``, and its collision matrix is
``W = diag(zeta/m, 1/m)`` with ``zeta = 1 + R^2/rho^2``
(:func:`~spinimpact.core.impulse.planar_collision_matrix` with ``r = (0, -R)``).
So the contact seam :mod:`spinimpact.core.impulse` takes ``(slip, vy, m, zeta)``
directly, and this module only maps body velocities to the contact point and
the contact impulse back to the body:

.. math::

    v_x^+ = v_x^- + f/m, \\qquad v_y^+ = -\\kappa v_y^-, \\qquad
    \\omega^+ = \\omega^- + R f/J = \\omega^- + (\\zeta - 1) f/(m R).

The contact-level kernels are re-exported here under their historical names
(``spinimpact.core.kinematics.sticks`` is :func:`spinimpact.core.impulse.sticks`).

Notation (SI units)
-------------------
``vx, vy, omega``
    Incidence velocity of the centre (``vy < 0``) and spin (counter-clockwise
    positive); the paper's ``u_C^-``, ``v^-``, ``omega^-``.
``mass, radius, zeta``
    Mass ``m``, contact radius ``R`` and ``zeta = 1 + R**2/rho**2``.
``mu, kappa``
    Kinetic Coulomb friction coefficient and coefficient of normal restitution.

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a
   fixed surface", Proceedings of the Section of Natural Sciences, Montenegrin
   Academy of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
.. [2] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays
from .impulse import (
    REGIMES,
    compression_impulse,
    force_ratio_at,
    friction_impulse_at,
    impulse_ratio,
    incidence_ratio,
    rebound_normal_velocity,
    rebound_slip,
    regime_code,
    regime_thresholds,
    restitution_coefficients,
    slip_at,
    stick_impulse,
    sticks,
    sticks_in_compression,
    tangential_impulse,
    total_impulse,
)

__all__ = [
    "REGIMES",
    "Rebound",
    "Velocities",
    "VelocityRatios",
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


class Velocities(NamedTuple):
    """Velocity state of a body in plane motion."""

    vx: Any  #: centre velocity along the surface, m/s
    vy: Any  #: centre velocity along the normal, m/s
    omega: Any  #: spin, rad/s, counter-clockwise positive


class Rebound(NamedTuple):
    """Rebound velocities and the friction impulse of :func:`rebound`."""

    vx: Any  #: ``vx^+``, m/s
    vy: Any  #: ``vy^+``, m/s
    omega: Any  #: ``omega^+``, rad/s
    tangential_impulse: Any  #: ``f_1``, N s


class VelocityRatios(NamedTuple):
    """``vx^+/vx^-`` and ``omega^+/omega^-`` (NaN where the incidence component is 0)."""

    vx: Any
    omega: Any


def slip_velocity(vx, omega, radius):
    """Horizontal velocity of the contact point, ``u = u_C + R*omega`` (eq. 4.4)."""
    return vx + radius * omega


def state_at(tau, vx, vy, omega, mass, radius, zeta, mu):
    """Velocities ``(vx, vy, omega)`` at normal impulse ``tau`` during the impact.

    Integrals of eqs. (2.7): ``vx = vx^- + f/m`` (eq. 4.11, 4.12),
    ``vy = vy^- + tau/m`` (eq. 3.1) and ``omega = omega^- + (zeta - 1) f/(m R)``
    (eq. 4.7, 4.9), with ``f = f(tau)`` of :func:`friction_impulse_at`.
    """
    f = friction_impulse_at(tau, mass, slip_velocity(vx, omega, radius), zeta, mu)
    return Velocities(vx + f / mass, vy + tau / mass, omega + (zeta - 1.0) * f / (mass * radius))


def rebound(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Rebound velocities ``(vx+, vy+, omega+)`` and the friction impulse ``f_1``.

    From the impulse equations (2.1)-(2.3) with ``f_1`` of :func:`tangential_impulse`:
    ``vx+ = vx + f_1/m``, ``vy+ = vy + tau_1/m = -kappa vy`` (eq. 3.4) and
    ``omega+ = omega + R f_1 / J = omega + (zeta - 1) f_1 / (m R)``.
    This reproduces eq. (4.13) (``vx+ = vx - u^-/zeta``, ``omega+ = -vx+/R``) when
    the contact sticks and eq. (4.16) when it slips throughout.

    Returns
    -------
    Rebound
        Named tuple ``(vx, vy, omega, tangential_impulse)``; it unpacks as before,
        ``vx1, vy1, om1, f1 = rebound(...)``.
    """
    f1 = tangential_impulse(mass, slip_velocity(vx, omega, radius), vy, zeta, mu, kappa)
    vx_after = vx + f1 / mass
    omega_after = omega + (zeta - 1.0) * f1 / (mass * radius)
    return Rebound(vx_after, rebound_normal_velocity(vy, kappa), omega_after, f1)


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
    return VelocityRatios(rvx, rom)
