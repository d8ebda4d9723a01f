"""The registry of problems: declarations, detection from columns, and a toy problem that
gets every consumer (solve, batch, units) from its declaration alone."""

import numpy as np
import pytest

import spinimpact
from spinimpact import detect, problem, problems, register


def test_the_built_in_problems_are_listed_and_solve_like_their_functions():
    names = ["paper", "planar", "pendulum", "sphere", "pair", "flight", "rigid"]
    assert [p.name for p in problems()] == names
    ball = spinimpact.Body.solid_sphere(mass=1.0, radius=0.1)
    for declared in problems():
        result = declared.solve(**declared.example)
        assert result.shape == (1,)
        assert set(declared.outputs(declared.example)) <= set(result.columns())
    want = spinimpact.solve_sphere(ball, [2.0, -3.0, 0.0], [0.0, 0.0, 30.0], mu=0.2, kappa=0.8)
    got = problem("sphere").solve(**problem("sphere").example)
    for name, column in want.columns().items():
        assert np.array_equal(np.asarray(got.columns()[name])[0], column), name  # bit for bit


def test_every_input_and_result_column_has_a_unit_or_is_text():
    for declared in problems():
        for each in declared.inputs:
            assert (each.unit is None) == each.text, (declared.name, each.name)
        kinds = {n: np.asarray(c).dtype.kind for n, c in declared.solve(**declared.example)
                 .columns().items()}  # fmt: skip
        for name in declared.outputs(declared.example):
            numeric = kinds[name] == "f"
            assert (declared.unit(name) is not None) == numeric, (declared.name, name)


@pytest.mark.parametrize(
    ("header", "name"),
    [
        (["vx", "vy", "omega"], "paper"),
        (["vx", "vy", "omega", "body", "mu"], "paper"),
        (["mass", "inertia", "rx", "ry", "vx", "vy", "omega"], "planar"),
        (["mass", "inertia", "gx", "gy", "px", "py", "omega"], "pendulum"),
        (["vx", "vy", "vz", "wx", "wy", "wz"], "sphere"),
        (["vx", "vy", "vz", "wx", "wy", "wz", "normal_x", "normal_y", "normal_z"], "sphere"),
        ([*"vx vy vz wx wy wz vx2 vy2 vz2 wx2 wy2 wz2".split()], "pair"),
        (["speed", "elevation_deg"], "flight"),
        (["ball", "surface", "speed", "elevation_deg", "topspin_rpm"], "flight"),
        ([*"mass ixx iyy izz rx ry rz vx vy vz wx wy wz".split()], "rigid"),
    ],
)
def test_a_files_columns_name_its_problem(header, name):
    assert detect(header).name == name


def test_columns_of_two_problems_are_refused_by_name():
    with pytest.raises(ValueError, match="column 'inertia' is an input of problem 'planar'"):
        detect(["vx", "vy", "omega", "inertia"])
    with pytest.raises(ValueError, match="column 'omega' is an input of problem"):
        detect(["vx", "vy", "vz", "wx", "wy", "wz", "omega"])
    with pytest.raises(ValueError, match="problem must be one of paper"):
        problem("ball")
    with pytest.raises(TypeError, match="problem must be a name"):
        problem(3)


def test_a_vector_given_in_part_is_refused_naming_the_components():
    sphere = problem("sphere")
    with pytest.raises(ValueError, match="normal of problem 'sphere' is given in part: normal_x"):
        sphere.solve(**sphere.example, normal_x=1.0)
    with pytest.raises(ValueError, match="problem 'sphere' has no input 'omega'"):
        sphere.solve(**sphere.example, omega=1.0)
    with pytest.raises(
        ValueError, match="spin of problem 'sphere' is given in part: wx, wy without"
    ):
        sphere.solve(vx=1.0, vy=-1.0, vz=0.0, wx=0.0, wy=0.0)
    with pytest.raises(ValueError, match="problem 'sphere' needs wx"):
        sphere.solve(vx=1.0, vy=-1.0, vz=0.0)
    with pytest.raises(ValueError, match="mu must be >= 0, got -1.0"):
        sphere.solve(**sphere.example, mu=-1.0)


def test_a_registered_problem_is_listed_detected_and_solved(toy):
    # the toy problem of tests/toy_problem.py, registered by the fixture of tests/conftest.py
    assert problem("toy") is toy and toy in problems()
    assert detect(["speed", "e"]) is toy
    assert toy.solve(speed=[-1.0, -3.0], e=0.25).speed_after.tolist() == [0.25, 0.75]
    assert toy.unit("speed_after") == "m/s" and toy.unit("e") == "1"
    with pytest.raises(ValueError, match="already registered"):
        register(toy)
    with pytest.raises(ValueError, match="e must be in \\[0, 1\\], got 2.0"):
        toy.solve(speed=-1.0, e=2.0)


def test_a_planar_problem_with_a_law_per_row_equals_solve_planar_law_by_law():
    from spinimpact import PlanarBody, solve_planar

    laws = np.array(["newton", "poisson", "energetic", "newton"], dtype=object)
    vx = np.array([0.5, 1.0, -0.3, 2.0])
    planar = problem("planar")
    got = planar.solve(mass=1.0, inertia=1 / 12, rx=0.4, ry=-0.2, vx=vx, vy=-1.0, omega=0.0,
                       mu=0.6, kappa=0.9, law=laws).columns()  # fmt: skip
    for i, law in enumerate(laws):
        one = solve_planar(PlanarBody(1.0, 1 / 12, 0.4, -0.2), vx[i], -1.0, 0.0, mu=0.6,
                           kappa=0.9, law=law).columns()  # fmt: skip
        for name in ("after_vx", "after_omega", "energetic_restitution", "regime"):
            assert np.asarray(got[name])[i] == np.asarray(one[name]).reshape(-1)[0], (law, name)


def test_an_optional_input_left_empty_takes_the_preset_row_by_row():
    sphere = problem("sphere")
    result = sphere.solve(vx=[2.0, 2.0], vy=-3.0, vz=0.0, wx=0.0, wy=0.0, wz=30.0,
                          gyration=[np.nan, 0.05])  # fmt: skip
    assert result.columns()["gyration"].tolist() == [0.1 * np.sqrt(0.4), 0.05]
    with pytest.raises(ValueError, match="gyration must be > 0, got -1.0"):
        sphere.solve(**sphere.example, gyration=[np.nan, -1.0])
