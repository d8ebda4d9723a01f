"""Maps over the incidence (Matplotlib, imported lazily): regimes, rebound outcomes,
energy lost, ``mu_hat``, the friction work ratio and the rebound slip on one grid of
dimensionless incidences.

The grid is solved a block of rows at a time and only the six pictured fields are kept,
so memory stays bounded by the picture, not by the whole :class:`~spinimpact.Impact`;
given the resolution it will be saved at, :func:`plot_map` never computes more grid
points than a panel has pixels.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from .._validation import scalar
from ..core import regime_thresholds
from ..model.body import Body
from ._labels import mathtext_escape

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["incidence_grid", "map_fields", "plot_map", "map_regimes", "map_outcomes"]

#: Grid points solved at once: a block of rows of about this many points (a few MB).
BLOCK = 1 << 16
#: Figure size of :func:`plot_map`, inches.
SIZE = (15.0, 9.2)

_REGIME_COLORS = {
    "frictionless": "#bbbbbb",
    "stick-compression": "#4c72b0",
    "stick-restitution": "#8fb8de",
    "slip": "#dd8452",
}


def _grid(extent: float, n: Any) -> np.ndarray:
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 2:
        raise ValueError(f"n must be an integer >= 2, got {n!r}")
    if not 0 < extent <= 1e6:
        raise ValueError(f"extent must be in (0, 1e6], got {extent!r}")
    return np.linspace(-extent, extent, int(n))


def _inputs(body: Any, mu: Any, kappa: Any) -> tuple[float, float]:
    """A map's ``mu`` and ``kappa`` as floats, once ``body`` is known to be a
    :class:`~spinimpact.Body`: a map is drawn at one friction and one restitution."""
    if not isinstance(body, Body):
        raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
    if callable(kappa):
        raise TypeError(
            f"kappa must be a number in [0, 1], not a restitution model: the maps are drawn "
            f"at one restitution over every impact speed, got {kappa!r}"
        )
    why = "a map is drawn at one mu and one kappa"
    return scalar("mu", mu, why=why), scalar("kappa", kappa, why=why)


def _radius(body: Any) -> float:
    radius = np.asarray(body.radius)
    if radius.ndim:
        raise ValueError("incidence maps need a single body, not an array of bodies")
    return float(radius)


def incidence_grid(body, *, mu: float, kappa: float, extent: float = 3.0, n: int = 400):
    """Solve every impact of an ``n`` x ``n`` grid of dimensionless incidences.

    The axes are ``a = vx/|vy|`` and ``b = R omega/|vy|``, each on
    ``[-extent, extent]``; every result of the theory depends on the incidence
    only through these ratios (and ``zeta``, ``mu``, ``kappa``), so the grid is
    solved at ``vy = -1`` m/s. Returns ``(a, b, impact)`` with ``impact`` of shape
    ``(n, n)``, indexed ``[b, a]``. The whole :class:`~spinimpact.Impact` is kept
    (about 0.4 kB per point); :func:`map_fields` keeps only what a map shows.
    """
    from ..model.impact import solve

    mu, kappa = _inputs(body, mu, kappa)
    a = _grid(extent, n)
    b = a.copy()
    imp = solve(body, a[None, :], -1.0, b[:, None] / _radius(body), mu=mu, kappa=kappa)
    return a, b, imp


def map_regimes(mu: float, kappa: float) -> tuple[str, ...]:
    """The regimes that can occur on a map at this ``mu`` and ``kappa``, in order.

    Without friction every impact is ``frictionless``. With friction,
    ``stick-restitution`` needs ``zeta mu < |u/v| <= (1 + kappa) zeta mu``, empty when
    ``kappa = 0``; ``no-slip`` (``u^- = 0``) is a line of no width inside the
    ``stick-compression`` band, of which it is the limit (``tau_* = 0``), and is drawn
    in that band's colour.
    """
    if mu == 0:
        return ("frictionless",)
    middle = ("stick-restitution",) if kappa > 0 else ()
    return ("stick-compression", *middle, "slip")


def map_outcomes(mu: float) -> tuple[str, ...]:
    """The rebound outcomes a map can show at this ``mu`` (codes 0, 1, 2 in order).

    Against a fixed plane a rebound is never both backward and spin-reversed: both need
    the friction impulse ``f`` to oppose ``vx^-`` and ``omega^-`` (``vx^+ = vx^- + f/m``,
    ``omega^+ = omega^- + (zeta - 1) f/(m R)``), so ``vx^-`` and ``R omega^-`` share the
    sign of ``u^-`` and ``|u^-| = |vx^-| + R|omega^-|``; reversing both needs
    ``|f|/m > |vx^-|`` and ``(zeta - 1)|f|/m > R|omega^-|``, hence ``zeta |f|/m > |u^-|``,
    while friction at most stops the slip (``u^+ = u^- + zeta f/m`` never changes sign),
    ``|f| <= m |u^-|/zeta``. Without friction nothing reverses.
    """
    if mu == 0:
        return ("unchanged (no friction)",)
    return ("no reversal", r"backward ($v_x$ reverses)", r"spin reverses ($\omega$)")


def map_fields(body, *, mu: float, kappa: float, extent: float = 3.0, n: int = 400):
    """The fields a map shows, solved on the grid of :func:`incidence_grid` a block of
    about :data:`BLOCK` points at a time.

    Returns
    -------
    a, b : ndarray
        The axes ``vx/|vy|`` and ``R omega/|vy|``, length ``n``.
    fields : dict of ndarray
        Each ``(n, n)``, indexed ``[b, a]``: ``regime`` (int8, index into
        :func:`map_regimes`), ``outcome`` (int8, index into :func:`map_outcomes`), and,
        as float32, ``dissipated_fraction``, ``impulse_ratio``, ``work_ratio_tangential``,
        ``slip_after`` (``u^+/|v^-|``) and ``after_vx`` (m/s at ``|v^-|`` = 1 m/s), and, as
        float64, ``after_omega`` (rad/s of ``body``), for the lines ``vx^+ = 0`` and
        ``omega^+ = 0``.

    Notes
    -----
    The grid is solved for a body of ``body``'s ``zeta`` with unit mass and radius (``R
    omega = b``), since nothing else of the body changes a map: so any radius the solver
    accepts gives the same map, where ``omega = b/R`` would leave the accepted range for
    a tiny radius. Only ``after_omega`` is converted to the body's spin, ``R omega^+/R``.
    """
    from ..model.impact import solve

    mu, kappa = _inputs(body, mu, kappa)
    a = _grid(extent, n)
    b = a.copy()
    radius = _radius(body)
    unit = Body.from_zeta(mass=1.0, radius=1.0, zeta=float(body.zeta))
    n = a.size
    regimes = map_regimes(mu, kappa)
    code = {name: i for i, name in enumerate(regimes)} | {"no-slip": 0}
    floats = ("dissipated_fraction", "impulse_ratio", "work_ratio_tangential", "slip_after")
    out = {k: np.empty((n, n), np.int8) for k in ("regime", "outcome")}
    out |= {k: np.empty((n, n), np.float32) for k in (*floats, "after_vx")}
    out["after_omega"] = np.empty((n, n))  # float64: a tiny body's spins overflow float32
    step = max(1, BLOCK // n)
    for start in range(0, n, step):
        rows = slice(start, start + step)
        imp = solve(unit, a[None, :], -1.0, b[rows, None], mu=mu, kappa=kappa)
        names, inverse = np.unique(imp.regime, return_inverse=True)
        out["regime"][rows] = np.array([code[str(x)] for x in names], np.int8)[inverse]
        o = imp.outcome
        if np.any(o.backward & o.reversed_spin):  # impossible: see map_outcomes
            raise RuntimeError("a rebound both backward and spin-reversed: please report")
        out["outcome"][rows] = np.where(o.backward, 1, np.where(o.reversed_spin, 2, 0))
        for k in floats:
            out[k][rows] = getattr(imp, k)
        out["after_vx"][rows], out["after_omega"][rows] = imp.after.vx, imp.after.omega / radius
    return a, b, out


def _panel_pixels(body, mu: float, kappa: float, extent: float, dpi: float) -> int:
    """The most pixels a map panel spans along either side at ``dpi``: the layout of
    the same figure drawn on a 2 x 2 grid (the layout does not depend on the grid)."""
    fig = _draw(body, mu, kappa, *map_fields(body, mu=mu, kappa=kappa, extent=extent, n=2))
    fig.draw_without_rendering()
    images = [ax for ax in fig.get_axes() if ax.get_images()]
    boxes = [ax.get_window_extent() for ax in images]
    return math.ceil(max(max(x.width, x.height) for x in boxes) * dpi / fig.dpi)


def plot_map(
    body,
    *,
    mu: float,
    kappa: float,
    extent: float = 3.0,
    n: int = 400,
    dpi: float | None = None,
) -> Figure:
    """Maps over the incidence: regimes, rebound outcomes, and colour maps of the
    energy lost ``Delta E/E^-``, the tangential impact coefficient ``mu_hat`` and
    the friction work ratio ``W_r^t/W_c^t`` (eqs. 4.6, 4.14, 5.4-5.6, 6.15-6.19,
    7.7-7.9). Axes are ``vx/|vy|`` and ``R omega/|vy|``; the regime boundaries
    ``|u/v| = zeta mu`` and ``(1 + kappa) zeta mu`` are drawn on every panel.

    Parameters
    ----------
    body : Body
        One body; only its ``zeta`` matters (the maps are dimensionless: mass and
        size change nothing but through ``zeta = 1 + R^2/rho^2``).
    mu, kappa : float
        Friction and restitution.
    extent : float
        The axes span ``[-extent, extent]``.
    n : int
        Grid points per axis.
    dpi : float, optional
        The resolution the figure will be saved at: ``n`` is then lowered to the most
        pixels a panel spans, since more points would add no pixel. ``None``: ``n``
        as given.

    Raises
    ------
    TypeError
        A ``body`` that is not a :class:`~spinimpact.Body`, or a ``mu`` or ``kappa`` that
        is not a number (a restitution model included: a map is drawn at one ``kappa``).
    ValueError
        ``mu`` or ``kappa`` out of range or not a single number, a body of many sizes.

    Notes
    -----
    Only the regimes and outcomes that can occur are offered in the legends
    (:func:`map_regimes`, :func:`map_outcomes`, which proves that no rebound is both
    backward and spin-reversed). On the line ``u^- = 0`` friction does no work and
    ``W_r^t/W_c^t`` is 0/0; the panel shows it in the colour of its limit from both
    sides, 0 (the contact sticks during compression), not as a gap.
    """
    mu, kappa = _inputs(body, mu, kappa)
    if dpi is not None:
        n = max(2, min(n, _panel_pixels(body, mu, kappa, extent, dpi)))
    return _draw(body, mu, kappa, *map_fields(body, mu=mu, kappa=kappa, extent=extent, n=n))


def _draw(body, mu: float, kappa: float, a: np.ndarray, b: np.ndarray, f: dict) -> Figure:
    from matplotlib import colormaps
    from matplotlib.colors import ListedColormap
    from matplotlib.figure import Figure

    fig = Figure(figsize=SIZE, layout="constrained")
    axes = fig.subplots(2, 3, sharex=True, sharey=True)
    span = (a[0], a[-1], b[0], b[-1])
    limits = regime_thresholds(float(body.zeta), mu, kappa)

    def boundaries(ax):
        for level, style in zip(limits, ("--", "-"), strict=True):
            for sign in (-1, 1) if mu > 0 else ():  # a + b = +-level
                ax.plot(a, sign * level - a, color="k", lw=0.9, ls=style)
        ax.set_xlim(a[0], a[-1])
        ax.set_ylim(b[0], b[-1])

    def show(ax, field, title, cmap, label, **kw):
        im = ax.imshow(
            field, origin="lower", extent=span, aspect="auto", cmap=cmap,
            interpolation="nearest", **kw,
        )  # fmt: skip
        fig.colorbar(im, ax=ax, label=label, shrink=0.9)
        boundaries(ax)
        ax.set_title(title, fontsize="medium")
        return im

    def categories(ax, field, title, names, colors):
        im = show(ax, field, title, ListedColormap(colors), "", vmin=-0.5, vmax=len(names) - 0.5)
        im.colorbar.set_ticks(range(len(names)), labels=list(names))

    regimes = map_regimes(mu, kappa)
    categories(axes[0, 0], f["regime"], "regime", regimes, [_REGIME_COLORS[r] for r in regimes])
    outcomes = map_outcomes(mu)
    colors = ["#f2f2f2", "#e15759", "#76b7b2"][: len(outcomes)]
    categories(axes[0, 1], f["outcome"], "rebound outcome", outcomes, colors)
    if mu > 0:
        for key, color in (("after_vx", "#e15759"), ("after_omega", "#2f7f79")):
            axes[0, 1].contour(a, b, f[key], levels=[0], colors=color, linewidths=1.6)
    loss = r"$\Delta E/E^-$"
    show(
        axes[0, 2], f["dissipated_fraction"], f"energy lost {loss}", "viridis", loss, vmin=0, vmax=1
    )
    top = mu if mu else 1
    title = r"tangential impact coefficient $\hat\mu = f_1/\tau_1$"
    show(axes[1, 0], f["impulse_ratio"], title, "RdBu_r", r"$\hat\mu$", vmin=-top, vmax=top)
    ratio = r"$W_r^t/W_c^t$"
    undefined = "" if mu > 0 else ": undefined, no friction work"
    magma = colormaps["magma"]
    if mu > 0:  # on the line u^- = 0 the ratio is 0/0; from either side it tends to 0
        magma = magma.with_extremes(bad=magma(0.0))
    show(
        axes[1, 1], f["work_ratio_tangential"], f"friction work ratio {ratio}{undefined}",
        magma, ratio,
        vmin=0, vmax=max(kappa, 1e-9),
    )  # fmt: skip
    slip = r"$u^+/|v^-|$"
    show(axes[1, 2], f["slip_after"], f"rebound slip {slip}", "PuOr", slip)
    for ax in axes[1]:
        ax.set_xlabel(r"$v_x^-/|v_y^-|$")
    for ax in axes[:, 0]:
        ax.set_ylabel(r"$R\,\omega^-/|v_y^-|$")
    head = (
        f"{mathtext_escape(body.name)} ($\\zeta$ = {float(body.zeta):.4g}), "
        f"$\\mu$ = {mu:g}, $\\kappa$ = {kappa:g}."
    )
    if mu > 0:
        head += (
            f"  Dashed: $|u/v| = \\zeta\\mu$ = {limits[0]:.3g}; solid: "
            f"$|u/v| = (1+\\kappa)\\zeta\\mu$ = {limits[1]:.3g}.  Outcome panel lines: "
            "$v_x^+ = 0$ (red), $\\omega^+ = 0$ (teal)"
        )
    else:
        head += "  No friction: one regime, and the slip and spin do not change."
    fig.suptitle(head)
    return fig
