"""Eq. (2.7) integrated in the normal impulse with exact fractions: a route to the paper's
quantities that uses no closed form of the paper and no code of the package.

Between breakpoints the force ratio F/N is constant (Coulomb's ``-mu sign(u)`` while the
contact point slips, 0 once it has stopped: a rolling rigid body needs no friction), so
every velocity is linear in ``tau`` and one step per piece is exact. The pieces are split
where ``u`` reaches 0, at the end of compression ``tau0`` and at a few more points; the
works are the exact trapezoids of ``v`` and ``(F/N) u`` over each piece, and the minimum
kinetic energy is found where ``dE/dtau = v + (F/N) u`` changes sign.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction as Fr


def _sign(x: Fr) -> int:
    return (x > 0) - (x < 0)


@dataclass(frozen=True)
class Process:
    """What the exact integration gives (SI units, fractions)."""

    tau0: Fr  # normal impulse at the end of compression
    tau1: Fr  # total normal impulse
    tau_star: Fr | None  # impulse at which the slip stops, None if it never does
    vx: Fr  # rebound velocity of the centre along the surface
    vy: Fr  # rebound normal velocity
    omega: Fr  # rebound spin
    f1: Fr  # tangential impulse
    work_compression_normal: Fr
    work_restitution_normal: Fr
    work_compression_tangential: Fr
    work_restitution_tangential: Fr
    energy_before: Fr
    energy_after: Fr
    min_energy: Fr
    tau_min_energy: Fr
    states: tuple  # (tau, vx, vy, omega) at every breakpoint, from 0 to tau1


def integrate(m, radius, rho2, vx, vy, rim, mu, kappa, pieces: int = 8) -> Process:
    """Integrate (2.7) exactly; ``rim = R omega`` before the impact, ``rho2 = rho**2``.

    All arguments are converted to fractions: pass ints, fractions or decimal strings.
    """
    m, radius, rho2 = Fr(m), Fr(radius), Fr(rho2)
    uc, v, mu, kappa = Fr(vx), Fr(vy), Fr(mu), Fr(kappa)
    w = Fr(rim) / radius
    inertia = m * rho2
    zeta = 1 + radius**2 / rho2
    tau0 = -m * v
    tau1 = (1 + kappa) * tau0
    cuts = {tau0, tau1} | {tau1 * Fr(k, pieces) for k in range(pieces + 1)}

    def energy(uc, v, w):
        return m * (uc * uc + v * v) / 2 + inertia * w * w / 2

    e_before = energy(uc, v, w)
    e_min, tau_min = e_before, Fr(0)
    works = {"cn": Fr(0), "rn": Fr(0), "ct": Fr(0), "rt": Fr(0)}
    tau, f1, tau_star = Fr(0), Fr(0), None
    states = [(tau, uc, v, w)]
    while tau < tau1:
        end = min(c for c in cuts if c > tau)
        u = uc + radius * w
        ratio = -mu * _sign(u)  # F/N
        du = zeta * ratio / m  # du/dtau, from the first and third of (2.7)
        if u != 0 and du != 0 and tau < tau - u / du <= end:
            end = tau_star = tau - u / du
        h = end - tau
        v2, uc2, w2 = v + h / m, uc + ratio * h / m, w + radius * ratio * h / inertia
        u2 = uc2 + radius * w2
        phase = "c" if end <= tau0 else "r"
        works[phase + "n"] += h * (v + v2) / 2
        works[phase + "t"] += ratio * h * (u + u2) / 2
        f1 += ratio * h
        slope0, slope1 = v + ratio * u, v2 + ratio * u2  # dE/dtau at both ends
        if slope0 < 0 <= slope1:
            s = h * -slope0 / (slope1 - slope0)
            e = energy(uc + ratio * s / m, v + s / m, w + radius * ratio * s / inertia)
            if e < e_min:
                e_min, tau_min = e, tau + s
        tau, uc, v, w = end, uc2, v2, w2
        states.append((tau, uc, v, w))
        if energy(uc, v, w) < e_min:
            e_min, tau_min = energy(uc, v, w), tau
    if tau_star is None and Fr(vx) + Fr(rim) == 0:
        tau_star = Fr(0)
    return Process(
        tau0,
        tau1,
        tau_star,
        uc,
        v,
        w,
        f1,
        works["cn"],
        works["rn"],
        works["ct"],
        works["rt"],
        e_before,
        energy(uc, v, w),
        e_min,
        tau_min,
        tuple(states),
    )
