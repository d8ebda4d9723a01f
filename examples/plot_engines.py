"""
Physics engines beside the exact bounce
=======================================

:mod:`spinimpact.engines` sets up PyBullet and MuJoCo (the ``[engines]`` extra) to bounce
exactly the impact :func:`spinimpact.solve` solves, and measures each engine's error over
the incidence speed scale. A handful of bounces of a solid sphere over the angle of
incidence, in three of the set-ups ``make bench`` compares over 1,152 cases (see the
performance page for those figures): PyBullet at its defaults, PyBullet with its contact
margin, position correction and restitution threshold switched off, and MuJoCo's best
calibrated set-up. Errors below 1e-16 (exact to rounding) are drawn at 1e-16.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si
from spinimpact.engines import CONFIGURATIONS, available, bounce

ball = si.Body.solid_sphere(mass=1.0, radius=0.1)
angle = np.radians(np.linspace(10.0, 80.0, 8))
vx, vy = 3.0 * np.sin(angle), -3.0 * np.cos(angle)
chosen = [CONFIGURATIONS[i] for i in (0, 2, 5)]

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
for label, engine, settings in chosen:
    if not available(engine):
        print(f"{label}: not installed")
        continue
    errors = [
        bounce(engine, ball, a, b, 0.0, mu=0.3, kappa=0.8, **settings).error
        for a, b in zip(vx, vy, strict=True)
    ]
    print(f"{label}: median error {np.median(errors):.1%}, largest {np.max(errors):.1%}")
    ax.semilogy(np.degrees(angle), np.maximum(errors, 1e-16), "o-", label=label)
ax.set_xlabel("angle of incidence from the normal, deg")
ax.set_ylabel("error / speed scale")
ax.legend(fontsize="small")
plt.show()
