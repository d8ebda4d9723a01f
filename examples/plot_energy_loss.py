"""
Energy lost over the angle of incidence
=======================================

A ball without spin hits the ground at 5 m/s, at angles from straight down to grazing. For
a sphere on a plane the normal and tangential impulses do not couple, so restitution takes
``1 - kappa**2`` of the *normal* kinetic energy whatever the angle; the rest of the loss
is friction's work. That share is zero straight down (no slip) and near grazing (almost no
normal impulse), and peaks in between, in the regime where the contact slips throughout
(dashed: the angle beyond which it does, ``tan(theta) = (1 + kappa) zeta mu``).
A solid sphere (``zeta = 7/2``) and a thin spherical shell (``zeta = 5/2``) of the same mass
and radius are compared.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

angle = np.radians(np.linspace(0.0, 89.0, 500))  # from the normal
speed, mu, kappa, mass = 5.0, 0.3, 0.7, 0.1
vx, vy = speed * np.sin(angle), -speed * np.cos(angle)
bodies = [
    si.Body.solid_sphere(mass=mass, radius=0.03),
    si.Body.spherical_shell(mass=mass, radius=0.03),
]

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
for body, color in zip(bodies, ("C0", "C1"), strict=True):
    imp = si.solve(body, vx, vy, 0.0, mu=mu, kappa=kappa)
    normal = (1 - kappa**2) * 0.5 * mass * vy**2  # restitution's share, J
    friction = (imp.dissipated_energy - normal) / imp.kinetic_energy_before
    boundary = np.degrees(np.arctan((1 + kappa) * float(body.zeta) * mu))
    peak = np.degrees(angle[np.argmax(friction)])
    print(
        f"{body.name}: friction takes at most {friction.max():.3f} of the energy, at "
        f"{peak:.1f} deg; slip lasts throughout beyond {boundary:.1f} deg"
    )
    ax.plot(np.degrees(angle), friction, color=color, label=f"{body.name}, friction's share")
    ax.axvline(boundary, color=color, ls="--", lw=0.8)
ax.plot(
    np.degrees(angle),
    normal / imp.kinetic_energy_before,
    color="0.4",
    label="restitution's share (both)",
)
ax.set_xlabel("angle of incidence from the normal, deg")
ax.set_ylabel("fraction of kinetic energy lost")
ax.legend()
plt.show()
