"""Array-API plumbing: the core kernels run on any array library with a
namespace known to ``array_api_compat`` (NumPy, CuPy, JAX, Dask, PyTorch,
``array_api_strict``), and on plain Python numbers (NumPy then)."""

from __future__ import annotations

import contextlib  # noqa: F401
from typing import Any

import numpy as np
from array_api_compat import array_namespace, is_numpy_namespace

__all__ = ["arrays", "quiet", "result"]

_NUMPY = array_namespace(np.asarray(0.0))


def arrays(*values: Any) -> tuple[Any, list[Any]]:
    """The namespace of the arrays among ``values``, and ``values`` with Python
    numbers turned into 0-d float64 arrays of that namespace."""
    present = [v for v in values if not isinstance(v, int | float)]
    xp = array_namespace(*present) if present else _NUMPY
    scalar = (int, float)
    return xp, [
        xp.asarray(float(v), dtype=xp.float64) if isinstance(v, scalar) else v for v in values
    ]


def quiet(xp: Any, **kwargs: str) -> contextlib.AbstractContextManager:
    """``numpy.errstate(**kwargs)``: silences the floating-point warnings of
    branches that ``where`` discards, for NumPy and for libraries computing with
    NumPy underneath (array_api_strict). Lazy libraries (Dask) evaluate later;
    their kernels avoid such branches where it matters."""
    return np.errstate(**kwargs)


def result(xp: Any, x: Any) -> Any:
    """A NumPy scalar for 0-d NumPy results (as NumPy itself returns); ``x`` otherwise."""
    return np.asarray(x)[()] if is_numpy_namespace(xp) else x
