"""Restitution models: the coefficient of normal restitution as a function of
the impact speed ``|v^-|`` (paper section 3).

The paper notes that ``kappa`` depends on ``v^-`` and is independent of ``mu``,
so ``kappa(|v^-|)`` can be measured by dropping the body vertically without
spin at several speeds and then used for any oblique, spinning impact with the
same normal speed. :func:`spinimpact.solve` accepts any callable
``kappa(speed) -> array``; the classes here are the common ones.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .._validation import as_real_array, check, scalar, setting, validated

__all__ = ["RestitutionModel", "ConstantRestitution", "TabulatedRestitution", "STANDARD_GRAVITY"]

#: Standard gravity in m/s^2, used to turn drop heights into impact speeds.
STANDARD_GRAVITY = 9.80665


class RestitutionModel:
    """Base class: ``model(speed)`` returns ``kappa`` for impact speeds ``|v^-|`` in m/s."""

    def __call__(self, speed: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError


class ConstantRestitution(RestitutionModel):
    """The same ``kappa`` (one number in ``[0, 1]``) at every impact speed.

    Examples
    --------
    >>> float(ConstantRestitution(0.7)(3.0))
    0.7
    """

    def __init__(self, kappa: float) -> None:
        self.kappa = scalar("kappa", kappa)

    def __call__(self, speed: np.ndarray) -> np.ndarray:
        return np.full(as_real_array("speed", speed).shape, self.kappa)

    def __repr__(self) -> str:
        return f"ConstantRestitution({self.kappa:g})"


class TabulatedRestitution(RestitutionModel):
    """``kappa`` interpolated linearly in speed from measured pairs.

    Parameters
    ----------
    speeds : sequence of float
        Impact speeds ``|v^-|`` in m/s, strictly increasing, ``>= 0``.
    kappas : sequence of float
        Measured restitution at those speeds, each in ``[0, 1]``.
    extrapolate : {"clip", "error"}
        Outside the measured speeds, ``"clip"`` (default) holds the end values
        and ``"error"`` raises ``ValueError``.

    Examples
    --------
    >>> model = TabulatedRestitution(speeds=[1.0, 3.0], kappas=[0.9, 0.7])
    >>> float(model(2.0))
    0.8
    """

    def __init__(
        self, speeds: Sequence[float], kappas: Sequence[float], *, extrapolate: str = "clip"
    ) -> None:
        s = as_real_array("speeds", speeds)
        k = validated("kappas", kappas, "kappa")
        if s.ndim != 1 or k.shape != s.shape or s.size < 1:
            raise ValueError(
                f"speeds and kappas must be 1-D and of equal non-zero length, "
                f"got shapes {s.shape} and {k.shape}"
            )
        check("speeds", s, lambda a: a >= 0, ">= 0")
        if np.any(np.diff(s) <= 0):
            i = int(np.argmax(np.diff(s) <= 0)) + 1
            raise ValueError(
                f"speeds must be strictly increasing, got {float(s[i])!r} at index {i}"
            )
        if not isinstance(extrapolate, str):
            raise TypeError(f"extrapolate must be 'clip' or 'error', got {extrapolate!r}")
        if extrapolate not in ("clip", "error"):
            raise ValueError(f"extrapolate must be 'clip' or 'error', got {extrapolate!r}")
        self.speeds, self.kappas, self.extrapolate = s, k, extrapolate

    @classmethod
    def from_drop_heights(
        cls,
        drop_heights: Sequence[float],
        rebound_heights: Sequence[float],
        *,
        gravity: float = STANDARD_GRAVITY,
        extrapolate: str = "clip",
    ) -> TabulatedRestitution:
        """From vertical drop tests without spin: ``|v^-| = sqrt(2 g h_drop)`` and
        ``kappa = sqrt(h_rebound/h_drop)`` (Newton's definition, eq. 1.1).

        Parameters
        ----------
        drop_heights : sequence of float
            Heights the body falls from, m, ``> 0`` and distinct.
        rebound_heights : sequence of float
            Heights it rises back to, m, ``>= 0``, one per drop.
        gravity : float
            ``g``, m/s^2, ``> 0`` (default :data:`STANDARD_GRAVITY`).
        extrapolate : {"clip", "error"}
            As for the constructor.

        Examples
        --------
        >>> m = TabulatedRestitution.from_drop_heights([1.0], [0.64])
        >>> round(float(m.kappas[0]), 12)
        0.8
        """
        g = setting("gravity", gravity, low=0.0, rule="a finite acceleration > 0 (m/s^2)")
        h0 = as_real_array("drop_heights", drop_heights)
        h1 = as_real_array("rebound_heights", rebound_heights)
        check("drop_heights", h0, lambda a: a > 0, "> 0")
        check("rebound_heights", h1, lambda a: a >= 0, ">= 0")
        if h0.shape != h1.shape:
            raise ValueError(
                f"drop_heights and rebound_heights must have the same shape, "
                f"got {h0.shape} and {h1.shape}"
            )
        if np.unique(h0).size != h0.size:
            raise ValueError(f"drop_heights must be distinct, got {h0.tolist()}")
        check("rebound_heights", h1 - h0, lambda a: a <= 0,
              "<= drop_heights (a ball cannot rebound higher than it fell)")  # fmt: skip
        order = np.argsort(h0)
        return cls(
            np.sqrt(2.0 * g * h0[order]),
            np.sqrt(h1[order] / h0[order]),
            extrapolate=extrapolate,
        )

    def __call__(self, speed: np.ndarray) -> np.ndarray:
        v = as_real_array("speed", speed)  # a masked speed is refused, not read through
        if self.extrapolate == "error":
            outside = (v < self.speeds[0]) | (v > self.speeds[-1])
            if np.any(outside):
                value = float(v[outside].flat[0]) if v.ndim else float(v)
                raise ValueError(
                    f"impact speed |vy| = {value!r} is outside the tabulated range "
                    f"[{self.speeds[0]:g}, {self.speeds[-1]:g}] m/s"
                )
        return np.interp(v, self.speeds, self.kappas)

    def __repr__(self) -> str:
        lo, hi = self.speeds[0], self.speeds[-1]
        return f"TabulatedRestitution({self.speeds.size} points, {lo:g}-{hi:g} m/s)"
