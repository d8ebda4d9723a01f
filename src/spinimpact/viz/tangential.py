"""The figure of an impact with tangential compliance in time (Matplotlib, imported lazily).

:func:`plot_tangential` draws a :class:`~spinimpact.model.mindlin.TangentialSimulation`:
the normal force and the tangential force inside Coulomb's cone, the tangential spring's
displacement, the contact point's velocity and the interface slip, and the energy that
never increases; the stick phases are shaded.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..model.mindlin import TangentialSimulation

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_tangential"]


def _stick_spans(t: np.ndarray, stuck: np.ndarray) -> list[tuple[float, float]]:
    """The time intervals where the contact sticks."""
    spans, start = [], None
    for time, s in zip(t, stuck, strict=True):
        if s and start is None:
            start = time
        elif not s and start is not None:
            spans.append((start, time))
            start = None
    if start is not None:
        spans.append((start, t[-1]))
    return spans


def plot_tangential(sim: TangentialSimulation) -> Figure:
    """Forces, spring displacement, velocities and energy of a compliant impact in time.

    Parameters
    ----------
    sim : TangentialSimulation
        Result of :func:`spinimpact.dynamics.simulate` with ``tangential=``.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> from spinimpact import Body
    >>> from spinimpact.dynamics import HertzContact, Mindlin, simulate
    >>> ball = Body.solid_sphere(mass=2.618e-4, radius=0.0025)
    >>> law = HertzContact(youngs_modulus=3.8e11, poisson_ratio=0.23, radius=0.0025)
    >>> sim = simulate(ball, 1.334, -3.665, 0.0, mu=0.092, contact=law, tangential=Mindlin())
    >>> len(plot_tangential(sim).axes)
    4
    """
    if not isinstance(sim, TangentialSimulation):
        raise TypeError(f"sim must be a TangentialSimulation, got {type(sim).__name__}")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10, 6.8), layout="constrained")
    axes = fig.subplots(2, 2, sharex=True)
    t = np.asarray(sim.t) * 1e6
    cap = sim.mu * np.asarray(sim.normal_force)
    (ax_f, ax_x), (ax_v, ax_e) = axes
    ax_f.plot(t, sim.normal_force, lw=1.6, label="normal $N$")
    ax_f.plot(t, sim.tangential_force, lw=1.6, label="tangential $F$")
    ax_f.plot(t, cap, "k:", lw=1.0, label=r"$\pm\mu N$")
    ax_f.plot(t, -cap, "k:", lw=1.0)
    ax_f.set_ylabel("force (N)")
    ax_x.plot(t, np.asarray(sim.spring_displacement) * 1e6, lw=1.6, color="C2")
    ax_x.set_ylabel(r"spring displacement $\xi$ ($\mu$m)")
    ax_v.plot(t, sim.contact_velocity, lw=1.6, label=r"contact point $u = v_x + R\omega$")
    ax_v.plot(t, sim.slip, lw=1.6, label=r"slip $w = u - \dot\xi$")
    ax_v.set_ylabel("velocity (m/s)")
    e = np.asarray(sim.energy)
    ax_e.plot(t, (e - e[0]) / e[0], lw=1.6, color="C3")
    spring = sim.tangential.spring
    stored = r"U_t" if spring == "history" else r"F^2/(2k_t)"  # history: the field's energy
    ax_e.set_ylabel(rf"$(E - E_0)/E_0$, $E = T + U_n + {stored}$")
    spans = _stick_spans(t, np.asarray(sim.stuck))
    for ax in axes.flat:
        ax.axhline(0, color="0.7", lw=0.8, zorder=0)
        for a, b in spans:
            ax.axvspan(a, b, color="0.9", zorder=-1)
    for ax in (ax_f, ax_v):  # above the axes, where no curve runs
        ax.legend(loc="lower left", bbox_to_anchor=(0, 1.01), ncol=3, fontsize="small")
    for ax in axes[1]:
        ax.set_xlabel(r"time ($\mu$s); stick phases shaded")
    switches = f"{sim.switches} stick/slip switch{'' if sim.switches == 1 else 'es'}"
    fig.suptitle(
        f"{type(sim.contact).__name__}, Mindlin spring ({spring}): "
        f"$k_t/k_n$ = {sim.stiffness_ratio:.3f}, {switches}, "
        f"$\\beta$ = {float(sim.tangential_restitution):.3f}"
    )
    return fig
