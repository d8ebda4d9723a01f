"""
Restitution that depends on the impact speed
============================================

Real balls bounce less the harder they hit.
:meth:`spinimpact.TabulatedRestitution.from_drop_heights` turns drop tests (release and
rebound heights) into a table of ``kappa`` over the impact speed, interpolated between the
drops and clipped outside them; it can be passed as ``kappa`` wherever a number is
accepted. The drop heights here are illustrative numbers, not measurements: the ball is
dropped from 0.5 to 3 m and comes back up to heights from which
``kappa = sqrt(h_after/h_before)`` falls with speed.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si

drops = [0.5, 1.0, 2.0, 3.0]  # m, release heights
rebounds = [0.40, 0.75, 1.40, 1.95]  # m, illustrative
model = si.TabulatedRestitution.from_drop_heights(drops, rebounds)

ball = si.Body.solid_sphere(mass=0.06, radius=0.033)
speed = np.linspace(1.0, 9.0, 200)
imp = si.solve(ball, vx=0.0 * speed, vy=-speed, omega=0.0, mu=0.3, kappa=model)
kappa = imp.after.vy / speed
for h, r in zip(drops, rebounds, strict=True):
    v = np.sqrt(2 * 9.80665 * h)
    print(
        f"drop {h} m: impact at {v:.2f} m/s, kappa {np.sqrt(r / h):.4f}, "
        f"model {float(np.interp(v, speed, kappa)):.4f}"
    )

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
ax.plot(speed, kappa, label="kappa of the model")
ax.plot(
    np.sqrt(2 * 9.80665 * np.array(drops)),
    np.sqrt(np.array(rebounds) / drops),
    "ko",
    label="drop tests",
)
ax.set_xlabel("impact speed, m/s")
ax.set_ylabel("$\\kappa$")
ax.legend()
plt.show()
