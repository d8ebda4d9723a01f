"""
Tangential compliance: the contact point can spring back
========================================================

The rigid law ends a sticking impact with the contact point at rest. Real contacts are
elastic in shear, so the contact point can leave with its slip reversed. The tangential
restitution of the contact point, ``beta = -c_t+/c_t-``, says by how much: 0 for the rigid
law; Walton's ``beta_0`` for :class:`spinimpact.Walton` while the contact would stick;
for :class:`spinimpact.Stronge`, the end of a tangential spring's oscillation while it
sticks, which can leave the slip reversed (``beta > 0``) or not yet stopped (``beta < 0``).
All agree when the contact slides throughout (a large slip for its approach speed). Shown
for the 5 mm aluminium-oxide sphere of Kharaz et al. (2001) at 3.9 m/s, with the
literature's ``mu = 0.092``, ``kappa = 0.98`` and Poisson's ratio 0.23.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

radius = 2.5e-3
ball = si.Body.solid_sphere(mass=4000.0 * 4.0 / 3.0 * np.pi * radius**3, radius=radius)
angle = np.radians(np.linspace(1.0, 80.0, 200))  # from the normal
vx, vy = 3.9 * np.sin(angle), -3.9 * np.cos(angle)
laws = {
    "rigid": None,
    "Walton, $\\beta_0$ = 0.33": si.Walton(0.33),
    "Stronge, $\\nu$ = 0.23": si.Stronge(poisson_ratio=0.23),
}

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
for label, law in laws.items():
    imp = si.solve(ball, vx, vy, 0.0, mu=0.092, kappa=0.98, tangential=law)
    beta = -imp.slip_after / imp.slip_before
    print(f"{label:28} beta at 5 deg: {np.interp(np.radians(5), angle, beta):+.3f}")
    ax.plot(np.degrees(angle), beta, label=label)
ax.set_xlabel("angle of incidence from the normal, deg")
ax.set_ylabel("tangential restitution $\\beta$")
ax.legend()
plt.show()
