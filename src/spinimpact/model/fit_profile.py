"""The least-squares problem of :func:`spinimpact.fit`, its curvature and its
profile-likelihood intervals.

A :class:`Problem` holds the data, the model and which parameters are free; every
evaluation is one vectorized call of the model over all bounces. :func:`intervals`
walks each parameter's profile outward from the estimate (the other free parameters
re-fitted at each step) until it rises by the confidence threshold, then refines the
crossing with Brent's method on ``sqrt(rise)``, which is nearly linear in the
parameter, so a few evaluations suffice.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .fit_data import MeasuredBounces
from .fit_models import MU_INFINITY, FitModel

__all__ = ["Problem", "Intervals", "minimize", "jacobian", "curvature", "intervals", "threshold"]


class Problem:
    """Weighted residuals of a model on measured bounces, over the free parameters.

    ``model`` is a :class:`~spinimpact.model.fit_models.FitModel` or any object with the
    same few members (``parameters`` with ``low``/``high``, ``names``, ``values(theta)``,
    ``predict(theta, bounces) -> (n, q)`` and ``scale() -> (q,)``), and ``bounces`` one
    with ``measured``, ``observed`` and ``sigma`` arrays of shape ``(n, q)``: the
    paper's 2D fit (:func:`spinimpact.fit`) and the fit of any registered problem
    (:func:`spinimpact.fit_problem`) share every step below.
    """

    def __init__(
        self, model: FitModel, bounces: MeasuredBounces, theta: np.ndarray, free: np.ndarray
    ):
        self.model, self.bounces = model, bounces
        self.theta, self.free = np.array(theta, dtype=float), np.asarray(free, dtype=bool)
        self.mask = bounces.measured
        given = bounces.sigma
        self.sigma_given = given is not None
        unit = np.broadcast_to(1.0 / model.scale(), self.mask.shape)
        self.sigma = np.array(given if given is not None else unit, dtype=float)
        self.observed = bounces.observed[self.mask]
        self.weight = 1.0 / self.sigma[self.mask]
        specs = [p for p, f in zip(model.parameters, self.free, strict=True) if f]
        self.low = np.array([p.low for p in specs])
        self.high = np.array([p.high for p in specs])
        self.evaluations = 0

    @property
    def dof(self) -> int:
        """Measured values less free parameters."""
        return int(self.mask.sum()) - int(self.free.sum())

    def full(self, x: np.ndarray) -> np.ndarray:
        """The whole parameter vector with the free ones set to ``x``."""
        theta = self.theta.copy()
        theta[self.free] = x
        return theta

    def residual(self, x: np.ndarray) -> np.ndarray:
        """Weighted residuals ``(f(theta) - y)/sigma`` of the measured values."""
        self.evaluations += 1
        pred = self.model.predict(self.full(x), self.bounces)[self.mask]
        if not np.all(np.isfinite(pred)):
            at = ", ".join(f"{k} = {v:.6g}" for k, v in self.model.values(self.full(x)).items())
            raise ValueError(f"the model gives a non-finite rebound at {at}")
        return (pred - self.observed) * self.weight

    def chi2(self, x: np.ndarray) -> float:
        """Sum of squared weighted residuals."""
        r = self.residual(x)
        return float(np.einsum("i,i", r, r))  # not BLAS: threads cost more than they save here

    def scan_mu(self) -> float:
        """The friction coefficient of least ``chi2`` on a grid from 0 to 10 (the other
        parameters at their starting values): a start on the right side of any kink, and
        the smallest of equals when the likelihood is flat (every bounce sticking)."""
        i = self.model.names.index("mu")
        grid = np.concatenate([[0.0], np.logspace(-3, 1, 49)])
        theta = list(self.theta)
        theta[i] = grid[:, None]  # every grid value against every bounce, in one call
        self.evaluations += 1
        pred = self.model.predict(theta, self.bounces)[:, self.mask]
        r = (pred - self.observed) * self.weight
        return float(grid[int(np.argmin(np.einsum("gi,gi->g", r, r)))])


def minimize(prob: Problem, x0: np.ndarray, fix: tuple[int, float] | None = None) -> Any:
    """Least squares over the free parameters (SciPy's trust-region reflective method
    with bounds, finite-difference Jacobian), optionally with parameter ``fix[0]`` held
    at ``fix[1]``. Returns SciPy's result; with a fixed parameter its ``x`` is the whole
    free vector."""
    from scipy.optimize import least_squares

    x0 = np.clip(np.asarray(x0, dtype=float), prob.low, prob.high)
    if fix is None:
        return least_squares(prob.residual, x0, bounds=(prob.low, prob.high), method="trf")
    j, value = fix
    keep = np.arange(x0.size) != j

    def residual(y: np.ndarray) -> np.ndarray:
        x = x0.copy()
        x[keep], x[j] = y, value
        return prob.residual(x)

    lo, hi = prob.low[keep], prob.high[keep]
    out = _newton(residual, x0[keep], lo, hi) if keep.sum() == 1 else None
    if out is None:
        out = least_squares(residual, x0[keep], bounds=(lo, hi), method="trf")
    x = x0.copy()
    x[keep], x[j] = out.x, value
    out.x = x
    return out


def _newton(residual: Any, y0: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> Any:
    """Least squares in one bounded parameter by Gauss-Newton steps with a central-difference
    derivative and step halving: the profile's inner fit of a two-parameter model, where
    SciPy's general method costs more in overhead than in evaluations. Exact in one step
    where the residuals are linear (the rigid model within a regime). ``None`` if it has
    not converged in 20 steps (the caller then uses SciPy)."""
    from types import SimpleNamespace

    y, low, high = float(y0[0]), float(lo[0]), float(hi[0])
    r = residual(np.array([y]))
    cost = float(np.einsum("i,i", r, r))
    for _ in range(20):
        h = 1e-6 * max(abs(y), 1e-2)
        up, down = min(y + h, high), max(y - h, low)
        d = (residual(np.array([up])) - residual(np.array([down]))) / (up - down)
        dd = float(np.einsum("i,i", d, d))
        if dd == 0.0:  # flat here: every nearby value fits as well
            return SimpleNamespace(x=np.array([y]), cost=0.5 * cost, success=True, message="")
        step, t = -float(np.einsum("i,i", d, r)) / dd, 1.0
        while True:
            trial = min(max(y + t * step, low), high)
            rt = residual(np.array([trial]))
            ct = float(np.einsum("i,i", rt, rt))
            if ct <= cost or t < 1e-6:
                break
            t *= 0.5
        if ct > cost or cost - ct <= 1e-12 * (1.0 + cost):  # no further decrease
            y, cost = (trial, ct) if ct <= cost else (y, cost)
            return SimpleNamespace(x=np.array([y]), cost=0.5 * cost, success=True, message="")
        y, r, cost = trial, rt, ct
    return None


def jacobian(prob: Problem, x: np.ndarray) -> np.ndarray:
    """Central-difference Jacobian of the weighted residuals (one-sided at a bound).

    The rigid model is piecewise linear in its parameters, so the differences are exact
    within each regime; a step of ``1e-6`` of the value keeps regime changes rare."""
    cols = []
    for j in range(x.size):
        h = 1e-6 * max(abs(float(x[j])), 1e-2)
        up, down = x.copy(), x.copy()
        up[j] = min(x[j] + h, prob.high[j])
        down[j] = max(x[j] - h, prob.low[j])
        cols.append((prob.residual(up) - prob.residual(down)) / (up[j] - down[j]))
    return np.stack(cols, axis=-1)


def curvature(prob: Problem, x: np.ndarray, s2: float) -> tuple[np.ndarray, np.ndarray]:
    """Covariance ``s2 (J^T J)^-1`` and standard errors.

    A parameter the residuals do not depend on near ``x`` (a zero column of ``J``), or
    one in a combination they do not depend on (a null direction of the column-scaled
    ``J``, e.g. two restitution knots that only ever act together), gets an infinite
    variance instead of the small number a pseudo-inverse would report."""
    jac = jacobian(prob, x)
    norms = np.linalg.norm(jac, axis=0)
    known = norms > 1e-9 * max(float(norms.max()), 1e-300)
    if known.sum() > 1:
        _, sv, vt = np.linalg.svd(jac[:, known] / norms[known], full_matrices=False)
        null = vt[sv < 1e-7 * sv[0]]
        if null.size:
            idx = np.flatnonzero(known)
            known[idx[np.any(np.abs(null) > 1e-6, axis=0)]] = False
    cov = np.full((x.size, x.size), np.nan)
    np.fill_diagonal(cov, np.inf)
    if known.any():
        sub = jac[:, known]
        cov[np.ix_(known, known)] = np.linalg.inv(sub.T @ sub) * s2
    return cov, np.sqrt(np.diag(cov))


@dataclass
class Intervals:
    """Profile-likelihood intervals of every free parameter."""

    low: np.ndarray
    high: np.ndarray
    one_sided: np.ndarray
    ends: list = field(default_factory=list)  #: free vectors at the interval ends
    profiles: dict = field(default_factory=dict)  #: name -> (values, rises)
    better: np.ndarray | None = None  #: a free vector with a lower chi2, if one was met


class _Profile:
    """The profile of parameter ``j``: ``rise(v) = (min chi2 | x_j = v) - chi2_min) / s2``."""

    def __init__(self, prob: Problem, x: np.ndarray, j: int, chi0: float, s2: float) -> None:
        self.prob, self.x, self.j, self.chi0, self.s2 = prob, x, j, chi0, s2
        self.seen: dict[float, tuple[float, np.ndarray]] = {float(x[j]): (0.0, x.copy())}
        self.warm = x.copy()
        self.better: np.ndarray | None = None

    def rise(self, v: float) -> float:
        if v in self.seen:
            return self.seen[v][0]
        if self.x.size == 1:
            xv = np.array([v])
            chi = self.prob.chi2(xv)
        else:
            out = minimize(self.prob, self.warm, fix=(self.j, v))
            xv = out.x
            chi = 2.0 * float(out.cost)
            self.warm = xv
        r = (chi - self.chi0) / self.s2
        lower = r < -1e-3 and self.chi0 - chi > 1e-12 * (1.0 + self.chi0)  # beyond rounding
        if lower and (self.better is None or chi < self.prob.chi2(self.better)):
            self.better = xv.copy()
        self.seen[v] = (r, xv.copy())
        return r

    def side(self, sign: int, q: float, se: float) -> tuple[float, np.ndarray, bool]:
        """The end of the interval on one side: ``(value, free vector there, open)``;
        ``open`` when the rise stays below ``q`` all the way to a bound (infinite for a
        parameter unbounded there)."""
        from scipy.optimize import brentq

        prob, j = self.prob, self.j
        xhat = float(self.x[j])
        bound = float(prob.high[j] if sign > 0 else prob.low[j])
        is_mu = prob.model.names[int(np.flatnonzero(prob.free)[j])] == "mu"
        if sign > 0 and is_mu:
            bound = MU_INFINITY
        if bound == xhat:
            return xhat, self.x.copy(), True
        g = lambda v: math.sqrt(max(self.rise(v), 0.0)) - math.sqrt(q)  # noqa: E731
        step = se if np.isfinite(se) and se > 0 else 0.1 * max(abs(xhat), 0.05)
        a, b = xhat, xhat + sign * math.sqrt(q) * step
        for _ in range(64):
            if math.isfinite(bound) and (b - bound) * sign >= 0:
                if g(bound) < 0:
                    end = math.inf if (is_mu and sign > 0) else bound
                    return end, self.seen[bound][1], True
                b = bound
                break
            if g(b) >= 0:
                break
            if math.isfinite(bound) and a == xhat and g(bound) < 0:  # flat to the bound
                end = math.inf if (is_mu and sign > 0) else bound
                return end, self.seen[bound][1], True
            a, b = b, xhat + 2.0 * (b - xhat)
        else:
            return sign * math.inf, self.warm.copy(), True
        root = brentq(g, min(a, b), max(a, b), xtol=1e-5 * abs(b - xhat), rtol=1e-10)
        self.rise(root)
        return float(root), self.seen[root][1], False


def threshold(level: float, dof: int, sigma_given: bool) -> float:
    """The rise of the profile, ``(chi2 - chi2_min)/s^2``, that ends an interval at
    ``level``: the ``chi2_1`` quantile with known sigmas, ``F(1, dof)`` with an
    estimated one (the exact level for a model linear in its parameters)."""
    from scipy.special import chdtri, fdtri

    return float(chdtri(1, 1.0 - level) if sigma_given else fdtri(1, dof, level))


def intervals(prob: Problem, x: np.ndarray, conf: float, se: np.ndarray) -> Intervals:
    """Profile-likelihood intervals at ``conf`` for every free parameter (see
    :func:`spinimpact.fit`, Notes): two-sided where the data bound a parameter on both
    sides, a one-sided lower bound where its profile stays flat to infinity."""
    chi0 = prob.chi2(x)
    dof = prob.dof
    s2 = max(1.0 if prob.sigma_given else chi0 / dof, 1e-300)
    q2 = threshold(conf, dof, prob.sigma_given)
    q1 = threshold(2 * conf - 1, dof, prob.sigma_given)
    k = x.size
    out = Intervals(np.empty(k), np.empty(k), np.zeros(k, dtype=bool))
    names = np.array(prob.model.names)[prob.free]
    for j in range(k):
        prof = _Profile(prob, x, j, chi0, s2)
        high, end_h, open_h = prof.side(+1, q2, se[j])
        low, end_l, _ = prof.side(-1, q2, se[j])
        if open_h and math.isinf(high) and q1 > 0:  # flat to infinity: a one-sided bound
            low, end_l, _ = prof.side(-1, q1, se[j])
            out.one_sided[j] = True
        out.low[j], out.high[j] = low, high
        out.ends += [end_l, end_h]
        values = np.array(sorted(prof.seen))
        out.profiles[str(names[j])] = (values, np.array([prof.seen[v][0] for v in values]))
        if prof.better is not None and (
            out.better is None or prob.chi2(prof.better) < prob.chi2(out.better)
        ):
            out.better = prof.better  # fmt: skip
    return out
