"""
Whittaker's simple law can create energy
========================================

The simplest frictional impact law takes the friction impulse as ``-mu`` times the whole
normal impulse, as if the contact slid in one direction throughout. For a particle (no
rotation) the paper's eq. (8.7) gives the change of kinetic energy, which is *positive*
for impacts close enough to the normal: friction would reverse the tangential velocity and
push the particle back harder than it came. :func:`spinimpact.solve_particle` computes it;
``energy_threshold`` is the ratio ``|u|/|v|`` below which energy appears (negative where no
incidence creates energy, as for ``mu = 0.3`` with ``kappa = 0.8`` below). The paper's
worked example states the opposite direction (see the errata page).
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

ratio = np.linspace(0.005, 2.0, 400)  # |u-|/|v-| (> 0: the slip has a direction)
fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
for mu in (0.3, 0.5, 0.8):
    imp = si.solve_particle(vx=ratio, vy=-1.0, mu=mu, kappa=0.8)
    threshold = float(np.ravel(imp.energy_threshold)[0])
    print(f"mu = {mu}: energy created below |u|/|v| = {threshold:.4f}")
    ax.plot(ratio, imp.energy_change, label=f"$\\mu$ = {mu}")
    if threshold > 0:
        ax.axvline(threshold, color="0.6", lw=0.8, ls="--")
ax.axhline(0.0, color="0.3", lw=0.8)
ax.set_xlabel("$|u^-|/|v^-|$")
ax.set_ylabel("$E^+ - E^-$, J (m = 1 kg, $|v^-|$ = 1 m/s)")
ax.legend()
plt.show()
