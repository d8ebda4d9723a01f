"""Benchmarks of one impact: solve() on plain numbers, the compiled per-contact law, and the
dispatch of small arrays. Ratios measured in one run, never absolute claims.

Run alone with ``.venv/bin/python -m benchmarks.one_impact`` (from the repository root);
``make bench`` prints the same tables after its own. Baselines, each measured in the same
run as what is compared with it:

* one impact: a hand-written Python closed form of the rebound (a function call, a
  branch, a dozen float operations: the Python floor of any scalar API);
* the compiled law: the same Numba loop with the closed form written out by hand inside
  it, and a Numba loop that only copies the same bytes;
* small arrays: the fastest of the paths ``fused.rebound`` can take, at each size.
"""

from __future__ import annotations

import math
import timeit

import numpy as np
from rich.console import Console
from rich.table import Table

from benchmarks.bench import python_rebound  # the paper's rebound in plain Python
from spinimpact import Body, Surface, core, solve, solve_pair, solve_planar, solve_sphere
from spinimpact.core import fused
from spinimpact.core import law as contact_law
from spinimpact.model.planar_body import PlanarBody


def per_call(fn, number: int, repeat: int = 7) -> float:
    """Best time per call, s, of ``repeat`` runs of ``number`` calls."""
    return min(timeit.repeat(fn, number=number, repeat=repeat)) / number


def python_sphere(v, w, m, r, j, z, mu, k):
    """A sphere on the plane y = 0 at rest, in 3D, written out in plain Python (the floor)."""
    cx, cz = v[0] + r * w[2], v[2] - r * w[0]  # c = v + w x (0, -r, 0), tangential part
    speed = math.sqrt(cx * cx + cz * cz)
    tau1 = -(1 + k) * m * v[1]
    f = min(m * speed / z, mu * tau1)  # |F|: stick or slide
    fx, fz = (-f * cx / speed, -f * cz / speed) if speed > 0 else (0.0, 0.0)
    s = r / j
    return (v[0] + fx / m, v[1] + tau1 / m, v[2] + fz / m, w[0] - s * fz, w[1], w[2] + s * fx)


def one_impact_rows() -> list[tuple[str, float, float, str]]:
    """Rows (what, time per call, baseline per call, baseline's name)."""
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    params = (1.0, 0.1, 3.5, 0.3, 0.8)
    rows = []
    floor = per_call(lambda: python_rebound(2.0, -3.0, 10.0, *params), 200_000)
    rows.append(
        (
            "solve(): one impact, every Impact field",
            per_call(lambda: solve(ball, 2.0, -3.0, 10.0, mu=0.3, kappa=0.8), 20_000),
            floor,
            "Python rebound",
        )
    )
    rows.append(
        (
            "solve() on 0-d NumPy arrays",
            per_call(
                lambda: solve(
                    ball, np.array(2.0), np.array(-3.0), np.float64(10.0), mu=0.3, kappa=0.8
                ),
                20_000,
            ),
            floor,
            "Python rebound",
        )
    )
    rows.append(
        (
            "solve() on a one-element array",
            per_call(lambda: solve(ball, np.array([2.0]), -3.0, 10.0, mu=0.3, kappa=0.8), 500),
            floor,
            "Python rebound",
        )
    )
    rows.append(
        (
            "contact_law.rebound from Python",
            per_call(lambda: contact_law.rebound(2.0, -3.0, 10.0, *params), 200_000),
            floor,
            "Python rebound",
        )
    )
    rows.append(
        (
            "core.rebound (array kernel) on floats",
            per_call(lambda: core.rebound(2.0, -3.0, 10.0, *params), 5_000),
            floor,
            "Python rebound",
        )
    )
    v, w = (2.0, -3.0, 0.5), (5.0, 20.0, -10.0)
    j = ball.inertia
    tilted = Surface(normal=(0.1, 1.0, 0.0), velocity=(1.0, 0, 0))  # built once, as a user would
    sphere_floor = per_call(lambda: python_sphere(v, w, 1.0, 0.1, j, 3.5, 0.3, 0.8), 100_000)
    rows.append(
        (
            "solve_sphere(): one impact",
            per_call(lambda: solve_sphere(ball, v, w, mu=0.3, kappa=0.8), 2_000),
            sphere_floor,
            "Python 3D rebound",
        )
    )
    rows.append(
        (
            "solve_sphere() on a tilted, moving surface",
            per_call(
                lambda: solve_sphere(
                    ball,
                    v,
                    w,
                    mu=0.3,
                    kappa=0.8,
                    surface=tilted,
                ),
                2_000,
            ),
            sphere_floor,
            "Python 3D rebound",
        )
    )
    rows.append(
        (
            "solve_pair(): one impact of two balls",
            per_call(
                lambda: solve_pair(ball, ball, velocity1=v, spin1=w, velocity2=(0.0, 0.0, 0.0),
                                   spin2=(0.0, 0.0, 0.0), normal=(0.0, 1.0, 0.0), mu=0.3,
                                   kappa=0.8),
                2_000,
            ),
            sphere_floor,
            "Python 3D rebound",
        )
    )  # fmt: skip
    rod = PlanarBody.rod(mass=1.0, length=0.5, angle=0.7)
    rows.append(
        (
            "solve_planar(): one impact of a rod",
            per_call(lambda: solve_planar(rod, 1.0, -2.0, 3.0, mu=0.3, kappa=0.8), 500),
            floor,
            "Python rebound",
        )
    )
    return rows


def compiled_rows(n: int = 1_000_000) -> list[tuple[str, float, float, float]]:
    """Rows (what, ns per contact, ratio to the hand-inlined loop, ratio to the copy loop)."""
    import numba

    law = contact_law

    @numba.njit
    def with_law(vx, vy, om, m, r, z, mu, k, out):
        for i in range(vx.size):
            a, b, c, _ = law.rebound(vx[i], vy[i], om[i], m, r, z, mu, k)
            out[i, 0] = a
            out[i, 1] = b
            out[i, 2] = c

    @numba.njit
    def with_energy(vx, vy, om, m, r, z, mu, k, out):
        for i in range(vx.size):
            out[i, 0] = law.dissipated_energy(vx[i], vy[i], om[i], m, r, z, mu, k)
            out[i, 1] = law.regime(vx[i], vy[i], om[i], r, z, mu, k)
            out[i, 2] = law.impulses(vx[i], vy[i], om[i], m, r, z, mu, k)[1]

    @numba.njit
    def by_hand(vx, vy, om, m, r, z, mu, k, out):
        for i in range(vx.size):
            u = vx[i] + r * om[i]
            v = vy[i]
            if abs(u) <= (1.0 + k) * z * mu * abs(v):
                f1 = -m * u / z
            else:
                f1 = -mu * np.sign(u) * ((1.0 + k) * (-m * v))
            out[i, 0] = vx[i] + f1 / m
            out[i, 1] = -k * v
            out[i, 2] = om[i] + (z - 1.0) * f1 / (m * r)

    @numba.njit
    def copy(vx, vy, om, m, r, z, mu, k, out):
        for i in range(vx.size):
            out[i, 0] = vx[i]
            out[i, 1] = vy[i]
            out[i, 2] = om[i]

    @numba.njit
    def sphere(v, w, m, r, j, z, mu, k, out):
        n = (0.0, 1.0, 0.0)
        rest = (0.0, 0.0, 0.0)
        for i in range(v.shape[0]):
            a = law.sphere_rebound(
                (v[i, 0], v[i, 1], v[i, 2]), (w[i, 0], w[i, 1], w[i, 2]), n, rest, m, r, j, z, mu, k
            )
            out[i, 0], out[i, 1], out[i, 2] = a[0], a[1], a[2]

    rng = np.random.default_rng(0)
    vx, vy, om = rng.normal(0, 3, n), -rng.uniform(0.1, 5, n), rng.normal(0, 60, n)
    args = (vx, vy, om, 1.0, 0.1, 3.5, 0.3, 0.8, np.zeros((n, 3)))
    v3 = np.stack([vx, vy, rng.normal(0, 1, n)], -1)
    w3 = rng.normal(0, 60, (n, 3))
    s_args = (v3, w3, 1.0, 0.1, 0.004, 3.5, 0.3, 0.8, args[-1])
    runs = {with_law: args, with_energy: args, by_hand: args, copy: args, sphere: s_args}
    for fn, a in runs.items():
        fn(*a)  # compile, and touch the output
    times = dict.fromkeys(runs, math.inf)
    for _ in range(15):  # interleaved, the best of each: the machine's noise hits all alike
        for fn, a in runs.items():
            times[fn] = min(times[fn], per_call(lambda fn=fn, a=a: fn(*a), 1, 1))
    t_sphere = times[sphere]
    hand, plain = times[by_hand], times[copy]
    return [
        (
            "contact_law.rebound in a user's njit loop",
            times[with_law] / n * 1e9,
            times[with_law] / hand,
            times[with_law] / plain,
        ),
        (
            "dissipated_energy + regime + impulses, njit loop",
            times[with_energy] / n * 1e9,
            times[with_energy] / hand,
            times[with_energy] / plain,
        ),
        (
            "contact_law.sphere_rebound (3D), njit loop",
            t_sphere / n * 1e9,
            t_sphere / hand,
            t_sphere / plain,
        ),
        ("the closed form inlined by hand (baseline)", hand / n * 1e9, 1.0, hand / plain),
        ("copying the same bytes (baseline)", plain / n * 1e9, plain / hand, 1.0),
    ]


def dispatch_rows() -> list[tuple[int, float, float, float, float]]:
    """Rows (size, auto, NumPy path, Numba kernel, solve()) per call, s, for small arrays."""
    rng = np.random.default_rng(1)
    params = (1.0, 0.1, 3.5, 0.3, 0.8)
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    rows = []
    for size in (1, 10, 100, 1_000, 10_000, 100_000):
        inc = (rng.normal(0, 3, size), -rng.uniform(0.1, 5, size), rng.normal(0, 60, size))
        number = max(1, 2_000 // size)  # the thread pool's start costs ~0.1 ms a call

        def path(choice, inc=inc):
            return lambda: fused.rebound(*inc, *params, fused=choice)

        auto, plain = per_call(path(None), number), per_call(path(False), number)
        kernel = math.nan
        if fused.HAVE_NUMBA:
            path(True)()  # compile
            kernel = per_call(path(True), number)
        whole = per_call(lambda inc=inc: solve(ball, *inc, mu=0.3, kappa=0.8), max(1, number // 10))
        rows.append((size, auto, plain, kernel, whole))
    return rows


def report(console: Console) -> None:
    """Print the three tables of this module."""
    table = Table(title="one impact: time per call / a baseline measured in the same run")
    for col, just in (
        ("call", "left"),
        ("per call", "right"),
        ("/ baseline", "right"),
        ("baseline", "left"),
    ):
        table.add_column(col, justify=just)
    for what, t, base, name in one_impact_rows():
        table.add_row(what, f"{t * 1e6:.3g} us", f"{t / base:.3g}", f"{name}, {base * 1e6:.3g} us")
    console.print(table)
    if fused.HAVE_NUMBA:
        table = Table(title="the compiled per-contact law: a million contacts in one njit loop")
        for col in ("loop", "ns per contact", "/ inlined by hand", "/ copy"):
            table.add_column(col, justify="left" if col == "loop" else "right")
        for what, ns, hand, plain in compiled_rows():
            table.add_row(what, f"{ns:.3g}", f"{hand:.3g}", f"{plain:.3g}")
        console.print(table)
    table = Table(
        title="small arrays: fused.rebound's automatic choice against each path, "
        "and solve() on the same arrays"
    )
    for col in (
        "impacts",
        "auto",
        "NumPy path",
        "Numba kernel",
        "auto / fastest",
        "solve() per impact",
    ):
        table.add_column(col, justify="right")
    for size, auto, plain, kernel, whole in dispatch_rows():
        fastest = min(plain, kernel) if not math.isnan(kernel) else plain
        table.add_row(
            f"{size:,}",
            f"{auto * 1e6:.3g} us",
            f"{plain * 1e6:.3g} us",
            f"{kernel * 1e6:.3g} us",
            f"{auto / fastest:.2f}",
            f"{whole / size * 1e6:.3g} us",
        )
    console.print(table)


if __name__ == "__main__":
    report(Console(width=120))
