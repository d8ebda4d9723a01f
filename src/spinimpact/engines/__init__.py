"""The same bounce in general-purpose physics engines, beside the exact answer.

Robotics, game and DEM developers usually bounce balls in a general engine. This
package sets up PyBullet [1]_, MuJoCo [2]_ and Drake [3]_ (the ``[engines]`` extra,
``pip install 'spinimpact[engines]'``) to bounce exactly the impact that
:func:`spinimpact.solve` solves, so the engine's error can be measured case by
case:

>>> from spinimpact import Body
>>> from spinimpact.engines import bounce
>>> ball = Body.solid_sphere(mass=1.0, radius=0.1)
>>> run = bounce("pybullet", ball, vx=3.0, vy=-1.0, omega=0.0, mu=0.1, kappa=0.5)
>>> print(f"vy+ {run.vy:.3f} m/s, exact {run.exact.after.vy:.3f}; error {run.error:.0%}")
vy+ -0.002 m/s, exact 0.500; error 17%
>>> run = bounce("mujoco", ball, vx=3.0, vy=-1.0, omega=0.0, mu=0.1, kappa=0.5)
>>> print(f"vy+ {run.vy:.3f} m/s, exact {run.exact.after.vy:.3f}; error {run.error:.0%}")
vy+ 0.574 m/s, exact 0.500; error 2%

At its default settings PyBullet lost this bounce altogether (the error is
over the incidence speed scale, here ``|vx| = 3`` m/s); with its contact margin,
position correction and restitution threshold set to 0 it gives the exact
answer at this contact phase (0.5, the default), though not for every phase
late in a time step unless its ``contact_slop`` is 0 too, and a calibrated
MuJoCo contact comes within a few percent (see ``docs/performance.md`` for many
impacts):

>>> exact = dict(contact_breaking_threshold=0, contact_erp=0, restitution_velocity_threshold=0)
>>> run = bounce("pybullet", ball, vx=3.0, vy=-1.0, omega=0.0, mu=0.1, kappa=0.5, **exact)
>>> print(f"vy+ {run.vy:.3f} m/s, exact {run.exact.after.vy:.3f}")
vy+ 0.500 m/s, exact 0.500
>>> bool(run.error < 1e-12)
True

The engines see the body as a sphere of the body's radius with the isotropic
inertia ``mass * gyration**2`` (so a disk or a shell bounces with its own
``zeta``), gravity is switched off so that only the impact acts, and friction
and restitution are set to the Coulomb ``mu`` and the ``kappa`` of the exact
solution as each engine defines them. Paper axes map to the engines' z-up axes
as x -> x, y -> z, and the spin ``omega`` (counter-clockwise, about the paper's
z = x cross y) is the angular velocity ``(0, -omega, 0)``.

Time-stepping engines resolve an impact at the steps, so their answer depends
on where, within a time step, the body reaches the surface: the ``phase`` in
[0, 1) of that instant. :func:`standard_cases` samples it uniformly.

The physics stays in :mod:`spinimpact.core`: this package only drives the
engines and compares their output with :func:`spinimpact.solve`. Its modules:
:mod:`~spinimpact.engines.compare` (:func:`bounce`),
:mod:`~spinimpact.engines.common` (:class:`EngineRun`, :func:`standard_cases`,
:data:`CONFIGURATIONS`, the scene and the axes), and one module per engine,
:mod:`~spinimpact.engines.pybullet`, :mod:`~spinimpact.engines.mujoco` and
:mod:`~spinimpact.engines.drake`; and the
impact hooks, which make one body's impacts on a plane exact inside the engine's own
time loop: :mod:`~spinimpact.engines.hook` (:class:`HookStep`, :class:`HookImpact`),
:class:`MujocoHook` and :class:`PybulletHook` (``docs/engine_hook.md``); and the engines'
own contact settings, measured against the exact answer (``docs/engines.md``):
:mod:`~spinimpact.engines.calibration` (:func:`calibrate`: settings searched for the
closest rebounds), :mod:`~spinimpact.engines.restitution` (:func:`restitution_settings`,
:func:`restitution_curve`: the setting for a head-on restitution) and
:mod:`~spinimpact.engines.configure` (settings as MJCF or PyBullet calls).

References
----------
.. [1] E. Coumans and Y. Bai, "PyBullet, a Python module for physics simulation
   for games, robotics and machine learning", http://pybullet.org, 2016-2021.
.. [2] E. Todorov, T. Erez and Y. Tassa, "MuJoCo: A physics engine for
   model-based control", 2012 IEEE/RSJ International Conference on Intelligent
   Robots and Systems (IROS), Vilamoura, 2012, pp. 5026-5033,
   doi:10.1109/IROS.2012.6386109.
.. [3] R. Tedrake and the Drake Development Team, "Drake: Model-based design and
   verification for robotics", 2019, https://drake.mit.edu.
"""

from __future__ import annotations

from .calibration import Calibration, calibrate, calibration_cases
from .common import CONFIGURATIONS, ENGINES, EngineRun, available, standard_cases
from .compare import bounce
from .configure import MUJOCO_SETTINGS, PYBULLET_SETTINGS
from .hook import HookImpact, HookStep
from .hook_mujoco import MujocoHook
from .hook_pybullet import PybulletHook
from .pybullet import PYBULLET_DEFAULTS
from .restitution import RestitutionCurve, restitution_curve, restitution_settings

#: Modules the docstring examples need (tests/test_docs.py skips them without).
__doctest_requires__ = ("pybullet", "mujoco")

__all__ = [
    "CONFIGURATIONS",
    "PYBULLET_DEFAULTS",
    "ENGINES",
    "EngineRun",
    "HookImpact",
    "HookStep",
    "MujocoHook",
    "PybulletHook",
    "available",
    "bounce",
    "Calibration",
    "calibrate",
    "calibration_cases",
    "MUJOCO_SETTINGS",
    "PYBULLET_SETTINGS",
    "RestitutionCurve",
    "restitution_curve",
    "restitution_settings",
    "standard_cases",
]
