"""The HTML page of a planar impact (spinimpact.viz.planar_html): its tables are the
terminal report's rows, it explains the body and the regime, and a real browser shows it
whole (every figure decoded, nothing wider than the window)."""

import io
import math
import re
from html.parser import HTMLParser

import numpy as np
import pytest
from rich.console import Console

from spinimpact import Body, Pendulum, PlanarBody, solve, solve_pendulum, solve_planar
from spinimpact.core.planar import PLANAR_REGIMES
from spinimpact.viz import planar_html
from spinimpact.viz.planar_html import planar_report_html, typeset_table
from spinimpact.viz.report import planar_tables, print_planar_report
from spinimpact.viz.tables import number

from tests.viz.browser import chromium, needs_browser

pytest.importorskip("matplotlib")

ROD = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(45))
PENDULUM = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
DISK = PlanarBody.eccentric_disk(
    mass=2.0, radius=0.1, gyration=0.06, offset=0.03, angle=math.radians(30)
)
BLOCK = PlanarBody.block(mass=2.0, width=0.3, height=0.1, angle=0.4)


class _Tables(HTMLParser):
    """The tables of a page that carry ``data-table``: key -> (headings, rows), as text."""

    def __init__(self):
        super().__init__()
        self.tables, self._key, self._cell, self._row = {}, None, None, None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "table" and "data-table" in attrs:
            self._key = attrs["data-table"]
            self.tables[self._key] = ([], [])
        elif self._key and tag == "tr":
            self._row = []
        elif self._key and tag in ("td", "th"):
            self._cell = []

    def handle_endtag(self, tag):
        if not self._key:
            return
        if tag in ("td", "th"):
            self._row.append("".join(self._cell))
            self._cell = None
        elif tag == "tr":
            heads, rows = self.tables[self._key]
            (rows if heads else heads).append(tuple(self._row))
        elif tag == "table":
            self._key = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def page_tables(text):
    parser = _Tables()
    parser.feed(text)
    return {k: (heads[0], tuple(rows)) for k, (heads, rows) in parser.tables.items()}


def terminal_rows(imp):
    """The rows the terminal report prints, read back from its text, table by table."""
    out = io.StringIO()
    print_planar_report(imp, Console(file=out, width=200, highlight=False, soft_wrap=True))
    tables, current = {}, None
    titles = {t.title: t.key for t in planar_tables(imp)}
    for line in out.getvalue().splitlines():
        if line.strip() in titles:
            current = tables.setdefault(titles[line.strip()], [])
        elif current is not None and "│" in line:
            current.append(tuple(cell.strip() for cell in line.split("│")))
    return {k: tuple(rows) for k, rows in tables.items()}


IMPACTS = {
    "rod, Poisson": lambda: solve_planar(ROD, 1.0, -1.0, 0.0, mu=0.3, kappa=0.8),
    "rod, Newton, creates energy": lambda: solve_planar(
        ROD, 0.5, -1.0, 0.0, mu=0.8, kappa=0.9, law="newton"
    ),
    "pendulum": lambda: solve_pendulum(PENDULUM, -2.0, mu=0.3, kappa=0.8, law="energetic"),
    "pendulum, locked": lambda: solve_pendulum(PENDULUM, -2.0, mu=1.0, kappa=0.8),
    "eccentric disk": lambda: solve_planar(DISK, 1.0, -1.0, -20.0, mu=0.4, kappa=0.7),
    "block": lambda: solve_planar(BLOCK, -0.5, -1.0, 0.0, mu=0.2, kappa=0.6, law="newton"),
}


@pytest.fixture(scope="module", params=list(IMPACTS))
def case(request):
    imp = IMPACTS[request.param]()
    return imp, planar_report_html(imp)


@pytest.mark.slow
def test_tables_are_the_terminal_reports_rows(case):
    imp, text = case
    shown, printed = page_tables(text), terminal_rows(imp)
    built = planar_tables(imp)
    assert list(shown) == [t.key for t in built]  # every table, in the report's order
    for table in built:
        heads, rows = shown[table.key]
        typeset = typeset_table(table)
        assert heads == typeset.columns
        assert rows == typeset.rows
        # the values are the terminal's strings, character for character
        assert [c for r in rows for c in r[1:]] == table.values()
        # and the terminal printed exactly these rows (labels in ASCII there)
        assert [r[1:] for r in printed[table.key]] == [r[1:] for r in rows]
        assert [r[0] for r in printed[table.key]] == [r[0] for r in table.rows]


def test_labels_are_typeset_and_values_untouched():
    table = typeset_table(planar_tables(IMPACTS["rod, Poisson"]())[2])  # impulses
    labels = [r[0] for r in table.rows]
    assert labels[0] == "end of compression τ₀" and labels[2] == "end of impact τ₁"
    assert "μ̂ = f₁/τ₁ (no unit)" in labels
    assert not any(re.search(r"tau|mu_hat", label) for label in labels)


@pytest.mark.slow  # renders a whole page or map (about a second)
def test_page_is_self_contained_and_names_the_regime(case):
    imp, text = case
    assert text.startswith("<!DOCTYPE html>")
    assert f'id="regime">{imp.regime}<' in text
    assert text.count('src="data:image/png;base64,') == 2  # Routh's diagram, three laws
    assert not re.search(r'(src|href)="(https?:)?//', text)  # nothing fetched from a network


def test_energy_creation_is_explained_only_where_it_happens(case):
    imp, text = case
    assert ('class="warn-box"' in text) == bool(imp.creates_energy)
    assert ('<span class="warn">yes</span>' in text) == bool(imp.creates_energy)


@pytest.mark.slow
def test_geometry_in_numbers():
    imp = IMPACTS["rod, Poisson"]()
    text = planar_report_html(imp, geometry={"length L": "1 m", "angle to the surface": 0.785398})
    w = ROD.collision_matrix
    for x in (w.tt, w.tn, w.nn):
        assert f"<span>{number(x)}</span>" in text  # the matrix W, entry by entry
    # r = (-L/2 cos 45°, -L/2 sin 45°): half a metre from G, 45° off the vertical, to the left
    assert f"({number(ROD.rx)}, {number(ROD.ry)}) m: 0.5 m from G, 45° from the vertical" in text
    assert "to the left (−x) of the centre of mass" in text
    assert "<td>length L</td><td>1 m</td>" in text
    assert "<td>angle to the surface</td><td>0.785398</td>" in text
    # |W_tn| = 1.5 > mu W_tt = 0.75: friction cannot hold it, the slip reverses
    assert "= 1.5 &gt; μ W<sub>tt</sub> = 0.75 1/kg, so it cannot" in text


@pytest.mark.slow
def test_pendulum_geometry_and_locked_regime():
    text = planar_report_html(IMPACTS["pendulum, locked"]())
    assert "fixed, frictionless pivot O" in text and "has rank one" in text
    assert f"({number(PENDULUM.px)}, {number(PENDULUM.py)}) m" in text
    assert f"{number(PENDULUM.inertia_pivot, 'kg m²')}" in text
    assert "stops against the surface and does not rebound" in text
    assert "no law gives a rebound" in text


@pytest.mark.slow
def test_the_laws_agree_or_not():
    differ = planar_report_html(IMPACTS["rod, Poisson"]())
    assert "so the three laws end it at different impulses" in differ
    # the paper's disk: W_tn = 0, the three laws coincide
    disk = PlanarBody.from_body(Body.solid_disk(mass=1.0, radius=0.1))
    same = planar_report_html(solve_planar(disk, 1.0, -1.0, 0.0, mu=0.2, kappa=0.7))
    assert "so the three laws coincide" in same
    assert "W<sub>tn</sub> = 0: the contact lies straight below G" in same


def test_every_regime_has_its_explanation():
    # one vectorized solve reaches every regime a free body can; the pendulum adds `locked`
    th = np.linspace(0.05, math.pi - 0.05, 31)[:, None, None]
    vx = np.linspace(-3, 3, 25)[None, :, None]
    mu = np.array([0.0, 0.1, 0.3, 0.8, 2.0])[None, None, :]
    grid = solve_planar(
        PlanarBody.rod(mass=1.0, length=1.0, angle=th), vx, -1.0, 0.0, mu=mu, kappa=0.8
    )
    found = {"locked": IMPACTS["pendulum, locked"]()}
    for regime in PLANAR_REGIMES:
        where = np.argwhere(np.asarray(grid.regime) == regime)
        if len(where):
            found[regime] = grid[tuple(where[0])]
    assert set(found) == set(PLANAR_REGIMES) - {"jam"}  # jam: no body reaches it
    for regime, imp in found.items():
        words = planar_html._regime_words(imp)
        assert imp.regime == regime
        if regime != "frictionless":
            assert number(imp.tau1, "N s") in words or number(imp.tau0, "N s") in words
        if regime in ("slip", "stick-compression", "stick-restitution"):
            assert number(imp.slip_before, "m/s") in words


def test_api_rejects_what_is_not_one_planar_impact():
    with pytest.raises(ValueError, match="one impact"):
        planar_report_html(solve_planar(ROD, [1.0, 2.0], -1.0, 0.0, mu=0.3, kappa=0.8))
    paper = solve(Body.solid_disk(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.3, kappa=0.8)
    with pytest.raises(TypeError, match="PlanarImpact"):
        planar_report_html(paper)  # the paper's bodies have impact_report_html


@pytest.fixture(scope="module")
def page_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("planar") / "planar.html"
    imp = IMPACTS["rod, Newton, creates energy"]()
    path.write_text(planar_report_html(imp, geometry={"length L": "1 m"}), encoding="utf-8")
    return path, imp


@pytest.mark.browser
@needs_browser
@pytest.mark.parametrize("width", [1200, 800])
def test_browser_shows_everything_within_the_window(page_file, tmp_path, width):
    path, imp = page_file
    out = chromium(
        tmp_path,
        f"--window-size={width},2000",
        "--virtual-time-budget=5000",
        "--dump-dom",
        path.as_uri(),
    )
    assert out.returncode == 0, out.stderr[-2000:]
    dom = out.stdout
    # the page's own load handler counted the figures decoded and the elements wider
    # than the window
    assert 'data-figures-shown="2/2"' in dom
    assert 'data-overflowing="none"' in dom
    assert f'id="regime">{imp.regime}<' in dom


@pytest.mark.browser
@needs_browser
def test_browser_screenshot(page_file, tmp_path):
    from matplotlib.image import imread

    path, _ = page_file
    shot = tmp_path / "shot.png"
    out = chromium(tmp_path, "--window-size=1200,3600", f"--screenshot={shot}", path.as_uri())
    assert out.returncode == 0, out.stderr[-2000:]
    pixels = imread(shot)
    assert pixels.shape[:2] == (3600, 1200)
    gray = pixels[..., :3].mean(axis=2)
    # a rendered page: mostly white background with dark text and coloured figures
    assert gray.mean() > 0.8
    assert (gray < 0.3).mean() > 0.005
    assert np.unique((pixels[..., :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0).shape[0] > 50
    # the warning box is drawn in its colour (a pale red band near the top)
    top = pixels[:700, :, :3]
    pale_red = (top[..., 0] > 0.95) & (top[..., 1] < 0.95) & (top[..., 2] < 0.95)
    assert pale_red.mean() > 0.01
