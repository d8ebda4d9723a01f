"""Energy of the paper's bodies during and after the impact (paper sections 5, 6 and 8).

The works, the dissipated energy and the impulse of least kinetic energy are
properties of the contact point (:mod:`spinimpact.core.works`); the functions here
take the body's incidence ``(vx, vy, omega)`` and ``(mass, radius, zeta)``, form
the slip ``u = vx + R omega`` (eq. 4.4) and call them. Only the kinetic energy
itself, ``m (vx^2 + vy^2)/2 + J omega^2/2``, needs the body.

The contact-level functions are re-exported here under their historical names
(``spinimpact.core.energetics.work_tangential`` is
:func:`spinimpact.core.works.work_tangential`).

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a
   fixed surface", Proceedings of the Section of Natural Sciences, Montenegrin
   Academy of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
"""

from __future__ import annotations

from .kinematics import slip_velocity, state_at
from .works import (
    MIN_ENERGY_CASES,
    PhaseWorks,
    WorkRatioBounds,
    contact_dissipated_energy,
    contact_min_energy_case,
    contact_min_energy_impulse,
    contact_phase_works,
    restitution_work,
    restitution_work_zero,
    work_normal,
    work_ratio_tangential,
    work_ratio_tangential_bounds,
    work_tangential,
)

__all__ = [
    "MIN_ENERGY_CASES",
    "PhaseWorks",
    "WorkRatioBounds",
    "kinetic_energy",
    "work_normal",
    "work_tangential",
    "phase_works",
    "dissipated_energy",
    "kinetic_energy_at",
    "min_energy_impulse",
    "min_energy_case",
    "work_ratio_tangential",
    "work_ratio_tangential_bounds",
    "restitution_work",
    "restitution_work_zero",
]


def kinetic_energy(vx, vy, omega, mass, inertia):
    """Kinetic energy of plane motion, ``m (vx^2 + vy^2)/2 + J omega^2/2``, J.

    Parameters
    ----------
    vx, vy : array_like
        Centre velocity, m/s.
    omega : array_like
        Spin, rad/s.
    mass : array_like
        Mass ``m``, kg.
    inertia : array_like
        Moment of inertia ``J = m rho^2`` about the centre, kg m^2.
    """
    return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * omega * omega


def phase_works(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Works ``(W_c^n, W_c^t, W_r^n, W_r^t)`` of the normal and friction forces in
    compression and restitution (eqs. 6.1-6.11), J, as a :class:`PhaseWorks`.

    :func:`~spinimpact.core.works.contact_phase_works` of the slip ``u^-``.
    """
    return contact_phase_works(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)


def dissipated_energy(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Energy lost in the impact, ``Delta E = -(W^n + W^t) >= 0`` (eqs. 5.1, 5.10), J.

    Equals eq. (5.4) ``m (v^-)^2 (1 - kappa^2 + |u^-/v^-|^2/zeta) / 2`` when the
    contact sticks and eq. (5.6) when it slips throughout;
    :func:`~spinimpact.core.works.contact_dissipated_energy` of the slip ``u^-``.
    """
    return contact_dissipated_energy(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)


def kinetic_energy_at(tau, vx, vy, omega, mass, radius, zeta, mu, inertia):
    """Kinetic energy ``E(tau)`` during the impact (eq. 8.1 and the two forms after it), J.

    By the work principle ``E(tau) = E^- + int_0^tau (v + u F/N) dtau`` equals the
    kinetic energy of the velocities at ``tau`` (:func:`state_at`), which is how it
    is evaluated here: non-negative by construction. ``tau`` broadcasts with the
    incidence arrays; ``inertia`` is ``J = m rho^2``.
    """
    return kinetic_energy(*state_at(tau, vx, vy, omega, mass, radius, zeta, mu), mass, inertia)


def min_energy_impulse(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Impulse ``tau_m`` at which the kinetic energy is smallest (eqs. 8.2-8.6), N s.

    :func:`~spinimpact.core.works.contact_min_energy_impulse` of the slip ``u^-``:
    ``m (|v^-| + mu |u^-|)/(1 + zeta mu^2)`` while slipping (eq. 8.2), ``tau_0`` in the
    rolling stage (eq. 8.6), and ``tau_1`` when slip continues past eq. (8.5) (a case
    the paper does not state; ``docs/errata.md``).
    """
    return contact_min_energy_impulse(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)


def min_energy_case(vx, vy, omega, mass, radius, zeta, mu, kappa):
    """Index into :data:`MIN_ENERGY_CASES` of where ``E(tau)`` is smallest (Fig. 5).

    :func:`~spinimpact.core.works.contact_min_energy_case` of the slip ``u^-``.
    """
    return contact_min_energy_case(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)
