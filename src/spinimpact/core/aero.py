r"""Aerodynamics of a spinning ball: quadratic drag, Magnus lift, spin decay.

Axes as everywhere in the package: ``y`` up (the ground's normal), gravity ``-g e_y``. A ball
of mass ``m``, radius ``R`` and moment of inertia ``J`` moves with velocity ``v`` and spin
``omega`` through still air of density ``rho``; ``A = pi R^2`` is its cross-section and
``S = R |omega| / |v|`` the spin ratio.

.. math::

    m \dot{\mathbf v} = -m g\,\mathbf e_y
        - \tfrac12 \rho A C_D |\mathbf v| \mathbf v
        + \tfrac12 \rho A C_L(S) |\mathbf v|^2\, \hat{\boldsymbol\omega} \times \hat{\mathbf v},
    \qquad
    J \dot{\boldsymbol\omega} = -\tfrac12 \rho A R^2 C_M |\mathbf v|\, \boldsymbol\omega .

* Drag: the usual quadratic law with a constant drag coefficient ``C_D``.
* Lift (Magnus): normal to the velocity and to the spin axis, with the saturating lift
  coefficient :func:`lift_coefficient`, ``C_L = S/(1/a + S/C_max)`` (initial slope ``a``,
  limit ``C_max``). ``a = 1``, ``C_max = 1/2`` is Stepanek's fit for tennis balls,
  ``C_L = 1/(2 + 1/S)`` (Stepanek 1988 [1]_). Since
  ``C_L |v|^2 omega_hat x v_hat = R (omega x v) / (1/a + S/C_max)``, the force is computed
  without dividing by ``|omega|``: no special case at zero spin, and it vanishes with ``|v|``.
* Spin decay: the air's torque opposes the spin with the coefficient
  ``C_M S = T / (1/2 rho A R v^2)``: a torque coefficient proportional to the spin ratio,
  the form Smits and Smith measured on golf balls (quoted by Nathan 2008 [2]_), so the spin decays
  at the rate ``k_s |v|``, ``k_s = rho A R^2 C_M / (2 J)`` (1/m). At constant speed the
  decay is exponential, as measured in golf (about 4 % per second).

The terminal speed of a ball falling without spin is ``sqrt(2 m g / (rho A C_D))``
(:func:`terminal_speed`): drag balances weight.

References
----------
.. [1] A. Stepanek, "The aerodynamics of tennis balls -- the topspin lob", American Journal
   of Physics 56 (1988) 138-142.
.. [2] A. J. Smits, D. R. Smith, "A new aerodynamic model of a golf ball in flight", Science
   and Golf II (1994) 340-347; A. M. Nathan, "The effect of spin-down on the flight of a
   baseball" (2008).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = [
    "AeroConstants",
    "aero_constants",
    "lift_coefficient",
    "derivatives",
    "terminal_speed",
    "drag_power",
]


class AeroConstants(NamedTuple):
    """The per-mass constants of the equations of motion in flight (all scalars)."""

    gravity: float  #: ``g``, m/s^2
    drag: float  #: ``k_d = rho A C_D / (2 m)``, 1/m
    lift: float  #: ``k_l = rho A R a / (2 m)``, dimensionless (``a``: the lift slope)
    saturation: float  #: ``a / C_max`` (0 for a linear lift law), dimensionless
    spin_decay: float  #: ``k_s = rho A R^2 C_M / (2 J)``, 1/m
    radius: float  #: ``R``, m


def aero_constants(*, mass, radius, inertia, density, drag_coefficient, lift_slope, lift_max,
                   spin_decay, gravity) -> AeroConstants:  # fmt: skip
    """Collect the constants of the equations of motion.

    Parameters
    ----------
    mass, radius, inertia : float
        ``m`` (kg), ``R`` (m), ``J`` (kg m^2).
    density : float
        Air density ``rho``, kg/m^3 (0: a vacuum).
    drag_coefficient, lift_slope, lift_max, spin_decay : float
        ``C_D``; the lift law's initial slope ``a`` and limit ``C_max`` (``inf``: linear);
        the spin-decay coefficient ``C_M``.
    gravity : float
        ``g``, m/s^2.
    """
    area = np.pi * radius**2
    q = density * area / (2.0 * mass)
    saturation = 0.0 if not np.isfinite(lift_max) else lift_slope / lift_max
    return AeroConstants(
        gravity=float(gravity),
        drag=float(q * drag_coefficient),
        lift=float(q * radius * lift_slope),
        saturation=float(saturation),
        spin_decay=float(density * area * radius**2 * spin_decay / (2.0 * inertia)),
        radius=float(radius),
    )


def lift_coefficient(spin_ratio, slope=1.0, maximum=0.5):
    """Saturating lift coefficient ``C_L(S) = S / (1/slope + S/maximum)``.

    ``slope = 1, maximum = 1/2`` is Stepanek's ``C_L = 1/(2 + 1/S)`` for tennis balls
    (Stepanek 1988); ``maximum = inf`` gives the linear law ``C_L = slope S``.

    Parameters
    ----------
    spin_ratio : array_like
        ``S = R |omega| / |v| >= 0``.
    slope, maximum : float
        Initial slope ``dC_L/dS`` at ``S = 0`` and the limit for large ``S``.

    Examples
    --------
    >>> float(lift_coefficient(1.0))    # Stepanek: 1/(2 + 1) = 1/3
    0.3333333333333333
    """
    s = np.asarray(spin_ratio, dtype=float)
    if slope == 0:
        return np.zeros_like(s)
    inv_max = 0.0 if not np.isfinite(maximum) else 1.0 / maximum
    return s / (1.0 / slope + s * inv_max)


def _speed(v):
    return np.sqrt(np.einsum("...i,...i->...", v, v))


def derivatives(velocity, spin, c: AeroConstants):
    """Time derivatives ``(dv/dt, domega/dt)`` of a ball in flight (module equations).

    Parameters
    ----------
    velocity, spin : ndarray, shape (..., 3)
        ``v`` (m/s) and ``omega`` (rad/s).
    c : AeroConstants

    Returns
    -------
    acceleration, spin_rate : ndarray, shape (..., 3)
        m/s^2 and rad/s^2.
    """
    vx, vy, vz = velocity[..., 0], velocity[..., 1], velocity[..., 2]
    speed = np.sqrt(vx * vx + vy * vy + vz * vz)
    drag = c.drag * speed
    ax, ay, az = -drag * vx, -drag * vy - c.gravity, -drag * vz
    if c.lift != 0.0:
        # R (omega x v) / (1/a + S/C_max), written as k_l (omega x v) / (1 + (a/C_max) S);
        # it vanishes with v, so zero speed gives zero lift (no division by |omega|)
        wx, wy, wz = spin[..., 0], spin[..., 1], spin[..., 2]
        moving = speed > 0
        with np.errstate(divide="ignore", invalid="ignore"):
            s = c.radius * np.sqrt(wx * wx + wy * wy + wz * wz) / np.where(moving, speed, 1.0)
        f = np.where(moving, c.lift / (1.0 + c.saturation * s), 0.0)
        ax = ax + f * (wy * vz - wz * vy)
        ay = ay + f * (wz * vx - wx * vz)
        az = az + f * (wx * vy - wy * vx)
    acc = np.empty(np.shape(velocity))
    acc[..., 0], acc[..., 1], acc[..., 2] = ax, ay, az
    spin_rate = (-c.spin_decay * speed)[..., None] * spin
    return acc, spin_rate


def terminal_speed(*, mass, radius, density, drag_coefficient, gravity):
    """Terminal speed ``sqrt(2 m g / (rho A C_D))`` of a ball falling without spin, m/s.

    Examples
    --------
    A table-tennis ball:

    >>> round(float(terminal_speed(mass=0.0027, radius=0.02, density=1.225,
    ...                            drag_coefficient=0.5, gravity=9.81)), 3)
    8.296
    """
    return np.sqrt(2.0 * mass * gravity / (density * np.pi * radius**2 * drag_coefficient))


def drag_power(velocity, c: AeroConstants, mass):
    """Power of the drag force, ``-m k_d |v|^3`` (W): the rate at which drag removes energy."""
    return -mass * c.drag * _speed(velocity) ** 3
