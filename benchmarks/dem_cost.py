"""The DEM contact force's cost per contact per step inside a user's ``numba.njit`` loop,
against a linear spring-dashpot with a Coulomb-capped tangential spring written by hand in
the same loop (the cheapest force a DEM code uses), both measured in this run.

The loop is what a DEM code's contact stage does for a sphere on a wall: for each of
``CONTACTS`` spheres striking with its own spin, velocity-Verlet steps until the contact
opens, one call of the force per step. Both loops are the same but for the force; the
ratio of their times per contact-step is the force's cost in units of the simplest one.

Run ``python -m benchmarks.dem_cost`` (``make bench`` prints it too).
"""

from __future__ import annotations

import dataclasses
import math
import time

import numpy as np

from spinimpact import Body, dem

CONTACTS = 1000
STEPS = 200  #: steps per undamped Hertz contact duration


def _loops():
    import numba

    from spinimpact.dem import contact_force

    @numba.njit(cache=False)
    def ours(params, states, mass, radius, inertia, vy0, omegas, dt):
        steps = 0
        out = 0.0
        for i in range(omegas.size):
            state = states[i]
            state[:] = 0.0
            vx, vy, om, y = 0.0, vy0, omegas[i], radius
            fn, ft = 0.0, 0.0
            for _ in range(100000):
                vx += 0.5 * dt * ft / mass
                vy += 0.5 * dt * fn / mass
                om += 0.5 * dt * radius * ft / inertia
                y += dt * vy
                overlap = radius - y
                u = vx + radius * om
                fn, ft, _f2 = contact_force(state, params, overlap, -vy, u * dt, 0.0, u, 0.0)
                vx += 0.5 * dt * ft / mass
                vy += 0.5 * dt * fn / mass
                om += 0.5 * dt * radius * ft / inertia
                steps += 1
                if overlap <= 0.0:
                    break
            out += vx + radius * om
        return steps, out

    @numba.njit(cache=False)
    def linear(k, c, kt, mu, mass, radius, inertia, vy0, omegas, dt):
        steps = 0
        out = 0.0
        for i in range(omegas.size):
            vx, vy, om, y = 0.0, vy0, omegas[i], radius
            fn, ft, spring = 0.0, 0.0, 0.0
            for _ in range(100000):
                vx += 0.5 * dt * ft / mass
                vy += 0.5 * dt * fn / mass
                om += 0.5 * dt * radius * ft / inertia
                y += dt * vy
                overlap = radius - y
                u = vx + radius * om
                if overlap > 0.0:
                    fn = max(k * overlap - c * vy, 0.0)
                    spring += kt * u * dt
                    cap = mu * fn
                    if abs(spring) > cap:
                        spring = math.copysign(cap, spring)
                    ft = -spring
                else:
                    fn, ft, spring = 0.0, 0.0, 0.0
                vx += 0.5 * dt * ft / mass
                vy += 0.5 * dt * fn / mass
                om += 0.5 * dt * radius * ft / inertia
                steps += 1
                if overlap <= 0.0:
                    break
            out += vx + radius * om
        return steps, out

    return ours, linear


def _best(fn, repeat=5):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t)
    return min(times), result


def rows():
    """``(label, ns per contact-step, ratio to the linear spring-dashpot, steps)``."""
    ours, linear = _loops()
    base = dem.ContactForce.sphere_on_wall(youngs_modulus=7.0e10, poisson_ratio=0.33,
                                           radius=0.1, density=2700.0, mu=0.4,
                                           restitution=0.5)  # fmt: skip
    ball = Body.solid_sphere(mass=base.mass, radius=0.1)
    m, r = float(ball.mass), 0.1
    inertia = 0.4 * m * r * r
    vn = 0.2
    dt = base.time_scale(vn) / STEPS
    rng = np.random.default_rng(1)
    omegas = rng.uniform(0.0, 20.0, CONTACTS)
    # the linear spring with the Hertz contact's duration and restitution 0.5
    k = m * (math.pi / base.time_scale(vn)) ** 2
    c = -2.0 * math.log(0.5) / math.hypot(math.log(0.5), math.pi) * math.sqrt(k * m)
    linear(k, c, 0.8 * k, 0.4, m, r, inertia, -vn, omegas[:2], dt)  # compile
    t_lin, (n_lin, _) = _best(lambda: linear(k, c, 0.8 * k, 0.4, m, r, inertia, -vn, omegas, dt))
    per_lin = t_lin / n_lin
    out = [("linear spring-dashpot, by hand", per_lin * 1e9, 1.0, n_lin)]
    for label, options in (
        ("incremental (Hertz-Mindlin no-slip)", {"model": "incremental"}),
        ("scaled, tangential damper", {"model": "scaled", "tangential_damping": 0.25}),
        ("history spring, 128 cells", {"model": "history"}),
        ("micro-slip, 128 cells", {"model": "micro-slip"}),
        ("micro-slip, 32 cells", {"model": "micro-slip", "cells": 32}),
    ):
        force = dataclasses.replace(base, **options)
        params = force.parameters()
        states = np.zeros((CONTACTS, force.new_state().size))
        ours(params, states[:2], m, r, inertia, -vn, omegas[:2], dt)  # compile
        t, (n, _) = _best(lambda p=params, s=states: ours(p, s, m, r, inertia, -vn, omegas, dt))
        out.append((label, t / n * 1e9, (t / n) / per_lin, n))
    return out


def report(print_=print):
    """Print the table."""
    print_(f"DEM force inside a user's numba.njit loop: {CONTACTS} sphere-wall contacts, "
           f"{STEPS} steps a contact duration; ns per contact-step and the ratio to a "
           "linear spring-dashpot written by hand in the same loop (this run)")  # fmt: skip
    for label, ns, ratio, n in rows():
        print_(f"  {label:38s} {ns:8.1f} ns  {ratio:6.1f} x  ({n} contact-steps)")


if __name__ == "__main__":
    report()
