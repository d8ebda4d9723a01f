"""The bounce in PyBullet (the ``[engines]`` extra): one world of spheres on a plane.

PyBullet [1]_, the Python interface of the Bullet physics library, resolves
contacts by sequential impulses once per time step: restitution as Newton's
velocity ratio, friction as a hard Coulomb constraint that may stick. For a
sphere, whose contact normal passes through its centre, Newton's ratio is
Poisson's ``kappa`` (Stronge [3]_, ch. 4), so with nothing else acting the
one-step solve is the exact rigid-body answer of Keller's method [4]_. Four of
Bullet's contact parameters add something else ([2]_, ``setPhysicsEngineParameter``):

* ``contactBreakingThreshold``, a margin within which contacts are created
  before the bodies touch (0.02 m by default): the impulse may be applied a
  step early, at a gap;
* ``contactERP``, the error reduction that pushes a penetrating body out over
  the next steps (0.08): it adds normal velocity after the impact;
* ``restitutionVelocityThreshold``, below which restitution is switched off
  (0.2 m/s);
* ``contactSlop``, a depth (1e-5 m) that a penetration must exceed before the
  contact counts as closed: where the sphere has sunk less than this in its
  first contact step, Bullet (in most cases measured) treats the remaining
  ``slop - depth`` as a gap still to close and lowers the restitution target
  by it over the time step.

:func:`run` sets all four on every run, by default to the values a fresh
process starts with (:data:`PYBULLET_DEFAULTS`), because Bullet keeps some of
them for the whole process. With the first three set to 0 a rebound agreed with
:func:`spinimpact.solve` to rounding in every case measured in which the sphere
sank at least the slop in its first contact step
(``|vy| (1 - phase) / hz >= 1e-5`` m); in most that sank less, ``vy+`` fell
short of ``kappa |vy|`` by ``(1e-5 - depth) * hz``, and friction with it.
With ``contact_slop=0`` as well, every rebound measured agreed to rounding, at
phases up to 0.99999 (``tests/engines/test_pybullet_phases.py``,
``docs/performance.md``).

References
----------
.. [1] E. Coumans and Y. Bai, "PyBullet, a Python module for physics simulation
   for games, robotics and machine learning", http://pybullet.org, 2016-2021.
.. [2] E. Coumans and Y. Bai, "PyBullet Quickstart Guide",
   https://docs.google.com/document/d/10sXEhzFRSnvFcl3XxNGhnD4N2SedqwdAvK3dsihxVUA
   (``setPhysicsEngineParameter``, ``changeDynamics``, ``resetBaseVelocity``).
.. [3] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.
.. [4] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53
   (1986) 1-4.
"""

from __future__ import annotations

import math
import time
from typing import Any

import numpy as np

from .._validation import require, setting
from ..model.body import Body
from .common import (
    LEAD_STEPS,
    Stepped,
    from_engine,
    no_more,
    spacing,
    start_heights,
    to_engine,
    whole_number,
)

__all__ = ["PYBULLET_DEFAULTS", "run"]

#: PyBullet 3.2.7's contact parameters in a fresh process, in :func:`run`'s names
#: (breaking threshold and slop in m, restitution threshold in m/s). Setting these values
#: explicitly reproduces a fresh process's results bit for bit. Some are global to
#: the process in Bullet, so every run sets them all.
PYBULLET_DEFAULTS = {
    "contact_breaking_threshold": 0.02,
    "contact_erp": 0.08,
    "restitution_velocity_threshold": 0.2,
    "contact_slop": 1e-5,
}

#: Time after the first contact at which the rebound is read, s.
_SETTLE = 0.05
#: Bullet caps the combined friction coefficient of a contact at this value.
_MAX_FRICTION = 10.0


def run(
    body: Body,
    vx: np.ndarray,
    vy: np.ndarray,
    omega: np.ndarray,
    mu: np.ndarray,
    kappa: np.ndarray,
    phase: np.ndarray,
    **settings: Any,
) -> Stepped:
    """Bounce one sphere per impact in one PyBullet world and read the rebounds.

    Parameters
    ----------
    body : Body
        The body, with scalar mass (kg), radius (m) and gyration (m).
    vx, vy, omega : ndarray
        Flat incidence velocities (m/s, ``vy < 0``) and spins (rad/s), in the
        paper's axes, already validated.
    mu, kappa : ndarray
        Flat Coulomb friction coefficients (``<= 10`` here) and coefficients of
        restitution.
    phase : ndarray
        Flat contact phases in ``[0, 1)``.
    **settings
        ``hz`` (step rate, Hz, default 240), ``solver_iterations`` (default 50)
        and the keys of :data:`PYBULLET_DEFAULTS` (finite, ``>= 0``).

    Returns
    -------
    Stepped
        The rebounds (flat), the steps taken, the wall time of the stepping (s)
        and every setting used.

    Raises
    ------
    TypeError
        For a setting of the wrong type.
    ValueError
        For an unknown setting, a setting out of range, or ``mu > 10``.
    ImportError
        If PyBullet is not installed.

    Notes
    -----
    The sphere's restitution is ``kappa`` and its lateral friction ``mu``
    against a plane with both equal to 1 (Bullet multiplies the two bodies'
    values). Rolling and spinning friction, velocity damping and Bullet's
    velocity clamp (100 m/s and rad/s by default) are removed; the inertia is
    the isotropic ``mass * gyration**2``. Each sphere starts
    ``LEAD_STEPS + phase`` steps of free flight above the plane, with gravity
    off; the velocities are read :data:`_SETTLE` s after contact, once Bullet's
    penetration recovery is over.
    """
    hz = setting("hz", settings.pop("hz", 240.0), low=0.0, rule="a finite rate > 0 (Hz)")
    iterations = whole_number("solver_iterations", settings.pop("solver_iterations", 50))
    contact = {
        name: setting(
            name, settings.pop(name, default), low=0.0, closed=True, rule="a finite number >= 0"
        )
        for name, default in PYBULLET_DEFAULTS.items()
    }
    no_more("pybullet", settings)
    if np.any(mu > _MAX_FRICTION):
        raise ValueError(
            f"mu must be <= 10 for PyBullet (Bullet caps the combined friction at 10), "
            f"got {float(mu[mu > _MAX_FRICTION][0])!r}"
        )
    pb = require("pybullet", "engines.bounce('pybullet', ...)")
    dt = 1.0 / hz
    mass, radius, inertia = float(body.mass), float(body.radius), float(body.inertia)
    linear, angular = to_engine(vx, vy, omega)
    client = pb.connect(pb.DIRECT)
    try:
        kw = {"physicsClientId": client}
        pb.setGravity(0, 0, 0, **kw)
        pb.setTimeStep(dt, **kw)
        pb.setPhysicsEngineParameter(
            numSolverIterations=iterations,
            contactBreakingThreshold=contact["contact_breaking_threshold"],
            contactERP=contact["contact_erp"],
            restitutionVelocityThreshold=contact["restitution_velocity_threshold"],
            contactSlop=contact["contact_slop"],
            **kw,
        )
        plane = pb.createMultiBody(0, pb.createCollisionShape(pb.GEOM_PLANE, **kw), **kw)
        pb.changeDynamics(plane, -1, restitution=1.0, lateralFriction=1.0, **kw)
        sphere = pb.createCollisionShape(pb.GEOM_SPHERE, radius=radius, **kw)
        height = start_heights(radius, vy, phase, dt)
        apart = spacing(radius)
        ids = []
        for i in range(vx.size):  # the engine's API creates bodies one by one
            b = pb.createMultiBody(mass, sphere, basePosition=[0.0, apart * i, height[i]], **kw)
            pb.changeDynamics(
                b,
                -1,
                restitution=float(kappa[i]),
                lateralFriction=float(mu[i]),
                rollingFriction=0.0,
                spinningFriction=0.0,
                linearDamping=0.0,
                angularDamping=0.0,
                maxJointVelocity=1e30,  # lift Bullet's default clamp of 100 m/s and rad/s
                localInertiaDiagonal=[inertia] * 3,
                **kw,
            )
            pb.resetBaseVelocity(b, linear[i].tolist(), angular[i].tolist(), **kw)
            ids.append(b)
        # Contact starts in step LEAD_STEPS + 1; the velocities are read
        # _SETTLE seconds later, once Bullet's penetration recovery is over.
        steps = LEAD_STEPS + 1 + math.ceil(_SETTLE * hz)
        start = time.perf_counter()
        for _ in range(steps):
            pb.stepSimulation(**kw)
        seconds = time.perf_counter() - start
        state = np.array([pb.getBaseVelocity(b, **kw) for b in ids]).reshape(-1, 2, 3)
    finally:
        pb.disconnect(client)
    used = {"hz": hz, "solver_iterations": iterations, **contact}
    return Stepped(*from_engine(state[:, 0], state[:, 1]), steps, seconds, used)
