"""Array-API plumbing: the core kernels run on any array library with a
namespace known to ``array_api_compat`` (NumPy, CuPy, JAX, Dask, PyTorch,
``array_api_strict``), and on plain Python numbers (NumPy then).

NumPy inputs take NumPy itself as the namespace (NumPy >= 2.1 implements the
standard's functions used here), so the common case pays no wrapper cost and
``array_api_compat`` is imported only when another library's arrays appear.
"""

from __future__ import annotations

import contextlib
from typing import Any

import numpy as np

__all__ = ["arrays", "quiet", "result"]


def _namespace(present: list[Any]) -> Any:
    if all(isinstance(v, np.ndarray | np.generic) for v in present):
        return np
    from array_api_compat import array_namespace

    return array_namespace(*present)


def arrays(*values: Any) -> tuple[Any, list[Any]]:
    """The namespace of the arrays among ``values``, and ``values`` with Python
    numbers turned into 0-d float64 arrays of that namespace."""
    present = [v for v in values if not isinstance(v, int | float)]
    xp = _namespace(present)
    return xp, [
        xp.asarray(float(v), dtype=xp.float64) if isinstance(v, int | float) else v for v in values
    ]


def quiet(xp: Any, **kwargs: str) -> contextlib.AbstractContextManager:
    """``numpy.errstate(**kwargs)``: silences the floating-point warnings of
    branches that ``where`` discards, for NumPy and for libraries computing with
    NumPy underneath (array_api_strict). Lazy libraries (Dask) evaluate later."""
    return np.errstate(**kwargs)


def result(xp: Any, x: Any) -> Any:
    """A NumPy scalar for 0-d NumPy results (as NumPy itself returns); ``x`` otherwise."""
    return np.asarray(x)[()] if xp is np else x
