"""Whittaker's unidirectional-slip model for a material particle (end of section 8).

A particle has no rotational inertia, so the impulse equations
``m u^- + f_1 = m u^+`` and ``m v^- + tau_1 = m v^+`` leave the problem
indeterminate. Assuming the slip keeps its direction throughout,
``f_1 = -mu sign(u^-) tau_1`` with ``tau_1 = -(1+kappa) m v^-`` gives
``u^+ = u^- - (1+kappa) mu sign(u^-) |v^-|`` (the paper writes it for ``u^- > 0``:
``u^+ = u^- + (1+kappa) mu v^-``). This can *create* energy (eq. 8.7); the rigid
body of this package, with its stick-slip transition, never does.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays, result

__all__ = [
    "ParticleRebound",
    "particle_rebound",
    "particle_energy_change",
    "particle_energy_threshold",
]


class ParticleRebound(NamedTuple):
    """Rebound velocity of a particle, m/s."""

    vx: Any
    vy: Any


def particle_rebound(vx, vy, mu, kappa):
    """Rebound ``(vx+, vy+)`` of a particle under Whittaker's model.

    ``vx+ = vx - (1+kappa) mu sign(vx) |vy|`` and ``vy+ = -kappa vy``. Where
    ``vx = 0`` the slip direction is undefined and no friction acts.
    """
    xp, (vx, vy) = arrays(vx, vy)
    return ParticleRebound(vx - (1.0 + kappa) * mu * xp.sign(vx) * xp.abs(vy), -kappa * vy)


def particle_energy_change(vx, vy, mass, mu, kappa):
    """Energy change ``E^+ - E^-`` of the particle model (eq. 8.7).

    .. math::

        E^+ - E^- = \\tfrac12 m (v^-)^2 (1+\\kappa)
            \\left[\\kappa - 1 + (1+\\kappa)\\mu^2 - 2\\mu\\frac{|u^-|}{|v^-|}\\right]

    (``u^- = vx``; for ``vx = 0`` the friction term vanishes, as in
    :func:`particle_rebound`). Positive values are energy created from nothing.
    """
    xp, (vx, vy) = arrays(vx, vy)
    friction = xp.where(vx != 0, (1.0 + kappa) * mu * mu - 2.0 * mu * xp.abs(vx / vy), 0.0)
    return 0.5 * mass * vy * vy * (1.0 + kappa) * (kappa - 1.0 + friction)


def particle_energy_threshold(mu, kappa):
    """Incidence ratio ``|u^-|/|v^-|`` below which the particle model creates energy.

    ``[(1+kappa) mu^2 + kappa - 1] / (2 mu)`` (the sentence after eq. 8.7): the
    energy *increases* when ``|u^-/v^-|`` is *smaller* than this, i.e. for impacts
    close to the normal. The paper's worked example (``mu = 0.5``,
    ``kappa = 0.8``: threshold 0.25, about 14 degrees) states the opposite
    direction ("if ``u^-/|v^-| > 0.25``"); see ``docs/errata.md``.
    ``-inf`` where ``mu = 0`` (no friction, no energy created).
    """
    xp, (mu, kappa) = arrays(mu, kappa)
    safe = xp.where(mu > 0, mu, 1.0)
    value = ((1.0 + kappa) * mu * mu + kappa - 1.0) / (2.0 * safe)
    return result(xp, xp.where(mu > 0, value, -xp.inf))
