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

from .scalar import contact_dissipated_energy, contact_impact, contact_impulses, regime_code

__all__ = [
    "sphere_contact",
    "sphere_rebound",
    "sphere_regime",
    "sphere_dissipated_energy",
    "sphere_approaching",
    "pair_approaching",
    "pair_parameters",
    "pair_rebound",
    "sphere_impact_fields",
    "pair_impact_fields",
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


def _impulse(tau1, f1, e, normal):
    """Friction impulse vector ``F = f_1 e_t`` and the whole impulse ``P = tau_1 n + F``."""
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
    tau1, f1 = contact_impulses(speed, cn, mass, zeta, mu, kappa)[2:]
    return _sphere_after(velocity, spin, normal, mass, radius, inertia, tau1, f1, e)


def _sphere_after(velocity, spin, normal, mass, radius, inertia, tau1, f1, e):
    """A sphere's ``(v+, w+)`` (six floats) after the normal impulse ``tau_1`` and the
    friction impulse ``f_1`` along the slip direction ``e``."""
    friction, total = _impulse(tau1, f1, e, normal)
    w1 = _spin_change(spin, normal, radius, inertia, friction)
    return (
        velocity[0] + total[0] / mass,
        velocity[1] + total[1] / mass,
        velocity[2] + total[2] / mass,
        w1[0],
        w1[1],
        w1[2],
    )


def sphere_approaching(velocity, spin, normal, surface_velocity, radius):
    """Whether a sphere's contact point approaches the surface: ``c_n < 0``, with ``c_n`` of
    :func:`sphere_contact` (the number :func:`spinimpact.solve_sphere` checks).

    Parameters
    ----------
    velocity, spin, normal, surface_velocity : 3-tuples of float
        As :func:`sphere_rebound`.
    radius : float
        m.

    Returns
    -------
    bool
        ``False`` for a contact at rest or separating (and for NaN): no impact to solve.

    Examples
    --------
    >>> sphere_approaching((1.0, -2.0, 0.0), (0.0, 0.0, 5.0), (0.0, 1.0, 0.0),
    ...                    (0.0, 0.0, 0.0), 0.1)
    True
    """
    return sphere_contact(velocity, spin, normal, radius, surface_velocity)[0] < 0.0


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


def _pair_contact(velocity1, spin1, velocity2, spin2, normal, radius1, radius2):
    """:func:`sphere_contact` of sphere 1 against sphere 2's material at the contact."""
    r2n = (radius2 * normal[0], radius2 * normal[1], radius2 * normal[2])
    w2r = _cross(spin2, r2n)
    other = (velocity2[0] + w2r[0], velocity2[1] + w2r[1], velocity2[2] + w2r[2])
    return sphere_contact(velocity1, spin1, normal, radius1, other)


def pair_approaching(velocity1, spin1, velocity2, spin2, normal, radius1, radius2):
    """Whether two spheres' contact points approach each other: ``c_n < 0`` along
    ``normal`` (from sphere 2's centre to sphere 1's), the number
    :func:`spinimpact.solve_pair` checks.

    Parameters
    ----------
    velocity1, spin1, velocity2, spin2, normal : 3-tuples of float
        As :func:`pair_rebound` (m/s, rad/s; ``normal`` of unit length).
    radius1, radius2 : float
        m.

    Returns
    -------
    bool
        ``False`` for contacts at rest relative to each other, separating, or NaN.

    Examples
    --------
    >>> pair_approaching((0.0, 0.0, -1.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0),
    ...                  (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 0.03, 0.03)
    True
    """
    return _pair_contact(velocity1, spin1, velocity2, spin2, normal, radius1, radius2)[0] < 0.0


def pair_rebound(velocity1, spin1, velocity2, spin2, normal, mass1, radius1, inertia1,
                 mass2, radius2, inertia2, mu, kappa):  # fmt: skip
    """Rebound of two spheres; ``normal`` points from sphere 2's centre to sphere 1's.

    Returns
    -------
    tuple of float
        ``(v1+ (3), w1+ (3), v2+ (3), w2+ (3))`` flattened: twelve floats, as
        :func:`spinimpact.solve_pair`'s ``after1`` and ``after2``.
    """
    cn, _, speed, e = _pair_contact(velocity1, spin1, velocity2, spin2, normal, radius1, radius2)
    m, zeta = pair_parameters(mass1, inertia1, radius1, mass2, inertia2, radius2)
    tau1, f1 = contact_impulses(speed, cn, m, zeta, mu, kappa)[2:]
    friction, total = _impulse(tau1, f1, e, normal)
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


def _energy(mass, inertia, velocity, spin):
    return 0.5 * mass * _dot(velocity, velocity) + 0.5 * inertia * _dot(spin, spin)


def sphere_impact_fields(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta,
                         mu, kappa):  # fmt: skip
    """Every field of :func:`spinimpact.solve_sphere`'s result for one impact.

    Returns
    -------
    tuple
        ``(c_n, c_t, v+, w+, slip_after, c_n+, tau0, tau_star, tau1, F, impulse_ratio,
        E-, E+, dissipated_energy, dissipated_fraction, W_c^n, W_c^t, W_r^n, W_r^t,
        newton, poisson, energetic, rebound_speed, up, along, topspin, sidespin, gyrospin,
        regime_code, grips)``: 3-tuples for the vectors ``c_t, v+, w+, slip_after, F``; the
        rebound angle is ``numpy.arctan2(up, along)`` (left to NumPy, whose ``atan2`` the
        array path uses); ``topspin`` and ``gyrospin`` are NaN without travel along the
        surface after the impact.
    """
    n, vs = normal, surface_velocity
    cn, ct, speed, e = sphere_contact(velocity, spin, n, radius, vs)
    (tau0, tau_star, tau1, f1, _a, _b, code, wcn, wct, wrn, wrt, loss, _c, _d) = contact_impact(
        speed, cn, mass, zeta, mu, kappa
    )
    friction = (f1 * e[0], f1 * e[1], f1 * e[2])
    total = (tau1 * n[0] + friction[0], tau1 * n[1] + friction[1], tau1 * n[2] + friction[2])
    v1 = (velocity[0] + total[0] / mass, velocity[1] + total[1] / mass,
          velocity[2] + total[2] / mass)  # fmt: skip
    w1 = _spin_change(spin, n, radius, inertia, friction)
    cn1, ct1, _e, _f = sphere_contact(v1, w1, n, radius, vs)
    vrel = (velocity[0] - vs[0], velocity[1] - vs[1], velocity[2] - vs[2])
    e0_rel = _energy(mass, inertia, vrel, spin)
    stuck = speed <= (1.0 + kappa) * zeta * mu * abs(cn)
    rel = (v1[0] - vs[0], v1[1] - vs[1], v1[2] - vs[2])
    up = _dot(rel, n)
    along = (rel[0] - up * n[0], rel[1] - up * n[1], rel[2] - up * n[2])
    travel = math.sqrt(_dot(along, along))
    if travel > 0.0:
        et = (along[0] / travel, along[1] / travel, along[2] / travel)
        top, gyro = _dot(w1, _cross(n, et)), _dot(w1, et)
    else:
        top = gyro = math.nan
    eta2 = -wrn / wcn
    return (
        cn, ct, v1, w1, (0.0, 0.0, 0.0) if stuck else ct1, cn1, tau0, tau_star, tau1,
        friction, (-f1 + 0.0) / tau1, _energy(mass, inertia, velocity, spin),
        _energy(mass, inertia, v1, w1), loss, loss / e0_rel, wcn, wct, wrn, wrt, -cn1 / cn,
        (tau1 - tau0) / tau0, math.sqrt(eta2 if eta2 > 0.0 else 0.0), math.sqrt(_dot(v1, v1)),
        up, travel, top, _dot(w1, n), gyro, code, stuck,
    )  # fmt: skip


def pair_impact_fields(velocity1, spin1, velocity2, spin2, normal, mass1, radius1, inertia1,
                       mass2, radius2, inertia2, mu, kappa):  # fmt: skip
    """Every field of :func:`spinimpact.solve_pair`'s result for one impact of two spheres
    (``normal`` from ball 2's centre to ball 1's, of unit length).

    Returns
    -------
    tuple
        ``(c_n, c_t, v1+, w1+, v2+, w2+, slip_after, c_n+, tau0, tau_star, tau1, F,
        impulse_ratio, E-, E+, dissipated_energy, dissipated_fraction, W_c^n, W_c^t, W_r^n,
        W_r^t, newton, poisson, energetic, sine, cosine, regime_code, grips)``: the angle
        between the paths after is ``numpy.arctan2(sine, cosine)`` (both NaN where a ball
        is at rest after the impact).
    """
    n = normal
    r2n = (radius2 * n[0], radius2 * n[1], radius2 * n[2])
    a = _cross(spin2, r2n)
    other = (velocity2[0] + a[0], velocity2[1] + a[1], velocity2[2] + a[2])
    cn, ct, speed, e = sphere_contact(velocity1, spin1, n, radius1, other)
    m, zeta = pair_parameters(mass1, inertia1, radius1, mass2, inertia2, radius2)
    (tau0, tau_star, tau1, f1, _a, _b, code, wcn, wct, wrn, wrt, loss, _c, _d) = contact_impact(
        speed, cn, m, zeta, mu, kappa
    )
    friction = (f1 * e[0], f1 * e[1], f1 * e[2])
    total = (tau1 * n[0] + friction[0], tau1 * n[1] + friction[1], tau1 * n[2] + friction[2])
    v1 = (velocity1[0] + total[0] / mass1, velocity1[1] + total[1] / mass1,
          velocity1[2] + total[2] / mass1)  # fmt: skip
    v2 = (velocity2[0] - total[0] / mass2, velocity2[1] - total[1] / mass2,
          velocity2[2] - total[2] / mass2)  # fmt: skip
    w1 = _spin_change(spin1, n, radius1, inertia1, friction)
    w2 = _spin_change(spin2, n, radius2, inertia2, friction)
    b = _cross(w2, r2n)
    cn1, ct1, _e, _f = sphere_contact(v1, w1, n, radius1, (v2[0] + b[0], v2[1] + b[1],
                                                             v2[2] + b[2]))  # fmt: skip
    e0 = _energy(mass1, inertia1, velocity1, spin1) + _energy(mass2, inertia2, velocity2, spin2)
    p = (mass1 * velocity1[0] + mass2 * velocity2[0], mass1 * velocity1[1] + mass2 * velocity2[1],
         mass1 * velocity1[2] + mass2 * velocity2[2])  # fmt: skip
    e_cm = e0 - 0.5 * _dot(p, p) / (mass1 + mass2)
    stuck = speed <= (1.0 + kappa) * zeta * mu * abs(cn)
    s1, s2 = math.sqrt(_dot(v1, v1)), math.sqrt(_dot(v2, v2))
    sine = _cross(v1, v2)
    if s1 > 0 and s2 > 0:
        along, across = math.sqrt(_dot(sine, sine)), _dot(v1, v2)
    else:
        along = across = math.nan
    eta2 = -wrn / wcn
    return (
        cn, ct, v1, w1, v2, w2, (0.0, 0.0, 0.0) if stuck else ct1, cn1, tau0, tau_star, tau1,
        friction, (-f1 + 0.0) / tau1, e0,
        _energy(mass1, inertia1, v1, w1) + _energy(mass2, inertia2, v2, w2), loss,
        loss / e_cm, wcn, wct, wrn, wrt, -cn1 / cn, (tau1 - tau0) / tau0,
        math.sqrt(eta2 if eta2 > 0.0 else 0.0), along, across, code, stuck,
    )  # fmt: skip
