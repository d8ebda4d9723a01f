"""The figure of impacts under micro-slip in time (Matplotlib, imported lazily).

:func:`plot_micro_slip` draws what :class:`~spinimpact.MindlinDeresiewicz` computes inside
an impact (:func:`spinimpact.core.mdr.mdr_trace`): the friction force over Coulomb's bound,
the radius of the contact's stuck core over the contact radius, and the contact point's
slip velocity, over the time of the contact. The law's rebound depends on the incidence
through ratios only, so the figure is dimensionless.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..core.mdr import mdr_trace
from ..model.body import Body
from ..model.compliance import MindlinDeresiewicz
from ..model.impact import solve

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_micro_slip", "MOST_CURVES"]

#: Most impacts one figure draws.
MOST_CURVES = 12


def plot_micro_slip(law: MindlinDeresiewicz, body: Body, vx: Any, vy: Any, omega: Any = 0.0, *,
                    mu: Any, kappa: Any, labels: Any = None) -> Figure:  # fmt: skip
    """Friction force, stuck core and slip over the contact time of impacts under
    micro-slip.

    Parameters
    ----------
    law : MindlinDeresiewicz
        The law (its stiffness ratio and resolution).
    body : Body
        One body (scalar parameters).
    vx, vy, omega : float or array_like
        Incidences as for :func:`~spinimpact.solve` (m/s, m/s, rad/s), broadcast together;
        one curve per impact, at most :data:`MOST_CURVES`.
    mu, kappa : float
        Friction coefficient and Newton's restitution (``0 < kappa <= 1``).
    labels : sequence of str, optional
        One legend entry per impact (default: the incidence angle and the regime).

    Returns
    -------
    matplotlib.figure.Figure
        Three panels over ``t/t_c``: ``F/(mu N)`` (``+-1``: Coulomb's bound, the whole
        contact slides), ``c/a`` (1: the whole contact sticks; 0: it slides), and the
        contact point's slip ``u/|v_n^-|``.

    Examples
    --------
    >>> from spinimpact import Body, MindlinDeresiewicz
    >>> from spinimpact.viz.micro_slip import plot_micro_slip
    >>> fig = plot_micro_slip(MindlinDeresiewicz(poisson_ratio=0.23, steps=512),
    ...                       Body.solid_sphere(mass=2.6e-4, radius=2.5e-3),
    ...                       [0.14, 0.67], -3.9, 0.0, mu=0.092, kappa=0.98)
    >>> len(fig.axes), len(fig.axes[0].lines)   # two impacts and Coulomb's two bounds
    (3, 4)
    """
    if not isinstance(law, MindlinDeresiewicz):
        raise TypeError(f"law must be a spinimpact.MindlinDeresiewicz, got {law!r}")
    if not isinstance(body, Body) or np.ndim(body.mass) or np.ndim(body.zeta):
        raise TypeError(f"body must be one spinimpact.Body (scalar parameters), got {body!r}")
    for name, value in (("mu", mu), ("kappa", kappa)):
        if np.ndim(value):
            raise TypeError(f"{name} must be one number here, got {value!r}")
    imp = solve(body, vx, vy, omega, mu=mu, kappa=kappa, tangential=law)  # validates all
    before = imp.before
    vxs, vys, oms = (np.atleast_1d(np.asarray(a, dtype=float)).ravel()
                     for a in (before.vx, before.vy, before.omega))  # fmt: skip
    regimes = np.atleast_1d(np.asarray(imp.regime)).ravel()
    if vxs.size > MOST_CURVES:
        raise ValueError(f"plot_micro_slip draws at most {MOST_CURVES} impacts, got {vxs.size}")
    if labels is not None:
        labels = [str(x) for x in labels]
        if len(labels) != vxs.size:
            raise ValueError(f"labels must give one entry per impact ({vxs.size}), "
                             f"got {len(labels)}")  # fmt: skip
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), constrained_layout=True)
    for k in range(vxs.size):
        slip = vxs[k] + float(body.radius) * oms[k]
        tr = mdr_trace(slip, vys[k], float(body.zeta), float(mu), float(kappa),
                       law.stiffness_ratio, law.springs, law.steps)  # fmt: skip
        t = tr.t / tr.t[-1]
        with np.errstate(divide="ignore", invalid="ignore"):
            bound = float(mu) * tr.normal_force
            ratio = np.where(tr.normal_force > 0, -tr.tangential_force / bound, np.nan)
        if labels is None:
            angle = np.degrees(np.arctan2(abs(slip), -vys[k]))
            label = f"{angle:.3g} deg, {regimes[k]}"
        else:
            label = labels[k]
        axes[0].plot(t, ratio, lw=1.6, label=label)
        axes[1].plot(t, tr.stick_radius, lw=1.6, label=label)
        axes[2].plot(t, tr.slip, lw=1.6, label=label)
    for bound in (1.0, -1.0):
        axes[0].axhline(bound, color="0.5", lw=0.8)
    axes[0].set_ylabel(r"friction force over Coulomb's bound, $F/(\mu N)$")
    axes[1].set_ylabel("stuck core over the contact radius, c/a")
    axes[2].set_ylabel(r"contact point's slip, $u/|v_n^-|$")
    for ax in axes:
        ax.set_xlabel("time over the contact time")
        ax.grid(alpha=0.3)
    # beside the last panel, where no curve runs
    axes[2].legend(*axes[1].get_legend_handles_labels(), title="incidence of the contact point",
                   fontsize="small", title_fontsize="small", loc="upper left",
                   bbox_to_anchor=(1.02, 1.0), borderaxespad=0)  # fmt: skip
    fig.suptitle(f"Mindlin-Deresiewicz micro-slip, {_stiffness(law)}: $\\mu$ = {float(mu):g}, "
                 f"$\\kappa$ = {float(kappa):g}, $\\zeta$ = {float(body.zeta):.4g}",
                 fontsize="medium")  # fmt: skip
    return fig


def _stiffness(law: MindlinDeresiewicz) -> str:
    """The law's elastic input in words: Poisson's ratio, or the stiffness ratio given."""
    if law.poisson_ratio is not None:
        return f"Poisson's ratio $\\nu$ = {law.poisson_ratio:g}"
    return f"stiffness ratio $4G^*/E^*$ = {law.stiffness_ratio:g}"
