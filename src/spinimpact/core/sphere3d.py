"""Spheres in three dimensions through the contact seam: a sphere on a plane, two spheres.

Axes: ``x`` along the surface, ``y`` along its outward normal (up), ``z = x cross y`` out of
the page; plane motion is the case ``v = (vx, vy, 0)``, ``omega = (0, 0, omega)``, which is
exactly the paper's problem (``omega`` counter-clockwise about ``+z``).

A sphere of mass ``m``, radius ``R`` and moment of inertia ``J = m rho^2`` touches a plane of
unit normal ``n`` at ``r = -R n`` from its centre. The contact point moves with
``c = v + omega x r - V_s`` relative to the surface (``V_s``: the surface's velocity). A
contact impulse ``P = tau n + F`` (``F`` tangential) changes ``v`` by ``P/m`` and ``omega`` by
``(r x P)/J = -(R/J) n x F``. Hence, since ``(n x F) x n = F`` for ``F`` normal to ``n``,

.. math::

    \\Delta c_n = \\Delta\\tau / m, \\qquad
    \\Delta \\mathbf{c}_t = (1/m + R^2/J)\\, \\Delta\\mathbf{F} = (\\zeta/m)\\, \\Delta\\mathbf{F}:

the collision matrix is isotropic in the tangent plane and uncoupled from the normal
(``W = diag(zeta/m, zeta/m, 1/m)``). Coulomb's friction ``dF = -mu (c_t/|c_t|) dtau`` then
changes ``c_t`` only along its own direction: **the slip keeps its direction** and its
magnitude falls linearly, exactly as the paper's slip does. So the scalar seam
(:mod:`spinimpact.core.impulse`, :mod:`spinimpact.core.works`) with ``slip = |c_t|`` gives
every impulse, regime and work, and the friction impulse vector is ``F = f_1 c_t/|c_t|``.
**The spin about the normal is unchanged** by friction: ``Delta omega = -(R/J) n x F`` is
normal to ``n``.

Two spheres (masses ``m_i``, radii ``R_i``, inertias ``J_i``) with ``n`` from the centre of
sphere 2 to that of sphere 1 touch at ``r_1 = -R_1 n`` and ``r_2 = +R_2 n``; the impulse on 1
is ``P``, on 2 ``-P``, and the relative contact velocity
``c = (v_1 + omega_1 x r_1) - (v_2 + omega_2 x r_2)`` changes with
``W = diag(W_tt, W_tt, W_nn)``, ``W_nn = 1/m_1 + 1/m_2``,
``W_tt = W_nn + R_1^2/J_1 + R_2^2/J_2``: the seam again, with the reduced mass
``m* = 1/W_nn`` and ``zeta = W_tt/W_nn`` (:func:`pair_parameters`).

References
----------
.. [1] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
.. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from . import impulse
from ._xp import quiet

__all__ = [
    "SphereContact",
    "SphereRebound",
    "cross",
    "dot",
    "pair_parameters",
    "sphere_contact",
    "sphere_rebound",
    "sphere_spin_change",
]


class SphereContact(NamedTuple):
    """The contact point's velocity split along the normal and in the tangent plane."""

    normal_velocity: Any  #: ``c_n = c . n`` (``< 0`` approaching), m/s
    slip: Any  #: tangential velocity ``c_t`` (vector, ``(..., 3)``), m/s
    slip_speed: Any  #: ``|c_t|``, m/s
    direction: Any  #: ``c_t/|c_t|`` (zero where ``c_t = 0``), ``(..., 3)``


class SphereRebound(NamedTuple):
    """The contact impulse of a sphere impact, from :func:`sphere_rebound`."""

    normal_impulse: Any  #: ``tau_1``, N s
    friction: Any  #: friction impulse vector ``F = f_1 c_t/|c_t|``, ``(..., 3)``, N s
    friction_magnitude: Any  #: ``|F| = -f_1 >= 0``, N s
    impulse: Any  #: ``P = tau_1 n + F``, ``(..., 3)``, N s


def dot(a, b):
    """Dot product over the last axis (length 3)."""
    return np.sum(a * b, axis=-1)


def cross(a, b):
    """Cross product over the last axis (length 3)."""
    return np.cross(a, b)


def sphere_contact(velocity, spin, normal, radius, surface_velocity=0.0):
    """Velocity of the contact point of a sphere relative to the surface.

    Parameters
    ----------
    velocity, spin : array_like, shape (..., 3)
        Centre velocity (m/s) and spin vector (rad/s).
    normal : array_like, shape (..., 3)
        Unit outward normal of the surface at the contact.
    radius : array_like
        Sphere radius ``R``, m (the contact is at ``-R n`` from the centre).
    surface_velocity : array_like, shape (..., 3)
        Velocity of the surface's material point at the contact, m/s.

    Returns
    -------
    SphereContact
        ``c = v + omega x (-R n) - V_s`` split into ``c_n`` and ``c_t``.
    """
    r = -np.asarray(radius)[..., None] * normal
    c = velocity + cross(spin, r) - surface_velocity
    cn = dot(c, normal)
    ct = c - cn[..., None] * normal
    speed = np.sqrt(dot(ct, ct))
    with quiet(np, invalid="ignore", divide="ignore"):
        direction = np.where(
            speed[..., None] > 0, ct / np.where(speed > 0, speed, 1.0)[..., None], 0.0
        )
    return SphereContact(cn, ct, speed, direction)


def sphere_rebound(contact, normal, mass, zeta, mu, kappa):
    """The contact impulse of the impact, from the scalar seam along the slip direction.

    ``mass`` and ``zeta`` are the seam's ``1/W_nn`` and ``W_tt/W_nn`` (the sphere's ``m`` and
    ``1 + R^2/rho^2``; for two spheres :func:`pair_parameters`).
    """
    tau1 = impulse.total_impulse(mass, contact.normal_velocity, kappa)
    f1 = impulse.tangential_impulse(mass, contact.slip_speed, contact.normal_velocity, zeta, mu,
                                    kappa)  # fmt: skip
    friction = np.asarray(f1)[..., None] * contact.direction
    return SphereRebound(tau1, friction, -f1 + 0.0, np.asarray(tau1)[..., None] * normal + friction)


def sphere_spin_change(normal, radius, inertia, friction):
    """Change of a sphere's spin by a friction impulse ``F`` at ``-R n``:
    ``-(R/J) n x F`` (normal to ``n``: the spin about the normal is unchanged), rad/s."""
    k = np.asarray(radius / inertia)[..., None]
    return -k * cross(normal, friction)


def pair_parameters(mass1, inertia1, radius1, mass2, inertia2, radius2):
    """The seam's ``(1/W_nn, W_tt/W_nn)`` for two spheres in contact.

    ``W_nn = 1/m_1 + 1/m_2`` and ``W_tt = W_nn + R_1^2/J_1 + R_2^2/J_2``; a sphere of
    infinite mass and inertia (``1/m_2 = R_2^2/J_2 = 0``) gives the sphere on a plane.
    """
    w_nn = 1.0 / mass1 + 1.0 / mass2
    w_tt = w_nn + radius1**2 / inertia1 + radius2**2 / inertia2
    return impulse.contact_parameters(w_tt, w_nn)
