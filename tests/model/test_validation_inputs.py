"""Every public numeric parameter goes through the one validation path
(spinimpact._validation), so odd input is refused in the same words everywhere:
a ragged list is a TypeError naming the parameter, a masked element a ValueError
naming the parameter and the first masked index (NumPy alone would silently
compute with the value under the mask), and valid tiny inputs are accepted.
"""

import re
import subprocess
import sys
import warnings

import numpy as np
import numpy.ma as ma
import pytest

import spinimpact as si
from spinimpact.dynamics import HertzContact, HuntCrossleyContact, LinearContact, simulate

BALL = si.Body.solid_sphere(mass=1.0, radius=0.1)
ROD = si.PlanarBody.rod(mass=1.0, length=1.0, angle=0.5)
PENDULUM = si.Pendulum.rod(mass=1.0, length=1.0, angle=0.5)

#: (entry point, its valid keyword arguments); every numeric parameter is probed.
ENTRY_POINTS = {
    "Body": (si.Body, dict(mass=1.0, radius=0.1, gyration=0.05)),
    "Body.solid_sphere": (si.Body.solid_sphere, dict(mass=1.0, radius=0.1)),
    "Body.from_zeta": (si.Body.from_zeta, dict(mass=1.0, radius=0.1, zeta=3.0)),
    "solve": (
        lambda **k: si.solve(BALL, **k),
        dict(vx=1.0, vy=-1.0, omega=0.0, mu=0.3, kappa=0.8),
    ),
    "Impact.history": (
        lambda **k: si.solve(BALL, 1.0, -1.0, 0.0, mu=0.3, kappa=0.8).history(**k),
        dict(tau=0.5),
    ),
    "solve_particle": (si.solve_particle, dict(vx=1.0, vy=-1.0, mu=0.3, kappa=0.8, mass=1.0)),
    "PlanarBody": (si.PlanarBody, dict(mass=1.0, inertia=0.1, rx=0.1, ry=-0.5)),
    "PlanarBody.rod": (si.PlanarBody.rod, dict(mass=1.0, length=1.0, angle=0.5)),
    "PlanarBody.block": (
        si.PlanarBody.block,
        dict(mass=1.0, width=1.0, height=0.5, angle=0.5),
    ),
    "PlanarBody.eccentric_disk": (
        si.PlanarBody.eccentric_disk,
        dict(mass=1.0, radius=0.1, gyration=0.07, offset=0.02, angle=0.5),
    ),
    "solve_planar": (
        lambda **k: si.solve_planar(ROD, **k),
        dict(vx=1.0, vy=-1.0, omega=0.0, mu=0.3, kappa=0.8),
    ),
    "Pendulum.rod": (si.Pendulum.rod, dict(mass=1.0, length=1.0, angle=0.5)),
    "solve_pendulum": (
        lambda **k: si.solve_pendulum(PENDULUM, **k),
        dict(omega=-1.0, mu=0.3, kappa=0.8),
    ),
    "ConstantRestitution": (si.ConstantRestitution, dict(kappa=0.5)),
    "TabulatedRestitution": (
        si.TabulatedRestitution,
        dict(speeds=[1.0, 2.0, 3.0], kappas=[0.8, 0.7, 0.6]),
    ),
    "from_drop_heights": (
        si.TabulatedRestitution.from_drop_heights,
        dict(drop_heights=[1.0, 2.0, 3.0], rebound_heights=[0.5, 0.6, 0.7]),
    ),
    "LinearContact": (LinearContact, dict(stiffness=1e6, damping=1.0)),
    "HuntCrossleyContact": (HuntCrossleyContact, dict(stiffness=1e8, exponent=1.5, alpha=0.1)),
    "HertzContact": (
        HertzContact,
        dict(youngs_modulus=2e9, poisson_ratio=0.35, radius=0.02, alpha=0.1),
    ),
    "restitution_model": (
        LinearContact(1e6, 1.0).restitution_model,
        dict(mass=1.0, speeds=[1.0, 2.0, 3.0]),
    ),
    "simulate": (
        lambda **k: simulate(BALL, **k, contact=LinearContact(1e6)),
        dict(vx=1.0, vy=-1.0, omega=0.0, mu=0.3),
    ),
}
PARAMETERS = [(entry, name) for entry, (_, kw) in ENTRY_POINTS.items() for name in kw]


def _call(entry, name, value):
    function, kwargs = ENTRY_POINTS[entry]
    return function(**(kwargs | {name: value}))


@pytest.mark.parametrize(("entry", "name"), PARAMETERS)
def test_valid_arguments_of_the_probe_are_accepted(entry, name):
    function, kwargs = ENTRY_POINTS[entry]
    function(**kwargs)  # the probe below changes one argument of a valid call


@pytest.mark.parametrize(("entry", "name"), PARAMETERS)
def test_ragged_list_is_a_type_error_naming_the_parameter(entry, name):
    with pytest.raises(TypeError, match=rf"^{name} must be a real number or array of numbers"):
        _call(entry, name, [[1.0, 2.0], [3.0]])


@pytest.mark.parametrize(("entry", "name"), PARAMETERS)
def test_masked_element_is_refused_by_name(entry, name):
    # the value under the mask is valid for every parameter, so only the mask can refuse it
    good = np.asarray(ENTRY_POINTS[entry][1][name], dtype=float)
    value = ma.array(np.broadcast_to(good, (3,)), mask=[False, True, False])
    with pytest.raises(ValueError, match=rf"^{name} must not have masked \(missing\) elements "
                       r"\(first masked index 1\)"):  # fmt: skip
        _call(entry, name, value)


@pytest.mark.parametrize(
    ("value", "where"),
    [
        (ma.masked, ""),
        (ma.array(0.5, mask=True), ""),
        ([0.5, ma.masked], " (first masked index 1)"),
        ([ma.array([0.5, 0.6], mask=[0, 1])], " (first masked index (0, 1))"),
        (ma.array([[0.5, 0.6], [0.7, 0.8]], mask=[[0, 0], [1, 0]]), " (first masked index (1, 0))"),
    ],
)
def test_masked_values_in_any_form_are_refused(value, where):
    message = f"mu must not have masked (missing) elements{where}:"
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no "converting a masked element to nan" on the way
        with pytest.raises(ValueError, match=re.escape(message)):
            si.solve(BALL, 1.0, -1.0, 0.0, mu=value, kappa=0.5)


def test_the_issue_case_masked_velocity_is_not_computed():
    # the issue's case: the masked 1e6 was computed and a plain array returned
    with pytest.raises(ValueError, match=r"vx must not have masked.*index 1.*filled.*compressed"):
        si.solve(BALL, ma.array([3.0, 1e6], mask=[0, 1]), -1.0, 0.0, mu=0.3, kappa=0.8)


def test_masked_array_with_nothing_masked_is_its_data():
    vx = ma.array([1.0, 2.0], mask=[False, False])
    imp = si.solve(BALL, vx, -1.0, 0.0, mu=0.3, kappa=0.8)
    plain = si.solve(BALL, [1.0, 2.0], -1.0, 0.0, mu=0.3, kappa=0.8)
    np.testing.assert_array_equal(imp.after.vx, plain.after.vx)


def test_a_restitution_model_returning_masked_values_is_refused():
    with pytest.raises(ValueError, match=r"kappa \(from .*\) must not have masked"):
        si.solve(BALL, 1.0, [-1.0, -2.0], 0.0, mu=0.3,
                 kappa=lambda v: ma.array(np.full(v.shape, 0.5), mask=[0, 1]))  # fmt: skip


@pytest.mark.parametrize("preset", list(si.model.body.PRESETS))
@pytest.mark.parametrize("radius", [1e-50, 1e50])
def test_presets_accept_every_radius_in_range(preset, radius):
    """The issue: Body.solid_sphere(mass=1, radius=1e-50) said "gyration must be >= 1e-50",
    a number the user never gave. Every radius in [1e-50, 1e50] makes every preset."""
    body = si.Body.preset(preset, mass=1.0, radius=radius)
    assert body.radius == radius and body.zeta == 1.0 + 1.0 / si.model.body.PRESETS[preset]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with np.errstate(over="raise", divide="raise", invalid="raise"):
            imp = si.solve(body, 1.0, -1.0, 1.0 / radius, mu=0.3, kappa=0.5)
    assert np.isfinite(imp.after.vx) and np.isfinite(imp.dissipated_energy)


def test_from_zeta_at_the_smallest_radius_and_largest_zeta():
    body = si.Body.from_zeta(mass=1.0, radius=1e-50, zeta=1e20)
    assert body.gyration == pytest.approx(1e-60, rel=1e-12)
    # below what any valid radius and zeta give, the limit is named with its value
    with pytest.raises(ValueError, match=r"gyration must be >= 1e-60, got 1e-61"):
        si.Body(mass=1.0, radius=1e-50, gyration=1e-61)


@pytest.mark.slow
def test_tiny_friction_is_accepted_by_the_command_line():
    """The issue: ``spinimpact solve --mu 1e-310`` failed with "overflow encountered in
    scalar divide" from the particle comparison's energy threshold."""
    out = subprocess.run(
        [sys.executable, "-m", "spinimpact", "solve", "--mu", "1e-310"],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert out.returncode == 0, out.stderr
    assert "overflow" not in out.stdout + out.stderr
    assert "particle (eq. 8.7)" in out.stdout  # the comparison that overflowed is printed


def test_particle_threshold_below_the_float_range_is_minus_infinity():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with np.errstate(over="raise", divide="raise", invalid="raise"):
            p = si.solve_particle(1.0, -1.0, mu=[1e-310, 0.0, 1e-300], kappa=0.8)
    # [(1+k) mu^2 + k - 1]/(2 mu) = -0.1/mu: below -1.8e308 it is -inf, as at mu = 0
    assert p.energy_threshold[0] == -np.inf and p.energy_threshold[1] == -np.inf
    assert p.energy_threshold[2] == pytest.approx(-0.1 / 1e-300, rel=1e-12)


@pytest.mark.parametrize(
    ("gravity", "error"),
    [(-9.8, ValueError), (0.0, ValueError), (np.array([9.8, 9.8]), TypeError),
     ([9.8], TypeError), ("9.8", TypeError), (ma.masked, TypeError), (np.nan, ValueError)],
)  # fmt: skip
def test_gravity_is_validated_under_its_own_name(gravity, error):
    """The issue: an array gravity was accepted and -9.8 was blamed on ``speeds``."""
    with pytest.raises(error, match=r"^gravity must be a finite acceleration > 0 \(m/s\^2\)"):
        si.TabulatedRestitution.from_drop_heights([1.0, 2.0], [0.5, 1.0], gravity=gravity)


@pytest.mark.parametrize(
    "model",
    [si.ConstantRestitution(0.5), si.TabulatedRestitution([1.0, 3.0], [0.9, 0.7])],
    ids=["constant", "tabulated"],
)
def test_restitution_models_called_directly_refuse_masked_speeds(model):
    with pytest.raises(ValueError, match=r"^speed must not have masked .*index 1"):
        model(ma.array([2.0, 1e6], mask=[False, True]))
    with pytest.raises(TypeError, match=r"^speed must be a real number"):
        model("fast")
    np.testing.assert_array_equal(model(np.array([2.0, 2.0])), model(2.0) * np.ones(2))
