"""``spinimpact planar``: every body as a subprocess (JSON equal to the Python API), the
report and the figures it writes, bad input as one line with exit status 2, ``--help``."""

import json
import math
import signal
import subprocess
import sys

import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar
from spinimpact.cli import main
from spinimpact.cli._common import jsonable


def run(*args):
    cmd = [sys.executable, "-m", "spinimpact", "planar", *map(str, args)]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


@pytest.fixture
def run_main(capsys):
    """Run ``spinimpact planar`` in this process: (exit status, stdout, stderr)."""
    previous = signal.getsignal(signal.SIGTERM)  # main installs its own handler

    def call(*args):
        try:
            main(["planar", *map(str, args)])
            status = 0
        except SystemExit as exit_:
            status = exit_.code
        out = capsys.readouterr()
        return status, out.out, out.err

    yield call
    signal.signal(signal.SIGTERM, previous)


CASES = {
    "rod": (
        ["--length", 0.8, "--orientation-deg", 60, "--vx", 1.5, "--vy", -2, "--omega", 3],
        lambda: PlanarBody.rod(mass=2.0, length=0.8, angle=math.radians(60)),
        (1.5, -2.0, 3.0),
    ),
    "block": (
        ["--width", 0.3, "--height", 0.1, "--orientation-deg", 23, "--vx", -0.5, "--vy", -1],
        lambda: PlanarBody.block(mass=2.0, width=0.3, height=0.1, angle=math.radians(23)),
        (-0.5, -1.0, 0.0),
    ),
    "eccentric-disk": (
        [
            "--radius",
            0.1,
            "--gyration",
            0.06,
            "--offset",
            0.03,
            "--orientation-deg",
            30,
            "--omega",
            -20,
        ],
        lambda: PlanarBody.eccentric_disk(
            mass=2.0, radius=0.1, gyration=0.06, offset=0.03, angle=math.radians(30)
        ),
        (1.0, -1.0, -20.0),
    ),
    "pendulum": (
        ["--length", 1.2, "--orientation-deg", 70, "--omega", -3],
        lambda: Pendulum.rod(mass=2.0, length=1.2, angle=math.radians(70)),
        (None, None, -3.0),
    ),
}


@pytest.mark.parametrize("body", list(CASES))
@pytest.mark.slow
def test_json_equals_the_python_api(body):
    options, make, (vx, vy, omega) = CASES[body]
    law = {"rod": "newton", "block": "energetic"}.get(body, "poisson")
    out = run(
        "--body", body, "--mass", 2, *options, "--mu", 0.4, "--kappa", 0.7, "--law", law, "--json"
    )
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""
    got = json.loads(out.stdout)
    if body == "pendulum":
        imp = solve_pendulum(make(), omega, mu=0.4, kappa=0.7, law=law)
    else:
        imp = solve_planar(make(), vx, vy, omega, mu=0.4, kappa=0.7, law=law)
    # JSON writes floats by repr, so every field comes back bit for bit
    assert got == jsonable(imp.to_dict())
    assert got["law"] == law and got["body"]["name"] == make().name


@pytest.mark.slow
def test_report_and_both_figures(tmp_path):
    routh, laws = tmp_path / "routh.png", tmp_path / "laws.svg"
    routh.write_bytes(b"previous")
    out = run("--orientation-deg", 45, "--plot", routh, "--laws-plot", laws, "--dpi", 50)
    assert out.returncode == 0, out.stderr
    imp = solve_planar(
        PlanarBody.rod(mass=1.0, length=1.0, angle=math.pi / 4), 1.0, -1.0, 0.0, mu=0.3, kappa=0.8
    )  # the documented defaults
    text = out.stdout
    for needle in (
        f"Regime: {imp.regime}",
        "Poisson (kinetic)",
        "Impulses",
        "Energy budget",
        "Coefficients",
        "W_tt, W_tn, W_nn (1/kg)",
        f"{float(imp.tau1):.6g}",
        f"{float(imp.after.omega):.6g}",
        f"wrote {routh}",
    ):
        assert needle in text, needle
    assert routh.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert laws.read_text().lstrip().startswith("<?xml")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["laws.svg", "routh.png"]  # no temps


@pytest.mark.slow
def test_map_plot_spans_the_angles_of_the_body(run_main, tmp_path):
    target = tmp_path / "map.png"
    status, out, err = run_main(
        "--body",
        "block",
        "--orientation-deg",
        10,
        "--map-plot",
        target,
        "--resolution",
        8,
        "--dpi",
        50,
    )
    assert status == 0, err
    assert out.splitlines()[-1] == f"wrote {target}"
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_energy_creation_is_flagged(run_main):
    status, out, _ = run_main("--vx", 0.5, "--mu", 0.8, "--kappa", 0.9, "--law", "newton")
    assert status == 0
    assert "creates energy" in out.splitlines()[1]


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--body", "rod", "--width", 1], "--width does not apply to --body rod"),
        (
            ["--orientation-deg", 190],
            "--orientation-deg 190 is 3.31613 rad: angle must be in (0, pi) rad",
        ),
        (["--body", "block", "--orientation-deg", 90], "angle must be in [0, pi/2) rad"),
        (["--body", "pendulum", "--vx", 1], "--vx does not apply to --body pendulum"),
        (["--body", "pendulum", "--omega", 2], "contact point must approach"),
        (["--vy", 1], "contact point must approach"),
        (["--kappa", 1.5], "kappa"),
        (["--mu", -1], "mu"),
        (["--mass", 0], "mass"),
        (["--law", "hooke"], "hooke"),
        (["--plot", "routh.txt"], "--plot must end in .png, .svg or .pdf"),
        (["--laws-plot", "laws"], "--laws-plot must end in .png, .svg or .pdf"),
        (["--body", "pendulum", "--map-plot", "m.png"], "--map-plot needs --body rod, block"),
    ],
)
def test_bad_input_is_one_line_exit_2(run_main, args, needle):
    status, out, err = run_main(*args)
    assert status == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("spinimpact: error: "), err
    assert needle in lines[0]


@pytest.mark.slow
def test_bad_input_from_the_shell():
    out = run("--body", "eccentric-disk", "--offset", 0.2)
    assert out.returncode == 2 and out.stdout == ""
    (line,) = out.stderr.strip().splitlines()
    assert line.startswith("spinimpact: error: offset must be < radius")


def test_help_names_the_units(run_main):
    status, out, _ = run_main("--help")
    assert status == 0
    for needle in (
        "--orientation-deg",
        "degrees",
        "conventions.md",
        "rod|block|eccentric-disk|pendulum",
        "--laws-plot",
        "newton|poisson|energetic",
    ):
        assert needle in out, needle


@pytest.mark.slow
def test_html_page_is_written_atomically(tmp_path):
    page = tmp_path / "rod.html"
    page.write_text("previous")
    out = run("--length", 0.8, "--orientation-deg", 60, "--law", "newton", "--html", page)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines()[-1] == f"wrote {page}"
    imp = solve_planar(
        PlanarBody.rod(mass=1.0, length=0.8, angle=math.radians(60)),
        1.0,
        -1.0,
        0.0,
        mu=0.3,
        kappa=0.8,
        law="newton",
    )
    text = page.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>")
    assert f'id="regime">{imp.regime}<' in text and "law: Newton (kinematic)" in text
    assert f"<td>{float(imp.tau1):.6g}</td>" in text  # the report's number
    # the geometry as the user gave it, and the figures
    assert "<td>length L</td><td>0.8 m</td>" in text
    assert "<td>angle to the surface</td><td>60° (1.0472 rad)</td>" in text
    assert text.count('src="data:image/png;base64,') == 2
    assert [p.name for p in tmp_path.iterdir()] == ["rod.html"]  # no temporary files


@pytest.mark.parametrize("body", list(CASES))
@pytest.mark.slow
def test_html_page_for_every_body(run_main, tmp_path, body):
    options, make, _ = CASES[body]
    target = tmp_path / f"{body}.htm"
    status, out, err = run_main("--body", body, "--mass", 2, *options, "--json", "--html", target)
    assert status == 0, err
    json.loads(out)  # --json keeps standard output to the JSON alone
    text = target.read_text(encoding="utf-8")
    assert f"Planar impact: {make().name} on a rough surface" in text
    assert sorted(p.name for p in tmp_path.iterdir()) == [target.name]


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--html", "report.txt"], "--html must end in .html or .htm, got 'report.txt'"),
        (["--html", "no/such/dir/r.html"], "--html: no such directory 'no/such/dir'"),
        (["--html", "r.html", "--kappa", 2], "kappa"),
    ],
)
def test_html_bad_input_is_one_line_exit_2(run_main, tmp_path, monkeypatch, args, needle):
    monkeypatch.chdir(tmp_path)
    status, out, err = run_main(*args)
    assert status == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("spinimpact: error: "), err
    assert needle in lines[0]
    assert not list(tmp_path.iterdir())  # nothing written, not even a temporary file


def test_help_names_the_html_page(run_main):
    status, out, _ = run_main("--help")
    assert status == 0
    assert "--html" in out and "self-contained HTML" in " ".join(out.split())
