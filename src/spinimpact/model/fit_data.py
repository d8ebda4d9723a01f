"""Measured bounces for :func:`spinimpact.fit`: incidences, measured rebounds and their
standard deviations, checked once.

The vocabulary is the one of :class:`~spinimpact.Impact`'s columns: the incidence
``vx, vy, omega`` and the measured rebound ``after_vx, after_vy, after_omega`` (m/s,
m/s, rad/s). Any rebound value may be missing (NaN): a high-speed video may give the
spin of one bounce and only the velocities of another. Standard deviations
``sigma_after_vx, sigma_after_vy, sigma_after_omega`` are optional.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import as_real_array, check

__all__ = ["MeasuredBounces", "QUANTITIES", "INCIDENCE", "SIGMAS"]

#: The measured rebound quantities, in the order of every ``(n, 3)`` array of a fit.
QUANTITIES = ("after_vx", "after_vy", "after_omega")
#: The incidence columns, all required.
INCIDENCE = ("vx", "vy", "omega")
#: The optional standard deviations of the measured rebound, one per quantity.
SIGMAS = tuple(f"sigma_{q}" for q in QUANTITIES)


def _column(name: str, value: Any, n: int | None, *, missing_ok: bool) -> np.ndarray:
    """A 1-D float column of length ``n``; NaN allowed (as missing) only if ``missing_ok``."""
    try:
        raw = np.asarray(value)
    except (ValueError, TypeError):
        raise TypeError(
            f"{name} must be a real number or array of numbers, got {value!r}"
        ) from None
    if raw.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be a real number or array of numbers, got {value!r}")
    arr = np.array(raw, dtype=np.float64)
    if missing_ok:  # NaN means "not measured"; infinities are errors
        check(name, arr, lambda a: ~np.isinf(a), "finite or NaN (missing)")
        arr = np.where(np.isnan(arr), np.nan, as_real_array(name, np.nan_to_num(arr)))
    else:
        arr = np.array(as_real_array(name, arr))
    if arr.ndim > 1:
        raise ValueError(f"{name} must be one number per bounce (1-D), got shape {arr.shape}")
    if n is not None:
        if arr.ndim == 0:
            arr = np.full(n, float(arr))
        elif arr.shape != (n,):
            raise ValueError(f"{name} must have one value per bounce ({n}), got {arr.size}")
    return np.atleast_1d(arr)


@dataclass(frozen=True, eq=False)
class MeasuredBounces:
    """Measured bounces: incidence, measured rebound (NaN where not measured), sigmas.

    Parameters
    ----------
    vx, vy, omega : array_like
        Incidence of each bounce: centre velocity along the surface and normal to it
        (m/s, ``vy < 0``: approaching) and spin (rad/s, counter-clockwise positive).
    after_vx, after_vy, after_omega : array_like, optional
        Measured rebound, same units; NaN (or omitted) where not measured. At least one
        is needed.
    sigma_after_vx, sigma_after_vy, sigma_after_omega : array_like or float, optional
        Standard deviations of the measured rebound (> 0 where a value is measured), all
        three or none. Without them every residual is weighted alike in m/s (the spin as
        ``R omega``) and one common standard deviation is estimated from the scatter.

    Raises
    ------
    TypeError
        For values that are not real numbers.
    ValueError
        Naming the column and the first offending bounce: a non-finite incidence, a
        bounce that does not approach (``vy >= 0``), an infinite rebound, a missing or
        non-positive sigma where a value is measured, some sigmas but not all, lengths
        that differ, or no measured rebound at all.

    Examples
    --------
    >>> b = MeasuredBounces(vx=[1.0, 2.0], vy=[-3.0, -3.0], omega=[0.0, 0.0],
    ...             after_vx=[0.7, float("nan")], after_vy=[2.4, 2.4])
    >>> len(b), b.n_observations
    (2, 3)
    """

    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    after_vx: Any = None
    after_vy: Any = None
    after_omega: Any = None
    sigma_after_vx: Any = None
    sigma_after_vy: Any = None
    sigma_after_omega: Any = None

    def __post_init__(self) -> None:
        vx = _column("vx", self.vx, None, missing_ok=False)
        n = vx.size
        if n == 0:
            raise ValueError("no bounces given (vx is empty)")
        vals = {"vx": vx}
        for name in ("vy", "omega"):
            vals[name] = _column(name, getattr(self, name), n, missing_ok=False)
        check("vy", vals["vy"], lambda v: v < 0, "< 0 (each bounce must approach the surface)")
        given = [q for q in QUANTITIES if getattr(self, q) is not None]
        if not given:
            raise ValueError(
                "no measured rebound: give at least one of after_vx, after_vy, after_omega"
            )
        for q in QUANTITIES:
            value = getattr(self, q)
            vals[q] = np.full(n, np.nan) if value is None else _column(q, value, n, missing_ok=True)
        sig = [s for s in SIGMAS if getattr(self, s) is not None]
        if sig and len(sig) != 3:
            absent = [s for s in SIGMAS if s not in sig]
            raise ValueError(
                f"give all three sigmas or none: {', '.join(sig)} given, "
                f"{', '.join(absent)} missing"
            )
        for s, q in zip(SIGMAS, QUANTITIES, strict=True):
            if not sig:
                vals[s] = None
                continue
            sv = _column(s, getattr(self, s), n, missing_ok=True)
            measured = ~np.isnan(vals[q])
            check(s, np.where(measured, sv, 1.0), lambda a: a > 0,
                  f"> 0 (and given) wherever {q} is measured")  # fmt: skip
            vals[s] = sv
        for name, v in vals.items():
            if v is not None:
                v.setflags(write=False)
            object.__setattr__(self, name, v)

    @classmethod
    def from_columns(cls, columns: Mapping[str, Any]) -> MeasuredBounces:
        """MeasuredBounces from named columns (a CSV file read as a dict of arrays).

        Parameters
        ----------
        columns : mapping of str to array_like
            ``vx``, ``vy``, ``omega`` are required; ``after_vx``, ``after_vy``,
            ``after_omega`` (at least one) and ``sigma_after_*`` are optional. Other
            columns are refused, so a misspelt name is not silently ignored.

        Raises
        ------
        ValueError
            Naming a missing required column or an unknown one.
        """
        missing = [c for c in INCIDENCE if c not in columns]
        if missing:
            raise ValueError(
                f"missing column(s): {', '.join(missing)} (need {', '.join(INCIDENCE)})"
            )
        known = set(INCIDENCE) | set(QUANTITIES) | set(SIGMAS)
        unknown = [c for c in columns if c not in known]
        if unknown:
            raise ValueError(
                f"unknown column(s): {', '.join(unknown)}; the columns are "
                f"{', '.join(INCIDENCE + QUANTITIES + SIGMAS)}"
            )
        return cls(**{k: columns[k] for k in columns})

    def __len__(self) -> int:
        return int(self.vx.size)

    @property
    def observed(self) -> np.ndarray:
        """Measured rebound ``(n, 3)``: ``after_vx, after_vy, after_omega`` (NaN: missing)."""
        return np.stack([getattr(self, q) for q in QUANTITIES], axis=-1)

    @property
    def sigma(self) -> np.ndarray | None:
        """Standard deviations, shape ``(n, 3)``, or ``None`` when not given."""
        if self.sigma_after_vx is None:
            return None
        return np.stack([getattr(self, s) for s in SIGMAS], axis=-1)

    @property
    def measured(self) -> np.ndarray:
        """Which values are measured, boolean ``(n, 3)``."""
        return ~np.isnan(self.observed)

    @property
    def n_observations(self) -> int:
        """Number of measured values (the data points of the fit)."""
        return int(self.measured.sum())

    @property
    def incidence_angle_deg(self) -> np.ndarray:
        """Incidence angle of the centre's velocity from the normal, degrees, signed
        as ``vx`` (``atan2(vx, -vy)``)."""
        return np.degrees(np.arctan2(self.vx, -self.vy))

    def select(self, rows: Any) -> MeasuredBounces:
        """The bounces at ``rows`` (a boolean mask or indices), sigmas included."""
        picked = {k: getattr(self, k) for k in INCIDENCE + QUANTITIES + SIGMAS}
        return MeasuredBounces(
            **{k: None if v is None else np.asarray(v)[rows] for k, v in picked.items()}
        )

    def __repr__(self) -> str:
        return (
            f"MeasuredBounces({len(self)} bounces, {self.n_observations} measured values, "
            f"sigmas {'given' if self.sigma is not None else 'not given'})"
        )
