r"""Stronge's lumped-parameter tangential compliance, solved piecewise in closed form.

The contact is a massless point joined to the body by a normal and a tangential spring
(Stronge [1]_, ch. 5; Maw, Barber and Fawcett [2]_ for the stiffness ratio). On the seam
(``W_tn = 0``; ``W_nn = 1/m``, ``W_tt = zeta/m``):

* Normal spring, linear: stiffness ``k_n`` while loading, ``k_n/kappa^2`` while unloading
  from the largest compression (Stronge's model of the energetic coefficient: the
  restitution phase returns ``kappa^2`` of the stored energy). With ``W_tn = 0`` the normal
  motion is independent of friction and Newton's, Poisson's and Stronge's coefficients all
  equal ``kappa``; ``tau_1 = (1 + kappa) m |c_n^-|``, as in the rigid law.
* Tangential spring, linear, stiffness ``k_t = r k_n`` with ``r`` from Poisson's ratio
  (:func:`spinimpact.core.compliance.mindlin_stiffness_ratio`: Mindlin's initial
  tangential stiffness over Hertz's normal stiffness, both proportional to the contact
  radius). Its force on the body is ``F = -k_t xi`` (``xi``: the body's contact point less
  the contact point's position on the surface).
* Coulomb: the contact point sticks to the surface while ``|F| < mu N``; otherwise it slips
  with ``F = -mu N sign(w)``, ``w`` its velocity on the surface.

Dimensionless form. Time ``s = omega_n t`` with ``omega_n = sqrt(k_n W_nn)``; velocities in
units of ``|c_n^-|``, forces in ``omega_n m |c_n^-|``: ``u = c_t/|c_n^-|``, ``x = -F/(...)``.
In compression (``n = sin t``, ``t = s``) and restitution (``n = cos t``, ``s = pi/2 +
kappa t``), with ``c = 1`` or ``kappa`` the phase's time scale, ``t`` in ``[0, pi/2]``:

* stick: :math:`u' = -c\zeta x,\ x' = c r u`: harmonic at ``c Omega``,
  :math:`\Omega = \sqrt{\zeta r} = \omega_t/\omega_n`, the ratio of the tangential to the
  normal frequency; it lasts while ``|x| < mu n(t)`` (the first crossing is found by
  sampling at a fine fraction of the period, then Newton's method kept inside the
  bracket);
* slip in direction ``sigma``: ``x = sigma mu n(t)``, :math:`u' = -c\zeta\mu\sigma n`, so
  ``u = u_a - zeta mu sigma (cos t_a - cos t)`` or ``u_a - kappa zeta mu sigma (sin t -
  sin t_a)``; the contact point's velocity :math:`w = u - \mu\sigma n'/(c r)` keeps the
  sign ``sigma`` until :math:`\sigma u - \mu n'/(c r)` vanishes, in closed form:
  :math:`\cos t = (\zeta\mu\cos t_a - \sigma u_a)/(\mu(\zeta - 1/r))` in compression and
  :math:`\sin t = (\sigma u_a + \kappa\zeta\mu\sin t_a)/(\mu(\kappa\zeta - 1/(\kappa r)))`
  in restitution.

The impact starts slipping if ``r |u^-| > mu`` (Maw et al.'s normalized incidence angle
above 1) and sticking otherwise. It ends with ``n = 0``, so ``x = 0``: no energy stays in
the spring, and ``u^2/zeta + x^2/r`` (the tangential kinetic plus spring energy) never
grows, so ``|beta| <= 1``. If it slides throughout, ``beta = beta_slide`` (Coulomb over
the whole ``tau_1``) exactly, also where the rigid law would have stuck: the unloading
spring lets the contact point slide on past ``c_t = 0`` by up to ``mu |c_n^-|/(kappa r)``.
As ``r -> inf`` (a rigid contact) the slip after tends to the rigid law's, the difference
bounded by the stuck spring's velocity amplitude ``mu |c_n^-| sqrt(zeta/r)``
(``docs/compliance.md``).

The computation is written once, for one contact on floats, in
:mod:`spinimpact.core.scalar_stronge`; :func:`stronge_restitution` runs it over the rows of
its arrays (a compiled loop with Numba, :mod:`spinimpact.core.stronge_kernel`; a Python
loop without), and :mod:`spinimpact.contact_law` gives it to users' compiled loops.

References
----------
.. [1] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000 (ch. 5, 8).
.. [2] N. Maw, J. R. Barber and J. N. Fawcett, "The role of elastic tangential compliance
   in oblique impact", Journal of Lubrication Technology 103 (1981) 74-80.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from .scalar_stronge import stronge_contact

__all__ = ["COMPILED_FROM", "StrongeRebound", "stronge_restitution"]


#: Impacts from which :func:`stronge_restitution` runs its compiled loop (with Numba): fewer
#: cost less in Python (about 0.1 ms each) than loading the loop (about a second, once).
COMPILED_FROM = 32


class StrongeRebound(NamedTuple):
    """Result of :func:`stronge_restitution`."""

    slip_after: Any  #: c_t^+, m/s
    stuck: Any  #: whether the contact point stuck at any time
    transitions: Any  #: number of stick/slip changes during the impact
    restitution: Any  #: beta = -c_t^+/c_t^- (NaN for c_t^- = 0)


def _python_rows(slip, vy, zeta, mu, kappa, ratio, after, stuck, changes):
    """:func:`~spinimpact.core.scalar_stronge.stronge_contact` over the rows, in Python
    (without Numba)."""
    rows = zip(*(a.tolist() for a in (slip, vy, zeta, mu, kappa, ratio)), strict=True)
    for i, row in enumerate(rows):
        after[i], stuck[i], changes[i] = stronge_contact(*row)


def stronge_restitution(slip, vy, zeta, mu, kappa, stiffness_ratio):
    """The slip after an impact with Stronge's lumped tangential compliance.

    Parameters
    ----------
    slip, vy : float or array
        Slip ``c_t^-`` and normal velocity ``c_n^- < 0`` of the contact point, m/s.
    zeta, mu, kappa : float or array
        ``W_tt/W_nn``, friction and normal restitution (here the energetic coefficient,
        equal to Newton's and Poisson's with ``W_tn = 0``).
    stiffness_ratio : float or array
        ``r = k_t/k_n > 0``, e.g. ``2(1-nu)/(2-nu)``.

    Returns
    -------
    StrongeRebound
        ``slip_after`` (m/s), ``stuck``, ``transitions`` and ``restitution`` (``beta``),
        of the broadcast shape (NumPy arrays).

    Notes
    -----
    Each impact is :func:`spinimpact.core.scalar_stronge.stronge_contact` (the phases
    followed one by one, on floats), run over the rows by a compiled loop where Numba is
    installed (the ``[fast]`` extra; :mod:`spinimpact.core.stronge_kernel`) for
    :data:`COMPILED_FROM` impacts or more, and by a Python loop otherwise: the same
    function, so the same bits as the compiled per-contact law of
    :mod:`spinimpact.contact_law` (``tests/core/test_law_tangential.py``).

    Examples
    --------
    Sliding throughout it is the rigid law's sliding rebound; a small incidence angle
    sticks and reverses the slip:

    >>> r = stronge_restitution([10.0, 0.3], -1.0, 3.5, 0.5, 0.8, 0.8)
    >>> round(float(r.restitution[0]), 12), bool(r.stuck[1]), bool(r.restitution[1] > 0)
    (-0.685, True, True)
    """
    rows = np.broadcast_arrays(slip, vy, zeta, mu, kappa, stiffness_ratio)
    shape = rows[0].shape
    u0, vy, zeta, mu, kappa, r = (np.ascontiguousarray(a, dtype=np.float64).ravel() for a in rows)
    after = np.empty(u0.size)
    stuck = np.empty(u0.size, dtype=bool)
    changes = np.empty(u0.size, dtype=np.int64)
    from . import fused  # Numba, if installed, is imported here: only when it is used

    if fused.HAVE_NUMBA and u0.size >= COMPILED_FROM:
        from .stronge_kernel import stronge_rows

        stronge_rows(u0, vy, zeta, mu, kappa, r, after, stuck, changes)
    else:
        _python_rows(u0, vy, zeta, mu, kappa, r, after, stuck, changes)
    with np.errstate(divide="ignore", invalid="ignore"):
        beta = np.where(u0 != 0, -after / np.where(u0 != 0, u0, 1.0), np.nan)
    return StrongeRebound(*(a.reshape(shape)[()] for a in (after, stuck, changes, beta)))
