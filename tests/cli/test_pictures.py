"""``spinimpact map`` and ``spinimpact figures`` as a user runs them (issue 10, items 7,
21 and 22): bounded memory, the output checked first, the user's own impact, honest
options."""

import math
import os
import struct
import subprocess
import sys

import numpy as np
import pytest
from click.testing import CliRunner

from spinimpact import Body, solve
from spinimpact.cli import pictures
from spinimpact.viz import maps

from tests.limits import under_limits

pytest.importorskip("matplotlib")


def run(*args, limit=None):
    env = os.environ | {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    command = [sys.executable, "-m", "spinimpact", *args]
    if limit:  # an address-space limit for the child: MemoryError beyond it
        command = under_limits(command, RLIMIT_AS=limit)
    return subprocess.run(command, capture_output=True, text=True, timeout=300, env=env)


def png_size(path):
    head = path.read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", head[16:24])


@pytest.mark.slow
def test_map_at_the_largest_resolution_runs_in_bounded_memory(tmp_path):
    """--resolution 4000 once needed 10 GB (the whole Impact of 16 million points); the
    picture has a few hundred pixels per panel, so it now fits in 1 GiB of address space."""
    target = tmp_path / "map.png"
    out = run("map", "--output", str(target), "--resolution", "4000", "--dpi", "50", limit=2**30)
    assert out.returncode == 0, out.stderr[-2000:]
    assert png_size(target) == (750, 460)


@pytest.mark.slow
def test_map_computes_no_more_points_than_a_panel_has_pixels():
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    fig = maps.plot_map(body, mu=0.2, kappa=0.8, n=4000, dpi=50)
    shapes = {im.get_array().shape for ax in fig.get_axes() for im in ax.get_images()}
    (shape,) = shapes
    fig.draw_without_rendering()  # the panels' size in pixels at 50 dpi
    boxes = [ax.get_window_extent() for ax in fig.get_axes() if ax.get_images()]
    pixels = math.ceil(max(max(b.width, b.height) for b in boxes) * 50 / fig.dpi)
    assert shape == (pixels, pixels) and pixels < 250  # a 15 x 9.2 inch figure at 50 dpi
    # fewer points than pixels are kept as asked; any more give the same picture
    small = maps.plot_map(body, mu=0.2, kappa=0.8, n=40, dpi=50)
    assert small.get_axes()[0].get_images()[0].get_array().shape == (40, 40)
    same = maps.plot_map(body, mu=0.2, kappa=0.8, n=pixels + 1, dpi=50)
    for ax, other in zip(fig.get_axes(), same.get_axes(), strict=True):
        for x, y in zip(ax.get_images(), other.get_images(), strict=True):
            np.testing.assert_array_equal(x.get_array(), y.get_array())


def test_map_fields_are_solved_in_blocks_and_agree_with_the_whole_grid(monkeypatch):
    body = Body.ring(mass=1.0, radius=0.1)
    monkeypatch.setattr(maps, "BLOCK", 50)  # 2 rows of 25 per block
    a, b, f = maps.map_fields(body, mu=0.3, kappa=0.5, extent=2.0, n=25)
    _, _, imp = maps.incidence_grid(body, mu=0.3, kappa=0.5, extent=2.0, n=25)
    np.testing.assert_allclose(f["dissipated_fraction"], imp.dissipated_fraction, rtol=1e-6)
    np.testing.assert_allclose(f["after_vx"], imp.after.vx, rtol=1e-6, atol=1e-7)
    regimes = np.asarray(maps.map_regimes(0.3, 0.5))[f["regime"]]
    expected = np.where(imp.regime == "no-slip", "stick-compression", imp.regime)
    assert np.array_equal(regimes, expected)


def test_map_checks_the_output_before_computing(tmp_path, monkeypatch):
    def no_computing(*args, **kwargs):
        raise AssertionError("computed before the output was checked")

    monkeypatch.setattr(maps, "map_fields", no_computing)
    runner = CliRunner()
    blocked = tmp_path / "ro"
    blocked.mkdir(mode=0o500)
    cases = [
        (tmp_path / "missing" / "map.png", "no such directory"),
        (tmp_path, "is a directory"),
        (tmp_path / "map.txt", "must end in .png, .svg or .pdf"),
    ]
    if os.geteuid() != 0:  # root writes anywhere
        cases.append((blocked / "map.png", "cannot write"))
    for target, needle in cases:
        out = runner.invoke(pictures.map_command, ["--output", str(target)])
        assert out.exit_code == 2 and needle in out.output, (target, out.output)
    out = run("map", "--output", str(tmp_path / "missing" / "map.png"), "--resolution", "4000")
    assert out.returncode == 2 and out.stderr.count("\n") == 1 and "no such directory" in out.stderr


def test_map_help_says_what_the_options_do():
    out = run("map", "--help")
    assert out.returncode == 0
    text = " ".join(out.stdout.split())
    for needle in (
        "the mass changes nothing",
        "only through zeta",
        "never more than a panel spans pixels at --dpi",
        "dots per inch",
    ):
        assert needle in text, needle


@pytest.mark.slow
def test_mass_and_size_change_no_map():
    def images(body):
        fig = maps.plot_map(body, mu=0.3, kappa=0.6, n=30)
        return [im.get_array() for ax in fig.get_axes() for im in ax.get_images()]

    one = images(Body.solid_disk(mass=1.0, radius=0.1))
    other = images(Body.solid_disk(mass=70.0, radius=3.0))
    for x, y in zip(one, other, strict=True):  # rounding of omega = b/R and back, only
        np.testing.assert_allclose(x, y, rtol=1e-12, atol=1e-12)


@pytest.mark.slow
def test_map_legends_offer_only_what_can_happen():
    body = Body.solid_sphere(mass=1.0, radius=0.1)

    def legend(mu, kappa, panel):
        fig = maps.plot_map(body, mu=mu, kappa=kappa, n=20)
        panels = [ax for ax in fig.get_axes() if ax.get_images()]
        bar = panels[panel].get_images()[0].colorbar
        return [t.get_text() for t in bar.ax.get_yticklabels()]

    assert legend(0.2, 0.8, 0) == ["stick-compression", "stick-restitution", "slip"]
    assert legend(0.2, 0.0, 0) == ["stick-compression", "slip"]
    assert legend(0.0, 0.8, 0) == ["frictionless"]
    outcomes = legend(0.2, 0.8, 1)
    assert len(outcomes) == 3 and not any("+" in o or "and" in o for o in outcomes)
    assert legend(0.0, 0.8, 1) == ["unchanged (no friction)"]


def test_no_rebound_is_both_backward_and_spin_reversed():
    """The proof is in maps.map_outcomes; here 300,000 random impacts of every regime."""
    rng = np.random.default_rng(7)
    n = 300_000
    body = Body.from_zeta(mass=1.0, radius=0.1, zeta=rng.uniform(1.01, 6.0, n))
    imp = solve(
        body,
        rng.normal(0, 3, n),
        -rng.uniform(0.1, 5, n),
        rng.normal(0, 30, n),
        mu=rng.uniform(0, 1.5, n),
        kappa=rng.uniform(0, 1, n),
    )
    o = imp.outcome
    assert o.backward.any() and o.reversed_spin.any()
    assert not (o.backward & o.reversed_spin).any()


@pytest.mark.slow
def test_figures_of_the_users_own_impact(tmp_path):
    out = run(
        "figures", "--output-dir", str(tmp_path), "--dpi", "50", "--body", "ring", "--vx", "2",
        "--vy", "-3", "--omega", "5", "--mu", "0.3", "--kappa", "0.5", "--mass", "2",
    )  # fmt: skip
    assert out.returncode == 0, out.stderr
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["energy.png", "history.png", "routh.png"]
    assert png_size(tmp_path / "history.png") == (400, 320)
    # one option is enough; the others keep the paper's values (a solid disk, mu 0.25)
    from spinimpact.viz.plots import impact_figures

    imp = solve(Body.solid_disk(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.25, kappa=0.3)
    title = impact_figures(imp)["history"].get_suptitle()
    out = run("figures", "--output-dir", str(tmp_path / "k"), "--kappa", "0.3", "--dpi", "50")
    assert out.returncode == 0, out.stderr
    assert len(list((tmp_path / "k").iterdir())) == 3
    assert imp.regime in title
    bad = run("figures", "--output-dir", str(tmp_path / "bad"), "--vy", "1")
    assert bad.returncode == 2 and "vy must be < 0" in bad.stderr
    assert not (tmp_path / "bad").exists()  # nothing written for a bad case
    both = run("figures", "--output-dir", str(tmp_path / "b"), "--body", "ring", "--gyration", "1")
    assert both.returncode == 2 and "either --body or --gyration" in both.stderr
