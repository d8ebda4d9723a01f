"""The figure, the report tables and the HTML page of a sphere's 3D impact and of two spheres
(spinimpact.viz.sphere, spinimpact.viz.sphere_html): every arrow drawn where its vector
points, nothing overlapping, the tables' numbers the result's, and the page shown whole by
a real browser."""

import math

import numpy as np
import pytest

from spinimpact import Body, Surface, solve, solve_pair, solve_sphere
from spinimpact.viz.sphere import RPM, headline, plot_sphere, sphere_tables
from spinimpact.viz.sphere_html import sphere_report_html
from spinimpact.viz.tables import number

from tests.viz.browser import chromium, needs_browser

pytest.importorskip("matplotlib")

SHELL = Body.spherical_shell(mass=0.057, radius=0.033)
BALL = Body.solid_sphere(mass=0.17, radius=0.028575)
TENNIS = solve_sphere(SHELL, [20, -8, 3], [0, 150, -200], mu=0.6, kappa=0.75)
RACKET = solve_sphere(SHELL, [5, -3, 1], [10, 20, 30], mu=0.3, kappa=0.7,
                      surface=Surface(normal=[-0.3, 1, 0.2], velocity=[-4, 0, 0]))  # fmt: skip
CUT = solve_pair(BALL, BALL, velocity1=[2, 0, 0], spin1=[0, 30, -70], velocity2=[0, 0, 0],
                 spin2=[0, 0, 0], normal=[-1, 0, 1], mu=0.06, kappa=0.93)  # fmt: skip


@pytest.fixture(scope="module")
def figures():
    """One figure per case, drawn once for the whole module (Matplotlib is slow to lay out)."""
    return {"tennis": plot_sphere(TENNIS), "racket": plot_sphere(RACKET), "pair": plot_sphere(CUT)}


def arrows(fig):
    """gid -> (tail, head) of every arrow, in data coordinates, per axes."""
    out = {}
    for ax in fig.axes:
        for patch in ax.patches:
            gid = patch.get_gid()
            if gid:
                vertices = patch._path_original.vertices  # the path it was given (data units)
                out[gid] = (vertices[0], vertices[-1])
    return out


def direction(a):
    a = np.asarray(a, float)
    return a / np.linalg.norm(a)


@pytest.mark.parametrize("name", ["tennis", "racket"])
@pytest.mark.slow
def test_sphere_arrows_point_along_the_projected_vectors(figures, name):
    imp, fig = {"tennis": TENNIS, "racket": RACKET}[name], figures[name]
    found = arrows(fig)
    for view, k in (("side", 1), ("top", 2)):
        for quantity in ("velocity", "spin"):
            for when in ("before", "after"):
                tail, head = found[f"{view}-ball-{quantity}-{when}"]
                vector = getattr(getattr(imp, when), quantity)[[0, k]]
                np.testing.assert_allclose(direction(head - tail), direction(vector), atol=1e-12)
        # the incoming velocity arrives at the centre, the rebound leaves it
        centre = float(imp.body.radius) * imp.normal.array[[0, k]]
        np.testing.assert_allclose(found[f"{view}-ball-velocity-before"][1], centre, atol=1e-15)
        np.testing.assert_allclose(found[f"{view}-ball-velocity-after"][0], centre, atol=1e-15)
    # the spin about the axis toward the reader curves: -z (topspin) in the side view,
    # +y (counter-clockwise seen from above) in the top view
    assert {"side-ball-spin-before-turn", "top-ball-spin-after-turn"} <= found.keys()
    assert ("side-surface-velocity" in found) == bool(np.any(imp.surface_velocity.array))
    side, top = fig.axes
    assert top.yaxis_inverted() and not side.yaxis_inverted()  # seen from above: z runs down
    # the same scale in both views
    assert np.diff(side.get_xlim()) == pytest.approx(np.diff(top.get_xlim()))
    assert abs(np.diff(side.get_ylim())) == pytest.approx(abs(np.diff(top.get_ylim())))


def test_pair_arrows_for_both_balls(figures):
    found = arrows(figures["pair"])
    for ball, state in (("ball1", CUT.after1), ("ball2", CUT.after2)):
        tail, head = found[f"top-{ball}-velocity-after"]
        np.testing.assert_allclose(direction(head - tail), direction(state.velocity[[0, 2]]),
                                   atol=1e-12)  # fmt: skip
    assert "top-ball2-velocity-before" not in found  # at rest: nothing to draw
    assert not any("surface" in gid for gid in found)


def test_curved_arrow_turns_the_way_the_spin_does():
    # backspin for travel along +x is counter-clockwise in the side view (omega_z > 0)
    imp = solve_sphere(SHELL, [3, -4, 0], [0, 0, 50], mu=0.1, kappa=0.8)
    fig = plot_sphere(imp)
    tail, head = arrows(fig)["side-ball-spin-before-turn"]
    centre = float(SHELL.radius) * np.array([0.0, 1.0])
    a, b = tail - centre, head - centre
    assert a[0] * b[1] - a[1] * b[0] < 0 or np.dot(a, b) < 0  # a long arc counter-clockwise
    patches = fig.axes[0].patches
    arc = next(p for p in patches if p.get_gid() == "side-ball-spin-before-turn")._path_original
    angles = np.unwrap(np.arctan2(*(arc.vertices - centre).T[::-1]))
    assert np.all(np.diff(angles) > 0)  # counter-clockwise throughout


@pytest.mark.parametrize("name", ["tennis", "racket", "pair"])
@pytest.mark.slow
def test_nothing_overlaps_and_labels_are_typeset(figures, name, tmp_path):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.image import imread

    fig, target = figures[name], tmp_path / "views.png"
    FigureCanvasAgg(fig)
    fig.set_dpi(60)
    fig.savefig(target, dpi=60)  # drawn as the file is: the boxes below are of this draw
    pixels = imread(target)
    assert pixels.shape[1] == round(10.5 * 60)
    assert np.unique((pixels[..., :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0).shape[0] > 30
    renderer = fig.canvas.get_renderer()
    axes = [ax.get_tightbbox(renderer) for ax in fig.axes]
    legend, title = fig.legends[0], fig._suptitle
    boxes = [legend.get_window_extent(renderer), title.get_window_extent(renderer), *axes]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1 :]:
            assert not a.overlaps(b), (a, b)
    width, height = fig.bbox.width, fig.bbox.height
    for box in boxes:  # everything inside the figure
        assert box.x0 >= -1 and box.y0 >= -1 and box.x1 <= width + 1 and box.y1 <= height + 1
    texts = [t.get_text() for t in legend.get_texts()]
    assert any(r"$\omega^+$" in t for t in texts) and any("$v^-$" in t for t in texts)
    assert r"$\mu = " in title.get_text() and r"$\kappa = " in title.get_text()


def test_a_dollar_in_a_name_is_shown_as_typed():
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    odd = Body(mass=1.0, radius=0.1, gyration=0.07, name="$5 ball")
    fig = plot_sphere(solve_sphere(odd, [1, -1, 0], [0, 0, 0], mu=0.2, kappa=0.5))
    fig.set_size_inches(4, 3)
    FigureCanvasAgg(fig).draw()  # an unescaped $ would start mathtext and fail to draw
    assert fig._suptitle.get_text().startswith(r"\$5 ball")


def test_tables_hold_the_results_numbers():
    tables = {t.key: t for t in sphere_tables(TENNIS)}
    outcome = dict(tables["outcome"].rows)
    assert outcome["rebound speed |v+|"] == number(TENNIS.rebound_speed, "m/s")
    assert outcome["rebound angle above the surface"] == (
        f"{math.degrees(float(TENNIS.rebound_angle)):.6g}°"
    )
    assert outcome["contact"].startswith("grips") == bool(TENNIS.grips)
    spin = {row[0]: row[1:] for row in tables["spin"].rows}
    top = float(TENNIS.topspin)
    assert spin["topspin"] == (number(top / RPM), number(top))
    assert spin["side spin, counter-clockwise"] == (number(TENNIS.sidespin / RPM),
                                                     number(TENNIS.sidespin))  # fmt: skip
    motion = {row[0]: row[1:] for row in tables["motion"].rows}
    assert motion["wz (rad/s)"] == (number(TENNIS.before.wz), number(TENNIS.after.wz))
    pair = {t.key: t for t in sphere_tables(CUT)}
    assert dict(pair["outcome"].rows)["angle between the paths after"] == (
        f"{math.degrees(float(CUT.angle_between_paths)):.6g}°"
    )
    assert pair["motion"].columns[1:] == ("ball 1 before", "ball 1 after", "ball 2 before",
                                          "ball 2 after")  # fmt: skip


def test_backspin_and_skids_are_named():
    imp = solve_sphere(BALL, [1, -4, 0], [0, 0, 300], mu=0.05, kappa=0.8)
    assert float(imp.topspin) < 0 and not bool(imp.grips)
    rows = dict((r[0], r[1]) for r in sphere_tables(imp)[1].rows)
    assert rows["backspin"] == number(-float(imp.topspin) / RPM)
    assert "backspin" in headline(imp) and "skids" in headline(imp)


def test_typeset_labels_and_the_same_values():
    plain, typeset = sphere_tables(CUT), sphere_tables(CUT, typeset=True)
    for a, b in zip(plain, typeset, strict=True):
        assert a.values() == b.values()
    labels = [row[0] for t in typeset for row in t.rows]
    assert "ωz (rad/s)" in labels and "end of impact τ₁" in labels
    assert "ζ = 1 + R²/ρ², ball 2" in labels


def test_what_is_not_one_3d_impact_is_refused():
    with pytest.raises(TypeError, match="SphereImpact or PairImpact"):
        plot_sphere(solve(BALL, 1.0, -1.0, 0.0, mu=0.2, kappa=0.5))
    many = solve_sphere(BALL, [[1, -1, 0], [2, -1, 0]], [0, 0, 0], mu=0.2, kappa=0.5)
    with pytest.raises(ValueError, match="shape"):
        sphere_tables(many)
    with pytest.raises(ValueError, match="shape"):
        sphere_report_html(many)


@pytest.fixture(scope="module")
def pages():
    return {"sphere": sphere_report_html(TENNIS), "pair": sphere_report_html(CUT)}


@pytest.mark.slow
def test_page_holds_the_tables_and_the_figure(pages):
    page = pages["sphere"]
    assert page.startswith("<!DOCTYPE html>") and "http" not in page.split("<body>")[1]
    for table in sphere_tables(TENNIS, typeset=True):
        assert f'data-table="{table.key}"' in page
        for value in table.values():
            assert value.replace("&", "&amp;").replace("<", "&lt;") in page
    assert page.count("data:image/png;base64,") == 1
    assert f'id="regime">{TENNIS.regime}<' in page
    assert "angle between the paths" in pages["pair"]


@pytest.mark.browser
@needs_browser
def test_browser_shows_everything_within_the_window(pages, tmp_path):
    path = tmp_path / "pair.html"  # the widest tables (four columns of velocities)
    path.write_text(pages["pair"], encoding="utf-8")
    out = chromium(tmp_path, "--window-size=800,2000", "--virtual-time-budget=5000",
                   "--dump-dom", path.as_uri())  # fmt: skip
    assert out.returncode == 0, out.stderr[-2000:]
    # the page's own load handler counted the figures decoded and the elements wider than
    # the window
    assert 'data-figures-shown="1/1"' in out.stdout
    assert 'data-overflowing="none"' in out.stdout
