"""spinimpact sphere --tangential walton|stronge: the report and JSON of
solve_sphere(..., tangential=law), and one-line errors (exit 2)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from spinimpact import Body, Stronge, Surface, Walton, solve_sphere
from spinimpact.cli import main

from .test_errors import assert_one_line, run_main

BALL = ("--mass", "0.057", "--radius", "0.033")
INCIDENCE = ("--velocity", "1,-3,0.5", "--spin", "0,40,-20", "--mu", "0.3", "--kappa", "0.8")
BODY = Body.solid_sphere(mass=0.057, radius=0.033)


def _rows(text: str) -> dict[str, list[float]]:
    """The report's rows whose values are numbers, by their label."""
    rows = {}
    for line in text.splitlines():
        key, _, value = line.partition("  ")
        try:
            rows[key.strip()] = [float(x) for x in value.split(",")]
        except ValueError:
            continue
    return rows


@pytest.mark.parametrize(
    ("args", "law"),
    [
        (("--tangential", "walton", "--beta0", "0.3"), Walton(0.3)),
        (("--tangential", "stronge", "--poisson-ratio", "0.3"), Stronge(poisson_ratio=0.3)),
        (("--tangential", "stronge", "--stiffness-ratio", "0.5"), Stronge(stiffness_ratio=0.5)),
    ],
)
def test_report_is_solve_sphere_with_the_law(capsys, args, law):
    main(["sphere", *BALL, *INCIDENCE, *args])
    out = capsys.readouterr().out
    imp = solve_sphere(BODY, [1, -3, 0.5], [0, 40, -20], mu=0.3, kappa=0.8, tangential=law)
    rows = _rows(out)
    lines = out.splitlines()
    assert lines[0].split() == ["law", repr(law)]
    assert lines[1].split() == ["regime", str(imp.regime)]
    np.testing.assert_allclose(rows["after velocity (m/s)"], imp.after.velocity, rtol=1e-5)
    np.testing.assert_allclose(rows["after spin (rad/s)"], imp.after.spin, rtol=1e-5)
    beta = rows["beta = -|c_t+|/|c_t-| (signed)"][0]
    assert beta == pytest.approx(float(imp.tangential_restitution), rel=1e-5)
    rigid = solve_sphere(BODY, [1, -3, 0.5], [0, 40, -20], mu=0.3, kappa=0.8)
    assert not np.allclose(rows["after spin (rad/s)"], rigid.after.spin, rtol=1e-3)


def test_json_has_the_law_and_every_field(capsys):
    args = ("--tangential", "walton", "--beta0", "-0.2", "--normal", "0,1,0.2")
    main(["sphere", *BALL, *INCIDENCE, *args, "--json"])
    data = json.loads(capsys.readouterr().out)
    imp = solve_sphere(BODY, [1, -3, 0.5], [0, 40, -20], mu=0.3, kappa=0.8,
                       tangential=Walton(-0.2), surface=Surface(normal=(0, 1, 0.2)))  # fmt: skip
    assert data["law"] == {"law": "walton", "beta0": -0.2}
    assert data["regime"] == str(imp.regime)
    after = [data["after"][k] for k in ("vx", "vy", "vz", "wx", "wy", "wz")]
    np.testing.assert_allclose(after, [*imp.after.velocity, *imp.after.spin], rtol=1e-12)


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (("--tangential", "walton"), "--tangential walton needs --beta0"),
        (("--beta0", "0.3"), "--beta0 applies to --tangential walton only"),
        (("--tangential", "walton", "--beta0", "2"), "beta0 must be in [-1, 1], got 2.0"),
        (("--tangential", "stronge"), "needs exactly one of --poisson-ratio and --stiffness-ratio"),
        (("--tangential", "walton", "--beta0", "0.3", "--poisson-ratio", "0.3"),
         "--poisson-ratio applies to --tangential stronge and mindlin-deresiewicz only"),
        (("--tangential", "stronge", "--poisson-ratio", "0.6"), "poisson_ratio must be in"),
        (("--tangential", "walton", "--beta0", "0.3", "--plot", "x.png"),
         "--plot takes the rigid law only, not --tangential walton"),
        (("--tangential", "walton", "--beta0", "0.3", "--html", "x.html"),
         "--html takes the rigid law only"),
        (("--tangential", "stronge", "--stiffness-ratio", "1", "--batch", "a.csv", "--output",
          "b.csv"), "--batch takes the rigid law only, not --tangential stronge"),
    ],
)  # fmt: skip
def test_bad_options_are_one_line_errors(capsys, tmp_path, monkeypatch, args, needle):
    monkeypatch.chdir(tmp_path)
    assert_one_line(*run_main(capsys, "sphere", *args), needle)
    assert list(tmp_path.iterdir()) == []  # nothing written
