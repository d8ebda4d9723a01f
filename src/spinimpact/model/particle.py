"""A material particle under Whittaker's unidirectional-slip model (section 8).

Kept for comparison: it is what a naive impact law does, and it can create
energy (eq. 8.7), which :func:`spinimpact.solve` for a rigid body never does.
The physics is in :mod:`spinimpact.core.particle`, with the references.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import as_real_array, broadcast, check
from .impact import State, _restitution
from .result import Array, Result, plain_repr
from .result import freeze as _out

__all__ = ["ParticleImpact", "solve_particle"]


@dataclass(frozen=True, eq=False)
class ParticleImpact(Result):
    """Result of :func:`solve_particle`: rebound and energy of a material particle.

    Attributes
    ----------
    mass, mu, kappa : float or ndarray
        Mass (kg), friction coefficient and normal restitution used (``kappa``
        evaluated from a restitution model if one was given).
    before, after : State
        Incidence and rebound velocities, m/s (``omega`` is 0: a particle does not spin).
    energy_change : float or ndarray
        ``E^+ - E^-`` in J (eq. 8.7); positive means energy created.
    creates_energy : bool or ndarray of bool
        ``energy_change > 0``.
    energy_threshold : float or ndarray
        The incidence ratio ``|u^-/v^-|`` below which this model creates energy,
        ``[(1+kappa) mu^2 + kappa - 1]/(2 mu)`` (``-inf`` for ``mu = 0``).
    """

    mass: Array
    mu: Array
    kappa: Array
    before: State
    after: State
    energy_change: Array
    creates_energy: Array
    energy_threshold: Array
    __repr__ = plain_repr


def solve_particle(vx: Any, vy: Any, *, mu: Any, kappa: Any, mass: Any = 1.0) -> ParticleImpact:
    r"""Rebound of a material particle assuming slip in one direction throughout.

    Parameters
    ----------
    vx : float or array_like
        Incidence velocity along the surface, m/s (the paper's ``u^-``).
    vy : float or array_like
        Incidence normal velocity, m/s, ``< 0`` (approaching the surface; ``v^-``).
    mu : float or array_like
        Kinetic Coulomb friction coefficient, ``>= 0``.
    kappa : float, array_like or callable
        Coefficient of normal restitution in ``[0, 1]``, or a restitution model (a
        callable of the impact speed ``|vy|``), as for :func:`spinimpact.solve`.
    mass : float or array_like, optional
        Mass ``m``, kg, ``> 0``; default 1.

    Returns
    -------
    ParticleImpact
        Every field with the broadcast shape of all the inputs.

    Raises
    ------
    TypeError
        For an input that is not a real number or array of them.
    ValueError
        For non-finite input, ``vy >= 0``, ``mu < 0``, ``mass <= 0``, ``kappa`` outside
        ``[0, 1]``, or shapes that do not broadcast.

    Notes
    -----
    Whittaker's theory [2]_ takes the friction impulse as ``f_1 = -mu sign(u^-) tau_1``
    with ``tau_1 = -(1 + kappa) m v^-`` (section 8 of [1]_):

    .. math::

        u^+ = u^- - (1+\kappa)\mu\,\mathrm{sign}(u^-)|v^-|, \qquad v^+ = -\kappa v^-,

        E^+ - E^- = \tfrac12 m (v^-)^2 (1+\kappa)
            \left[\kappa - 1 + (1+\kappa)\mu^2 - 2\mu\frac{|u^-|}{|v^-|}\right] \quad (8.7),

    which is positive for impacts close to the normal. The paper's worked example after
    eq. (8.7) states the opposite direction; see ``docs/errata.md``.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    .. [2] E. T. Whittaker, A Treatise on the Analytical Dynamics of Particles and Rigid
       Bodies, Cambridge University Press (1961 ed.).

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
