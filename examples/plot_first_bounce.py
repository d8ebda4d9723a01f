"""
A ball bouncing with topspin
============================

A solid sphere of 1 kg and 0.1 m hits the ground at 3 m/s down and 2 m/s forward, with
several rates of topspin; the rebound's forward speed and spin depend on whether the
contact slips through the impact or sticks.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

ball = si.Body.solid_sphere(mass=1.0, radius=0.1)
omega = np.linspace(-60.0, 60.0, 241)  # rad/s, counter-clockwise positive
imp = si.solve(ball, 2.0, -3.0, omega, mu=0.3, kappa=0.8)

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
ax.plot(omega, imp.after.vx, label="forward speed after (m/s)")
ax.plot(omega, imp.after.omega / 10, label="spin after / 10 (rad/s)")
ax.set_xlabel("spin before, rad/s")
ax.legend()
plt.show()
