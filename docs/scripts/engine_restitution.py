"""Table and figure for docs/engines.md: the engine setting for a head-on restitution e.

Usage: python docs/scripts/engine_restitution.py OUTPUT.png   (needs the [engines] extra)

For a ball of 60 g and radius 33 mm, spinimpact.engines.restitution_settings solves each
engine's one restitution setting for e in {0.5, 0.75, 0.9} at 2 m/s, every other setting at
the engine's default, and spinimpact.engines.restitution_curve measures the restitution it
then gives from 0.5 to 10 m/s (mean, least and greatest over 8 contact phases). MuJoCo is also
shown with the damping ratio a user would take from the damped linear oscillator,
xi = -ln e / sqrt(pi^2 + ln^2 e). Prints the table (Markdown) and draws the figure.
"""

import math
import sys

import numpy as np
from matplotlib.figure import Figure

from spinimpact import Body
from spinimpact import engines as E
from spinimpact.io import atomic_path

BALL = Body.solid_sphere(mass=0.06, radius=0.033)
TARGETS = (0.5, 0.75, 0.9)
AT = 2.0  # m/s: where e is asked for
TABLE_SPEEDS = np.array([0.5, 1.0, 2.0, 5.0, 10.0])
CURVE_SPEEDS = np.geomspace(0.5, 10.0, 13)
TOP = 1.3  # the figure's highest restitution
EXACT = {
    "contact_breaking_threshold": 0.0,
    "contact_erp": 0.0,
    "restitution_velocity_threshold": 0.0,
    "contact_slop": 0.0,
}


def oscillator(e: float) -> float:
    """Damping ratio of a linear spring-damper that bounces with restitution e."""
    log = math.log(e)
    return -log / math.sqrt(math.pi**2 + log**2)


def setups(e: float) -> list[tuple[str, str, str, dict, str | None]]:
    """(label, engine, the setting as text, settings, line style or None) for one target e."""
    pyb = E.restitution_settings("pybullet", e, AT, 1 / 240, BALL)
    exact = E.restitution_settings("pybullet", e, AT, 1 / 240, BALL, **EXACT)
    out = [
        ("PyBullet 1/240 s, its defaults", "pybullet", pyb["restitution"], pyb, "-"),
        ("PyBullet 1/240 s, exact contact", "pybullet", exact["restitution"], exact, "--"),
    ]
    for dt in (0.002, 0.0005):
        mj = E.restitution_settings("mujoco", e, AT, dt, BALL)
        naive = {**mj, "solref": (0.02, oscillator(e))}
        plotted = dt == 0.002
        out.append((f"MuJoCo {dt:g} s, solved", "mujoco", mj["solref"][1], mj, "-" * plotted))
        out.append((f"MuJoCo {dt:g} s, oscillator formula", "mujoco", oscillator(e), naive,
                    ":" * plotted))  # fmt: skip
    return out


def main(output: str) -> None:
    header = " | ".join(f"{v:g} m/s" for v in TABLE_SPEEDS)
    print(f"| e wanted at {AT:g} m/s | set-up | setting | {header} | range over phases at "
          f"{AT:g} m/s |")  # fmt: skip
    print("|---|---|---|" + "---:|" * (TABLE_SPEEDS.size + 1))
    fig = Figure(figsize=(13, 5.6), layout="constrained")
    subs = fig.subfigures(1, 2, wspace=0.02)
    axes = {"pybullet": subs[0].subplots(), "mujoco": subs[1].subplots()}
    colors = dict(zip(TARGETS, ("C0", "C1", "C2"), strict=True))
    at = int(np.flatnonzero(TABLE_SPEEDS == AT)[0])
    for e in TARGETS:
        for label, engine, value, settings, style in setups(e):
            table = E.restitution_curve(engine, settings, BALL, TABLE_SPEEDS)
            cells = " | ".join(f"{r:.3f}" for r in table.restitution)
            name = "restitution" if engine == "pybullet" else "solref damping ratio"
            spread = f"{table.low[at]:.3f} to {table.high[at]:.3f}"
            print(f"| {e} | {label} | {name} {value:.4f} | {cells} | {spread} |")
            if not style:
                continue
            curve = E.restitution_curve(engine, settings, BALL, CURVE_SPEEDS)
            kind = label.split(", ", 1)[1]
            if np.max(curve.restitution) > TOP:  # drawn above the axes: say where it is
                kind += f" (off the scale: about {np.mean(curve.restitution):.0f})"
            axes[engine].plot(CURVE_SPEEDS, curve.restitution, style, color=colors[e],
                              label=f"e = {e}: {kind}")  # fmt: skip
            if style == "-":
                axes[engine].fill_between(CURVE_SPEEDS, curve.low, curve.high, color=colors[e],
                                          alpha=0.12)  # fmt: skip
    titles = {
        "pybullet": "PyBullet, 1/240 s: restitution solved at 2 m/s",
        "mujoco": "MuJoCo, 0.002 s: solref damping ratio (time constant 0.02 s)",
    }
    for engine, ax in axes.items():
        ax.set_xscale("log")
        ax.set_xlabel("impact speed, m/s")
        ax.set_ylabel(r"head-on $v_y^+/|v_y^-|$, mean over 8 phases (band: range)")
        ax.set_title(titles[engine])
        ax.axvline(AT, color="0.6", lw=0.8)
        ax.grid(alpha=0.3)
        ax.set_ylim(0.0, TOP)
    for sub, ax in zip(subs, axes.values(), strict=True):
        sub.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncol=2, fontsize=9)
    with atomic_path(output) as tmp:
        fig.savefig(tmp, dpi=80, format="png")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
