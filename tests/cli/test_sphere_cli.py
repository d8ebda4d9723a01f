"""``spinimpact sphere`` and ``spinimpact pair``: JSON equal to the Python API, a person's
inputs (speed, angles in degrees, rpm about a named axis) equal to the vectors they
describe, the report, the files written, and bad input as one line with exit status 2."""

import json
import math
import subprocess
import sys

import pytest

from spinimpact import Body, Surface, solve_pair, solve_sphere
from spinimpact.cli._common import jsonable

RPM = 2 * math.pi / 60  # rad/s per rpm, written out here independently of the package
BALL = Body.solid_sphere(mass=1.0, radius=0.1)  # the defaults: --mass 1 --radius 0.1


def run(*args):
    cmd = [sys.executable, "-m", "spinimpact", *map(str, args)]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


def as_json(cli, *args):
    status, out, err = cli(*args, "--json")
    assert status == 0, err
    return json.loads(out)


@pytest.mark.slow
def test_sphere_json_equals_the_python_api():
    out = run("sphere", "--body", "spherical-shell", "--mass", 0.057, "--radius", 0.033,
              "--velocity", "20,-8,3", "--spin=-10,150,-200", "--normal", "0.1,1,-0.2",
              "--surface-velocity", "-5,0,1", "--mu", 0.6, "--kappa", 0.75, "--json")  # fmt: skip
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""
    ball = Body.spherical_shell(mass=0.057, radius=0.033)
    surface = Surface(normal=[0.1, 1, -0.2], velocity=[-5, 0, 1])
    imp = solve_sphere(ball, [20, -8, 3], [-10, 150, -200], mu=0.6, kappa=0.75, surface=surface)
    # JSON writes floats by repr, so every field comes back bit for bit; angles in radians
    assert json.loads(out.stdout) == jsonable(imp.to_dict())
    assert json.loads(out.stdout)["rebound_angle"] == float(imp.rebound_angle)


def test_pair_json_equals_the_python_api(cli):
    got = as_json(cli, "pair", "--body2", "spherical-shell", "--mass2", 0.5, "--radius2", 0.05,
                  "--gyration1", 0.07, "--velocity1", "2,0,0.5", "--spin1", "0,30,-20",
                  "--velocity2=-1,0,0", "--spin2", "5,0,0", "--normal", "-1,0.2,1",
                  "--mu", 0.1, "--kappa", 0.9)  # fmt: skip
    b1 = Body(mass=1.0, radius=0.1, gyration=0.07)
    b2 = Body.spherical_shell(mass=0.5, radius=0.05)
    imp = solve_pair(b1, b2, velocity1=[2, 0, 0.5], spin1=[0, 30, -20], velocity2=[-1, 0, 0],
                     spin2=[5, 0, 0], normal=[-1, 0.2, 1], mu=0.1, kappa=0.9)  # fmt: skip
    assert got == jsonable(imp.to_dict())


def test_pair_centres_instead_of_a_normal(cli):
    got = as_json(cli, "pair", "--centre1", "0,0,0", "--centre2", "0.2,0,0")
    centres = ([0, 0, 0], [0.2, 0, 0])
    imp = solve_pair(BALL, BALL, velocity1=[2, 0, 0], spin1=[0, 0, -20], velocity2=[0, 0, 0],
                     spin2=[0, 0, 0], centres=centres, mu=0.2, kappa=0.8)  # fmt: skip
    assert got == jsonable(imp.to_dict())
    assert got["normal"] == {"x": -1.0, "y": 0.0, "z": 0.0}  # from ball 2's centre to 1's


def test_default_sphere_is_the_plane_default_of_solve(cli):
    from spinimpact import solve

    got = as_json(cli, "sphere")
    plane = solve(BALL, 3.0, -4.0, 10.0, mu=0.2, kappa=0.8)  # spinimpact solve's defaults
    assert got["after"]["vx"] == pytest.approx(float(plane.after.vx), rel=1e-12)
    assert got["after"]["wz"] == pytest.approx(float(plane.after.omega), rel=1e-12)
    assert got["regime"] == plane.regime


def _numbers(d):
    """The numeric leaves of a JSON dict, flattened by path."""
    out = {}
    for key, value in d.items():
        if isinstance(value, dict):
            out.update({f"{key}.{k}": v for k, v in _numbers(value).items()})
        elif isinstance(value, float | int) and not isinstance(value, bool):
            out[key] = value
    return out


def assert_same(got, imp):
    """JSON ``got`` equals ``imp`` to rounding (the inputs went through sin/cos once)."""
    want = _numbers(jsonable(imp.to_dict()))
    have = _numbers(got)
    assert have.keys() == want.keys()
    for key, value in want.items():  # closed forms: 1e-12 of the field's scale
        scale = max(1.0, abs(value))
        assert have[key] == pytest.approx(value, rel=1e-9, abs=1e-12 * scale), key
    assert got["regime"] == str(imp.regime)


c30, s30 = math.cos(math.radians(30)), math.sin(math.radians(30))
PERSON = {
    "along +x, topspin": (
        ["--speed", 10, "--incidence-from-surface-deg", 30, "--spin-rpm", 3000, "--spin-axis",
         "topspin"],
        (10 * c30, -10 * s30, 0), (0, 0, -3000 * RPM), None,
    ),
    "heading 90 (-z), backspin": (
        ["--speed", 10, "--incidence-from-surface-deg", 30, "--heading-deg", 90, "--spin-rpm", 1200,
         "--spin-axis", "backspin"],
        (0, -10 * s30, -10 * c30), (1200 * RPM, 0, 0), None,
    ),
    "heading 180 (-x), side spin": (
        ["--speed", 4, "--incidence-from-surface-deg", 60, "--heading-deg", 180, "--spin-rpm", -500,
         "--spin-axis", "sidespin"],
        (-4 * s30, -4 * c30, 0), (0, -500 * RPM, 0), None,
    ),
    "an axis x,y,z": (
        ["--speed", 5, "--incidence-from-surface-deg", 90, "--spin-rpm", 600, "--spin-axis",
         "3,0,4"],
        (0, -5, 0), (600 * RPM * 0.6, 0, 600 * RPM * 0.8), None,
    ),
    "a tilted, moving surface": (  # normal tilted 30 deg about z: t1 = (c, s, 0), t2 = -z
        ["--normal", f"{-s30!r},{c30!r},0", "--surface-velocity", "1,2,0", "--speed", 6,
         "--incidence-from-surface-deg", 45, "--heading-deg", 90, "--spin-rpm", 100,
             "--spin-axis", "topspin"],
        (1 + 6 * math.sqrt(0.5) * s30, 2 - 6 * math.sqrt(0.5) * c30, -6 * math.sqrt(0.5)),
        # n x e = (-s, c, 0) x (0, 0, -1) = (-c, -s, 0)
        (-100 * RPM * c30, -100 * RPM * s30, 0), ((-s30, c30, 0), (1, 2, 0)),
    ),
}  # fmt: skip


@pytest.mark.parametrize("case", list(PERSON))
def test_person_inputs_equal_the_vectors_they_describe(cli, case):
    args, v, w, surface = PERSON[case]
    got = as_json(cli, "sphere", *args)
    plane = Surface(*surface) if surface else None
    assert_same(got, solve_sphere(BALL, v, w, mu=0.2, kappa=0.8, surface=plane))
    vector = as_json(cli, "sphere", "--velocity", ",".join(map(repr, v)),
                     "--spin", ",".join(map(repr, w)),
                     *(["--normal", ",".join(map(repr, surface[0])),
                        "--surface-velocity", "1,2,0"] if surface else []))  # fmt: skip
    assert_same(vector, solve_sphere(BALL, v, w, mu=0.2, kappa=0.8, surface=plane))


def test_topspin_input_leaves_with_topspin_and_a_ball_rolling_forward_grips(cli):
    # rolling forward at 2 m/s with R = 0.1: 20 rad/s of topspin; a vertical drop changes
    # nothing along the surface, so it leaves rolling, with the same topspin
    got = as_json(
        cli, "sphere", "--velocity", "2,-1,0", "--spin-rpm", 20 / RPM, "--spin-axis", "topspin"
    )
    assert got["before"]["wz"] == pytest.approx(-20.0, rel=1e-12)
    assert got["grips"] is True  # (rpm to rad/s rounds: the slip is ~1e-16, not 0)
    assert got["topspin"] == pytest.approx(20.0, rel=1e-12)


def test_pair_person_inputs(cli):
    got = as_json(cli, "pair", "--speed1", 2, "--heading1-deg", 90, "--spin1-rpm", 600,
                  "--spin1-axis", "backspin", "--normal", "0,0,1")  # fmt: skip
    v1, w1 = (0, 0, -2), (600 * RPM, 0, 0)  # along -z; backspin turns about +x
    imp = solve_pair(BALL, BALL, velocity1=v1, spin1=w1, velocity2=[0, 0, 0], spin2=[0, 0, 0],
                     normal=[0, 0, 1], mu=0.2, kappa=0.8)  # fmt: skip
    assert_same(got, imp)


def test_sphere_report_says_what_a_person_asks(cli):
    status, out, err = cli("sphere", "--velocity", "20,-8,3", "--spin", "0,150,-200",
                           "--mu", 0.6, "--kappa", 0.75)  # fmt: skip
    assert status == 0, err
    imp = solve_sphere(BALL, [20, -8, 3], [0, 150, -200], mu=0.6, kappa=0.75)
    degrees = math.degrees(float(imp.rebound_angle))
    for needle in (
        f"Regime: {imp.regime}",
        "rebound speed |v+|", f"{float(imp.rebound_speed):.6g} m/s",
        f"{degrees:.6g}°",
        "topspin", f"{float(imp.topspin) / RPM:.6g}", f"{float(imp.topspin):.6g}",
        "side spin, counter-clockwise", "grips (leaves rolling, no slip)",
        "Energy budget", "Coefficients",
    ):  # fmt: skip
        assert needle in out, needle
    status, out, _ = cli("sphere", "--velocity", "1,-4,0", "--spin", "0,0,30", "--mu", 0.1)
    assert "backspin" in out and "skids (leaves sliding at" in out


def test_pair_report_names_the_angle_between_paths(cli):
    status, out, err = cli("pair")
    assert status == 0, err
    imp = solve_pair(BALL, BALL, velocity1=[2, 0, 0], spin1=[0, 0, -20], velocity2=[0, 0, 0],
                     spin2=[0, 0, 0], normal=[-1, 0, 1], mu=0.2, kappa=0.8)  # fmt: skip
    assert "angle between the paths after" in out
    assert f"{math.degrees(float(imp.angle_between_paths)):.6g}°" in out
    assert "ball 2 after" in out and "Contact, ball 1 relative to ball 2" in out


@pytest.mark.slow
def test_plot_and_html_are_written(cli, tmp_path):
    plot, page = tmp_path / "views.png", tmp_path / "report.html"
    plot.write_bytes(b"previous")
    status, out, err = cli("sphere", "--plot", plot, "--html", page, "--dpi", 50)
    assert status == 0, err
    assert out.splitlines()[-2:] == [f"wrote {plot}", f"wrote {page}"]
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert page.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.html", "views.png"]


BAD = [
    (["sphere", "--velocity", "1,2"], "three finite numbers"),
    (["sphere", "--velocity", "a,b,c"], "three finite numbers"),
    (["sphere", "--spin", "1,nan,0"], "three finite numbers"),
    (["sphere", "--velocity", "1,-1,0", "--speed", 3], "either --velocity or --speed"),
    (["sphere", "--speed", 3], "--speed needs --incidence-from-surface-deg"),
    (["sphere", "--incidence-from-surface-deg", 30], "--incidence-from-surface-deg needs --speed"),
    (["sphere", "--speed", 3, "--incidence-from-surface-deg", 120],
     "--incidence-from-surface-deg must be in [0, 90]"),
    (["sphere", "--speed", 3, "--incidence-from-surface-deg", 0], "must approach"),
    (["sphere", "--speed", -3, "--incidence-from-surface-deg", 10],
     "--speed must be a finite number > 0"),
    (["sphere", "--spin-rpm", 100], "--spin-rpm and --spin-axis go together"),
    (["sphere", "--spin-rpm", 100, "--spin-axis", "wobble"],
     "topspin, backspin, sidespin, a combination"),
    (["sphere", "--spin-rpm", 100, "--spin-axis", "0,0,0"], "--spin-axis must be a direction"),
    (["sphere", "--spin", "0,0,1", "--spin-rpm", 100, "--spin-axis", "x"],
     "either --spin or --spin-rpm"),
    (["sphere", "--velocity", "0,-3,0", "--spin-rpm", 1, "--spin-axis", "topspin"],
     "needs a direction"),
    (["sphere", "--normal", "0,0,0"], "normal"),
    (["sphere", "--velocity", "1,1,0"], "must approach"),
    (["sphere", "--body", "spherical-shell", "--gyration", 0.05], "not both"),
    (["sphere", "--body", "solid-disk"], "solid-disk"),
    (["sphere", "--mu", -1], "mu"),
    (["sphere", "--kappa", 2], "kappa"),
    (["sphere", "--plot", "views.txt"], "--plot must end in .png, .svg or .pdf"),
    (["sphere", "--html", "page.txt"], "--html must end in .html"),
    (["sphere", "--plot", "/no/such/dir/v.png"], "no such directory"),
    (["sphere", "--batch", "in.csv"], "--batch needs --output"),
    (["sphere", "--batch", "in.csv", "--output", "o.csv", "--velocity", "1,-1,0"],
     "--velocity describes one impact"),
    (["sphere", "--batch", "missing.csv", "--output", "o.csv"], "does not exist"),
    (["pair", "--batch", "in.csv", "--output", "o.csv", "--plot", "v.png"],
     "--plot describes one impact"),
    (["sphere", "--output", "o.csv"], "--output goes with --batch"),
    (["pair", "--centre1", "0,0,0"], "--centre1 and --centre2 go together"),
    (["pair", "--centre1", "0,0,0", "--centre2", "0.2,0,0", "--normal", "1,0,0"], "not both"),
    (["pair", "--centre1", "0,0,0", "--centre2", "0.1,0,0"], "overlap"),
    (["pair", "--normal", "1,0,0"], "must approach"),
    (["pair", "--speed1", 2, "--velocity1", "1,0,0"], "either --velocity1 or --speed1"),
    (["pair", "--spin2-rpm", 100, "--spin2-axis", "topspin"], "needs a direction of travel"),
]  # fmt: skip


@pytest.mark.parametrize(("args", "needle"), BAD, ids=[" ".join(map(str, a)) for a, _ in BAD])
def test_bad_input_is_one_line_and_exit_status_2(cli, args, needle):
    status, out, err = cli(*args)
    assert status == 2
    assert out == ""
    assert err.startswith("spinimpact: error: ") and err.count("\n") == 1, err
    assert needle in err


@pytest.mark.slow
def test_bad_input_as_a_subprocess():
    out = run("pair", "--velocity1", "1,2,3,4")
    assert out.returncode == 2
    assert out.stdout == "" and len(out.stderr.splitlines()) == 1
    assert "three finite numbers" in out.stderr and "Traceback" not in out.stderr


def test_batch_through_the_command_line(cli, tmp_path):
    source, target = tmp_path / "in.csv", tmp_path / "out.csv"
    source.write_text("vx,vy,vz,wx,wy,wz\n20,-8,3,0,150,-200\n1,-2,0,0,0,0\n")
    status, out, err = cli("sphere", "--batch", source, "--output", target, "--mu", 0.6)
    assert status == 0, err
    assert out.strip() == f"wrote 2 rows (spheres) to {target}"
    import csv

    with target.open() as f:
        rows = list(csv.DictReader(f))
    imp = solve_sphere(BALL, [[20, -8, 3], [1, -2, 0]], [[0, 150, -200], [0, 0, 0]],
                       mu=0.6, kappa=0.8)  # fmt: skip
    assert [float(r["after_vx"]) for r in rows] == imp.after.vx.tolist()
    assert [r["mu"] for r in rows] == ["0.6", "0.6"]  # the default, written where it was used

    pairs = tmp_path / "pairs.csv"
    pairs.write_text("vx,vy,vz,wx,wy,wz,vx2,vy2,vz2,wx2,wy2,wz2\n2,0,0,0,0,-20,0,0,0,0,0,0\n")
    status, out, err = cli("pair", "--batch", pairs, "--output", target, "--normal", "-1,0,0")
    assert status == 0, err
    assert "1 row (pairs of spheres)" in out
    status, _, err = cli("sphere", "--batch", pairs, "--output", target)
    assert status == 2 and "describe problem 'pair'" in err
