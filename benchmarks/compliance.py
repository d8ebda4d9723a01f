"""What the impulse-space tangential laws cost: ratios against the rigid solve, one run.

Run from the repository root: ``.venv/bin/python -m benchmarks.compliance [--n N]``.
Every figure is a ratio against ``solve`` without a law on the same impacts, measured in
the same run on the same machine (best of several runs each), never an absolute claim.
Stronge's cost grows with the number of stick/slip changes, so it is measured at the
literature's stiffness ratio (Poisson's ratio 0.3) and at a stiff contact (``r = 100``).
MindlinDeresiewicz steps every impact in time (256 springs, 2048 steps by default), so it is
measured on the first ``--n-mdr`` impacts only (default 1,000), against the rigid solve of
those same impacts.
"""

from __future__ import annotations

import argparse

import numpy as np

from spinimpact import Body, MindlinDeresiewicz, Stronge, Walton, solve

from .bench import best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="impacts (default 100000)")
    parser.add_argument("--n-mdr", type=int, default=1_000,
                        help="impacts for MindlinDeresiewicz (default 1000)")  # fmt: skip
    args = parser.parse_args()
    n = args.n
    rng = np.random.default_rng(0)
    ball = Body.solid_sphere(mass=0.057, radius=0.033)
    vx, vy = rng.uniform(-6, 6, n), -rng.uniform(0.5, 6, n)
    omega = rng.uniform(-200, 200, n)

    def run(law, k=n):
        return lambda: solve(ball, vx[:k], vy[:k], omega[:k], mu=0.4, kappa=0.8, tangential=law)

    run(None)()  # compile and warm whatever the rigid path uses
    base = best(run(None))
    print(f"{n:,} random impacts of a tennis-ball-like shell, mu = 0.4, kappa = 0.8")
    print(f"{'law':32s} {'time / rigid solve':>20s}")
    print(f"{'rigid solve (baseline)':32s} {1.0:20.2f}")
    for name, law in [
        ("Walton(beta0=0.3)", Walton(0.3)),
        ("Stronge(poisson_ratio=0.3)", Stronge(poisson_ratio=0.3)),
        ("Stronge(stiffness_ratio=100)", Stronge(stiffness_ratio=100.0)),
    ]:
        print(f"{name:32s} {best(run(law), repeat=3) / base:20.2f}")
    k = min(args.n_mdr, n)
    law = MindlinDeresiewicz(poisson_ratio=0.3)
    run(law, k)()  # the normal motion's calibration, once per kappa
    ratio = best(run(law, k), repeat=1) / best(run(None, k))
    print(f"{'MindlinDeresiewicz(nu=0.3)':32s} {ratio:20.0f}   (on {k:,} impacts)")


if __name__ == "__main__":
    main()
