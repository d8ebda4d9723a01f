"""
A rod's impact in Routh's diagram
=================================

For a body touching off the normal through its centre of mass, Routh's diagram shows the
contact point's slip and normal velocity as straight lines in the plane of the tangential
and normal impulses; the path of the impulse follows the friction cone's edge while the
contact slips, and turns along the sticking line when it stops.
:func:`spinimpact.viz.planar.plot_routh_planar` draws it for a uniform rod at 45 degrees
(as ``spinimpact planar --body rod --orientation-deg 45 --mu 0.3 --kappa 0.8 --plot``).
"""

import math

import matplotlib.pyplot as plt

import spinimpact as si
from spinimpact.viz.planar import plot_routh_planar

rod = si.PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(45))
imp = si.solve_planar(rod, vx=0.5, vy=-1.0, omega=0.0, mu=0.3, kappa=0.8)
print(
    imp.regime,
    f"Newton {float(imp.newton_restitution):.4f}, "
    f"Poisson {float(imp.poisson_restitution):.4f}, "
    f"energetic {float(imp.energetic_restitution):.4f}",
)

fig = plot_routh_planar(imp)
plt.show()
