"""Compliant normal contact laws and the impact in time.

The paper works in the normal impulse ``tau`` and never needs the shape of
``N(t)`` (Keller's method). These kernels add what happens in time: a
compliant normal force ``N(delta, delta_dot)`` of the compression
``delta >= 0`` (positive into the surface, ``delta_dot = -v``), the equations of
motion (2.4) with Coulomb friction ``F = -mu N sign(u)`` while slipping and
``F = 0`` once the contact point sticks (zero tangential compliance, as in the
paper), integrated with SciPy's ``solve_ivp`` and event location.

The normal motion does not depend on friction, and while slipping
``du/dt = -zeta mu N sign(u)/m``, i.e. ``du/dtau = -zeta mu sign(u)/m`` whatever
``N(t)`` is: the rebound therefore equals the rigid-body closed form with
``kappa`` set to the contact law's own restitution - the check that
:mod:`spinimpact.dynamics` is tested against.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "linear_force",
    "hunt_crossley_force",
    "effective_modulus",
    "hertz_stiffness",
    "hertz_max_compression",
    "hertz_duration",
    "HERTZ_DURATION_FACTOR",
    "power_law_time_scale",
    "integrate_contact",
]

#: ``2 int_0^1 (1 - x^{5/2})^{-1/2} dx = (4/5) B(2/5, 1/2)``: Hertz contact duration
#: in units of ``delta_max / v`` (Johnson, *Contact Mechanics*, 1985, sec. 11.4).
HERTZ_DURATION_FACTOR = 0.8 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)


def linear_force(delta, delta_dot, stiffness, damping):
    """Kelvin-Voigt force ``N = k delta + c delta_dot``.

    Signed: the integrator applies ``max(N, 0)`` (a surface cannot pull) and ends
    the contact where this value falls to zero.
    """
    return stiffness * delta + damping * delta_dot


def hunt_crossley_force(delta, delta_dot, stiffness, exponent, alpha):
    """Hunt-Crossley force ``N = k delta^n (1 + 3/2 alpha delta_dot)``.

    ``alpha`` (s/m) sets the dissipation; ``alpha = 0`` is a purely elastic power
    law (Hertz for ``n = 3/2``). Hunt & Crossley, J. Appl. Mech. 42 (1975) 440.
    Signed like :func:`linear_force` (``delta^n`` continued as
    ``sign(delta)|delta|^n``).
    """
    return stiffness * np.sign(delta) * np.abs(delta) ** exponent * (1.0 + 1.5 * alpha * delta_dot)


def effective_modulus(youngs_modulus, poisson_ratio):
    """Plane-strain modulus ``E* = E/(1 - nu^2)`` of an elastic body on a rigid plane."""
    return youngs_modulus / (1.0 - poisson_ratio**2)


def hertz_stiffness(youngs_modulus, poisson_ratio, radius):
    """Hertz sphere-on-plane stiffness ``k = 4/3 E* sqrt(R)`` in ``N = k delta^{3/2}``."""
    return 4.0 / 3.0 * effective_modulus(youngs_modulus, poisson_ratio) * np.sqrt(radius)


def hertz_max_compression(mass, speed, stiffness):
    """Largest compression of an elastic Hertz impact, ``(5 m v^2/(4 k))^{2/5}``.

    From energy balance ``m v^2/2 = int_0^dm k d^{3/2} dd = 2 k dm^{5/2}/5``.
    """
    return (1.25 * mass * speed**2 / stiffness) ** 0.4


def hertz_duration(mass, speed, stiffness):
    """Classical Hertz contact duration ``HERTZ_DURATION_FACTOR * delta_max / v``."""
    return HERTZ_DURATION_FACTOR * hertz_max_compression(mass, speed, stiffness) / speed


def power_law_time_scale(mass, speed, stiffness, exponent):
    """``delta_max/v`` of an elastic ``N = k delta^n`` impact, with
    ``delta_max = ((n+1) m v^2/(2k))^{1/(n+1)}``: the order of the contact duration."""
    return ((exponent + 1.0) * mass * speed**2 / (2.0 * stiffness)) ** (
        1.0 / (exponent + 1.0)
    ) / speed


def integrate_contact(
    force,
    mass,
    radius,
    inertia,
    mu,
    vx,
    vy,
    omega,
    *,
    time_scale,
    rtol=1e-10,
    atol=None,
    samples=400,
    exponent=1.0,
):
    """Integrate one compliant impact in time (eq. 2.4) with exact stick-slip switching.

    Parameters
    ----------
    force : callable
        ``force(delta, delta_dot) -> N`` (scalars), smooth and signed: the
        contact force is ``max(N, 0)`` and the contact ends where ``N`` falls to 0.
    mass, radius, inertia, mu, vx, vy, omega : float
        One impact; ``vy < 0``.
    time_scale : float
        Order of magnitude of the contact duration (s), for scaling.
    exponent : float
        Power ``n`` with which the force vanishes at separation (``N ~ delta^n``).
        The separation event watches ``sign(N) |N|^(1/n)``, which crosses zero
        linearly, so the root finder locates it even for ``n >= 2.5``.
    rtol, atol : float
        Tolerances of the adaptive integrator (DOP853); ``atol`` defaults to
        ``rtol`` times the natural scales.
    samples : int
        Number of evenly spaced output times (the dense output of the
        integrator), to which the event times are added.

    Returns
    -------
    dict
        ``t`` and the states ``y = (delta, vx, vy, omega, tau, f, work_n)`` at the
        output times, ``stuck`` (bool per sample),
        the event times ``t0`` (end of compression), ``t_star`` (stick; ``nan``
        if never) and ``t1`` (separation, ``N = 0``), and ``tau0`` and
        ``work_n0``, the impulse and normal work at ``t0``.
    """
    from scipy.integrate import solve_ivp

    speed = abs(vy)
    scale_t = time_scale
    vscale = abs(vx) + speed + abs(radius * omega)
    if atol is None:
        atol = rtol * np.array([speed * scale_t, vscale, vscale, vscale / radius,
                                mass * vscale, mass * vscale, mass * vscale**2])  # fmt: skip

    def rhs(_t, y, ratio):
        delta, vx_, vy_, om, tau, f, wn = y
        n = max(force(delta, -vy_), 0.0)
        friction = ratio * n
        return [-vy_, friction / mass, n / mass, friction * radius / inertia, n, friction, n * vy_]

    def slip_zero(_t, y, ratio):
        return y[1] + radius * y[3]

    slip_zero.terminal = True

    def compression_end(_t, y, ratio):
        return y[2]

    compression_end.direction = 1

    def separation(_t, y, ratio):
        n = force(y[0], -y[2])
        return math.copysign(abs(n) ** (1.0 / exponent), n)

    separation.terminal = True
    separation.direction = -1

    y = np.array([0.0, vx, vy, omega, 0.0, 0.0, 0.0])
    t = 0.0
    stuck = vx + radius * omega == 0
    segments = []  # (start, end, dense solution, stuck)
    t0 = t_star = math.nan
    tau0 = work_n0 = math.nan
    horizon = 1e3 * scale_t
    while True:
        ratio = 0.0 if stuck else -mu * math.copysign(1.0, y[1] + radius * y[3])
        events = [compression_end, separation] + ([] if stuck else [slip_zero])
        sol = solve_ivp(rhs, (t, t + horizon), y, method="DOP853", args=(ratio,), events=events,
                        rtol=rtol, atol=atol, dense_output=True)  # fmt: skip
        if sol.status == -1:
            raise RuntimeError(f"contact integration failed: {sol.message}")
        if sol.t_events[0].size and math.isnan(t0):
            t0, y0 = sol.t_events[0][0], sol.y_events[0][0]
            tau0, work_n0 = y0[4], y0[6]
        if sol.t[-1] > t:  # an event exactly at the start leaves nothing to keep
            segments.append((t, sol.t[-1], sol.sol, stuck))
        t, y = sol.t[-1], sol.y[:, -1].copy()
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
    return {
        "t": times,
        "y": out,
        "stuck": flags,
        "t0": t0,
        "t_star": t_star,
        "t1": t,
        "tau0": tau0,
        "work_n0": work_n0,
    }
