"""
Micro-slip: Mindlin and Deresiewicz inside one impact
=====================================================

Under Hertz contact the traction near the rim of the contact area reaches the friction
limit first: an annulus slips while the centre sticks (Mindlin and Deresiewicz).
:class:`spinimpact.MindlinDeresiewicz` follows that loading history through the impact (by
the method of dimensionality reduction, with a row of springs), and
:func:`spinimpact.viz.micro_slip.plot_micro_slip` shows the tangential force and the slipping
fraction of the contact for a few incidences of the Kharaz et al. (2001) sphere. A coarse
discretization (``springs=64``, ``steps=512``) keeps the page quick.
"""

import matplotlib.pyplot as plt

import spinimpact as si
from spinimpact.viz.micro_slip import plot_micro_slip

law = si.MindlinDeresiewicz(poisson_ratio=0.23, springs=64, steps=512)
ball = si.Body.solid_sphere(mass=2.6e-4, radius=2.5e-3)
fig = plot_micro_slip(law, ball, [0.14, 0.27, 0.68, 1.33], -3.7, 0.0, mu=0.092, kappa=0.98)
plt.show()
