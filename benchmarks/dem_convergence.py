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


if __name__ == "__main__":
    main()
