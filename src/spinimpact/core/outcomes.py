"""Qualitative rebound outcomes: conditions on the incidence (paper section 4).

The paper states that the conditions for backward rebound, reversed spin and
spinning or non-spinning vertical rebound are "straightforward and omitted for
brevity". They are derived here from eqs. (4.13) and (4.16).

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
    """Flags of the qualitative rebound outcome, decided from the incidence alone.

    Returns
    -------
    OutcomeFlags
        A named tuple of boolean arrays:

    backward : ndarray of bool
        ``vx^- != 0`` and ``vx^+`` has the opposite sign (the body bounces back).
    reversed_spin : ndarray of bool
        ``omega^- != 0`` and ``omega^+`` has the opposite sign.
    vertical : ndarray of bool
        ``vx^+ = 0``: the centre leaves along the normal.
    spinning : ndarray of bool
        ``omega^+ != 0``.
    rolling : ndarray of bool
        ``u^+ = 0``: the body leaves rolling (the contact stuck, eq. 4.6).
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
