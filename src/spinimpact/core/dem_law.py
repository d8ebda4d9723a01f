"""The DEM contact force compiled: :mod:`spinimpact.core.dem_force` registered for
``numba.njit`` callers, and the loops of :mod:`spinimpact.core.dem_loop` compiled.

The force's functions are registered with Numba's ``register_jitable`` (as the impact law
of :mod:`spinimpact.core.law`): the same function objects are plain Python when called
from Python and are compiled into a caller's ``numba.njit`` code. Without Numba (the
``[fast]`` extra) the loops run as plain Python, the same arithmetic a thousand times
slower.
"""

from __future__ import annotations

from . import dem_force, dem_loop
from .fused import HAVE_NUMBA, _njit

__all__ = ["HAVE_NUMBA", "wall_impact", "pair_impact"]

if HAVE_NUMBA:  # pragma: no branch - the test extra installs Numba
    from numba.extending import register_jitable

    for _name in ("normal_force", "normal_energy", "tangential_energy", "contact_force",
                  "_band", "_merge", "_cells_step", "_history_slide"):  # fmt: skip
        register_jitable(getattr(dem_force, _name))
    wall_impact = _njit(dem_loop.wall_impact, parallel=False)
    pair_impact = _njit(dem_loop.pair_impact, parallel=False)
else:  # pragma: no cover
    wall_impact = dem_loop.wall_impact
    pair_impact = dem_loop.pair_impact
