"""``spinimpact track``: the fit and the prediction from the command line, the files it writes,
and bad input as one line on stderr with exit status 2."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tests.model.track_cases import CONTACT_HEIGHT, shot

EXE = Path(sys.executable).parent / "spinimpact"


def _file(tmp_path, with_flight=True) -> Path:
    """One synthetic shot across the table and, optionally, one that ends in the air."""
    rng = np.random.default_rng(4)
    rows = ["set,trajectory,t,x,y,z"]
    bounce, _ = shot(rng, before=0.15, after=0.1)
    tracks = [("synthetic", 1, bounce)]
    if with_flight:
        air, _ = shot(rng, before=0.3, after=0.0)
        tracks.append(("synthetic", 2, air.select(air.time < 0.2)))
    for name, k, tr in tracks:
        rows += [f"{name},{k},{t:.6f},{p[0]:.6f},{p[1]:.6f},{p[2]:.6f}"
                 for t, p in zip(tr.time, tr.position, strict=True)]  # fmt: skip
    path = tmp_path / "tracks.csv"
    path.write_text("\n".join(rows) + "\n")
    return path


def test_fit_and_predict_write_the_json_and_the_figure(tmp_path):
    path = _file(tmp_path)
    out = subprocess.run(
        [str(EXE), "track", str(path), "--tangential", "rigid", "--fix", "kappa=0.88",
         "--fix", f"contact_height={CONTACT_HEIGHT}", "--sigma", "0.0015", "--predict",
         "--plot", str(tmp_path / "p.png"), "--json-file", str(tmp_path / "p.json")],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert out.returncode == 0, out.stderr
    assert "mu = " in out.stdout and "(95 % profile)" in out.stdout
    assert "contact_height = 0.759 (fixed)" in out.stdout
    assert "track synthetic 2 (tracks.csv): flight" in out.stdout
    assert out.stdout.count("contact at") >= 3  # the fit's shot and two predictions
    assert (tmp_path / "p.png").read_bytes()[:4] == b"\x89PNG"
    d = json.loads((tmp_path / "p.json").read_text())
    assert d["bounce_fit"]["free"] == ["mu"]
    assert 0.15 < d["bounce_fit"]["values"]["mu"] < 0.25  # the truth is 0.2
    assert len(d["flights"]) == 1 and len(d["predictions"]) == 2
    # the gyrospin prior of the predictions is said when a fitted shot determined it
    gyro = [s["spin_components_before"]["gyrospin"] for s in d["bounce_fit"]["shots"]]
    said = "the gyrospin of each incoming fit held near" in out.stdout
    assert said == any("determined" == str(g[-1]) for g in gyro), gyro
    assert not list(tmp_path.glob("*.tmp*"))


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--fix", "kappa"], "write NAME=VALUE"),
        (["--sigma", "-1"], "must be > 0"),
        (["--plot", "x.bmp"], "--plot"),
        (["--predict"], "no track crosses the surface"),
    ],
)  # fmt: skip
def test_bad_options_are_one_line_and_exit_2(cli, tmp_path, args, message):
    path = _file(tmp_path, with_flight=False) if "--predict" not in args else tmp_path / "a.csv"
    if "--predict" in args:
        path.write_text("t,x,y,z\n" + "".join(f"{i / 100},{i / 10},0,1\n" for i in range(8)))
    status, _, err = cli("track", path, "--tangential", "rigid", *args)
    assert status == 2
    assert len(err.strip().splitlines()) == 1, err
    import re

    assert re.search(message, err), err


def test_a_bad_file_names_the_line(cli, tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("t,x,y,z\n0,0,0,1\n0.01,0,0,oops\n")
    status, _, err = cli("track", path)
    assert status == 2
    assert "bad.csv, line 3: column z is not a number" in err
    assert "Traceback" not in err
