r"""Impulse-space tangential compliance: the tangential restitution of the contact point.

The rigid law of :mod:`spinimpact.core.impulse` ends a sticking impact with the contact
point at rest (``c_t^+ = 0``). Real contacts are elastic in shear: the contact point can
leave with its slip reversed. Both laws here say how by the *tangential restitution of the
contact point*

.. math:: \beta = -c_t^+/c_t^- ,

on the seam of :mod:`spinimpact.core.impulse` (contact-point slip ``c_t``, normal velocity
``c_n < 0``, ``mass = 1/W_nn``, ``zeta = W_tt/W_nn``, ``W_tn = 0``): the friction impulse
is then ``f_1 = (c_t^+ - c_t^-)/W_tt = -(1 + beta) m c_t^-/zeta`` and the normal problem is
the rigid one (``c_n^+ = -kappa c_n^-``). The same kernels serve the paper's disk and
sphere and the 3D sphere, whose slip keeps its direction
(:mod:`spinimpact.core.sphere3d`).

Sliding throughout. With Coulomb friction over the whole normal impulse
``tau_1 = (1 + kappa) m |c_n^-|``, ``c_t^+ = c_t^- - sign(c_t^-) zeta mu (1 + kappa)|c_n^-|``:

.. math:: \beta_{slide} = -1 + (1 + \kappa)\,\zeta\mu\,|c_n^-|/|c_t^-| ,

which is ``>= 0`` exactly when the rigid law sticks (``tau_* <= tau_1``, eq. 4.6 of
Lubarda [1]_). For two spheres Walton [2]_ writes ``zeta = 1 + 1/K`` with
``K = 4 J/(m sigma^2)`` (``sigma`` the diameter; ``K = 2/5``, ``zeta = 7/2`` for solid
spheres): the same number.

Walton's model ([2]_; measured by Foerster et al. [3]_): ``beta = min(beta_0, beta_slide)``
with ``beta_0 in [-1, 1]`` the tangential restitution of sticking impacts.
``beta_0 = 0`` is the rigid law; ``beta_0 = -1`` removes friction.

Stronge's lumped-parameter model [4]_ (``beta`` from the time history of a normal and a
tangential spring at the contact) is :func:`stronge_restitution`.

Maw, Barber and Fawcett's normalized angles [5]_ [6]_ are :func:`maw_angles`.

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed surface",
   Proceedings of the Section of Natural Sciences, Montenegrin Academy of Sciences and Arts
   (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
.. [2] O. R. Walton, "Numerical simulation of inclined chute flows of monodisperse,
   inelastic, frictional spheres", Mechanics of Materials 16 (1993) 239-247.
.. [3] S. F. Foerster, M. Y. Louge, H. Chang and K. Allia, "Measurements of the collision
   properties of small spheres", Physics of Fluids 6 (1994) 1108-1115.
.. [4] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000 (ch. 5).
.. [5] N. Maw, J. R. Barber and J. N. Fawcett, "The oblique impact of elastic spheres",
   Wear 38 (1976) 101-114.
.. [6] N. Maw, J. R. Barber and J. N. Fawcett, "The role of elastic tangential compliance
   in oblique impact", Journal of Lubrication Technology 103 (1981) 74-80.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from . import scalar_tangential as _tangential
from ._xp import arrays, quiet
from .scalar_tangential import impulse_to_body, tangential_impulse_of
from .stronge import StrongeRebound, stronge_restitution

__all__ = [
    "MawAngles",
    "impulse_to_body",
    "StrongeRebound",
    "maw_angles",
    "mindlin_stiffness_ratio",
    "sliding_restitution",
    "slip_after_restitution",
    "stronge_restitution",
    "tangential_impulse_of",
    "walton_restitution",
    "walton_slip",
    "COMPLIANT_REGIMES",
    "compliant_regime_code",
]

#: Names of the regimes of an impact under a tangential compliance law, indexed by
#: :func:`compliant_regime_code`.
COMPLIANT_REGIMES = ("frictionless", "no-slip", "stick", "slip-reversal", "slip")


class MawAngles(NamedTuple):
    """Maw, Barber and Fawcett's normalized incidence and recoil angles."""

    incidence: Any  #: psi_1, dimensionless
    recoil: Any  #: psi_2, dimensionless


def sliding_restitution(slip, vy, zeta, mu, kappa):
    r"""Tangential restitution of an impact that slides throughout, ``beta_slide``.

    Parameters
    ----------
    slip, vy : float or array
        Slip ``c_t^-`` and normal velocity ``c_n^- < 0`` of the contact point, m/s.
    zeta, mu, kappa : float or array
        ``W_tt/W_nn``, friction and normal restitution.

    Returns
    -------
    beta_slide : float or array
        :math:`-1 + (1+\kappa)\zeta\mu|c_n^-|/|c_t^-|` (``+inf`` where ``c_t^- = 0``).
    """
    xp, (slip, vy) = arrays(slip, vy)
    num = _tangential.sliding_change(vy, zeta, mu, kappa)
    den = xp.abs(slip)
    with quiet(xp, divide="ignore", invalid="ignore"):
        ratio = xp.where(den > 0, num / xp.where(den > 0, den, 1.0), xp.inf)
    return ratio - 1.0


def walton_restitution(slip, vy, zeta, mu, kappa, beta0):
    r"""Walton's tangential restitution of the contact point, ``min(beta_0, beta_slide)``.

    Parameters
    ----------
    slip, vy, zeta, mu, kappa : float or array
        As for :func:`sliding_restitution`.
    beta0 : float or array
        Tangential restitution of sticking impacts, in ``[-1, 1]``.

    Returns
    -------
    beta : float or array
        ``-c_t^+/c_t^-``; NaN where ``c_t^- = 0`` (the ratio is ``0/0``: the contact point
        leaves at rest).

    Notes
    -----
    Walton (1993) (also Foerster et al. 1994, eqs. 3-5): ``beta = beta_0`` if that takes
    less friction impulse than Coulomb's limit allows, otherwise the contact slides
    throughout (``beta = beta_slide``). ``beta_0 = 0`` gives the rigid law exactly: stick
    (``c_t^+ = 0``) when ``beta_slide >= 0``, the rigid sliding rebound otherwise.

    Examples
    --------
    >>> float(walton_restitution(1.0, -1.0, 3.5, 0.5, 0.8, 0.3))   # sticks: beta_0
    0.3
    >>> round(float(walton_restitution(10.0, -1.0, 3.5, 0.5, 0.8, 0.3)), 12)  # slides
    -0.685
    """
    xp, (slip, beta0) = arrays(slip, beta0)
    beta = xp.minimum(beta0, sliding_restitution(slip, vy, zeta, mu, kappa))
    return xp.where(slip == 0, xp.nan, beta) + 0.0


def walton_slip(slip, vy, zeta, mu, kappa, beta0):
    r"""Slip after the impact under Walton's law, ``c_t^+``, and whether it stuck.

    Returns
    -------
    slip_after : float or array
        ``-beta_0 c_t^-`` where ``beta_0 <= beta_slide`` (the stick branch), else the rigid
        sliding rebound :math:`c_t^- - \mathrm{sign}(c_t^-)(1+\kappa)\zeta\mu|c_n^-|`
        evaluated as :func:`~spinimpact.core.impulse.rebound_slip` does (m/s), so that
        ``beta_0 = 0`` gives the rigid law's numbers to the last bit.
    stuck : bool array
        The stick branch: ``beta_0 <= beta_slide``, written free of divisions as
        ``(1 + beta_0)|c_t^-| <= (1+kappa) zeta mu |c_n^-|`` (the rigid law's test
        :func:`~spinimpact.core.impulse.sticks` for ``beta_0 = 0``).
    """
    xp, (slip, vy, beta0) = arrays(slip, vy, beta0)
    change = _tangential.sliding_change(vy, zeta, mu, kappa)  # the formulas of the law on
    stuck = _tangential.walton_sticks(slip, beta0, change)  # floats (walton_contact)
    slide = _tangential.slid(slip, xp.sign(slip), change)
    return xp.where(stuck, -beta0 * slip, slide) + 0.0, stuck


def compliant_regime_code(slip, slip_after, mu, stuck, frictionless=False):
    """Integer code of the regime under a compliance law; ``COMPLIANT_REGIMES[code]``.

    Parameters
    ----------
    slip, slip_after : float or array
        ``c_t^-`` and ``c_t^+``, m/s.
    mu : float or array
        Friction coefficient.
    stuck : bool or array
        Whether the contact point stuck during the impact.
    frictionless : bool
        The law applies no friction whatever ``mu`` (Walton's ``beta_0 = -1``: the contact
        point keeps its slip, ``f_1 = 0``, the outcome of ``mu = 0``).

    Returns
    -------
    code : int8 array
        0 ``frictionless`` (``mu = 0``, or a law without friction), 1 ``no-slip``
        (``c_t^- = 0``), 2 ``stick`` (the contact stuck and leaves with ``beta <= 0``),
        3 ``slip-reversal`` (it stuck and leaves slipping the other way, ``beta > 0``),
        4 ``slip`` (it slid throughout).
    """
    xp, (slip, slip_after, mu, stuck) = arrays(slip, slip_after, mu, stuck)
    code = xp.where(stuck, xp.where(slip_after * slip < 0, 3, 2), 4)
    code = xp.where(slip == 0, 1, code)
    return xp.astype(xp.where((mu == 0) | bool(frictionless), 0, code), xp.int8)


def slip_after_restitution(slip, beta):
    """Slip after the impact from the tangential restitution, ``c_t^+ = -beta c_t^-`` (m/s);
    ``0`` where ``c_t^- = 0`` (whatever ``beta``, NaN included)."""
    xp, (slip, beta) = arrays(slip, beta)
    return xp.where(slip == 0, 0.0, -beta * slip) + 0.0


def mindlin_stiffness_ratio(poisson_ratio):
    r"""Mindlin's ratio of the tangential to the normal contact stiffness, ``k_t/k_n``.

    Parameters
    ----------
    poisson_ratio : float or array
        Poisson's ratio ``nu`` of the body (or of both bodies, if of one material).

    Returns
    -------
    ratio : float or array
        :math:`2(1-\nu)/(2-\nu)`.

    Notes
    -----
    The normal stiffness of a Hertz contact of radius ``a`` is ``dP/d delta = 2 E* a`` and
    Mindlin's initial tangential stiffness is ``8 G* a``; their ratio ``4 G*/E*`` is
    ``2(1-nu)/(2-nu)`` when one body is rigid (``E* = E/(1-nu^2)``, ``G* = G/(2-nu)``) or
    both are of one material, with ``G = E/(2(1+nu))`` (Johnson, Contact Mechanics, 1985,
    sections 4.2 and 7.2; Maw et al. 1976).

    Examples
    --------
    >>> round(float(mindlin_stiffness_ratio(0.25)), 12)
    0.857142857143
    """
    return 2.0 * (1.0 - poisson_ratio) / (2.0 - poisson_ratio)


def maw_angles(slip, vy, slip_after, vy_after, mu, poisson_ratio):
    r"""Maw, Barber and Fawcett's normalized incidence and recoil angles ``psi_1, psi_2``.

    Parameters
    ----------
    slip, vy : float or array
        Contact-point slip ``c_t^-`` and normal velocity ``c_n^- < 0`` before, m/s.
    slip_after, vy_after : float or array
        The same after the impact (``c_n^+ >= 0``), m/s.
    mu : float or array
        Friction coefficient, ``> 0``.
    poisson_ratio : float or array
        Poisson's ratio ``nu``.

    Returns
    -------
    MawAngles
        :math:`\psi_1 = \frac{2(1-\nu)}{\mu(2-\nu)}\,\frac{c_t^-}{-c_n^-}` and
        :math:`\psi_2 = \frac{2(1-\nu)}{\mu(2-\nu)}\,\frac{c_t^+}{c_n^+}`: the tangents of
        the contact point's local angles of incidence and recoil from the normal,
        normalized by the friction angle and Mindlin's ratio (``psi_2 < 0``: the slip
        reversed). ``psi_2`` is NaN where ``c_n^+ = 0`` (``kappa = 0``).

    Notes
    -----
    Maw et al. (1976, 1981) define the local angles by the contact point's velocities; with
    ``chi = zeta (1-nu)/(2-nu)`` (their parameter, 1.2558 for a disk of
    ``nu = 0.28``) the rigid law gives ``psi_2 = (psi_1 - 2 chi (1+kappa))/kappa`` while the
    contact slides throughout (``psi_2 = psi_1 - 4 chi`` for ``kappa = 1``, their elastic
    case) and ``psi_2 = 0`` when it sticks. The recoil angle here is the angle of the
    rebound velocity itself (``c_t^+/c_n^+``); DEM papers that divide by the incidence
    normal speed instead obtain ``kappa psi_2``.

    Examples
    --------
    >>> a = maw_angles(1.0, -1.0, -0.2, 1.0, 0.5, 0.25)
    >>> [round(float(x), 6) for x in a]
    [1.714286, -0.342857]
    """
    xp, (slip, vy, slip_after, vy_after) = arrays(slip, vy, slip_after, vy_after)
    k = mindlin_stiffness_ratio(poisson_ratio) / mu
    with quiet(xp, divide="ignore", invalid="ignore"):
        recoil = xp.where(vy_after > 0, slip_after / xp.where(vy_after > 0, vy_after, 1.0),
                          xp.nan)  # fmt: skip
    return MawAngles(k * slip / -vy, k * recoil)
