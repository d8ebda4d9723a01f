"""bounce(): one batch of impacts in an engine, beside :func:`spinimpact.solve`.

:func:`bounce` validates the impacts, hands them flat to the engine module's
``run`` (:mod:`spinimpact.engines.pybullet`, :mod:`spinimpact.engines.mujoco`,
:mod:`spinimpact.engines.drake`),
solves the same impacts exactly and packs both into an
:class:`~spinimpact.engines.EngineRun`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._validation import as_real_array, broadcast, check, validated
from ..model.body import Body
from ..model.impact import solve
from . import drake, mujoco, pybullet
from .common import EngineRun, check_engine, one_body, shaped

__all__ = ["bounce"]

#: Each engine's ``run(body, vx, vy, omega, mu, kappa, phase, **settings)``.
_RUNNERS = {"pybullet": pybullet.run, "mujoco": mujoco.run, "drake": drake.run}


def bounce(
    engine: str,
    body: Body,
    vx: Any,
    vy: Any,
    omega: Any,
    *,
    mu: Any,
    kappa: Any,
    phase: Any = 0.5,
    **settings: Any,
) -> EngineRun:
    """Bounce ``body`` off the plane in a physics engine and compare with :func:`~spinimpact.solve`.

    Parameters
    ----------
    engine : {"pybullet", "mujoco", "drake"}
        The engine (from the ``[engines]`` extra).
    body : Body
        The body, with scalar mass (kg), radius (m) and gyration (m); the engine
        sees a sphere of its radius with isotropic inertia ``mass * gyration**2``.
    vx, vy : float or array_like
        Incidence velocity of the centre, m/s, ``vy < 0``, as in :func:`~spinimpact.solve`.
    omega : float or array_like
        Incidence spin, rad/s, counter-clockwise positive.
    mu : float or array_like
        Coulomb friction coefficient, ``>= 0``.
    kappa : float or array_like
        Coefficient of restitution in ``[0, 1]``, set as the engine defines it
        (see the engine's notes below).
    phase : float or array_like
        Where within a time step the body reaches the surface, in ``[0, 1)``:
        it starts ``(2 + phase)`` time steps of free flight above the plane.
    **settings
        Engine options, below.

    Returns
    -------
    EngineRun
        The engine's rebounds, the exact :class:`~spinimpact.Impact`, the errors
        and the wall time of the stepping, of the broadcast shape of the inputs.

    Raises
    ------
    TypeError
        If ``engine`` is not a string, ``body`` not a :class:`~spinimpact.Body`,
        an input not a real number or array of them, or a setting of the wrong
        type.
    ValueError
        For an unknown engine or setting, inputs or settings outside their
        ranges, a body of many sizes, or inputs that hold no impact.
    ImportError
        If the engine is not installed (``pip install 'spinimpact[engines]'``).

    Notes
    -----
    **PyBullet** settings: ``hz`` (240, its default step rate, Hz),
    ``solver_iterations`` (50), and the contact parameters
    ``contact_breaking_threshold`` (m), ``contact_erp``,
    ``restitution_velocity_threshold`` (m/s) and ``contact_slop`` (m), by
    default the values PyBullet starts with (:data:`PYBULLET_DEFAULTS`). Bullet
    keeps some of them for the whole process, so every run sets them all. The
    sphere's restitution is ``kappa`` and its lateral friction ``mu`` against a
    plane with both equal to 1 (Bullet multiplies the two bodies' values, and
    caps friction at 10, so ``mu <= 10``); rolling and spinning friction,
    velocity damping and Bullet's velocity clamp (100 m/s and rad/s by default)
    are removed. Bullet's restitution is Newton's velocity ratio, which for a
    body whose contact normal passes through its centre is Poisson's ``kappa``;
    with ``contact_breaking_threshold=0, contact_erp=0,
    restitution_velocity_threshold=0`` its one-step impulse solve gave the exact
    rigid-body answer in every bounce measured in which the sphere sank at least
    ``contact_slop`` (1e-5 m) in its first contact step,
    ``|vy| (1 - phase) / hz >= 1e-5``; in most that sank less, ``vy+`` fell
    short of ``kappa |vy|`` by ``(1e-5 - depth) * hz`` m/s, and friction with
    it. With ``contact_slop=0`` too, every rebound measured was exact, at phases
    up to 0.99999 (``docs/performance.md``). Velocities are read 50 ms after
    contact (:mod:`spinimpact.engines.pybullet`).

    **MuJoCo** has no coefficient of restitution or hard Coulomb friction: its
    contacts are soft constraints. ``contact="calibrated"`` (the default) gives
    each sphere a contact pair with friction ``mu`` (``condim=3``) and a linear
    spring-damper normal law (``solref`` as ``(-stiffness, -damping)``, flat
    ``solimp`` 0.99). Its stiffness sets the head-on contact duration
    ``contact_time`` (s), by default ``0.01 pi R / max|vy|`` so the sphere sinks
    about 1 % of its radius (the estimate is ``settings["penetration"]``); its
    damping is calibrated, by secant iterations on head-on bounces at the
    contact phase 0.5, so that the head-on restitution is ``kappa`` to 1e-5 at
    any speed (other phases shift it by up to a few 1e-3); ``kappa`` must lie in
    about [0.01, 0.99]. Friction is a velocity-damping target with time constant
    ``friction_time * contact_time`` (``solreffriction``, default 0.6, which needs
    the elliptic cone); with ``friction_time=None`` it follows the normal
    ``solref`` under MuJoCo's default pyramidal cone, which leaves much of the
    slip unresolved. ``timestep`` (s) defaults to ``contact_time / 100``; Newton
    solver, 100 iterations, tolerance 1e-10, ``implicitfast`` integrator.
    ``contact="default"`` is MuJoCo's own contact with only the friction set
    (``timestep=0.002``): its restitution is fixed by the default ``solref``
    whatever ``kappa`` is. Steps run until every sphere has left the surface.
    The spin is read from the free joint's body-frame angular velocity rotated
    to the world frame (:mod:`spinimpact.engines.mujoco`).

    All impacts of a call share one scene (one world, bodies far apart), which
    is how an engine is run at scale; setting up the scene is a Python loop
    over the impacts through the engine's API, and is not timed.

    References
    ----------
    .. [1] E. Coumans and Y. Bai, "PyBullet, a Python module for physics
       simulation for games, robotics and machine learning", http://pybullet.org,
       2016-2021.
    .. [2] E. Todorov, T. Erez and Y. Tassa, "MuJoCo: A physics engine for
       model-based control", 2012 IEEE/RSJ International Conference on
       Intelligent Robots and Systems (IROS), Vilamoura, 2012, pp. 5026-5033,
       doi:10.1109/IROS.2012.6386109.
    """
    check_engine(engine)
    body = one_body(body, "an engine run takes one body size")
    arrays = {
        "vx": validated("vx", vx),
        "vy": validated("vy", vy),
        "omega": validated("omega", omega),
        "mu": validated("mu", mu),
        "kappa": validated("kappa", kappa),
        "phase": as_real_array("phase", phase),
    }
    check("phase", arrays["phase"], lambda p: (p >= 0) & (p < 1), "in [0, 1)")
    shaped_in = dict(zip(arrays, broadcast(**arrays), strict=True))
    shape = shaped_in["vx"].shape
    if shaped_in["vx"].size == 0:
        raise ValueError(f"the inputs hold no impact (broadcast shape {shape})")
    flat = {k: np.ravel(v) for k, v in shaped_in.items()}
    out = _RUNNERS[engine](body, **flat, **settings)
    exact = solve(
        body,
        shaped_in["vx"],
        shaped_in["vy"],
        shaped_in["omega"],
        mu=shaped_in["mu"],
        kappa=shaped_in["kappa"],
    )
    return EngineRun(
        engine=engine,
        settings=out.settings,
        vx=shaped(out.vx, shape),
        vy=shaped(out.vy, shape),
        omega=shaped(out.omega, shape),
        exact=exact,
        phase=shaped(shaped_in["phase"], shape),
        steps=out.steps,
        seconds=out.seconds,
        batch_size=flat["vx"].size,
    )
