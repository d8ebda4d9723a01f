"""A self-contained HTML page of a sphere's 3D impact or of two spheres colliding (the
figure embedded, no network).

The tables are :func:`~spinimpact.viz.sphere.sphere_tables`, the builder the terminal
report (``spinimpact sphere``, ``spinimpact pair``) prints: the same rows and numbers,
with typeset labels (``ω``, ``τ₁``, ``μ̂``). The figure is
:func:`~spinimpact.viz.sphere.plot_sphere`. The stylesheet, the figure encoder, the table
markup and the script that checks the page in a browser are those of the other pages
(:mod:`spinimpact.viz.html`, :mod:`spinimpact.viz.planar_html`).
"""

from __future__ import annotations

import html

from ..model.pair import PairImpact
from ..model.sphere3d import SphereImpact
from .html import _CSS, _png
from .planar_html import _SCRIPT, _table
from .sphere import _single, headline, plot_sphere, sphere_tables

__all__ = ["sphere_report_html"]

#: Tables shown side by side, row by row.
_GRID = (
    ("outcome", "spin", "contact"),
    ("inputs", "motion"),
    ("impulses", "energy"),
    ("works", "coefficients"),
)
_E = html.escape

_AXES = (
    "Axes: x along the surface, y along its outward normal (up), z = x × y (out of the "
    "page in the side view). Vectors are in the ground frame, SI units; spin vectors are "
    "right-handed."
)
_SPIN = (
    "Spin after the impact, with e the direction of travel along the surface (relative to "
    "it) and n its normal: topspin about n × e (the way a ball rolling forward turns; "
    "negative: backspin), side spin about n (counter-clockwise seen from above, from the "
    "side n points to), gyrospin about e. The ball grips when its contact point leaves "
    "without slip, and skids when it still slides."
)
_PAIR = (
    "The normal n points from ball 2's centre to ball 1's; the contact velocity is ball "
    "1's contact point relative to ball 2's. The contact grips when it leaves without "
    "slip and skids when it still slides; the angle between the paths is that of the two "
    "centres' velocities after the impact."
)
_CAPTION = (
    "Side view (x, y) and top view (x, z, seen from above) at one scale: each ball touches "
    "the contact point (black dot). Straight arrows are projections of the velocity "
    "before (arriving) and after (leaving), and of the spin vector before and after "
    "(dashed); a curved arrow turns the way the spin about the axis toward the reader "
    "does. Velocities and spins have their own scales; the legend gives the magnitudes."
)


def sphere_report_html(imp: SphereImpact | PairImpact) -> str:
    """The report of one 3D impact as one self-contained HTML page.

    Parameters
    ----------
    imp : SphereImpact or PairImpact
        One impact (shape ``()``), from :func:`~spinimpact.solve_sphere` or
        :func:`~spinimpact.solve_pair`.

    Returns
    -------
    str
        The page, UTF-8 text starting with ``<!DOCTYPE html>``: the regime, a sentence on
        how the ball leaves (rebound speed, its angle in degrees, topspin or backspin in
        rpm, grips or skids; for a pair the angle between the paths), the conventions,
        the tables of :func:`~spinimpact.viz.sphere.sphere_tables` (typeset) and the
        figure of :func:`~spinimpact.viz.sphere.plot_sphere`, embedded as PNG data.

    Raises
    ------
    TypeError
        For anything but a :class:`~spinimpact.SphereImpact` or
        :class:`~spinimpact.PairImpact`.
    ValueError
        For more than one impact.
    """
    from .. import __version__

    _single(imp)
    tables = {t.key: t for t in sphere_tables(imp, typeset=True)}
    grids = "\n".join(
        '<div class="grid">'
        + "".join(_table(tables.pop(k)) for k in keys if k in tables)
        + "</div>"
        for keys in _GRID
    )
    rest = "".join(_table(t) for t in tables.values())
    if isinstance(imp, PairImpact):
        title = f"Two spheres colliding: {imp.ball1.name} on {imp.ball2.name}"
        words = _PAIR
    else:
        title = f"A sphere on a surface, in 3D: {imp.body.name}"
        words = _SPIN
    regime = _E(str(imp.regime))
    figure = (
        f'<figure><img alt="side and top views with the velocity and spin arrows" '
        f'src="data:image/png;base64,{_png(plot_sphere(imp))}">'
        f"<figcaption>{_E(_CAPTION)}</figcaption></figure>"
    )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>spinimpact: {_E(title)}, {regime}</title>
<style>{_CSS}</style><script>{_SCRIPT}</script></head>
<body>
<h1>{_E(title)}</h1>
<p class="sub">Regime <span class="regime" id="regime">{regime}</span></p>
<p id="headline">{_E(headline(imp))}.</p>
<p class="sub" id="conventions">{_E(_AXES)} {_E(words)}</p>
{grids}
{rest}
<h2>Figure</h2>{figure}
<footer>spinimpact {__version__}: exact rigid-body impact in the normal impulse τ (Keller
1986; Lubarda 2010); the sphere's collision matrix is isotropic in the tangent plane, so the
slip keeps its direction and the spin about the normal is unchanged.</footer>
</body></html>
"""
