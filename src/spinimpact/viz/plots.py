"""Figures of the impact process (Matplotlib, imported lazily).

Each function takes a single :class:`~spinimpact.Impact` and returns a
:class:`matplotlib.figure.Figure`, so it displays inline in Jupyter and can be
saved with ``fig.savefig``. All curves come from :meth:`Impact.history`; nothing
here computes physics. Every symbol is typeset with Matplotlib's mathtext, and the
marks of ``tau_0``, ``tau_*`` and ``tau_1`` are named above the axes, where no curve
runs. The maps over the incidence are in :mod:`spinimpact.viz.maps`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..model.impact import Impact
from ._labels import mathtext_escape, min_energy_words
from .maps import incidence_grid, plot_map

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = [
    "plot_history",
    "plot_routh",
    "plot_energy",
    "impact_figures",
    "PAPER_FIGURES",
    "paper_figure",
    "incidence_grid",
    "plot_map",
    "plot_simulation",
]


def _figure(*args, **kwargs) -> Figure:
    from matplotlib.figure import Figure  # no pyplot: no global state, no GUI backend

    return Figure(*args, layout="constrained", **kwargs)


#: Marks closer than this share of the impulse axis have their names on two rows.
_CLOSE = 0.08


def _marks(ax, h) -> None:
    """Vertical lines at tau0, tau* and tau1 (where inside the impact), named by ticks
    on an axis above the plot, where no curve or label of the data can be; a name
    closer than :data:`_CLOSE` of the axis to the previous one goes a row higher."""
    marks = [
        (h.tau0, r"$\tau_0$", ":"),
        (h.tau_star, r"$\tau_*$", "--"),
        (h.tau1, r"$\tau_1$", "-"),
    ]
    shown = sorted((t, name, style) for t, name, style in marks if 0 < t <= h.tau1)
    for tau, _, style in shown:
        ax.axvline(tau, color="0.45", lw=0.9, ls=style, zorder=0)
    top = ax.secondary_xaxis("top")
    top.set_xticks([t for t, *_ in shown], [name for _, name, _ in shown])
    top.tick_params(length=3, color="0.45", labelcolor="0.3", pad=1)
    row = 0
    for i, tick in enumerate(top.xaxis.get_major_ticks()[: len(shown)]):
        close = i > 0 and shown[i][0] - shown[i - 1][0] < _CLOSE * h.tau1
        row = row + 1 if close else 0
        tick.set_pad(1 + 11 * row)


def _title(imp: Impact) -> str:
    return (
        rf"{mathtext_escape(imp.body.name)}, $\mu$ = {float(imp.mu):g}, "
        rf"$\kappa$ = {float(imp.kappa):g}, $|u^-/v^-|$ = {float(imp.incidence_ratio):.3g}: "
        f"{imp.regime}"
    )


_TAU = r"normal impulse $\tau$ (N s)"


def _impact(imp: object) -> Impact:
    """``imp`` if it is an :class:`~spinimpact.Impact`, else a ``TypeError`` naming it."""
    if not isinstance(imp, Impact):
        raise TypeError(
            f"imp must be a spinimpact.Impact (what spinimpact.solve returns), "
            f"got {type(imp).__name__}"
        )
    return imp


def plot_history(imp: Impact, n: int = 401) -> Figure:
    """Force ratio ``F/N``, normal velocity ``v``, slip ``u`` and spin ``omega``
    against the normal impulse ``tau``, with ``tau0``, ``tau*``, ``tau1`` marked
    (the paper's Figs. 2 and 3)."""
    h = _impact(imp).history(n)
    fig = _figure(figsize=(8, 6.4))
    axes = fig.subplots(2, 2, sharex=True)
    panels = (
        (h.force_ratio, r"force ratio $F/N$", "(a)"),
        (h.vy, r"normal velocity $v$ (m/s)", "(b)"),
        (h.slip, r"slip velocity $u$ (m/s)", "(c)"),
        (h.omega, r"angular velocity $\omega$ (rad/s)", "(d)"),
    )
    for ax, (y, label, tag) in zip(axes.flat, panels, strict=True):
        ax.plot(h.tau, y, color="C0", lw=1.8)
        ax.axhline(0, color="0.7", lw=0.8, zorder=0)
        _marks(ax, h)
        ax.set_ylabel(label)
        ax.set_title(tag, loc="left", fontsize="medium")
    for ax in axes[1]:
        ax.set_xlabel(_TAU)
    fig.suptitle(_title(imp))
    return fig


def plot_routh(imp: Impact, n: int = 401) -> Figure:
    """Routh's impact diagram: friction impulse ``f`` against normal impulse
    ``tau`` (the paper's Fig. 4), with the Coulomb cone ``|f| = mu tau``."""
    h = _impact(imp).history(n)
    fig = _figure(figsize=(6, 4.4))
    ax = fig.subplots()
    mu = float(imp.mu)
    cone = dict(color="0.6", ls="--", lw=1)
    ax.plot(h.tau, mu * h.tau, **cone, label=r"$\pm\mu\tau$ (Coulomb limit)")
    ax.plot(h.tau, -mu * h.tau, **cone)
    ax.plot(h.tau, h.tangential_impulse, color="C3", lw=2, label=r"$f(\tau)$")
    ax.axhline(0, color="0.7", lw=0.8, zorder=0)
    _marks(ax, h)
    ax.set_xlabel(_TAU)
    ax.set_ylabel(r"friction impulse $f$ (N s)")
    fig.legend(loc="outside lower center", ncol=2)  # below the axes: on no line
    fig.suptitle(_title(imp), fontsize="medium")
    return fig


def plot_energy(imp: Impact, n: int = 401) -> Figure:
    """Kinetic energy ``E(tau)`` with its minimum ``E_m`` at ``tau_m`` marked (the
    paper's Fig. 5; the values are in the panel's title, clear of every line), and the
    works of the normal and friction forces by phase."""
    h = _impact(imp).history(n)
    fig = _figure(figsize=(9, 4.2))
    ax, bx = fig.subplots(1, 2, width_ratios=[3, 2])
    ax.plot(h.tau, h.kinetic_energy, color="C2", lw=2)
    tm, em = float(imp.tau_min_energy), float(imp.min_kinetic_energy)
    ax.plot([tm], [em], "o", color="k", zorder=3)
    _marks(ax, h)
    ax.set_xlabel(_TAU)
    ax.set_ylabel(r"kinetic energy $E$ (J)")
    ax.set_title(
        f"minimum: {min_energy_words(imp)}\n"
        rf"$E_m$ = {em:.4g} J at $\tau_m$ = {tm:.4g} N s (dot)",
        fontsize="medium",
    )
    phases = ("compression", "restitution")
    normal = (float(imp.work_compression_normal), float(imp.work_restitution_normal))
    friction = (float(imp.work_compression_tangential), float(imp.work_restitution_tangential))
    x = [0.0, 1.0]
    bx.bar([i - 0.18 for i in x], normal, width=0.36, label="normal force", color="C0")
    bx.bar([i + 0.18 for i in x], friction, width=0.36, label="friction", color="C3")
    bx.axhline(0, color="0.4", lw=0.8)
    bx.set_xticks(x, phases)
    bx.set_ylabel("work (J)")
    # the panel's title and key in one, on top of the bars' panel, where no bar reaches
    bx.legend(title="works by phase", title_fontsize="medium", loc="lower center",
              bbox_to_anchor=(0.5, 1.0), ncols=2, frameon=False, borderaxespad=0.2)  # fmt: skip
    fig.suptitle(_title(imp))
    return fig


def impact_figures(imp: Impact) -> dict[str, Figure]:
    """The three figures of one impact, by name: ``history``, ``routh`` and ``energy``."""
    return {"history": plot_history(imp), "routh": plot_routh(imp), "energy": plot_energy(imp)}


#: The paper's figures with inputs that put each in its regime: a solid disk
#: (m = 1 kg, R = 0.1 m, no spin) striking at vy = -1 m/s on mu = 0.25,
#: kappa = 0.6, so zeta mu = 0.75 and (1 + kappa) zeta mu = 1.2.
#: name -> (plot, vx, caption)
PAPER_FIGURES = {
    "fig2": ("history", 1.0, r"Fig. 2: slip then stick, $\tau_* < \tau_1$ ($|u/v| = 1$)"),
    "fig3": ("history", 2.0, r"Fig. 3: slip throughout, $\tau_* > \tau_1$ ($|u/v| = 2$)"),
    "fig4a": ("routh", -1.0, r"Fig. 4a: Routh diagram, $u^- < 0$, $\tau_* < \tau_1$"),
    "fig4b": ("routh", -2.0, r"Fig. 4b: Routh diagram, $u^- < 0$, $\tau_* > \tau_1$"),
    "fig5a": (
        "energy",
        1.0,
        r"Fig. 5a: minimum while sliding, $\zeta\mu < |u/v| \leq (1+\kappa)\zeta\mu$",
    ),
    "fig5b": ("energy", 0.5, r"Fig. 5b: minimum while rolling, $|u/v| < \zeta\mu$"),
    "fig5c": ("energy", 2.0, "Fig. 5c: sliding throughout, minimum after compression"),
}


def paper_figure(name: str) -> Figure:
    """One of :data:`PAPER_FIGURES`, computed with :func:`spinimpact.solve`."""
    from ..model.body import Body
    from ..model.impact import solve

    if not isinstance(name, str):
        raise TypeError(f"name must be one of {', '.join(PAPER_FIGURES)}; got {name!r}")
    if name not in PAPER_FIGURES:
        raise ValueError(f"figure must be one of {', '.join(PAPER_FIGURES)}; got {name!r}")
    kind, vx, caption = PAPER_FIGURES[name]
    imp = solve(Body.solid_disk(mass=1.0, radius=0.1), vx, -1.0, 0.0, mu=0.25, kappa=0.6)
    fig = {"history": plot_history, "routh": plot_routh, "energy": plot_energy}[kind](imp)
    fig.suptitle(f"{caption}\n{fig.get_suptitle() or _title(imp)}", fontsize="medium")
    return fig


def plot_simulation(sim) -> Figure:
    """Normal and friction force, velocities and slip of a compliant impact
    against time (:func:`spinimpact.dynamics.simulate`), with the end of
    compression and the stick instant marked."""
    from ..model.dynamics import Simulation

    if not isinstance(sim, Simulation):
        raise TypeError(
            "sim must be a Simulation (what spinimpact.dynamics.simulate returns), "
            f"got {type(sim).__name__}"
        )
    fig = _figure(figsize=(10, 6.4))
    axes = fig.subplots(2, 2, sharex=True)
    t = sim.t * 1e3
    series = (
        ((sim.normal_force, "normal $N$"), (sim.friction_force, "friction $F$")),
        ((sim.vx, "$v_x$"), (sim.vy, "$v_y$")),
        ((sim.slip, "slip $u$"),),
        ((sim.omega, r"$\omega$"),),
    )
    labels = (
        "force (N)",
        "velocity (m/s)",
        r"slip velocity $u$ (m/s)",
        r"angular velocity $\omega$ (rad/s)",
    )
    for ax, group, label in zip(axes.flat, series, labels, strict=True):
        for y, name in group:
            ax.plot(t, y, lw=1.6, label=name)
        ax.axhline(0, color="0.7", lw=0.8, zorder=0)
        if sim.stick_time == sim.stick_time:
            ax.axvline(sim.stick_time * 1e3, color="0.45", ls="--", lw=0.9, label="stick")
        ax.set_ylabel(label)
        if len(group) > 1:  # above the axes, where no curve runs
            ax.legend(loc="lower left", bbox_to_anchor=(0, 1.01), ncol=3, fontsize="small")
    for ax in axes[1]:
        ax.set_xlabel("time (ms)")
    fig.suptitle(
        f"{sim.contact.__class__.__name__}: duration {sim.contact_duration * 1e3:.4g} ms, "
        f"peak force {sim.peak_force:.4g} N, $\\kappa$ = {sim.newton_restitution:.4f}"
    )
    return fig
