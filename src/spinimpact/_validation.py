"""Input checking shared by every layer: one vocabulary for bad input.

Every public entry point funnels its numbers through :func:`as_real_array`
(arrays) or :func:`scalar` (single numbers), so bad input fails early:

* a value of the wrong *type* (a string, ``None``, a bool, a complex number)
  raises ``TypeError`` naming the parameter and the value;
* a number with a bad *value* (non-finite, out of range) raises ``ValueError``
  naming the parameter, the value and, for arrays, the first offending index;
* a missing optional package raises ``ImportError`` naming the extra that
  installs it (:func:`require`).
"""

from __future__ import annotations

import importlib
import importlib.util
import math
import numbers
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any

import numpy as np

__all__ = [
    "approach",
    "as_real_array",
    "callback",
    "scalar",
    "whole",
    "vector3",
    "require",
    "available",
    "broadcast",
    "check",
    "validated",
    "row_problems",
    "rule_problems",
    "RULES",
    "LARGEST",
    "SMALLEST",
]

#: Largest magnitude accepted for any input. Keeping every input within
#: [1e-50, 1e50] keeps every product the formulas form (m v^2, zeta mu^2, ...)
#: far from overflow and underflow, so no result is silently inf, NaN or 0.
LARGEST = 1e50
#: Smallest magnitude accepted for strictly positive inputs (mass, radius, ``|vy|``, ...).
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


def _holds_masked_array(value: object) -> bool:
    """Whether ``value`` is a masked array or a (nested) list or tuple holding one;
    level by level, so a long list of plain numbers costs one pass over their types."""
    level = [value]
    while level:
        kinds = set(map(type, level))
        if any(issubclass(k, np.ma.MaskedArray) for k in kinds):
            return True
        if not any(issubclass(k, list | tuple) for k in kinds):
            return False
        level = [x for seq in level if isinstance(seq, list | tuple) for x in seq]
    return False


def _masked_index(value: object) -> tuple[int, ...] | None:
    """The first index of ``value`` (a masked array, or a list or tuple holding one)
    hidden behind a mask (``()`` for a masked scalar), or ``None``."""
    if isinstance(value, np.ma.MaskedArray):
        hidden = np.ma.getmaskarray(value)
        return tuple(int(i) for i in np.argwhere(hidden)[0]) if hidden.any() else None
    if isinstance(value, list | tuple):
        for i, item in enumerate(value):
            inner = _masked_index(item)
            if inner is not None:
                return (i, *inner)
    return None


def as_real_array(name: str, value: object) -> np.ndarray:
    """Convert ``value`` to a finite float64 array.

    Parameters
    ----------
    name : str
        Parameter name used in the error message.
    value : array_like
        Number or array of numbers.

    Raises
    ------
    TypeError
        If ``value`` is not a real number or an array of them (a string, ``None``,
        a bool, a complex number, a ragged sequence).
    ValueError
        If an element is not finite or exceeds :data:`LARGEST` in magnitude, or is
        masked: NumPy would silently compute with the value under a masked array's
        mask, so a masked element is refused (a masked array with nothing masked is
        its data).
    """
    where = _masked_index(value) if _holds_masked_array(value) else None
    if where is not None:
        at = f" (first masked index {where[0] if len(where) == 1 else where})" if where else ""
        raise ValueError(
            f"{name} must not have masked (missing) elements{at}: fill them "
            f"(.filled(value)) or drop them (.compressed()) first"
        )
    try:
        raw = np.asarray(value)
    except (ValueError, TypeError):  # ragged nested sequences
        raise TypeError(
            f"{name} must be a real number or array of numbers, got {value!r}"
        ) from None
    if raw.dtype.kind not in "iuf":  # not bool, str, None, complex, object
        raise TypeError(f"{name} must be a real number or array of numbers, got {value!r}")
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
    # A body's gyration may be its radius over sqrt(MAX_ZETA) (R/rho up to 1e10), so the
    # smallest accepted radius, SMALLEST, allows rho down to SMALLEST/1e10; J = m rho^2
    # then stays above 1e-170, far from underflow.
    "gyration": [
        (lambda a: a > 0, "> 0"),
        (lambda a: a >= SMALLEST / math.sqrt(MAX_ZETA), f">= {SMALLEST / math.sqrt(MAX_ZETA):g}"),
    ],
    # a ball's launch (spinimpact.flight): speed in m/s, elevation in degrees, height in m
    "speed": [(lambda s: s >= 0, ">= 0")],
    "elevation_deg": [(lambda a: np.abs(a) <= 90, "in [-90, 90]")],
    "launch_height": [(lambda h: h > 0, "> 0")],
}


def approach(name: str, velocity: np.ndarray, who: str) -> None:
    """Refuse a normal approach velocity as ``RULES["vy"]`` refuses ``vy``.

    ``velocity`` must be ``< 0`` (``who`` completes "(... must approach ...)", e.g. "the
    sphere must approach the surface") and ``<= -SMALLEST``: a slower approach grazes the
    surface, and the impulses, which divide by it, would be infinite or NaN.
    """
    (approaches, _), (fast_enough, rule) = RULES["vy"]
    check(name, velocity, approaches, f"< 0 ({who})")
    check(name, velocity, fast_enough, f"{rule} (a slower approach only grazes the surface)")


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
    return rule_problems(name, values, RULES[name])


def rule_problems(
    name: str, values: np.ndarray, rules: Sequence[tuple[Callable, str]] = ()
) -> np.ndarray:
    """Per-element message of what breaks ``rules`` ('' where nothing): a number must be
    finite, at most :data:`LARGEST` in magnitude, then pass each ``(ok, rule)`` of
    ``rules``; an element is named by the first it breaks.

    Returns
    -------
    numpy.ndarray
        A cheap array of ``''`` (fixed-width) where every element passes, else an object
        array of messages such as ``"mass must be > 0, got -1.0"``.
    """
    values = np.asarray(values, dtype=np.float64)
    every = [(np.isfinite, "finite"),
             (lambda a: np.abs(a) <= LARGEST, f"at most {LARGEST:g} in magnitude"),
             *rules]  # fmt: skip
    with np.errstate(invalid="ignore"):
        bad = [(~np.asarray(ok(values), dtype=bool), rule) for ok, rule in every]
    if not any(mask.any() for mask, _ in bad):  # the common case: no message to make
        return np.zeros(values.shape, dtype="U1")
    out = np.full(values.shape, "", dtype=object)
    named = np.zeros(values.shape, dtype=bool)
    for mask, rule in bad:
        for i in np.flatnonzero(mask & ~named):
            out[i] = f"{name} must be {rule}, got {float(values[i])!r}"
        named |= mask
    return out


def scalar(name: str, value: object, rules_for: str | None = None, *, why: str = "") -> float:
    """One real number: :func:`validated` (or :func:`as_real_array` when ``rules_for``
    is ``None`` and ``name`` has no rules), then a check that it is not an array.

    ``why`` completes the error for an array, e.g. ``"simulate() integrates one
    impact at a time"``.
    """
    rules = rules_for or (name if name in RULES else None)
    arr = validated(name, value, rules) if rules else as_real_array(name, value)
    if arr.ndim:
        reason = f": {why}" if why else ""
        raise ValueError(f"{name} must be a single number, got an array of shape {arr.shape}"
                         f"{reason}")  # fmt: skip
    return float(arr)


def vector3(name: str, value: object) -> np.ndarray:
    """A finite real 3-vector or an array of them (last axis of length 3), read-only.

    ``TypeError`` for what is not numbers (:func:`as_real_array`), ``ValueError`` naming
    ``name`` for a last axis that is not of length 3 or a non-finite component.
    """
    arr = as_real_array(name, value)
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(
            f"{name} must be a 3-vector (x, y, z) or an array of them along the last axis, "
            f"got shape {arr.shape}"
        )
    return arr


def whole(name: str, value: object, low: int | None = None) -> int:
    """A whole number (a Python or NumPy integer, not a bool), optionally ``>= low``.

    Raises ``TypeError`` for anything else (``2.5``, ``"5"``, ``True``) and
    ``ValueError`` below ``low``; both name the parameter and the value.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer, got {value!r}")
    if low is not None and value < low:
        raise ValueError(f"{name} must be an integer >= {low}, got {value!r}")
    return int(value)


def callback(name: str, value: Any, call: str) -> Any:
    """``value`` if it is ``None`` or callable, else a ``TypeError`` naming ``name`` and how
    it is called (``call``, e.g. ``"progress(done, total)"``), before any work starts."""
    if value is not None and not callable(value):
        raise TypeError(f"{name} must be a callable {call}, or None, got {value!r}")
    return value


def setting(
    name: str, value: Any, *, low: float | None = None, closed: bool = False, rule: str = ""
) -> float:
    """A finite real keyword setting (a Python or NumPy number, not a bool or array),
    optionally ``> low`` (``>= low`` with ``closed=True``); ``rule`` completes
    "``name`` must be ..." in the error."""
    text = rule or "a finite real number"
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be {text}, got {value!r}")
    v = float(value)
    if not math.isfinite(v) or (low is not None and (v < low if closed else v <= low)):
        raise ValueError(f"{name} must be {text}, got {value!r}")
    return v


#: Optional extras: import name -> (distribution, extra of ``spinimpact`` that installs it).
EXTRAS: dict[str, tuple[str, str]] = {
    "numba": ("numba", "fast"),
    "pyarrow": ("pyarrow", "parquet"),
    "dask": ("dask", "dask"),
    "distributed": ("distributed", "dask"),
    "pybullet": ("pybullet", "engines"),
    "mujoco": ("mujoco", "engines"),
    "pydrake": ("drake", "engines"),
    "jax": ("jax", "jax"),
}


def available(module: str) -> bool:
    """Whether the optional ``module`` (e.g. ``"numba"``, ``"pyarrow.parquet"``) can be
    imported, without importing it."""
    try:
        return importlib.util.find_spec(module.split(".")[0]) is not None
    except (ImportError, ValueError):
        return False


def require(module: str, purpose: str) -> ModuleType:
    """Import the optional ``module`` or raise ``ImportError`` naming the extra.

    Parameters
    ----------
    module : str
        Import name, e.g. ``"pyarrow.parquet"``; its top-level package must be a key
        of :data:`EXTRAS`.
    purpose : str
        What needs it, completing "``purpose`` needs ...", e.g. ``"Parquet files"``.

    Raises
    ------
    ImportError
        If the package is missing; the message names ``pip install
        'spinimpact[EXTRA]'``. A package that is installed but fails to load (a compiled
        library that cannot be mapped for want of memory) raises its own error.
    """
    top = module.split(".")[0]
    if top not in EXTRAS:
        raise KeyError(f"{top} is not an optional dependency of spinimpact")
    dist, extra = EXTRAS[top]
    try:
        return importlib.import_module(module)
    except ImportError as err:
        if not isinstance(err, ModuleNotFoundError):
            raise  # installed but failed to load (e.g. no address space left to map it)
        raise ImportError(
            f"{purpose} needs {dist}, which is not installed: pip install 'spinimpact[{extra}]'",
            name=top,
        ) from err
