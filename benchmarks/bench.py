"""Benchmarks of spinimpact: ratios measured in one run, never absolute claims.

Run with `make bench` (or `.venv/bin/python -m benchmarks.bench [--n N]` from the
repository root, so that ``tests.reference`` imports without editing ``sys.path``).
Every figure is a ratio against a baseline measured in the same run on the
same machine: the memory-copy bound for the fused kernel, and the fused
kernel's time per impact for everything else; at the end, ``solve()`` with every field
against copies of its bytes and ``spinimpact batch`` against Arrow's reading and writing
(:mod:`benchmarks.limits`), and every solver's call on one impact against the closed form
of that impact in plain Python (:mod:`benchmarks.scalar_calls`).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import sys
import time

import numpy as np
from rich.console import Console
from rich.table import Table

from spinimpact import Body, solve
from spinimpact.core import fused, rebound


def best(fn, repeat: int = 7) -> float:
    """Best wall time of ``repeat`` runs (the least disturbed by the machine)."""
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times)


def python_rebound(vx, vy, omega, m, r, z, mu, k):
    """The closed form for one impact in plain Python (the scalar-loop baseline)."""
    u = vx + r * omega
    if abs(u) <= (1 + k) * z * mu * abs(vy):
        f1 = -m * u / z
    else:
        f1 = -mu * math.copysign(1.0, u) * (1 + k) * (-m * vy)
    return vx + f1 / m, -k * vy, omega + (z - 1) * f1 / (m * r)


def tangential_rows(n: int = 1_000_000) -> list[tuple[str, float, float]]:
    """The compiled tangential laws (Walton's, Stronge's, micro-slip from its table) in a
    user's ``njit`` loop over ``n`` contacts, against Walton's closed form written out by hand
    in the same kind of loop (micro-slip: against the table's interpolation written out by
    hand, every contact reading its own weights), measured interleaved in this run: rows
    (what, ns per contact, ratio to the loop by hand)."""
    import numba

    from spinimpact.core import law

    @numba.njit
    def walton(vx, vy, om, m, r, z, mu, k, beta0, out):
        for i in range(vx.size):
            a, b, c, _ = law.walton_rebound(vx[i], vy[i], om[i], m, r, z, mu, k, beta0)
            out[i, 0], out[i, 1], out[i, 2] = a, b, c

    @numba.njit
    def stronge(vx, vy, om, m, r, z, mu, k, ratio, out):
        for i in range(vx.size):
            a, b, c, _ = law.stronge_rebound(vx[i], vy[i], om[i], m, r, z, mu, k, ratio)
            out[i, 0], out[i, 1], out[i, 2] = a, b, c

    @numba.njit
    def micro_slip(vx, vy, om, m, r, z, mu, k, ratio, tab, out):
        for i in range(vx.size):
            a, b, c, _ = law.mdr_rebound(vx[i], vy[i], om[i], m, r, z, mu, k[i], ratio, tab)
            out[i, 0], out[i, 1], out[i, 2] = a, b, c

    @numba.njit
    def by_hand(vx, vy, om, m, r, z, mu, k, beta0, out):
        for i in range(vx.size):
            u = vx[i] + r * om[i]
            v = vy[i]
            change = (1.0 + k) * z * mu * abs(v)
            if (1.0 + beta0) * abs(u) <= change:
                u1 = -beta0 * u
            else:
                u1 = u - np.sign(u) * change
            f1 = m * (u1 - u) / z
            out[i, 0] = vx[i] + f1 / m
            out[i, 1] = -k * v
            out[i, 2] = om[i] + (z - 1.0) * f1 / (m * r)

    @numba.njit
    def _lagrange(x, start, step, size, w):
        s = (x - start) / step
        first = min(max(int(math.floor(s)) - 1, 0), size - 4)
        p = s - first
        w[0] = -(p - 1.0) * (p - 2.0) * (p - 3.0) / 6.0
        w[1] = p * (p - 2.0) * (p - 3.0) / 2.0
        w[2] = -p * (p - 1.0) * (p - 3.0) / 2.0
        w[3] = p * (p - 1.0) * (p - 2.0) / 6.0
        return first

    @numba.njit
    def micro_slip_by_hand(vx, vy, om, m, r, z, mu, kappa, ratio, tab, out):
        axes, _, touch, threshold, share = tab
        wk, wq, wt = np.empty(4), np.empty(4), np.empty(4)
        for i in range(vx.size):  # the table read written out, every contact its own
            u, v, q, k = vx[i] + r * om[i], vy[i], z * ratio, kappa[i]
            change = (1.0 + k) * z * mu * abs(v)
            fk = _lagrange(k, axes[0], axes[1], int(axes[2]), wk)
            fq = _lagrange(q, axes[3], axes[4], int(axes[5]), wq)
            xa, star = 0.0, 0.0
            for a in range(4):
                xa += wk[a] * touch[fk + a]
                for b in range(4):
                    star += wk[a] * wq[b] * threshold[fk + a, fq + b]
            xa /= (1.0 + k) * q
            x = u / change
            phi = 1.0
            if abs(x) < star:
                part, st = abs(x) / xa, 0
                if abs(x) > xa:
                    part = min(max((abs(x) - xa) / (star - xa), 0.0), 1.0)
                    part, st = math.acos(1.0 - 2.0 * part) / math.pi, 1
                ft = _lagrange(part, axes[6], axes[7], int(axes[8]), wt)
                phi = 0.0
                for a in range(4):
                    for b in range(4):
                        for c in range(4):
                            phi += wk[a] * wq[b] * wt[c] * share[st, fk + a, fq + b, ft + c]
            f1 = -m * change * (phi if x > 0.0 else -phi) / z
            out[i, 0] = vx[i] + f1 / m
            out[i, 1] = -k * v
            out[i, 2] = om[i] + (z - 1.0) * f1 / (m * r)

    rng = np.random.default_rng(0)
    vx, vy, om = rng.normal(0, 3, n), -rng.uniform(0.1, 5, n), rng.normal(0, 60, n)
    out = np.zeros((n, 3))
    ball = (1.0, 0.1, 3.5, 0.3, 0.8)  # 1 kg solid sphere, R = 0.1 m, mu = 0.3, kappa = 0.8
    slide = np.abs(vx + 0.1 * om) > 4 * 3.5 * 0.3 * np.abs(vy)  # slides throughout
    s = (vx[slide], vy[slide], om[slide])
    # every contact its own kappa, inside the micro-slip table's range
    table = (1.0, 0.1, 3.5, 0.3, rng.uniform(0.85, 1.0, n))
    runs = {
        "micro-slip": (micro_slip, (vx, vy, om, *table, 0.8701, law.mdr_table(), out)),
        "micro-slip by hand": (
            micro_slip_by_hand,
            (vx, vy, om, *table, 0.8701, law.mdr_table(), out),
        ),
        "walton": (walton, (vx, vy, om, *ball, 0.35, out)),
        "hand": (by_hand, (vx, vy, om, *ball, 0.35, out)),
        "stronge": (stronge, (vx, vy, om, *ball, 0.8701, out)),
        "stronge slides": (stronge, (*s, *ball, 0.8701, out)),
        "hand slides": (by_hand, (*s, *ball, 0.35, out)),
    }
    for fn, a in runs.values():
        fn(*a)  # compile, and touch the output
    checks = {}  # each loop by hand computes what its law computes, before either is timed
    for law_key, hand_key in (("walton", "hand"), ("micro-slip", "micro-slip by hand")):
        for key in (law_key, hand_key):
            runs[key][0](*runs[key][1])
            checks[key] = out.copy()
        scale = np.abs(checks[law_key]).max()
        if not np.allclose(checks[hand_key], checks[law_key], rtol=0, atol=1e-12 * scale):
            raise AssertionError(f"{hand_key}: the loop by hand is not the law's rebound")
    times = dict.fromkeys(runs, math.inf)
    for _ in range(7):  # interleaved, the best of each: the machine's noise hits all alike
        for key, (fn, a) in runs.items():
            times[key] = min(times[key], best(lambda fn=fn, a=a: fn(*a), 1))
    hand, hand_s, m = times["hand"], times["hand slides"], int(slide.sum())
    return [
        ("contact_law.walton_rebound (beta0 = 0.35)", times["walton"] / n * 1e9,
         times["walton"] / hand),
        ("contact_law.stronge_rebound (k_t/k_n = 0.8701)", times["stronge"] / n * 1e9,
         times["stronge"] / hand),
        (f"stronge_rebound, the {m:,} contacts that slide throughout",
         times["stronge slides"] / m * 1e9, times["stronge slides"] / hand_s),
        ("Walton's closed form inlined by hand (baseline)", hand / n * 1e9, 1.0),
        ("contact_law.mdr_rebound (micro-slip table, nu = 0.23, kappa in [0.85, 1])",
         times["micro-slip"] / n * 1e9, times["micro-slip"] / times["micro-slip by hand"]),
        ("the table read inlined by hand (its baseline)", times["micro-slip by hand"] / n * 1e9,
         1.0),
    ]  # fmt: skip


def tangential_report(console: Console, n: int = 1_000_000) -> None:
    """Print :func:`tangential_rows` as a table."""
    table = Table(title=f"compiled tangential laws: {n:,} contacts in one njit loop")
    for col in ("loop", "ns per contact", "/ by hand"):
        table.add_column(col, justify="left" if col == "loop" else "right")
    for what, ns, ratio in tangential_rows(n):
        table.add_row(what, f"{ns:.3g}", f"{ratio:.3g}")
    console.print(table)
    console.print(
        "Stronge's law has no closed form when the contact sticks: its stick phases are "
        "followed in windows of samples (spinimpact.core.scalar_stronge); on the contacts "
        "that slide throughout it is closed form, compared there with the loop by hand on "
        "the same contacts."
    )


def engine_comparison() -> list[tuple[str, float, str, dict]]:
    """Rows (name, time per impact, note, error summary) for the installed engines."""
    from spinimpact import engines

    cases = engines.standard_cases()
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    rows = []
    for label, engine, settings in engines.CONFIGURATIONS:
        if not engines.available(engine):
            print(f"{engine} is not installed: pip install -e '.[engines]' to compare it")
            continue
        run = engines.bounce(engine, body, **cases, **settings)
        shown = ", ".join(f"{k}={v}" for k, v in run.settings.items() if np.ndim(v) == 0)
        print(f"{label}: bounce({engine!r}, ..., {shown}), {run.steps} steps")
        worst = run.summary()["worst"]
        note = f"error median {worst['median']:.2g}, max {worst['max']:.2g}"
        rows.append((label, run.seconds_per_impact, note, run.summary()))
    return rows


def late_phase_rows() -> list[tuple[str, int, int, float]]:
    """PyBullet's exact-contact settings on the standard cases moved late in the step.

    The standard cases at 10 contact phases from 0.99 to 0.999 of a time step, with
    Bullet's contact slop at its default (1e-5 m) and at 0: rows (label, bounces not
    exact to 1e-12, bounces, largest error). See docs/performance.md, "PyBullet late
    in a time step".
    """
    from spinimpact import engines

    if not engines.available("pybullet"):
        return []
    cases = engines.standard_cases(phases=10)
    cases["phase"] = 0.99 + 0.01 * (cases["phase"] - 0.05)  # 0.99, 0.991, ..., 0.999
    exact = next(s for label, _, s in engines.CONFIGURATIONS if "exact-contact" in label)
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    rows = []
    for hz in (240.0, 1000.0):
        for slop in (1e-5, 0.0):
            run = engines.bounce("pybullet", body, **cases, hz=hz, contact_slop=slop, **exact)
            label = f"PyBullet, {hz:.0f} Hz, exact-contact settings, contact_slop={slop:g}"
            rows.append((label, int((run.error > 1e-12).sum()), run.error.size, run.error.max()))
    return rows


def micro_slip_line(n: int = 100_000) -> str:
    """``solve`` under ``MindlinDeresiewicz`` read from its table against Walton's law on
    the same ``n`` rows, each with its own ``kappa`` (in the table's ``[0.85, 1]``): the
    ratio of their best times in this run."""
    from spinimpact import MindlinDeresiewicz, Walton
    from spinimpact.core.mdr_table import table_rows

    rng = np.random.default_rng(3)
    ball = Body.solid_sphere(mass=0.0027, radius=0.02)
    vx, vy, om = rng.uniform(-6, 6, n), -rng.uniform(0.5, 8, n), rng.uniform(-300, 300, n)
    kappa = rng.uniform(0.85, 1.0, n)
    law = MindlinDeresiewicz(poisson_ratio=0.3)
    served = float(table_rows(3.5, 0.3, kappa, law.stiffness_ratio).mean())

    def run(tangential):
        return lambda: solve(ball, vx, vy, om, mu=0.3, kappa=kappa, tangential=tangential)

    run(law)(), run(Walton(0.3))()  # the table's loading and first calls outside the timing
    t_table, t_walton = best(run(law), 5), best(run(Walton(0.3)), 5)
    return (f"MindlinDeresiewicz from its table, {n:,} rows with {n:,} distinct kappa "
            f"({served:.0%} of them in the table): {t_table / t_walton:.2f} times Walton's "
            f"law on the same rows ({t_walton / n * 1e9:.0f} ns a row), both in this "
            "run")  # fmt: skip


def fit_benchmark(n: int = 10_000) -> tuple[float, float]:
    """Time of ``spinimpact.fit`` (rigid model, constant kappa, profile intervals included)
    on ``n`` noisy synthetic bounces, and of one vectorized ``solve()`` of the same
    bounces, measured in this run: ``(t_fit, t_solve)`` in seconds."""
    from spinimpact import MeasuredBounces, fit

    rng = np.random.default_rng(15)
    ball = Body.solid_sphere(mass=0.058, radius=0.033)
    vy = -rng.uniform(1.0, 6.0, n)
    vx, om = rng.uniform(0.2, 4.0, n) * -vy, rng.normal(0.0, 30.0, n)
    after = solve(ball, vx, vy, om, mu=0.35, kappa=0.8).after
    sd = (0.05, 0.05, 3.0)
    obs = [
        a + rng.normal(0.0, s, n)
        for a, s in zip((after.vx, after.vy, after.omega), sd, strict=True)
    ]
    data = MeasuredBounces(vx, vy, om, *obs, *sd)
    fit(data.select(np.arange(50)), ball)  # imports and first calls outside the timing
    t_fit = best(lambda: fit(data, ball), 3)
    t_solve = best(lambda: solve(ball, vx, vy, om, mu=0.35, kappa=0.8), 5)
    return t_fit, t_solve


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--n", type=int, default=10_000_000, help="impacts in the batch")
    parser.add_argument(
        "--sweep-points", type=int, default=100_000_000, help="points of the out-of-core sweep"
    )
    parser.add_argument("--rows", type=int, default=1_000_000, help="rows of the batch files")
    args = parser.parse_args()
    n = args.n
    # An out-of-core sweep in a child process, started before this process holds
    # the big arrays: Linux carries a process's peak RSS across fork and exec.
    import resource
    import subprocess

    cmd = [
        sys.executable,
        "-m",
        "spinimpact",
        "sweep",
        "--vx",
        "uniform:-5:5",
        "--vy",
        "uniform:-6:-0.5",
        "--omega",
        "uniform:-60:60",
        "--samples",
        str(args.sweep_points),
    ]
    t = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True)
    t_sweep = time.perf_counter() - t
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024  # KiB on Linux
    sweep_row = (
        f"sweep of {args.sweep_points:,} random points (regime fractions; "
        "whole command, interpreter start included)",
        t_sweep / args.sweep_points,
        f"peak RSS {peak:.0f} MiB",
    )

    rng = np.random.default_rng(0)
    vx, vy, om = rng.normal(0, 3, n), -rng.uniform(0.1, 5, n), rng.normal(0, 60, n)
    params = (1.0, 0.1, 3.5, 0.3, 0.8)  # a 1 kg solid sphere, R = 0.1 m, mu = 0.3, kappa = 0.8
    outs = tuple(np.empty(n) for _ in range(3))
    moved = 6 * 8 * n  # bytes: three float64 arrays read, three written

    # Copy bound: the same bytes read and written, single-threaded NumPy and, if
    # Numba is there, a parallel copy; the faster one is the bound.
    dst = tuple(np.empty(n) for _ in range(3))
    t_copy = best(lambda: [np.copyto(d, s) for d, s in zip(dst, (vx, vy, om), strict=True)])
    copy_kind = "np.copyto"
    if fused.HAVE_NUMBA:
        import numba

        @numba.njit(parallel=True)
        def pcopy(a, b, c, x, y, z):
            for i in numba.prange(a.size):
                x[i] = a[i]
                y[i] = b[i]
                z[i] = c[i]

        pcopy(vx, vy, om, *dst)
        t_pcopy = best(lambda: pcopy(vx, vy, om, *dst))
        if t_pcopy < t_copy:
            t_copy, copy_kind = t_pcopy, "parallel copy (Numba)"

    rows = []
    if fused.HAVE_NUMBA:
        fused.rebound(vx, vy, om, *params, out=outs)  # compile
        t_fused = best(lambda: fused.rebound(vx, vy, om, *params, out=outs))
        per = t_fused / n
        rows.append(
            ("fused kernel (Numba) into preallocated out=", per, f"{t_copy / t_fused:.2f} of copy")
        )
        t_fresh = best(lambda: fused.rebound(vx, vy, om, *params), 5)
        rows.append(
            ("fused kernel, fresh output arrays", t_fresh / n, f"{t_copy / t_fresh:.2f} of copy")
        )
        mass = np.full(n, 1.0)
        t_arr = best(lambda: fused.rebound(vx, vy, om, mass, 0.1, 3.5, 0.3, 0.8, out=outs), 5)
        # it reads a fourth array: 7 arrays of traffic against the copy's 6
        rows.append(
            (
                "fused kernel, per-impact mass array",
                t_arr / n,
                f"{7 / 6 * t_copy / t_arr:.2f} of copy",
            )
        )
    t_numpy = best(lambda: rebound(vx, vy, om, *params), 3)
    if not fused.HAVE_NUMBA:
        per = t_numpy / n
    rows.append(("plain NumPy path, rebound", t_numpy / n, f"{t_copy / t_numpy:.2f} of copy"))
    m = min(n, 1_000_000)
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    t_solve = best(lambda: solve(body, vx[:m], vy[:m], om[:m], mu=0.3, kappa=0.8), 3) / m
    rows.append(("solve(): every Impact field", t_solve, ""))
    k = 50_000
    sub = list(zip(vx[:k].tolist(), vy[:k].tolist(), om[:k].tolist(), strict=True))
    t_py = best(lambda: [python_rebound(a, b, c, *params) for a, b, c in sub], 3) / k
    rows.append(("pure-Python scalar loop, rebound", t_py, ""))
    from tests.reference import integrate_ivp

    j = 30
    g = float(body.gyration)
    t_ivp = (
        best(
            lambda: [integrate_ivp(vx[i], vy[i], om[i], 1.0, 0.1, g, 0.3, 0.8) for i in range(j)], 1
        )
        / j
    )
    rows.append(("numerical integration in tau (SciPy solve_ivp)", t_ivp, ""))

    rows.append(sweep_row)
    engine_rows = engine_comparison()
    rows.extend((name, t, note) for name, t, note, _ in engine_rows)
    table = Table(title=f"spinimpact benchmarks: {n:,} impacts, float64")
    table.add_column("method")
    table.add_column(
        "time per impact / fused" if fused.HAVE_NUMBA else "time / NumPy path", justify="right"
    )
    table.add_column("bandwidth", justify="right")
    for name, t, note in rows:
        table.add_row(name, f"{t / per:,.3g}", note)
    console = Console(width=110)
    console.print(table)
    if engine_rows:
        errors = Table(
            title="engines against the exact answer: error of the rebound "
            "(|engine - exact| / max(|vx|, |vy|, R|omega|) before impact)"
        )
        errors.add_column("engine")
        for col in ("vx+ median / max", "vy+ median / max", "R omega+ median / max", "worst p95"):
            errors.add_column(col, justify="right")
        for name, _, _, s in engine_rows:
            errors.add_row(
                name,
                *(f"{s[k]['median']:.3g} / {s[k]['max']:.3g}" for k in ("vx", "vy", "omega")),
                f"{s['worst']['p95']:.3g}",
            )
        console.print(errors)
        console.print(
            "engine cases: spinimpact.engines.standard_cases(), 144 impacts of a solid "
            "sphere x 8 contact phases"
        )
    t_fit, t_solve = fit_benchmark()
    console.print(
        f"spinimpact.fit of 10,000 bounces (rigid, mu and kappa, profile intervals): "
        f"{t_fit:.2f} s, {t_fit / t_solve:,.0f} times one vectorized solve() of them "
        f"({t_solve * 1e3:.1f} ms), both in this run"
    )
    console.print(micro_slip_line())  # the micro-slip law from its table, a kappa per row
    from benchmarks.flight_bench import flight_benchmark
    from benchmarks.flight_bench import line as flight_line

    console.print(flight_line(10_000, *flight_benchmark()))  # serves/s against one at a time
    late = late_phase_rows()
    if late:
        phases = Table(
            title="PyBullet late in a time step: the standard cases at 10 contact phases "
            "from 0.99 to 0.999"
        )
        phases.add_column("engine")
        phases.add_column("not exact (error > 1e-12)", justify="right")
        phases.add_column("largest error", justify="right")
        for name, off, total, worst in late:
            phases.add_row(name, f"{off} of {total}", f"{worst:.2g}")
        console.print(phases)
    from benchmarks.limits import lines as limit_lines  # solve() and batch at their limits

    for line in limit_lines(n, args.rows):
        console.print(line)
    console.print(
        f"copy bound: {copy_kind}, {moved / t_copy / 1e9:.1f} GB/s of traffic in this run; "
        f"machine: {platform.machine()}, {os.cpu_count()} cores, "
        f"Python {platform.python_version()}, "
        f"NumPy {np.__version__}, Numba {'yes' if fused.HAVE_NUMBA else 'no'}"
    )
    from benchmarks.one_impact import report as one_impact  # one impact; the compiled law

    one_impact(console)
    from benchmarks.scalar_calls import report as scalar_calls  # every solver on one impact

    scalar_calls(console)
    if fused.HAVE_NUMBA:
        from benchmarks.dem_cost import report as dem_cost  # the DEM force in an njit loop

        dem_cost(console.print)
        tangential_report(console)  # Walton's and Stronge's laws in an njit loop


if __name__ == "__main__":
    main()
