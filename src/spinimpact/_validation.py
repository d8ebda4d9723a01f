"""Input checking shared by the model and command-line layers.

Every public entry point funnels its numbers through :func:`as_real_array`
so that bad input fails early with a ``ValueError`` that names the parameter,
the offending value and, for arrays, the first offending index.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = ["as_real_array", "broadcast", "check", "LARGEST", "SMALLEST"]

#: Largest magnitude accepted for any input. Keeping every input within
#: [1e-50, 1e50] keeps every product the formulas form (m v^2, zeta mu^2, ...)
#: far from overflow and underflow, so no result is silently inf, NaN or 0.
LARGEST = 1e50
#: Smallest magnitude accepted for strictly positive inputs (mass, radius, |vy|, ...).
SMALLEST = 1e-50


def _where(mask: np.ndarray) -> str:
    """Describe the first True position of ``mask`` for an error message."""
    if mask.ndim == 0:
        return ""
    index = tuple(int(i) for i in np.argwhere(mask)[0])
    return f" (first offending index {index[0] if len(index) == 1 else index})"


def _value(arr: np.ndarray, mask: np.ndarray) -> str:
    return repr(float(arr[mask].flat[0] if arr.ndim else arr[()]))


def as_real_array(name: str, value: object) -> np.ndarray:
    """Convert ``value`` to a finite float64 array or raise ``ValueError``.

    Parameters
    ----------
    name : str
        Parameter name used in the error message.
    value : array_like
        Number or array of numbers.
    """
    raw = np.asarray(value)
    if raw.dtype.kind not in "iuf":  # not bool, str, None, complex, object
        raise ValueError(f"{name} must be a real number or array of numbers, got {value!r}")
    arr = np.array(raw, dtype=np.float64)  # a copy: later changes by the caller do not leak in
    bad = ~np.isfinite(arr)
    if bad.any():
        raise ValueError(f"{name} must be finite, got {_value(arr, bad)}{_where(bad)}")
    check(name, arr, lambda a: np.abs(a) <= LARGEST, f"at most {LARGEST:g} in magnitude")
    arr.setflags(write=False)
    return arr


def check(name: str, arr: np.ndarray, ok: Callable[[np.ndarray], np.ndarray], rule: str) -> None:
    """Raise ``ValueError`` unless ``ok(arr)`` holds everywhere.

    ``rule`` completes the sentence "``name`` must be ...", e.g. ``"> 0"``.
    """
    bad = ~np.asarray(ok(arr), dtype=bool)
    if bad.any():
        raise ValueError(f"{name} must be {rule}, got {_value(arr, bad)}{_where(bad)}")


def broadcast(**arrays: np.ndarray) -> list[np.ndarray]:
    """Broadcast named arrays together, naming the shapes if they do not fit."""
    try:
        return list(np.broadcast_arrays(*arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {np.shape(v)}" for k, v in arrays.items())
        raise ValueError(f"input shapes do not broadcast together: {shapes}") from None
