"""The fields of :func:`~spinimpact.solve`'s result from the fused all-field kernel.

For arrays of at least :data:`THRESHOLD` impacts and with Numba installed, ``solve()``
takes every field from :func:`spinimpact.core.fused_impact.impact_fields` (one pass over
memory) instead of the NumPy kernels; the fields are equal bit for bit
(``tests/model/test_impact_fused.py``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .._validation import available

__all__ = ["THRESHOLD", "fused_fields"]

#: Fewest impacts for which ``solve()`` uses the fused kernel. Measured on a 2-core
#: machine: fused 0.19 ms against NumPy 0.39 ms for 1 to 5 impacts, 0.22 against 0.62 ms
#: for 1,000 (validation and the result's construction dominate small calls), so every
#: array takes it; the NumPy path remains for 0-d input, empty arrays and without Numba.
THRESHOLD = 1


def _frozen(a: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """``a`` as a read-only C-contiguous array of ``shape``, copied only if it is not one.

    ``a`` is one of ``solve()``'s own validated copies (or a broadcast view of one), never
    the caller's array, so it may be frozen in place.
    """
    if a.shape != shape or not a.flags.c_contiguous or 0 in a.strides:
        a = np.ascontiguousarray(np.broadcast_to(a, shape))
    view = a.view()
    view.setflags(write=False)
    return view


def fused_fields(
    state: Callable[..., Any],
    outcome: Callable[..., Any],
    vx: np.ndarray,
    vy: np.ndarray,
    omega: np.ndarray,
    mu: np.ndarray,
    kappa: np.ndarray,
    mass: np.ndarray,
    radius: np.ndarray,
    gyration: np.ndarray,
    zeta: np.ndarray,
    *,
    threshold: int | None = None,
) -> dict[str, Any] | None:
    """Keyword arguments of :class:`~spinimpact.Impact` (all but ``body``), or ``None``.

    Parameters
    ----------
    state, outcome : callable
        The :class:`~spinimpact.model.impact.State` and
        :class:`~spinimpact.model.impact.Outcome` classes.
    vx, vy, omega, mu, kappa, mass, radius, gyration, zeta : ndarray
        ``solve()``'s validated, broadcast arrays (all of one shape).
    threshold : int, optional
        Fewest impacts to take the fused path (default :data:`THRESHOLD`).

    Returns
    -------
    dict or None
        ``None`` without Numba, for 0-d input, or below the threshold: use the NumPy path.

    Notes
    -----
    Numba is imported on the first call that uses it (``import spinimpact`` stays light).
    """
    least = THRESHOLD if threshold is None else threshold
    if vx.ndim == 0 or vx.size < least or not available("numba"):
        return None
    from ..core import fused_impact  # imports Numba: only when it is used

    if not fused_impact.HAVE_NUMBA:  # installed, but it failed to import
        return None
    shape = vx.shape
    f = fused_impact.impact_fields(vx, vy, omega, mass, radius, gyration, zeta, mu, kappa)
    out = {name: _frozen(a, shape) for name, a in f._asdict().items()}
    flags = [out.pop(name) for name in ("backward", "reversed_spin", "vertical", "spinning",
                                        "rolling")]  # fmt: skip
    after = [out.pop(f"after_{c}") for c in ("vx", "vy", "omega")]
    return dict(
        out,
        mu=_frozen(mu, shape),
        kappa=_frozen(kappa, shape),
        before=state(*(_frozen(a, shape) for a in (vx, vy, omega))),
        after=state(*after),
        outcome=outcome(*flags),
    )
