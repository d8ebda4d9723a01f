"""How the DEM contact force's impact converges to the impulse-space law as the step shrinks.

One impact of Chung & Ooi's Test 6 sphere (aluminium alloy, R = 0.1 m, 0.2 m/s normal
speed, mu = 0.4, no damping) with backspin ``u-/vn = 1`` (``chi = 2.1``: the contact
slides, sticks and the slip reverses) is stepped by the DEM loop with each tangential
model at 100 to 6,400 steps per Hertz contact duration (cells: 65,536, so that the history
is kept whole), and the slip after the impact is compared with the independent solution of
the same model: :func:`spinimpact.dynamics.simulate` (events located to ``rtol = 1e-12``)
for the springs, :func:`spinimpact.core.mdr.mdr_slip` (1,024 springs, 8,192 steps, its own
error about 2e-7 of vn) for micro-slip. The last column is micro-slip with Hunt-Crossley
damping for e = 0.5 (2,048 springs and 16,384 steps for its reference). The order is
``log2`` of the ratio of successive errors.

Run ``python -m benchmarks.dem_convergence``.
"""

from __future__ import annotations

import dataclasses
import math

from spinimpact import Body, dem
from spinimpact.core.mdr import mdr_slip
from spinimpact.dynamics import HertzContact, Mindlin, simulate

E, NU, RHO, R, VN, MU = 7.0e10, 0.33, 2700.0, 0.1, 0.2, 0.4
STEPS = (100, 200, 400, 800, 1600, 3200, 6400)
#: The rows: each tangential model undamped, and micro-slip damped.
MODELS = (*dem.MODELS, "micro-slip, e = 0.5")


#: The damped case: micro-slip with Hunt-Crossley damping for e = 0.5 and the friction
#: limit on the whole normal force (as :func:`~spinimpact.core.mdr.mdr_slip` takes it).
DAMPED = "micro-slip, e = 0.5"


def _force(model):
    options = {"model": model}
    if model == DAMPED:
        options = {"model": "micro-slip", "restitution": 0.5, "damping": "hunt-crossley",
                   "speed": VN, "friction_limit": "total"}  # fmt: skip
    return dem.ContactForce.sphere_on_wall(youngs_modulus=E, poisson_ratio=NU, radius=R,
                                           density=RHO, mu=MU, cells=1 << 16,
                                           **options)  # fmt: skip


def reference(model, omega):
    """The slip after the impact by the model's independent solution (m/s)."""
    force = _force(model)
    if model in ("micro-slip", DAMPED):
        ratio = 4.0 * force.shear_modulus / force.modulus
        kappa = 0.5 if model == DAMPED else 1.0
        springs, steps = (2048, 16384) if model == DAMPED else (1024, 8192)
        return float(mdr_slip(R * omega, -VN, 3.5, MU, kappa, ratio, springs=springs,
                              steps=steps)[0])  # fmt: skip
    body = Body.solid_sphere(mass=force.mass, radius=R)
    law = Mindlin(poisson_ratio=NU, spring=model)
    sim = simulate(body, 0.0, -VN, omega, mu=MU, contact=HertzContact(E, NU, R),
                   tangential=law, rtol=1e-12)  # fmt: skip
    return float(sim.after.vx + R * sim.after.omega)


def table():
    """``model -> [(steps, error/vn, order)]``."""
    omega = VN / R
    out = {}
    for model in MODELS:
        ref = reference(model, omega)
        force = _force(model)
        ball = Body.solid_sphere(mass=force.mass, radius=R)
        rows, previous = [], None
        for steps in STEPS:
            run = dem.wall_impact(force, ball, 0.0, -VN, omega, dt=force.time_scale(VN) / steps)
            err = (float(run.vx) + R * float(run.omega) - ref) / VN
            order = math.log2(abs(previous / err)) if previous else float("nan")
            rows.append((steps, err, order))
            previous = err
        out[model] = rows
    return out


def default_cells_table():
    """``model -> [(steps, error/vn)]`` for micro-slip and history with the default cells."""
    omega = VN / R
    out = {}
    for model in ("micro-slip", "history"):
        ref = reference(model, omega)
        force = dataclasses.replace(_force(model), cells=dem.ContactForce.cells)
        ball = Body.solid_sphere(mass=force.mass, radius=R)
        out[model] = []
        for steps in STEPS:
            run = dem.wall_impact(force, ball, 0.0, -VN, omega, dt=force.time_scale(VN) / steps)
            out[model].append((steps, (float(run.vx) + R * float(run.omega) - ref) / VN))
    return out


def restitution_table():
    """``damping -> [(steps, e - 0.5)]``: the normal restitution's error, e = 0.5."""
    out = {}
    for damping in ("viscous", "hunt-crossley"):
        force = dem.ContactForce.sphere_on_wall(youngs_modulus=E, poisson_ratio=NU, radius=R,
                                                density=RHO, mu=0.0, restitution=0.5,
                                                damping=damping, speed=VN)  # fmt: skip
        ball = Body.solid_sphere(mass=force.mass, radius=R)
        out[damping] = [
            (steps, float(dem.wall_impact(force, ball, 0.0, -VN, 0.0,
                                          dt=force.time_scale(VN) / steps).vy) / VN - 0.5)
            for steps in STEPS
        ]  # fmt: skip
    return out


#: Test 6's incidences (chi) at which the cells are compared.
CELLS_CHI = (0.5, 1.19, 1.5, 2.09, 3.0, 5.75, 10.0, 24.0)


def cells_table(cells=(16, 32, 64, 128), steps=(200, 1000)):
    """The history's resolution on Test 6 (default micro-slip, viscous damping, e = 0.5):
    ``(steps, cells) -> the largest |beta - beta_fine|`` over :data:`CELLS_CHI`, with
    ``beta_fine`` from 32,768 cells at the same steps; ``("step", steps)``: the step's own
    error, 32,768 cells at ``steps`` against 4,000 steps."""
    import numpy as np

    from . import chung_ooi, dem_chung_ooi

    chi = np.array(CELLS_CHI)
    case = chung_ooi.TEST6[0]

    def beta(n_cells, n_steps):
        return dem_chung_ooi.test6_beta({"cells": n_cells}, chi, case, n_steps)

    out, finest = {}, beta(1 << 15, 4000)
    for n_steps in steps:
        fine = beta(1 << 15, n_steps)
        out[("step", n_steps)] = float(np.abs(fine - finest).max())
        for n_cells in cells:
            out[(n_steps, n_cells)] = float(np.abs(beta(n_cells, n_steps) - fine).max())
    return out


def reentry(cells=(16, 128, 4096), cycles=10):
    """``cells -> F_end/F_start``: a contact pressed to 2e-5 m, loaded tangentially to half
    its full-slip displacement, then its overlap cycled between 0.9 and 1 of that (20 steps
    each way) with no tangential motion; the ratio of the tangential force after the cycles
    to that before them."""
    base = dem.ContactForce.sphere_on_wall(youngs_modulus=E, poisson_ratio=NU, radius=R,
                                           density=RHO, mu=MU)  # fmt: skip
    d0 = 2e-5
    a = math.sqrt(R * d0)
    slide = 3.0 * MU * 4.0 / 3.0 * base.modulus * math.sqrt(R) * d0**1.5
    slide /= 16.0 * base.shear_modulus * a
    out = {}
    for n in cells:
        force = dataclasses.replace(base, cells=n)
        state = force.new_state()
        for k in range(1, 201):
            force.step(state, d0 * k / 200, 0.0, (0.0, 0.0))
        for _ in range(100):
            start = force.step(state, d0, 0.0, (0.5 * slide / 100, 0.0))[1]
        for _ in range(cycles):
            for k in range(1, 21):
                force.step(state, d0 * (1.0 - 0.1 * k / 20), 0.0, (0.0, 0.0))
            for k in range(1, 21):
                end = force.step(state, d0 * (0.9 + 0.1 * k / 20), 0.0, (0.0, 0.0))[1]
        out[n] = end / start
    return out


def main():
    print("slip after the impact, (DEM - independent solution)/vn, and the observed order")
    print(f"{'steps':>6s} " + " ".join(f"{m:>20s}" for m in MODELS))
    data = table()
    for i, steps in enumerate(STEPS):
        cells = []
        for model in MODELS:
            _, err, order = data[model][i]
            cells.append(f"{err:11.2e} ({order:5.2f})")
        print(f"{steps:6d} " + " ".join(f"{c:>20s}" for c in cells))
    print()
    print(f"the same with the default {dem.ContactForce.cells} cells, (DEM - independent)/vn")
    print(f"{'steps':>6s} {'micro-slip':>12s} {'history':>12s}")
    default = default_cells_table()
    for i, steps in enumerate(STEPS):
        print(f"{steps:6d} {default['micro-slip'][i][1]:12.2e} {default['history'][i][1]:12.2e}")
    print()
    print("normal restitution e = 0.5: (DEM - 0.5), viscous and Hunt-Crossley damping")
    print(f"{'steps':>6s} {'viscous':>12s} {'Hunt-Crossley':>14s}")
    rest = restitution_table()
    for i, steps in enumerate(STEPS):
        print(f"{steps:6d} {rest['viscous'][i][1]:12.2e} {rest['hunt-crossley'][i][1]:14.2e}")
    print()
    print("Test 6 (micro-slip, viscous, e = 0.5), largest |beta - beta(32,768 cells)| over chi "
          f"= {', '.join(map(str, CELLS_CHI))}")  # fmt: skip
    resolution = cells_table()
    for steps in (200, 1000):
        cells = ", ".join(f"{n} cells {resolution[(steps, n)]:.1e}" for n in (16, 32, 64, 128))
        print(f"  {steps} steps: {cells}; the step's own error {resolution[('step', steps)]:.1e}")
    print()
    ratios = ", ".join(f"{n} cells {r:.4f}" for n, r in reentry().items())
    print(f"overlap cycled 10 times between 0.9 and 1 of its peak: tangential force after / "
          f"before: {ratios}")  # fmt: skip


if __name__ == "__main__":
    main()
