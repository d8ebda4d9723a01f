"""A self-contained HTML report of one impact (figures embedded, no network).

The tables come from :mod:`spinimpact.viz.tables`, the same builder the terminal
report uses, in its typeset notation (``ω``, ``τ₁``, ``μ̂``), so the page and the
terminal show the same rows and numbers.
"""

from __future__ import annotations

import base64
import html
import io
import re
from typing import Any

from ..model.impact import Impact
from ..model.particle import ParticleImpact
from ._labels import report_title
from .tables import Table, impact_tables, number, regime_summary

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
    """:func:`~spinimpact.viz.tables.number`, escaped for HTML."""
    return html.escape(number(x, unit))


def _cell(table: Table, text: str) -> str:
    """One cell, escaped; outcome flags and an energy-creating model are styled."""
    safe = html.escape(text)
    if table.key == "outcome" and text in ("yes", "no"):
        return f'<span class="flag-{text}">{safe}</span>'
    if text == "creates energy":
        return f'<span class="warn">{safe}</span>'
    return safe


_SUB = re.compile(r"(?<=[A-Za-zτ])_([A-Za-z0-9])")
_SUP = re.compile(r"(?<=[A-Za-zτ>])\^([A-Za-z0-9])")


def _math(text: str) -> str:
    """A typeset label, escaped, with its scripts set: ``W_r^n`` as W<sub>r</sub><sup>n</sup>,
    ``E_m`` as E<sub>m</sub>. Only for the package's labels, never for user text."""
    return _SUP.sub(r"<sup>\1</sup>", _SUB.sub(r"<sub>\1</sub>", html.escape(text)))


def _table(table: Table) -> str:
    """A builder table as an HTML table (headings and cells escaped, labels typeset)."""
    head = "".join(f"<th>{_math(c)}</th>" for c in table.columns)
    body = "".join(
        f"<tr><td>{_math(row[0])}</td>"
        + "".join(f"<td>{_cell(table, c)}</td>" for c in row[1:])
        + "</tr>"
        for row in table.rows
    )
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _section(table: Table) -> str:
    """Title, table and note of one builder table."""
    note = f"<p>{_math(table.note)}</p>" if table.note else ""
    return f"<h2>{html.escape(table.title)}</h2>{_table(table)}{note}"


#: Tables shown side by side, row by row; any other table follows at full width.
_GRID = (("inputs", "rebound", "impulses"), ("energy", "works"), ("coefficients", "outcome"))


def _png(fig: Any) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def impact_report_html(imp: Impact, particle: ParticleImpact | None = None) -> str:
    """The complete report of a single impact as one HTML page.

    The regime and its thresholds, the tables of
    :func:`~spinimpact.viz.tables.impact_tables` in typeset notation (inputs,
    rebound, impulses, energy budget, works by phase, the three restitution
    coefficients, ``mu_hat``, the outcome flags and, with ``particle``,
    Whittaker's particle beside the rigid body) and the figures (history,
    Routh's diagram, energy), embedded as PNG data so the page needs no network
    or other files.

    Parameters
    ----------
    imp : Impact
        A single impact (shape ``()``), from :func:`spinimpact.solve`.
    particle : ParticleImpact, optional
        Whittaker's particle with the same incidence, from
        :func:`spinimpact.solve_particle`.

    Returns
    -------
    str
        The page, UTF-8 text starting with ``<!DOCTYPE html>``.

    Raises
    ------
    ValueError
        If ``imp`` holds more than one impact.

    Notes
    -----
    Units are SI: velocities in m/s, spin in rad/s (counter-clockwise
    positive), impulses in N s, energies and works in J. The figures follow
    Figs. 2-5 of the paper.

    References
    ----------
    V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
    surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy
    of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    """
    tables = {t.key: t for t in impact_tables(imp, particle, typeset=True)}
    from .plots import plot_energy, plot_history, plot_routh

    grids = "\n".join(
        '<div class="grid">'
        + "".join(f"<div>{_section(tables.pop(key))}</div>" for key in keys)
        + "</div>"
        for keys in _GRID
    )
    rest = "\n".join(_section(t) for t in tables.values())
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
    from .. import __version__

    regime = html.escape(str(imp.regime))
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>spinimpact report: {regime}</title>
<style>{_CSS}</style><script>{_SCRIPT}</script></head>
<body>
<h1>{html.escape(report_title(imp, typeset=True))}</h1>
<p class="sub">Regime <span class="regime" id="regime">{regime}</span>
&nbsp; {_math(regime_summary(imp, typeset=True))}</p>
{grids}
{rest}
<h2>Figures</h2>{figures}
<footer>spinimpact {__version__} — exact rigid-body theory of Lubarda (2010), Keller's method.
SI units; ω counter-clockwise positive; u = vx + Rω.</footer>
</body></html>
"""
