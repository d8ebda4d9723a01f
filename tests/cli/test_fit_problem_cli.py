"""``spinimpact fit --problem NAME FILE``: any registered problem fitted from a CSV file of
its inputs and measured result columns; bad input as one line on stderr, exit status 2."""

from __future__ import annotations

import json
import signal

import numpy as np
import pytest

from spinimpact import BALLS, solve_sphere
from spinimpact.cli import main

TENNIS = BALLS["tennis"]
BODY = ("--radius", repr(TENNIS.radius), "--gyration", repr(TENNIS.gyration))


@pytest.fixture(autouse=True)
def _keep_sigterm():
    """``main`` installs a SIGTERM handler; give pytest its own back."""
    previous = signal.getsignal(signal.SIGTERM)
    yield
    signal.signal(signal.SIGTERM, previous)


def sphere_file(tmp_path, n=20, blank=None):
    """Tennis-ball bounces in 3D (side spin, spin about the normal), mu = 0.55, kappa =
    0.75, the rebound measured with 0.05 m/s of noise; ``blank``: (row, column) left empty."""
    rng = np.random.default_rng(11)
    v = np.stack([rng.uniform(2, 12, n), -rng.uniform(3, 8, n), rng.uniform(-3, 3, n)], -1)
    w = rng.normal(0.0, 80.0, (n, 3))
    after = solve_sphere(TENNIS.body, v, w, mu=0.55, kappa=0.75).after
    cols = {f"v{k}": v[:, i] for i, k in enumerate("xyz")}
    cols |= {f"w{k}": w[:, i] for i, k in enumerate("xyz")}
    cols |= {f"after_{q}": getattr(after, q) + rng.normal(0, 0.05, n) for q in ("vx", "vy", "vz")}
    lines = ["# tennis-ball bounces", ",".join(cols)]
    for i in range(n):
        cells = [repr(float(c[i])) for c in cols.values()]
        if blank is not None and blank[0] == i:
            cells[list(cols).index(blank[1])] = ""
        lines.append(",".join(cells))
    path = tmp_path / "bounces.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def refused(capsys, *args):
    with pytest.raises(SystemExit) as stop:
        main(["fit", *args])
    err = capsys.readouterr().err.strip()
    assert stop.value.code == 2 and len(err.splitlines()) == 1, err
    return err


@pytest.mark.slow
def test_a_sphere_file_is_fitted_and_written_as_json(tmp_path, capsys):
    src, out = sphere_file(tmp_path), tmp_path / "fit.json"
    main(["fit", "--problem", "sphere", str(src), *BODY, "--json-file", str(out)])
    text = capsys.readouterr().out
    assert "fit: sphere, rigid" in text and "law: rigid" in text
    assert f"radius = {TENNIS.radius} (fixed)" in text
    assert "mass = 1.0 (default (no part in the measured columns))" in text
    got = json.loads(out.read_text())
    mu = got["parameters"]["mu"]
    assert mu["low"] <= 0.55 <= mu["high"] and mu["high"] - mu["low"] < 0.05
    assert got["problem"] == "sphere" and got["law"] is None
    assert got["body"]["gyration"] == TENNIS.gyration


@pytest.mark.slow
def test_walton_from_the_command_line_fits_its_parameter(tmp_path, capsys):
    src = sphere_file(tmp_path)
    main(["fit", "--problem", "sphere", str(src), *BODY, "--tangential", "walton",
          "--fix", "beta0=0.2"])  # fmt: skip
    text = capsys.readouterr().out
    assert "fit: sphere, walton (beta0 = 0.2)" in text and "law: law = walton, beta0 = 0.2" in text


def test_the_toy_problem_is_fitted_from_a_file(tmp_path, capsys, toy):
    rng = np.random.default_rng(2)
    speed = -rng.uniform(1, 5, 12)
    rows = [f"{float(s)!r},{float(-0.6 * s + rng.normal(0, 0.02))!r}" for s in speed]
    src = tmp_path / "toy.csv"
    src.write_text("speed,speed_after\n" + "\n".join(rows) + "\n")
    main(["fit", "--problem", "toy", str(src)])
    text = capsys.readouterr().out
    assert "fit: toy, rigid" in text and "body: none" in text
    row = next(line for line in text.splitlines() if line.strip("│ ").startswith("e "))
    assert float(row.split("│")[2]) == pytest.approx(0.6, abs=0.02)


def test_bad_input_is_one_line_naming_what_is_wrong(tmp_path, capsys):
    src = sphere_file(tmp_path, n=6)
    assert "--problem" in refused(capsys, "--problem", "spheres", str(src))
    assert "a fit needs its body" in refused(capsys, "--problem", "sphere", str(src))
    assert "--restitution" in refused(
        capsys, "--problem", "sphere", str(src), *BODY, "--restitution", "power"
    )
    assert "--fix" in refused(capsys, "--problem", "sphere", str(src), *BODY, "--fix", "mu")
    assert "neither an input" in refused(
        capsys, "--problem", "sphere", str(src), *BODY, "--fix", "kapa=0.7"
    )
    blank = sphere_file(tmp_path, n=6, blank=(2, "vz"))
    err = refused(capsys, "--problem", "sphere", str(blank), *BODY)
    assert "row 5" in err and "vz" in err  # the comment and the header come first
