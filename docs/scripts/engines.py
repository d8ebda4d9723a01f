"""Figure for docs/performance.md: how far PyBullet, MuJoCo and Drake land from the exact bounce.

Usage: python docs/scripts/engines.py OUTPUT.png   (needs the [engines] extra)

Left: the distribution of each engine configuration's worst error over the standard
cases (spinimpact.engines.standard_cases). Right: PyBullet's rebound speed against
where, within its time step, the sphere reaches the plane.
"""

import sys

import numpy as np
from matplotlib.figure import Figure

from spinimpact import Body
from spinimpact import engines as E
from spinimpact.io import atomic_path


def main(output: str) -> None:
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    cases = E.standard_cases()
    fig = Figure(figsize=(14, 6.4), layout="constrained")
    # one subfigure per panel, each with its legend below it, where no curve runs
    subs = fig.subfigures(1, 2, width_ratios=[1.5, 1], wspace=0.02)
    left, right = (sub.subplots() for sub in subs)
    for label, engine, settings in E.CONFIGURATIONS:
        run = E.bounce(engine, ball, **cases, **settings)
        err = np.sort(run.error)
        if err[-1] < 1e-15:  # exact to rounding: off the left of the axis
            label = f"{label}: all below 1e-15"
        left.step(err, np.arange(1, err.size + 1) / err.size, where="post", label=label)
    left.set_xscale("log")
    left.set_xlim(1e-4, 1.5)
    left.set_xlabel(
        r"largest error of $v_x^+$, $v_y^+$, $R\omega^+$, relative to "
        r"$\max(|v_x^-|, |v_y^-|, R|\omega^-|)$"
    )
    left.set_ylabel(f"fraction of the {err.size} impacts")
    left.set_title("Error against the exact rigid-body answer")
    left.grid(alpha=0.3)
    subs[0].legend(loc="outside lower center", ncol=2, fontsize=9.5)

    phase = np.linspace(0.0, 1.0, 201, endpoint=False)
    for vy in (-1.0, -3.0):
        for kappa in (0.5, 0.8):
            run = E.bounce("pybullet", ball, 0.0, vy, 0.0, mu=0.3, kappa=kappa, phase=phase)
            right.plot(phase, run.vy / -vy, label=rf"$v_y^-$ = {vy:g} m/s, $\kappa$ = {kappa}")
            right.axhline(kappa, color="0.6", lw=0.8, ls="--")
    right.set_xlabel("contact phase: where in its 1/240 s step the sphere meets the plane")
    right.set_ylabel(r"PyBullet's $v_y^+/|v_y^-|$ (dashed: $\kappa$)")
    right.set_title("PyBullet at its defaults, head-on: rebound against phase")
    right.grid(alpha=0.3)
    subs[1].legend(loc="outside lower center", ncol=2, fontsize=10)
    with atomic_path(output) as tmp:
        fig.savefig(tmp, dpi=80, format="png")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
