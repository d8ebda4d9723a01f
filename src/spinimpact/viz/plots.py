"""Figures of the impact process (Matplotlib, imported lazily).

Each function takes a single :class:`~spinimpact.Impact` and returns a
:class:`matplotlib.figure.Figure`, so it displays inline in Jupyter and can be
saved with ``fig.savefig``. All curves come from :meth:`Impact.history`; nothing
here computes physics.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..model.impact import Impact

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_history", "plot_routh", "plot_energy", "PAPER_FIGURES", "paper_figure"]


def _figure(*args, **kwargs) -> Figure:
    from matplotlib.figure import Figure  # no pyplot: no global state, no GUI backend

    return Figure(*args, layout="constrained", **kwargs)


def _marks(ax, h, labels: bool = True) -> None:
    """Vertical lines at tau0, tau* and tau1 (where inside the impact), labelled on
    three staggered rows so that close marks do not overprint."""
    marks = [(h.tau0, "τ₀", ":"), (h.tau_star, "τ*", "--"), (h.tau1, "τ₁", "-")]
    for row, (tau, name, style) in enumerate(marks):
        if 0 < tau <= h.tau1:
            ax.axvline(tau, color="0.45", lw=0.9, ls=style, zorder=0)
            if labels:  # the label of tau1 goes left of its line, inside the axes
                dx, ha = (-3, "right") if tau == h.tau1 else (3, "left")
                ax.annotate(
                    name,
                    (tau, 1.0),
                    xycoords=("data", "axes fraction"),
                    ha=ha,
                    xytext=(dx, -12 - 11 * row),
                    textcoords="offset points",
                    color="0.3",
                )


def _title(imp: Impact) -> str:
    return (
        f"{imp.body.name}, μ = {float(imp.mu):g}, κ = {float(imp.kappa):g}, "
        f"|u⁻/v⁻| = {float(imp.incidence_ratio):.3g}: {imp.regime}"
    )


def plot_history(imp: Impact, n: int = 401) -> Figure:
    """Force ratio ``F/N``, normal velocity ``v``, slip ``u`` and spin ``omega``
    against the normal impulse ``tau``, with ``tau0``, ``tau*``, ``tau1`` marked
    (the paper's Figs. 2 and 3)."""
    h = imp.history(n)
    fig = _figure(figsize=(8, 6.4))
    axes = fig.subplots(2, 2, sharex=True)
    panels = (
        (h.force_ratio, "force ratio F/N", "(a)"),
        (h.vy, "normal velocity v (m/s)", "(b)"),
        (h.slip, "slip velocity u (m/s)", "(c)"),
        (h.omega, "angular velocity ω (rad/s)", "(d)"),
    )
    for ax, (y, label, tag) in zip(axes.flat, panels, strict=True):
        ax.plot(h.tau, y, color="C0", lw=1.8)
        ax.axhline(0, color="0.7", lw=0.8, zorder=0)
        _marks(ax, h)
        ax.set_ylabel(label)
        ax.set_title(tag, loc="left", fontsize="medium")
    for ax in axes[1]:
        ax.set_xlabel("normal impulse τ (N s)")
    fig.suptitle(_title(imp))
    return fig


def plot_routh(imp: Impact, n: int = 401) -> Figure:
    """Routh's impact diagram: friction impulse ``f`` against normal impulse
    ``tau`` (the paper's Fig. 4), with the Coulomb cone ``|f| = mu tau``."""
    h = imp.history(n)
    fig = _figure(figsize=(6, 4.4))
    ax = fig.subplots()
    mu = float(imp.mu)
    ax.plot(h.tau, mu * h.tau, color="0.6", ls="--", lw=1, label="±μτ (Coulomb limit)")
    ax.plot(h.tau, -mu * h.tau, color="0.6", ls="--", lw=1)
    ax.plot(h.tau, h.tangential_impulse, color="C3", lw=2, label="f(τ)")
    ax.axhline(0, color="0.7", lw=0.8, zorder=0)
    _marks(ax, h)
    ax.set_xlabel("normal impulse τ (N s)")
    ax.set_ylabel("friction impulse f (N s)")
    ax.legend(loc="best")
    fig.suptitle(_title(imp), fontsize="medium")
    return fig


def plot_energy(imp: Impact, n: int = 401) -> Figure:
    """Kinetic energy ``E(tau)`` with its minimum ``tau_m`` marked (the paper's
    Fig. 5), and the works of the normal and friction forces by phase."""
    h = imp.history(n)
    fig = _figure(figsize=(9, 4.2))
    ax, bx = fig.subplots(1, 2, width_ratios=[3, 2])
    ax.plot(h.tau, h.kinetic_energy, color="C2", lw=2)
    tm, em = float(imp.tau_min_energy), float(imp.min_kinetic_energy)
    ax.plot([tm], [em], "o", color="k", zorder=3)
    ax.annotate(
        f"E_m = {em:.4g} J\nτ_m = {tm:.4g} N s",
        (tm, em),
        xytext=(0, 28),
        ha="center",
        textcoords="offset points",
        arrowprops={"arrowstyle": "-", "color": "0.5"},
    )
    _marks(ax, h)
    ax.set_xlabel("normal impulse τ (N s)")
    ax.set_ylabel("kinetic energy E (J)")
    ax.set_title(f"minimum: {imp.min_energy_case}", fontsize="medium")
    phases = ("compression", "restitution")
    normal = (float(imp.work_compression_normal), float(imp.work_restitution_normal))
    friction = (float(imp.work_compression_tangential), float(imp.work_restitution_tangential))
    x = [0.0, 1.0]
    bx.bar([i - 0.18 for i in x], normal, width=0.36, label="normal force", color="C0")
    bx.bar([i + 0.18 for i in x], friction, width=0.36, label="friction", color="C3")
    bx.axhline(0, color="0.4", lw=0.8)
    bx.set_xticks(x, phases)
    bx.set_ylabel("work (J)")
    bx.legend(loc="best")
    bx.set_title("works by phase", fontsize="medium")
    fig.suptitle(_title(imp))
    return fig


#: The paper's figures with inputs that put each in its regime: a solid disk
#: (m = 1 kg, R = 0.1 m, no spin) striking at vy = -1 m/s on mu = 0.25,
#: kappa = 0.6, so zeta mu = 0.75 and (1 + kappa) zeta mu = 1.2.
#: name -> (plot, vx, caption)
PAPER_FIGURES = {
    "fig2": ("history", 1.0, "Fig. 2: slip then stick, tau* < tau1 (|u/v| = 1)"),
    "fig3": ("history", 2.0, "Fig. 3: slip throughout, tau* > tau1 (|u/v| = 2)"),
    "fig4a": ("routh", -1.0, "Fig. 4a: Routh diagram, u- < 0, tau* < tau1"),
    "fig4b": ("routh", -2.0, "Fig. 4b: Routh diagram, u- < 0, tau* > tau1"),
    "fig5a": (
        "energy",
        1.0,
        "Fig. 5a: minimum while sliding, zeta mu < |u/v| <= (1+kappa) zeta mu",
    ),
    "fig5b": ("energy", 0.5, "Fig. 5b: minimum while rolling, |u/v| < zeta mu"),
    "fig5c": ("energy", 2.0, "Fig. 5c: sliding throughout, minimum after compression"),
}


def paper_figure(name: str) -> Figure:
    """One of :data:`PAPER_FIGURES`, computed with :func:`spinimpact.solve`."""
    from ..model.body import Body
    from ..model.impact import solve

    if name not in PAPER_FIGURES:
        raise ValueError(f"figure must be one of {', '.join(PAPER_FIGURES)}; got {name!r}")
    kind, vx, caption = PAPER_FIGURES[name]
    imp = solve(Body.solid_disk(mass=1.0, radius=0.1), vx, -1.0, 0.0, mu=0.25, kappa=0.6)
    fig = {"history": plot_history, "routh": plot_routh, "energy": plot_energy}[kind](imp)
    fig.suptitle(f"{caption}\n{fig.get_suptitle() or _title(imp)}", fontsize="medium")
    return fig


def incidence_grid(body, *, mu: float, kappa: float, extent: float = 3.0, n: int = 400):
    """Solve every impact of an ``n`` x ``n`` grid of dimensionless incidences.

    The axes are ``a = vx/|vy|`` and ``b = R omega/|vy|``, each on
    ``[-extent, extent]``; every result of the theory depends on the incidence
    only through these ratios (and ``zeta``, ``mu``, ``kappa``), so the grid is
    solved at ``vy = -1`` m/s. Returns ``(a, b, impact)`` with ``impact`` of shape
    ``(n, n)``, indexed ``[b, a]``.
    """
    import numpy as np

    from ..model.impact import solve

    if not isinstance(n, int | np.integer) or n < 2:
        raise ValueError(f"n must be an integer >= 2, got {n!r}")
    if not 0 < extent <= 1e6:
        raise ValueError(f"extent must be in (0, 1e6], got {extent!r}")
    a = np.linspace(-extent, extent, n)
    b = np.linspace(-extent, extent, n)
    radius = np.asarray(body.radius)
    if radius.ndim:
        raise ValueError("incidence maps need a single body, not an array of bodies")
    imp = solve(body, a[None, :], -1.0, b[:, None] / float(radius), mu=mu, kappa=kappa)
    return a, b, imp


def plot_map(body, *, mu: float, kappa: float, extent: float = 3.0, n: int = 400) -> Figure:
    """Maps over the incidence: regimes, rebound outcomes, and colour maps of the
    energy lost ``Delta E/E^-``, the tangential impact coefficient ``mu_hat`` and
    the friction work ratio ``W_r^t/W_c^t`` (eqs. 4.6, 4.14, 5.4-5.6, 6.15-6.19,
    7.7-7.9). Axes are ``vx/|vy|`` and ``R omega/|vy|``; the regime boundaries
    ``|u/v| = zeta mu`` and ``(1 + kappa) zeta mu`` are drawn on every panel.
    """
    import numpy as np
    from matplotlib.colors import ListedColormap

    from ..core import REGIMES, regime_thresholds

    a, b, imp = incidence_grid(body, mu=mu, kappa=kappa, extent=extent, n=n)
    fig = _figure(figsize=(15, 9.2))
    axes = fig.subplots(2, 3, sharex=True, sharey=True)
    span = (a[0], a[-1], b[0], b[-1])
    limits = regime_thresholds(float(body.zeta), mu, kappa)

    def boundaries(ax):
        for level, style in zip(limits, ("--", "-"), strict=True):
            for sign in (-1, 1):  # a + b = +-level
                ax.plot(a, sign * level - a, color="k", lw=0.9, ls=style)
        ax.set_xlim(a[0], a[-1])
        ax.set_ylim(b[0], b[-1])

    def show(ax, field, title, cmap, label, **kw):
        im = ax.imshow(
            field,
            origin="lower",
            extent=span,
            aspect="auto",
            cmap=cmap,
            interpolation="nearest",
            **kw,
        )
        fig.colorbar(im, ax=ax, label=label, shrink=0.9)
        boundaries(ax)
        ax.set_title(title, fontsize="medium")
        return im

    codes = np.searchsorted(np.asarray(REGIMES), imp.regime, sorter=np.argsort(REGIMES))
    order = np.argsort(REGIMES)
    codes = order[codes]
    colors = ["#bbbbbb", "#444444", "#4c72b0", "#8fb8de", "#dd8452"]
    im = show(axes[0, 0], codes, "regime", ListedColormap(colors), "", vmin=-0.5, vmax=4.5)
    im.colorbar.set_ticks(range(5), labels=list(REGIMES))

    o = imp.outcome
    outcome = o.backward.astype(int) + 2 * o.reversed_spin.astype(int)
    labels = ["forward, same spin", "backward", "reversed spin", "backward + reversed spin"]
    im = show(
        axes[0, 1],
        outcome,
        "rebound outcome",
        ListedColormap(["#f2f2f2", "#e15759", "#76b7b2", "#b07aa1"]),
        "",
        vmin=-0.5,
        vmax=3.5,
    )
    im.colorbar.set_ticks(range(4), labels=labels)
    axes[0, 1].contour(a, b, imp.after.vx, levels=[0], colors="#e15759", linewidths=1.6)
    axes[0, 1].contour(a, b, imp.after.omega, levels=[0], colors="#2f7f79", linewidths=1.6)

    loss = imp.dissipated_fraction
    show(axes[0, 2], loss, "energy lost ΔE/E⁻", "viridis", "ΔE/E⁻", vmin=0, vmax=1)
    show(
        axes[1, 0],
        imp.impulse_ratio,
        "tangential impact coefficient μ̂ = f₁/τ₁",
        "RdBu_r",
        "μ̂",
        vmin=-mu if mu else -1,
        vmax=mu if mu else 1,
    )
    show(
        axes[1, 1],
        imp.work_ratio_tangential,
        "friction work ratio W_r^t/W_c^t",
        "magma",
        "W_r^t/W_c^t",
        vmin=0,
        vmax=max(kappa, 1e-9),
    )
    show(axes[1, 2], imp.slip_after, "rebound slip u⁺/|v⁻|", "PuOr", "u⁺/|v⁻|")
    for ax in axes[1]:
        ax.set_xlabel("vx⁻/|vy⁻|")
    for ax in axes[:, 0]:
        ax.set_ylabel("R ω⁻/|vy⁻|")
    fig.suptitle(
        f"{body.name} (ζ = {float(body.zeta):.4g}), μ = {mu:g}, κ = {kappa:g}.  "
        f"Dashed: |u/v| = ζμ = {limits[0]:.3g}; solid: |u/v| = (1+κ)ζμ = {limits[1]:.3g}.  "
        "Outcome panel lines: vx⁺ = 0 (red), ω⁺ = 0 (teal)"
    )
    return fig


def plot_simulation(sim) -> Figure:
    """Normal and friction force, velocities and slip of a compliant impact
    against time (:func:`spinimpact.dynamics.simulate`), with the end of
    compression and the stick instant marked."""
    fig = _figure(figsize=(10, 6.4))
    axes = fig.subplots(2, 2, sharex=True)
    t = sim.t * 1e3
    series = (
        ((sim.normal_force, "N"), (sim.friction_force, "F")),
        ((sim.vx, "vx"), (sim.vy, "vy")),
        ((sim.slip, "slip u"),),
        ((sim.omega, "ω"),),
    )
    labels = ("force (N)", "velocity (m/s)", "slip velocity (m/s)", "angular velocity (rad/s)")
    for ax, group, label in zip(axes.flat, series, labels, strict=True):
        for y, name in group:
            ax.plot(t, y, lw=1.6, label=name)
        ax.axhline(0, color="0.7", lw=0.8, zorder=0)
        if sim.stick_time == sim.stick_time:
            ax.axvline(sim.stick_time * 1e3, color="0.45", ls="--", lw=0.9, label="stick")
        ax.set_ylabel(label)
        if len(group) > 1:
            ax.legend(loc="best", fontsize="small")
    for ax in axes[1]:
        ax.set_xlabel("time (ms)")
    fig.suptitle(
        f"{sim.contact.__class__.__name__}: duration {sim.contact_duration * 1e3:.4g} ms, "
        f"peak force {sim.peak_force:.4g} N, κ = {sim.newton_restitution:.4f}"
    )
    return fig
