"""
The DEM contact force: micro-slip's hysteresis, and a bounce stepped in time
============================================================================

:mod:`spinimpact.dem` gives DEM loops a contact force with the Mindlin-Deresiewicz
tangential law: the contact's edge slips while its centre sticks. Left: a sphere pressed
onto a wall at a constant overlap, its contact point moved back and forth. The
micro-slip force follows Cattaneo and Mindlin's closed form as it loads and the Masing
branches (the loading curve doubled) as it unloads; the loop's area is the energy friction
takes per cycle. A DEM code's incremental spring goes straight to the Coulomb limit and
dissipates only once it slides. Right: the tangential force during one bounce of
Chung & Ooi's Test 6 sphere with backspin, stepped by :func:`spinimpact.dem.wall_impact`,
with and without the viscous tangential damper DEM codes add.
"""

import dataclasses
import math

import matplotlib.pyplot as plt
import numpy as np

from spinimpact import Body, dem

force = dem.ContactForce.sphere_on_wall(
    youngs_modulus=7.0e10, poisson_ratio=0.33, radius=0.1, density=2700.0, mu=0.4
)
overlap = 2.0e-5  # m
a = math.sqrt(force.radius * overlap)
n_el = 4.0 / 3.0 * force.modulus * math.sqrt(force.radius) * overlap**1.5
slide = 3.0 * force.mu * n_el / (16.0 * force.shear_modulus * a)  # full-slip displacement
amplitude = 0.8 * slide


def cycle(model, steps=400):
    """Press to ``overlap``, then move the contact point 0 -> +A -> -A -> +A."""
    law = dataclasses.replace(force, model=model)
    state = law.new_state()
    for k in range(1, 201):  # the normal loading, no tangential motion
        law.step(state, overlap * k / 200, 0.0, (0.0, 0.0))
    path = np.concatenate([np.linspace(0, amplitude, steps), np.linspace(amplitude, -amplitude,
                           2 * steps), np.linspace(-amplitude, amplitude, 2 * steps)])  # fmt: skip
    forces, x = [], 0.0
    for target in path[1:]:
        _n, f, _ = law.step(state, overlap, 0.0, (target - x, 0.0))
        forces.append(-f)  # the force the contact carries, along the displacement
        x = target
    return path[1:], np.array(forces)


def cattaneo(x):
    """Cattaneo-Mindlin loading: F = mu N [1 - (1 - x/x*)^(3/2)], x <= x*."""
    return force.mu * n_el * (1.0 - (1.0 - np.minimum(x, slide) / slide) ** 1.5)


x, micro = cycle("micro-slip")
_, spring = cycle("incremental")
turn = cattaneo(amplitude)
grid = np.linspace(-amplitude, amplitude, 2001)
masing_down = turn - 2.0 * cattaneo((amplitude - grid) / 2.0)  # unloading from +A
masing_up = -turn + 2.0 * cattaneo((grid + amplitude) / 2.0)  # reloading from -A
loop_exact = np.trapezoid(masing_up - masing_down, grid)  # the work friction takes
last = len(x) - 4 * 400  # the closing cycle: from +A down to -A and back
loop_micro = abs(np.trapezoid(micro[last:], x[last:]))
print(f"loop area: micro-slip {loop_micro:.4e} J, Mindlin-Deresiewicz {loop_exact:.4e} J, "
      f"difference {abs(loop_micro / loop_exact - 1):.1e}")  # fmt: skip
assert abs(loop_micro / loop_exact - 1) < 1e-2

fig, (left, right) = plt.subplots(1, 2, figsize=(10.5, 4.0), layout="constrained")
left.plot(x * 1e6, micro / (force.mu * n_el), label="micro-slip")
left.plot(x * 1e6, spring / (force.mu * n_el), label="incremental spring", lw=1.0)
left.plot(grid * 1e6, masing_down / (force.mu * n_el), "k:", label="Mindlin-Deresiewicz")
left.plot(grid * 1e6, masing_up / (force.mu * n_el), "k:")
left.set_xlabel(r"tangential displacement, $\mu$m")
left.set_ylabel(r"tangential force / $\mu N$")
left.legend(fontsize=8)

ball = Body.solid_sphere(mass=force.mass, radius=0.1)
for label, damper in (("micro-slip", False), ("micro-slip + tangential damper", True)):
    law = dem.ContactForce.sphere_on_wall(
        youngs_modulus=7.0e10, poisson_ratio=0.33, radius=0.1, density=2700.0, mu=0.4,
        restitution=0.5,
    )  # fmt: skip
    if damper:  # the normal damping's ratio, as DEM codes size the tangential damper
        law = dataclasses.replace(law, tangential_damping=law.damping_coefficient)
    run = dem.wall_impact(law, ball, 0.0, -0.2, 0.7 * 0.2 / 0.1, dt=law.time_scale(0.2) / 1000,
                          trace=True)  # fmt: skip
    trace = np.asarray(run.trace)
    u = 0.7 * 0.2
    print(f"{label}: beta = -u+/u- = {-(float(run.vx) + 0.1 * float(run.omega)) / u:.3f}")
    right.plot(trace[:, 0] * 1e3, trace[:, 3], label=label)
right.set_xlabel("time, ms")
right.set_ylabel("tangential force on the ball, N")
right.legend(fontsize=8)
plt.show()
