"""Pictures of a fit (:func:`spinimpact.model.fit.fit`): measured against fitted over the
incidence angle with the band, the residuals, and a corner plot of the parameters.

Nothing here fits or solves: every number drawn is a field of the
:class:`~spinimpact.model.fit_result.FitResult`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..model.fit_result import FitResult

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_fit", "plot_corner", "LABELS"]

#: Typeset axis label of each fitted quantity.
LABELS = {
    "after_vx": r"$v_x^+$ (m/s)",
    "after_vy": r"$v_y^+$ (m/s)",
    "after_omega": r"$\omega^+$ (rad/s)",
}
_SYMBOLS = {"mu": r"$\mu$", "kappa": r"$\kappa$", "kappa_ref": r"$\kappa_{ref}$",
            "exponent": "exponent", "gyration": r"$\rho$ (m)",
            "beta0": r"$\beta_0$", "poisson_ratio": r"$\nu$"}  # fmt: skip


def _figure(**kwargs) -> Figure:
    from matplotlib.figure import Figure  # no pyplot: no global state, no GUI backend

    return Figure(layout="constrained", **kwargs)


def symbol(name: str) -> str:
    """Typeset name of a parameter (``kappa_at_2`` becomes ``kappa`` at 2 m/s)."""
    if name.startswith("kappa_at_"):
        return rf"$\kappa$({name[9:]} m/s)"
    return _SYMBOLS.get(name, name)


def plot_fit(res: FitResult) -> Figure:
    """Measured against fitted for each measured quantity over the incidence angle (top
    row) and the normalized residuals (bottom row).

    Parameters
    ----------
    res : FitResult
        The fit.

    Returns
    -------
    matplotlib.figure.Figure
        One column per quantity that was measured at least once. Top: measured values
        with error bars of one standard deviation (``sigma``), the fitted values joined
        in order of the angle, and the band ``fitted_low``-``fitted_high`` (the model
        over the ends of the profile intervals) shaded; sliding bounces are filled
        markers, sticking ones open. Bottom: ``(observed - fitted)/sigma`` with lines at
        0 and +-2. When every bounce has the same incidence speed and spin, the fitted
        values are drawn as a curve over the angle with a shaded band; otherwise as a
        mark per bounce with its band as a bar.
    """
    from ..model.fit_data import QUANTITIES
    from ..model.fit_drops import DropFit

    if isinstance(res, DropFit):
        return _plot_drops(res)
    shown = [j for j in range(3) if np.isfinite(res.observed[:, j]).any()]
    fig = _figure(figsize=(4.2 * len(shown), 6.2))
    axes = fig.subplots(2, len(shown), squeeze=False, sharex="col")
    angle = res.incidence_angle_deg
    order = np.argsort(angle)
    curve = _one_family(res)
    for col, j in enumerate(shown):
        top, bottom = axes[0, col], axes[1, col]
        seen = np.isfinite(res.observed[:, j])
        if curve:  # one speed and spin: the fitted values are a curve over the angle
            top.fill_between(angle[order], res.fitted_low[order, j], res.fitted_high[order, j],
                             color="tab:orange", alpha=0.3, lw=0, label="band")  # fmt: skip
            top.plot(angle[order], res.fitted[order, j], "-", color="tab:orange", lw=1.2,
                     label="fitted")  # fmt: skip
        else:
            top.vlines(angle, res.fitted_low[:, j], res.fitted_high[:, j], color="tab:orange",
                       alpha=0.5, lw=3, label="band")  # fmt: skip
            top.plot(angle, res.fitted[:, j], "_", color="tab:orange", ms=9, label="fitted")
        for mask, face, label in ((res.sliding, "tab:blue", "measured, slid"),
                                  (~res.sliding, "white", "measured, stuck")):  # fmt: skip
            pick = seen & mask
            if pick.any():
                top.errorbar(angle[pick], res.observed[pick, j], yerr=res.sigma[pick, j],
                             fmt="o", ms=4, mfc=face, mec="tab:blue", ecolor="tab:blue",
                             elinewidth=0.8, capsize=2, label=label)  # fmt: skip
        top.set_ylabel(LABELS[QUANTITIES[j]])
        top.set_title("measured and fitted", fontsize="medium")
        bottom.axhline(0.0, color="0.3", lw=0.8)
        for y in (-2.0, 2.0):
            bottom.axhline(y, color="0.6", lw=0.8, ls="--")
        bottom.plot(angle[seen], res.normalized_residuals[seen, j], "o", ms=4, color="tab:blue")
        bottom.set_xlabel("incidence angle from the normal (deg)")
        bottom.set_ylabel(r"(measured $-$ fitted)/$\sigma$")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncol=len(labels), fontsize="small",
               frameon=False)  # fmt: skip
    fig.suptitle(_title(res), fontsize="medium")
    return fig


def _plot_drops(res: Any) -> Figure:
    """Drop tests: measured ``kappa`` against the impact speed with the fitted
    ``kappa(v)`` and its band (top), the normalized residuals (bottom)."""
    fig = _figure(figsize=(6.4, 6.2))
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.fill_between(res.curve_speed, res.curve_kappa_low, res.curve_kappa_high,
                     color="tab:orange", alpha=0.3, lw=0, label="band")  # fmt: skip
    top.plot(res.curve_speed, res.curve_kappa, "-", color="tab:orange", lw=1.2, label="fitted")
    top.errorbar(res.impact_speed, res.kappa, yerr=res.sigma_kappa, fmt="o", ms=4,
                 color="tab:blue", elinewidth=0.8, capsize=2, label="measured")  # fmt: skip
    top.set_ylabel(r"$\kappa$ = rebound speed / impact speed")
    top.set_title("measured and fitted", fontsize="medium")
    bottom.axhline(0.0, color="0.3", lw=0.8)
    for y in (-2.0, 2.0):
        bottom.axhline(y, color="0.6", lw=0.8, ls="--")
    bottom.plot(res.impact_speed, res.normalized_residuals[:, 1], "o", ms=4, color="tab:blue")
    bottom.set_xlabel("impact speed (m/s)")
    bottom.set_ylabel(r"(measured $-$ fitted)/$\sigma$")
    handles, labels = top.get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncol=len(labels), fontsize="small",
               frameon=False)  # fmt: skip
    fig.suptitle(_title(res), fontsize="medium")
    return fig


def _one_family(res: FitResult) -> bool:
    """Whether every bounce has one incidence speed and spin (only the angle varies)."""
    speed = np.hypot(res.incidence[:, 0], res.incidence[:, 1])
    spin = res.incidence[:, 2]
    same_speed = np.ptp(speed) <= 1e-9 * np.max(speed)
    return bool(same_speed and np.ptp(spin) <= 1e-9 * (1.0 + np.max(np.abs(spin))))


def _title(res: FitResult) -> str:
    parts = []
    for n in res.names:
        e = res[n]
        if e.one_sided:
            parts.append(f"{symbol(n)} $\\geq$ {e.low:.3g}")
        else:
            parts.append(f"{symbol(n)} = {e.estimate:.3g} [{e.low:.3g}, {e.high:.3g}]")
    held = "".join(f"; {symbol(n)} = {v:.4g} held" for n, v in res.fixed.items())
    return f"{res.model}\n" + ", ".join(parts) + f" ({100 * res.confidence:g} %){held}"


#: The top of a corner plot's profile panels, in units of the interval's threshold: a
#: profile rise of about 10 at 95 % with known sigmas (a parabola's window is
#: sqrt(2.6) = 1.6 times the interval's half-widths).
RISE_SHOWN = 2.6


def _window(res: FitResult, i: int, r2: float) -> tuple[float, float]:
    """The values of parameter ``i`` a corner plot shows: its interval widened to where a
    parabola through it would rise to ``RISE_SHOWN`` thresholds, the projection of the
    pair ellipses (``est +- sqrt(r2 var)``), and, for a parameter the data only bound
    below, from under the bound to past the estimate (the profile is flat beyond)."""
    est, low, high = res.estimate[i], res.interval_low[i], res.interval_high[i]
    widen = np.sqrt(RISE_SHOWN)
    if res.one_sided[i] or not np.isfinite(high):
        span = max(est - low, 0.05 * abs(low), 1e-6)
        lo, hi = low - span, max(est, low) + 2.0 * span
    else:
        lo, hi = est - widen * (est - low), est + widen * (high - est)
    var = res.covariance[i, i]
    if np.isfinite(var) and var > 0:
        half = np.sqrt(r2 * var)
        lo, hi = min(lo, est - half), max(hi, est + half)
    if not hi > lo:  # an interval of zero width (a perfect fit): a small window about it
        lo, hi = est - 0.05 * max(abs(est), 1.0), est + 0.05 * max(abs(est), 1.0)
    pad = 0.04 * (hi - lo)
    return float(lo - pad), float(hi + pad)


def plot_corner(res: FitResult) -> Figure:
    """Corner plot of the fitted parameters: each parameter's profile on the diagonal,
    the joint confidence ellipse of each pair below it.

    Parameters
    ----------
    res : FitResult
        A fit of at least two parameters.

    Returns
    -------
    matplotlib.figure.Figure
        Diagonal: the profile's rise ``(chi2 - chi2_min)/s^2`` at the values visited,
        the threshold of the interval and the interval's ends (for a parameter the data
        only bound, its finite part and the lower bound), shown up to a rise of
        :data:`RISE_SHOWN` thresholds (about 10 at 95 % with known sigmas). Below: the
        estimate and the ellipse of the covariance at the fit's confidence for two
        parameters (omitted for a pair holding a parameter of infinite standard error;
        a bound-only parameter's lower bound dashed). Each column shares its x axis, and
        each row's ellipses show the row's parameter over the same values as its
        diagonal panel: about the interval, wide enough for the ellipses.

    Raises
    ------
    ValueError
        For a fit of fewer than two parameters.
    """
    p = len(res.names)
    if p < 2:
        raise ValueError(f"a corner plot needs at least two fitted parameters, got {p}")
    fig = _figure(figsize=(2.6 * p + 0.6, 2.6 * p + 0.4))
    axes = fig.subplots(p, p, squeeze=False, sharex="col")
    r2 = -2.0 * np.log1p(-res.confidence)  # the chi2 quantile of two degrees of freedom
    level = res.threshold
    windows = [_window(res, k, r2) for k in range(p)]
    for i, ni in enumerate(res.names):
        for j, nj in enumerate(res.names):
            ax = axes[i, j]
            if j > i:
                ax.set_axis_off()
                continue
            if i == j:
                values, rise = res.profiles[ni]
                if res.one_sided[i]:  # flat to infinity: draw the finite part, say the rest
                    keep = values <= 3.0 * max(res.interval_low[i], res.estimate[i])
                    values, rise = values[keep], rise[keep]
                    ax.text(0.97, 0.9, "flat to $\\infty$", transform=ax.transAxes,
                            ha="right", va="top", fontsize="small")  # fmt: skip
                ax.plot(values, rise, "o-", ms=3, color="tab:blue")
                ax.axhline(level, color="0.5", ls="--", lw=0.8)
                for end in (res.interval_low[i], res.interval_high[i]):
                    if np.isfinite(end):
                        ax.axvline(end, color="tab:orange", lw=0.8)
                ax.set_ylim(-0.04 * RISE_SHOWN * level, RISE_SHOWN * level)
                ax.set_ylabel("profile rise" if j == 0 else "")
            else:
                ax.plot(res.estimate[j], res.estimate[i], "+", color="k", ms=8)
                for k, line in ((j, ax.axvline), (i, ax.axhline)):
                    if res.one_sided[k]:  # the lower bound of a parameter only bounded
                        line(res.interval_low[k], color="tab:orange", lw=0.8, ls="--")
                cov = res.covariance[np.ix_([j, i], [j, i])]
                if np.all(np.isfinite(cov)):
                    vals, vecs = np.linalg.eigh(cov)
                    t = np.linspace(0, 2 * np.pi, 181)
                    circle = np.stack([np.cos(t), np.sin(t)])
                    ring = vecs @ (np.sqrt(np.maximum(vals, 0.0) * r2)[:, None] * circle)
                    ax.plot(res.estimate[j] + ring[0], res.estimate[i] + ring[1], color="tab:blue")
                ax.set_ylim(*windows[i])
                if j == 0:
                    ax.set_ylabel(symbol(ni))
                else:
                    ax.tick_params(labelleft=False)
            if i == p - 1:
                ax.set_xlabel(symbol(nj))
        axes[i, i].set_xlim(*windows[i])  # the column's x axis, shared by its ellipses
    fig.suptitle(f"{res.model}: profiles and {100 * res.confidence:g} % ellipses",
                 fontsize="medium")  # fmt: skip
    return fig
