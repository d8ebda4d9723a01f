"""
A table-tennis ball: topspin, no spin, backspin
===============================================

A table-tennis ball (2.7 g, 20 mm radius, a thin shell) lands on the table at 8 m/s, 20
degrees below the horizontal, with spin from 150 rev/s of backspin to 150 rev/s of topspin.
Without spin the contact point slides forward through the whole impact, and friction slows
the ball; backspin only adds to that slip, and as long as the contact slides throughout the
friction impulse is ``mu`` times the normal impulse whatever the spin, so the rebound is
the same. Topspin reduces the forward slip, then reverses it: friction pushes the ball
forward and it leaves faster and lower. :func:`spinimpact.solve_sphere` with the
``table-tennis`` ball and the ``table`` ground presets; topspin is a negative spin about
``z`` (``x`` forward, ``y`` up).
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

ball, table = si.BALLS["table-tennis"], si.GROUNDS["table"]
angle = np.radians(20.0)
rev_s = np.linspace(-150.0, 150.0, 121)  # positive: topspin
spin = np.stack([0 * rev_s, 0 * rev_s, -2 * np.pi * rev_s], axis=-1)
imp = si.solve_sphere(
    ball,
    velocity=[8.0 * np.cos(angle), -8.0 * np.sin(angle), 0.0],
    spin=spin,
    mu=table.mu,
    kappa=table.kappa,
)
out_angle = np.degrees(imp.rebound_angle)
for s in (-150.0, 0.0, 150.0):
    i = int(np.argmin(abs(rev_s - s)))
    print(
        f"{s:+6.0f} rev/s: {imp.regime[i]:18} leaves at {float(imp.rebound_speed[i]):.2f} m/s, "
        f"{float(out_angle[i]):.1f} deg above the table"
    )

fig, (a, b) = plt.subplots(1, 2, figsize=(7.5, 3.4), layout="constrained")
a.plot(rev_s, imp.rebound_speed)
a.set_xlabel("topspin before, rev/s")
a.set_ylabel("speed after, m/s")
b.plot(rev_s, out_angle)
b.set_xlabel("topspin before, rev/s")
b.set_ylabel("angle after, deg above the table")
plt.show()
