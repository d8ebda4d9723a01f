"""Engine contact settings calibrated against the exact answer, measured on held-out bounces.

Run from the repository root (needs the [engines] extra):

    .venv/bin/python -m benchmarks.engine_calibrate [--n 48] [--evaluations 300] [--seed 0]

For a 1 kg solid sphere of radius 0.1 m and each (mu, kappa) in {0.1, 0.3, 0.6} x {0.5, 0.8},
``spinimpact.engines.calibrate`` searches each engine's contact settings on ``n`` incidences
drawn from the standard cases' ranges (vx in [-2, 3] m/s, vy in [-3, -1] m/s, rim speed
R omega in [-3, 2] m/s, contact phase in [0, 1)), and the settings found are measured on
``n`` other incidences drawn with ``seed + 1``. Beside them, on the same held-out incidences
and time step:

* PyBullet (1/240 s, its default step): its defaults (restitution kappa, lateral friction mu),
  and the hand-found exact-contact settings (no contact margin, position correction,
  restitution threshold or slop);
* MuJoCo (the time step of ``make bench``'s calibrated contact, 0.01 pi R / 3 / 100 =
  1.05e-5 s): the search's start (the damped oscillator), and ``bounce``'s calibrated
  contact (elliptic cone, ``solreffriction``; its damping solved per (mu, kappa) on head-on
  bounces) with the same contact time and time step; and the search again with the sliding
  friction held at mu (``hold=("friction",)``).

Each figure is the error of a rebound, the largest of those of vx+, vy+ and R omega+ over
the incidence speed scale (``EngineRun.error``): its median and its maximum over the
incidences. Nothing is timed but the whole run.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from spinimpact import Body
from spinimpact import engines as E
from spinimpact.engines.configure import version

BALL = Body.solid_sphere(mass=1.0, radius=0.1)
#: ``make bench``'s calibrated MuJoCo contact: 1 % penetration at 3 m/s, 100 steps.
CONTACT_TIME = 0.01 * math.pi * 0.1 / 3.0
MUJOCO_DT = CONTACT_TIME / 100
PAIRS = [(mu, kappa) for mu in (0.1, 0.3, 0.6) for kappa in (0.5, 0.8)]
EXACT = {
    "contact_breaking_threshold": 0.0,
    "contact_erp": 0.0,
    "restitution_velocity_threshold": 0.0,
    "contact_slop": 0.0,
}


def _cell(run) -> str:
    return f"{np.median(run.error):.2g} / {np.max(run.error):.2g}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=48, help="incidences in each set")
    parser.add_argument("--evaluations", type=int, default=300, help="simplex budget")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--engine", choices=["pybullet", "mujoco"], nargs="*",
                        default=["pybullet", "mujoco"], help="engines to calibrate")  # fmt: skip
    parser.add_argument("--scan", action="store_true",
                        help="only MuJoCo's friction settings, one at a time")  # fmt: skip
    args = parser.parse_args()
    if args.scan:
        _scan(E.calibration_cases(args.n, args.seed, 0.1))
        return
    began = time.perf_counter()
    held = E.calibration_cases(args.n, args.seed + 1, 0.1)
    common = {"n": args.n, "seed": args.seed, "max_evaluations": args.evaluations}
    print(f"held-out rebound error, median / max over {args.n} incidences (seed {args.seed + 1})")
    if "pybullet" in args.engine:
        _pybullet(held, common)
    if "mujoco" in args.engine:
        _mujoco(held, common)
    print(f"\nwhole run {time.perf_counter() - began:.0f} s")


def _pybullet(held: dict, common: dict) -> None:
    print(f"\nPyBullet {version('pybullet')}, 1/240 s")
    print("| mu | kappa | defaults | hand-found exact | calibrated from defaults | "
          "calibrated, search |")  # fmt: skip
    print("|---:|---:|---:|---:|---:|---:|")
    for mu, kappa in PAIRS:
        cal = E.calibrate("pybullet", BALL, mu=mu, kappa=kappa, dt=1 / 240, **common)
        hand = E.bounce("pybullet", BALL, **held, mu=mu, kappa=kappa, **EXACT)
        print(f"| {mu} | {kappa} | {_cell(cal.start_held_out)} | {_cell(hand)} | "
              f"{_cell(cal.held_out)} | {_cell(cal.calibration)} |")  # fmt: skip
        changed = {k: v for k, v in cal.settings.items() if cal.start[k] != v}
        print(f"|  |  | settings changed from the defaults: {changed} | | | |")


def _mujoco(held: dict, common: dict) -> None:
    print(f"\nMuJoCo {version('mujoco')}, time step {MUJOCO_DT:.4g} s")
    print("| mu | kappa | search's start | bounce's calibrated contact | calibrated | "
          "calibrated, search | calibrated, friction held at mu |")  # fmt: skip
    print("|---:|---:|---:|---:|---:|---:|---:|")
    for mu, kappa in PAIRS:
        cal = E.calibrate("mujoco", BALL, mu=mu, kappa=kappa, dt=MUJOCO_DT, **common)
        held_mu = E.calibrate(
            "mujoco", BALL, mu=mu, kappa=kappa, dt=MUJOCO_DT, hold=("friction",), **common
        )
        today = E.bounce("mujoco", BALL, **held, mu=mu, kappa=kappa, contact_time=CONTACT_TIME)
        cells = [cal.start_held_out, today, cal.held_out, cal.calibration, held_mu.held_out]
        print(f"| {mu} | {kappa} | {' | '.join(_cell(c) for c in cells)} |")
        print(f"|  |  | found: {dict(cal.settings)} | | | | |")


def _scan(cases: dict) -> None:
    """MuJoCo's friction settings one at a time, from the calibration's start (mu 0.3,
    kappa 0.8): median errors of vx+, vy+ and R omega+ over the cases."""
    from spinimpact.engines import calibration as module

    mu, kappa = 0.3, 0.8
    bench = module._Bench("mujoco", BALL, cases, mu, kappa)
    space = module._mujoco_space(mu, kappa, MUJOCO_DT)
    print(f"MuJoCo {version('mujoco')}, time step {MUJOCO_DT:.4g} s, mu {mu}, kappa {kappa}, "
          f"{cases['vx'].size} incidences: median error of vx+ / vy+ / R omega+")  # fmt: skip
    print("| cone | friction time constant, steps | impratio | noslip_iterations | median errors |")
    print("|---|---:|---:|---:|---|")
    for cone in ("elliptic", "pyramidal"):
        for steps in (5, 20, 60):
            for impratio, noslip in ((1.0, 0), (10.0, 0), (1.0, 20)):
                x = space.start.copy()
                x[2] = math.log(steps)
                settings = {**space.settings(x), "cone": cone, "impratio": impratio,
                            "noslip_iterations": noslip}  # fmt: skip
                errors = bench.run(settings).errors()
                cells = " / ".join(f"{np.median(errors[k]):.2g}" for k in ("vx", "vy", "omega"))
                print(f"| {cone} | {steps} | {impratio:g} | {noslip} | {cells} |")


if __name__ == "__main__":
    main()
