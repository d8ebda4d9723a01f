r"""Compliant normal contact laws and the impact in time.

The paper works in the normal impulse ``tau`` and never needs the shape of
``N(t)`` (Keller's method). These kernels add what happens in time: a
compliant normal force ``N(delta, delta_dot)`` of the compression
``delta >= 0`` (m, positive into the surface, ``delta_dot = -v_y``), the
equations of motion (2.4) with Coulomb friction ``F = -mu N sign(u)`` while
slipping and ``F = 0`` once the contact point sticks (zero tangential
compliance, as in the paper), integrated with SciPy's ``solve_ivp`` and event
location.

The normal motion does not depend on friction, and while slipping
``du/dt = -zeta mu N sign(u)/m``, i.e. ``du/dtau = -zeta mu sign(u)/m`` whatever
``N(t)`` is: the rebound therefore equals the rigid-body closed form with
``kappa`` set to the contact law's own restitution - the check that
:func:`spinimpact.dynamics.simulate` is tested against.

Plain numerics, no validation: the force laws broadcast, and
:func:`integrate_contact` is the one place the physics of the impact in time lives.

References
----------
.. [1] H. Hertz, "Ueber die Berührung fester elastischer Körper", Journal für
   die reine und angewandte Mathematik 92 (1882) 156-171.
.. [2] K. H. Hunt, F. R. E. Crossley, "Coefficient of restitution interpreted as
   damping in vibroimpact", Journal of Applied Mechanics 42 (1975) 440-445.
.. [3] W. J. Stronge, *Impact Mechanics*, Cambridge University Press,
   Cambridge (2000).
.. [4] K. L. Johnson, *Contact Mechanics*, Cambridge University Press,
   Cambridge (1985), sec. 11.4.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from .restitution import restitution_by_definition

__all__ = [
    "linear_force",
    "hunt_crossley_force",
    "effective_modulus",
    "hertz_stiffness",
    "hertz_max_compression",
    "hertz_duration",
    "HERTZ_DURATION_FACTOR",
    "power_law_time_scale",
    "ContactRun",
    "integrate_contact",
    "integrate_normal_impact",
]

#: ``2 int_0^1 (1 - x^{5/2})^{-1/2} dx = (4/5) B(2/5, 1/2)``: Hertz contact duration
#: in units of ``delta_max / v`` (Johnson, *Contact Mechanics*, 1985, sec. 11.4).
HERTZ_DURATION_FACTOR = 0.8 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)


def linear_force(delta, delta_dot, stiffness, damping):
    r"""Linear spring-dashpot (Kelvin-Voigt) normal force.

    Parameters
    ----------
    delta : array_like
        Compression ``delta``, m (positive into the surface).
    delta_dot : array_like
        Compression rate ``d delta/dt = -v_y``, m/s.
    stiffness : array_like
        Spring stiffness ``k``, N/m.
    damping : array_like
        Dashpot coefficient ``c``, N s/m.

    Returns
    -------
    ndarray
        Signed force ``N``, N.

    Notes
    -----
    .. math:: N = k \delta + c \dot\delta

    The law is linear, so its restitution depends on the damping ratio
    ``c/(2 sqrt(k m))`` only, not on the impact speed [1]_. The value is signed:
    the integrator applies ``max(N, 0)`` (a surface cannot pull) and ends the
    contact where ``N`` falls to zero, before ``delta`` returns to zero.

    References
    ----------
    .. [1] W. J. Stronge, *Impact Mechanics*, Cambridge University Press,
       Cambridge (2000).
    """
    return stiffness * delta + damping * delta_dot


def hunt_crossley_force(delta, delta_dot, stiffness, exponent, alpha):
    r"""Hunt-Crossley normal force, a power-law spring with damping proportional to it.

    Parameters
    ----------
    delta : array_like
        Compression ``delta``, m.
    delta_dot : array_like
        Compression rate ``-v_y``, m/s.
    stiffness : array_like
        ``k``, N/m^n.
    exponent : array_like
        ``n``, dimensionless (3/2 for Hertz sphere-on-plane contact).
    alpha : array_like
        Damping factor, s/m; ``0`` is purely elastic.

    Returns
    -------
    ndarray
        Signed force ``N``, N (``delta^n`` is continued as ``sign(delta)|delta|^n``).

    Notes
    -----
    .. math:: N = k \delta^n \left(1 + \tfrac{3}{2} \alpha \dot\delta\right)

    Hunt and Crossley [2]_ chose damping proportional to the elastic force, so
    the force is continuous at first touch and the restitution falls with the
    impact speed, ``kappa ~ 1 - alpha v`` for small ``alpha v``; with ``n = 3/2``
    and ``alpha = 0`` this is Hertz's law [1]_.

    References
    ----------
    .. [1] H. Hertz, "Ueber die Berührung fester elastischer Körper", Journal für
       die reine und angewandte Mathematik 92 (1882) 156-171.
    .. [2] K. H. Hunt, F. R. E. Crossley, "Coefficient of restitution interpreted as
       damping in vibroimpact", Journal of Applied Mechanics 42 (1975) 440-445.
    """
    return stiffness * np.sign(delta) * np.abs(delta) ** exponent * (1.0 + 1.5 * alpha * delta_dot)


def effective_modulus(youngs_modulus, poisson_ratio):
    """Plane-strain modulus ``E* = E/(1 - nu^2)`` in Pa of an elastic body on a rigid
    plane (``E`` in Pa, ``nu`` dimensionless)."""
    return youngs_modulus / (1.0 - poisson_ratio**2)


def hertz_stiffness(youngs_modulus, poisson_ratio, radius):
    r"""Hertz sphere-on-plane stiffness ``k`` in N/m^(3/2).

    Parameters
    ----------
    youngs_modulus : array_like
        ``E``, Pa.
    poisson_ratio : array_like
        ``nu``, dimensionless.
    radius : array_like
        Radius of curvature at the contact ``R``, m.

    Notes
    -----
    .. math:: N = k \delta^{3/2}, \qquad k = \tfrac{4}{3} E^* \sqrt{R},
        \qquad E^* = E/(1 - \nu^2)

    for an elastic sphere on a rigid plane [1]_ (Johnson 1985, sec. 4.2).

    References
    ----------
    .. [1] H. Hertz, "Ueber die Berührung fester elastischer Körper", Journal für
       die reine und angewandte Mathematik 92 (1882) 156-171.
    """
    return 4.0 / 3.0 * effective_modulus(youngs_modulus, poisson_ratio) * np.sqrt(radius)


def hertz_max_compression(mass, speed, stiffness):
    """Largest compression in m of an elastic Hertz impact, ``(5 m v^2/(4 k))^{2/5}``
    (``mass`` kg, ``speed`` m/s, ``stiffness`` N/m^(3/2)).

    From energy balance ``m v^2/2 = int_0^dm k d^{3/2} dd = 2 k dm^{5/2}/5``.
    """
    return (1.25 * mass * speed**2 / stiffness) ** 0.4


def hertz_duration(mass, speed, stiffness):
    """Classical elastic Hertz contact duration in s,
    ``HERTZ_DURATION_FACTOR * delta_max / v`` (Johnson 1985, eq. 11.24)."""
    return HERTZ_DURATION_FACTOR * hertz_max_compression(mass, speed, stiffness) / speed


def power_law_time_scale(mass, speed, stiffness, exponent):
    """``delta_max/v`` in s of an elastic ``N = k delta^n`` impact, with
    ``delta_max = ((n+1) m v^2/(2k))^{1/(n+1)}``: the order of the contact duration."""
    return ((exponent + 1.0) * mass * speed**2 / (2.0 * stiffness)) ** (
        1.0 / (exponent + 1.0)
    ) / speed


class ContactRun(NamedTuple):
    """One compliant impact sampled in time (:func:`integrate_contact`); the arrays
    share one length, and the event times are samples."""

    t: np.ndarray  #: sample times, s
    compression: np.ndarray  #: delta, m
    vx: np.ndarray  #: centre velocity along the surface, m/s
    vy: np.ndarray  #: normal velocity, m/s
    omega: np.ndarray  #: spin, rad/s
    tau: np.ndarray  #: normal impulse, N s
    tangential_impulse: np.ndarray  #: f, N s
    normal_work: np.ndarray  #: work of the normal force, J
    normal_force: np.ndarray  #: max(N, 0), N
    friction_force: np.ndarray  #: F, N
    slip: np.ndarray  #: contact-point velocity u = vx + R omega, m/s
    stuck: np.ndarray  #: whether the contact point sticks (bool)
    t0: float  #: end of compression (v_y = 0), s
    t_star: float  #: slip stops, s (nan if never)
    t1: float  #: separation (N = 0): the contact duration, s
    tau0: float  #: normal impulse at t0, N s
    compression_work: float  #: work of N up to t0, J (< 0)
    peak_force: float  #: largest N over the samples, N
    max_compression: float  #: delta at t0, m
    newton_restitution: float  #: -v_y(t1)/v_y(0) (eq. 1.1)
    poisson_restitution: float  #: (tau1 - tau0)/tau0 (eq. 1.2)
    energetic_restitution: float  #: sqrt(-W_r/W_c) of the normal works (eq. 1.3)


def integrate_contact(
    force: Callable[[float, float], float],
    mass: float,
    radius: float,
    inertia: float,
    mu: float,
    vx: float,
    vy: float,
    omega: float,
    *,
    time_scale: float,
    rtol: float = 1e-10,
    atol=None,
    samples: int = 400,
    exponent: float = 1.0,
) -> ContactRun:
    r"""Integrate one compliant impact in time (eq. 2.4) with exact stick-slip switching.

    Parameters
    ----------
    force : callable
        ``force(delta, delta_dot) -> N`` (scalars; m, m/s -> N), smooth and signed:
        the contact force is ``max(N, 0)`` and the contact ends where ``N`` falls to 0.
    mass : float
        ``m``, kg.
    radius : float
        Contact radius ``R``, m.
    inertia : float
        Moment of inertia about the centre ``J``, kg m^2.
    mu : float
        Kinetic Coulomb friction coefficient.
    vx, vy, omega : float
        Incidence: centre velocity in m/s (``vy < 0``) and spin in rad/s.
    time_scale : float
        Order of magnitude of the contact duration, s, for scaling.
    rtol, atol : float
        Tolerances of the adaptive integrator (DOP853); ``atol`` defaults to
        ``rtol`` times the natural scales of the state.
    samples : int
        Number of evenly spaced output times (the dense output of the
        integrator), to which the event times are added.
    exponent : float
        Power ``n`` with which the force vanishes at separation (``N ~ delta^n``).
        The separation event watches ``sign(N) |N|^(1/n)``, which crosses zero
        linearly, so the root finder locates it even for ``n >= 2.5``.

    Returns
    -------
    ContactRun
        The time series, the event times, the extremes and the three
        restitution coefficients measured on the process.

    Notes
    -----
    The state ``(delta, v_x, v_y, omega, tau, f, W_n)`` obeys

    .. math::

        \dot\delta = -v_y, \quad m \dot v_x = F, \quad m \dot v_y = N, \quad
        J \dot\omega = R F, \quad \dot\tau = N, \quad \dot f = F, \quad
        \dot W_n = N v_y,

    with ``N = max(force(delta, -v_y), 0)`` and ``F = -mu N sign(u)``,
    ``u = v_x + R omega``, while the contact point slips. The instant ``u = 0``
    is an event; from there ``F = 0`` and ``u`` stays zero (Stronge 2000,
    pp. 55-57, as the paper uses it). ``v_y = 0`` marks the end of compression
    (``t0``, ``tau0``, ``W_c``) and ``N = 0`` the separation (``t1``). The
    restitution coefficients are then ``-v_y(t1)/v_y(0)`` (Newton),
    ``(tau1 - tau0)/tau0`` (Poisson) and ``sqrt(-W_r/W_c)`` (energetic, with
    ``W_r = W_n(t1) - W_c``), measured on the process rather than from a
    closed form.
    """
    from .events import Event, integrate_events

    speed = abs(vy)
    vscale = abs(vx) + speed + abs(radius * omega)
    if atol is None:
        atol = rtol * np.array([speed * time_scale, vscale, vscale, vscale / radius,
                                mass * vscale, mass * vscale, mass * vscale**2])  # fmt: skip

    def rhs(_t, y, ratio):
        delta, vx_, vy_, om, tau, f, wn = y
        n = max(force(delta, -vy_), 0.0)
        friction = ratio * n
        return [-vy_, friction / mass, n / mass, friction * radius / inertia, n, friction, n * vy_]

    def slip_zero(_t, y):
        return y[1] + radius * y[3]

    def compression_end(_t, y):
        return y[2]

    def separation(_t, y):
        n = force(y[0], -y[2])
        return math.copysign(abs(n) ** (1.0 / exponent), n)

    y = np.array([0.0, vx, vy, omega, 0.0, 0.0, 0.0])
    t = 0.0
    stuck = vx + radius * omega == 0
    segments = []  # (start, end, dense solution, stuck)
    t0 = t_star = tau0 = work_n0 = math.nan
    horizon = 1e3 * time_scale
    while True:
        sign = math.copysign(1.0, y[1] + radius * y[3])
        ratio = 0.0 if stuck else -mu * sign
        # each crosses zero once: v_y rising, N falling, the slip towards zero (at the step
        # ends, as solve_ivp; the state at separation is integrated up to it, not
        # interpolated across the end of the force)
        events = [Event(compression_end, 1, terminal=False, watched=False),
                  Event(separation, -1, watched=False, integrate_to=True)]  # fmt: skip
        events += [] if stuck else [Event(slip_zero, -int(sign), watched=False)]
        sol = integrate_events(lambda tt, yy, r=ratio: rhs(tt, yy, r), t, y, t + horizon,
                               events, rtol=rtol, atol=atol)  # fmt: skip
        if sol.status == -1:
            raise RuntimeError(f"contact integration failed: {sol.message}")
        if sol.t_events[0].size and math.isnan(t0):
            t0, y0 = sol.t_events[0][0], sol.y_events[0][0]
            tau0, work_n0 = y0[4], y0[6]
        if sol.t > t:  # an event exactly at the start leaves nothing to keep
            segments.append((t, sol.t, sol.sol, stuck))
        t, y = sol.t, sol.y.copy()
        if sol.status == 0:
            raise RuntimeError("contact did not end within 1000 time scales; check the contact law")
        if sol.t_events[1].size:  # separation: N has fallen to zero
            break
        # slip has stopped: from here F = 0 and u stays 0 (the paper's rolling stage)
        stuck, t_star = True, t
        y[3] = -y[1] / radius
    ends = [seg[1] for seg in segments]
    times = np.union1d(np.linspace(0.0, t, samples), [x for x in (t0, *ends) if x == x])
    out = np.empty((7, times.size))
    flags = np.empty(times.size, dtype=bool)
    for i, (start, end, dense, is_stuck) in enumerate(segments):
        last = i == len(segments) - 1
        sel = (times >= start) & ((times < end) | last)
        out[:, sel] = dense(times[sel])
        flags[sel] = is_stuck
    out[:, -1] = y  # the end state exactly as integrated
    for start, _, _, is_stuck in segments[1:]:  # the stick instant belongs to the stuck phase
        k = np.searchsorted(times, start)
        flags[k] = is_stuck
        out[3, k] = -out[1, k] / radius if is_stuck else out[3, k]
    delta, vxs, vys, oms, tau, f, work_n = out
    normal = np.maximum([force(d, -v) for d, v in zip(delta, vys, strict=True)], 0.0)
    slip = np.where(flags, 0.0, vxs + radius * oms)
    ratio = np.where(flags, 0.0, -mu * np.sign(vxs + radius * oms))
    tau0, tau1, work_n0 = float(tau0), float(y[4]), float(work_n0)
    work_r = float(y[6]) - work_n0
    kappas = restitution_by_definition(vy, float(y[2]), tau0, tau1, work_n0, work_r)
    return ContactRun(
        t=times, compression=delta, vx=vxs, vy=vys, omega=oms, tau=tau,
        tangential_impulse=f, normal_work=work_n, normal_force=normal,
        friction_force=ratio * normal, slip=slip, stuck=flags,
        t0=float(t0), t_star=float(t_star), t1=float(t), tau0=tau0,
        compression_work=work_n0, peak_force=float(normal.max()),
        max_compression=float(np.interp(t0, times, delta)),  # largest where v_y = 0
        newton_restitution=float(kappas.newton), poisson_restitution=float(kappas.poisson),
        energetic_restitution=float(kappas.energetic),
    )  # fmt: skip


def integrate_normal_impact(
    force: Callable[[float, float], float], mass: float, speed: float, *,
    time_scale: float, rtol: float = 1e-10, exponent: float = 1.0,
) -> ContactRun:  # fmt: skip
    """A drop at ``speed`` (m/s) without spin or friction: :func:`integrate_contact`
    with ``vx = omega = mu = 0``.

    The normal motion is that of a point ``mass`` (kg): the contact radius and the
    inertia do not enter it (set to 1 m and ``mass`` x 1 m^2). The run's
    ``newton_restitution``, ``t1`` (the duration), ``peak_force`` and
    ``max_compression`` are the law's answers at this speed; the other
    arguments are as for :func:`integrate_contact`.
    """
    return integrate_contact(force, mass, 1.0, mass, 0.0, 0.0, -speed, 0.0,
                             time_scale=time_scale, rtol=rtol, exponent=exponent)  # fmt: skip
