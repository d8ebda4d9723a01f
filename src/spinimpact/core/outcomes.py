"""Qualitative rebound outcomes: conditions on the incidence (paper section 4).

The paper [1]_ states that the conditions for backward rebound, reversed spin and
spinning or non-spinning vertical rebound are "straightforward and omitted for
brevity". They are derived here from eqs. (4.13) and (4.16); equation numbers are the
paper's.

Write ``a = vx^-``, ``b = R omega^-``, ``w = |v^-|``, ``u = a + b``,
``s = sign(u)`` and ``c = (1 + kappa) mu w``.

*Stick* (``|u| <= (1+kappa) zeta mu w``; eq. 4.13):
``vx+ = ((zeta-1) a - b)/zeta`` and ``R omega+ = -vx+``. Hence

* backward rebound  <=>  ``a ((zeta-1) a - b) < 0``, i.e. ``b/a > zeta - 1``;
* reversed spin     <=>  ``b (b - (zeta-1) a) < 0``;
* vertical rebound  <=>  ``b = (zeta - 1) a``, and it is then *non-spinning*
  (``omega+ = 0``): the body leaves straight up without spin.

*Slip throughout* (``|u| > (1+kappa) zeta mu w``; eq. 4.16):
``vx+ = a - s c`` and ``R omega+ = b - s (zeta-1) c``. Hence

* backward rebound  <=>  ``s a > 0`` and ``|a| < c`` (friction overturns ``vx``);
* reversed spin     <=>  ``s b > 0`` and ``|b| < (zeta-1) c``;
* vertical rebound  <=>  ``a = s c``; it is *spinning* (``omega+ = (b - s(zeta-1)c)/R``,
  non-zero since ``|u| > zeta c``).

Together: the body rebounds vertically without spin iff
``R omega^- = (zeta-1) vx^-`` and ``|vx^-| <= (1+kappa) mu |v^-|``; it rebounds
vertically with spin iff it slips throughout and ``vx^- = sign(u^-)(1+kappa) mu |v^-|``.

Equalities are decided to within a few rounding errors of the size of the
terms in each condition (e.g. ``|(zeta-1) a| + |b|`` for ``b = (zeta-1) a``).

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a
   fixed surface", Proceedings of the Section of Natural Sciences, Montenegrin
   Academy of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from ._xp import arrays
from .impulse import sticks

__all__ = ["OUTCOMES", "OutcomeFlags", "rebound_outcomes"]

#: Names of the flags returned by :func:`rebound_outcomes`, in order.
OUTCOMES = ("backward", "reversed_spin", "vertical", "spinning", "rolling")


class OutcomeFlags(NamedTuple):
    """The flags of :func:`rebound_outcomes` (boolean arrays), in the order of :data:`OUTCOMES`."""

    backward: Any
    reversed_spin: Any
    vertical: Any
    spinning: Any
    rolling: Any


#: Relative tolerance, in units of the velocity scale, for the equalities.
_RTOL = 16 * float(np.finfo(np.float64).eps)  # a Python float: any array library takes it


def rebound_outcomes(vx, vy, omega, radius, zeta, mu, kappa):
    r"""Flags of the qualitative rebound outcome, decided from the incidence alone.

    Parameters
    ----------
    vx, vy, omega : float or array
        Incidence velocity of the centre (m/s, ``vy < 0``) and spin (rad/s,
        counter-clockwise positive): the paper's ``u_C^-``, ``v^-``, ``omega^-``.
    radius, zeta : float or array
        Contact radius ``R`` (m) and ``zeta = 1 + R^2/rho^2``.
    mu, kappa : float or array
        Kinetic Coulomb friction coefficient and coefficient of normal restitution.

    Returns
    -------
    OutcomeFlags
        A named tuple of boolean arrays of the broadcast shape:

        ``backward``
            ``vx^- != 0`` and ``vx^+`` has the opposite sign (the body bounces back).
        ``reversed_spin``
            ``omega^- != 0`` and ``omega^+`` has the opposite sign.
        ``vertical``
            ``vx^+ = 0``: the centre leaves along the normal.
        ``spinning``
            ``omega^+ != 0``.
        ``rolling``
            ``u^+ = 0``: the body leaves rolling (the contact stuck, eq. 4.6).

    Notes
    -----
    With ``u^- = vx^- + R omega^-`` and ``s = sign(u^-)``, the rebound of eqs. (4.13)
    and (4.16) [1]_ is

    .. math::

        \begin{cases}
            v_x^+ = v_x^- - u^-/\zeta, \quad R\omega^+ = -v_x^+,
                & |u^-| \le (1+\kappa)\zeta\mu|v^-| \\
            v_x^+ = v_x^- - s(1+\kappa)\mu|v^-|, \quad
                R\omega^+ = R\omega^- - s(\zeta - 1)(1+\kappa)\mu|v^-|, & \text{otherwise,}
        \end{cases}

    and each flag is a sign condition on these, written in the incidence (module
    docstring) and decided without computing the rebound, so that an exactly vertical
    or non-spinning rebound is recognised despite rounding. The paper omits these
    conditions "for brevity".

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).

    Examples
    --------
    A solid sphere (``zeta = 7/2``) with backspin ``R omega^- = (zeta - 1) vx^-`` sticks
    and leaves straight up without spin:

    >>> flags = rebound_outcomes(0.5, -1.0, 12.5, radius=0.1, zeta=3.5, mu=0.5, kappa=0.8)
    >>> [name for name, flag in zip(OUTCOMES, flags) if flag]
    ['vertical', 'rolling']
    """
    xp, (a, vy, omega) = arrays(vx, vy, omega)
    b = radius * omega
    w = xp.abs(vy)
    u = a + b
    s = xp.sign(u)
    c = (1.0 + kappa) * mu * w
    stick = sticks(u, vy, zeta, mu, kappa)

    # Quantities with the signs of vx+ and omega+ (times zeta), each with the size
    # of its own terms, against which "zero" is judged.
    za = (zeta - 1.0) * a
    gx = xp.where(stick, za - b, zeta * (a - s * c))
    gw = xp.where(stick, b - za, zeta * (b - s * (zeta - 1.0) * c))
    size_x = xp.where(stick, xp.abs(za) + xp.abs(b), zeta * (xp.abs(a) + c))
    size_w = xp.where(stick, xp.abs(za) + xp.abs(b), zeta * (xp.abs(b) + (zeta - 1.0) * c))
    zero_x = xp.abs(gx) <= _RTOL * size_x
    zero_w = xp.abs(gw) <= _RTOL * size_w
    backward = (a != 0) & ~zero_x & (xp.sign(gx) == -xp.sign(a))
    reversed_spin = (b != 0) & ~zero_w & (xp.sign(gw) == -xp.sign(b))
    return OutcomeFlags(backward, reversed_spin, zero_x, ~zero_w, stick)
