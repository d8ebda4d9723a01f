"""
A die landing on a corner: the slip turns
=========================================

A die strikes the table on one corner, its diagonal tilted 30 degrees from the vertical.
Its collision matrix couples the two directions along the table with the normal, so the
contact point's slip does not keep its direction: friction pulls it round as the impulse
grows. :func:`spinimpact.rigid_history` follows one impact over the normal impulse. The
panels draw the slip's hodograph for eight directions of the same sliding speed (a curve
while the direction turns, a straight run while it keeps), at two friction coefficients:
where the slip stops, the corner sticks if the friction cone can hold it (``mu = 0.5``,
a cross), and otherwise slides again along the one direction the collision matrix allows
(``mu = 0.35``, a triangle where it stopped). The right panel is the corner's normal
velocity at ``mu = 0.5``. :func:`spinimpact.solve_rigid` solves any number of such
impacts at once.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

corner = -np.ones(3) / np.sqrt(3)  # the touching corner's direction, in the die's frame
tilt = np.radians(30.0)
down = np.array([np.sin(tilt), -np.cos(tilt), 0.0])  # where it points in the world
axis = np.cross(corner, down)
angle = np.arccos(corner @ down)
quaternion = np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * axis / np.linalg.norm(axis)])
die = si.RigidBody.cuboid(mass=0.0045, size=[0.016, 0.016, 0.016], orientation=quaternion)

fig, axes = plt.subplots(1, 3, figsize=(10.5, 3.7), layout="constrained")
for panel, mu in zip(axes[:2], (0.5, 0.35), strict=True):
    for heading in np.radians(np.arange(0, 360, 45)):
        velocity = [0.6 * np.cos(heading), -1.5, 0.6 * np.sin(heading)]  # m/s
        h = si.rigid_history(die, velocity, [0.0, 0.0, 0.0], mu=mu, kappa=0.5)
        (line,) = panel.plot(h.slip[:, 0], h.slip[:, 1], lw=1.2)
        panel.plot(*h.slip[0], "o", color=line.get_color(), ms=4)
        if h.sequence == "slide-stick":
            panel.plot(0, 0, "x", color="k", ms=8)
        elif h.sequence == "slide-reslide":
            panel.plot(0, 0, "^", color="k", ms=6)
        if mu == 0.5:
            axes[2].plot(1e3 * h.normal_impulse, h.normal_velocity, color=line.get_color())
        print(f"mu {mu}, heading {np.degrees(heading):5.1f} deg: {h.sequence:13s} "
              f"normal impulse {1e3 * h.final_impulse:.3f} mN s")  # fmt: skip
    panel.set_aspect("equal")
    panel.set_xlabel("slip along $t_1$, m/s")
    panel.set_ylabel("slip along $t_2$, m/s")
    panel.set_title(f"$\\mu$ = {mu}: slip hodographs")
axes[2].axhline(0.0, color="0.6", lw=0.8)
axes[2].set_xlabel("normal impulse, mN s")
axes[2].set_ylabel("normal velocity of the corner, m/s")
axes[2].set_title("$\\mu$ = 0.5: normal velocity")
plt.show()
