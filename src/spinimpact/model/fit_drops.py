"""Drop tests: the normal restitution ``kappa(|v|)`` from drop and rebound heights or
speeds, with uncertainties (:func:`fit_drops`)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from .._validation import as_real_array, check, setting
from .body import Body
from .fit import fit
from .fit_data import MeasuredBounces
from .fit_result import FitResult
from .restitution import STANDARD_GRAVITY

__all__ = ["fit_drops"]


def _sigma(name: str, value: Any, shape: tuple[int, ...]) -> np.ndarray:
    s = np.broadcast_to(as_real_array(name, value), shape)
    check(name, s, lambda a: a > 0, "> 0")
    return s


def fit_drops(
    before: Sequence[float],
    after: Sequence[float],
    *,
    heights: bool = True,
    sigma_before: Any = None,
    sigma_after: Any = None,
    restitution: str | Sequence[float] = "constant",
    gravity: float = STANDARD_GRAVITY,
    confidence: float = 0.95,
) -> FitResult:
    r"""Fit ``kappa(|v|)`` to vertical drop tests without spin.

    Parameters
    ----------
    before, after : sequence of float
        Drop and rebound heights (m, ``heights=True``) or impact and rebound speeds
        (m/s, ``heights=False``), one pair per drop; ``before > 0``, ``after >= 0``.
    heights : bool
        Whether the values are heights (default) or speeds.
    sigma_before, sigma_after : float or sequence of float, optional
        Standard deviations of the measurements, same units; both or neither. Without
        them one common standard deviation of the rebound speed is estimated.
    restitution : {"constant", "power"} or sequence of float
        As for :func:`~spinimpact.model.fit.fit`.
    gravity : float
        ``g``, m/s^2, to turn heights into speeds: ``v = sqrt(2 g h)``.
    confidence : float
        Level of the confidence intervals.

    Returns
    -------
    FitResult
        With the restitution parameters only (``mu`` plays no part in a drop without
        spin and is held at 0).

    Notes
    -----
    Each drop is a bounce with ``vx = omega = 0`` and ``vy = -v_before``; its measured
    rebound is ``after_vy = v_after``. A height's standard deviation becomes the
    speed's by :math:`\sigma_v = g \sigma_h / v` (first order in :math:`\sigma_h`). The
    uncertainty of the impact speed moves the prediction ``kappa v_before`` too; it is
    added to the rebound's in quadrature with the slope taken as the measured ratio
    :math:`v_{after}/v_{before}` (the effective-variance method, first order, the
    slope of ``kappa(v)`` itself neglected).

    Examples
    --------
    >>> res = fit_drops([1.0, 0.5, 0.25], [0.64, 0.32, 0.16], sigma_before=0.002,
    ...                 sigma_after=0.002)
    >>> round(res["kappa"].estimate, 6)
    0.8
    """
    g = setting("gravity", gravity, low=0.0, rule="a finite acceleration > 0 (m/s^2)")
    if not isinstance(heights, bool):
        raise TypeError(f"heights must be True or False, got {heights!r}")
    what = "heights" if heights else "speeds"
    b = as_real_array(f"drop {what}", before)
    a = as_real_array(f"rebound {what}", after)
    if b.ndim != 1 or a.shape != b.shape:
        raise ValueError(f"drop and rebound {what} must be 1-D of one length, got shapes "
                         f"{b.shape} and {a.shape}")  # fmt: skip
    check(f"drop {what}", b, lambda x: x > 0, "> 0")
    check(f"rebound {what}", a, lambda x: x >= 0, ">= 0")
    higher = np.flatnonzero(a > b)
    if higher.size:
        i = int(higher[0])
        one = what[:-1]
        raise ValueError(f"rebound {one} {float(a[i])!r} > drop {one} {float(b[i])!r} at "
                         f"index {i} (a ball cannot rebound higher than it fell)")  # fmt: skip
    if (sigma_before is None) != (sigma_after is None):
        raise ValueError("give sigma_before and sigma_after together, or neither")
    v0 = np.sqrt(2 * g * b) if heights else b
    v1 = np.sqrt(2 * g * a) if heights else a
    sig = {}
    if sigma_before is not None:
        s0, s1 = (
            _sigma("sigma_before", sigma_before, b.shape),
            _sigma("sigma_after", sigma_after, a.shape),
        )
        if heights:  # sigma_v = g sigma_h / v, kept finite at a rebound of zero height
            s0 = g * s0 / v0
            s1 = np.where(v1 > 0, g * s1 / np.maximum(v1, 1e-300), np.sqrt(2 * g * s1))
        s = np.hypot(s1, (v1 / v0) * s0)
        sig = {"sigma_after_vx": 1.0, "sigma_after_vy": s, "sigma_after_omega": 1.0}
    zeros = np.zeros_like(v0)
    data = MeasuredBounces(zeros, -v0, zeros, after_vy=v1, **sig)
    body = Body.solid_sphere(mass=1.0, radius=1.0)  # drops without spin: the body plays no part
    return fit(data, body, restitution=restitution, fixed={"mu": 0.0}, confidence=confidence)
