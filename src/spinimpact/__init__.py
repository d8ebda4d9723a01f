"""spinimpact: exact frictional impact of a spinning rigid body on a rough surface.

The theory is V. A. Lubarda (2010), "On the frictional impact of a spinning
disk against a fixed surface", solved with Keller's method: the normal impulse
``tau`` replaces time and every velocity is piecewise linear in it.

>>> from spinimpact import Body, solve
>>> imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), vx=3.0, vy=-4.0, omega=10.0,
...             mu=0.2, kappa=0.8)
>>> str(imp.regime)
'stick-restitution'

Layers: :mod:`spinimpact.core` (pure vectorized kernels) <- the model
(:class:`Body`, :func:`solve`, :class:`Impact`) <- :mod:`spinimpact.cli`.
"""

from importlib import metadata as _metadata

from . import _limits  # noqa: F401  (first: bounds the thread pools under ulimit -v)
from .model import flight_problem as _flight_problem  # noqa: F401  (and the ball's flight)
from .model import problems as _problems  # noqa: F401  (declares the built-in problems)
from .model import rigid_problem as _rigid_problem  # noqa: F401  (and any rigid body in 3D)
from .model.body import Body
from .model.compliance import (
    CompliantImpact,
    CompliantSphereImpact,
    MindlinDeresiewicz,
    Stronge,
    TangentialLaw,
    Walton,
)
from .model.fit import FitResult, FitWarning, fit
from .model.fit_data import MeasuredBounces
from .model.fit_drops import fit_drops
from .model.fit_problem import ProblemFit, fit_problem
from .model.flight import flight, launch
from .model.flight_result import Flight
from .model.impact import History, Impact, Outcome, State, solve
from .model.pair import PairImpact, solve_pair
from .model.particle import ParticleImpact, solve_particle
from .model.planar import (
    PendulumImpact,
    PlanarHistory,
    PlanarImpact,
    solve_pendulum,
    solve_planar,
)
from .model.planar_body import Pendulum, PlanarBody
from .model.presets import BALLS, GROUNDS, Ball, Ground, Wall
from .model.registry import Input, Problem, detect, problem, problems, register, unregister
from .model.restitution import ConstantRestitution, RestitutionModel, TabulatedRestitution
from .model.rigid import (
    RigidBody,
    RigidHistory,
    RigidImpact,
    rigid_history,
    solve_contact,
    solve_rigid,
)
from .model.sphere3d import SphereImpact, State3, Surface, Vector, solve_sphere

try:  # one source of the version: the package's metadata, from pyproject.toml
    __version__ = _metadata.version("spinimpact")
except _metadata.PackageNotFoundError:  # pragma: no cover - run from a source tree uninstalled
    __version__ = "0+unknown"

__all__ = [
    "Input",
    "Problem",
    "detect",
    "problem",
    "problems",
    "register",
    "unregister",
    "fit",
    "fit_drops",
    "fit_problem",
    "ProblemFit",
    "MeasuredBounces",
    "FitResult",
    "FitWarning",
    "flight",
    "launch",
    "Flight",
    "Ball",
    "Ground",
    "Wall",
    "BALLS",
    "GROUNDS",
    "solve_pair",
    "PairImpact",
    "solve_sphere",
    "Vector",
    "Surface",
    "State3",
    "SphereImpact",
    "Body",
    "CompliantImpact",
    "CompliantSphereImpact",
    "MindlinDeresiewicz",
    "Stronge",
    "TangentialLaw",
    "Walton",
    "ConstantRestitution",
    "History",
    "Impact",
    "Outcome",
    "ParticleImpact",
    "Pendulum",
    "PendulumImpact",
    "PlanarBody",
    "PlanarHistory",
    "PlanarImpact",
    "RestitutionModel",
    "State",
    "TabulatedRestitution",
    "solve",
    "solve_particle",
    "solve_pendulum",
    "solve_planar",
    "RigidBody",
    "RigidImpact",
    "RigidHistory",
    "rigid_history",
    "solve_contact",
    "solve_rigid",
]
