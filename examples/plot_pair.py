"""
Two balls colliding: the 90-degree rule
=======================================

A cue ball strikes an object ball of the same mass, off-centre. With no friction between
the balls and a perfectly elastic impact, the two leave at right angles; restitution below
one closes the angle, and friction between the balls (which here also passes spin) changes
it again. :func:`spinimpact.solve_pair` gives ``angle_between_paths`` for each cut.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

ball = si.Body.solid_sphere(mass=0.17, radius=0.028575)  # pool balls, kg and m
cut = np.radians(
    np.linspace(5.0, 80.0, 76)
)  # angle between the cue ball's path and the line of centres
normal = np.stack([-np.cos(cut), 0.0 * cut, np.sin(cut)], axis=-1)  # from ball 2 to ball 1

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
for mu, kappa in ((0.0, 1.0), (0.0, 0.9), (0.06, 0.9)):
    imp = si.solve_pair(
        ball,
        ball,
        velocity1=[2.0, 0.0, 0.0],
        spin1=[0.0, 0.0, 0.0],
        velocity2=[0.0, 0.0, 0.0],
        spin2=[0.0, 0.0, 0.0],
        mu=mu,
        kappa=kappa,
        normal=normal,
    )
    angle = np.degrees(imp.angle_between_paths)
    print(f"mu {mu}, kappa {kappa}: {angle.min():.2f} to {angle.max():.2f} deg")
    ax.plot(np.degrees(cut), angle, label=f"$\\mu$ = {mu}, $\\kappa$ = {kappa}")
ax.set_xlabel("cut angle, deg")
ax.set_ylabel("angle between the paths, deg")
ax.legend()
plt.show()
