"""Every solver's call on one impact, against a hand-written Python closed form of the same
impact timed in the same run.

Run alone with ``.venv/bin/python -m benchmarks.scalar_calls`` (from the repository root);
``make bench`` prints the same table after its own. For each solver, one impact given as
plain Python numbers (the scalar path) and the same impact with one input an array of one
element (the result then holds arrays of shape ``(1,)``), each the best of many calls,
all timed interleaved so that a busy spell of the machine slows every row alike. The
baseline of a row is the rebound of that impact written out by hand in plain Python (a
function call, a few branches, the floating-point operations of the closed form): the
floor of any scalar API in Python. The solvers return every field of their result (25 to
45 numbers, each a NumPy scalar or array, with validation of every input); the ratio says
how many baselines that costs. Each closed form is checked against the solver's rebound
before it is timed.
"""

from __future__ import annotations

import math
import timeit

import numpy as np
from rich.console import Console
from rich.table import Table

from benchmarks.bench import python_rebound  # the paper's rebound in plain Python
from benchmarks.one_impact import python_sphere  # a sphere on a plane, in plain Python
from spinimpact import (
    Body,
    MindlinDeresiewicz,
    Pendulum,
    PlanarBody,
    Stronge,
    Walton,
    solve,
    solve_pair,
    solve_pendulum,
    solve_planar,
    solve_sphere,
)


def python_pair(v1, w1, v2, w2, n, m1, r1, j1, m2, r2, j2, mu, k):
    """Two spheres (``n`` from ball 2's centre to ball 1's), written out in plain Python:
    the contact's relative velocity, the reduced mass and ``zeta``, then the sphere's law."""
    nx, ny, nz = n
    # c = v1 + w1 x (-r1 n) - v2 - w2 x (r2 n) = v1 - v2 - (r1 w1 + r2 w2) x n
    sx, sy, sz = r1 * w1[0] + r2 * w2[0], r1 * w1[1] + r2 * w2[1], r1 * w1[2] + r2 * w2[2]
    cx = v1[0] - v2[0] - (sy * nz - sz * ny)
    cy = v1[1] - v2[1] - (sz * nx - sx * nz)
    cz = v1[2] - v2[2] - (sx * ny - sy * nx)
    cn = cx * nx + cy * ny + cz * nz
    tx, ty, tz = cx - cn * nx, cy - cn * ny, cz - cn * nz
    speed = math.sqrt(tx * tx + ty * ty + tz * tz)
    w_nn = 1 / m1 + 1 / m2
    m, z = 1 / w_nn, (w_nn + r1 * r1 / j1 + r2 * r2 / j2) / w_nn
    tau1 = -(1 + k) * m * cn
    f = min(m * speed / z, mu * tau1) / speed if speed > 0 else 0.0
    fx, fy, fz = -f * tx, -f * ty, -f * tz  # the friction impulse
    px, py, pz = tau1 * nx + fx, tau1 * ny + fy, tau1 * nz + fz
    ax, ay, az = ny * fz - nz * fy, nz * fx - nx * fz, nx * fy - ny * fx  # n x F
    a1, a2 = r1 / j1, r2 / j2
    return ((v1[0] + px / m1, v1[1] + py / m1, v1[2] + pz / m1),
            (w1[0] - a1 * ax, w1[1] - a1 * ay, w1[2] - a1 * az),
            (v2[0] - px / m2, v2[1] - py / m2, v2[2] - pz / m2),
            (w2[0] - a2 * ax, w2[1] - a2 * ay, w2[2] - a2 * az))  # fmt: skip


def python_planar(vx, vy, omega, m, j, rx, ry, mu, k):
    """A planar body touching at ``(rx, ry)`` from its centre, Poisson's restitution, by
    Keller's method written out in plain Python: slide, then stick or slide back."""
    a, b, d = 1 / m + ry * ry / j, -rx * ry / j, 1 / m + rx * rx / j  # the collision matrix
    u, v = vx - omega * ry, vy + omega * rx  # the contact point's slip and approach
    s = math.copysign(1.0, u) if u else 0.0
    k1, r1 = b - mu * s * a, d - mu * s * b  # du/dtau, dv/dtau while sliding
    ts = -u / k1 if s * k1 < 0 else (0.0 if u == 0 else math.inf)  # the slip stops
    if abs(b) <= mu * a:  # then it sticks
        s2, r2 = -b / a, d - b * b / a
    else:  # or slides back
        s2 = -mu * math.copysign(1.0, b)
        r2 = d + s2 * b
    tc = -v / r1 if r1 > 0 and -v / r1 <= ts else ts - (v + r1 * ts) / r2  # compression ends
    tf = (1 + k) * tc
    f = -mu * s * min(tf, ts) + (s2 * (tf - ts) if tf > ts else 0.0)
    return vx + f / m, vy + tf / m, omega + (rx * tf - ry * f) / j


def python_pendulum(omega, m, j, gx, gy, px, py, mu, k):
    """A pendulum on a pivot striking at ``(px, py)`` from it, Poisson's restitution, in
    plain Python: the contact slides until compression ends with the spin, then it is held
    (``|px| <= mu |py|``) or slides back."""
    jo = j + m * (gx * gx + gy * gy)  # inertia about the pivot
    s = math.copysign(1.0, -omega * py)  # the slip's sign
    tc = -omega * jo / (px + mu * s * py)  # compression ends where the spin does
    tf = (1 + k) * tc
    f = -mu * s * tc + (0.0 if abs(px) <= mu * abs(py) else mu * s * (tf - tc))
    om = omega + (px * tf - py * f) / jo
    if abs(px) <= mu * abs(py):
        om = 0.0  # locked against the surface
    return -om * gy, om * gx, om


def python_walton(vx, vy, omega, m, r, z, mu, k, beta0):
    """Walton's law for one of the paper's bodies, in plain Python."""
    u = vx + r * omega
    change = (1 + k) * z * mu * abs(vy)
    u1 = -beta0 * u if (1 + beta0) * abs(u) <= change else u - math.copysign(change, u)
    f1 = m * (u1 - u) / z
    return vx + f1 / m, -k * vy, omega + (z - 1) * f1 / (m * r)


def python_stronge(contact, vx, vy, omega, m, r, z, mu, k, ratio):
    """Stronge's law (or micro-slip) for one of the paper's bodies: the slip after from the
    law's own per-contact function (``contact``: neither has a closed form while the contact
    sticks; micro-slip's is the table read, compiled), the rest in plain Python."""
    u = vx + r * omega
    u1 = contact(u, vy, z, mu, k, ratio)[0]
    f1 = m * (u1 - u) / z
    return vx + f1 / m, -k * vy, omega + (z - 1) * f1 / (m * r)


def _close(a, b) -> bool:
    a, b = np.ravel(np.asarray(a, float)), np.ravel(np.asarray(b, float))
    return bool(np.allclose(a, b, rtol=1e-12, atol=1e-12 * np.max(np.abs(b))))


def cases() -> list[tuple[str, object, object, object]]:
    """``(name, solver call on plain numbers, the same with a one-element array, closed
    form)``, each closed form checked against the solver's rebound first."""
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    m, r, j, z = ball.mass, ball.radius, ball.inertia, ball.zeta
    one = np.array([2.0])
    v, w = (2.0, -3.0, 0.5), (5.0, 20.0, -10.0)
    v_one = np.array([v])
    zero = (0.0, 0.0, 0.0)
    pair = dict(spin1=w, velocity2=zero, spin2=zero, normal=(0.0, 1.0, 0.0), mu=0.3, kappa=0.8)
    rod = PlanarBody.rod(mass=1.0, length=0.5, angle=0.7)
    p = Pendulum.rod(mass=1.0, length=1.0, angle=1.0)
    walton, stronge = Walton(0.35), Stronge(poisson_ratio=0.23)
    micro = MindlinDeresiewicz(poisson_ratio=0.23)
    from spinimpact.core.mdr_table_kernel import contact_one
    from spinimpact.core.scalar_tangential import stronge_contact

    rows = [
        ("solve()", lambda: solve(ball, 2.0, -3.0, 10.0, mu=0.3, kappa=0.8),
         lambda: solve(ball, one, -3.0, 10.0, mu=0.3, kappa=0.8),
         lambda: python_rebound(2.0, -3.0, 10.0, m, r, z, 0.3, 0.8)),
        ("solve_sphere()", lambda: solve_sphere(ball, v, w, mu=0.3, kappa=0.8),
         lambda: solve_sphere(ball, v_one, w, mu=0.3, kappa=0.8),
         lambda: python_sphere(v, w, m, r, j, z, 0.3, 0.8)),
        ("solve_pair()", lambda: solve_pair(ball, ball, velocity1=v, **pair),
         lambda: solve_pair(ball, ball, velocity1=v_one, **pair),
         lambda: python_pair(v, w, zero, zero, (0.0, 1.0, 0.0), m, r, j, m, r, j, 0.3, 0.8)),
        ("solve_planar(), a rod", lambda: solve_planar(rod, 1.0, -2.0, 3.0, mu=0.3, kappa=0.8),
         lambda: solve_planar(rod, np.array([1.0]), -2.0, 3.0, mu=0.3, kappa=0.8),
         lambda: python_planar(1.0, -2.0, 3.0, rod.mass, rod.inertia, rod.rx, rod.ry, 0.3,
                               0.8)),
        ("solve_pendulum()", lambda: solve_pendulum(p, -2.0, mu=0.3, kappa=0.8),
         lambda: solve_pendulum(p, np.array([-2.0]), mu=0.3, kappa=0.8),
         lambda: python_pendulum(-2.0, p.mass, p.inertia, p.gx, p.gy, p.px, p.py, 0.3, 0.8)),
        ("solve(..., tangential=Walton(0.35))",
         lambda: solve(ball, 2.0, -3.0, 10.0, mu=0.3, kappa=0.8, tangential=walton),
         lambda: solve(ball, one, -3.0, 10.0, mu=0.3, kappa=0.8, tangential=walton),
         lambda: python_walton(2.0, -3.0, 10.0, m, r, z, 0.3, 0.8, 0.35)),
        ("solve(..., tangential=Stronge(poisson_ratio=0.23))",
         lambda: solve(ball, 1.0, -1.0, 0.0, mu=0.5, kappa=0.8, tangential=stronge),
         lambda: solve(ball, np.array([1.0]), -1.0, 0.0, mu=0.5, kappa=0.8, tangential=stronge),
         lambda: python_stronge(stronge_contact, 1.0, -1.0, 0.0, m, r, z, 0.5, 0.8,
                                stronge.stiffness_ratio)),
        ("solve(..., tangential=MindlinDeresiewicz(poisson_ratio=0.23)), from its table",
         lambda: solve(ball, 1.0, -1.0, 0.0, mu=0.5, kappa=0.9, tangential=micro),
         lambda: solve(ball, np.array([1.0]), -1.0, 0.0, mu=0.5, kappa=0.9, tangential=micro),
         lambda: python_stronge(contact_one, 1.0, -1.0, 0.0, m, r, z, 0.5, 0.9,
                                micro.stiffness_ratio)),
    ]  # fmt: skip
    for name, call, call_one, closed in rows:
        res, res_one, ref = call(), call_one(), closed()
        if hasattr(res, "after1"):
            got = [res.after1.velocity, res.after1.spin, res.after2.velocity, res.after2.spin]
            got_one = [res_one.after1.velocity, res_one.after1.spin, res_one.after2.velocity,
                       res_one.after2.spin]  # fmt: skip
        elif hasattr(res.after, "wz"):
            got, got_one = [res.after.velocity, res.after.spin], [
                res_one.after.velocity, res_one.after.spin]  # fmt: skip
        else:
            got = [res.after.vx, res.after.vy, res.after.omega]
            got_one = [res_one.after.vx, res_one.after.vy, res_one.after.omega]
        if not (_close(got, ref) and _close(got_one, ref)):
            raise AssertionError(f"{name}: the closed form {ref} is not the solver's {got}")
    return rows


def rows(rounds: int = 15) -> list[tuple[str, float, float, float]]:
    """``(name, scalar call, one-element call, closed form)``, s per call, each the best of
    ``rounds`` runs of many calls, all interleaved."""
    calls = cases()
    best = {}
    for _ in range(rounds):
        for name, *fns in calls:
            for i, fn in enumerate(fns):
                number = 5_000 if i == 2 else 500
                t = timeit.timeit(fn, number=number) / number
                best[name, i] = min(best.get((name, i), math.inf), t)
    return [(name, best[name, 0], best[name, 1], best[name, 2]) for name, *_ in calls]


def report(console: Console) -> None:
    """Print the table of :func:`rows`."""
    table = Table(title="one impact of each solver: time per call / its closed form in "
                        "plain Python, measured in the same run")  # fmt: skip
    for col in ("call", "plain numbers", "/ closed form", "one-element array", "/ closed form",
                "closed form"):  # fmt: skip
        table.add_column(col, justify="left" if col == "call" else "right")
    for name, t, t_one, base in rows():
        table.add_row(name, f"{t * 1e6:.3g} us", f"{t / base:.3g}", f"{t_one * 1e6:.3g} us",
                      f"{t_one / base:.3g}", f"{base * 1e6:.3g} us")  # fmt: skip
    console.print(table)


if __name__ == "__main__":
    report(Console(width=120))
