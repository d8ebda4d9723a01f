"""What a fit refuses in measured data: rebounds no bounce can give, and data without the
scatter a standard deviation could be estimated from (:func:`spinimpact.fit`,
:func:`spinimpact.fit_drops`, :func:`spinimpact.fit_problem`)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .fit_profile import Problem

__all__ = ["NOISE_SIGMAS", "NOISE_FRACTION", "NAMED_ROWS", "refuse_impossible", "NoScatterError",
           "scatter"]  # fmt: skip

#: A measured ``after_vy`` may pass the bounds of a rebound (``0 <= after_vy <= -vy``) by
#: this many of its standard deviations, or, without sigmas, by this fraction of ``-vy``:
#: near ``kappa = 0`` or ``1`` noise crosses them; beyond, the row is a mistake.
NOISE_SIGMAS = 5.0
NOISE_FRACTION = 0.05
#: Rows an error names one by one; the rest are counted.
NAMED_ROWS = 5


def refuse_impossible(
    before: np.ndarray,
    up: np.ndarray,
    sigma: np.ndarray | None,
    *,
    after_name: str = "after_vy",
    before_name: str = "vy",
) -> None:
    """Refuse measured normal rebounds ``up`` (NaN: not measured) that no impact with the
    normal approach velocities ``before`` (< 0) can give, beyond the noise: into the
    surface (``up < 0``) or faster than the impact (``up > -before``), by more than
    :data:`NOISE_SIGMAS` of ``sigma`` or, without sigmas, :data:`NOISE_FRACTION` of
    ``-before``. The error names the rows (their indices) and values."""
    speed = -np.asarray(before, dtype=float)
    if sigma is None:
        slack = NOISE_FRACTION * speed
        allowance = (f"{100 * NOISE_FRACTION:g} % of the impact speed -{before_name} without "
                     f"sigmas; give sigma_{after_name} to judge by the measurement's own "
                     "noise")  # fmt: skip
    else:
        slack = NOISE_SIGMAS * np.where(np.isnan(up), 0.0, sigma)
        allowance = f"{NOISE_SIGMAS:g} sigma_{after_name}"
    measured = ~np.isnan(up)
    into = measured & (np.where(measured, up, 0.0) < -slack)
    faster = measured & (np.where(measured, up, 0.0) > speed + slack)
    bad = np.flatnonzero(into | faster)
    if not bad.size:
        return
    items = [f"{after_name} = {up[i]:g} m/s at index {i} "
             f"({'into the surface' if into[i] else 'faster than the impact'}, "
             f"{before_name} = {-speed[i]:g} m/s)" for i in bad[:NAMED_ROWS]]  # fmt: skip
    if bad.size > NAMED_ROWS:
        items.append(f"and {bad.size - NAMED_ROWS} more")
    raise ValueError(
        f"impossible rebound(s): a bounce leaves the surface ({after_name} >= 0) no faster "
        f"than it came ({after_name} <= -{before_name}), within the noise ({allowance}); "
        "got " + "; ".join(items)
    )


class NoScatterError(ValueError):
    """The measured values fit the model to rounding and no sigmas were given: the one
    standard deviation a fit estimates from the scatter would be 0, and every interval
    of zero width."""


def scatter(prob: Problem, chi2: float, size: float, sigmas: Sequence[str]) -> float:
    """The variance ``s^2 = chi2/dof`` a fit estimates from the scatter (1 with sigmas given);
    :class:`NoScatterError` where it is 0 to rounding (``s`` below ``1e-8`` of the measured
    values' size). ``size`` is a speed the measured values' scatter is
    judged against (besides their own size, m/s), ``sigmas`` the names of the sigma
    columns the error asks for."""
    if prob.sigma_given:
        return 1.0
    s2 = chi2 / prob.dof
    size = max(float(np.sqrt(np.mean(np.square(prob.observed * prob.weight)))), size)
    if np.sqrt(s2) <= 1e-8 * size:
        n = int(prob.mask.sum())
        raise NoScatterError(
            f"the {n} measured values show no scatter about the fitted model (the standard "
            f"deviation estimated from them is {np.sqrt(s2):.3g} m/s, zero to rounding): no "
            "uncertainty can be estimated from them, and every interval would have zero "
            f"width; give the standard deviations of the measured values ({', '.join(sigmas)})"
        )
    return s2
