"""`spinimpact sweep --problem NAME`: the problem's inputs as options, from its declaration."""

import json

import numpy as np
import pytest

PAIR = ["--vy", "0", "--vz", "0", "--wx", "0", "--wy", "20", "--wz", "0", "--vx2", "0",
        "--vy2", "0", "--vz2", "0", "--wx2", "0", "--wy2", "0", "--wz2", "0",
        "--normal-x", "-1", "--normal-y", "0", "--normal-z", "0"]  # fmt: skip


def test_a_pair_sweep_on_the_command_line(cli, tmp_path):
    out = tmp_path / "pair/"
    status, stdout, err = cli("sweep", "--problem", "pair", "--vx", "0.5:3:5", *PAIR,
                              "--body2", "spherical-shell", "--output", out)  # fmt: skip
    assert status == 0, err
    assert "5 points (problem pair)" in stdout and "slip " in stdout
    meta = json.loads((out / "metadata.json").read_text())
    assert meta["problem"] == "pair" and meta["fixed"]["body2"] == "spherical-shell"
    assert meta["columns"]["after2_wz"]["unit"] == "rad/s"
    np.testing.assert_array_equal(np.load(out / "vx.npy"), np.linspace(0.5, 3, 5))
    assert (out / "after1_vx.npy").exists() and (out / "regime.npy").exists()


def test_the_options_come_from_the_declaration(cli):
    status, stdout, _ = cli("sweep", "--problem", "pair", "--help")
    assert status == 0
    for option in ("--vx2", "--normal-x", "--body2", "--radius2", "--samples", "--output"):
        assert option in stdout
    assert "\n  --planar " not in stdout and "\n  --omega " not in stdout
    status, stdout, _ = cli("sweep", "--help")
    assert "--problem" in stdout and "--planar" in stdout and "--vx2" not in stdout


def test_a_problem_registered_later_gets_options(cli, toy, tmp_path):
    args = ["--speed", "-3:-1:3", "--e", "0.25", "--fields", "speed_after"]
    status, stdout, err = cli("sweep", "--problem", "toy", *args, "--output", tmp_path / "t.csv")
    assert status == 0, err
    assert "3 points (problem toy)" in stdout
    rows = (tmp_path / "t.csv").read_text().splitlines()
    assert rows[0].split(",") == ["speed", "e", "speed_after"]
    assert [float(r.split(",")[2]) for r in rows[1:]] == [0.75, 0.5, 0.25]


@pytest.mark.parametrize(
    "args, message",
    [
        (["--problem", "nope"], "--problem: problem must be one of paper, planar"),
        (["--problem", "pair", "--vx", "1"], "--problem pair needs --vy, --vz, --wx"),
        (["--problem", "pair", "--vx", "1:2", *PAIR], "'--vx': vx must be a number, START:STOP"),
        (["--problem", "pair", "--vx", "1", "--mu", "-1", *PAIR], "'--mu': mu must be >= 0"),
        (["--problem", "pair", "--vx", "1", "--planar", "rod", *PAIR], "No such option"),
        (["--problem", "pair", "--vx", "1", "--body2", "ring", *PAIR], "'--body2'"),
        (["--problem", "pair", "--vx", "-1:1:3", *PAIR], "cannot be solved at the corner vx = -1"),
    ],
)
def test_bad_input_is_one_line_exit_2(cli, args, message):
    status, stdout, err = cli("sweep", *args)
    assert status == 2 and stdout == ""
    assert message in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err
