"""The registry on the command line: ``spinimpact problems``, ``spinimpact batch --problem``
and ``--set``, and the deprecated ``sphere --batch`` that now runs ``spinimpact batch``."""

import json

SPHERES = "vx,vy,vz,wx,wy,wz\n2,-3,0,0,0,30\n1,-1,1,0,100,0\n"


def test_problems_lists_every_problem_and_each_ones_inputs(cli):
    status, out, err = cli("problems")
    assert status == 0 and err == ""
    for name in ("paper", "planar", "pendulum", "sphere", "pair"):
        assert f" {name} " in out
    status, out, _ = cli("problems", "pair", "--json")
    declared = json.loads(out)
    assert declared["name"] == "pair" and declared["marks"][0] == "vx2"
    inputs = {i["name"]: i for i in declared["inputs"]}
    assert inputs["wz2"]["unit"] == "rad/s" and inputs["wz2"]["vector"] == "spin2"
    assert inputs["kappa"]["default"] == 0.8 and inputs["body2"]["choices"][0] == "solid-sphere"
    assert declared["outputs"]["after2_wx"] == "rad/s" and declared["outputs"]["regime"] is None
    status, _, err = cli("problems", "ball")
    assert status == 2 and err.count("\n") == 1 and "problem must be one of paper" in err


def test_a_registered_problem_is_listed(cli, toy):
    status, out, _ = cli("problems", "toy")
    assert status == 0 and "speed_after" in out and "m/s" in out


def test_batch_problem_and_set_options(cli, tmp_path):
    source = tmp_path / "in.csv"
    source.write_text(SPHERES)
    out = tmp_path / "out.csv"
    sets = ("--set", "normal=0,0.96,0.28", "--set", "body=spherical-shell")
    status, _, err = cli("batch", source, "--output", out, *sets, "--fields", "gyration,normal_y")
    assert status == 0, err
    row = out.read_text().splitlines()[1].split(",")
    assert abs(float(row[-2]) - 0.1 * (2 / 3) ** 0.5) < 1e-15 and float(row[-1]) == 0.96
    for args, message in [
        (("--problem", "pair"), "describe problem 'sphere'"),
        (("--problem", "ball"), "--problem: problem must be one of"),
        (("--set", "spin_rate=1"), "--set spin_rate: problem 'sphere' has no input"),
        (("--set", "normal=0,1"), "default normal must have 3 components"),
        (("--set", "normal_x=1"), "defaults give the normal in part"),
        (("--set", "body=ring"), "default body must be one of solid-sphere, spherical-shell"),
        (("--set", "mu"), "--set takes INPUT=VALUE"),
    ]:
        out.write_text("kept")
        status, _, err = cli("batch", source, "--output", out, *args)
        assert status == 2 and err.count("\n") == 1 and message in err, (args, err)
        assert out.read_text() == "kept"


def test_sphere_batch_is_a_deprecated_alias_of_batch(cli, tmp_path):
    source = tmp_path / "in.csv"
    source.write_text(SPHERES)
    status, _, err = cli("batch", source, "--output", tmp_path / "new.csv")
    assert status == 0, err
    status, out, err = cli("sphere", "--batch", source, "--output", tmp_path / "old.csv")
    assert status == 0 and "wrote 2 rows (spheres)" in out
    assert "'sphere --batch' is deprecated; use 'spinimpact batch" in err
    assert (tmp_path / "old.csv").read_bytes() == (tmp_path / "new.csv").read_bytes()
    status, out, _ = cli("sphere", "--help")
    assert status == 0 and "--batch" not in out and "spinimpact batch" in out
    status, _, err = cli("sphere", "--on-error", "skip")  # without a file: not silently ignored
    assert status == 2 and "--on-error goes with a file of impacts" in err


def test_solve_and_report_one_impact_of_any_problem(cli, tmp_path):
    sets = ("--set", "velocity=2,-3,0", "--set", "spin=0,0,30", "--set", "mu=0.3")
    status, out, err = cli("solve", "--problem", "sphere", *sets, "--json")
    assert status == 0, err
    from spinimpact import Body, solve_sphere

    want = solve_sphere(Body.solid_sphere(mass=1.0, radius=0.1), [2, -3, 0], [0, 0, 30],
                        mu=0.3, kappa=0.8)  # fmt: skip
    assert json.loads(out) == json.loads(json.dumps(want.to_dict()))
    status, out, _ = cli("solve", "--problem", "sphere", *sets)
    assert status == 0 and "after_wz" in out and "rad/s" in out and "default" in out
    page = tmp_path / "one.html"
    status, _, err = cli("report", "--problem", "pair", "--set", "velocity1=1,0,0", "--set",
                         "spin1=0,20,0", "--set", "velocity2=0,0,0", "--set", "spin2=0,0,0",
                         "--set", "normal=-1,0,0", "--output", page)  # fmt: skip
    assert status == 0, err
    assert page.read_text().startswith("<!DOCTYPE html>") and "after2_vx" in page.read_text()
    for args, message in [
        (("--problem", "sphere", "--vx", "2"), "--vx describes the paper's bodies"),
        (("--set", "vx=1"), "--set goes with --problem NAME"),
        (("--problem", "sphere", "--set", "velocity=1,2"), "--set velocity takes 3 numbers"),
        (("--problem", "sphere", "--set", "vx=1"), "velocity of problem 'sphere' is given in part"),
        (("--problem", "sphere", "--set", "velocity=1,-1,0"), "problem 'sphere' needs wx"),
    ]:
        status, _, err = cli("solve", *args)
        assert status == 2 and err.count("\n") == 1 and message in err, (args, err)


def test_a_registered_problem_gets_solve_options(cli, toy):
    status, out, err = cli("solve", "--problem", "toy", "--set", "speed=-2", "--json")
    assert status == 0, err
    assert json.loads(out)["speed_after"] == 1.0  # e's default, 0.5
