"""Input checking shared by the model and command-line layers.

Every public entry point funnels its numbers through :func:`as_real_array`
so that bad input fails early with a ``ValueError`` that names the parameter,
the offending value and, for arrays, the first offending index.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = [
    "as_real_array",
    "broadcast",
    "check",
    "validated",
    "row_problems",
    "RULES",
    "LARGEST",
    "SMALLEST",
]

#: Largest magnitude accepted for any input. Keeping every input within
#: [1e-50, 1e50] keeps every product the formulas form (m v^2, zeta mu^2, ...)
#: far from overflow and underflow, so no result is silently inf, NaN or 0.
LARGEST = 1e50
#: Smallest magnitude accepted for strictly positive inputs (mass, radius, |vy|, ...).
SMALLEST = 1e-50
#: Largest zeta = 1 + R^2/rho^2 accepted (R/rho up to 1e10).
MAX_ZETA = 1e20


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


_POSITIVE = [(lambda a: a > 0, "> 0"), (lambda a: a >= SMALLEST, f">= {SMALLEST:g}")]

#: The rules each named input must obey beyond being a finite number of magnitude
#: at most ``LARGEST``: (predicate, text completing "NAME must be ...").
RULES: dict[str, list[tuple[Callable[[np.ndarray], np.ndarray], str]]] = {
    "vx": [],
    "omega": [],
    "vy": [
        (lambda v: v < 0, "< 0 (the body must approach the surface)"),
        (lambda v: v <= -SMALLEST, f"<= -{SMALLEST:g}"),
    ],
    # A Coulomb coefficient beyond 1e6 is not physical, and the bound keeps
    # zeta mu^2 far from overflow even for zeta up to MAX_ZETA.
    "mu": [(lambda m: m >= 0, ">= 0"), (lambda m: m <= 1e6, "<= 1e6")],
    "kappa": [(lambda k: (k >= 0) & (k <= 1), "in [0, 1]")],
    "mass": _POSITIVE,
    "radius": _POSITIVE,
    "gyration": _POSITIVE,
}


def validated(name: str, value: object, rules_for: str | None = None) -> np.ndarray:
    """:func:`as_real_array` plus the rules of ``RULES[rules_for or name]``."""
    arr = as_real_array(name, value)
    for ok, rule in RULES[rules_for or name]:
        check(name, arr, ok, rule)
    return arr


def row_problems(name: str, values: np.ndarray) -> np.ndarray:
    """Per-element description of what is wrong with ``values`` ('' where nothing).

    The same checks as :func:`validated`, reported for every element instead of
    raising at the first, for batch processing that skips bad rows.
    """
    values = np.asarray(values, dtype=np.float64)
    out = np.full(values.shape, "", dtype=object)
    with np.errstate(invalid="ignore"):
        rules = [
            (np.isfinite, "finite"),
            (lambda a: np.abs(a) <= LARGEST, f"at most {LARGEST:g} in magnitude"),
            *RULES[name],
        ]
        for ok, rule in rules:
            bad = ~np.asarray(ok(values), dtype=bool) & (out == "")
            for i in np.flatnonzero(bad):
                out[i] = f"{name} must be {rule}, got {float(values[i])!r}"
    return out
