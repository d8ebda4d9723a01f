"""
Where each regime lives
=======================

The regime depends on the incidence only through ``r = |u/vy|``, the contact point's slip
over the normal approach speed: the slip stops during compression when ``r <= zeta mu``,
during restitution when ``zeta mu < r <= (1 + kappa) zeta mu``, and never beyond.
:func:`spinimpact.viz.maps.plot_map` draws the regimes, the rebound outcomes, the energy
lost, the impulse ratio and the work ratio over the incidence plane (``vx/|vy|``,
``R omega/|vy|``); a coarse grid keeps this page quick.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si
from spinimpact.viz.maps import plot_map

ball = si.Body.solid_sphere(mass=1.0, radius=0.1)
mu, kappa = 0.2, 0.8

# The two boundaries, checked on a line of incidences: r = zeta mu and (1 + kappa) zeta mu.
zeta = float(ball.zeta)
r = np.array([0.99, 1.01]) * zeta * mu
print(si.solve(ball, vx=r, vy=-1.0, omega=0.0, mu=mu, kappa=kappa).regime)
r = np.array([0.99, 1.01]) * (1 + kappa) * zeta * mu
print(si.solve(ball, vx=r, vy=-1.0, omega=0.0, mu=mu, kappa=kappa).regime)

fig = plot_map(ball, mu=mu, kappa=kappa, n=80)
plt.show()
