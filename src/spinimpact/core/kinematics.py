r"""The paper's bodies on a fixed plane: body velocities in, body velocities out
(paper sections 2-4 and 7).

A disk, ring, sphere, shell or spool of mass ``m``, contact radius ``R`` and radius of
gyration ``rho`` touches the plane straight below its centre, at ``r = (0, -R)``. Its
contact point moves with the slip ``u = vx + R omega`` (eq. 4.4) and the normal velocity
``vy``, and its collision matrix is ``W = diag(zeta/m, 1/m)`` with ``zeta = 1 + R^2/rho^2``
(:func:`~spinimpact.core.impulse.planar_collision_matrix` with ``r = (0, -R)``). So the
contact seam :mod:`spinimpact.core.impulse` takes ``(slip, vy, m, zeta)`` directly, and this
module only maps body velocities to the contact point and the contact impulse back to the
body (eqs. 2.1-2.3):

.. math::

    v_x^+ = v_x^- + f/m, \qquad v_y^+ = -\kappa v_y^-, \qquad
    \omega^+ = \omega^- + R f/J = \omega^- + (\zeta - 1) f/(m R).

The contact-level kernels are re-exported here under their historical names
(``spinimpact.core.kinematics.sticks`` is :func:`spinimpact.core.impulse.sticks`).
Equation numbers are those of Lubarda [1]_.

Notation, in SI units:

``vx, vy, omega``
    Incidence velocity of the centre (m/s, ``vy < 0``) and spin (rad/s, counter-clockwise
    positive); the paper's ``u_C^-``, ``v^-``, ``omega^-``.
``mass, radius, zeta``
    Mass ``m`` (kg), contact radius ``R`` (m) and ``zeta = 1 + R**2/rho**2``.
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
    """Velocity state of a body in plane motion: centre velocity and spin."""

    vx: Any  #: centre velocity along the surface, m/s
    vy: Any  #: centre velocity along the normal, m/s
    omega: Any  #: spin, rad/s, counter-clockwise positive


class Rebound(NamedTuple):
    """Rebound velocities and the friction impulse, as :func:`rebound` returns them."""

    vx: Any  #: ``vx^+``, m/s
    vy: Any  #: ``vy^+``, m/s
    omega: Any  #: ``omega^+``, rad/s
    tangential_impulse: Any  #: ``f_1``, N s


class VelocityRatios(NamedTuple):
    """Rebound-to-incidence ratios ``vx^+/vx^-`` and ``omega^+/omega^-`` (after eq. 4.17)."""

    vx: Any
    omega: Any


def slip_velocity(vx, omega, radius):
    r"""Tangential velocity of the contact point, the slip ``u`` (eq. 4.4).

    Parameters
    ----------
    vx : float or array
        Velocity of the centre along the surface, ``u_C``, m/s.
    omega : float or array
        Spin, rad/s, counter-clockwise positive.
    radius : float or array
        Contact radius ``R``, m.

    Returns
    -------
    slip : float or array
        ``u``, m/s; ``0`` for a body rolling without slip.

    Notes
    -----
    .. math:: u = u_C + R\,\omega \qquad (4.4)

    The contact point lies at ``(0, -R)`` from the centre, and ``omega`` is positive
    counter-clockwise, so a spin ``omega > 0`` moves it in ``+x``.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    A ball rolling to the right without slip has ``omega = -vx/R``:

    >>> float(slip_velocity(vx=2.0, omega=-20.0, radius=0.1))
    0.0
    """
    return vx + radius * omega


def state_at(tau, vx, vy, omega, mass, radius, zeta, mu):
    r"""Velocities ``(vx, vy, omega)`` at normal impulse ``tau`` during the impact.

    Parameters
    ----------
    tau : float or array
        Normal impulse since first contact, N s, in ``[0, tau_1]``.
    vx, vy, omega : float or array
        Incidence velocity of the centre (m/s, ``vy < 0``) and spin (rad/s).
    mass, radius, zeta : float or array
        Mass ``m`` (kg), contact radius ``R`` (m) and ``zeta = 1 + R^2/rho^2``.
    mu : float or array
        Kinetic Coulomb friction coefficient.

    Returns
    -------
    Velocities
        ``(vx, vy, omega)`` at ``tau``, in m/s and rad/s, of the broadcast shape of
        ``tau`` and the incidence arrays.

    Notes
    -----
    Keller's method [2]_: the integrals of eqs. (2.7) in the normal impulse,

    .. math::

        v_x(\tau) = v_x^- + f(\tau)/m, \qquad v_y(\tau) = v_y^- + \tau/m, \qquad
        \omega(\tau) = \omega^- + (\zeta - 1)\,f(\tau)/(m R),

    with the friction impulse ``f(tau)`` of
    :func:`~spinimpact.core.impulse.friction_impulse_at` (eqs. 7.2, 7.3). They are eqs.
    (4.11) and (4.12) for ``vx``, (3.1) for ``vy`` and (4.7), (4.9) and (4.12) for
    ``omega`` [1]_. ``tau`` is not checked against ``[0, tau_1]``.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    .. [2] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.

    Examples
    --------
    A solid sphere (``zeta = 7/2``) stops slipping at ``tau_* = 8/7`` N s, before the end
    of compression, ``tau_0 = 3`` N s; it then rolls at ``vx = 10/7`` m/s:

    >>> import numpy as np
    >>> tau = np.array([0.0, 1.0, 3.0])
    >>> s = state_at(tau, 2.0, -3.0, 0.0, mass=1.0, radius=0.1, zeta=3.5, mu=0.5)
    >>> [[round(float(x), 6) for x in v] for v in s]
    [[2.0, 1.5, 1.428571], [-3.0, -2.0, 0.0], [0.0, -12.5, -14.285714]]
    """
    f = friction_impulse_at(tau, mass, slip_velocity(vx, omega, radius), zeta, mu)
    return Velocities(vx + f / mass, vy + tau / mass, omega + (zeta - 1.0) * f / (mass * radius))


def rebound(vx, vy, omega, mass, radius, zeta, mu, kappa):
    r"""Rebound velocities ``(vx^+, vy^+, omega^+)`` and the friction impulse ``f_1``.

    Parameters
    ----------
    vx, vy, omega : float or array
        Incidence velocity of the centre (m/s, ``vy < 0``) and spin (rad/s,
        counter-clockwise positive): the paper's ``u_C^-``, ``v^-``, ``omega^-``.
    mass, radius, zeta : float or array
        Mass ``m`` (kg), contact radius ``R`` (m) and ``zeta = 1 + R^2/rho^2``.
    mu, kappa : float or array
        Kinetic Coulomb friction coefficient and coefficient of normal restitution.

    Returns
    -------
    Rebound
        Named tuple ``(vx, vy, omega, tangential_impulse)``: ``vx^+``, ``vy^+`` (m/s),
        ``omega^+`` (rad/s) and ``f_1`` (N s). It unpacks as
        ``vx1, vy1, om1, f1 = rebound(...)``.

    Notes
    -----
    The impulse equations (2.1)-(2.3) with ``f_1`` of
    :func:`~spinimpact.core.impulse.tangential_impulse` and ``tau_1`` of eq. (3.6):

    .. math::

        v_x^+ = v_x^- + f_1/m, \qquad v_y^+ = v_y^- + \tau_1/m = -\kappa v_y^-, \qquad
        \omega^+ = \omega^- + R f_1/J = \omega^- + (\zeta - 1) f_1/(m R).

    This reproduces eq. (4.13) (``vx^+ = vx^- - u^-/zeta``, ``omega^+ = -vx^+/R``) when
    the contact sticks and eq. (4.16) when it slips throughout [1]_.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    A solid sphere (``zeta = 7/2``) struck without spin sticks and leaves rolling at
    5/7 of its incidence speed along the surface:

    >>> vx, vy, omega, f1 = rebound(
    ...     2.0, -3.0, 0.0, mass=1.0, radius=0.1, zeta=3.5, mu=0.5, kappa=0.8
    ... )
    >>> [round(float(x), 6) for x in (vx, vy, omega, f1)]
    [1.428571, 2.4, -14.285714, -0.571429]
    """
    f1 = tangential_impulse(mass, slip_velocity(vx, omega, radius), vy, zeta, mu, kappa)
    vx_after = vx + f1 / mass
    omega_after = omega + (zeta - 1.0) * f1 / (mass * radius)
    return Rebound(vx_after, rebound_normal_velocity(vy, kappa), omega_after, f1)


def velocity_ratios(vx, vy, omega, radius, zeta, mu, kappa):
    r"""Ratios ``vx^+/vx^-`` and ``omega^+/omega^-`` (the two equations after eq. 4.17).

    Parameters
    ----------
    vx, vy, omega : float or array
        Incidence velocity of the centre (m/s, ``vy < 0``) and spin (rad/s).
    radius, zeta : float or array
        Contact radius ``R`` (m) and ``zeta = 1 + R^2/rho^2``.
    mu, kappa : float or array
        Kinetic Coulomb friction coefficient and coefficient of normal restitution.

    Returns
    -------
    VelocityRatios
        ``(vx, omega)``: the two ratios, dimensionless; NaN where the incidence component
        is zero (the ratio is undefined).

    Notes
    -----
    With ``u^- = u_C^- + R omega^-`` [1]_:

    .. math::

        \frac{u_C^+}{u_C^-} = 1 - \begin{cases}
            \zeta^{-1}\, u^-/u_C^-, & |u^-/v^-| \le (1+\kappa)\zeta\mu\\
            \dfrac{(1+\kappa)\mu}{|u^-/v^-|}\, u^-/u_C^-, & \text{otherwise}
        \end{cases}
        \qquad
        \frac{\omega^+}{\omega^-} = 1 - \begin{cases}
            (1-\zeta^{-1})\, u^-/(R\omega^-), & |u^-/v^-| \le (1+\kappa)\zeta\mu\\
            (\zeta-1)\dfrac{(1+\kappa)\mu}{|u^-/v^-|}\, u^-/(R\omega^-), & \text{otherwise}
        \end{cases}

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    >>> r = velocity_ratios(2.0, -3.0, 10.0, radius=0.1, zeta=3.5, mu=0.5, kappa=0.8)
    >>> round(float(r.vx), 6), round(float(r.omega), 6)
    (0.571429, -1.142857)
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
