"""
A tennis ball with topspin and side spin on a hard court
========================================================

In three dimensions the contact point's slip keeps its direction through the impact
(the sphere's collision matrix is isotropic in the tangent plane), so the paper's closed
forms hold along it; the spin about the normal never changes. The ball and court come
from the presets :data:`spinimpact.BALLS` and :data:`spinimpact.GROUNDS`; axes: ``x`` along
the court, ``y`` up, ``z = x × y``. :func:`spinimpact.viz.sphere.plot_sphere` draws the
side and top views.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si
from spinimpact.viz.sphere import plot_sphere

ball, court = si.BALLS["tennis"], si.GROUNDS["hard"]
imp = si.solve_sphere(
    ball, velocity=[20.0, -8.0, 3.0], spin=[0.0, 150.0, -200.0], mu=court.mu, kappa=court.kappa
)
print(f"{imp.regime}, grips: {bool(imp.grips)}")
print(f"{float(imp.rebound_speed):.2f} m/s at {np.degrees(float(imp.rebound_angle)):.1f} deg")
print(f"topspin {float(imp.topspin):.1f} rad/s, side spin {float(imp.sidespin):.1f} rad/s")
# The spin about the normal (y) is the same before and after.
assert np.isclose(float(imp.after.wy), 150.0)

fig = plot_sphere(imp)
plt.show()
