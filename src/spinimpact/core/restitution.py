r"""The three coefficients of restitution, each evaluated by its own definition.

Newton's kinematic coefficient compares the normal velocities of the contact point,
Poisson's kinetic coefficient the normal impulses of the two phases, and Stronge's
energetic coefficient the works of the normal impulse in the two phases:

.. math::

    \kappa_N = -\frac{v^+}{v^-}, \qquad
    \kappa_P = \frac{\tau_1 - \tau_0}{\tau_0}, \qquad
    \eta = \sqrt{-\frac{W_r^n}{W_c^n}}

(Lubarda 2010, eqs. 1.1-1.3). They coincide when the normal velocity of the contact
rises at one rate through the whole impact (the paper's bodies, section 3) and differ
when the normal and tangential impulses couple (:mod:`spinimpact.core.planar`). Every
solver of the package reports all three through :func:`restitution_by_definition`.

References
----------
.. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
   surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
   Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
.. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays

__all__ = ["RestitutionCoefficients", "restitution_by_definition"]


class RestitutionCoefficients(NamedTuple):
    """Newton's, Poisson's and Stronge's coefficients, each by its own definition."""

    newton: Any  #: ``kappa_N = -v^+/v^-`` (eq. 1.1)
    poisson: Any  #: ``kappa_P = (tau_1 - tau_0)/tau_0`` (eq. 1.2)
    energetic: Any  #: ``eta = sqrt(-W_r^n/W_c^n)`` (eq. 1.3)


def restitution_by_definition(
    v_before, v_after, tau_compression, tau_end, work_compression_normal, work_restitution_normal
):
    """Newton's, Poisson's and Stronge's coefficients of one impact process.

    Parameters
    ----------
    v_before, v_after : float or array
        Normal velocity of the contact point before (``< 0``) and after the impact, m/s.
    tau_compression, tau_end : float or array
        Normal impulse at the end of compression and of the impact, N s.
    work_compression_normal, work_restitution_normal : float or array
        Works of the normal impulse in compression (``< 0``) and restitution, J.

    Returns
    -------
    RestitutionCoefficients
        ``(newton, poisson, energetic)``; ``energetic`` is ``0`` where the restitution
        work is negative.

    Examples
    --------
    >>> c = restitution_by_definition(-2.0, 1.6, 2.0, 3.6, -2.0, 1.28)
    >>> tuple(round(float(x), 12) for x in c)
    (0.8, 0.8, 0.8)
    """
    eta2 = -work_restitution_normal / work_compression_normal
    xp, (eta2,) = arrays(eta2)
    return RestitutionCoefficients(
        -v_after / v_before,
        (tau_end - tau_compression) / tau_compression,
        xp.sqrt(xp.maximum(eta2, 0.0)),
    )
