"""
Validation: oblique impacts measured by Kharaz et al. (2001)
============================================================

Kharaz, Gorham and Salman shot 5 mm aluminium-oxide spheres without spin at a glass anvil
at 3.9 m/s and measured the tangential restitution of the centre, ``e_t = vx+/vx-``, over
the angle of incidence. The points (as digitized for MFiX's DEM05 test) ship with the
repository in ``benchmarks/data/kharaz2001``. The rigid law (``mu = 0.092``,
``kappa = 0.98``) matches them where the ball slides; at small angles real balls grip and
spring back, which the tangential compliance laws reproduce. ``make validation`` prints the
errors of every model.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

try:
    examples = Path(__file__).resolve().parent
except NameError:  # Sphinx-Gallery runs the examples from their own folder
    examples = Path.cwd()
data = examples.parent / "benchmarks" / "data" / "kharaz2001"
measured = np.loadtxt(data / "tangential_restitution.csv", delimiter=",", comments="#", skiprows=3)
angle_deg, e_t = measured[:, 0], measured[:, 1]

radius = 2.5e-3
ball = si.Body.solid_sphere(mass=4000.0 * 4.0 / 3.0 * np.pi * radius**3, radius=radius)
grid = np.linspace(1.0, 85.0, 300)
vx, vy = 3.9 * np.sin(np.radians(grid)), -3.9 * np.cos(np.radians(grid))

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
ax.plot(angle_deg, e_t, "ko", label="measured (Kharaz et al. 2001)")
for label, law in (
    ("rigid", None),
    ("Walton, $\\beta_0$ = 0.33", si.Walton(0.33)),
    ("Stronge, $\\nu$ = 0.23", si.Stronge(poisson_ratio=0.23)),
):
    imp = si.solve(ball, vx, vy, 0.0, mu=0.092, kappa=0.98, tangential=law)
    model = imp.after.vx / vx
    at = np.interp(angle_deg, grid, model)
    print(f"{label:26} median |error| in e_t: {np.median(np.abs(at - e_t)):.3f}")
    ax.plot(grid, model, label=label)
ax.set_xlabel("angle of incidence from the normal, deg")
ax.set_ylabel("$e_t = v_x^+/v_x^-$")
ax.legend()
plt.show()
