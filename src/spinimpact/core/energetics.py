"""Energy of the paper's bodies during and after the impact (paper sections 5, 6 and 8).

The works, the dissipated energy and the impulse of least kinetic energy are
properties of the contact point (:mod:`spinimpact.core.works`); the functions here
take the body's incidence ``(vx, vy, omega)`` and ``(mass, radius, zeta)``, form
the slip ``u = vx + R omega`` (eq. 4.4) and call them. Only the kinetic energy
itself, ``m (vx^2 + vy^2)/2 + J omega^2/2``, needs the body. Equation and figure
numbers are those of Lubarda [1]_; all quantities are in SI units.

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
    r"""Kinetic energy of a rigid body in plane motion.

    Parameters
    ----------
    vx, vy : float or array
        Velocity of the centre of mass, m/s.
    omega : float or array
        Spin, rad/s.
    mass : float or array
        Mass ``m``, kg.
    inertia : float or array
        Moment of inertia ``J = m rho^2`` about the centre of mass, kg m^2.

    Returns
    -------
    energy : float or array
        ``E``, J.

    Notes
    -----
    König's theorem: translation of the centre of mass plus rotation about it [2]_,

    .. math:: E = \tfrac12 m (v_x^2 + v_y^2) + \tfrac12 J \omega^2 .

    ``E^-`` and ``E^+`` of the paper's eq. (5.11) [1]_.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    .. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.

    Examples
    --------
    A solid sphere of 1 kg and radius 0.1 m (``J = 0.004`` kg m^2) rolling at 2 m/s:

    >>> float(kinetic_energy(vx=2.0, vy=0.0, omega=-20.0, mass=1.0, inertia=0.004))
    2.8
    """
    return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * omega * omega


def phase_works(vx, vy, omega, mass, radius, zeta, mu, kappa):
    r"""Works of the normal and friction forces in compression and restitution.

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
    PhaseWorks
        ``(compression_normal, compression_tangential, restitution_normal,
        restitution_tangential)``: ``(W_c^n, W_c^t, W_r^n, W_r^t)``, J.

    Notes
    -----
    :func:`~spinimpact.core.works.contact_phase_works` of the slip ``u^- = vx + R omega``:

    .. math::

        W_c = \int_0^{\tau_0} v\,d\tau + \int_0^{\tau_0} \frac{F}{N} u\,d\tau , \qquad
        W_r = \int_{\tau_0}^{\tau_1} v\,d\tau + \int_{\tau_0}^{\tau_1} \frac{F}{N} u\,d\tau

    (eqs. 6.1, 6.2), the first integral of each the normal work ``W^n``, the second the
    friction work ``W^t``; in closed form eqs. (6.6)-(6.11) [1]_.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    A solid disk (``zeta = 3``, ``m = 1`` kg, ``R = 0.1`` m) sliding at ``u^- = 1`` m/s
    onto the surface at ``v^- = -1`` m/s with ``mu = 0.2``, ``kappa = 0.5`` slips
    throughout (``|u^-/v^-| = 1 > (1 + kappa) zeta mu = 0.9``):

    >>> w = phase_works(1.0, -1.0, 0.0, mass=1.0, radius=0.1, zeta=3.0, mu=0.2, kappa=0.5)
    >>> [round(float(x), 12) for x in w]
    [-0.5, -0.14, 0.125, -0.025]
    """
    return contact_phase_works(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)


def dissipated_energy(vx, vy, omega, mass, radius, zeta, mu, kappa):
    r"""Energy lost in the impact, ``Delta E = E^- - E^+ >= 0``.

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
    energy : float or array
        ``Delta E``, J.

    Notes
    -----
    :func:`~spinimpact.core.works.contact_dissipated_energy` of the slip
    ``u^- = vx + R omega``: the negative work of the contact forces (eqs. 5.1, 5.10),

    .. math:: \Delta E = -\int_0^{\tau_1} v\,d\tau - \int_0^{\tau_1} \frac{F}{N} u\,d\tau ,

    equal to ``m |v^-|^2 (1 - kappa^2 + |u^-/v^-|^2/zeta)/2`` (after eq. 5.4) when the
    contact sticks and to eq. (5.6) when it slips throughout [1]_.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    A solid disk (``zeta = 3``, ``m = 1`` kg, ``R = 0.1`` m) sliding at ``u^- = 1`` m/s
    onto the surface at ``v^- = -1`` m/s with ``mu = 0.2``, ``kappa = 0.5`` slips
    throughout (``|u^-/v^-| = 1 > (1 + kappa) zeta mu = 0.9``):

    >>> e = dissipated_energy(1.0, -1.0, 0.0, mass=1.0, radius=0.1, zeta=3.0, mu=0.2, kappa=0.5)
    >>> round(float(e), 12)  # eq. (5.6): (1.5/2) (0.5 + 0.2 (2 - 0.9))
    0.54
    """
    return contact_dissipated_energy(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)


def kinetic_energy_at(tau, vx, vy, omega, mass, radius, zeta, mu, inertia):
    r"""Kinetic energy ``E(tau)`` during the impact (eq. 8.1 and the two forms after it).

    Parameters
    ----------
    tau : float or array
        Normal impulse since first contact, N s, in ``[0, tau_1]``; broadcasts with the
        incidence arrays.
    vx, vy, omega : float or array
        Incidence velocity of the centre (m/s, ``vy < 0``) and spin (rad/s).
    mass, radius, zeta : float or array
        Mass ``m`` (kg), contact radius ``R`` (m) and ``zeta = 1 + R^2/rho^2``.
    mu : float or array
        Kinetic Coulomb friction coefficient.
    inertia : float or array
        Moment of inertia ``J = m rho^2`` about the centre, kg m^2.

    Returns
    -------
    energy : float or array
        ``E(tau)``, J.

    Notes
    -----
    By the work principle (eq. 8.1 [1]_)

    .. math:: E(\tau) = E^- + \int_0^\tau \left(v + u\,\frac{F}{N}\right) d\tau' ,

    which equals the kinetic energy of the velocities at ``tau``
    (:func:`~spinimpact.core.kinematics.state_at`). It is evaluated that way here, so it
    is non-negative by construction.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    The disk of :func:`dissipated_energy` (``E^- = 1`` J) at the start, at the end of
    compression (``tau_0 = 1`` N s) and at the end of the impact (``tau_1 = 1.5`` N s):

    >>> import numpy as np
    >>> tau = np.array([0.0, 1.0, 1.5])
    >>> e = kinetic_energy_at(tau, 1.0, -1.0, 0.0, 1.0, 0.1, 3.0, 0.2, inertia=0.005)
    >>> [round(float(x), 12) for x in e]
    [1.0, 0.36, 0.46]
    """
    return kinetic_energy(*state_at(tau, vx, vy, omega, mass, radius, zeta, mu), mass, inertia)


def min_energy_impulse(vx, vy, omega, mass, radius, zeta, mu, kappa):
    r"""Normal impulse ``tau_m`` at which the kinetic energy is smallest (eqs. 8.2-8.6).

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
    tau_m : float or array
        N s, in ``[tau_0, tau_1]``.

    Notes
    -----
    :func:`~spinimpact.core.works.contact_min_energy_impulse` of the slip
    ``u^- = vx + R omega``:

    .. math:: \tau_m = \begin{cases}
            \tau_0, & |u^-/v^-| \le \zeta\mu \quad \text{(rolling, 8.6)} \\
            m\,(|v^-| + \mu|u^-|)/(1 + \zeta\mu^2), & \text{otherwise, if below } \tau_1
                \quad \text{(sliding, 8.2, 8.5)} \\
            \tau_1, & \text{otherwise (slip beyond 8.5)}
        \end{cases}

    The last case, where slip continues and eq. (8.2) exceeds ``tau_1``, is not stated by
    the paper [1]_: the energy still falls when the impact ends, so its minimum is the
    rebound energy (``docs/errata.md``).

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    The case of ``docs/errata.md``: a solid disk with ``mu = 0.1``, ``kappa = 0.5``,
    ``u^- = 10`` m/s, ``v^- = -1`` m/s reaches its least energy at the rebound,
    ``tau_m = tau_1 = 1.5`` N s:

    >>> args = (10.0, -1.0, 0.0, 1.0, 0.1, 3.0, 0.1, 0.5)
    >>> float(min_energy_impulse(*args)), MIN_ENERGY_CASES[min_energy_case(*args)]
    (1.5, 'at rebound')
    """
    return contact_min_energy_impulse(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)


def min_energy_case(vx, vy, omega, mass, radius, zeta, mu, kappa):
    r"""Index into :data:`MIN_ENERGY_CASES` of where ``E(tau)`` is smallest (Fig. 5).

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
    case : int8 array
        ``MIN_ENERGY_CASES[case]`` names it: sliding then stick (Fig. 5a), rolling
        (Fig. 5b), sliding throughout (Fig. 5c), at rebound, or frictionless.

    Notes
    -----
    :func:`~spinimpact.core.works.contact_min_energy_case` of the slip
    ``u^- = vx + R omega``; the cases follow eqs. (8.2)-(8.6) [1]_, with "at rebound"
    where slip continues past eq. (8.5) (``docs/errata.md``).

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    A solid sphere struck without spin at ``vx = 2``, ``vy = -3`` m/s sticks in
    compression, and its least energy is at the end of compression:

    >>> MIN_ENERGY_CASES[min_energy_case(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8)]
    'rolling (Fig. 5b)'
    """
    return contact_min_energy_case(slip_velocity(vx, omega, radius), vy, mass, zeta, mu, kappa)
