"""A fixed-step explicit DEM integration of a sphere striking a flat wall, the kind of step a
DEM code such as MFiX takes, to measure what its time step and its contact geometry change.

This package integrates an impact with events located to integrator precision
(:func:`spinimpact.dynamics.simulate`); a DEM code steps the same force laws with a fixed
step and takes the contact geometry its own way. :func:`explicit_impacts` does that here,
written from the scheme's definition, so that the difference between MFiX's published
curves and this package's model can be split into its parts (``benchmarks.dem_reference``):

* **the step**: second-order Adams-Bashforth for the velocities and the spin, the
  trapezoidal rule for the positions, a fixed step ``dt`` (the first step is Euler's);
  contact exists at a step when the overlap ``delta = R - y`` is positive there;
* **the tangential spring**: the displacement ``xi`` accumulates ``dt u`` at each step of
  contact, the force is ``F = -k_t(delta) xi`` (the "total" rule of
  :mod:`spinimpact.core.tangential`), and where ``|F| > mu N`` the force is ``mu N`` and
  ``xi`` is reset to ``mu N / k_t(delta)`` (the spring holds the cap force);
* **the lever arm**: ``lever="wall"`` takes the centre's distance to the wall, ``R - delta``,
  as the arm of the friction torque and in the contact point's velocity
  ``u = vx + (R - delta) omega`` (MFiX's convention); ``lever="radius"`` takes ``R``
  (this package's).

Normal force ``N = k_n delta^n`` and tangential stiffness ``k_t(delta) = k_t delta^(n-1)``
(``n = 1``: linear springs; ``n = 3/2``: Hertz with Mindlin's stiffness ``8 G* sqrt(R delta)``
when ``k_t = 8 G* sqrt(R)``); no damping (restitution 1) and no gravity.
"""

from __future__ import annotations

import numpy as np


def explicit_impacts(angles_deg, *, speed, mass, radius, inertia, mu, normal_stiffness,
                     tangential_stiffness, exponent, dt, lever="wall", offset=0.5,
                     max_steps=2_000_000):  # fmt: skip
    """Rebound of a sphere striking a wall at ``speed`` (m/s) and ``angles_deg`` from the
    normal, without spin, integrated with the fixed explicit step ``dt`` (s).

    Parameters
    ----------
    angles_deg : array_like
        Incidence angles, degrees (one run each, stepped together).
    speed, mass, radius, inertia, mu : float
        m/s, kg, m, kg m^2, Coulomb friction.
    normal_stiffness, tangential_stiffness : float
        ``k_n`` (N/m^n) and ``k_t`` (N/m^n) of ``N = k_n delta^n``,
        ``F = -k_t delta^(n-1) xi``.
    exponent : float
        ``n``: 1 or 1.5.
    dt : float
        The step, s.
    lever : {"wall", "radius"}
        The friction's lever arm and the contact point's radius: ``R - delta`` or ``R``.
    offset : float
        In ``(0, 1]``: how far into the wall, in steps of travel, the first step that sees
        the contact finds the sphere (where the touch falls within a step).

    Returns
    -------
    vx, vy, omega : ndarray
        The rebound (m/s, m/s, rad/s; ``omega`` counter-clockwise, ``u = vx + R omega``).
    """
    if lever not in ("wall", "radius"):
        raise ValueError(f"lever must be 'wall' or 'radius', got {lever!r}")
    a = np.radians(np.asarray(angles_deg, dtype=float))
    vx, vy = speed * np.sin(a), -speed * np.cos(a)
    omega = np.zeros_like(a)
    y = radius + (1.0 - offset) * dt * np.abs(vy)  # the first contact step overlaps offset
    xi = np.zeros_like(a)
    acc_old = None
    for _ in range(max_steps):
        delta = radius - y
        touch = delta > 0.0
        d = np.where(touch, delta, 0.0)
        k_t = tangential_stiffness * d ** (exponent - 1.0)
        big_n = normal_stiffness * d**exponent
        arm = radius - d if lever == "wall" else np.full_like(d, radius)
        xi = np.where(touch, xi + dt * (vx + arm * omega), 0.0)
        force = -k_t * xi
        cap = mu * big_n
        slide = touch & (np.abs(force) > cap)
        force = np.where(slide, -cap * np.sign(xi), force)
        xi = np.where(slide, cap / np.where(k_t > 0.0, k_t, 1.0) * np.sign(xi), xi)
        acc = (force / mass, big_n / mass, arm * force / inertia)
        if acc_old is None:
            acc_old = acc  # Adams-Bashforth starts with Euler's step
        new = [v + 0.5 * (3.0 * f - f0) * dt
               for v, f, f0 in zip((vx, vy, omega), acc, acc_old, strict=True)]  # fmt: skip
        y = y + 0.5 * (vy + new[1]) * dt
        vx, vy, omega = new
        acc_old = acc
        if np.all((y > radius) & (vy > 0.0)):
            return vx, vy, omega
    raise RuntimeError(f"the impacts did not end within {max_steps} steps of {dt:g} s")
