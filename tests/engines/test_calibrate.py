"""spinimpact.engines.calibrate: settings searched, measured on held-out incidences, written
as the engine's own configuration (the full measurement: benchmarks/engine_calibrate.py)."""

import json
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body
from spinimpact.engines import calibrate, calibration_cases, configure

from .bodies import SPHERE, needs

#: The time step of the calibrated MuJoCo tests, s: 2e-5 keeps their contacts short to step.
MUJOCO_DT = 2e-5


@pytest.fixture(scope="module")
def mujoco_calibration():
    needs("mujoco")
    return calibrate("mujoco", SPHERE, mu=0.3, kappa=0.8, dt=MUJOCO_DT, n=12, max_evaluations=60)


@pytest.mark.slow
def test_mujoco_calibration_beats_its_start_on_held_out_cases(mujoco_calibration):
    """The search lowers the calibration error, and the settings found do better than the
    start (the damped oscillator) on incidences the search never saw."""
    cal = mujoco_calibration
    errors = cal.errors()
    assert errors["held_out"]["worst"]["median"] < errors["start_held_out"]["worst"]["median"]
    assert cal.held_out.batch_size == cal.calibration.batch_size == 12
    assert not np.array_equal(cal.held_out.exact.before.vx, cal.calibration.exact.before.vx)
    assert cal.version == __import__("mujoco").__version__
    assert cal.settings["timestep"] == MUJOCO_DT  # the time step is never searched
    assert json.loads(json.dumps(cal.to_dict()))["errors"] == errors


@pytest.mark.slow
def test_mjcf_fragment_loads_and_reproduces_the_calibrated_rebounds(mujoco_calibration):
    """The MJCF written, pasted into a model of one ball on a floor, bounces the ball as the
    calibration measured (MuJoCo's solver stops at its tolerance, 1e-8: hence 1e-6)."""
    import mujoco

    cal = mujoco_calibration
    text = cal.mjcf()
    assert f"MuJoCo {mujoco.__version__}" in text.splitlines()[0]
    i = 3
    before = cal.calibration.exact.before[i]
    run = cal.calibration[i]
    radius, mass, inertia = 0.1, 1.0, float(SPHERE.inertia)
    height = radius + abs(float(before.vy)) * (2 + float(run.phase)) * MUJOCO_DT
    xml = (
        f'<mujoco>{text}<option gravity="0 0 0"/><worldbody>'
        '<geom name="floor" type="plane" size="0 0 1" contype="0" conaffinity="0"/>'
        f'<body pos="0 0 {height!r}"><freejoint/><inertial pos="0 0 0" mass="{mass}" '
        f'diaginertia="{inertia!r} {inertia!r} {inertia!r}"/><geom name="ball" type="sphere" '
        f'size="{radius}" contype="0" conaffinity="0"/></body></worldbody>'
        '<contact><pair geom1="ball" geom2="floor"/></contact></mujoco>'
    )
    model = mujoco.MjModel.from_xml_string(xml)
    assert model.opt.timestep == MUJOCO_DT and model.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC
    np.testing.assert_array_equal(model.pair_solref[0], cal.settings["solref"])
    data = mujoco.MjData(model)
    data.qvel[:] = [float(before.vx), 0.0, float(before.vy), 0.0, -float(before.omega), 0.0]
    touched = False
    for _ in range(100_000):
        mujoco.mj_step(model, data)
        touched = touched or data.ncon > 0
        if touched and data.ncon == 0 and data.qvel[2] > 0:
            break
    spin = np.zeros(3)
    mujoco.mju_rotVecQuat(spin, data.qvel[3:], data.qpos[3:])
    got = np.array([data.qvel[0], data.qvel[2], -spin[1] * radius])
    want = np.array([float(run.vx), float(run.vy), float(run.omega) * radius])
    np.testing.assert_allclose(got, want, atol=1e-6 * float(run.scale))


@pytest.mark.slow
def test_pybullet_from_its_defaults_finds_the_exact_settings():
    """From PyBullet's defaults (restitution kappa, lateral friction mu) the search finds
    settings that are exact to rounding on held-out incidences, where the defaults miss by
    tenths of the speed scale, and writes them as calls that set them."""
    needs("pybullet")
    import pybullet as p

    cal = calibrate("pybullet", SPHERE, mu=0.3, kappa=0.8, dt=1 / 240, n=8, max_evaluations=200)
    errors = cal.errors()
    assert errors["start_held_out"]["worst"]["max"] > 0.1
    assert errors["held_out"]["worst"]["max"] < 1e-12  # rounding of the impulse solve
    assert cal.settings["contact_breaking_threshold"] == 0 and cal.settings["contact_erp"] == 0
    source = cal.pybullet_source()
    assert f"PyBullet API {p.getAPIVersion()}" in source.splitlines()[0]
    client = p.connect(p.DIRECT)
    try:
        plane = p.createMultiBody(0, p.createCollisionShape(p.GEOM_PLANE))
        ball = p.createMultiBody(1.0, p.createCollisionShape(p.GEOM_SPHERE, radius=0.1))
        exec(source, {"p": p, "plane": plane, "ball": ball})  # noqa: S102 - text under test
        info = p.getDynamicsInfo(ball, -1)
        assert info[1] == pytest.approx(cal.settings["lateral_friction"], rel=1e-6)
        assert info[5] == pytest.approx(cal.settings["restitution"], rel=1e-6)
        params = p.getPhysicsEngineParameters()
        assert params["fixedTimeStep"] == pytest.approx(1 / 240)
    finally:
        p.disconnect(client)


def test_calibration_cases_are_drawn_in_the_ranges():
    cases = calibration_cases(200, seed=4, radius=0.05)
    assert set(cases) == {"vx", "vy", "omega", "phase"}
    assert np.all((cases["vx"] >= -2) & (cases["vx"] <= 3))
    assert np.all((cases["vy"] >= -3) & (cases["vy"] <= -1))
    assert np.all(np.abs(0.05 * cases["omega"]) <= 3)
    assert np.all((cases["phase"] >= 0) & (cases["phase"] < 1))
    again = calibration_cases(200, seed=4, radius=0.05)
    assert all(np.array_equal(cases[k], again[k]) for k in cases)


def test_configuration_text_names_every_setting():
    needs("mujoco")
    text = configure.mjcf({"solref": (0.01, 0.2), "cone": "elliptic"})
    assert 'solref="0.01 0.2"' in text and 'cone="elliptic"' in text
    assert 'solimp="0.9 0.95 0.001 0.5 2.0"' in text  # MuJoCo's default, filled in


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        ({"engine": "bullet"}, ValueError, "engine must be one of pybullet, mujoco"),
        ({"engine": 3}, TypeError, "engine must be one of"),
        ({"body": "ball"}, TypeError, "body must be a spinimpact.Body"),
        ({"mu": -0.1}, ValueError, "mu"),
        ({"kappa": 1.5}, ValueError, "kappa"),
        ({"kappa": "0.5"}, TypeError, "kappa"),
        ({"dt": 0.0}, ValueError, "dt must be a finite number > 0"),
        ({"dt": None}, TypeError, "dt must be a finite number > 0"),
        ({"max_evaluations": 0}, ValueError, "max_evaluations must be a whole number >= 1"),
        ({"hold": ("stiffness",)}, ValueError, "hold names no pybullet setting searched"),
        ({"hold": "contact_erp"}, TypeError, "hold must be a tuple of setting names"),
        ({"cases": {"vx": 1.0}}, ValueError, "cases lacks omega, phase, vy"),
        ({"cases": [1.0]}, TypeError, "cases must be a mapping"),
        (
            {"cases": {"vx": 1.0, "vy": -1.0, "omega": 0.0, "phase": 1.0}},
            ValueError,
            r"phase must be in \[0, 1\)",
        ),
        ({"cases": {"vx": 1.0, "vy": 1.0, "omega": 0.0, "phase": 0.5}}, ValueError, "vy"),
    ],
)
def test_bad_input_is_named(kwargs, error, message):
    args = {"engine": "pybullet", "body": SPHERE, "mu": 0.3, "kappa": 0.5, "dt": 1 / 240}
    args.update({"n": 2, "max_evaluations": 1, **kwargs})
    engine, body = args.pop("engine"), args.pop("body")
    with pytest.raises(error, match=message):
        calibrate(engine, body, **args)


@pytest.mark.slow
def test_command_writes_the_configuration_and_prints_json(tmp_path):
    needs("pybullet")
    out = tmp_path / "contact.py"
    command = [sys.executable, "-m", "spinimpact", "engines", "calibrate", "pybullet",
               "0.0041666667", "--samples", "4", "--output", str(out), "--json"]  # fmt: skip
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    result = json.loads(done.stdout)
    assert result["engine"] == "pybullet" and result["version"].startswith("API ")
    assert result["cases"] == result["held_out_cases"] == 4
    assert out.read_text().startswith("# PyBullet API ")
    assert [p.name for p in tmp_path.iterdir()] == ["contact.py"]  # no temporary left
    bad = subprocess.run(command[:6] + ["0", "--samples", "4"], capture_output=True, text=True)
    assert bad.returncode == 2
    assert bad.stderr.count("\n") == 1 and "TIMESTEP must be a finite number > 0" in bad.stderr
    lost = [*command[:7], "--output", str(tmp_path / "no such folder" / "x.py")]
    bad = subprocess.run(lost, capture_output=True, text=True)  # refused before the search
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1
    assert "the directory of --output" in bad.stderr and "does not exist" in bad.stderr
    bad = subprocess.run(command[:7] + ["--samples", "0"], capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "--samples" in bad.stderr


def test_a_body_of_many_sizes_is_refused():
    body = Body.solid_sphere(mass=1.0, radius=np.array([0.1, 0.2]))
    with pytest.raises(ValueError, match="body.radius must be a single number"):
        calibrate("pybullet", body, mu=0.3, kappa=0.5, dt=1 / 240)
