"""Build the table of :mod:`spinimpact.core.mdr_table` and measure its error.

Run from the repository root: ``.venv/bin/python -m benchmarks.mdr_table`` (a few minutes on
two cores with Numba). It solves the impact in time (:func:`spinimpact.core.mdr.mdr_slip`,
256 springs, 2048 steps) on the grid, then on ``--check`` random ``kappa`` values off the
grid, 40 random points each (seed 1), prints the largest error in ``phi`` and writes
``src/spinimpact/core/data/mdr_table.npz`` with that error in it. ``--check-only`` measures
the shipped table without rebuilding it.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from spinimpact.core import mdr
from spinimpact.core import mdr_table as mt

OUT = Path(__file__).resolve().parents[1] / "src" / "spinimpact" / "core" / "data" / mt.FILE

#: The grid: equal steps in each axis.
KAPPA = np.linspace(0.85, 1.0, 13)
Q = np.linspace(2.0, 4.0, 41)
T = np.linspace(0.0, 1.0, 65)


def build() -> dict:
    """The grid's ``X*`` and ``phi`` by the full solution."""
    touch = np.array([mt.build_touch(float(kappa)) for kappa in KAPPA])
    threshold = np.empty((KAPPA.size, Q.size))
    share = np.empty((2, KAPPA.size, Q.size, T.size))
    start = time.perf_counter()
    for i, kappa in enumerate(KAPPA):
        threshold[i] = mt.build_threshold(Q, float(kappa))
        share[:, i] = mt.build_share(T, Q, float(kappa), touch[i], threshold[i])
        print(f"kappa = {kappa:.4f}: X* in [{threshold[i].min():.4f}, {threshold[i].max():.4f}]"
              f" ({time.perf_counter() - start:.0f} s)", flush=True)  # fmt: skip
    return {"kappa": KAPPA, "q": Q, "t": T, "touch": touch, "threshold": threshold, "share": share,
            "springs": 256, "steps": 2048}  # fmt: skip


def check(table: mt.MdrTable, groups: int, per: int = 40, seed: int = 1) -> float:
    """The largest error in ``phi`` on ``groups`` random ``kappa`` with ``per`` random
    ``(q, X)`` each (``X`` up to 1.2 ``X*``: the sliding side included), none on the grid."""
    rng = np.random.default_rng(seed)
    kappa = np.repeat(rng.uniform(table.kappa[0], table.kappa[-1], groups), per)
    q = rng.uniform(table.q[0], table.q[-1], kappa.size)
    x = rng.uniform(0.0, 1.2, kappa.size) * mt.breaks(q, kappa, table)[1]
    got, _ = mt.impulse_share(x, q, kappa, table)
    impulse = (1.0 + kappa) * q  # the full solution at zeta = q, r = mu = |v_n| = 1
    after, _ = mdr.mdr_slip(x * impulse, -1.0, q, 1.0, kappa, 1.0)
    err = np.abs(got - (x * impulse - after) / impulse)
    worst = float(err.max())
    j = int(err.argmax())
    print(f"{kappa.size} random points: largest |phi error| {worst:.3g} at kappa = "
          f"{kappa[j]:.4f}, q = {q[j]:.4f}, X = {x[j]:.4f}; median "
          f"{np.median(err):.3g}")  # fmt: skip
    return worst


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", type=int, default=100,
                        help="random kappa values, 40 points each (default 100)")  # fmt: skip
    parser.add_argument("--check-only", action="store_true", help="measure the shipped table")
    args = parser.parse_args()
    if args.check_only:
        check(mt.load_table(), args.check)
        return
    data = build()
    table = mt.MdrTable(*(data[k] for k in mt.FIELDS), 0.0, 256, 2048)
    worst = check(table, args.check)
    OUT.parent.mkdir(exist_ok=True)
    tmp = OUT.with_suffix(".tmp.npz")
    np.savez_compressed(tmp, **data, max_error=worst)
    tmp.replace(OUT)
    print(f"wrote {OUT} (max_error = {worst:.3g})")


if __name__ == "__main__":
    main()
