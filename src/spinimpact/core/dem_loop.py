r"""A small DEM loop around :mod:`spinimpact.core.dem_force`: a sphere on a flat wall, and
two spheres, in plane motion, stepped as the DEM codes step them.

The step is velocity Verlet in the form DEM codes use (LIGGGHTS, Kratos): a half kick
with the forces of the last step, a drift of the positions, the contact forces at the new
positions (the tangential displacement increment ``u_{n+1/2} dt``), and a second half
kick. The dampings and the friction limit need the overlap's rate and the contact point's
velocity at the new step, where the positions are: they are extrapolated from the last two
half steps, ``(3 v_{n+1/2} - v_{n-1/2})/2``. (DEM codes take the half step's value, which
makes a damped impact's rebound converge at first order only.) The contact opens where the
overlap is no longer positive, and the run ends there.

Conventions are the package's (``docs/conventions.md``): ``x`` along the wall, ``y`` up,
spin ``omega`` counter-clockwise; the contact point of a sphere on the wall slips at
``u = v_x + R omega``. For two spheres, ``n`` points from sphere 1's centre to sphere 2's,
``t`` is ``n`` turned by +90 degrees, and the contact slips at
``u = (v_1 - v_2) . t + R_1 omega_1 + R_2 omega_2``.

The functions are plain Python; :mod:`spinimpact.core.dem_law` compiles them with Numba
when it is installed.
"""

from __future__ import annotations

import math

import numpy as np

from .dem_force import contact_force, normal_energy, tangential_energy

__all__ = ["TRACE_COLUMNS", "wall_impact", "pair_impact"]

#: The columns of a trace: time (s), overlap (m), normal force (N), tangential force (N),
#: the contact point's slip (m/s), kinetic energy (J), the springs' energy (J, normal
#: and tangential).
TRACE_COLUMNS = ("time", "overlap", "normal_force", "tangential_force", "slip",
                 "kinetic_energy", "spring_energy")  # fmt: skip


def wall_impact(params, state, mass, radius, inertia, vx, vy, omega, dt, max_steps, trace):
    """A sphere touching a wall (``y = R`` at ``t = 0``) with velocity ``(vx, vy)``
    (``vy < 0``) and spin ``omega``, stepped at ``dt`` until the contact opens.

    Returns ``(vx, vy, omega, steps, duration)`` after the contact; ``steps`` is negative if
    the contact was still closed after ``max_steps``. Row ``i`` of ``trace`` (an array of
    ``(rows, 7)``, :data:`TRACE_COLUMNS`, or of zero rows) records step ``i`` where there
    is room.
    """
    y = radius
    fn, ft = 0.0, 0.0
    touched = False
    rate_before, u_before = -vy, vx + radius * omega
    for step in range(1, max_steps + 1):
        vx += 0.5 * dt * ft / mass
        vy += 0.5 * dt * fn / mass
        omega += 0.5 * dt * radius * ft / inertia
        y += dt * vy
        overlap = radius - y
        u = vx + radius * omega
        # the rates at the new step, extrapolated from the last two half steps (the
        # dampings and the friction limit need them where the positions are)
        rate, slip = 1.5 * -vy - 0.5 * rate_before, 1.5 * u - 0.5 * u_before
        rate_before, u_before = -vy, u
        fn, ft, _f2 = contact_force(state, params, overlap, rate, u * dt, 0.0, slip, 0.0)
        vx += 0.5 * dt * ft / mass
        vy += 0.5 * dt * fn / mass
        omega += 0.5 * dt * radius * ft / inertia
        if step - 1 < trace.shape[0]:
            row = trace[step - 1]
            row[0], row[1], row[2], row[3] = step * dt, overlap, fn, ft
            row[4] = vx + radius * omega
            row[5] = 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * omega * omega
            row[6] = normal_energy(params, overlap) + tangential_energy(state, params, overlap)
        if overlap > 0.0:
            touched = True
        elif touched or step > 1:
            return vx, vy, omega, step, step * dt
    return vx, vy, omega, -max_steps, max_steps * dt


def pair_impact(params, state, bodies, velocities, dt, max_steps, trace):
    """Two spheres in plane motion, touching at ``t = 0``: sphere 1 at the origin, sphere 2
    at ``(0, R_1 + R_2)`` above it.

    ``bodies``: ``(m_1, R_1, I_1, m_2, R_2, I_2)``; ``velocities``: ``(vx_1, vy_1,
    omega_1, vx_2, vy_2, omega_2)``, updated in place to the velocities after the contact.
    Returns ``(steps, duration)`` as :func:`wall_impact`; ``trace`` likewise (its slip
    column is the contact's ``u``).
    """
    m1, r1, i1, m2, r2, i2 = bodies[0], bodies[1], bodies[2], bodies[3], bodies[4], bodies[5]
    v = velocities
    p1x, p1y, p2x, p2y = 0.0, 0.0, 0.0, r1 + r2
    f1x, f1y, tq1, tq2 = 0.0, 0.0, 0.0, 0.0  # force on sphere 1; torques
    touched = False
    rate_before, u_before = v[1] - v[4], -(v[0] - v[3]) + r1 * v[2] + r2 * v[5]
    for step in range(1, max_steps + 1):
        v[0] += 0.5 * dt * f1x / m1
        v[1] += 0.5 * dt * f1y / m1
        v[2] += 0.5 * dt * tq1 / i1
        v[3] -= 0.5 * dt * f1x / m2
        v[4] -= 0.5 * dt * f1y / m2
        v[5] += 0.5 * dt * tq2 / i2
        p1x += dt * v[0]
        p1y += dt * v[1]
        p2x += dt * v[3]
        p2y += dt * v[4]
        dx, dy = p2x - p1x, p2y - p1y
        distance = math.hypot(dx, dy)
        nx, ny = dx / distance, dy / distance
        tx, ty = -ny, nx
        overlap = r1 + r2 - distance
        rate = (v[0] - v[3]) * nx + (v[1] - v[4]) * ny
        u = (v[0] - v[3]) * tx + (v[1] - v[4]) * ty + r1 * v[2] + r2 * v[5]
        rate_new, slip = 1.5 * rate - 0.5 * rate_before, 1.5 * u - 0.5 * u_before
        rate_before, u_before = rate, u
        fn, ft, _f2 = contact_force(state, params, overlap, rate_new, u * dt, 0.0, slip, 0.0)
        f1x, f1y = -fn * nx + ft * tx, -fn * ny + ft * ty
        tq1, tq2 = r1 * ft, r2 * ft
        v[0] += 0.5 * dt * f1x / m1
        v[1] += 0.5 * dt * f1y / m1
        v[2] += 0.5 * dt * tq1 / i1
        v[3] -= 0.5 * dt * f1x / m2
        v[4] -= 0.5 * dt * f1y / m2
        v[5] += 0.5 * dt * tq2 / i2
        if step - 1 < trace.shape[0]:
            row = trace[step - 1]
            row[0], row[1], row[2], row[3] = step * dt, overlap, fn, ft
            row[4] = (v[0] - v[3]) * tx + (v[1] - v[4]) * ty + r1 * v[2] + r2 * v[5]
            row[5] = 0.5 * (m1 * (v[0] ** 2 + v[1] ** 2) + i1 * v[2] ** 2
                            + m2 * (v[3] ** 2 + v[4] ** 2) + i2 * v[5] ** 2)  # fmt: skip
            row[6] = normal_energy(params, overlap) + tangential_energy(state, params, overlap)
        if overlap > 0.0:
            touched = True
        elif touched or step > 1:
            return step, step * dt
    return -max_steps, max_steps * dt


def empty_trace():
    """A trace with no rows (record nothing)."""
    return np.zeros((0, len(TRACE_COLUMNS)))
