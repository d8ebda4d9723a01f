"""
A sweep over random incidences
==============================

:func:`spinimpact.io.sweep.run_sweep` solves a grid or random samples of any inputs in
chunks of bounded memory, counting the regimes and folding a histogram on the fly (what
``spinimpact sweep`` runs). 200,000 incidences of a solid sphere without spin, ``vx``
uniform between 0 and 3 m/s at ``vy = -1`` m/s: the regime depends on ``r = vx/|vy|``
only, so its fractions are known in advance, ``zeta mu / 3`` for sticking in compression and
``kappa zeta mu / 3`` in restitution; the sampled fractions agree with them within two
standard errors.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si
from spinimpact.io.sweep import Sweep, parse_axis, run_sweep

mu, kappa = 0.2, 0.8
ball = si.Body.solid_sphere(mass=1.0, radius=0.1)
axes = {
    name: parse_axis(name, text)
    for name, text in dict(
        vx="uniform:0:3", vy="-1", omega="0", mu=str(mu), kappa=str(kappa)
    ).items()
}
sweep = Sweep(ball, axes, samples=200_000, seed=1)
result = run_sweep(sweep, histogram=("energy_loss", 0.15, 0.4, 50))

zeta = float(ball.zeta)
expected = {"stick-compression": zeta * mu / 3, "stick-restitution": kappa * zeta * mu / 3}
expected["slip"] = 1 - sum(expected.values())
fractions = result.regime_counts / result.points
for name, fraction in zip(result.regimes, fractions, strict=True):
    if result.regime_counts[result.regimes.index(name)]:
        error = np.sqrt(fraction * (1 - fraction) / result.points)  # one standard error
        print(f"{name:18} sampled {fraction:.4f} +- {error:.4f}, exact {expected[name]:.4f}")

inside = result.histogram.sum() / result.points
print(f"{inside:.4f} of the impacts lose 15 to 40 % of their energy")

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
centres = 0.5 * (result.bin_edges[1:] + result.bin_edges[:-1])
ax.bar(centres, result.histogram / result.points, width=np.diff(result.bin_edges), color="C0")
ax.set_xlabel("fraction of kinetic energy lost")
ax.set_ylabel("fraction of the impacts")
plt.show()
