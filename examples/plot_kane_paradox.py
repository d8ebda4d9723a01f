"""
Kane's paradox: Newton's law can create energy
==============================================

A rod falling on a rough floor touches it away from the normal through its centre of
mass, so the tangential and normal impulses couple. With Newton's restitution (the normal
*velocity* reverses to ``-kappa`` times its value) and a perfectly elastic ``kappa = 1``, the
rod can leave with more kinetic energy than it came with: Kane's paradox. Poisson's law
(the normal *impulse* of restitution is ``kappa`` times that of compression) and Stronge's
energetic law (the normal *work*) never gain energy. :func:`spinimpact.solve_planar` solves all
three; the plot sweeps the rod's angle.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

angles = np.radians(np.linspace(5.0, 85.0, 161))
rod = si.PlanarBody.rod(mass=1.0, length=1.0, angle=angles)

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
for law in ("newton", "poisson", "energetic"):
    imp = si.solve_planar(rod, vx=0.5, vy=-1.0, omega=0.0, mu=1.0, kappa=1.0, law=law)
    gain = imp.kinetic_energy_after - imp.kinetic_energy_before
    print(
        f"{law:9}: largest change {gain.max():+.4f} J, creates energy in "
        f"{int(np.sum(imp.creates_energy))} of {gain.size} angles"
    )
    ax.plot(np.degrees(angles), gain, label=law)
ax.axhline(0.0, color="0.5", lw=0.8)
ax.set_xlabel("rod's angle to the floor, deg")
ax.set_ylabel("$E^+ - E^-$, J")
ax.legend()
plt.show()
