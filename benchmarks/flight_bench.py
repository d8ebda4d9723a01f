"""Trajectories per second of ``spinimpact.flight``: 10,000 tennis serves (scattered in speed,
angle, direction and spin) with three bounces each, flown together, against the same serves
flown one at a time (a sample of them, timed in the same run).

Usage: python -m benchmarks.flight_bench [--n 10000] [--loop 50]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from spinimpact.model.flight import flight


def serves(n: int, seed: int = 16) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    return {
        "speed": rng.normal(50.0, 2.0, n), "angle": rng.normal(-6.0, 0.4, n),
        "direction": rng.normal(0.0, 1.5, n), "spin_rpm": rng.normal(2000.0, 300.0, n),
    }  # fmt: skip


def flight_benchmark(n: int = 10_000, loop: int = 50) -> tuple[float, float]:
    """``(vectorized, one at a time)`` in trajectories per second, measured in this run."""
    s = serves(n)
    common = {"height": 2.8, "max_bounces": 3, "path": False}
    flight("tennis", "hard", speed=50.0, angle=-6.0, **common)  # imports outside the timing
    start = time.perf_counter()
    many = flight("tennis", "hard", **s, **common)
    t_many = time.perf_counter() - start
    assert np.all(many.bounce_count == 3)
    start = time.perf_counter()
    for i in range(loop):
        flight("tennis", "hard", **{k: v[i] for k, v in s.items()}, **common)
    t_loop = time.perf_counter() - start
    return n / t_many, loop / t_loop


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--n", type=int, default=10_000, help="serves flown together")
    parser.add_argument("--loop", type=int, default=50, help="serves flown one at a time")
    args = parser.parse_args()
    fast, slow = flight_benchmark(args.n, args.loop)
    print(line(args.n, fast, slow))


def line(n: int, fast: float, slow: float) -> str:
    return (f"spinimpact.flight: {n:,} serves, three bounces each: {fast:,.0f} trajectories/s "
            f"together, {slow:,.1f}/s one at a time: {fast / slow:,.0f} times faster, both in "
            "this run")  # fmt: skip


if __name__ == "__main__":
    main()
