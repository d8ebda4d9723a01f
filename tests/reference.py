"""Independent numerical route: direct integration of eqs. (2.7) in tau.

Nothing here uses a closed form of the package or of the paper beyond the
equations of motion themselves: the state (vx, vy, omega) is advanced in the
normal impulse ``tau`` with ``m dvx = (F/N) dtau``, ``m dvy = dtau``,
``J domega = R (F/N) dtau`` and Coulomb's law (``F/N = -mu sign(u)`` while the
contact point slips, ``F = 0`` once it has stopped). The compression ends at the
event ``v = 0`` (impulse ``tau0``) and, by Poisson's definition of restitution
(eq. 1.2), the impact ends at ``tau = (1 + kappa) tau0``.

Two integrators:

* :func:`integrate` - vectorized over many impacts, fixed steps in ``tau`` with
  both events (``u = 0`` and ``v = 0``) located inside the step. On each
  sub-step the right-hand side is constant, so the velocities are advanced
  exactly and the works (trapezoid rule on linear integrands) are exact; the
  result differs from the closed forms only by rounding.
* :func:`integrate_ivp` - one impact at a time with SciPy's adaptive
  Runge-Kutta ``solve_ivp`` and its event location; a generic ODE solver, so it
  agrees with the closed forms to its tolerance.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp


@dataclass
class Result:
    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    f1: np.ndarray  # total friction impulse
    tau0: np.ndarray
    tau1: np.ndarray
    tau_stick: np.ndarray  # impulse at which the slip stopped (inf if it never did)
    wcn: np.ndarray
    wct: np.ndarray
    wrn: np.ndarray
    wrt: np.ndarray
    e_min: np.ndarray
    tau_min: np.ndarray


def _energy(m, J, vx, vy, om):
    return 0.5 * m * (vx**2 + vy**2) + 0.5 * J * om**2


def integrate(vx, vy, omega, mass, radius, gyration, mu, kappa, steps=16):
    """Integrate many impacts at once; all inputs broadcast to one shape."""
    vx, vy, om, m, R, rho, mu, kappa = (
        np.atleast_1d(np.array(a, dtype=float))
        for a in np.broadcast_arrays(vx, vy, omega, mass, radius, gyration, mu, kappa)
    )
    J = m * rho**2
    shape = vx.shape
    tau = np.zeros(shape)
    h = -m * vy / steps  # nominal step: a fraction of the initial momentum
    end = np.full(shape, np.inf)  # known once compression ends
    stuck = (vx + R * om) == 0
    tau_stick = np.where(stuck, 0.0, np.inf)
    tau0 = np.full(shape, np.nan)
    f = np.zeros(shape)
    w = {k: np.zeros(shape) for k in ("cn", "ct", "rn", "rt")}
    e = _energy(m, J, vx, vy, om)
    e_min, tau_min = e.copy(), np.zeros(shape)

    def substep(length):
        nonlocal vx, vy, om, tau, f, e
        ratio = np.where(stuck, 0.0, -mu * np.sign(vx + R * om))
        u0, v0 = vx + R * om, vy
        vx = vx + ratio * length / m
        om = om + R * ratio * length / J
        vy = vy + length / m
        u1 = vx + R * om
        wn = length * (v0 + vy) / 2
        wt = length * ratio * (u0 + u1) / 2
        compression = v0 < 0
        w["cn"] += np.where(compression, wn, 0)
        w["ct"] += np.where(compression, wt, 0)
        w["rn"] += np.where(compression, 0, wn)
        w["rt"] += np.where(compression, 0, wt)
        # Energy minimum inside the sub-step: dE/dtau = v + (F/N) u is linear here.
        d0, d1 = v0 + ratio * u0, vy + ratio * u1
        with np.errstate(divide="ignore", invalid="ignore"):
            theta = np.where((d0 < 0) & (d1 > 0), d0 / (d0 - d1), np.nan)
        inside = np.isfinite(theta) & (length > 0)
        s = np.where(inside, theta * length, 0.0)
        e_in = e + s * (v0 + (v0 + s / m)) / 2 + ratio * s * (u0 + (u0 + (u1 - u0) * theta)) / 2
        e_end = e + wn + wt
        for cand, where_tau in ((e_in, tau + s), (e_end, tau + length)):
            better = (cand < e_min) & ((cand is e_end) | inside)
            e_min[...] = np.where(better, cand, e_min)
            tau_min[...] = np.where(better, where_tau, tau_min)
        f = f + ratio * length
        tau = tau + length
        e = e_end

    while True:
        active = tau < end
        if not active.any():
            break
        length = np.where(active, np.minimum(h, end - tau), 0.0)
        # Event v = 0 (end of compression): v is linear in tau, so shorten the step
        # to end exactly there.
        cross_v = active & np.isnan(tau0) & (vy + length / m >= 0)
        length = np.where(cross_v, -m * vy, length)
        # Event u = 0 (slip stops) inside the step: u is linear in tau while sliding.
        ratio = np.where(stuck, 0.0, -mu * np.sign(vx + R * om))
        u0 = vx + R * om
        u1 = u0 + ratio * length / m + R * R * ratio * length / J
        cross_u = ~stuck & (np.sign(u1) != np.sign(u0))
        with np.errstate(divide="ignore", invalid="ignore"):
            th_u = np.where(cross_u, u0 / (u0 - u1), 1.0)
        substep(th_u * length)
        stuck = stuck | cross_u
        tau_stick = np.where(cross_u, tau, tau_stick)
        substep((1.0 - th_u) * length)
        vy = np.where(cross_v, 0.0, vy)
        tau0 = np.where(cross_v, tau, tau0)
        end = np.where(cross_v, (1.0 + kappa) * tau, end)
    return Result(
        vx, vy, om, f, tau0, tau, tau_stick, w["cn"], w["ct"], w["rn"], w["rt"], e_min, tau_min
    )


def integrate_ivp(vx, vy, omega, mass, radius, gyration, mu, kappa, rtol=1e-10, atol=1e-12):
    """One impact with ``scipy.integrate.solve_ivp`` (RK45) and event location.

    Returns ``(vx+, vy+, omega+, dissipated energy)``.
    """
    m, R, J = mass, radius, mass * gyration**2
    scale = abs(vx) + abs(vy) + abs(R * omega)

    def rhs(_tau, y, ratio):
        return [ratio / m, 1.0 / m, R * ratio / J]

    def stops(_tau, y, ratio):
        return y[0] + R * y[2]

    stops.terminal = True
    y = np.array([vx, vy, omega], dtype=float)
    tau, tau0 = 0.0, -m * vy  # tau0 re-found below from the event v = 0

    def v_zero(_tau, y, ratio):
        return y[1]

    # Integrate until v = 0 (compression) while watching for the stick event.
    segments = []
    stuck = (vx + R * omega) == 0
    phase_end = None
    while True:
        ratio = 0.0 if stuck else -mu * np.sign(y[0] + R * y[2])
        events = [v_zero] if phase_end is None else []
        if not stuck:
            events.append(stops)
        v_zero.terminal = True
        limit = phase_end if phase_end is not None else tau + 10 * tau0
        sol = solve_ivp(
            rhs, (tau, limit), y, args=(ratio,), events=events, rtol=rtol, atol=atol * scale
        )
        segments.append((sol.t, sol.y, ratio))
        tau, y = sol.t[-1], sol.y[:, -1]
        if sol.status == 1:  # an event stopped it
            ev = [i for i, e in enumerate(sol.t_events) if e.size]
            name = events[ev[0]].__name__
            if name == "v_zero":
                phase_end = (1.0 + kappa) * tau
            else:
                stuck = True
            continue
        if phase_end is not None and tau >= phase_end:
            break
    e0 = _energy(m, J, vx, vy, omega)
    e1 = _energy(m, J, *y)
    return y[0], y[1], y[2], e0 - e1
