"""A ball on level ground (``y = 0``, normal ``n = e_y``): the bounce and the roll to rest.

* :func:`ground_bounce` -- the exact 3D impact of :mod:`spinimpact.core.sphere3d` (the
  kernels of :func:`spinimpact.solve_sphere`, vectorized over many balls): the slip keeps its
  direction and the scalar seam gives the friction impulse along it.
* :func:`roll_to_rest` -- the ball on the ground after its last bounce (its normal velocity
  set to zero). While the contact point slips, Coulomb friction ``mu m g`` acts against the
  slip ``c_t = v + omega x (-R n)``; as in the impact, the slip keeps its direction and falls
  at the constant rate ``mu g zeta`` (``dv/dt = -mu g e``, ``d omega/dt = (mu m g R / J)
  n x e``, so ``dc_t/dt = -mu g (1 + m R^2/J) e``). Once it rolls, the ball slows at the
  constant rate ``mu_r g`` (``mu_r``: the coefficient of rolling resistance, defined by that
  deceleration, as a stimpmeter measures it on a golf green) and keeps rolling without slip;
  the spin about the normal is kept (an assumption: pivoting friction is neglected), and the
  air is neglected on the ground.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from . import compliance, impulse
from .sphere3d import cross, dot, sphere_contact, sphere_rebound, sphere_spin_change

__all__ = ["GroundBounce", "Roll", "UP", "ground_bounce", "roll_to_rest"]

UP = np.array([0.0, 1.0, 0.0])


class GroundBounce(NamedTuple):
    """One bounce of each ball (arrays over the balls)."""

    velocity: Any  #: after, (n, 3), m/s
    spin: Any  #: after, (n, 3), rad/s
    regime: Any  #: code into :data:`spinimpact.core.impulse.REGIMES`
    grips: Any  #: bool: leaves without slip (the slip stopped during the impact)


class Roll(NamedTuple):
    """The ball on the ground until rest or the stopping time (arrays over the balls)."""

    time: Any  #: s
    position: Any  #: centre, (n, 3), m
    velocity: Any  #: (n, 3), m/s
    spin: Any  #: (n, 3), rad/s
    at_rest: Any  #: bool
    slide_end: Any  #: time the slip stops (inf: never), s


def ground_bounce(velocity, spin, *, mass, radius, inertia, zeta, mu, kappa,
                  rebound_slip=None, frictionless=False, normal=None) -> GroundBounce:  # fmt: skip
    """The exact bounce of balls on the ground: :func:`spinimpact.solve_sphere`'s kernels.

    Parameters
    ----------
    velocity, spin : ndarray, shape (n, 3)
        Before the impact (``v_y < 0``), m/s and rad/s.
    mass, radius, inertia, zeta : float
        ``m`` (kg), ``R`` (m), ``J`` (kg m^2), ``1 + R^2/rho^2``.
    mu, kappa : float
        Coulomb friction and restitution of the ground.
    rebound_slip : callable, optional
        A tangential compliance law's ``rebound_slip(slip, vy, zeta, mu, kappa) -> (c_t^+,
        stuck)`` on the seam (``spinimpact.Walton(...).rebound_slip``): the slip after, signed
        along the slip before, as :func:`spinimpact.solve_sphere` with ``tangential=`` uses
        it. The regime codes are then :data:`spinimpact.core.compliance.COMPLIANT_REGIMES`'s
        and ``grips`` says the contact stuck.
    frictionless : bool
        The law applies no friction whatever ``mu`` (Walton's ``beta_0 = -1``): its bounces
        are labelled ``frictionless``, as those with ``mu = 0``.
    normal : array_like, shape (3,), optional
        The plane's unit normal towards the ball (default ``e_y``: the ground; a wall).
    """
    n = np.broadcast_to(UP if normal is None else np.asarray(normal, float), np.shape(velocity))
    c = sphere_contact(velocity, spin, n, radius)
    if rebound_slip is None:
        r = sphere_rebound(c, n, mass, zeta, mu, kappa)
        impulse_vector, friction = r.impulse, r.friction
        code = impulse.regime_code(c.slip_speed, c.normal_velocity, zeta, mu, kappa)
        grips = impulse.sticks(c.slip_speed, c.normal_velocity, zeta, mu, kappa)
    else:
        speed1, grips = rebound_slip(c.slip_speed, c.normal_velocity, zeta, mu, kappa)
        f1 = compliance.tangential_impulse_of(mass, zeta, c.slip_speed, speed1)
        friction = np.asarray(f1)[..., None] * c.direction
        tau1 = impulse.total_impulse(mass, c.normal_velocity, kappa)
        impulse_vector = np.asarray(tau1)[..., None] * n + friction
        code = compliance.compliant_regime_code(c.slip_speed, speed1, mu, grips, frictionless)
    v1 = velocity + impulse_vector / mass
    w1 = spin + sphere_spin_change(n, radius, inertia, friction)
    return GroundBounce(v1, w1, np.asarray(code), np.asarray(grips, dtype=bool))


def roll_to_rest(time, position, velocity, spin, *, mass, radius, inertia, zeta, mu,
                 rolling, gravity, t_stop, samples=0) -> tuple[Roll, list]:  # fmt: skip
    """Slide, then roll, to rest or to ``t_stop`` in closed form (module docstring).

    Parameters
    ----------
    time : ndarray, shape (n,)
        Time the ball settles on the ground, s.
    position, velocity, spin : ndarray, shape (n, 3)
        Its state then (the normal velocity is dropped).
    mass, radius, inertia, zeta : float
        The ball.
    mu, rolling : float
        Coulomb friction and coefficient of rolling resistance of the ground.
    gravity : float
        ``g``, m/s^2.
    t_stop : float
        Stopping time, s.
    samples : int
        Points of the path to return (0: none), as ``[(index, times, positions)]``.
    """
    t = np.asarray(time, dtype=float)
    p = np.array(position, dtype=float)
    v = np.array(velocity, dtype=float)
    p[:, 1] = radius
    v[:, 1] = 0.0
    n = np.broadcast_to(UP, v.shape)
    slip = v + cross(spin, -radius * n)
    slip[:, 1] = 0.0
    size = np.sqrt(dot(slip, slip))
    e = np.where(size[:, None] > 0, slip / np.where(size > 0, size, 1.0)[:, None], 0.0)
    rate = mu * gravity * zeta
    slide = np.where(size > 0, size / rate if rate > 0 else np.inf, 0.0)
    left = np.maximum(t_stop - t, 0.0)
    t1 = np.minimum(slide, left)
    a = mu * gravity
    v_s = v - a * e * t1[:, None]
    w_s = spin + (a * mass * radius / inertia) * cross(n, e) * t1[:, None]
    p_s = p + v * t1[:, None] - 0.5 * a * e * (t1 * t1)[:, None]
    rolls = slide <= left
    speed = np.sqrt(dot(v_s, v_s))
    d = np.where(speed[:, None] > 0, v_s / np.where(speed > 0, speed, 1.0)[:, None], 0.0)
    b = rolling * gravity
    stop = np.where(speed > 0, speed / b if b > 0 else np.inf, 0.0)
    t2 = np.where(rolls, np.minimum(stop, left - t1), 0.0)
    v_f = v_s - b * d * t2[:, None]
    p_f = p_s + v_s * t2[:, None] - 0.5 * b * d * (t2 * t2)[:, None]
    w_roll = dot(w_s, n)[:, None] * n + cross(n, v_f) / radius
    w_f = np.where(rolls[:, None], w_roll, w_s)
    rest = rolls & (stop <= left - t1)
    v_f = np.where(rest[:, None], 0.0, v_f)
    end = t + t1 + t2
    path: list = []
    if samples:
        frac = np.linspace(0.0, 1.0, samples)
        s1 = t1[:, None] * frac
        pts1 = p[:, None] + v[:, None] * s1[..., None] - 0.5 * a * e[:, None] * (s1 * s1)[..., None]
        s2 = t2[:, None] * frac
        pts2 = (p_s[:, None] + v_s[:, None] * s2[..., None]
                - 0.5 * b * d[:, None] * (s2 * s2)[..., None])  # fmt: skip
        idx = np.arange(len(t))
        path = [(idx, t[:, None] + s1, pts1), (idx, (t + t1)[:, None] + s2, pts2)]
    return Roll(end, p_f, v_f, w_f, rest, t + slide), path
