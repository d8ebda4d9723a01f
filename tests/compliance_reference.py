"""An independent integration, in time, of Stronge's lumped tangential compliance.

Not the closed form of ``spinimpact.core.stronge``: real time, real stiffnesses and masses,
the normal spring's compression ``delta`` as a state, SciPy's ``solve_ivp`` (DOP853, tight
tolerances, short steps) with events for every change: end of compression, stick -> slip
(``|k_t xi|`` reaching ``mu N``), slip -> stick (the contact point's velocity on the surface
reaching zero), separation (``N = 0``).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

RTOL, ATOL = 1e-12, 1e-14


def integrate(slip, vy, zeta, mu, kappa, ratio, *, mass=0.3, k_n=2.0e5):
    """Slip after the impact, the number of stick/slip changes and the largest rise of
    ``E_t = m c_t^2/(2 zeta) + k_t xi^2/2`` found (it must not rise)."""
    w_nn, w_tt = 1.0 / mass, zeta / mass
    k_t = ratio * k_n
    v0 = -vy  # approach speed
    # state: [delta, delta_dot, c_t, xi]
    y = np.array([0.0, v0, slip, 0.0])
    t = 0.0
    loading = True
    delta_max = 0.0
    k_u = k_n / kappa**2 if kappa > 0 else np.inf

    def normal_force(d, loading_, dmax):
        if loading_:
            return k_n * d
        return k_u * (d - dmax * (1.0 - kappa**2))

    def normal_rate(dd, loading_):
        return (k_n if loading_ else k_u) * dd

    if slip == 0:
        return 0.0, 0, 0.0
    stick = ratio * abs(slip / vy) <= mu
    sigma = np.sign(slip)
    changes = 0
    energy_rise = 0.0
    for _ in range(100000):
        ld, dm, sg = loading, delta_max, sigma
        if not ld and kappa == 0:
            break

        def rhs(_t, s, ld=ld, dm=dm, sg=sg, stick_=stick):
            d, dd, c, xi = s
            n = normal_force(d, ld, dm)
            if stick_:
                f = -k_t * xi
                dxi = c
            else:
                f = -mu * n * sg
                dxi = mu * normal_rate(dd, ld) * sg / k_t
            return [dd, -w_nn * n, w_tt * f, dxi]

        events = []

        def compression_end(_t, s):
            return s[1]

        compression_end.terminal, compression_end.direction = True, -1

        def separation(_t, s, ld=ld, dm=dm):
            return normal_force(s[0], ld, dm)

        separation.terminal, separation.direction = True, -1

        def stick_limit(_t, s, ld=ld, dm=dm):  # > 0 while the spring holds
            return mu * normal_force(s[0], ld, dm) - abs(k_t * s[3])

        stick_limit.terminal, stick_limit.direction = True, -1

        def slip_stop(_t, s, ld=ld, sg=sg):  # sigma times the contact point's velocity
            return sg * (s[2] - mu * normal_rate(s[1], ld) * sg / k_t)

        slip_stop.terminal, slip_stop.direction = True, -1

        events = [compression_end] if ld else [separation]
        events.append(stick_limit if stick else slip_stop)
        period = 2 * np.pi / np.sqrt(k_n * w_nn)
        # steps of at most period/200: an event is found only where its function changes
        # sign between steps, and a short slip phase can hide inside one long step
        sol = solve_ivp(rhs, (t, t + 2 * period), y, method="DOP853", rtol=RTOL, atol=ATOL,
                        events=events, max_step=period / 200)  # fmt: skip
        t, y = sol.t[-1], sol.y[:, -1].copy()
        e_t = mass * sol.y[2] ** 2 / (2 * zeta) + (
            k_t * sol.y[3] ** 2 / 2 if stick else mu**2 * 0.0
        )
        if stick:
            energy_rise = max(energy_rise, float(np.max(e_t - e_t[0])))
        which = [i for i, ev in enumerate(sol.t_events) if len(ev)]
        if not which:
            raise RuntimeError("no event within two normal periods")
        ev = which[0]
        if ld and ev == 0:  # end of compression
            loading, delta_max = False, y[0]
            y[1] = 0.0
            continue
        if not ld and ev == 0:  # separation
            break
        # a stick/slip change
        changes += 1
        if stick:
            sigma = np.sign(y[3])
            y[3] = sigma * mu * normal_force(y[0], ld, dm) / k_t
            stick = False
        else:
            stick = True
    return y[2], changes, energy_rise
