"""The result of :func:`spinimpact.fit`: estimates, uncertainties, residuals, goodness of fit."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .fit_data import QUANTITIES
from .result import Array, Result

__all__ = ["FitResult", "Estimate", "FitWarning"]


class FitWarning(UserWarning):
    """A fit that did not converge, or whose answer needs a caveat the numbers alone hide."""


@dataclass(frozen=True)
class Estimate:
    """One fitted parameter: estimate, standard error and confidence interval.

    ``one_sided`` is ``True`` when the data bound the parameter from one side only (the
    likelihood is flat to infinity on the other): ``low`` is then a one-sided lower bound
    at the fit's confidence and ``high`` is ``inf``.
    """

    name: str
    estimate: float
    standard_error: float
    low: float
    high: float
    one_sided: bool

    def __str__(self) -> str:
        if self.one_sided:
            return f"{self.name} >= {self.low:.4g} (one-sided; estimate {self.estimate:.4g})"
        return (f"{self.name} = {self.estimate:.4g} +- {self.standard_error:.2g} "
                f"[{self.low:.4g}, {self.high:.4g}]")  # fmt: skip


@dataclass(frozen=True, eq=False)
class FitResult(Result):
    """Everything :func:`spinimpact.fit` found, in the manner of SciPy's result objects.

    Parameters are indexed by name (or position): ``result["mu"]`` is an
    :class:`Estimate`, and iterating gives every fitted parameter's. Arrays of
    shape ``(n, 3)`` hold one row per bounce and the columns ``after_vx, after_vy,
    after_omega`` (m/s, m/s, rad/s); NaN where a value was not measured.

    Attributes
    ----------
    model : str
        The model in words: the tangential law and the normal restitution.
    body : dict or None
        The body fitted for: its ``name``, ``radius`` and ``gyration`` (m) and
        ``zeta = 1 + R^2/rho^2``, as given (a fitted gyration is among the
        parameters); ``None`` for drop tests, where the body plays no part. A radius
        and gyration of ``None`` (from ``spinimpact fit`` without ``--radius``): not
        given, as without spin the radius plays no part.
    names : tuple of str
        The fitted (free) parameters, in the order of every parameter array.
    estimate, standard_error : ndarray
        Least-squares estimates and their standard errors from the curvature
        (``inf`` for a parameter the data do not determine locally, e.g. ``mu`` when
        every bounce sticks).
    covariance, correlation : ndarray
        ``(p, p)`` matrices from the Jacobian at the estimate, ``(J^T J)^-1`` times
        the estimated variance when no sigmas were given.
    interval_low, interval_high : ndarray
        Profile-likelihood confidence interval of each parameter at ``confidence``.
    one_sided : ndarray of bool
        Which intervals are one-sided lower bounds (``interval_high`` infinite).
    confidence : float
        Confidence level of the intervals, e.g. 0.95.
    threshold : float
        The rise of a profile, ``(chi2 - chi2_min)/s^2``, that ends a two-sided interval
        (3.84 at 95 % with known sigmas).
    fixed : dict
        Parameters held fixed, with their values.
    observed, fitted, residuals, normalized_residuals, sigma : ndarray
        ``(n, 3)``: measured, fitted, ``observed - fitted``, that over ``sigma``, and the
        standard deviations used (given, or the common estimate scaled to each unit).
    fitted_low, fitted_high : ndarray
        ``(n, 3)`` band: the least and greatest prediction over the ends of every
        profile interval (each end with the other parameters profiled).
    incidence : ndarray
        ``(n, 3)``: the incidence ``vx, vy, omega`` of each bounce.
    incidence_angle_deg : ndarray
        Incidence angle from the normal of each bounce, degrees.
    sliding, sticking : ndarray of bool
        MeasuredBounces that slide throughout at the estimate (they determine ``mu``) and bounces
        whose contact sticks (they only bound ``mu`` from below); only bounces with a
        measured ``after_vx`` or ``after_omega`` count.
    n_sliding, n_sticking : int
        Their numbers.
    chi2, dof, reduced_chi2 : float, int, float
        Sum of squared normalized residuals, measured values less free parameters, and
        their ratio (``dof`` and 1 by construction when no sigmas were given: the
        goodness of fit cannot be judged without them).
    sigma_given : bool
        Whether the standard deviations were given (otherwise estimated).
    scale : float
        Without sigmas: the one standard deviation estimated from the scatter, m/s (of
        ``vx``, ``vy`` and ``R omega``); NaN when sigmas were given.
    log_likelihood, aic, bic : float
        Gaussian log-likelihood at the estimate, ``AIC = 2k - 2 ln L`` and
        ``BIC = k ln N - 2 ln L`` (``k`` counts the estimated sigma when it is).
    n_bounces, n_observations : int
        MeasuredBounces and measured values.
    converged : bool
        Whether the optimizer reported convergence.
    message : str
        The optimizer's message.
    evaluations : int
        Model evaluations (each is one vectorized call over all bounces).
    profiles : dict
        For each parameter, the values visited along its profile and the profile's
        rise ``(chi2(value) - chi2_min) / s^2``, for pictures.
    """

    model: str
    body: dict | None
    names: tuple
    estimate: Array
    standard_error: Array
    covariance: Array
    correlation: Array
    interval_low: Array
    interval_high: Array
    one_sided: Array
    confidence: float
    threshold: float
    fixed: dict
    observed: Array
    fitted: Array
    fitted_low: Array
    fitted_high: Array
    residuals: Array
    normalized_residuals: Array
    sigma: Array
    incidence: Array
    incidence_angle_deg: Array
    sliding: Array
    sticking: Array
    n_sliding: int
    n_sticking: int
    chi2: float
    dof: int
    reduced_chi2: float
    sigma_given: bool
    scale: float
    log_likelihood: float
    aic: float
    bic: float
    n_bounces: int
    n_observations: int
    converged: bool
    message: str
    evaluations: int
    profiles: dict

    _per_impact = False
    _shape_field = "estimate"

    def __getitem__(self, name: Any) -> Estimate:
        if isinstance(name, int | np.integer) and not isinstance(name, bool):
            name = self.names[name]  # the i-th fitted parameter (IndexError past the end)
        if not isinstance(name, str) or name not in self.names:
            raise KeyError(f"no fitted parameter {name!r}; the fitted ones are {self.names}")
        i = self.names.index(name)
        return Estimate(name, float(self.estimate[i]), float(self.standard_error[i]),
                        float(self.interval_low[i]), float(self.interval_high[i]),
                        bool(self.one_sided[i]))  # fmt: skip

    def __iter__(self):  # type: ignore[no-untyped-def]
        return (self[n] for n in self.names)

    @property
    def identifiability(self) -> str:
        """What the data say about ``mu``, in words (sliding bounces determine it,
        sticking bounces only bound it)."""
        text = (f"{self.n_sliding} bounce(s) slid throughout (they determine mu), "
                f"{self.n_sticking} stuck (they only bound mu from below)")  # fmt: skip
        if "mu" in self.names and self["mu"].one_sided:
            text += f"; the data only bound mu: mu >= {self['mu'].low:.4g} (one-sided)"
        return text

    @property
    def p_value(self) -> float:
        """Probability of a ``chi2`` at least this large if the model and the given sigmas
        were right (``chi2`` distribution with ``dof`` degrees of freedom); NaN when the
        sigmas were estimated (the goodness of fit is then not testable)."""
        if not self.sigma_given or self.dof < 1:
            return float("nan")
        from scipy.special import chdtrc

        return float(chdtrc(self.dof, self.chi2))

    def to_dict(self) -> dict[str, Any]:
        """Every field as plain Python values (for JSON; ``inf`` stays a float)."""
        out = super().to_dict()
        out["profiles"] = {k: {"value": np.asarray(v).tolist(), "rise": np.asarray(r).tolist()}
                           for k, (v, r) in self.profiles.items()}  # fmt: skip
        out["names"] = list(self.names)
        out["parameters"] = {n: vars(self[n]) for n in self.names}
        out["p_value"] = self.p_value
        return out

    def _quantities(self) -> tuple[str, ...]:
        """The measured quantities, in the order of the ``(n, q)`` arrays' columns."""
        return QUANTITIES

    def columns(self) -> dict[str, np.ndarray]:
        """One row per bounce: incidence angle, measured, fitted, band and residual of
        each quantity, and whether the bounce slid."""
        out: dict[str, np.ndarray] = {"incidence_angle_deg": self.incidence_angle_deg}
        for j, q in enumerate(self._quantities()):
            for prefix, arr in (("observed", self.observed), ("fitted", self.fitted),
                                ("fitted_low", self.fitted_low),
                                ("fitted_high", self.fitted_high),
                                ("residual", self.residuals)):  # fmt: skip
                out[f"{prefix}_{q}"] = arr[:, j]
        out["sliding"] = self.sliding
        return out

    @staticmethod
    def _column_names(quantities: tuple[str, ...]) -> tuple[str, ...]:
        names = ["incidence_angle_deg"]
        for q in quantities:
            names += [f"{p}_{q}" for p in ("observed", "fitted", "fitted_low", "fitted_high",
                                            "residual")]  # fmt: skip
        return (*names, "sliding")

    @classmethod
    def column_names(cls) -> tuple[str, ...]:
        """Names of :meth:`columns`, in order."""
        return cls._column_names(QUANTITIES)

    def __repr__(self) -> str:
        parts = "; ".join(str(self[n]) for n in self.names)
        body = f", body {self.body['name']}" if self.body else ""
        return (f"<FitResult {self.model}{body}: {parts}; "
                f"chi2/dof = {self.chi2:.4g}/{self.dof}>")  # fmt: skip
