"""A material particle under Whittaker's unidirectional-slip model (section 8).

Kept for comparison: it is what a naive impact law does, and it can create
energy (eq. 8.7), which :func:`spinimpact.solve` for a rigid body never does.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import as_real_array, broadcast, check
from .impact import State, _restitution
from .result import Array, Result
from .result import freeze as _out

__all__ = ["ParticleImpact", "solve_particle"]


@dataclass(frozen=True, eq=False)
class ParticleImpact(Result):
    """Result of :func:`solve_particle`.

    Attributes
    ----------
    before, after : State
        Incidence and rebound (``omega`` is 0: a particle does not spin).
    energy_change : ``E^+ - E^-`` in J (eq. 8.7); positive means energy created.
    creates_energy : bool, ``energy_change > 0``.
    energy_threshold : the incidence ratio ``|u^-/v^-|`` below which this model
        creates energy, ``[(1+kappa) mu^2 + kappa - 1]/(2 mu)``.
    """

    mass: Array
    mu: Array
    kappa: Array
    before: State
    after: State
    energy_change: Array
    creates_energy: Array
    energy_threshold: Array


def solve_particle(vx: Any, vy: Any, *, mu: Any, kappa: Any, mass: Any = 1.0) -> ParticleImpact:
    """Rebound of a material particle assuming slip in one direction throughout.

    Parameters are as for :func:`spinimpact.solve` (``mass`` in kg, default 1).

    Examples
    --------
    >>> p = solve_particle(vx=0.1, vy=-1.0, mu=0.5, kappa=0.8)
    >>> bool(p.creates_energy), round(float(p.energy_threshold), 12)
    (True, 0.25)
    """
    vx_, vy_, mu_, m = (
        as_real_array(n, v) for n, v in (("vx", vx), ("vy", vy), ("mu", mu), ("mass", mass))
    )
    check("vy", vy_, lambda v: v < 0, "< 0 (the particle must approach the surface)")
    check("mu", mu_, lambda x: x >= 0, ">= 0")
    check("mass", m, lambda x: x > 0, "> 0")
    kappa_ = _restitution(kappa, vy_)
    vx_, vy_, mu_, kappa_, m = broadcast(vx=vx_, vy=vy_, mu=mu_, kappa=kappa_, mass=m)
    vx1, vy1 = core.particle_rebound(vx_, vy_, mu_, kappa_)
    change = core.particle_energy_change(vx_, vy_, m, mu_, kappa_)
    zero = np.zeros_like(vx_)
    return ParticleImpact(
        mass=_out(m),
        mu=_out(mu_),
        kappa=_out(kappa_),
        before=State(_out(vx_), _out(vy_), _out(zero)),
        after=State(_out(vx1), _out(vy1), _out(zero)),
        energy_change=_out(change),
        creates_energy=_out(change > 0),
        energy_threshold=_out(core.particle_energy_threshold(mu_, kappa_)),
    )
