"""
The impact in time, with Hertz contact
======================================

The rigid law needs no force history: Keller's method works in the normal impulse. A
compliant contact law gives the history itself. :func:`spinimpact.dynamics.simulate`
integrates one impact in time with a Hertz contact (with Hunt-Crossley damping) and
Coulomb friction, and :meth:`~spinimpact.dynamics.Simulation.rigid` gives the rigid closed
form at the simulation's own Newton restitution: the rebound agrees, as Keller's method
says it must for a sphere on a plane. :func:`spinimpact.viz.plots.plot_simulation` draws it.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si
from spinimpact.dynamics import HertzContact, simulate
from spinimpact.viz.plots import plot_simulation

ball = si.Body.solid_sphere(mass=0.0577, radius=0.0335)
contact = HertzContact(youngs_modulus=2e7, poisson_ratio=0.45, radius=0.0335, alpha=0.05)
sim = simulate(ball, vx=2.0, vy=-3.0, omega=60.0, mu=0.3, contact=contact)
rigid = sim.rigid()
print(f"contact lasted {sim.contact_duration * 1e3:.3f} ms, peak force {sim.peak_force:.1f} N")
print(f"Newton's restitution of the simulation {float(sim.newton_restitution):.4f}")
print(f"vx after: simulated {float(sim.after.vx):.6f}, rigid {float(rigid.after.vx):.6f} m/s")
assert np.isclose(float(sim.after.vx), float(rigid.after.vx), rtol=1e-6)

fig = plot_simulation(sim)
plt.show()
