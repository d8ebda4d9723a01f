r"""The least-squares problem of a fit of tracks across a bounce, and its profile likelihood.

:class:`Joint` holds the tracks of :func:`spinimpact.model.track_fit.fit_bounces`, their split
at the contact and which samples are kept; its parameters are the free shared ones (``mu``,
``kappa``, ``contact_height``, ``beta0``) followed by ten a shot (state and drag coefficient).
Every evaluation flies all shots, and all perturbed states of each, in one batch
(:func:`spinimpact.model.track_bounce.flights`). :meth:`Joint.solve` is Levenberg-Marquardt on
the normal equations (small and dense: the shots' blocks touch only their own samples);
:func:`profile` walks a shared parameter's profile likelihood to its interval.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .track_bounce import BOUNDS, SCALE, SHARED_SCALE, SHARED_STEP, STEP, flights, padded

__all__ = ["Joint", "profile"]


class Joint:
    """The joint least-squares problem: the free shared parameters first, then 10 a shot
    (state and ``C_D``); every evaluation flies all shots in one batch."""

    def __init__(self, tracks, splits, air, law, names, fixed, up):
        self.tracks, self.splits, self.air, self.law = tracks, splits, air, law
        self.names, self.fixed, self.up = names, fixed, up
        self.free = [n for n in names if n not in fixed]
        self.k = len(self.free)
        self.t0 = np.array([float(tr.time[0]) for tr in tracks])
        self.set_keep([np.ones(len(tr), dtype=bool) for tr in tracks])

    def set_keep(self, keep: list[np.ndarray]) -> None:
        """Use only the samples ``keep`` (one mask a track)."""
        self.keep = keep
        parts = []
        for side in (0, 1):
            sel = [(np.arange(len(tr)) < sp) == (side == 0) for tr, sp in
                   zip(self.tracks, self.splits, strict=True)]  # fmt: skip
            times = [tr.time[m & k] for tr, m, k in zip(self.tracks, sel, keep, strict=True)]
            meas = [tr.position[m & k] for tr, m, k in zip(self.tracks, sel, keep, strict=True)]
            grid = padded(times)
            mask = np.arange(grid.shape[1])[None, :] < np.array([len(t) for t in times])[:, None]
            full = np.zeros((*grid.shape, 3))
            full[mask] = np.concatenate(meas) if meas and grid.size else np.zeros((0, 3))
            parts.append((grid, mask, full))
        self.parts = parts
        self.n_obs = 3 * int(sum(m.sum() for _, m, _ in parts))

    def shared(self, x: np.ndarray, b: int) -> dict[str, np.ndarray]:
        vals = dict(self.fixed)
        vals.update({n: x[i] for i, n in enumerate(self.free)})
        return {n: np.full(b, float(vals[n])) for n in self.names}

    def states(self, x: np.ndarray) -> np.ndarray:
        return x[self.k :].reshape(-1, 10)

    def _fly(self, states: np.ndarray, shared: dict, reps: int) -> list[np.ndarray]:
        """Residuals ``(N, reps, m, 3)`` before and after, of ``reps`` states a shot."""
        grids = [np.repeat(g, reps, axis=0) for g, _, _ in self.parts]
        fl = flights(np.repeat(self.t0, reps), states, shared, self.air, self.law, grids[0],
                     grids[1], self.up)  # fmt: skip
        out = []
        for key, (g, _, meas) in zip(("before", "after"), self.parts, strict=True):
            r = fl[key].reshape(len(self.tracks), reps, g.shape[1], 3) - meas[:, None]
            out.append(np.where(np.isfinite(r), r, 1.0))  # a flight that misses: far off
        return out

    def residual(self, x: np.ndarray) -> np.ndarray:
        r = self._fly(self.states(x), self.shared(x, len(self.tracks)), 1)
        return np.concatenate([ri[:, 0][m].ravel() for ri, (_, m, _) in zip(
            r, self.parts, strict=True)])  # fmt: skip

    def jacobian(self, x: np.ndarray) -> Any:
        from scipy.sparse import coo_matrix

        n, k = len(self.tracks), self.k
        reps = 11 + k
        base = self.states(x)
        batch = np.repeat(base[:, None], reps, axis=1)
        batch[:, 1:11] += np.diag(STEP)
        sh = self.shared(x, n * reps)
        steps = np.r_[STEP, [SHARED_STEP[m] for m in self.free]]
        for j, m in enumerate(self.free):
            sh[m].reshape(n, reps)[:, 11 + j] += SHARED_STEP[m]
        r = self._fly(batch.reshape(-1, 10), sh, reps)
        rows, cols, vals, start = [], [], [], 0
        for ri, (_, mask, _) in zip(r, self.parts, strict=True):
            d = (ri[:, 1:] - ri[:, :1]) / steps[None, :, None, None]  # (n, 10+k, m, 3)
            d = np.moveaxis(d, 1, -1)[mask]  # (kept, 3, 10+k)
            shot = np.repeat(np.nonzero(mask)[0], 3)
            d = d.reshape(-1, 10 + k)
            here = start + np.arange(len(d))
            c = k + 10 * shot[:, None] + np.arange(10)
            rows += [np.repeat(here, 10), np.repeat(here, k)]
            cols += [c.ravel(), np.tile(np.arange(k), len(d))]
            vals += [d[:, :10].ravel(), d[:, 10:].ravel()]
            start += len(d)
        return coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(start, x.size)).tocsr()  # fmt: skip

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        n = len(self.tracks)
        lo = np.r_[[BOUNDS[m][0] for m in self.free], np.tile(np.r_[np.full(9, -np.inf), 0.0], n)]
        hi = np.r_[[BOUNDS[m][1] for m in self.free], np.full(10 * n, np.inf)]
        return lo, hi

    def scale(self) -> np.ndarray:
        return np.r_[[SHARED_SCALE[m] for m in self.free], np.tile(SCALE, len(self.tracks))]

    def solve(self, x0: np.ndarray, loss: str = "linear", f_scale: float = 1.0,
              hold: tuple[int, float] | None = None, iterations: int = 100) -> Any:  # fmt: skip
        """Levenberg-Marquardt from ``x0`` within the bounds (a step that leaves them is cut
        back to them); ``loss="soft_l1"`` reweights each residual by
        ``1/sqrt(1 + (r/f_scale)^2)`` at every step (iteratively reweighted least squares:
        samples far off the path count less). ``hold = (j, value)`` fixes free shared
        parameter ``j``. The normal equations are sparse in the shots (each shot's 10
        parameters touch only its samples) and small: solved dense.

        Returns an object with ``x`` and ``cost`` (half the sum of squared, weighted
        residuals at ``x``)."""
        lo, hi = self.bounds()
        x = np.clip(np.array(x0, dtype=float), lo, hi)
        m = np.ones(x.size, dtype=bool)
        if hold is not None:
            m[hold[0]] = False
            x[hold[0]] = hold[1]
        scale = self.scale()[m]

        def weights(r: np.ndarray) -> np.ndarray:
            if loss == "linear":
                return np.ones_like(r)
            return 1.0 / np.sqrt(np.sqrt(1.0 + (r / f_scale) ** 2))

        def cost(r: np.ndarray) -> float:
            if loss == "linear":
                return 0.5 * float(r @ r)
            return float(np.sum(f_scale**2 * (np.sqrt(1.0 + (r / f_scale) ** 2) - 1.0)))

        r = self.residual(x)
        c = cost(r)
        lam = 1e-3
        for _ in range(iterations):
            w = weights(r)
            jac = self.jacobian(x)[:, m].multiply(w[:, None]).multiply(scale[None, :]).tocsr()
            a = (jac.T @ jac).toarray()
            g = jac.T @ (w * r)
            diag = np.maximum(np.diag(a), 1e-12 * max(float(np.diag(a).max()), 1e-300))
            improved = False
            for _ in range(12):
                try:
                    step = -np.linalg.solve(a + lam * np.diag(diag), g) * scale
                except np.linalg.LinAlgError:
                    lam *= 10.0
                    continue
                y = x.copy()
                y[m] = np.clip(x[m] + step, lo[m], hi[m])
                ry = self.residual(y)
                cy = cost(ry)
                if cy <= c:
                    improved = True
                    small = c - cy <= 1e-10 * (c + 1e-300) and np.all(
                        np.abs(y - x)[m] <= 1e-8 * (np.abs(x[m]) + scale))  # fmt: skip
                    x, r, c = y, ry, cy
                    lam = max(lam / 5.0, 1e-9)
                    break
                lam *= 10.0
            if not improved or small:
                break
        return _Solved(x, c)


class _Solved:
    """What :meth:`Joint.solve` found."""

    def __init__(self, x: np.ndarray, cost: float) -> None:
        self.x, self.cost = x, cost


def profile(prob: Joint, x: np.ndarray, j: int, chi0: float, s2: float, q: float,
             se: float) -> tuple[float, float, bool]:  # fmt: skip
    """The profile-likelihood interval of free shared parameter ``j``: the values whose
    re-fitted ``chi2`` rises by less than ``q s2``. Walked outward from the estimate in
    steps of the standard error (doubling), the crossing then refined by the Illinois
    variant of regula falsi on ``sqrt(rise) - sqrt(q)``, which is nearly linear in the
    parameter. Returns ``(low, high, open)``: ``open`` when the profile stays below the
    threshold up to a bound of the parameter, which is then the end."""
    name = prob.free[j]
    xhat = float(x[j])
    step = se if np.isfinite(se) and se > 0 else 0.1 * max(abs(xhat), 0.05)
    ends, open_ = [], False
    for sign, bound in ((-1, BOUNDS[name][0]), (+1, BOUNDS[name][1])):
        warm = [x.copy()]

        def g(v: float, warm: list = warm) -> float:
            out = prob.solve(warm[0], hold=(j, v))
            warm[0] = out.x
            return math.sqrt(max((2.0 * out.cost - chi0) / s2, 0.0)) - math.sqrt(q)

        a, ga = xhat, -math.sqrt(q)
        b = xhat + sign * math.sqrt(q) * step
        for _ in range(30):
            if math.isfinite(bound) and (b - bound) * sign >= 0:
                b = bound
            gb = g(b)
            if gb >= 0 or b == bound:
                break
            a, ga, b = b, gb, xhat + 2.0 * (b - xhat)
        if gb < 0:  # below the threshold up to the bound
            ends.append(b if math.isfinite(b) else sign * math.inf)
            open_ = True
            continue
        side = 0
        for _ in range(40):
            c = b - gb * (b - a) / (gb - ga)
            gc = g(c)
            if abs(gc) < 1e-3 or abs(b - a) < 1e-4 * step:
                break
            if (gc < 0) == (ga < 0):
                a, ga = c, gc
                if side == -1:
                    gb /= 2.0
                side = -1
            else:
                b, gb = c, gc
                if side == 1:
                    ga /= 2.0
                side = 1
        ends.append(float(c))
    return float(min(ends)), float(max(ends)), open_
