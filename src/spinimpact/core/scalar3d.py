r"""The per-contact law of spheres in 3D on plain numbers: a sphere on a plane, two spheres.

The scalar counterpart of :mod:`spinimpact.core.sphere3d`: vectors are 3-tuples of floats,
and each function performs the array kernels' IEEE operations in their order (a dot
product sums ``0.0 + a_x b_x + a_y b_y + a_z b_z`` left to right, as NumPy's sum of three
does; a cross product is NumPy's), so the results equal :func:`spinimpact.solve_sphere`'s
and :func:`spinimpact.solve_pair`'s bit for bit (``tests/core/test_law.py``). The
collision matrix of a sphere contact is isotropic in the tangent plane, so the slip keeps
its direction and the seam's scalar law (:func:`spinimpact.core.scalar.contact_impact`)
holds along it with ``slip = |c_t|``. Numba-compatible; registered for compiled callers by
:mod:`spinimpact.core.law`. Nothing is validated.

Arguments: ``velocity``, ``spin``, ``normal`` (unit, outward), ``surface_velocity``:
3-tuples (m/s, rad/s); ``mass`` (kg), ``radius`` (m), ``inertia`` (``J = m rho^2``,
kg m^2), ``zeta = 1 + R^2/rho^2``, ``mu >= 0``, ``kappa`` in ``[0, 1]``.

References
----------
.. [1] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
.. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.
"""

from __future__ import annotations

import math

from .scalar import contact_dissipated_energy, contact_impulses, regime_code

__all__ = [
    "sphere_contact",
    "sphere_rebound",
    "sphere_regime",
    "sphere_dissipated_energy",
    "pair_parameters",
    "pair_rebound",
]


def _dot(a, b):
    return 0.0 + a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def sphere_contact(velocity, spin, normal, radius, surface_velocity):
    """Velocity of a sphere's contact point relative to the surface.

    Returns
    -------
    tuple
        ``(c_n, c_t, |c_t|, e_t)``: the normal velocity (m/s, ``< 0`` approaching), the
        tangential velocity (3-tuple, m/s), its magnitude, and its direction (3-tuple;
        zeros where ``c_t = 0``), as :func:`spinimpact.core.sphere3d.sphere_contact`.
    """
    r = (-radius * normal[0], -radius * normal[1], -radius * normal[2])
    wr = _cross(spin, r)
    c = (
        velocity[0] + wr[0] - surface_velocity[0],
        velocity[1] + wr[1] - surface_velocity[1],
        velocity[2] + wr[2] - surface_velocity[2],
    )
    cn = _dot(c, normal)
    ct = (c[0] - cn * normal[0], c[1] - cn * normal[1], c[2] - cn * normal[2])
    speed = math.sqrt(_dot(ct, ct))
    if speed > 0.0:
        e = (ct[0] / speed, ct[1] / speed, ct[2] / speed)
    else:
        e = (0.0, 0.0, 0.0)
    return cn, ct, speed, e


def _impulse(cn, speed, e, normal, mass, zeta, mu, kappa):
    """Friction impulse vector ``F = f_1 e_t`` and the whole impulse ``P = tau_1 n + F``."""
    tau1, f1 = contact_impulses(speed, cn, mass, zeta, mu, kappa)[2:]
    friction = (f1 * e[0], f1 * e[1], f1 * e[2])
    total = (
        tau1 * normal[0] + friction[0],
        tau1 * normal[1] + friction[1],
        tau1 * normal[2] + friction[2],
    )
    return friction, total


def _spin_change(spin, normal, radius, inertia, friction):
    k = -(radius / inertia)
    nf = _cross(normal, friction)
    return (spin[0] + k * nf[0], spin[1] + k * nf[1], spin[2] + k * nf[2])


def sphere_rebound(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta, mu,
                   kappa):  # fmt: skip
    """Rebound of a sphere from a plane (moving with ``surface_velocity``), in 3D.

    Returns
    -------
    tuple of float
        ``(vx+, vy+, vz+, wx+, wy+, wz+)``: centre velocity (m/s) and spin (rad/s) after the
        impact, as :func:`spinimpact.solve_sphere`'s ``after``.

    Examples
    --------
    Plane motion is the paper's problem: a solid sphere's 5/7 rule.

    >>> out = sphere_rebound((2.0, -3.0, 0.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0),
    ...                      (0.0, 0.0, 0.0), 1.0, 0.1, 0.004, 3.5, 0.5, 0.8)
    >>> round(out[0] / 2.0, 12), out[1]
    (0.714285714286, 2.4000000000000004)
    """
    cn, _, speed, e = sphere_contact(velocity, spin, normal, radius, surface_velocity)
    friction, total = _impulse(cn, speed, e, normal, mass, zeta, mu, kappa)
    w1 = _spin_change(spin, normal, radius, inertia, friction)
    return (
        velocity[0] + total[0] / mass,
        velocity[1] + total[1] / mass,
        velocity[2] + total[2] / mass,
        w1[0],
        w1[1],
        w1[2],
    )


def sphere_regime(velocity, spin, normal, surface_velocity, radius, zeta, mu, kappa):
    """Regime code of a sphere impact along its slip direction (into
    :data:`~spinimpact.core.impulse.REGIMES`)."""
    cn, _, speed, _ = sphere_contact(velocity, spin, normal, radius, surface_velocity)
    return regime_code(speed, cn, zeta, mu, kappa)


def sphere_dissipated_energy(velocity, spin, normal, surface_velocity, mass, radius, zeta, mu,
                             kappa):  # fmt: skip
    """Energy a sphere impact dissipates (in the surface's frame), J, ``>= 0``."""
    cn, _, speed, _ = sphere_contact(velocity, spin, normal, radius, surface_velocity)
    return contact_dissipated_energy(speed, cn, mass, zeta, mu, kappa)


def pair_parameters(mass1, inertia1, radius1, mass2, inertia2, radius2):
    """The seam's ``(1/W_nn, W_tt/W_nn)`` of two spheres in contact (reduced mass and
    ``zeta``), as :func:`spinimpact.core.sphere3d.pair_parameters`."""
    w_nn = 1.0 / mass1 + 1.0 / mass2
    w_tt = w_nn + radius1 * radius1 / inertia1 + radius2 * radius2 / inertia2
    return 1.0 / w_nn, w_tt / w_nn


def pair_rebound(velocity1, spin1, velocity2, spin2, normal, mass1, radius1, inertia1,
                 mass2, radius2, inertia2, mu, kappa):  # fmt: skip
    """Rebound of two spheres; ``normal`` points from sphere 2's centre to sphere 1's.

    Returns
    -------
    tuple of float
        ``(v1+ (3), w1+ (3), v2+ (3), w2+ (3))`` flattened: twelve floats, as
        :func:`spinimpact.solve_pair`'s ``after1`` and ``after2``.
    """
    r2n = (radius2 * normal[0], radius2 * normal[1], radius2 * normal[2])
    w2r = _cross(spin2, r2n)
    other = (velocity2[0] + w2r[0], velocity2[1] + w2r[1], velocity2[2] + w2r[2])
    cn, _, speed, e = sphere_contact(velocity1, spin1, normal, radius1, other)
    m, zeta = pair_parameters(mass1, inertia1, radius1, mass2, inertia2, radius2)
    friction, total = _impulse(cn, speed, e, normal, m, zeta, mu, kappa)
    a = _spin_change(spin1, normal, radius1, inertia1, friction)
    b = _spin_change(spin2, normal, radius2, inertia2, friction)
    return (
        velocity1[0] + total[0] / mass1,
        velocity1[1] + total[1] / mass1,
        velocity1[2] + total[2] / mass1,
        a[0], a[1], a[2],
        velocity2[0] - total[0] / mass2,
        velocity2[1] - total[1] / mass2,
        velocity2[2] - total[2] / mass2,
        b[0], b[1], b[2],
    )  # fmt: skip
