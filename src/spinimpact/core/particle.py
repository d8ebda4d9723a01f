"""Whittaker's unidirectional-slip model for a material particle (end of section 8).

A particle has no rotational inertia, so the impulse equations
``m u^- + f_1 = m u^+`` and ``m v^- + tau_1 = m v^+`` leave the problem
indeterminate. Assuming, with Whittaker [2]_, that the slip keeps its direction
throughout, ``f_1 = -mu sign(u^-) tau_1`` with ``tau_1 = -(1+kappa) m v^-`` gives
``u^+ = u^- - (1+kappa) mu sign(u^-) |v^-|`` (the paper [1]_ writes it for ``u^- > 0``:
``u^+ = u^- + (1+kappa) mu v^-``). This can *create* energy (eq. 8.7); the rigid
body of this package, with its stick-slip transition, never does. Keller [3]_ traced
the paradox to the assumption: the slip may stop, or reverse, during the impact.
Equation numbers are those of [1]_; all quantities are in SI units.

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a
   fixed surface", Proceedings of the Section of Natural Sciences, Montenegrin
   Academy of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
.. [2] E. T. Whittaker, A Treatise on the Analytical Dynamics of Particles and Rigid
   Bodies, Cambridge University Press (1961 ed.).
.. [3] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays, quiet, result

__all__ = [
    "ParticleRebound",
    "particle_rebound",
    "particle_energy_change",
    "particle_energy_threshold",
]


class ParticleRebound(NamedTuple):
    """Rebound velocity ``(vx^+, vy^+)`` of a particle, m/s."""

    vx: Any
    vy: Any


def particle_rebound(vx, vy, mu, kappa):
    r"""Rebound ``(vx^+, vy^+)`` of a particle under Whittaker's unidirectional-slip model.

    Parameters
    ----------
    vx, vy : float or array
        Incidence velocity, m/s, ``vy < 0``: the paper's ``u^-`` and ``v^-``.
    mu, kappa : float or array
        Kinetic Coulomb friction coefficient and coefficient of normal restitution.

    Returns
    -------
    ParticleRebound
        ``(vx, vy)``: the rebound velocity ``(u^+, v^+)``, m/s.

    Notes
    -----
    With ``f_1 = -mu sign(u^-) tau_1`` [2]_ and ``tau_1 = -(1+kappa) m v^-`` (section 8
    of [1]_):

    .. math:: u^+ = u^- - (1+\kappa)\,\mu\,\mathrm{sign}(u^-)\,|v^-|, \qquad
        v^+ = -\kappa v^- .

    Where ``vx = 0`` the slip direction is undefined and no friction acts. The friction
    may overturn ``u``, which a slip of constant direction cannot do: the model holds
    only while ``|u^-| >= (1+kappa) mu |v^-|`` (Keller [3]_).

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    .. [2] E. T. Whittaker, A Treatise on the Analytical Dynamics of Particles and Rigid
       Bodies, Cambridge University Press (1961 ed.).
    .. [3] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.

    Examples
    --------
    >>> vx, vy = particle_rebound(vx=1.0, vy=-1.0, mu=0.5, kappa=0.8)
    >>> round(float(vx), 12), round(float(vy), 12)
    (0.1, 0.8)
    """
    xp, (vx, vy) = arrays(vx, vy)
    return ParticleRebound(vx - (1.0 + kappa) * mu * xp.sign(vx) * xp.abs(vy), -kappa * vy)


def particle_energy_change(vx, vy, mass, mu, kappa):
    r"""Energy change ``E^+ - E^-`` of a particle under Whittaker's model (eq. 8.7).

    Parameters
    ----------
    vx, vy : float or array
        Incidence velocity, m/s, ``vy < 0``: the paper's ``u^-`` and ``v^-``.
    mass : float or array
        Mass ``m``, kg.
    mu, kappa : float or array
        Kinetic Coulomb friction coefficient and coefficient of normal restitution.

    Returns
    -------
    change : float or array
        ``E^+ - E^-``, J. Positive values are energy created from nothing.

    Notes
    -----
    .. math::

        E^+ - E^- = \tfrac12 m (v^-)^2 (1+\kappa)
            \left[\kappa - 1 + (1+\kappa)\mu^2 - 2\mu\frac{|u^-|}{|v^-|}\right]

    Eq. (8.7) of [1]_, written with ``|u^-|`` for either direction of slip (the paper
    takes ``u^- > 0``); for ``vx = 0`` the friction term vanishes, as in
    :func:`particle_rebound`.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    The numbers of ``docs/errata.md`` (``m = 1`` kg, ``v^- = -1`` m/s, ``mu = 0.5``,
    ``kappa = 0.8``): a near-normal impact at 5.7 degrees gains energy, one at 45 degrees
    loses it.

    >>> round(float(particle_energy_change(0.1, -1.0, 1.0, mu=0.5, kappa=0.8)), 12)
    0.135
    >>> round(float(particle_energy_change(1.0, -1.0, 1.0, mu=0.5, kappa=0.8)), 12)
    -0.675
    """
    xp, (vx, vy) = arrays(vx, vy)
    friction = xp.where(vx != 0, (1.0 + kappa) * mu * mu - 2.0 * mu * xp.abs(vx / vy), 0.0)
    return 0.5 * mass * vy * vy * (1.0 + kappa) * (kappa - 1.0 + friction)


def particle_energy_threshold(mu, kappa):
    r"""Incidence ratio ``|u^-/v^-|`` below which the particle model creates energy.

    Parameters
    ----------
    mu, kappa : float or array
        Kinetic Coulomb friction coefficient and coefficient of normal restitution.

    Returns
    -------
    ratio : float or array
        Dimensionless: the tangent of the incidence angle from the normal. ``-inf`` where
        ``mu = 0`` (no friction, no energy created), and where the value lies below the
        float range (``kappa < 1`` with ``mu`` below about ``(1 - kappa) 1e-308``).

    Notes
    -----
    Eq. (8.7) is positive exactly when

    .. math:: \frac{|u^-|}{|v^-|} < \frac{(1+\kappa)\mu^2 + \kappa - 1}{2\mu}

    (the sentence after eq. 8.7 of [1]_): the energy *increases* for impacts close to
    the normal. The paper's worked example (``mu = 0.5``, ``kappa = 0.8``: threshold
    0.25, about 14 degrees) states the opposite direction ("if ``u^-/|v^-| > 0.25``");
    see ``docs/errata.md``.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    >>> import math
    >>> t = float(particle_energy_threshold(mu=0.5, kappa=0.8))
    >>> round(t, 12), round(math.degrees(math.atan(t)), 2)
    (0.25, 14.04)
    """
    xp, (mu, kappa) = arrays(mu, kappa)
    safe = xp.where(mu > 0, mu, 1.0)
    with quiet(xp, over="ignore"):  # below the float range (mu < ~1e-308): -inf, as at mu = 0
        value = ((1.0 + kappa) * mu * mu + kappa - 1.0) / (2.0 * safe)
    return result(xp, xp.where(mu > 0, value, -xp.inf))
