"""
A die landing on a corner: the slip turns
=========================================

A die strikes the table on one corner, its diagonal tilted 30 degrees from the vertical.
Its collision matrix couples the two directions along the table with the normal, so the
contact point's slip does not keep its direction: friction pulls it round as the impulse
grows. :func:`spinimpact.rigid_history` follows one impact over the normal impulse; the
left panel draws the slip's hodograph for eight directions of the same sliding speed (a
curve while the direction turns, a straight run while it keeps; the cross marks where the
slip stops and the corner sticks), the right one the corner's normal velocity.
:func:`spinimpact.solve_rigid` solves any number of such impacts at once.
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

fig, (hodo, normal) = plt.subplots(1, 2, figsize=(7.6, 3.8), layout="constrained")
for heading in np.radians(np.arange(0, 360, 45)):
    velocity = [0.6 * np.cos(heading), -1.5, 0.6 * np.sin(heading)]  # m/s
    h = si.rigid_history(die, velocity, [0.0, 0.0, 0.0], mu=0.5, kappa=0.5)
    (line,) = hodo.plot(h.slip[:, 0], h.slip[:, 1], lw=1.2)
    hodo.plot(*h.slip[0], "o", color=line.get_color(), ms=4)
    if np.isfinite(h.stop_impulse):
        hodo.plot(0, 0, "x", color="k", ms=8)
    normal.plot(1e3 * h.normal_impulse, h.normal_velocity, color=line.get_color(), lw=1.2)
    print(
        f"heading {np.degrees(heading):5.1f} deg: {h.sequence:12s} "
        f"normal impulse {1e3 * h.final_impulse:.3f} mN s"
    )
hodo.set_aspect("equal")
hodo.set_xlabel("slip along $t_1$, m/s")
hodo.set_ylabel("slip along $t_2$, m/s")
hodo.set_title("slip hodograph (dot: start, x: stick)")
normal.axhline(0.0, color="0.6", lw=0.8)
normal.set_xlabel("normal impulse, mN s")
normal.set_ylabel("normal velocity of the corner, m/s")
plt.show()
