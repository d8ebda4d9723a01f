"""A self-contained HTML page of one planar impact (figures embedded, no network).

The tables are :func:`~spinimpact.viz.report.planar_tables`, the builder the terminal
report (``spinimpact planar``) prints: the same rows and the same numbers, with the
labels in typeset notation (``ω``, ``τ₁``, ``μ̂``) as on the paper's page
(:mod:`spinimpact.viz.html`). Beside them: the body's geometry in words and numbers,
what the regime means for this impact, whether the three restitution laws agree here,
Routh's diagram (:func:`~spinimpact.viz.planar.plot_routh_planar`) and the three laws
side by side (:func:`~spinimpact.viz.planar.plot_laws`).
"""

from __future__ import annotations

import html
import math
import re
from collections.abc import Mapping
from typing import Any

from ..model.planar import PlanarImpact
from ..model.planar_body import Pendulum
from ._labels import notation
from .html import _CSS, _png
from .tables import Table, number

__all__ = ["planar_report_html"]

#: Labels of the planar tables whose typeset form the paper's tables do not share.
_TYPESET = {
    "tangential impulse, f1": "tangential impulse f₁",
    "mu_hat = f1/tau1 (no unit)": "μ̂ = f₁/τ₁ (no unit)",
    "creates energy (E+ > E-)": "creates energy (E⁺ > E⁻)",
}
#: Tables shown side by side, row by row.
_GRID = (("inputs", "rebound"), ("impulses", "energy"), ("works", "coefficients"))

_PLANAR_CSS = """
.law { color: #555; } .warn-box { border-left: 4px solid #a33; padding: .2rem .8rem;
       background: #fbeeee; }
.explain { max-width: 52rem; } .geometry td:first-child { color: #444; }
.matrix { display: inline-grid; grid-template-columns: auto auto; gap: .1rem 1rem;
          vertical-align: middle; padding: .1rem .5rem; border-left: 1.5px solid #444;
          border-right: 1.5px solid #444; border-radius: .35rem; text-align: right; }
.wline { display: flex; align-items: center; gap: .5rem; margin: .6rem 0; }
"""

# Counts the figures the browser decoded and the elements wider than the page, for a
# reader (or a test) to check: the page should show every figure and need no scrolling.
_SCRIPT = """
window.addEventListener('load', function () {
  var imgs = document.querySelectorAll('img'), ok = 0, wide = [];
  imgs.forEach(function (i) { if (i.complete && i.naturalWidth > 0) { ok += 1; } });
  var right = document.documentElement.clientWidth;
  document.querySelectorAll('body *').forEach(function (e) {
    var box = e.getBoundingClientRect();
    if (box.right > right + 0.5 || e.scrollWidth > e.clientWidth + 1 && e.clientWidth > 0) {
      wide.push(e.tagName.toLowerCase() + (e.id ? '#' + e.id : ''));
    }
  });
  document.body.setAttribute('data-figures-shown', ok + '/' + imgs.length);
  document.body.setAttribute('data-overflowing', wide.length ? wide.join(' ') : 'none');
});
"""

_E = html.escape
_f = number  # six significant digits, as in the tables
_SUB = re.compile(r"(?<![A-Za-z0-9_])([A-Za-zτ])_([A-Za-z]{1,2})(?![A-Za-z0-9_])")


def _label(text: str) -> str:
    return _TYPESET.get(text, notation(True)(text))


def _cell(row: tuple[str, ...], text: str) -> str:
    safe = _E(text)
    if row[0].startswith("creates energy") and text == "yes":
        return f'<span class="warn">{safe}</span>'
    return safe


def typeset_table(table: Table) -> Table:
    """A builder table with its headings and row labels in typeset notation; the values
    (every cell but the row labels) are the terminal's, unchanged."""
    rows = tuple((_label(r[0]), *r[1:]) for r in table.rows)
    note = table.note.replace("tau_m", "τ_m")
    return Table(table.key, table.title, tuple(map(_label, table.columns)), rows, note)


def _table(table: Table) -> str:
    head = "".join(f"<th>{_E(c)}</th>" for c in table.columns)
    body = "".join(
        "<tr>" + "".join(f"<td>{_cell(row, c)}</td>" for c in row) + "</tr>" for row in table.rows
    )
    note = f"<p>{_E(table.note)}</p>" if table.note else ""
    return (
        f"<div><h2>{_E(table.title)}</h2>"
        f'<table data-table="{_E(table.key)}"><thead><tr>{head}</tr></thead>'
        f"<tbody>{body}</tbody></table>{note}</div>"
    )


def _matrix(w: Any) -> str:
    """``W`` as a bracketed 2x2 matrix, 1/kg."""
    cells = "".join(f"<span>{_E(_f(x))}</span>" for x in (w.tt, w.tn, w.tn, w.nn))
    return (
        '<div class="wline" id="collision-matrix">collision matrix W = '
        f'<span class="matrix">{cells}</span> 1/kg</div>'
    )


def _prose(text: str) -> str:
    """Escaped text with its subscripts set: ``W_tn`` as W<sub>tn</sub>."""
    return _SUB.sub(r"\1<sub>\2</sub>", _E(text))


def _where(x: float) -> str:
    if x == 0:
        return "straight below"
    return "to the right (+x) of" if x > 0 else "to the left (−x) of"


def _geometry(imp: PlanarImpact, given: Mapping[str, Any] | None) -> str:
    """The body in words and numbers: what it is, where it touches, and its ``W``."""
    b, w, mu = imp.body, imp.body.collision_matrix, float(imp.mu)
    m, j = float(b.mass), float(b.inertia)
    rows = [(k, v if isinstance(v, str) else _f(v)) for k, v in (given or {}).items()]
    if isinstance(b, Pendulum):
        gx, gy, px, py, jo = (float(x) for x in (b.gx, b.gy, b.px, b.py, b.inertia_pivot))
        q, below = math.hypot(px, py), math.degrees(math.atan2(-py, abs(px)))
        words = (
            f"A pendulum ({b.name}) of mass m = {_f(m, 'kg')} swinging on a fixed, "
            f"frictionless pivot O. Its centre of mass G lies at g = ({_f(gx)}, {_f(gy)}) m "
            f"from the pivot; it strikes the surface at P, q = P − O = ({_f(px)}, {_f(py)}) m: "
            f"{_f(q, 'm')} from the pivot, {below:.4g}° below the horizontal, {_where(px)} "
            f"the pivot. Moment of inertia J_G = {_f(j, 'kg m²')} about G and J_O = J_G + m|g|² "
            f"= {_f(jo, 'kg m²')} about the pivot. The pivot leaves one motion, the rotation ω: "
            f"W = [[q_y², −q_x q_y], [−q_x q_y, q_x²]]/J_O has rank one, so the slip and the "
            f"normal velocity of the contact stay proportional and vanish together."
        )
        rows += [
            ("centre of mass from the pivot, g", f"({_f(gx)}, {_f(gy)}) m"),
            ("contact from the pivot, q", f"({_f(px)}, {_f(py)}) m"),
            ("inertia about the pivot, J_O", _f(jo, "kg m²")),
        ]
    else:
        rx, ry = float(b.rx), float(b.ry)
        r, tilt = math.hypot(rx, ry), math.degrees(math.atan2(abs(rx), -ry))
        coupled = (
            "W_tn = −r_x r_y/J ≠ 0 couples the impulses: friction changes the contact's "
            "normal velocity and the normal impulse changes its slip"
            if float(w.tn) != 0
            else "W_tn = 0: the contact lies straight below G and the impulses do not couple "
            "(the paper's case)"
        )
        words = (
            f"A free rigid body ({b.name}) of mass m = {_f(m, 'kg')} and moment of inertia "
            f"J = {_f(j, 'kg m²')} about its centre of mass G (radius of gyration "
            f"ρ = √(J/m) = {_f(math.sqrt(j / m), 'm')}). It touches the surface at P, "
            f"r = P − G = ({_f(rx)}, {_f(ry)}) m: {_f(r, 'm')} from G, {tilt:.4g}° from the "
            f"vertical through G, {_where(rx)} the centre of mass. {coupled}."
        )
        rows += [
            ("contact from the centre of mass, r", f"({_f(rx)}, {_f(ry)}) m"),
            ("distance |r|, angle from the vertical", f"{_f(r, 'm')}, {tilt:.4g}°"),
            ("radius of gyration ρ", _f(math.sqrt(j / m), "m")),
        ]
    a, c = abs(float(w.tn)), float(w.tt)
    holds = a <= mu * c
    hold = (
        "Without friction (μ = 0) nothing holds the contact: it slips freely."
        if mu == 0
        else (
            f"Once the slip stops, friction can hold the contact if |W_tn| ≤ μ W_tt: here "
            f"|W_tn| = {_f(a)} {'≤' if holds else '>'} μ W_tt = {_f(mu * c)} 1/kg, so "
            + ("it would stick." if holds else "it cannot: the slip would reverse.")
        )
    )
    table = "".join(f"<tr><td>{_prose(k)}</td><td>{_E(v)}</td></tr>" for k, v in rows)
    return (
        f'<h2>The body</h2><p class="explain" id="geometry">{_prose(words)}</p>'
        f'<div class="grid"><table class="geometry"><tbody>{table}</tbody></table>'
        f'{_matrix(w)}</div><p class="explain" id="hold">{_prose(hold)}</p>'
    )


def _regime_words(imp: PlanarImpact) -> str:
    """What the regime means, with this impact's impulses."""
    t0, ts, t1 = (_f(x, "N s") for x in (imp.tau0, imp.tau_star, imp.tau1))
    u0, w = _f(imp.slip_before, "m/s"), imp.body.collision_matrix
    during = (
        "exactly where compression ends (τ₀ = τ*: the slip and the normal velocity vanish together)"
        if float(imp.tau0) == float(imp.tau_star)
        else f"during compression (which ends at τ₀ = {t0})"
    )
    cone = "friction holds it (|W_tn| ≤ μ W_tt)"
    turn = (
        "friction cannot hold it (|W_tn| > μ W_tt): the slip reverses and the contact "
        "slips the other way"
    )
    return {
        "frictionless": "μ = 0: no friction. Only the normal impulse acts, from compression "
        f"(to τ₀ = {t0}) to the end at τ₁ = {t1}; through W_tn it still changes the slip, "
        f"from u⁻ = {u0} to u⁺ = {_f(imp.slip_after, 'm/s')}.",
        "no-slip": f"The contact does not slip at incidence (u⁻ = 0), and {cone}: it sticks "
        f"throughout, with F/N = −W_tn/W_tt = {_f(-float(w.tn) / float(w.tt))}, until the end "
        f"at τ₁ = {t1}.",
        "stick-compression": f"The slip u⁻ = {u0} stops at τ* = {ts}, {during}; from then "
        f"on {cone}, and the contact sticks until the end at τ₁ = {t1}.",
        "stick-restitution": f"Compression ends at τ₀ = {t0} with the contact still slipping; "
        f"the slip u⁻ = {u0} stops at τ* = {ts}, during restitution, and then {cone}: the "
        f"contact sticks until the end at τ₁ = {t1}.",
        "slip": f"The contact slips one way throughout, F = −μ N sign(u⁻): the slip "
        f"u⁻ = {u0} would stop only at τ* = {ts}, after the impact ends at τ₁ = {t1}.",
        "reverse-compression": f"The slip u⁻ = {u0} stops at τ* = {ts}, {during}, and "
        f"{turn} until the end at τ₁ = {t1}.",
        "reverse-restitution": f"Compression ends at τ₀ = {t0}; the slip u⁻ = {u0} stops at "
        f"τ* = {ts}, during restitution, and {turn} until the end at τ₁ = {t1}.",
        "slip-from-rest": "The contact does not slip at incidence (u⁻ = 0), but friction "
        "cannot hold it (|W_tn| > μ W_tt): it slips from the start, in the direction of "
        f"W_tn, until the end at τ₁ = {t1}.",
        "locked": f"A pendulum whose slip and normal velocity vanish together at τ₀ = τ* = "
        f"{t0}, where {cone}: it stops against the surface and does not rebound.",
        "jam": "The slip never stops and the normal velocity never rises: no finite impulse "
        "ends this impact, and its results are undefined.",
    }[str(imp.regime)]


def _laws_words(imp: PlanarImpact, imps: dict[str, PlanarImpact]) -> str:
    """Whether Newton's, Poisson's and Stronge's laws end this impact at the same place."""
    from .planar import LAW_NAMES

    ends = {law: float(i.tau1) for law, i in imps.items()}
    listed = ", ".join(f"{LAW_NAMES[law]} {_f(t)}" for law, t in ends.items())
    if imp.regime == "locked":
        why = (
            "the pendulum stops against the surface at τ₀: v stays 0 after it, so no law "
            "gives a rebound (Poisson's law adds normal impulse up to (1 + κ) τ₀ without one)"
        )
    elif max(ends.values()) - min(ends.values()) <= 1e-9 * max(ends.values()):
        why = (
            "the contact's normal velocity v rises at one rate through the whole impact, "
            "so the three laws coincide"
        )
    else:
        why = (
            f"the rate at which v rises changes at τ* = {_f(imp.tau_star, 'N s')}, inside "
            "the impact, so the three laws end it at different impulses and rebounds"
        )
    return f"Each law ends the impact at τ₁ (N s): {listed}. Here {why}."


def _figures(imp: PlanarImpact) -> str:
    from .planar import _solve_all, plot_laws, plot_routh_planar

    b, before = imp.body, imp.before
    free = not isinstance(b, Pendulum)
    incidence = {
        "vx": float(before.vx) if free else None,
        "vy": float(before.vy) if free else None,
        "omega": float(before.omega),
        "mu": float(imp.mu),
        "kappa": float(imp.kappa),
    }
    if not math.isfinite(float(imp.tau1)):
        return "<p>No finite impulse ends this impact: there is nothing to draw.</p>"
    laws = _laws_words(imp, _solve_all(b, **incidence))
    figures = (
        (
            plot_routh_planar(imp),
            "Routh diagram",
            "Routh's diagram: the impulse path (τ, f) in the friction cone, with the "
            "compression line (v = 0) and the sticking line (u = 0).",
        ),
        (
            plot_laws(b, **incidence),
            "three restitution laws",
            "Newton's, Poisson's and Stronge's laws on this incidence: the contact's normal "
            "velocity and the kinetic energy over τ, each law's end marked, and each law's "
            "rebound below.",
        ),
    )
    return f'<p class="explain" id="laws">{_prose(laws)}</p>' + "".join(
        f'<figure><img alt="{_E(alt)}" src="data:image/png;base64,{_png(fig)}">'
        f"<figcaption>{_E(caption)}</figcaption></figure>"
        for fig, alt, caption in figures
    )


def planar_report_html(imp: PlanarImpact, *, geometry: Mapping[str, Any] | None = None) -> str:
    """The report of one planar impact as one self-contained HTML page.

    The regime and the law, what the regime means for this impact, the body's geometry
    in words and numbers (with its collision matrix ``W`` and whether friction can hold
    the contact once the slip stops), the tables of
    :func:`~spinimpact.viz.report.planar_tables` (the terminal report's rows, labels
    typeset), whether the three restitution laws agree here, Routh's diagram and the
    three laws side by side, embedded as PNG data: the page needs no network or other
    files.

    Parameters
    ----------
    imp : PlanarImpact
        One impact (shape ``()``), from :func:`~spinimpact.solve_planar` or
        :func:`~spinimpact.solve_pendulum`.
    geometry : mapping, optional
        The preset's parameters as the caller gave them, shown first under "The body":
        label to a number (SI) or a string with its unit, e.g.
        ``{"length L (m)": 1.0, "angle to the surface": "45° (0.785398 rad)"}``. The
        body itself holds only ``m``, ``J`` and the contact's position.

    Returns
    -------
    str
        The page, UTF-8 text starting with ``<!DOCTYPE html>``.

    Raises
    ------
    TypeError
        If ``imp`` is not a :class:`~spinimpact.PlanarImpact`.
    ValueError
        If ``imp`` holds more than one impact.

    Notes
    -----
    Units are SI: velocities in m/s, spin in rad/s (counter-clockwise positive),
    impulses in N s, energies and works in J, ``W`` in 1/kg. The theory is in
    ``docs/planar.md`` (Keller 1986; Stronge 2000).
    """
    from .. import __version__
    from .planar import LAW_NAMES
    from .report import planar_tables

    if not isinstance(imp, PlanarImpact):
        raise TypeError(f"expected a spinimpact.PlanarImpact, got {type(imp).__name__}")
    tables = {t.key: typeset_table(t) for t in planar_tables(imp)}
    grids = "\n".join(
        '<div class="grid">' + "".join(_table(tables.pop(k)) for k in keys) + "</div>"
        for keys in _GRID
    )
    rest = "".join(_table(t) for t in tables.values())
    regime, law = _E(str(imp.regime)), _E(LAW_NAMES[imp.law])
    gain = ""
    if bool(imp.creates_energy):
        e1, e0 = _f(imp.kinetic_energy_after, "J"), _f(imp.kinetic_energy_before, "J")
        gain = (
            '<p class="warn-box"><span class="warn">creates energy</span>: '
            + _prose(
                f"this law gives the body more kinetic energy than it had (E⁺ = {e1} > "
                f"E⁻ = {e0}): Kane's paradox. Keller (1986) traced it to the change of the "
                "slip inside the impact. The three laws are compared under Figures."
            )
            + "</p>"
        )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>spinimpact planar report: {_E(str(imp.body.name))}, {regime}</title>
<style>{_CSS}{_PLANAR_CSS}</style><script>{_SCRIPT}</script></head>
<body>
<h1>Planar impact: {_E(str(imp.body.name))} on a rough surface</h1>
<p class="sub">Regime <span class="regime" id="regime">{regime}</span>
&nbsp; <span class="law" id="law">law: {law}</span></p>
<p class="explain" id="regime-words">{_prose(_regime_words(imp))}</p>
{gain}
{_geometry(imp, geometry)}
{grids}
{rest}
<h2>Figures</h2>{_figures(imp)}
<footer>spinimpact {__version__}: exact rigid-body impact in the normal impulse τ
(Keller 1986; Stronge 2000). SI units; ω counter-clockwise positive; contact velocity
{_prose("c = (u, v) = v_G + ω e_z × r, dc = W dp")}.</footer>
</body></html>
"""
