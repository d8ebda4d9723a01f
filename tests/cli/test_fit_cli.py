"""``spinimpact fit``: the table, the files it writes, and bad input as one line on stderr
with exit status 2."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from spinimpact import BALLS, Body, solve
from spinimpact.cli import main

from tests.model.test_fit import stall_the_optimizer

EXE = Path(sys.executable).parent / "spinimpact"
BALL = Body.solid_sphere(mass=0.058, radius=0.033)
HEADER = "vx,vy,omega,after_vx,after_vy,after_omega"
BODY = ("--body", "solid-sphere", "--radius", "0.033")  # a fit needs its body


@pytest.fixture(autouse=True)
def _keep_sigterm():
    """``main`` installs a SIGTERM handler; give pytest its own back."""
    previous = signal.getsignal(signal.SIGTERM)
    yield
    signal.signal(signal.SIGTERM, previous)


def bounce_file(tmp_path, n=24, missing=True, sigmas=False, name="bounces.csv"):
    rng = np.random.default_rng(7)
    vy = -rng.uniform(2, 6, n)
    vx = np.linspace(0.3, 4.0, n) * -vy
    after = solve(BALL, vx, vy, 0.0, mu=0.35, kappa=0.75).after
    cols = [vx, vy, np.zeros(n), after.vx + rng.normal(0, 0.05, n),
            after.vy + rng.normal(0, 0.05, n), after.omega + rng.normal(0, 3, n)]  # fmt: skip
    header = HEADER + (",sigma_after_vx,sigma_after_vy,sigma_after_omega" if sigmas else "")
    lines = ["# measured bounces", header]
    for i in range(n):
        cells = [repr(float(c[i])) for c in cols] + (["0.05", "0.05", "3"] if sigmas else [])
        if missing and i % 5 == 0:
            cells[5] = ""  # spin not measured
        lines.append(",".join(cells))
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


def run(*args):
    cmd = [str(EXE), *args] if EXE.exists() else [sys.executable, "-m", "spinimpact", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


@pytest.mark.slow
def test_fit_prints_the_table_and_writes_json_and_pictures(tmp_path):
    src = bounce_file(tmp_path, sigmas=True)
    out = run("fit", str(src), *BODY, "--restitution", "power",
              "--json-file", str(tmp_path / "fit.json"), "--plot", str(tmp_path / "fit.png"),
              "--corner", str(tmp_path / "corner.png"))  # fmt: skip
    assert out.returncode == 0, out.stderr
    for needle in ("mu", "kappa_ref", "exponent", "profile likelihood", "AIC", "slid throughout"):
        assert needle in out.stdout
    doc = json.loads((tmp_path / "fit.json").read_text())
    mu = doc["parameters"]["mu"]
    assert mu["low"] < 0.35 < mu["high"]
    assert doc["n_observations"] == 24 * 3 - 5
    for image in ("fit.png", "corner.png"):
        assert (tmp_path / image).read_bytes()[:4] == b"\x89PNG"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bounces.csv", "corner.png",
                                                          "fit.json", "fit.png"]  # fmt: skip


def test_without_sigmas_the_goodness_of_fit_is_not_claimed(tmp_path, capsys):
    main(["fit", str(bounce_file(tmp_path)), *BODY])
    out = capsys.readouterr().out
    assert "not testable without sigmas" in out and "chi2 =" not in out
    assert "one sigma estimated" in out


def test_drop_tests(tmp_path, capsys):
    src = tmp_path / "drops.csv"
    src.write_text("drop_height,rebound_height\n1.0,0.64\n0.5,0.33\n0.25,0.17\n")
    main(["fit", str(src), "--drops"])
    out = capsys.readouterr().out
    assert "kappa" in out and "mu" not in out.split("kappa")[0].split("\n")[-1]
    assert "fit: drop tests" in out and "3 drops," in out
    assert not any(line.strip("│┃ ").startswith("mu ") for line in out.splitlines())
    assert "bounces" not in out and "rigid" not in out


def run_main(capsys, *args):
    with pytest.raises(SystemExit) as exit_:
        main([str(a) for a in args])
    out = capsys.readouterr()
    assert exit_.value.code == 2
    assert out.out == ""
    lines = out.err.strip().splitlines()
    assert len(lines) == 1, out.err
    return lines[0]


@pytest.mark.parametrize(
    "text, extra, needle",
    [
        ("vx,vy,after_vx\n1,-2,0.5\n", (), "missing column(s): omega"),
        (HEADER + ",spin\n1,-2,0,0.5,1,0,3\n", (), "unknown column(s): spin"),
        (HEADER + "\n1,-2,0,0.5,1,0\n2,2,0,0.5,1,0\n", (), "vy must be < 0"),
        (HEADER + "\n1,-2,0,0.5,1,abc\n", (), "row 2, column after_omega: 'abc'"),
        (HEADER + "\n1,-2,0,nan,1,0\n", (), "leave a value that was not measured empty"),
        (HEADER + "\n1,-2,,0.5,1,0\n", (), "omega must be finite"),
        (HEADER + "\n1,-2,0,0.5,,\n", (), "too few usable values"),
        ("", (), "empty file"),
        (HEADER + "\n", (), "no rows"),
        (HEADER + "\n1,-2,0,0.5,1,-20\n", ("--fix", "kappa"), "NAME=VALUE"),
        (HEADER + "\n1,-2,0,0.5,1,-20\n", ("--restitution", "1,x"), "knot speeds"),
    ],
)  # fmt: skip
def test_bad_input_is_one_line(tmp_path, capsys, text, extra, needle):
    src = tmp_path / "bad.csv"
    src.write_text(text)
    line = run_main(capsys, "fit", src, *BODY, *extra)
    assert needle in line


@pytest.mark.parametrize(
    "text, extra, needle",
    [
        ("# c\n" + HEADER + "\n1,-2,0,0.5,1,0\n# c\n\n2,2,0,0.5,1,0\n", (),
         "bad.csv: row 6: vy must be < 0 (each bounce must approach the surface), got 2.0"),
        (HEADER + "\n1,-2,0,0.5,1,0\n# c\n2,-2,0,x,1,0\n", (),
         "bad.csv: row 4, column after_vx: 'x' is not a number"),
        (HEADER + ",sigma_after_vx,sigma_after_vy,sigma_after_omega\n\n1,-2,0,0.5,1,0,1,1,1\n"
         "1,-2,0,0.5,1,0,1,-1,1\n", (), "bad.csv: row 4: sigma_after_vy must be > 0"),
        ("# d\ndrop_height,rebound_height\n1,0.5\n2,2.5\n", ("--drops",),
         "bad.csv: row 4: rebound height 2.5 > drop height 2.0 (a ball"),
        ("# d\ndrop_height,rebound_height\n1,0.5\n\n2,\n", ("--drops",),
         "bad.csv: row 5: column rebound_height is empty"),
        ("drop_height,rebound_height\n1,0.5\n# d\n-2,0.5\n", ("--drops",),
         "bad.csv: row 4: drop heights must be > 0, got -2.0"),
    ],
)  # fmt: skip
def test_a_bad_row_is_named_by_its_line_in_the_file(tmp_path, capsys, text, extra, needle):
    """Comments and blank lines counted, as the errors about a cell count them; no index
    among the data rows."""
    src = tmp_path / "bad.csv"
    src.write_text(text)
    line = run_main(capsys, "fit", src, *BODY, *extra)
    assert needle in line and "index" not in line


def test_usage_errors_are_one_line(tmp_path, capsys):
    src = bounce_file(tmp_path)
    assert "--radius is needed" in run_main(capsys, "fit", src, "--body", "solid-sphere")
    assert "--corner needs at least two" in run_main(
        capsys, "fit", src, *BODY, "--fix", "kappa=0.75", "--corner",
        tmp_path / "c.png")  # fmt: skip
    assert "must end in .png" in run_main(capsys, "fit", src, "--plot", tmp_path / "c.gif")
    assert "not a file" in run_main(capsys, "fit", tmp_path / "nothing.csv")
    assert not (tmp_path / "c.png").exists()


def test_a_fit_that_does_not_converge_is_an_error(tmp_path, capsys, monkeypatch):
    stall_the_optimizer(monkeypatch)
    line = run_main(capsys, "fit", bounce_file(tmp_path), *BODY)
    assert "did not converge" in line


def test_a_compliance_model_and_the_goodness_of_fit(tmp_path, capsys):
    src = bounce_file(tmp_path, sigmas=True, missing=False)
    main(["fit", str(src), *BODY, "--tangential", "walton"])
    out = capsys.readouterr().out
    assert "walton" in out and "beta0" in out
    assert "reduced chi2" in out and "p = " in out and "does not explain" not in out


def test_parameters_the_data_do_not_separate_are_named(tmp_path, capsys):
    """Without measured vy+, sliding bounces give only mu (1 + kappa): mu and kappa are
    not determined apart, and the output says so."""
    rng = np.random.default_rng(3)
    vy = -rng.uniform(2, 6, 20)
    vx = rng.uniform(2.5, 4.0, 20) * -vy  # all slide
    after = solve(BALL, vx, vy, 0.0, mu=0.35, kappa=0.75).after
    a_vx = (after.vx + rng.normal(0, 0.05, 20)).tolist()
    a_om = (after.omega + rng.normal(0, 3, 20)).tolist()
    rows = zip(vx.tolist(), vy.tolist(), a_vx, a_om, strict=True)
    lines = ["vx,vy,omega,after_vx,after_omega"] + [
        f"{a!r},{b!r},0,{c!r},{d!r}" for a, b, c, d in rows
    ]
    src = tmp_path / "slide.csv"
    src.write_text("\n".join(lines) + "\n")
    main(["fit", str(src), *BODY])
    out = capsys.readouterr().out
    assert "not determined locally by these data: mu, kappa" in out


def test_strong_correlations_are_named(tmp_path, capsys):
    """vy+ measured on three sliding bounces only: kappa is determined, but barely apart
    from mu (r = -0.93), and the output names the pair."""
    rng = np.random.default_rng(3)
    vy = -rng.uniform(2, 6, 20)
    vx = rng.uniform(2.5, 4.0, 20) * -vy
    after = solve(BALL, vx, vy, 0.0, mu=0.35, kappa=0.75).after
    a_vx = (after.vx + rng.normal(0, 0.05, 20)).tolist()
    a_vy = [
        repr(v) if i < 3 else ""
        for i, v in enumerate((after.vy + rng.normal(0, 0.05, 20)).tolist())
    ]
    a_om = (after.omega + rng.normal(0, 3, 20)).tolist()
    rows = zip(vx.tolist(), vy.tolist(), a_vx, a_vy, a_om, strict=True)
    lines = [HEADER] + [f"{a!r},{b!r},0,{c!r},{d},{e!r}" for a, b, c, d, e in rows]
    src = tmp_path / "three.csv"
    src.write_text("\n".join(lines) + "\n")
    main(["fit", str(src), *BODY])
    out = capsys.readouterr().out
    assert "strongly correlated: mu and kappa (r = -0.9" in out


def no_spin_file(tmp_path):
    """Bounces without spin, given or measured: the radius plays no part, the shape does."""
    vx, vy = np.linspace(0.5, 12.0, 12), np.full(12, -4.0)
    after = solve(BALL, vx, vy, 0.0, mu=0.35, kappa=0.75).after
    noise = np.random.default_rng(5).normal(0.0, 0.05, (2, 12))
    cols = np.stack([vx, vy, after.vx + noise[0], after.vy + noise[1]], axis=-1).tolist()
    lines = ["vx,vy,omega,after_vx,after_vy"] + [
        f"{a!r},{b!r},0,{c!r},{d!r}" for a, b, c, d in cols
    ]
    path = tmp_path / "nospin.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_fit_needs_its_body(tmp_path, capsys):
    """No body is assumed: a tennis ball's bounces fitted as a solid sphere's give a wrong
    mu with a confident interval."""
    src, flat = bounce_file(tmp_path), no_spin_file(tmp_path)
    for path in (src, flat):
        line = run_main(capsys, "fit", path, "--radius", "0.033")
        assert "a body is needed" in line
        assert all(option in line for option in ("--ball", "--body", "--gyration"))
    line = run_main(capsys, "fit", flat, "--gyration", "0.02")
    assert "--gyration needs --radius" in line
    line = run_main(capsys, "fit", src, "--ball", "tennis", "--radius", "0.03")
    assert "--ball" in line and "--radius" in line
    line = run_main(capsys, "fit", src, "--ball", "tennis", "--body", "ring")
    assert "one of --ball, --body, --gyration" in line


def test_the_body_and_the_law_are_printed_and_stored(tmp_path, capsys):
    src = bounce_file(tmp_path, sigmas=True)
    main(["fit", str(src), "--ball", "tennis", "--json-file", str(tmp_path / "fit.json")])
    out = capsys.readouterr().out
    assert "fit: rigid, constant kappa" in out
    r, rho = BALLS["tennis"].radius, BALLS["tennis"].gyration
    assert f"body: tennis, R = {r:.4g} m, rho = {rho:.4g} m, zeta = {1 + (r / rho) ** 2:.4g}" in out
    doc = json.loads((tmp_path / "fit.json").read_text())
    assert doc["model"] == "rigid, constant kappa"
    assert doc["body"]["name"] == "tennis" and doc["body"]["radius"] == r
    main(["fit", str(no_spin_file(tmp_path)), "--body", "ring", "--json",
          str(tmp_path / "ring.json")])  # fmt: skip
    out = capsys.readouterr().out
    assert "body: ring, zeta = 2 (its radius plays no part without spin)" in out
    body = json.loads((tmp_path / "ring.json").read_text())["body"]
    assert body == {"name": "ring", "radius": None, "gyration": None, "zeta": 2.0}


def test_impossible_rebounds_are_named_by_their_lines(tmp_path, capsys):
    text = HEADER + "\n# row 2 is a comment\n1,-5,0,0.7,3,0\n2,-5,0,1.4,-3,0\n3,-5,0,2.1,8,0\n"
    src = tmp_path / "bad.csv"
    src.write_text(text)
    line = run_main(capsys, "fit", src, "--body", "solid-sphere", "--radius", "0.033")
    assert line.startswith("spinimpact: error: ")
    assert "bad.csv: impossible rebound(s)" in line and "index" not in line
    assert "after_vy = -3 m/s at row 4 (into the surface" in line
    assert "after_vy = 8 m/s at row 5 (faster than the impact" in line


def test_identical_drops_are_refused_on_one_line(tmp_path, capsys):
    src = tmp_path / "drops.csv"
    src.write_text("drop_height,rebound_height\n" + "1.0,0.64\n" * 6)
    line = run_main(capsys, "fit", src, "--drops")
    assert "the 6 drops show no scatter" in line and "sigma_" in line


#: Runs ``spinimpact fit`` as the program does (``main()`` without arguments) and sends
#: itself a signal just after its two outputs are renamed, or from an exit handler once
#: ``main`` has returned (the interpreter's shutdown).
SIGNAL_SCRIPT = """
import atexit, os, signal, sys
from spinimpact.cli import main
from spinimpact.io import atomic

when, signum = sys.argv[1], int(sys.argv[2])
sys.argv = ["spinimpact", *sys.argv[3:]]
commit, outputs = atomic._Temporary.commit, []

def renamed(self):
    commit(self)
    outputs.append(self.target)
    if when == "renamed" and len(outputs) == 2:
        os.kill(os.getpid(), signum)

atomic._Temporary.commit = renamed
try:
    main()
finally:
    if when == "shutdown":
        atexit.register(os.kill, os.getpid(), signum)
"""


@pytest.mark.parametrize("when", ["renamed", "shutdown"])
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
@pytest.mark.slow
def test_a_signal_after_the_outputs_are_renamed_exits_128_plus_it(tmp_path, signum, when):
    """The outputs are in place and complete; the run used to say "no output was changed"
    (just after the renames) or be killed by the signal (-2, -15) during the shutdown."""
    src = bounce_file(tmp_path, sigmas=True)
    outputs = [tmp_path / n for n in ("fit.png", "corner.png")]
    args = ["fit", str(src), "--body", "solid-sphere", "--radius", "0.033", "--plot",
            str(outputs[0]), "--corner", str(outputs[1])]  # fmt: skip
    out = subprocess.run([sys.executable, "-c", SIGNAL_SCRIPT, when, str(int(signum)), *args],
                         capture_output=True, text=True, timeout=120)  # fmt: skip
    name = signal.Signals(signum).name
    assert out.returncode == 128 + signum, out.stderr
    assert out.stderr == (f"spinimpact: {name} came after the command had finished; its "
                          "output is complete\n")  # fmt: skip
    assert all(path.read_bytes()[:4] == b"\x89PNG" for path in outputs)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bounces.csv", "corner.png",
                                                          "fit.png"]  # fmt: skip


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
@pytest.mark.slow
def test_a_signal_while_a_failed_run_exits_says_nothing_changed(tmp_path, signum):
    """A run that failed (no body: exit 2) and gets a signal during its shutdown exits
    128 + the signal, saying no output was changed; it used to be killed by the signal."""
    src = bounce_file(tmp_path)
    (tmp_path / "fit.png").write_bytes(b"old")
    args = ["fit", str(src), "--radius", "0.033", "--plot", str(tmp_path / "fit.png")]
    out = subprocess.run([sys.executable, "-c", SIGNAL_SCRIPT, "shutdown", str(int(signum)),
                          *args], capture_output=True, text=True, timeout=120)  # fmt: skip
    name = signal.Signals(signum).name
    assert out.returncode == 128 + signum, out.stderr
    first, second = out.stderr.splitlines()
    assert first.startswith("spinimpact: error: a body is needed")
    assert second == f"spinimpact: {name} came while it was exiting; no output was changed"
    assert (tmp_path / "fit.png").read_bytes() == b"old"
