"""
The paper's figures, recomputed
===============================

Lubarda (2010) illustrates the impact of a solid disk (``zeta = 3``) at ``mu = 0.25`` and
``kappa = 0.6`` by three kinds of figure: the velocities over the normal impulse ``tau``
(Fig. 2 and 3), Routh's diagram of the friction impulse against the normal impulse
(Fig. 4) and the kinetic energy over ``tau`` (Fig. 5). :func:`spinimpact.viz.plots.paper_figure`
recomputes each one from :func:`spinimpact.solve`; here is Fig. 2, a disk whose contact
point slips during compression and sticks during restitution.
"""

import matplotlib.pyplot as plt

from spinimpact.viz.plots import PAPER_FIGURES, paper_figure

print("figures:", ", ".join(PAPER_FIGURES))
fig = paper_figure("fig2")
plt.show()
