"""Figures of a planar impact (any planar body, or a pendulum).

* :func:`plot_routh_planar`: Routh's impact diagram for a contact whose impulses couple:
  the impulse path ``(tau, f)`` between the compression line, the sticking line and the
  friction cone, with ``tau_0``, ``tau_*``, ``tau_1`` and the slip reversal marked.
* :func:`plot_laws`: Newton's, Poisson's and Stronge's laws on one configuration.
* :func:`plot_planar_map`: regimes, and where Newton's law creates energy, over the
  body's angle and the incidence's slip ratio (one vectorized solve).

Matplotlib is imported inside the functions; every curve and number comes from
:func:`~spinimpact.solve_planar` / :func:`~spinimpact.solve_pendulum` and
:meth:`~spinimpact.PlanarImpact.history`: nothing here computes physics but the two
straight lines of Routh's diagram, read off the collision matrix.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from ..core.planar import LAWS, PLANAR_REGIMES
from ..model.planar import PlanarImpact, solve_pendulum, solve_planar
from ..model.planar_body import Pendulum, PlanarBody
from ._marks import round_ticks, same_points
from .tables import number

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_routh_planar", "plot_laws", "plot_planar_map", "LAW_NAMES"]

#: How the figures and reports name each restitution law.
LAW_NAMES = {
    "newton": "Newton (kinematic)",
    "poisson": "Poisson (kinetic)",
    "energetic": "Stronge (energetic)",
}
_LAW_STYLE = {"newton": ("C0", "o"), "poisson": ("C1", "s"), "energetic": ("C2", "^")}
_COLORS = "#bbbbbb #444444 #4c72b0 #8fb8de #dd8452 #c44e52 #f1a3a5 #8172b3 #55a868 #000000"
_REGIME_COLORS = dict(zip(PLANAR_REGIMES, _COLORS.split(), strict=True))
#: Angles each preset accepts, rad: the default span of :func:`plot_planar_map`.
_ANGLE_SPANS = {"rod": (0, math.pi), "block": (0, math.pi / 2), "eccentric-disk": (0, 2 * math.pi)}


def _figure(*args: Any, **kwargs: Any) -> Figure:
    from matplotlib.figure import Figure  # no pyplot: no global state, no GUI backend

    return Figure(*args, layout="constrained", **kwargs)


def _single(imp: PlanarImpact) -> None:
    if not isinstance(imp, PlanarImpact):
        raise TypeError(f"expected a spinimpact.PlanarImpact, got {type(imp).__name__}")
    if imp.shape != ():
        raise ValueError(f"a figure describes one impact; this PlanarImpact has shape {imp.shape}")
    if not math.isfinite(float(imp.tau1)):
        raise ValueError(
            f"regime {imp.regime}: no finite impulse ends this impact; nothing to draw"
        )


def _dot(ax: Any, x: float, y: float, fmt: str, label: str, **style: Any) -> None:
    """One marker at ``(x, y)``, named in the legend (never written on the axes)."""
    ax.plot([x], [y], fmt, label=label, **{"ms": 7, "mec": "k", "mew": 0.6, "zorder": 5, **style})


def _title(imp: PlanarImpact) -> str:
    return (
        f"{imp.body.name}, $\\mu = {float(imp.mu):g}$, $\\kappa = {float(imp.kappa):g}$, "
        f"{LAW_NAMES[imp.law]}: {imp.regime}"
    )


def plot_routh_planar(imp: PlanarImpact, n: int = 401) -> Figure:
    """Routh's impact diagram of one planar impact: tangential impulse ``f`` against the
    normal impulse ``tau``.

    Parameters
    ----------
    imp : PlanarImpact
        One impact (shape ``()``), from :func:`~spinimpact.solve_planar` or
        :func:`~spinimpact.solve_pendulum`.
    n : int, optional
        Points of the path (:meth:`~spinimpact.PlanarImpact.history`).

    Returns
    -------
    matplotlib.figure.Figure
        One axes: the friction cone ``f = +-mu tau``; the compression line, the impulses
        that bring the contact's normal velocity to zero, ``W_tn f + W_nn tau = -v^-``;
        the sticking line, those that bring its slip to zero, ``W_tt f + W_tn tau = -u^-``;
        the path of the impulse, ending at ``(tau_1, f_1)``; markers at ``tau_0``,
        ``tau_*`` (when finite; a cross if the slip reverses) and ``tau_1``, one named for
        each where they coincide. The legend sits outside the axes.

    Notes
    -----
    With ``dc = W dp`` the contact velocity after an impulse ``(f, tau)`` is
    ``u = u^- + W_tt f + W_tn tau`` and ``v = v^- + W_tn f + W_nn tau``: the two lines
    are ``v = 0`` and ``u = 0``. The path crosses the compression line at ``tau_0`` and
    meets the sticking line at ``tau_*``, then follows it (stick) or leaves it along the
    other side of the cone (reversal). For a pendulum ``W`` has rank one and the two
    lines coincide. (Routh 1905; Stronge 2000, ch. 5.)

    Raises
    ------
    ValueError
        An array of impacts, or one that no finite impulse ends (regime ``jam``).
    """
    _single(imp)
    h = imp.history(n)
    w = imp.body.collision_matrix
    a, b, d = (float(x) for x in (w.tt, w.tn, w.nn))
    u0, v0, mu = float(imp.slip_before), float(imp.normal_velocity_before), float(imp.mu)
    t0, ts, t1 = float(imp.tau0), float(imp.tau_star), float(imp.tau1)
    f = h.tangential_impulse
    span = 1.15 * t1
    reach = max(float(np.max(np.abs(f))), mu * span, 0.05 * span)
    fig = _figure(figsize=(8.6, 4.6))
    ax = fig.subplots()
    ax.set_xlim(-0.04 * span, span)
    ax.set_ylim(-1.2 * reach, 1.2 * reach)
    ax.axhline(0, color="0.8", lw=0.8, zorder=0)
    ax.axvline(0, color="0.8", lw=0.8, zorder=0)
    x = np.array([0.0, 2.0 * span])
    ax.fill_between(x, -mu * x, mu * x, color="0.6", alpha=0.12, lw=0, zorder=0)
    ax.plot(x, mu * x, color="0.45", ls="--", lw=1, label=r"friction cone $f = \pm\mu\tau$")
    ax.plot(x, -mu * x, color="0.45", ls="--", lw=1)
    same = "\n(the same line: $W$ has rank one)" if a * d - b * b <= 1e-12 * a * d else ""
    # each line {n . (tau, f) = c} through its foot c n/|n|^2, along (-n_f, n_tau)
    lines = (
        (d, b, -v0, "C0", 2.2, "-", r"compression line $v = 0$: $W_{tn} f + W_{nn} \tau = -v^-$"),
        (b, a, -u0, "C2", 1.4, "--", r"sticking line $u = 0$: $W_{tt} f + W_{tn} \tau = -u^-$"),
    )
    for k, (nt, nf, c, color, lw, ls, label) in enumerate(lines):
        foot = np.array([nt, nf]) * c / (nt * nt + nf * nf)
        label += same if k else ""
        ax.axline(tuple(foot), tuple(foot + [-nf, nt]), color=color, lw=lw, ls=ls, label=label)
    ax.plot(h.tau, f, color="C3", lw=2.4, label=r"impulse path $(\tau, f)$", zorder=3)

    f1, reverses = float(imp.tangential_impulse), imp.regime.startswith("reverse")
    ring = {"mfc": "none", "mec": "C0", "ms": 12, "mew": 1.8, "zorder": 6}
    # (tau, symbol, what happens, marker, style), latest first: one marker per point
    events = [(t1, r"\tau_1", f"end, $f_1 = {f1:.4g}$ N s", "o", {"color": "k"}),
              (t0, r"\tau_0", "end of compression", "s", ring)]  # fmt: skip
    if math.isfinite(ts) and ts <= t1:
        mark = ("X", {"color": "C3", "ms": 14}) if reverses else ("D", {"color": "C2"})
        events.insert(1, (ts, r"\tau_*", "slip stops" + " and reverses" * reverses, *mark))
    for group in reversed(same_points(events, 1e-9 * t1)):  # in the order they happen
        tau = group[0][0]
        names = " = ".join(e[1] for e in reversed(group))
        whats = ", ".join(e[2] for e in reversed(group))
        _, _, _, marker, style = max(group, key=lambda e: e[3] == "X")  # a reversal shows
        y = float(np.interp(tau, h.tau, f))  # f1 at tau1: the path ends there exactly
        _dot(ax, tau, y, marker, rf"${names} = {tau:.4g}$ N s: {whats}", **style)
    ax.set_xlabel(r"normal impulse $\tau$ (N s)")
    ax.set_ylabel(r"tangential impulse $f$ (N s)")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0, fontsize="small")
    fig.suptitle(f"Routh's diagram: {_title(imp)}", fontsize="medium")
    return fig


def _solve_all(body: Any, vx: Any, vy: Any, omega: Any, mu: Any, kappa: Any) -> dict:
    """The impact under each law; a pendulum's centre moves with ``omega`` alone."""
    if isinstance(body, Pendulum):
        if vx is not None or vy is not None:
            raise ValueError("a pendulum's centre moves with omega: pass vx=None and vy=None")
        return {law: solve_pendulum(body, omega, mu=mu, kappa=kappa, law=law) for law in LAWS}
    return {law: solve_planar(body, vx, vy, omega, mu=mu, kappa=kappa, law=law) for law in LAWS}


def plot_laws(
    body: PlanarBody | Pendulum, vx: Any, vy: Any, omega: Any, mu: Any, kappa: Any, n: int = 401
) -> Figure:
    """The three restitution laws side by side on one configuration.

    Parameters
    ----------
    body : PlanarBody or Pendulum
        A single body.
    vx, vy : float or None
        Velocity of the centre of mass before the impact, m/s (``None`` for a pendulum).
    omega : float
        Spin before the impact, rad/s, counter-clockwise positive.
    mu, kappa : float
        Friction, and the coefficient given to each law in turn.
    n : int, optional
        Points of the process.

    Returns
    -------
    matplotlib.figure.Figure
        The contact's normal velocity ``v`` and the kinetic energy ``E`` over ``tau``,
        each law's end ``tau_1`` marked (one marker where ends coincide); below, a table
        of each law's rebound, its three restitution coefficients and its energy change.

    Notes
    -----
    The process in ``tau`` (the slip, ``v`` and ``E``) does not depend on the law: the
    laws differ only in where they end it, so one curve carries the three ends.
    """
    imps = _solve_all(body, vx, vy, omega, mu, kappa)
    for imp in imps.values():
        _single(imp)
    last = max(imps.values(), key=lambda i: float(i.tau1))
    h = last.history(n)
    fig = _figure(figsize=(12, 7.4))
    grid = fig.add_gridspec(2, 2, height_ratios=[3, 2])
    axes = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])
    # laws whose ends coincide share one marker (the first law's style), named for all
    groups = same_points([(float(i.tau1), k) for k, i in imps.items()], 1e-12 * float(last.tau1))
    ends = {g[0][1]: " = ".join(LAW_NAMES[x] for _, x in g) if len(g) < 3 else "all three laws"
            for g in groups}  # fmt: skip
    panels = (
        (h.normal_velocity, "normal_velocity_after", r"contact normal velocity $v$ (m/s)"),
        (h.kinetic_energy, "kinetic_energy_after", r"kinetic energy $E$ (J)"),
    )
    for ax, (y, field, label) in zip(axes, panels, strict=True):
        ax.plot(h.tau, y, color="0.35", lw=1.8, label="process (the same for every law)")
        t0, ts = float(last.tau0), float(last.tau_star)
        name = r"$\tau_0 = \tau_*$" if t0 == ts else r"$\tau_0$ (end of compression)"
        ax.axvline(t0, color="0.55", ls=":", lw=1, label=name, zorder=0)
        if 0 < ts < float(last.tau1) and ts != t0:
            ax.axvline(ts, color="0.55", ls="--", lw=1, zorder=0, label=r"$\tau_*$ (slip stops)")
        for law, names in ends.items():
            color, marker = _LAW_STYLE[law]
            end = (float(imps[law].tau1), float(getattr(imps[law], field)))
            _dot(ax, *end, marker, rf"{names}: $\tau_1$", color=color, ms=9)
        ax.set_xlabel(r"normal impulse $\tau$ (N s)")
        ax.set_ylabel(label)
    axes[0].axhline(0, color="0.8", lw=0.8, zorder=0)
    e0 = float(last.kinetic_energy_before)
    axes[1].axhline(e0, color="0.55", ls="--", lw=1, label=r"$E^-$ (before)", zorder=0)
    axes[1].legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0, fontsize="small")
    rows = {
        r"$\tau_1$ (N s)": lambda i: i.tau1,
        r"$v_x^+$ (m/s)": lambda i: i.after.vx,
        r"$v_y^+$ (m/s)": lambda i: i.after.vy,
        r"$\omega^+$ (rad/s)": lambda i: i.after.omega,
        r"Newton $-v^+/v^-$": lambda i: i.newton_restitution,
        r"Poisson $(\tau_1 - \tau_0)/\tau_0$": lambda i: i.poisson_restitution,
        r"energetic $\sqrt{-W_r^n/W_c^n}$": lambda i: i.energetic_restitution,
        r"energy change $(E^+ - E^-)/E^-$": lambda i: -i.dissipated_fraction,
    }
    tx = fig.add_subplot(grid[1, :])
    tx.axis("off")
    table = tx.table(
        cellText=[[number(get(imp)) for imp in imps.values()] for get in rows.values()],
        rowLabels=list(rows),
        colLabels=[LAW_NAMES[law] for law in imps],
        loc="center",
        cellLoc="right",
    )
    table.auto_set_font_size(False)
    table.set_fontsize(9)
    table.scale(0.8, 1.35)
    first = next(iter(imps.values()))
    fig.suptitle(
        f"Three restitution laws, {first.body.name}, $\\mu = {float(first.mu):g}$, "
        f"$\\kappa = {float(first.kappa):g}$, $u^- = {float(first.slip_before):.4g}$ m/s, "
        f"$v^- = {float(first.normal_velocity_before):.4g}$ m/s"
        + ("\n(the three laws coincide here: one end)" if len(ends) == 1 else ""),
        fontsize="medium",
    )
    return fig


def plot_planar_map(
    body_factory: Callable[[np.ndarray], PlanarBody],
    *,
    mu: float,
    kappa: float,
    law: str = "newton",
    angles: Any = None,
    extent: float = 3.0,
    n: int = 200,
) -> Figure:
    """Regimes, and where Newton's law creates energy, over the body's angle and the slip
    ratio of the incidence.

    Parameters
    ----------
    body_factory : callable
        ``angle -> PlanarBody`` taking an array of angles, rad (e.g.
        ``lambda a: PlanarBody.rod(mass=1.0, length=1.0, angle=a)``).
    mu, kappa : float
        Friction and restitution.
    law : {"newton", "poisson", "energetic"}, optional
        The law of the regime panel.
    angles : array_like, optional
        Angles, rad; by default ``n`` points inside the preset's range (rod ``(0, pi)``,
        block ``[0, pi/2)``, eccentric disk ``[0, 2 pi)``).
    extent : float, optional
        The slip ratio ``u^-/|v^-|`` spans ``[-extent, extent]``.
    n : int, optional
        Points per axis.

    Returns
    -------
    matplotlib.figure.Figure
        Left: the regimes under ``law``, with a legend of those present. Right: the
        energy change ``(E^+ - E^-)/E^-`` under Newton's law, the region where it
        creates energy outlined and hatched.

    Notes
    -----
    The body falls without spin, ``v_y^- = -1`` m/s and ``v_x^- = u^-``, so the contact
    velocity is ``(u^-, v^-)``; the regime and the sign of the energy change depend on
    the incidence only through it. The whole grid is one call of
    :func:`~spinimpact.solve_planar` per law (Newton's, and ``law`` if another). The
    regimes come out the same under every law: an impact that ends before the first slip
    phase does ends where ``v`` is linear in ``tau``, and there the three laws agree.
    """
    from matplotlib.colors import ListedColormap, Normalize, TwoSlopeNorm
    from matplotlib.patches import Patch

    if not callable(body_factory):
        raise TypeError(
            f"body_factory must be callable (angle -> PlanarBody), got {body_factory!r}"
        )
    if not isinstance(n, int | np.integer) or isinstance(n, bool) or n < 2:
        raise ValueError(f"n must be an integer >= 2, got {n!r}")
    if not 0 < extent <= 1e6:
        raise ValueError(f"extent must be in (0, 1e6], got {extent!r}")
    if angles is None:
        name = body_factory(np.asarray(math.pi / 4)).name
        if name not in _ANGLE_SPANS:
            raise ValueError(f"give the angles for a {name!r} body (rad)")
        lo, hi = _ANGLE_SPANS[name]
        angles = lo + (hi - lo) * (np.arange(n) + 0.5) / n
    th = np.asarray(angles, dtype=float).ravel()
    ratio = np.linspace(-extent, extent, n)
    body = body_factory(th[None, :])
    grid = {
        "newton": solve_planar(body, ratio[:, None], -1.0, 0.0, mu=mu, kappa=kappa, law="newton")
    }
    if law != "newton":
        grid[law] = solve_planar(body, ratio[:, None], -1.0, 0.0, mu=mu, kappa=kappa, law=law)
    newton, shown = grid["newton"], grid[law]
    deg = np.degrees(th)
    span = (deg[0], deg[-1], ratio[0], ratio[-1])
    fig = _figure(figsize=(12.5, 5.6))
    rx, ex = fig.subplots(1, 2, sharey=True)
    codes = np.searchsorted(
        np.asarray(PLANAR_REGIMES), shown.regime, sorter=np.argsort(PLANAR_REGIMES)
    )
    codes = np.argsort(PLANAR_REGIMES)[codes]
    cmap = ListedColormap([_REGIME_COLORS[r] for r in PLANAR_REGIMES])
    style = dict(origin="lower", extent=span, aspect="auto", interpolation="nearest")
    rx.imshow(codes, cmap=cmap, vmin=-0.5, vmax=len(PLANAR_REGIMES) - 0.5, **style)
    present = [r for r in PLANAR_REGIMES if np.any(shown.regime == r)]
    rx.legend(
        [Patch(color=_REGIME_COLORS[r]) for r in present],
        present,
        title="regime",
        loc="upper center",
        bbox_to_anchor=(0.5, -0.13),
        ncols=3,
        fontsize="small",
    )
    rx.set_title(f"regimes under {LAW_NAMES[law]}", fontsize="medium")
    gain = -np.asarray(newton.dissipated_fraction)
    top, bottom = float(np.max(gain)), float(np.min(gain))
    if top > 0:
        norm, cmap2 = TwoSlopeNorm(0.0, min(bottom, -top * 1e-3), top), "RdBu_r"
    else:
        norm, cmap2 = Normalize(bottom, 0.0), "Blues_r"
    im = ex.imshow(gain, cmap=cmap2, norm=norm, **style)
    bar = fig.colorbar(im, ax=ex, label=r"$(E^+ - E^-)/E^-$ under Newton's law")
    if top > 0:  # 0 sits mid-bar: round ticks on each side, spaced for its own half
        bar.set_ticks(round_ticks(norm.vmin, top))
    created = np.asarray(newton.creates_energy)
    if created.any():
        mask = created.astype(float)
        ex.contourf(deg, ratio, mask, levels=[0.5, 1.5], colors="none", hatches=["///"])
        ex.contour(deg, ratio, mask, levels=[0.5], colors="k", linewidths=1.4)
        ex.legend(
            [Patch(facecolor="none", edgecolor="k", hatch="///")],
            [r"Newton creates energy, $E^+ > E^-$"],
            loc="upper center",
            bbox_to_anchor=(0.5, -0.13),
            fontsize="small",
        )
        ex.set_title(
            f"Newton's law creates energy on {created.mean():.1%} of the map", fontsize="medium"
        )
    else:
        ex.set_title("Newton's law creates no energy on this map", fontsize="medium")
    for ax in (rx, ex):
        ax.set_xlabel(r"angle $\theta$ of the body (degrees)")
    rx.set_ylabel(r"slip ratio $u^-/|v^-|$")
    fig.suptitle(
        f"{body.name}, $\\mu = {mu:g}$, $\\kappa = {kappa:g}$; incidence without spin, "
        r"$v_y^- = -1$ m/s, $v_x^- = u^-$",
        fontsize="medium",
    )
    return fig
