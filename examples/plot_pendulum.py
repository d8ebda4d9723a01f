"""
A pendulum striking the ground
==============================

A rigid pendulum on a fixed frictionless pivot has a collision matrix of rank one: its
contact point's slip and normal velocity vanish together, at the end of compression. If
the friction cone cannot hold it there, the slip reverses for the restitution phase, and
Stronge's energetic coefficient is the geometric mean of Newton's and Poisson's,
``eta**2 = kappa_N kappa_P`` (Lubarda 2010, the pendulum paper). The plot sweeps the
friction coefficient for a rod pendulum at 60 degrees struck with Poisson's ``kappa = 0.8``.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

pendulum = si.Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
mu = np.linspace(0.0, 1.0, 201)
imp = si.solve_pendulum(pendulum, omega=-2.0, mu=mu, kappa=0.8, law="poisson")

reverse = np.char.startswith(np.asarray(imp.regime, dtype=str), "reverse")
gap = imp.energetic_restitution**2 - imp.newton_restitution * imp.poisson_restitution
print("regimes:", sorted(set(np.asarray(imp.regime, dtype=str).tolist())))
print(
    f"largest |eta^2 - kappa_N kappa_P| where the slip reverses: {np.abs(gap[reverse]).max():.1e}"
)

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
ax.plot(mu, imp.newton_restitution, label="Newton's $\\kappa_N$")
ax.plot(mu, imp.poisson_restitution, label="Poisson's $\\kappa_P$")
ax.plot(mu, imp.energetic_restitution, label="energetic $\\eta$")
ax.set_xlabel("friction coefficient $\\mu$")
ax.set_ylabel("coefficient of restitution")
ax.legend()
plt.show()
