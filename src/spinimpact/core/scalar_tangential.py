r"""The tangential compliance laws for one contact, on floats: Walton's and Stronge's.

The compiled per-contact counterparts of ``solve(..., tangential=Walton(beta0))``,
``tangential=Stronge(...)`` and the same for ``solve_sphere``
(:mod:`spinimpact.model.compliance`, :mod:`spinimpact.model.compliant`). Each law gives the
slip of the contact point after the impact, ``c_t^+ = -beta c_t^-``, on the seam of
:mod:`spinimpact.core.impulse` (``W_tn = 0``: the paper's bodies, a sphere in 3D, whose
slip keeps its direction); the friction impulse ``f_1 = m (c_t^+ - c_t^-)/zeta`` goes back
to the body as in the rigid law, and the normal problem is the rigid one
(``c_n^+ = -kappa c_n^-``, ``tau_1 = (1 + kappa) m |c_n^-|``, eqs. 3.2, 3.6 of Lubarda
(2010), cited in :mod:`spinimpact.core.scalar`).

The formulas are written once, here and in :mod:`spinimpact.core.scalar_stronge`: the array
kernels (:func:`spinimpact.core.compliance.walton_slip`,
:func:`spinimpact.core.stronge.stronge_restitution`) and ``model/compliant.py`` call the same
functions, so the results equal the library's bit for bit (``tests/core/test_law_tangential.py``).
Numba-compatible; registered for compiled callers by :mod:`spinimpact.core.law`. Nothing is
validated: pass what ``solve`` accepts (``beta0`` in ``[-1, 1]``, ``stiffness_ratio > 0``).

References
----------
.. [1] O. R. Walton, "Numerical simulation of inclined chute flows of monodisperse,
   inelastic, frictional spheres", Mechanics of Materials 16 (1993) 239-247.
.. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000 (ch. 5).
"""

from __future__ import annotations

from .impulse import rebound_normal_velocity, total_impulse
from .kinematics import slip_velocity
from .scalar import sign
from .scalar3d import _sphere_after, sphere_contact
from .scalar_stronge import stronge_contact

__all__ = [
    "walton_contact",
    "walton_rebound",
    "stronge_contact",
    "stronge_rebound",
    "sphere_walton_rebound",
    "sphere_stronge_rebound",
]


def sliding_change(vy, zeta, mu, kappa):
    """``(1 + kappa) zeta mu |c_n^-|``: the slip Coulomb friction takes away over the whole
    impact when the contact slides throughout (eq. 4.16), m/s. Floats or arrays."""
    return (1.0 + kappa) * zeta * mu * abs(vy)


def walton_sticks(slip, beta0, change):
    """Walton's stick branch, ``beta_0 <= beta_slide``, free of divisions:
    ``(1 + beta_0)|c_t^-| <= (1 + kappa) zeta mu |c_n^-|`` (``change``). Floats or arrays."""
    return (1.0 + beta0) * abs(slip) <= change


def slid(slip, s, change):
    """Slip after sliding throughout, ``c_t^- - sign(c_t^-) change`` (``s`` the sign), m/s.
    Floats or arrays."""
    return slip - s * change


def tangential_impulse_of(mass, zeta, slip, slip_after):
    """Friction impulse that changes the slip from ``c_t^-`` to ``c_t^+``, N s:
    ``f_1 = (c_t^+ - c_t^-)/W_tt = m (c_t^+ - c_t^-)/zeta`` (``dc_t = W_tt df``)."""
    return mass * (slip_after - slip) / zeta


def impulse_to_body(vx, omega, mass, radius, zeta, f1):
    """The friction impulse ``f_1`` back to one of the paper's bodies (eqs. 2.1, 2.3):
    ``(vx + f_1/m, omega + (zeta - 1) f_1/(m R))``, m/s and rad/s. Floats or arrays."""
    return vx + f1 / mass, omega + (zeta - 1.0) * f1 / (mass * radius)


def walton_contact(slip, vy, zeta, mu, kappa, beta0):
    r"""Slip after one impact under Walton's law, ``beta = min(beta_0, beta_slide)``.

    Parameters
    ----------
    slip, vy : float
        Slip ``c_t^-`` and normal velocity ``c_n^- < 0`` of the contact point, m/s.
    zeta, mu, kappa : float
        ``W_tt/W_nn``, friction (``>= 0``) and normal restitution (in ``[0, 1]``).
    beta0 : float
        Tangential restitution of sticking impacts, in ``[-1, 1]`` (``0``: the rigid law).

    Returns
    -------
    tuple
        ``(slip_after, stuck)``: ``c_t^+ = -beta_0 c_t^-`` on the stick branch (m/s), else
        the rigid sliding rebound
        :math:`c_t^- - \mathrm{sign}(c_t^-)(1+\kappa)\zeta\mu|c_n^-|`; and whether it took
        the stick branch; as :func:`spinimpact.core.compliance.walton_slip`.

    Examples
    --------
    >>> walton_contact(1.0, -1.0, 3.5, 0.5, 0.8, 0.3)   # sticks: beta_0
    (-0.3, True)
    """
    change = sliding_change(vy, zeta, mu, kappa)
    if walton_sticks(slip, beta0, change):
        return -beta0 * slip + 0.0, True
    return slid(slip, sign(slip), change) + 0.0, False


def _rebound(vx, vy, omega, mass, radius, zeta, kappa, slip, slip_after):
    f1 = tangential_impulse_of(mass, zeta, slip, slip_after)
    vx1, omega1 = impulse_to_body(vx, omega, mass, radius, zeta, f1)
    return vx1, rebound_normal_velocity(vy, kappa), omega1, f1


def walton_rebound(vx, vy, omega, mass, radius, zeta, mu, kappa, beta0):
    """Rebound of one of the paper's bodies under Walton's law (eqs. 2.1-2.3, 4.4).

    Parameters
    ----------
    vx, vy, omega, mass, radius, zeta, mu, kappa : float
        As :func:`spinimpact.core.scalar.rebound`: incidence velocity (m/s, ``vy < 0``) and
        spin (rad/s), mass (kg), contact radius (m), ``zeta = 1 + R^2/rho^2``, friction and
        normal restitution.
    beta0 : float
        Walton's tangential restitution of sticking impacts, in ``[-1, 1]``.

    Returns
    -------
    tuple of float
        ``(vx^+, vy^+, omega^+, f_1)`` (m/s, m/s, rad/s, N s): ``solve(body, vx, vy, omega,
        mu=mu, kappa=kappa, tangential=Walton(beta0))``'s ``after`` and
        ``tangential_impulse``, bit for bit.

    Examples
    --------
    A solid sphere leaves with its contact point's slip reversed to ``beta_0`` of it:

    >>> vx, vy, omega, f1 = walton_rebound(1.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8, 0.4)
    >>> round(vx + 0.1 * omega, 12)   # u+ = -beta0 u-
    -0.4
    """
    slip = slip_velocity(vx, omega, radius)
    slip_after = walton_contact(slip, vy, zeta, mu, kappa, beta0)[0]
    return _rebound(vx, vy, omega, mass, radius, zeta, kappa, slip, slip_after)


def stronge_rebound(vx, vy, omega, mass, radius, zeta, mu, kappa, stiffness_ratio):
    """Rebound of one of the paper's bodies under Stronge's lumped tangential compliance.

    Parameters
    ----------
    vx, vy, omega, mass, radius, zeta, mu, kappa : float
        As :func:`walton_rebound` (``kappa``: Stronge's energetic coefficient, equal to
        Newton's and Poisson's here).
    stiffness_ratio : float
        ``k_t/k_n > 0``, e.g. Mindlin's ``2(1 - nu)/(2 - nu)``
        (:func:`spinimpact.core.compliance.mindlin_stiffness_ratio`; ``Stronge(...)``'s
        ``stiffness_ratio`` attribute).

    Returns
    -------
    tuple of float
        ``(vx^+, vy^+, omega^+, f_1)`` (m/s, m/s, rad/s, N s): ``solve(body, vx, vy, omega,
        mu=mu, kappa=kappa, tangential=Stronge(stiffness_ratio=r))``'s, bit for bit.

    Examples
    --------
    >>> vx, vy, omega, f1 = stronge_rebound(1.0, -1.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8, 0.87)
    >>> vx + 0.1 * omega > 0   # the slip reversed: the ball leaves with overspin
    False
    """
    slip = slip_velocity(vx, omega, radius)
    slip_after = stronge_contact(slip, vy, zeta, mu, kappa, stiffness_ratio)[0]
    return _rebound(vx, vy, omega, mass, radius, zeta, kappa, slip, slip_after)


def _sphere(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta, kappa, law,
            mu, parameter):  # fmt: skip
    cn, _, speed, e = sphere_contact(velocity, spin, normal, radius, surface_velocity)
    if law == 0:
        speed_after = walton_contact(speed, cn, zeta, mu, kappa, parameter)[0]
    else:
        speed_after = stronge_contact(speed, cn, zeta, mu, kappa, parameter)[0]
    f1 = tangential_impulse_of(mass, zeta, speed, speed_after)
    tau1 = total_impulse(mass, cn, kappa)
    return _sphere_after(velocity, spin, normal, mass, radius, inertia, tau1, f1, e)


def sphere_walton_rebound(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta,
                          mu, kappa, beta0):  # fmt: skip
    """Rebound of a sphere from a plane in 3D under Walton's law, along the slip.

    Parameters
    ----------
    velocity, spin, normal, surface_velocity : 3-tuples of float
        Centre velocity (m/s), spin (rad/s), the surface's unit normal and its velocity
        (m/s), as :func:`spinimpact.core.scalar3d.sphere_rebound`.
    mass, radius, inertia, zeta, mu, kappa : float
        kg, m, kg m^2, ``1 + R^2/rho^2``, friction, restitution.
    beta0 : float
        Walton's tangential restitution of sticking impacts, in ``[-1, 1]``.

    Returns
    -------
    tuple of float
        ``(vx+, vy+, vz+, wx+, wy+, wz+)``: ``solve_sphere(..., tangential=Walton(beta0))``'s
        ``after``, bit for bit.
    """
    return _sphere(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta,
                   kappa, 0, mu, beta0)  # fmt: skip


def sphere_stronge_rebound(velocity, spin, normal, surface_velocity, mass, radius, inertia,
                           zeta, mu, kappa, stiffness_ratio):  # fmt: skip
    """Rebound of a sphere from a plane in 3D under Stronge's law, along the slip.

    Parameters
    ----------
    velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta, mu, kappa
        As :func:`sphere_walton_rebound`.
    stiffness_ratio : float
        ``k_t/k_n > 0``.

    Returns
    -------
    tuple of float
        ``(vx+, vy+, vz+, wx+, wy+, wz+)``: ``solve_sphere(..., tangential=Stronge(...))``'s
        ``after``, bit for bit.
    """
    return _sphere(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta,
                   kappa, 1, mu, stiffness_ratio)  # fmt: skip
