"""Drop tests: the normal restitution ``kappa(|v|)`` from drop and rebound heights or
speeds, with uncertainties (:func:`fit_drops`)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from .._validation import as_real_array, check, setting
from .body import Body
from .fit import NoScatterError, fit
from .fit_data import MeasuredBounces
from .fit_models import make_model
from .fit_result import FitResult
from .restitution import STANDARD_GRAVITY

__all__ = ["fit_drops", "DropFit"]

#: Speeds at which the fitted ``kappa(v)`` and its band are drawn.
CURVE_POINTS = 81


@dataclass(frozen=True, eq=False, repr=False)
class DropFit(FitResult):
    """A :class:`~spinimpact.model.fit_result.FitResult` of drop tests
    (:func:`fit_drops`), with the drops in their own terms and the fitted ``kappa(v)``.

    Attributes
    ----------
    impact_speed, rebound_speed : ndarray
        ``(n,)``: each drop's impact and rebound speed, m/s.
    sigma_rebound_speed : ndarray
        ``(n,)``: the rebound speed's standard deviation used in the fit (the impact
        speed's added in quadrature, see :func:`fit_drops`), m/s; the common estimate
        when no sigmas were given.
    curve_speed : ndarray
        ``(m,)``: impact speeds spanning the drops', m/s.
    curve_kappa, curve_kappa_low, curve_kappa_high : ndarray
        ``(m,)``: the fitted ``kappa`` at ``curve_speed`` and its band, the least and
        greatest ``kappa`` over the ends of every profile interval (as ``fitted_low``
        and ``fitted_high``).
    """

    impact_speed: Any
    rebound_speed: Any
    sigma_rebound_speed: Any
    curve_speed: Any
    curve_kappa: Any
    curve_kappa_low: Any
    curve_kappa_high: Any

    @property
    def kappa(self) -> np.ndarray:
        """Measured ``kappa = rebound_speed / impact_speed`` of each drop."""
        return self.rebound_speed / self.impact_speed

    @property
    def sigma_kappa(self) -> np.ndarray:
        """Standard deviation of :attr:`kappa`, ``sigma_rebound_speed / impact_speed``."""
        return self.sigma_rebound_speed / self.impact_speed


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
) -> DropFit:
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
    DropFit
        A :class:`~spinimpact.model.fit_result.FitResult` with the restitution
        parameters only (``mu`` plays no part in a drop without spin: it is held at 0
        and not reported), the drops' speeds and the fitted ``kappa(v)`` with its band
        over their range.

    Raises
    ------
    TypeError, ValueError
        For values that are not numbers, no drops, a rebound above its drop, fewer drops
        than free parameters plus one ("too few drops"), or, without sigmas, drops that
        fit ``kappa`` to rounding (identical drops: no scatter to estimate an
        uncertainty from; a ``spinimpact.model.fit.NoScatterError``).

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
    if b.size == 0:
        raise ValueError(f"no drops given: the drop and rebound {what} are empty")
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
    return _fit(v0, v1, sig, restitution, confidence)


def _fit(v0: np.ndarray, v1: np.ndarray, sig: dict[str, Any], restitution: Any,
         confidence: float) -> DropFit:  # fmt: skip
    """The drops and, unmeasured (no part of chi2), drops at the speeds of the curve: the
    fit predicts them and their band as it does the measured ones."""
    n = v0.size
    low, high = float(v0.min()), float(v0.max())
    grid = np.geomspace(0.95 * low, 1.05 * high, CURVE_POINTS)
    speed = np.concatenate([v0, grid])
    after = np.concatenate([v1, np.full(grid.size, np.nan)])
    ones = np.ones(grid.size)
    sig = {k: np.concatenate([np.broadcast_to(v, v0.shape), ones]) for k, v in sig.items()}
    zeros = np.zeros_like(speed)
    data = MeasuredBounces(zeros, -speed, zeros, after_vy=after, **sig)
    body = Body.solid_sphere(mass=1.0, radius=1.0)  # drops without spin: the body plays no part
    ref = float(np.exp(np.mean(np.log(v0))))  # the power law's v_ref from the drops alone
    free = make_model(body, data, restitution=restitution, reference_speed=ref).names[1:]
    if n <= len(free):  # mu is held: the restitution's parameters are free
        raise ValueError(f"too few drops: {n} drop(s) for {len(free)} free parameter(s) "
                         f"({', '.join(free)}); need at least {len(free) + 1}")  # fmt: skip
    try:
        res = fit(data, body, restitution=restitution, fixed={"mu": 0.0},
                  confidence=confidence, reference_speed=ref)  # fmt: skip
    except NoScatterError:
        raise NoScatterError(
            f"the {n} drops show no scatter about the fitted kappa (their rebound speeds fit "
            "it to rounding): no uncertainty can be estimated from them, and every interval "
            "would have zero width; give the standard deviations of the measured heights or "
            "speeds (sigma_before and sigma_after; in a file, the sigma_ columns)"
        ) from None
    values = {f.name: getattr(res, f.name) for f in fields(FitResult)}
    for name, v in values.items():  # the measured drops' rows only
        if isinstance(v, np.ndarray) and v.shape[:1] == (n + grid.size,):
            values[name] = v[:n]
    values.update(
        model=res.model.replace("rigid, ", "drop tests, ").replace("|vy|", "|v|"),
        body=None,  # the body plays no part in a drop without spin
        fixed={},  # mu plays no part in a drop without spin
        n_bounces=n,
        impact_speed=v0,
        rebound_speed=v1,
        sigma_rebound_speed=res.sigma[:n, 1],
        curve_speed=grid,
        curve_kappa=res.fitted[n:, 1] / grid,
        curve_kappa_low=res.fitted_low[n:, 1] / grid,
        curve_kappa_high=res.fitted_high[n:, 1] / grid,
    )
    return DropFit(**values)
