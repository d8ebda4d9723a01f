"""``spinimpact flight``: JSON equal to the Python API, the person's units converted, the
bounce table printed, files written atomically, many balls with their spread, and bad input
as one line with exit status 2."""

import json
import subprocess
import sys

import numpy as np
import pytest

from spinimpact.model.flight import flight

SERVE = ("--ball", "tennis", "--surface", "hard", "--speed", "180", "--speed-unit", "km/h",
         "--elevation-deg", "-6", "--launch-height", "2.8", "--spin-rpm", "2000", "--spin-axis",
             "topspin",
         "--max-bounces", "3")  # fmt: skip


def test_json_is_the_python_api_with_the_units_converted(cli):
    status, out, _ = cli("flight", *SERVE, "--json")
    assert status == 0
    got = json.loads(out)
    want = flight("tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0,
                  max_bounces=3)  # fmt: skip
    np.testing.assert_allclose(got["bounces"]["time"], want.bounces.time, rtol=1e-12)
    np.testing.assert_allclose(got["bounces"]["after"]["wz"], want.bounces.after.wz, rtol=1e-12)
    assert got["stop"] == "bounces" and "path_time" not in got


def test_the_bounce_table_and_the_summary_are_printed(cli):
    status, out, err = cli("flight", *SERVE)
    assert status == 0 and err == ""
    assert "Bounces: tennis ball on hard" in out
    want = flight("tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0,
                  max_bounces=3)  # fmt: skip
    assert ("grips" if want.bounces.grips[0] else "skids") in out
    assert f"{float(want.bounces.position.x[0]):.2f}" in out
    assert max(len(line) for line in out.splitlines()) <= 80


@pytest.mark.slow
def test_plot_and_animation_are_written_and_nothing_else(cli, tmp_path):
    png, gif = tmp_path / "serve.png", tmp_path / "serve.gif"
    status, out, _ = cli("flight", "--speed", "8", "--elevation-deg", "30", "--max-bounces", "1",
                         "--plot", png, "--animate", gif, "--fps", "3", "--dpi", "50")  # fmt: skip
    assert status == 0 and f"wrote {png}" in out and f"wrote {gif}" in out
    assert png.read_bytes()[:4] == b"\x89PNG" and gif.read_bytes()[:3] == b"GIF"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["serve.gif", "serve.png"]


def test_a_failed_run_keeps_the_old_file(cli, tmp_path):
    png = tmp_path / "old.png"
    png.write_bytes(b"old")
    status, _, err = cli("flight", "--speed", "-3", "--plot", png)
    assert status == 2 and "speed must be >= 0" in err
    assert png.read_bytes() == b"old" and [p.name for p in tmp_path.iterdir()] == ["old.png"]


@pytest.mark.slow
def test_many_balls_print_the_spread(cli):
    status, out, _ = cli("flight", "--samples", "50", "--speed", "50", "--speed-sd", "2",
                         "--elevation-deg", "-6", "--launch-height", "2.8", "--spin-rpm", "2000",
                         "--max-bounces", "2", "--seed", "3")  # fmt: skip
    assert status == 0 and "50 tennis balls on hard" in out and "bounce 2: x (m)" in out
    rng = np.random.default_rng(3)
    speed = np.abs(50 + 2 * rng.standard_normal(50))
    want = flight("tennis", "hard", speed=speed, angle=-6.0, height=2.8, spin_rpm=2000.0,
                  max_bounces=2)  # fmt: skip
    row = next(line for line in out.splitlines() if line.strip().startswith("bounce 1: x"))
    assert f"{float(np.mean(want.bounces.position.x[:, 0])):.4g}" in row


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("--speed", "-1"), "--speed must be >= 0, got -1.0"),
        (("--elevation-deg", "95"), "--elevation-deg must be in [-90, 90], got 95.0"),
        (("--heading-deg", "inf"), "--heading-deg must be finite, got inf"),
        (("--launch-height", "-2"), "--launch-height must be > 0, got -2.0"),
        (("--spin-rpm", "100", "--spin-axis", "0,0,0"), "length of spin_axis"),
        (("--spin-axis", "wobble"), "--spin-axis must be"),
        (("--launch-height", "0.01"), "start on or above the ground"),
        (("--ball", "cricket"), "Invalid value for '--ball'"),
        (("--plot", "x.gif"), "--plot must end in"),
        (("--animate", "x.avi"), "--animate must end in .gif or .mp4"),
        (("--animate", "x.gif", "--samples", "3"), "--animate moves one ball"),
        (("--kappa", "2"), "kappa must be in [0, 1]"),
        (("--dt", "0"), "dt must be > 0 (s), got 0.0"),
        (("--dt", "10", "--max-bounces", "3"), "dt must be <= 0.165 s for this flight, got 10.0"),
        (("--t-stop", "-1"), "t_stop must be > 0 (s), got -1.0"),
        (("--air-density", "-1"), "air_density must be >= 0 (kg/m^3), got -1.0"),
        (("--samples", "5", "--speed-sd", "-1"), "--speed-sd must be >= 0"),
        (("--samples", "5", "--elevation-sd-deg", "-0.5"), "--elevation-sd-deg must be >= 0"),
        (("--samples", "5", "--heading-sd-deg", "-2"), "--heading-sd-deg must be >= 0"),
        (("--samples", "5", "--spin-sd-rpm", "-300"), "--spin-sd-rpm must be >= 0"),
        (("--samples", "5", "--spin-sd-rpm", "nan"), "--spin-sd-rpm must be >= 0"),
        (("--speed-sd", "2"), "--speed-sd goes with --samples N"),
    ],
)  # fmt: skip
def test_bad_input_is_one_line_and_exit_2(cli, args, message):
    status, out, err = cli("flight", *args)
    assert status == 2 and out == ""
    assert err.startswith("spinimpact: error:") and message in err
    assert len(err.strip().splitlines()) == 1


@pytest.mark.slow
def test_the_command_runs_as_a_program():
    cmd = [sys.executable, "-m", "spinimpact", "flight", "--speed", "-1"]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert run.returncode == 2 and "Traceback" not in run.stderr


@pytest.mark.slow
def test_a_compliance_law_from_the_command_line(cli):
    from spinimpact.model.compliance import Walton

    args = ("flight", "--speed", "20", "--elevation-deg", "-30", "--launch-height", "1.5",
            "--spin-rpm", "500",
            "--max-bounces", "2", "--tangential", "walton", "--beta0", "0.4")  # fmt: skip
    status, out, _ = cli(*args, "--json")
    want = flight("tennis", "hard", speed=20.0, angle=-30.0, height=1.5, spin_rpm=500.0,
                  max_bounces=2, tangential=Walton(0.4))  # fmt: skip
    got = json.loads(out)
    assert status == 0 and got["tangential"] == {"law": "walton", "beta0": 0.4}
    assert got["bounces"]["regime"] == want.bounces.regime.tolist()
    status, out, _ = cli(*args)
    assert status == 0 and "Walton(beta0=0.4)" in out
    status, _, err = cli("flight", "--tangential", "walton")
    assert status == 2 and "needs --beta0" in err


@pytest.mark.slow
def test_a_wall_from_the_command_line(cli, tmp_path):
    from spinimpact.model.presets import Wall

    png = tmp_path / "wall.png"
    args = ("flight", "--speed", "20", "--elevation-deg", "10", "--max-bounces", "3",
            "--wall-distance", "10", "--wall-heading-deg", "5", "--wall-kappa", "0.6")  # fmt: skip
    status, out, _ = cli(*args, "--json")
    want = flight("tennis", "hard", speed=20.0, angle=10.0, max_bounces=3,
                  wall=Wall(10.0, 5.0, kappa=0.6))  # fmt: skip
    got = json.loads(out)
    assert status == 0 and got["bounces"]["surface"] == want.bounces.surface.tolist()
    assert got["wall"]["distance"] == 10.0 and got["bounces"]["surface"][0] == "wall"
    status, out, _ = cli(*args, "--plot", png)
    assert status == 0 and " 1w " in out and png.exists()
    status, _, err = cli("flight", "--wall-kappa", "0.5")
    assert status == 2 and "--wall-kappa needs --wall-distance" in err
