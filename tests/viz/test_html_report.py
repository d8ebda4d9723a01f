"""The self-contained HTML report: content, and what a real browser shows."""

import re
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, solve, solve_particle
from spinimpact.viz.html import _num, impact_report_html

from tests.viz.browser import chromium, needs_browser

pytest.importorskip("matplotlib")

ARGS = dict(vx=1.5, vy=-2.0, omega=-80.0, mu=0.1, kappa=0.6)


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    path = tmp_path_factory.mktemp("report") / "impact.html"
    args = ["--body", "solid-disk", "--mass", "2", "--radius", "0.05"]
    for key, value in ARGS.items():
        args += [f"--{key}", str(value)]
    out = subprocess.run(
        [sys.executable, "-m", "spinimpact", "report", "--output", str(path), *args],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0, out.stderr
    imp = solve(Body.solid_disk(mass=2.0, radius=0.05), **ARGS)
    return path, path.read_text(encoding="utf-8"), imp


@pytest.mark.slow
def test_report_holds_the_numbers_of_the_impact(page):
    _, text, imp = page
    assert f'id="regime">{imp.regime}<' in text
    for value in (
        imp.after.vx,
        imp.after.vy,
        imp.after.omega,
        imp.slip_after,
        imp.tau0,
        imp.tau1,
        imp.tangential_impulse,
        imp.dissipated_energy,
        imp.kinetic_energy_after,
        imp.min_kinetic_energy,
        imp.work_compression_normal,
        imp.work_compression_tangential,
        imp.work_restitution_normal,
        imp.work_restitution_tangential,
        imp.impulse_ratio,
        imp.work_ratio_tangential,
        imp.newton_restitution,
        imp.energetic_restitution,
    ):
        assert f"<td>{_num(value)}</td>" in text, value


@pytest.mark.slow  # renders a whole page or map (about a second)
def test_report_is_self_contained(page):
    _, text, _ = page
    assert text.count('src="data:image/png;base64,') == 3
    assert not re.search(r'(src|href)="(https?:)?//', text)  # nothing fetched from a network


def test_report_api_rejects_arrays():
    imp = solve(Body.ring(mass=1.0, radius=0.1), [1.0, 2.0], -1.0, 0.0, mu=0.2, kappa=0.5)
    with pytest.raises(ValueError, match="one impact"):
        impact_report_html(imp)


@pytest.mark.slow
def test_report_flags_energy_creating_particle():
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 0.1, -1.0, 0.0, mu=0.5, kappa=0.8)
    text = impact_report_html(imp, solve_particle(0.1, -1.0, mu=0.5, kappa=0.8))
    assert '<span class="warn">creates energy</span>' in text


@pytest.mark.slow
def test_report_bad_output_name(tmp_path):
    out = subprocess.run(
        [sys.executable, "-m", "spinimpact", "report", "--output", str(tmp_path / "r.txt")],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert out.returncode == 2 and "must end in .html" in out.stderr
    assert not list(tmp_path.iterdir())


@pytest.mark.browser
@needs_browser
def test_browser_shows_the_report(page, tmp_path):
    path, _, imp = page
    out = chromium(tmp_path, "--virtual-time-budget=5000", "--dump-dom", path.as_uri())
    assert out.returncode == 0, out.stderr[-2000:]
    dom = out.stdout
    # the page's own load handler counted the figures the browser decoded
    assert 'data-figures-shown="3/3"' in dom
    assert f'id="regime">{imp.regime}<' in dom


@pytest.mark.browser
@needs_browser
def test_browser_screenshot(page, tmp_path):
    from matplotlib.image import imread

    path, _, _ = page
    shot = tmp_path / "shot.png"
    out = chromium(tmp_path, "--window-size=1200,2400", f"--screenshot={shot}", path.as_uri())
    assert out.returncode == 0, out.stderr[-2000:]
    pixels = imread(shot)
    assert pixels.shape[:2] == (2400, 1200)
    gray = pixels[..., :3].mean(axis=2)
    # a rendered page: mostly white background with dark text and coloured figures
    assert gray.mean() > 0.8
    assert (gray < 0.3).mean() > 0.005
    assert np.unique((pixels[..., :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0).shape[0] > 50
