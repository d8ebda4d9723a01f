"""Contact laws (spinimpact.model.contact): independence from the simulation,
results in the shared vocabulary, and validation."""

import json
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, ConstantRestitution, TabulatedRestitution
from spinimpact.dynamics import (
    HertzContact,
    HuntCrossleyContact,
    LinearContact,
    NormalImpact,
    simulate,
)
from spinimpact.model.result import Result


@pytest.mark.slow
def test_contact_laws_import_and_run_without_the_simulation():
    """model.contact used to call simulate() (an import cycle); now both use the core
    kernel, so a fresh interpreter that only uses the laws never imports dynamics."""
    code = (
        "import sys\n"
        "import spinimpact.model.contact as c\n"
        "loaded = 'spinimpact.model.dynamics' in sys.modules\n"
        "c.LinearContact(1e6, 40.0).normal_impact(0.05, 3.0)\n"  # a lazy import would show here
        "print(loaded, 'spinimpact.model.dynamics' in sys.modules,"
        " 'spinimpact.dynamics' in sys.modules)"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True
    )
    assert out.stdout.split() == ["False", "False", "False"]


@pytest.mark.parametrize(
    "law",
    [
        LinearContact(stiffness=1e6, damping=40.0),
        HertzContact(youngs_modulus=2e9, poisson_ratio=0.35, radius=0.02, alpha=0.05),
        HuntCrossleyContact(stiffness=1e8, exponent=1.5, alpha=0.2),
    ],
)
def test_normal_impact_is_the_simulated_drop(law):
    """normal_impact and simulate share one integrator: the same numbers, whatever the
    body's radius and inertia (they do not enter the normal motion)."""
    imp = law.normal_impact(0.05, 3.0, rtol=1e-11)
    sim = simulate(Body(mass=0.05, radius=0.03, gyration=0.01), 0.0, -3.0, 0.0, mu=0.0,
                   contact=law, rtol=1e-11)  # fmt: skip
    assert isinstance(imp, NormalImpact) and isinstance(imp, Result) and imp.shape == ()
    assert float(imp.speed) == 3.0
    assert float(imp.restitution) == pytest.approx(sim.newton_restitution, abs=1e-12)
    assert float(imp.duration) == pytest.approx(sim.contact_duration, rel=1e-12)
    assert float(imp.peak_force) == pytest.approx(sim.peak_force, rel=1e-12)
    assert float(imp.max_compression) == pytest.approx(sim.max_compression, rel=1e-12)
    assert law.restitution(0.05, 3.0, rtol=1e-11) == float(imp.restitution)
    d = imp.to_dict()
    assert set(d) == {"speed", "restitution", "duration", "peak_force", "max_compression"}
    assert all(type(v) is float for v in d.values())
    assert set(imp.columns()) == set(NormalImpact.column_names()) == set(d)


def test_laws_describe_themselves_as_plain_values():
    assert LinearContact(1e6, 40.0).to_dict() == {
        "law": "LinearContact",
        "stiffness": 1e6,
        "damping": 40.0,
    }
    assert HuntCrossleyContact(1e8, 2.0, 0.1).to_dict() == {
        "law": "HuntCrossleyContact",
        "stiffness": 1e8,
        "exponent": 2.0,
        "alpha": 0.1,
    }
    hertz = HertzContact(2e9, 0.35, 0.02, alpha=0.05).to_dict()
    assert hertz["law"] == "HertzContact"
    assert (hertz["youngs_modulus"], hertz["poisson_ratio"], hertz["radius"]) == (2e9, 0.35, 0.02)
    # k = 4/3 E* sqrt(R), E* = E/(1 - nu^2) (Hertz 1882)
    assert hertz["stiffness"] == pytest.approx(4 / 3 * 2e9 / (1 - 0.35**2) * 0.02**0.5, rel=1e-15)
    json.dumps(hertz)  # plain values only


def test_parameters_are_stored_as_plain_floats():
    law = HuntCrossleyContact(np.float32(1e8), np.int64(2), np.array(0.1))
    assert all(type(v) is float for v in (law.stiffness, law.exponent, law.alpha))


@pytest.mark.parametrize(
    ("build", "message"),
    [
        (lambda: LinearContact(stiffness=[1e6, 2e6]), "stiffness must be a single number"),
        (lambda: HuntCrossleyContact(1e8, exponent=11.0), r"exponent must be in \[1, 10\]"),
        (lambda: HuntCrossleyContact(1e8, alpha=-0.1), "alpha must be >= 0"),
        (lambda: HertzContact(1e9, 0.3, 0.0), "radius must be > 0"),
        (lambda: LinearContact(1e6).normal_impact(-0.05, 1.0), "mass must be > 0"),
        (lambda: LinearContact(1e6).normal_impact(0.05, 0.0), "speed must be > 0"),
        (lambda: LinearContact(1e6).restitution(0.05, 1.0, rtol=1e-2), r"rtol must be in \["),
        (
            lambda: HuntCrossleyContact.calibrated(stiffness=1e8, kappa=1.5, mass=0.05, speed=1),
            r"kappa must be in \[0, 1\]",
        ),
        (
            lambda: HuntCrossleyContact.calibrated(stiffness=1e8, kappa=0.5, mass=0.05, speed=-1),
            "speed must be > 0",
        ),
        (
            lambda: LinearContact(1e6).restitution_model(0.05, [[1.0, 2.0]]),
            "speeds must be a 1-D array",
        ),
        (lambda: ConstantRestitution([0.5, 0.6]), "kappa must be a single number"),
    ],
)
def test_bad_values(build, message):
    with pytest.raises(ValueError, match=message):
        build()


@pytest.mark.parametrize(
    ("build", "message"),
    [
        (lambda: LinearContact(stiffness=True), "stiffness must be"),
        (lambda: HuntCrossleyContact(1e8, exponent="3/2"), "exponent must be"),
        (lambda: HertzContact("70 GPa", 0.3, 0.02), "youngs_modulus must be"),
        (lambda: LinearContact(1e6).normal_impact(None, 1.0), "mass must be"),
        (lambda: LinearContact.calibrated(stiffness=1e6, kappa="0.5", mass=0.05), "kappa must"),
        (lambda: TabulatedRestitution.from_drop_heights([1.0], [0.5], gravity="g"), "gravity"),
        (lambda: TabulatedRestitution([1.0], [0.5], extrapolate=None), "extrapolate must be"),
        (lambda: ConstantRestitution("0.5"), "kappa must be"),
    ],
)
def test_wrong_types(build, message):
    with pytest.raises(TypeError, match=message):
        build()


def test_drop_heights_need_positive_gravity():
    with pytest.raises(ValueError, match="gravity must be a finite acceleration > 0"):
        TabulatedRestitution.from_drop_heights([1.0], [0.5], gravity=-9.8)
    moon = TabulatedRestitution.from_drop_heights([1.0], [0.25], gravity=1.62)
    assert float(moon.speeds[0]) == pytest.approx((2 * 1.62) ** 0.5, rel=1e-15)


@pytest.mark.parametrize(
    ("mass", "speed", "error", "message"),
    [(-0.05, 3.0, ValueError, "mass must be > 0"), ("a", 3.0, TypeError, "mass must be a real"),
     (0.05, 0.0, ValueError, "speed must be > 0")],
)  # fmt: skip
def test_hertz_duration_names_bad_input(mass, speed, error, message):
    with pytest.raises(error, match=message):
        HertzContact(youngs_modulus=2e9, poisson_ratio=0.3, radius=0.02).duration(mass, speed)


def test_drop_heights_rebound_above_the_drop_is_named():
    from spinimpact import TabulatedRestitution

    with pytest.raises(ValueError, match=r"^rebound_heights must be <= drop_heights"):
        TabulatedRestitution.from_drop_heights([1.0], [2.0])
