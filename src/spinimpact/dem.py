"""A DEM contact force: Hertz with Mindlin-Deresiewicz micro-slip and its loading history,
the usual DEM variants beside it, and a small DEM loop (``docs/dem.md``).

Build the law once, keep a state array per contact, and call :func:`contact_force` once
per contact per step, from your own ``numba.njit`` loop or from Python:

>>> from spinimpact import dem
>>> force = dem.ContactForce.sphere_on_wall(youngs_modulus=7.0e10, poisson_ratio=0.33,
...                                         radius=0.1, density=2700.0, mu=0.4)
>>> params, state = force.parameters(), force.new_state()
>>> n, f1, f2 = dem.contact_force(state, params, 1e-6, 0.2, 1e-9, 0.0, 0.0, 0.0)
>>> round(float(n), 3), round(float(f1), 4)
(33.122, -0.0266)
"""

from .core.dem_force import contact_force, normal_energy, normal_force, tangential_energy
from .core.dem_law import HAVE_NUMBA
from .model.dem import (
    DAMPINGS,
    MODELS,
    TRACE_COLUMNS,
    ContactForce,
    DemImpact,
    log_decrement_damping,
    pair_impact,
    viscous_damping,
    wall_impact,
)

__all__ = [
    "HAVE_NUMBA",
    "MODELS",
    "DAMPINGS",
    "TRACE_COLUMNS",
    "ContactForce",
    "DemImpact",
    "contact_force",
    "normal_force",
    "normal_energy",
    "tangential_energy",
    "wall_impact",
    "pair_impact",
    "viscous_damping",
    "log_decrement_damping",
]
