"""Any rigid body in 3D: the cost per impact of ``solve_rigid`` against ``solve_sphere``.

Both solve arrays of ``--rows`` impacts (10,000 by default) in one call, after an untimed
call of each (Numba compiles or loads its kernels then); the calls take turns for
``--repeat`` rounds, and the best of each is printed per impact, with the ratio to
``solve_sphere`` measured in the same run. Three sets
of rigid bodies: spheres given as rigid bodies (the slip keeps its direction: closed
form), dice on a corner in random orientations and random bodies (random inertia
tensors and offsets: the slip turns and is integrated). The mean number of integration
steps per impact is printed beside them.

Run from the repository root: ``.venv/bin/python -m benchmarks.rigid [--rows N] [--repeat K]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import spinimpact as si
from spinimpact.core import rigid3d


def best(calls: dict, repeat: int) -> dict:
    """The best time of each call over ``repeat`` rounds, the calls taking turns within a
    round (so that a change in the machine's load falls on all of them alike)."""
    for call in calls.values():
        call()  # untimed: kernels compiled or loaded
    times = {name: [] for name in calls}
    for _ in range(repeat):
        for name, call in calls.items():
            start = time.perf_counter()
            call()
            times[name].append(time.perf_counter() - start)
    return {name: min(t) for name, t in times.items()}


def approaching(rng, offset, n):
    v = rng.normal(size=(n, 3)) * 3.0
    w = rng.normal(size=(n, 3)) * 10.0
    contact = v + np.cross(w, offset)
    v[:, 1] -= np.maximum(contact[:, 1], 0) + 0.3
    return v, w


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=9)
    args = parser.parse_args(argv)
    n = args.rows
    rng = np.random.default_rng(1)
    ball = si.Body.solid_sphere(mass=0.057, radius=0.033)
    moment = ball.mass * ball.gyration**2
    sphere_body = si.RigidBody.principal(ball.mass, [moment] * 3, [0.0, -ball.radius, 0.0])
    v, w = approaching(rng, sphere_body.offset, n)
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    dice = si.RigidBody.cuboid(0.0045, [0.016] * 3, rng.choice([-1.0, 1.0], (n, 3)), q)
    moments = np.sort(rng.uniform(0.2, 1.0, (n, 3)), axis=1)
    moments[:, 2] = np.minimum(moments[:, 2], moments[:, 0] + moments[:, 1])
    q2 = rng.normal(size=(n, 4))
    q2 /= np.linalg.norm(q2, axis=1, keepdims=True)
    random = si.RigidBody.principal(1.0, moments, rng.normal(size=(n, 3)) * 0.5, q2)
    sets = {"spheres as rigid bodies": sphere_body, "dice on a corner": dice,
            "random bodies": random}  # fmt: skip
    motion = {name: approaching(rng, body.offset, n) for name, body in sets.items()}
    calls = {"solve_sphere": lambda: si.solve_sphere(ball, v, w, mu=0.5, kappa=0.7)}
    for name, body in sets.items():
        calls[name] = lambda b=body, m=motion[name]: si.solve_rigid(b, *m, mu=0.5, kappa=0.7)
    times = best(calls, args.repeat)
    base = times["solve_sphere"]
    print(f"{n} impacts per call, best of {args.repeat} (the calls taking turns); "
          f"solve_sphere {1e9 * base / n:.0f} ns per impact")  # fmt: skip
    print(f"{'bodies':28s} {'ns per impact':>14s} {'x solve_sphere':>15s} {'steps':>7s}")
    axes = rigid3d.frame(np.array([0.0, 1.0, 0.0]))
    for name, body in sets.items():
        vb, wb = motion[name]
        local = np.swapaxes(axes, -1, -2) @ body.matrix() @ axes
        contact = (vb + np.cross(wb, body.offset)) @ axes
        steps = rigid3d.contact_impact(local, contact, 0.5, 0.7).steps.mean()
        t = times[name]
        print(f"{name:28s} {1e9 * t / n:14.0f} {t / base:15.1f} {steps:7.1f}")


if __name__ == "__main__":
    main()
