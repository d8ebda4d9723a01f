"""
Fitting friction and restitution, with intervals
================================================

Twelve bounces of a solid sphere are generated with known values, ``mu = 0.25`` and
``kappa = 0.8``, and measured with seeded noise (0.02 m/s on the speeds, 2 rad/s on the
spin). :func:`spinimpact.fit` finds the values back with profile-likelihood intervals, says
which bounces slid (they carry the information on ``mu``) and which stuck, and
:func:`spinimpact.viz.fit.plot_fit` draws the fit against the data.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si
from spinimpact.viz.fit import plot_fit

rng = np.random.default_rng(7)
ball = si.Body.solid_sphere(mass=0.06, radius=0.033)
angle = np.radians(np.linspace(10.0, 70.0, 12))  # from the normal
vx, vy, omega = 6.0 * np.sin(angle), -6.0 * np.cos(angle), np.zeros(12)
truth = si.solve(ball, vx, vy, omega, mu=0.25, kappa=0.8)
data = si.MeasuredBounces(
    vx,
    vy,
    omega,
    after_vx=truth.after.vx + rng.normal(0.0, 0.02, 12),
    after_vy=truth.after.vy + rng.normal(0.0, 0.02, 12),
    after_omega=truth.after.omega + rng.normal(0.0, 2.0, 12),
    sigma_after_vx=0.02,
    sigma_after_vy=0.02,
    sigma_after_omega=2.0,
)
res = si.fit(data, ball)
for name, value, low, high in zip(
    res.names, res.estimate, res.interval_low, res.interval_high, strict=True
):
    print(f"{name}: {value:.4f}  (95% interval {low:.4f} to {high:.4f})")
print(f"{res.n_sliding} bounces slid, {res.n_sticking} stuck; reduced chi2 {res.reduced_chi2:.2f}")

fig = plot_fit(res)
plt.show()
