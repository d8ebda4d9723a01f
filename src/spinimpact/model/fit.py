r"""Fit friction, restitution and the body's gyration to measured bounces.

:func:`fit` finds the parameters of a rebound model that best explain measured
rebounds (weighted least squares, the Gaussian maximum likelihood), with standard
errors from the curvature and confidence intervals from the profile likelihood. The
model is evaluated on all bounces at once (:mod:`spinimpact.model.fit_models`); the
profile and the intervals are in :mod:`spinimpact.model.fit_profile`.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import _long as long
from .._validation import setting
from .._words import count
from .body import Body
from .fit_checks import NoScatterError, refuse_impossible, scatter
from .fit_data import SIGMAS, MeasuredBounces
from .fit_models import FitModel, make_model
from .fit_profile import Intervals, Problem, curvature, intervals, minimize, threshold
from .fit_result import FitResult, FitWarning
from .presets import Ball

__all__ = [
    "fit",
    "FitResult",
    "FitWarning",
    "NoScatterError",
    "Estimation",
    "estimate",
    "refuse_impossible",
    "scatter",
    "summary",
]


def _start(fm: FitModel, bounces: MeasuredBounces, given: Mapping[str, float]) -> np.ndarray:
    """Starting values from the data: restitution from the measured ``vy^+``, the body's
    gyration; ``mu`` is chosen afterwards by a scan (:func:`fit`)."""
    speed = -bounces.vy
    ratio = bounces.after_vy / speed
    ok = np.isfinite(ratio) & (ratio > 0)
    k0 = float(np.clip(np.median(ratio[ok]), 0.05, 0.99)) if ok.any() else 0.8
    theta = []
    for p in fm.parameters:
        if p.name in given:
            theta.append(float(given[p.name]))
        elif p.name == "mu":
            theta.append(0.1)
        elif p.name in ("kappa", "kappa_ref") or p.name.startswith("kappa_at_"):
            theta.append(k0)
        elif p.name == "exponent":
            slope = 0.0  # the log-log slope of the measured kappa over the speed, if any
            if ok.sum() > 1 and np.ptp(speed[ok]) > 0:
                slope = np.polyfit(np.log(speed[ok]), np.log(ratio[ok]), 1)[0]
            theta.append(float(np.clip(slope, -1.0, 1.0)))
        else:  # gyration
            theta.append(float(np.mean(fm.body.gyration)))
    return np.array(theta)


def _values(what: str, fm: FitModel, given: Mapping[str, float] | None) -> dict[str, float]:
    """``fixed`` or ``start``: known parameter names, each value within its bounds."""
    if given is None:
        return {}
    if not isinstance(given, Mapping):
        raise TypeError(f"{what} must be a dict of parameter name to value, got {given!r}")
    out = {}
    for name, value in given.items():
        if name not in fm.names:
            raise ValueError(f"{what} names an unknown parameter {name!r}; "
                             f"this model has {', '.join(fm.names)}")  # fmt: skip
        p = fm.parameters[fm.names.index(name)]
        v = setting(f"{what}[{name!r}]", value)
        if not p.low <= v <= p.high:
            raise ValueError(f"{what}[{name!r}] must be in [{p.low:g}, {p.high:g}], got {value!r}")
        out[name] = v
    return out


def _impossible(bounces: MeasuredBounces) -> None:
    """Refuse measured normal rebounds no impact can give, beyond the measurement's noise:
    into the surface (``after_vy < 0``), or faster than the impact (``after_vy > -vy``)."""
    refuse_impossible(bounces.vy, bounces.after_vy, bounces.sigma_after_vy)


def _scatter(prob: Problem, chi2: float) -> float:
    """The variance ``s^2 = chi2/dof`` estimated from the scatter (1 with sigmas given);
    :class:`NoScatterError` where it is 0 to rounding (``s`` below ``1e-8`` of the
    measured values' size)."""
    return scatter(prob, chi2, float(np.mean(-prob.bounces.vy)), SIGMAS)


@dataclass
class Estimation:
    """What :func:`estimate` found: the optimizer's result, the estimate of the free
    parameters, the variance scale, the covariance, standard errors and intervals, and a
    warning to give (``None`` when it converged)."""

    best: Any
    x: np.ndarray
    s2: float
    covariance: np.ndarray
    standard_error: np.ndarray
    intervals: Intervals
    warning: str | None


#: Evaluations of the model a fit makes per free parameter, for its estimate of its own time:
#: an upper figure (fits of 40 bounces measured 75 a parameter with the rigid law, 87 with
#: Walton's, 183 with Stronge's: least squares, finite-difference curvature, profiles).
EVALUATIONS_PER_PARAMETER = 200


def fit_cost(prob: Problem, x0: np.ndarray, force: bool, announce: Any) -> None:
    """The rule of every long run (:mod:`spinimpact._long`) for a fit: one evaluation of the
    model over all bounces, timed, times :data:`EVALUATIONS_PER_PARAMETER` per free
    parameter; said first over a minute (``announce``), refused over an hour unless
    ``force``."""
    start = long.clock()
    prob.residual(x0)
    took = long.clock() - start
    k = int(np.sum(prob.free))
    n = prob.mask.shape[0]
    what = f"this fit ({count(n, 'bounce')}, {count(k, 'free parameter')})"
    cost = long.Estimate(what, took * EVALUATIONS_PER_PARAMETER * k,
                         "one evaluation of the model over all its bounces")  # fmt: skip
    cost.check(force)
    if announce is not None and cost.announced:
        announce(cost)


def estimate(prob: Problem, x0: np.ndarray, conf: float, scatter: Any, *, force: bool = False,
             announce: Any = None) -> Estimation:  # fmt: skip
    """Least squares from ``x0``, then the curvature and the profile intervals; where a
    profile meets a lower ``chi2`` (several minima), start again from there (at most
    twice). ``scatter(prob, chi2)`` gives the variance scale ``s^2`` (1 with sigmas) or
    raises where it cannot be estimated. Shared by :func:`fit` and
    :func:`spinimpact.fit_problem`, whatever model ``prob`` holds. First, its time is
    estimated (:func:`fit_cost`)."""
    fit_cost(prob, x0, force, announce)
    best = minimize(prob, x0)
    for attempt in range(3):
        x = best.x
        s2 = scatter(prob, prob.chi2(x))
        cov, se = curvature(prob, x, s2)
        ivals = intervals(prob, x, conf, se)
        if ivals.better is None or attempt == 2:
            break
        best = minimize(prob, ivals.better)  # a profile met a lower chi2: start again there
    warning = None
    if not best.success:
        warning = f"the fit did not converge: {best.message}"
    elif ivals.better is not None:
        text = "its profiles keep finding lower chi2 (several minima?); try other start values"
        warning = f"the fit did not converge: {text}"
    return Estimation(best, x, s2, cov, se, ivals, warning)


def fit(
    bounces: MeasuredBounces,
    body: Body | Ball,
    *,
    model: str = "rigid",
    restitution: str | Sequence[float] = "constant",
    free_gyration: bool = False,
    fixed: Mapping[str, float] | None = None,
    start: Mapping[str, float] | None = None,
    confidence: float = 0.95,
    reference_speed: float | None = None,
    force: bool = False,
    announce: Callable[[Any], None] | None = None,
) -> FitResult:
    r"""Fit a rebound model to measured bounces, with honest uncertainties.

    Parameters
    ----------
    bounces : MeasuredBounces
        Incidences, measured rebounds (any value may be missing) and, optionally,
        their standard deviations.
    body : Body or Ball
        The body (a :class:`~spinimpact.Ball` is taken as its ``body``); required, as
        its ``zeta = 1 + R^2/rho^2`` decides how much a bounce's spin changes. Its radius
        turns spin into contact-point speed; its mass does not matter (the rebound
        velocities do not depend on it).
    model : {"rigid", "walton", "stronge", "mindlin-deresiewicz"}
        The tangential model (:data:`~spinimpact.model.fit_models.TANGENTIAL`):
        ``"rigid"`` (Coulomb friction ``mu``, the paper's closed form);
        ``"walton"`` (``mu`` and Walton's tangential restitution ``beta0`` of
        :class:`~spinimpact.model.compliance.Walton`); ``"stronge"`` (``mu`` and the
        ``poisson_ratio`` of :class:`~spinimpact.model.compliance.Stronge`'s lumped
        tangential compliance); ``"mindlin-deresiewicz"`` (``mu`` and the
        ``poisson_ratio`` of Hertz-Mindlin-Deresiewicz micro-slip,
        :class:`~spinimpact.model.compliance.MindlinDeresiewicz`: read from its table where
        ``kappa >= 0.85``, solved in time, much slower, elsewhere).
    restitution : {"constant", "power"} or sequence of float
        ``kappa`` constant; ``kappa = kappa_ref (|vy|/v_ref)^exponent`` (clipped to
        ``[0, 1]``); or knot speeds (m/s) at which ``kappa`` is fitted and between which
        it is interpolated linearly in ``|vy|``.
    free_gyration : bool
        Fit the radius of gyration ``rho`` (m) too, instead of taking the body's.
    fixed : dict, optional
        Parameters held at given values, e.g. ``{"kappa": 0.98}`` from a drop test.
    start : dict, optional
        Starting values (by default from the data, and a scan over ``mu``).
    confidence : float
        Level of the confidence intervals, in ``(0.5, 1)``.
    reference_speed : float, optional
        ``v_ref`` of the power law, m/s (default: geometric mean of ``|vy|``).
    force : bool
        Run a fit estimated to take over an hour (the rule of every long run,
        :mod:`spinimpact._long`: one evaluation of the model timed, times the evaluations a
        fit makes); without it such a fit raises :class:`~spinimpact._long.TooLong`.
    announce : callable, optional
        Called with the estimate before a fit estimated over a minute starts.

    Returns
    -------
    FitResult
        Estimates, standard errors, covariance, correlation, profile-likelihood
        intervals, residuals, ``chi2``, AIC, BIC, and which bounces slid.

    Raises
    ------
    TypeError, ValueError
        For bad options, a fixed or starting value outside its parameter's range, or
        fewer measured values than free parameters plus one ("too few usable values").
    ValueError
        For measured rebounds no bounce can give, beyond the noise: ``after_vy < 0``
        (into the surface) or ``after_vy > -vy`` (faster than the impact), by more than
        5 ``sigma_after_vy``, or without sigmas by more than 5 % of ``-vy``; the error
        names the rows (their indices) and values.
    NoScatterError
        A ``ValueError``: without sigmas, when the measured values fit the model to
        rounding (identical rows, a single bounce, noise-free data): the standard
        deviation estimated from their scatter would be 0 and every interval of zero
        width. Give the sigmas.

    Warns
    -----
    FitWarning
        When the optimizer does not converge (``converged`` is then ``False``).

    Notes
    -----
    The estimate minimizes :math:`\chi^2(\theta) = \sum_i ((y_i - f_i(\theta))/\sigma_i)^2`
    over the measured values only. Without sigmas, velocities are weighted in m/s and
    spins as ``R omega``, one common :math:`\sigma` is estimated as
    :math:`s^2 = \chi^2_{min}/\nu` (:math:`\nu` degrees of freedom) and the covariance
    is scaled by it, as :func:`scipy.optimize.curve_fit` does without ``absolute_sigma``.

    The interval of each parameter is the set of values whose profile
    :math:`\chi^2` (the other parameters re-fitted) rises by less than the
    :math:`\chi^2_1` quantile at ``confidence`` (known sigmas) or by less than
    :math:`s^2 F_{1,\nu}` (estimated sigma) [1]_. Unlike :math:`\pm 1.96` standard
    errors it follows the model's kinks and the parameter's bounds, and where the
    likelihood is flat to infinity, as for ``mu`` when every bounce sticks, it gives
    a one-sided lower bound (at the one-sided level, :math:`\chi^2_1` at
    ``2 confidence - 1``) instead of a meaningless symmetric interval.

    References
    ----------
    .. [1] D. J. Venzon and S. H. Moolgavkar, "A method for computing
       profile-likelihood-based confidence intervals", Applied Statistics 37 (1988)
       87-94.

    Examples
    --------
    >>> import numpy as np
    >>> from spinimpact import Body, MeasuredBounces, fit, solve
    >>> ball = Body.solid_sphere(mass=0.06, radius=0.033)
    >>> vx = np.linspace(1.0, 12.0, 12); vy = np.full(12, -4.0); om = np.zeros(12)
    >>> true = solve(ball, vx, vy, om, mu=0.3, kappa=0.7).after
    >>> data = MeasuredBounces(vx, vy, om, true.vx, true.vy, true.omega,
    ...                        sigma_after_vx=0.05, sigma_after_vy=0.05, sigma_after_omega=2.0)
    >>> res = fit(data, ball)
    >>> round(res["mu"].estimate, 6), round(res["kappa"].estimate, 6)
    (0.3, 0.7)
    >>> print(res.identifiability)
    5 bounce(s) slid throughout (they determine mu), 7 stuck (they only bound mu from below)
    >>> print(res["mu"])
    mu = 0.3 +- 0.0017 [0.2967, 0.3033]
    """
    if not isinstance(bounces, MeasuredBounces):
        raise TypeError(
            f"bounces must be a spinimpact.MeasuredBounces, got {type(bounces).__name__}"
        )
    if not isinstance(free_gyration, bool):
        raise TypeError(f"free_gyration must be True or False, got {free_gyration!r}")
    conf = setting("confidence", confidence, low=0.5, rule="in (0.5, 1)")
    if conf >= 1.0:
        raise ValueError(f"confidence must be in (0.5, 1), got {confidence!r}")
    if reference_speed is not None:
        reference_speed = setting("reference_speed", reference_speed, low=0.0,
                                  rule="a speed > 0 (m/s)")  # fmt: skip
    if isinstance(body, Ball):
        body = body.body
    fm = make_model(body, bounces, tangential=model, restitution=restitution,
                    free_gyration=free_gyration, reference_speed=reference_speed)  # fmt: skip
    held = _values("fixed", fm, fixed)
    if len(held) == len(fm.names):
        raise ValueError("every parameter is fixed: nothing to fit")
    begin = _values("start", fm, start)
    _impossible(bounces)
    theta = _start(fm, bounces, {**begin, **held})
    for p in fm.parameters:  # a starting value from the data, within its bounds
        i = fm.names.index(p.name)
        if p.name not in held:
            theta[i] = float(np.clip(theta[i], p.low, p.high))
    free = np.array([n not in held for n in fm.names])
    n_obs, k = bounces.n_observations, int(free.sum())
    if n_obs <= k:
        raise ValueError(
            f"too few usable values: {n_obs} measured value(s) in {len(bounces)} bounce(s) "
            f"for {k} free parameter(s) ({', '.join(np.array(fm.names)[free])}); "
            f"need at least {k + 1}"
        )
    prob = Problem(fm, bounces, theta, free)
    if "mu" not in held and "mu" not in begin:
        prob.theta[fm.names.index("mu")] = prob.scan_mu()
    est = estimate(prob, prob.theta[free], conf, _scatter, force=force, announce=announce)
    if est.warning is not None:
        warnings.warn(est.warning, FitWarning, stacklevel=2)
    return _result(prob, est, conf, held)


def summary(prob: Problem, est: Estimation, conf: float,
            sliding: Any = None) -> dict[str, Any]:  # fmt: skip
    """The fields of a :class:`FitResult` that every fit computes alike from its least
    squares: estimates, covariance and correlation, intervals, fitted values and their
    band, residuals, ``chi2``, likelihood, AIC and BIC. ``sliding``: ``(theta, measured)
    -> (sliding, sticking)`` rows, or ``None`` (no friction regimes: neither)."""
    data, x, cov, se, ivals = prob.bounces, est.x, est.covariance, est.standard_error, est.intervals
    theta = prob.full(x)
    chi2 = prob.chi2(x)
    dof = prob.dof
    s2 = 1.0 if prob.sigma_given else chi2 / dof
    with np.errstate(invalid="ignore"):  # an infinite standard error: no correlation
        corr = cov / np.outer(se, se)
    corr[np.isinf(se)[:, None] | np.isinf(se)[None, :]] = np.nan
    np.fill_diagonal(corr, 1.0)
    fitted = prob.model.predict(theta, data)
    measured = data.measured
    obs = data.observed
    sigma = prob.sigma * np.sqrt(s2)
    sigma = np.where(measured, sigma, np.nan)
    resid = np.where(measured, obs - fitted, np.nan)
    if sliding is None:
        slid = stuck = np.zeros(len(obs), dtype=bool)
    else:
        slid, stuck = sliding(theta, measured)
    n = data.n_observations
    if prob.sigma_given:
        loglik = -0.5 * (chi2 + float(np.sum(np.log(2 * np.pi * prob.sigma[measured] ** 2))))
        k = x.size
    else:  # chi2 > 0: a fit without scatter was refused (_scatter)
        loglik = -0.5 * n * (np.log(2 * np.pi * chi2 / n) + 1.0)
        loglik += float(np.sum(np.log(1.0 / prob.sigma[measured])))  # the weights' Jacobian
        k = x.size + 1
    normalized = resid / sigma
    preds = [prob.model.predict(prob.full(e), data) for e in ivals.ends]
    lows = np.min([fitted, *preds], axis=0)
    highs = np.max([fitted, *preds], axis=0)
    return dict(
        names=tuple(np.array(prob.model.names)[prob.free].tolist()),
        estimate=x.copy(),
        standard_error=se,
        covariance=cov,
        correlation=corr,
        interval_low=ivals.low,
        interval_high=ivals.high,
        one_sided=ivals.one_sided,
        confidence=conf,
        threshold=threshold(conf, dof, prob.sigma_given),
        observed=obs,
        fitted=fitted,
        fitted_low=lows,
        fitted_high=highs,
        residuals=resid,
        normalized_residuals=normalized,
        sigma=sigma,
        sliding=slid,
        sticking=stuck,
        n_sliding=int(slid.sum()),
        n_sticking=int(stuck.sum()),
        chi2=chi2 if prob.sigma_given else float(dof),  # chi2/s^2 = dof by construction
        dof=int(dof),
        reduced_chi2=chi2 / dof if prob.sigma_given else 1.0,
        scale=float("nan") if prob.sigma_given else float(np.sqrt(s2)),
        sigma_given=prob.sigma_given,
        log_likelihood=float(loglik),
        aic=float(2 * k - 2 * loglik),
        bic=float(k * np.log(n) - 2 * loglik),
        n_bounces=len(obs),
        n_observations=n,
        converged=bool(est.best.success),
        message=str(est.best.message),
        evaluations=prob.evaluations,
        profiles=ivals.profiles,
    )


def _result(prob: Problem, est: Estimation, conf: float, held: dict[str, float]) -> FitResult:
    fm, data = prob.model, prob.bounces

    def contact(theta: np.ndarray, measured: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        tangential = measured[:, 0] | measured[:, 2]
        sliding, sticking = fm.contact(theta, data)
        return sliding & tangential, sticking & tangential

    body = {k: np.asarray(getattr(fm.body, k)).tolist() for k in ("radius", "gyration", "zeta")}
    return FitResult(
        model=fm.description,
        body={"name": fm.body.name, **body},
        fixed=held,
        incidence=np.stack([data.vx, data.vy, data.omega], axis=-1),
        incidence_angle_deg=data.incidence_angle_deg,
        **summary(prob, est, conf, contact),
    )
