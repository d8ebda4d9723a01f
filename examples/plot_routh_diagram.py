"""
Routh's diagram
===============

Routh's graphical method plots the friction impulse against the normal impulse. While the
contact point slips, the friction impulse grows at ``-mu`` times the normal one (a line of
slope ``-mu``); once it sticks, a rolling sphere or disk on a plane needs no more friction
and the line turns flat. Below, a solid disk (the paper's Fig. 4 set-up, ``mu = 0.25``,
``kappa = 0.6``) with slip that stops during compression.
"""

import matplotlib.pyplot as plt

import spinimpact as si
from spinimpact.viz.plots import plot_routh

disk = si.Body.solid_disk(mass=1.0, radius=0.1)
imp = si.solve(disk, vx=0.5, vy=-1.0, omega=0.0, mu=0.25, kappa=0.6)
print(imp.regime, f"impulse ratio mu_hat = {float(imp.impulse_ratio):.4f}")
# Slip stops before the end of compression, so |mu_hat| < mu.
assert abs(float(imp.impulse_ratio)) < 0.25

fig = plot_routh(imp)
plt.show()
