"""The result of :func:`spinimpact.core.tangential.integrate_tangential`: the run sampled
in time from the dense solutions of its stick and slip segments."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .spring_history import history_energy

__all__ = ["TangentialRun", "sampled"]


class TangentialRun(NamedTuple):
    """One impact with tangential compliance sampled in time
    (:func:`integrate_tangential`); the arrays share one length and every
    stick/slip switch is a sample."""

    t: np.ndarray  #: s
    compression: np.ndarray  #: delta, m
    vx: np.ndarray  #: m/s
    vy: np.ndarray  #: m/s
    omega: np.ndarray  #: rad/s
    tau: np.ndarray  #: normal impulse, N s
    tangential_impulse: np.ndarray  #: N s
    normal_force: np.ndarray  #: N
    tangential_force: np.ndarray  #: F, N
    spring_displacement: np.ndarray  #: xi, m (the tangential spring's displacement)
    slip: np.ndarray  #: interface slip velocity w, m/s (0 while sticking)
    contact_velocity: np.ndarray  #: u = vx + R omega, m/s
    stuck: np.ndarray  #: bool
    energy: np.ndarray  #: T + U_n + F^2/(2 k_t) (history: the field's), J; never increases
    switches: np.ndarray  #: times of the stick/slip switches, s
    t0: float  #: end of compression, s
    t1: float  #: separation, s
    tau0: float  #: normal impulse at t0, N s
    compression_work: float  #: work of N up to t0, J
    newton_restitution: float
    poisson_restitution: float
    energetic_restitution: float


def sampled(segments, t_end, y_end, t0, tau0, work0, switches, samples, mass, radius,
             inertia, mu, vy, normal, kt, k, n, rates, history=None) -> TangentialRun:  # fmt: skip
    """Sample the dense solutions of the segments, the switches and ``t0`` included."""
    from .restitution import restitution_by_definition

    marks = [x for x in (t0, *switches) if x == x]
    times = np.union1d(np.linspace(0.0, t_end, samples), marks)
    out = np.empty((9, times.size))
    stuck = np.empty(times.size, dtype=bool)
    sig = np.zeros(times.size)
    for i, (start, end, dense, stick, sigma) in enumerate(segments):
        last = i == len(segments) - 1
        sel = (times >= start) & ((times < end) | last)
        out[:, sel] = dense(times[sel])
        stuck[sel] = stick
        sig[sel] = sigma
    out[:, -1] = y_end
    delta, vxs, vys, oms, tau, f, _wn, force, xi = out
    big_n = np.array([max(normal(d, -v), 0.0) for d, v in zip(delta, vys, strict=True)])
    force = np.where(stuck, force, sig * mu * big_n)
    u = vxs + radius * oms
    w = np.zeros(times.size)
    for j in np.flatnonzero(~stuck):
        _, n_rate, unload = rates(out[:, j], sig[j])
        w[j] = u[j] + sig[j] * mu * (n_rate - unload)
    stiff = np.array([kt(d) for d in delta])
    with np.errstate(divide="ignore", invalid="ignore"):
        spring_energy = np.where(stiff > 0, force**2 / (2.0 * stiff), 0.0)
    if history is not None:  # spring="history": its loading history
        spring_energy = history_energy(history, t0, times, delta, force, stiff)
    energy = (0.5 * mass * (vxs**2 + vys**2) + 0.5 * inertia * oms**2
              + k * np.maximum(delta, 0.0) ** (n + 1.0) / (n + 1.0) + spring_energy)  # fmt: skip
    tau1 = float(y_end[4])
    kappas = restitution_by_definition(vy, float(y_end[2]), tau0, tau1, work0,
                                       float(y_end[6]) - work0)  # fmt: skip
    return TangentialRun(
        t=times, compression=delta, vx=vxs, vy=vys, omega=oms, tau=tau, tangential_impulse=f,
        normal_force=big_n, tangential_force=force, spring_displacement=xi, slip=w,
        contact_velocity=u, stuck=stuck, energy=energy, switches=np.asarray(switches),
        t0=float(t0), t1=float(t_end), tau0=float(tau0), compression_work=float(work0),
        newton_restitution=float(kappas.newton), poisson_restitution=float(kappas.poisson),
        energetic_restitution=float(kappas.energetic),
    )  # fmt: skip
