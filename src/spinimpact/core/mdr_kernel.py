"""The compiled time stepping of :mod:`spinimpact.core.mdr` (Numba, the ``[fast]`` extra).

The same leapfrog as ``core.mdr``'s NumPy loop, one impact per thread, the springs in an
inner loop that stops at the last spring in contact: no array is allocated per step, so one
impact costs what its arithmetic costs. The springs' forces are added in order (NumPy adds
them pairwise), so the two paths agree to rounding, not bit for bit
(``tests/core/test_mdr.py``).
"""

from __future__ import annotations

import numpy as np

from .fused import HAVE_NUMBA, _njit

__all__ = ["HAVE_NUMBA", "step_rows"]


if HAVE_NUMBA:  # pragma: no branch - the test extra installs Numba
    import numba

    @_njit
    def _step_rows(u0, zeta, mu, delta, factor, x2, active, stiffness, dt, out_u, out_stuck):
        last = delta.size - 1
        for k in numba.prange(u0.size):
            s = np.zeros(x2.size)
            u, cap, z, stuck = u0[k], mu[k], zeta[k], False
            for i in range(1, last + 1):
                total = 0.0
                for j in range(active[i]):
                    w = delta[i] - x2[j]  # the spring's compression, and the step before's
                    before = delta[i - 1] - x2[j]
                    bound = cap * (max(w, 0.0) * factor[i])
                    if w <= 0.0:
                        share = 0.0
                    elif before > 0.0:
                        share = 1.0
                    else:  # it came into contact during the step
                        share = max(w, 0.0) / (w - before)
                    trial = s[j] + dt * u * share
                    if trial > bound:
                        value = bound
                    elif trial < -bound:
                        value = -bound
                    else:
                        value = trial
                        if j == 0 and abs(trial) < bound:
                            stuck = True
                    s[j] = value
                    total += value
                force = -stiffness * total
                u = u + (dt if i < last else 0.5 * dt) * z * force
            out_u[k] = u
            out_stuck[k] = stuck


def step_rows(u0, zeta, mu, delta, factor, x2, active, stiffness, dt):
    """``(u+, stuck)`` of rows of impacts (the solver's units), compiled: the springs'
    bounds and shares of a step computed from ``delta`` (per step), ``factor`` (per step)
    and ``x2 = x^2`` (per spring) as ``core.mdr._setup`` computes them; ``active[i]``: one
    past the last spring to visit at step ``i`` (``core.mdr.active_springs``)."""
    out_u = np.empty(u0.size)
    out_stuck = np.empty(u0.size, dtype=np.bool_)
    _step_rows(np.ascontiguousarray(u0, dtype=float), np.ascontiguousarray(zeta, dtype=float),
               np.ascontiguousarray(mu, dtype=float), delta, factor, x2, active,
               float(stiffness), float(dt), out_u, out_stuck)  # fmt: skip
    return out_u, out_stuck
