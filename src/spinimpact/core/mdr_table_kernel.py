"""The compiled reading of :mod:`spinimpact.core.mdr_table` (Numba, the ``[fast]`` extra).

The same local cubic interpolation as ``core.mdr_table``'s NumPy path, one row at a time
(no temporary arrays over the rows: about ten times faster on 100,000 rows); the two agree
to rounding (``tests/core/test_mdr_table.py``). Each row is read by
:func:`spinimpact.core.scalar_mdr.share_of`, the function users' ``numba.njit`` code calls
through :mod:`spinimpact.contact_law`, so the two give the same bits.
"""

from __future__ import annotations

import numpy as np

from . import law  # registers the law on floats (scalar_mdr included) for compiled code
from .fused import HAVE_NUMBA, _njit
from .scalar_mdr import mdr_contact, mdr_table, share_of, table_axes

__all__ = ["HAVE_NUMBA", "share_rows", "contact_one"]


if HAVE_NUMBA:  # pragma: no branch - the test extra installs Numba
    import numba

    assert law.HAVE_NUMBA

    @_njit
    def _share_rows(x, q, kappa, axes, touch, threshold, share, out_share, out_stuck):
        for n in numba.prange(x.size):
            out_share[n], out_stuck[n] = share_of(x[n], q[n], kappa[n], axes, touch, threshold,
                                                  share)  # fmt: skip


def share_rows(x, q, kappa, table):
    """``(phi, stuck)`` of rows inside the table's range (one-dimensional float arrays),
    compiled: what :func:`spinimpact.core.mdr_table.impulse_share` computes."""
    axes = table_axes(table)
    out_share = np.empty(x.size)
    out_stuck = np.empty(x.size, dtype=np.bool_)
    _share_rows(np.ascontiguousarray(x, dtype=float), np.ascontiguousarray(q, dtype=float),
                np.ascontiguousarray(kappa, dtype=float), axes, table.touch, table.threshold,
                table.share, out_share, out_stuck)  # fmt: skip
    return out_share, out_stuck


def contact_one(slip, vy, zeta, mu, kappa, stiffness_ratio):
    """:func:`spinimpact.core.scalar_mdr.mdr_contact` of one impact with the shipped table,
    compiled (the plain-Python function costs tens of microseconds a call)."""
    axes, limits, touch, threshold, share = mdr_table()
    return _contact_one(slip, vy, zeta, mu, kappa, stiffness_ratio, axes, limits, touch,
                        threshold, share)  # fmt: skip


def _contact_one(slip, vy, zeta, mu, kappa, ratio, axes, limits, touch, threshold, share):
    return mdr_contact(slip, vy, zeta, mu, kappa, ratio, (axes, limits, touch, threshold, share))


if HAVE_NUMBA:  # pragma: no branch
    _contact_one = _njit(_contact_one, parallel=False)
