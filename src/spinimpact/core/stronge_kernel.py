"""The compiled loop of :func:`spinimpact.core.stronge.stronge_restitution` (Numba, the
``[fast]`` extra): :func:`~spinimpact.core.scalar_stronge.stronge_contact`, the one
formulation of Stronge's law on floats, over rows of impacts in parallel. The function is
the one users' ``numba.njit`` code calls through :mod:`spinimpact.contact_law`, so the array
path and the compiled per-contact law give the same bits. Imported only when a batch of
Stronge impacts is solved (Numba is heavy).
"""

from __future__ import annotations

from . import law  # registers the law on floats (scalar_stronge included) for compiled code
from .fused import HAVE_NUMBA, _njit
from .scalar_stronge import stronge_contact

__all__ = ["HAVE_NUMBA", "stronge_rows"]


def stronge_rows(slip, vy, zeta, mu, kappa, ratio, after, stuck, changes):
    """``stronge_contact`` of every row ``i`` of the 1-D float arrays, into ``after[i]``,
    ``stuck[i]`` and ``changes[i]``."""
    for i in numba.prange(slip.size):
        a, s, c = stronge_contact(slip[i], vy[i], zeta[i], mu[i], kappa[i], ratio[i])
        after[i] = a
        stuck[i] = s
        changes[i] = c


if HAVE_NUMBA:  # pragma: no branch - the module is imported only with Numba
    import numba

    assert law.HAVE_NUMBA
    stronge_rows = _njit(stronge_rows)
