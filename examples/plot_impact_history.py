"""
The impact process over the normal impulse
==========================================

Keller's method replaces time by the normal impulse ``tau``: every velocity is piecewise
linear in it, whatever the force's history. A solid sphere hitting the ground with some
backspin slips at first; the slip falls linearly until it stops (at ``tau_*``), and from
then on the contact point rolls. :meth:`spinimpact.Impact.history` gives the arrays,
:func:`spinimpact.viz.plots.plot_history` draws them.
"""

import matplotlib.pyplot as plt

import spinimpact as si
from spinimpact.viz.plots import plot_history

ball = si.Body.solid_sphere(mass=0.17, radius=0.028)
imp = si.solve(ball, vx=3.0, vy=-4.0, omega=50.0, mu=0.2, kappa=0.8)
print(imp.regime)
print(f"tau* = {float(imp.tau_star):.4f} N s of tau1 = {float(imp.tau1):.4f} N s")

h = imp.history(n=5)
print("tau (N s):", h.tau.round(4))
print("slip (m/s):", h.slip.round(4))

fig = plot_history(imp)
plt.show()
