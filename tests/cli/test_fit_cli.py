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

from spinimpact import Body, solve
from spinimpact.cli import main

from tests.model.test_fit import stall_the_optimizer

EXE = Path(sys.executable).parent / "spinimpact"
BALL = Body.solid_sphere(mass=0.058, radius=0.033)
HEADER = "vx,vy,omega,after_vx,after_vy,after_omega"


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


def test_fit_prints_the_table_and_writes_json_and_pictures(tmp_path):
    src = bounce_file(tmp_path, sigmas=True)
    out = run("fit", str(src), "--radius", "0.033", "--restitution", "power",
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
    main(["fit", str(bounce_file(tmp_path)), "--radius", "0.033"])
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
    line = run_main(capsys, "fit", src, "--radius", "0.033", *extra)
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
    line = run_main(capsys, "fit", src, "--radius", "0.033", *extra)
    assert needle in line and "index" not in line


def test_usage_errors_are_one_line(tmp_path, capsys):
    src = bounce_file(tmp_path)
    assert "--radius is needed" in run_main(capsys, "fit", src)
    assert "--corner needs at least two" in run_main(
        capsys, "fit", src, "--radius", "0.033", "--fix", "kappa=0.75", "--corner",
        tmp_path / "c.png")  # fmt: skip
    assert "must end in .png" in run_main(capsys, "fit", src, "--plot", tmp_path / "c.gif")
    assert "not a file" in run_main(capsys, "fit", tmp_path / "nothing.csv")
    assert not (tmp_path / "c.png").exists()


def test_a_fit_that_does_not_converge_is_an_error(tmp_path, capsys, monkeypatch):
    stall_the_optimizer(monkeypatch)
    line = run_main(capsys, "fit", bounce_file(tmp_path), "--radius", "0.033")
    assert "did not converge" in line


def test_a_compliance_model_and_the_goodness_of_fit(tmp_path, capsys):
    src = bounce_file(tmp_path, sigmas=True, missing=False)
    main(["fit", str(src), "--radius", "0.033", "--tangential", "walton"])
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
    main(["fit", str(src), "--radius", "0.033"])
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
    main(["fit", str(src), "--radius", "0.033"])
    out = capsys.readouterr().out
    assert "strongly correlated: mu and kappa (r = -0.9" in out
