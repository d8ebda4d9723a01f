"""Regenerate docs/images/convergence.png: simulated rebound vs the rigid closed form.

Run with `make images` (or `.venv/bin/python docs/scripts/convergence.py OUT.png`).
For each contact law and each regime, the largest of the rebound-velocity,
dissipated-energy and mu_hat errors against solve(kappa), kappa being the law's
restitution at this speed computed once at rtol = 1e-13, as the integrator
tolerance of the simulation tightens.
"""

import sys

import numpy as np
from matplotlib.figure import Figure

from spinimpact import Body, solve
from spinimpact.dynamics import HertzContact, HuntCrossleyContact, LinearContact, simulate

BALL = Body.solid_sphere(mass=0.05, radius=0.02)
LAWS = {
    "LinearContact(k=1e6 N/m, c=40 N s/m)": LinearContact(stiffness=1e6, damping=40.0),
    "HertzContact(E=2 GPa, ν=0.35, α=0.05 s/m)": HertzContact(2e9, 0.35, 0.02, alpha=0.05),
    "HuntCrossleyContact(k=1e8, n=1.5, α=0.2 s/m)": HuntCrossleyContact(1e8, 1.5, 0.2),
}
CASES = {  # (vx, omega, mu) at vy = -3 m/s
    "frictionless": (1.0, 10.0, 0.0),
    "no-slip": (1.0, -50.0, 0.3),
    "stick-compression": (0.5, 0.0, 0.3),
    "stick-restitution": (1.0, 20.0, 0.12),
    "slip": (2.0, 60.0, 0.1),
}
RTOLS = np.geomspace(1e-4, 1e-12, 9)


def error(sim, kappa):
    b = sim.before
    rigid = solve(BALL, b.vx, b.vy, b.omega, mu=sim.mu, kappa=kappa)
    scale = abs(sim.before.vx) + abs(sim.before.vy) + abs(BALL.radius * sim.before.omega)
    return max(
        abs(sim.after.vx - rigid.after.vx) / scale,
        abs(BALL.radius * (sim.after.omega - rigid.after.omega)) / scale,
        abs(sim.dissipated_energy - rigid.dissipated_energy) / rigid.kinetic_energy_before,
        abs(sim.impulse_ratio - rigid.impulse_ratio),
    )


def main(out: str) -> None:
    fig = Figure(figsize=(11, 4.2), layout="constrained")
    axes = fig.subplots(1, 3, sharey=True)
    for ax, (name, law) in zip(axes, LAWS.items(), strict=True):
        kappa = law.restitution(BALL.mass, 3.0, rtol=1e-13)
        for regime, (vx, om, mu) in CASES.items():
            errs = [
                error(simulate(BALL, vx, -3.0, om, mu=mu, contact=law, rtol=r), kappa)
                for r in RTOLS
            ]
            ax.loglog(RTOLS, np.maximum(errs, 1e-17), marker="o", ms=3, label=regime)
        ax.loglog(RTOLS, RTOLS, color="0.6", ls="--", label="error = rtol")
        ax.set_xlabel("integrator rtol")
        ax.set_title(f"{name}\nκ = {kappa:.6f} at 3 m/s", fontsize="medium")
        ax.invert_xaxis()
    axes[0].set_ylabel("largest error vs. rigid closed form")
    axes[0].legend(fontsize="small")
    fig.suptitle("Simulated rebound converges to the rigid closed form at the law's restitution κ")
    fig.savefig(out, dpi=80)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "docs/images/convergence.png")
