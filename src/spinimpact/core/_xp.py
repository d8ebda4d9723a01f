"""Array-API plumbing: the core kernels run on any array library with a
namespace known to ``array_api_compat`` (NumPy, CuPy, JAX, Dask, PyTorch,
``array_api_strict``), and on plain Python numbers (NumPy then).

NumPy inputs take NumPy itself as the namespace (NumPy >= 2.1 implements the
standard's functions used here), so the common case pays no wrapper cost and
``array_api_compat`` is imported only when another library's arrays appear.
Python lists and tuples are not arrays here: pass ``numpy.asarray(values)``.

References
----------
.. [1] Consortium for Python Data API Standards, "Python array API standard",
   https://data-apis.org/array-api/
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
    """The array namespace of ``values``, and ``values`` as arrays of it.

    Parameters
    ----------
    *values : int, float or array
        Python numbers, or arrays of one array-API library (NumPy, CuPy, JAX, ...).

    Returns
    -------
    xp : module
        The namespace of the arrays among ``values`` (``numpy`` itself for NumPy arrays
        and scalars, or when all values are Python numbers; otherwise the
        ``array_api_compat`` namespace).
    values : list
        ``values`` in order, with Python numbers turned into 0-d float64 arrays of ``xp``
        and arrays passed through unchanged.

    Raises
    ------
    TypeError
        From ``array_api_compat`` when the arrays belong to different libraries or a
        value is neither a number nor an array (a list, say).

    Examples
    --------
    >>> import numpy as np
    >>> xp, (a, b) = arrays(2, np.array([1.0, 2.0]))
    >>> xp is np, a.dtype, a.ndim, b
    (True, dtype('float64'), 0, array([1., 2.]))
    """
    present = [v for v in values if not isinstance(v, int | float)]
    xp = _namespace(present)
    return xp, [
        xp.asarray(float(v), dtype=xp.float64) if isinstance(v, int | float) else v for v in values
    ]


def quiet(xp: Any, **kwargs: str) -> contextlib.AbstractContextManager:
    """Silence the floating-point warnings of branches that ``where`` discards.

    Parameters
    ----------
    xp : module
        The array namespace (unused: the context is NumPy's, which also covers libraries
        computing with NumPy underneath, such as ``array_api_strict``).
    **kwargs : str
        As for :func:`numpy.errstate` (``divide="ignore"``, ``all="ignore"``, ...).

    Returns
    -------
    contextlib.AbstractContextManager
        ``numpy.errstate(**kwargs)``. Lazy libraries (Dask) evaluate later, outside it,
        which is why the kernels also guard their divisors.
    """
    return np.errstate(**kwargs)


def result(xp: Any, x: Any) -> Any:
    """A NumPy scalar for a 0-d NumPy result, as NumPy itself returns; ``x`` otherwise.

    Parameters
    ----------
    xp : module
        The array namespace ``x`` belongs to.
    x : array
        A result of a kernel.

    Returns
    -------
    scalar or array
        ``x[()]`` for NumPy (a NumPy scalar if 0-d, else ``x``); ``x`` unchanged for any
        other library.

    Examples
    --------
    >>> import numpy as np
    >>> result(np, np.asarray(1.5))
    np.float64(1.5)
    """
    return np.asarray(x)[()] if xp is np else x
