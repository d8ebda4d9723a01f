"""A self-contained HTML report of one impact (figures embedded, no network)."""

from __future__ import annotations

import base64
import html
import io
import math
from typing import Any

from ..model.impact import Impact
from ..model.particle import ParticleImpact

__all__ = ["impact_report_html"]

_CSS = """
body { font-family: system-ui, -apple-system, "Segoe UI", sans-serif; margin: 2rem auto;
       max-width: 1100px; color: #222; line-height: 1.45; padding: 0 1rem; }
h1 { font-size: 1.5rem; margin-bottom: .2rem; } h2 { font-size: 1.15rem; margin-top: 2rem;
     border-bottom: 1px solid #ddd; padding-bottom: .2rem; }
.sub { color: #555; margin-top: 0; }
.regime { display: inline-block; padding: .15rem .6rem; border-radius: 1rem;
          background: #e8eef8; font-weight: 600; }
table { border-collapse: collapse; margin: .6rem 0; }
th, td { padding: .25rem .8rem; border-bottom: 1px solid #eee; text-align: right; }
th:first-child, td:first-child { text-align: left; }
thead th { border-bottom: 2px solid #ccc; }
.grid { display: flex; flex-wrap: wrap; gap: 2rem; }
.flag-yes { color: #0a6b2d; font-weight: 600; } .flag-no { color: #888; }
.warn { color: #a33; font-weight: 600; }
figure { margin: 1rem 0; } img { max-width: 100%; height: auto; }
figcaption { color: #555; font-size: .9rem; }
footer { margin-top: 3rem; color: #777; font-size: .85rem; }
"""

# Counts the figures the browser actually decoded, for a reader (or a test) to check.
_SCRIPT = """
window.addEventListener('load', function () {
  var imgs = document.querySelectorAll('img');
  var ok = 0;
  imgs.forEach(function (i) { if (i.complete && i.naturalWidth > 0) { ok += 1; } });
  document.body.setAttribute('data-figures-shown', ok + '/' + imgs.length);
});
"""


def _num(x: Any, unit: str = "") -> str:
    x = float(x) + 0.0  # no "-0"
    text = "∞" if math.isinf(x) else ("undefined" if math.isnan(x) else f"{x:.6g}")
    return html.escape(f"{text} {unit}".rstrip())


def _table(head: list[str], rows: list[list[str]]) -> str:
    h = "".join(f"<th>{html.escape(c)}</th>" for c in head)
    body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><thead><tr>{h}</tr></thead><tbody>{body}</tbody></table>"


def _png(fig: Any) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def impact_report_html(imp: Impact, particle: ParticleImpact | None = None) -> str:
    """The complete report of a single impact as one HTML page.

    Inputs, regime, rebound table, energy budget, works by phase, the three
    restitution coefficients, ``mu_hat``, the outcome flags and the figures
    (history, Routh's diagram, energy), embedded as PNG data so the page needs
    no network or other files.
    """
    from ..core import regime_thresholds
    from .plots import plot_energy, plot_history, plot_routh

    if imp.shape != ():
        raise ValueError(f"a report describes one impact; this Impact has shape {imp.shape}")
    b = imp.body
    low, high = regime_thresholds(b.zeta, imp.mu, imp.kappa)
    e0 = float(imp.kinetic_energy_before)

    def share(x: Any) -> str:
        return f"{float(x) / e0:.2%}" if e0 else ""

    inputs = _table(
        ["input", "value"],
        [
            ["body", html.escape(b.name)],
            ["mass m", _num(b.mass, "kg")],
            ["contact radius R", _num(b.radius, "m")],
            ["radius of gyration ρ", _num(b.gyration, "m")],
            ["ζ = 1 + R²/ρ²", _num(b.zeta)],
            ["friction μ", _num(imp.mu)],
            ["restitution κ", _num(imp.kappa)],
        ],
    )
    rebound = _table(
        ["", "before", "after"],
        [
            ["vx (m/s)", _num(imp.before.vx), _num(imp.after.vx)],
            ["vy (m/s)", _num(imp.before.vy), _num(imp.after.vy)],
            ["ω (rad/s)", _num(imp.before.omega), _num(imp.after.omega)],
            ["slip u = vx + Rω (m/s)", _num(imp.slip_before), _num(imp.slip_after)],
        ],
    )
    impulses = _table(
        ["normal impulse", "N s"],
        [
            ["end of compression τ₀", _num(imp.tau0)],
            ["end of slip τ*", _num(imp.tau_star)],
            ["end of impact τ₁", _num(imp.tau1)],
            ["friction impulse f₁", _num(imp.tangential_impulse)],
        ],
    )
    energy = _table(
        ["energy", "J", "of E⁻"],
        [
            ["kinetic energy before E⁻", _num(imp.kinetic_energy_before), share(e0)],
            [
                "kinetic energy after E⁺",
                _num(imp.kinetic_energy_after),
                share(imp.kinetic_energy_after),
            ],
            ["dissipated ΔE", _num(imp.dissipated_energy), share(imp.dissipated_energy)],
            [
                "minimum during impact E_m",
                _num(imp.min_kinetic_energy),
                share(imp.min_kinetic_energy),
            ],
        ],
    )
    wn = (imp.work_compression_normal, imp.work_restitution_normal)
    wt = (imp.work_compression_tangential, imp.work_restitution_tangential)
    works = _table(
        ["phase", "normal (J)", "friction (J)", "total (J)"],
        [
            ["compression", _num(wn[0]), _num(wt[0]), _num(wn[0] + wt[0])],
            ["restitution", _num(wn[1]), _num(wt[1]), _num(wn[1] + wt[1])],
            ["whole impact", _num(sum(wn)), _num(sum(wt)), _num(sum(wn) + sum(wt))],
        ],
    )
    coefficients = _table(
        ["coefficient", "value"],
        [
            ["Newton restitution −v⁺/v⁻", _num(imp.newton_restitution)],
            ["Poisson restitution (τ₁ − τ₀)/τ₀", _num(imp.poisson_restitution)],
            ["energetic restitution √(−W_r^n/W_c^n)", _num(imp.energetic_restitution)],
            ["tangential impact coefficient μ̂ = f₁/τ₁", _num(imp.impulse_ratio)],
            ["friction work ratio W_r^t/W_c^t", _num(imp.work_ratio_tangential)],
        ],
    )
    o = imp.outcome
    flags = _table(
        ["rebound outcome", ""],
        [
            [name, f'<span class="flag-{"yes" if v else "no"}">{"yes" if v else "no"}</span>']
            for name, v in (
                ("backward rebound", o.backward),
                ("reversed spin", o.reversed_spin),
                ("vertical rebound", o.vertical),
                ("leaves spinning", o.spinning),
                ("leaves rolling (u⁺ = 0)", o.rolling),
            )
        ],
    )
    figures = "".join(
        f'<figure><img alt="{html.escape(alt)}" src="data:image/png;base64,{_png(plot(imp))}">'
        f"<figcaption>{html.escape(caption)}</figcaption></figure>"
        for plot, alt, caption in (
            (
                plot_history,
                "impact history",
                "F/N, v, u and ω over the normal impulse τ (Figs. 2–3).",
            ),
            (
                plot_routh,
                "Routh diagram",
                "Routh's impact diagram: friction impulse f(τ) (Fig. 4).",
            ),
            (
                plot_energy,
                "kinetic energy",
                "Kinetic energy E(τ), its minimum, and the works by phase (Fig. 5).",
            ),
        )
    )
    compare = ""
    if particle is not None:
        verdict = (
            '<span class="warn">creates energy</span>'
            if particle.creates_energy
            else "dissipates energy"
        )
        compare = (
            "<h2>Compared with a material particle</h2><p>Whittaker's unidirectional-slip model "
            f"(eq. 8.7) for a particle with the same vx, vy leaves at vx⁺ = {_num(particle.after.vx, 'm/s')}; "
            f"its energy changes by {_num(particle.energy_change, 'J')} — it {verdict}. "
            "The rigid body never gains energy.</p>"
        )
    from .. import __version__

    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>spinimpact report: {html.escape(str(imp.regime))}</title>
<style>{_CSS}</style><script>{_SCRIPT}</script></head>
<body>
<h1>Impact of a {html.escape(b.name)} body on a rough surface</h1>
<p class="sub">Regime <span class="regime" id="regime">{html.escape(str(imp.regime))}</span>
&nbsp; |u⁻/v⁻| = {_num(imp.incidence_ratio)} (stick in compression if ≤ ζμ = {_num(low)};
stick before rebound if ≤ (1+κ)ζμ = {_num(high)})</p>
<div class="grid"><div><h2>Inputs</h2>{inputs}</div><div><h2>Rebound</h2>{rebound}</div>
<div><h2>Impulses</h2>{impulses}</div></div>
<div class="grid"><div><h2>Energy budget</h2>{energy}
<p>Minimum at τ_m = {_num(imp.tau_min_energy, "N s")}: {html.escape(str(imp.min_energy_case))}.</p></div>
<div><h2>Works by phase</h2>{works}</div></div>
<div class="grid"><div><h2>Coefficients</h2>{coefficients}</div><div><h2>Outcome</h2>{flags}</div></div>
{compare}
<h2>Figures</h2>{figures}
<footer>spinimpact {__version__} — exact rigid-body theory of Lubarda (2010), Keller's method.
SI units; ω counter-clockwise positive; u = vx + Rω.</footer>
</body></html>
"""
