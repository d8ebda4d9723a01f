"""
The compiled contact law in your own Numba loop
===============================================

:mod:`spinimpact.contact_law` holds scalar functions (floats in, floats out) that your own
``numba.njit`` code can call, for a time-stepping simulator or a DEM code that wants the
exact impact at each contact. Here a loop of ``numba.njit`` bounces a ball on the ground
ten times and records its rebound velocities, and the same bounces computed by
:func:`spinimpact.solve` agree to rounding. The first bounce leaves the ball rolling
(``vx = -R omega``), so friction does no more work and only the height of the bounces
falls. Arguments of ``rebound``: the incidence ``vx, vy, omega``, then
``mass, radius, zeta, mu, kappa``.
"""

import matplotlib.pyplot as plt
import numpy as np

import spinimpact as si
from spinimpact import contact_law as law

try:
    from numba import njit
except ImportError:  # the loop runs as plain Python without Numba

    def njit(f):
        return f


@njit
def bounces(vx, vy, omega, mass, radius, zeta, mu, kappa, n):
    """Drop the ball ``n`` times: each rebound's upward speed comes back down."""
    out = np.empty((n, 3))
    for i in range(n):
        vx, vy_up, omega, _ = law.rebound(vx, vy, omega, mass, radius, zeta, mu, kappa)
        out[i] = vx, vy_up, omega
        vy = -vy_up  # ballistic flight: the same speed down at the next bounce
    return out


ball = si.Body.solid_sphere(mass=0.06, radius=0.033)
zeta = float(ball.zeta)
path = bounces(4.0, -5.0, 80.0, 0.06, 0.033, zeta, 0.3, 0.8, 10)

# The same bounces through the NumPy API, one after another.
vx, vy, omega = 4.0, -5.0, 80.0
for i in range(10):
    imp = si.solve(ball, vx, vy, omega, mu=0.3, kappa=0.8)
    vx, vy, omega = float(imp.after.vx), -float(imp.after.vy), float(imp.after.omega)
    assert np.allclose(path[i], [vx, -vy, omega], rtol=1e-12, atol=1e-12)
print("Numba loop and solve() agree; Numba available:", law.HAVE_NUMBA)

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
n = np.arange(1, 11)
ax.plot(n, path[:, 0], "o-", label="$v_x$ after, m/s")
ax.plot(n, path[:, 1], "s-", label="$v_y$ after, m/s")
ax.plot(n, path[:, 2] * 0.033, "^-", label="$R\\omega$ after, m/s")
ax.set_xlabel("bounce")
ax.legend()
plt.show()
