"""Edges: exact regime boundaries, extreme magnitudes, immutability, CLI without arguments."""

import re
import subprocess
import sys
import warnings

import numpy as np
import pytest

from spinimpact import Body, solve

STICK = ("no-slip", "stick-compression", "stick-restitution")


def test_every_result_agrees_on_stick_or_slip_at_exact_boundaries():
    """Sample |u| = (1+kappa) zeta mu |vy| to the last bit, where rounding decides."""
    rng = np.random.default_rng(11)
    n = 50_000
    mass = 10 ** rng.uniform(-3, 3, n)
    radius = rng.uniform(0.01, 1, n)
    zeta = rng.choice([2.0, 2.5, 3.0, 3.5, 1.3], n)
    mu, kappa, vy = rng.uniform(0.05, 1, n), rng.uniform(0, 1, n), -rng.uniform(0.1, 10, n)
    edge = np.where(rng.random(n) < 0.5, 1 + kappa, 1.0) * zeta * mu * np.abs(vy)
    edge = edge * (1 + rng.integers(-2, 3, n) * np.finfo(float).eps)
    vx = rng.normal(0, 2, n)
    omega = (rng.choice([-1, 1], n) * edge - vx) / radius
    body = Body.from_zeta(mass=mass, radius=radius, zeta=zeta)
    imp = solve(body, vx, vy, omega, mu=mu, kappa=kappa)
    stuck = np.isin(imp.regime, STICK)
    assert np.array_equal(stuck, imp.slip_after == 0)
    assert np.array_equal(stuck, imp.outcome.rolling)
    compression = np.isin(imp.regime, STICK[:2])
    assert np.array_equal(compression, imp.min_energy_case == "rolling (Fig. 5b)")
    assert np.all(
        (imp.min_energy_case == "sliding, then stick (Fig. 5a)") == (imp.regime == STICK[2])
    )


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        (dict(vy=-1e-200), ValueError, "vy must be <= -1e-50"),
        (dict(vx=1e160), ValueError, "vx must be at most 1e+50 in magnitude"),
        (dict(mu=1e300), ValueError, "mu must be at most 1e+50"),
        # a value of the wrong type is a TypeError, a bad number a ValueError
        (dict(vx=True), TypeError, "vx must be a real number"),
        (dict(vx="3"), TypeError, "vx must be a real number"),
        (dict(omega=None), TypeError, "omega must be a real number"),
        (dict(vx=np.array([1 + 2j])), TypeError, "vx must be a real number"),
        (dict(vx=[[1.0], [1.0, 2.0]]), TypeError, "vx must be a real number"),
    ],
)
def test_extreme_or_odd_inputs_are_rejected_by_name(kwargs, error, message):
    args = dict(vx=1.0, vy=-1.0, omega=0.0, mu=0.3, kappa=0.5) | kwargs
    body = Body.solid_disk(mass=1.0, radius=0.1)
    with pytest.raises(error, match=re.escape(message)):
        solve(body, args.pop("vx"), args.pop("vy"), args.pop("omega"), **args)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(mass=1.0, radius=1.0, gyration=1e-200), "gyration must be >= 1e-60"),
        (dict(mass=1e300, radius=1.0, gyration=1.0), "mass must be at most 1e"),
        (dict(mass=1.0, radius=1e-9, gyration=1.0), "zeta = 1 \\+ \\(radius/gyration\\)"),
    ],
)
def test_body_limits(kwargs, message):
    with pytest.raises(ValueError, match=message):
        Body(**kwargs)


def test_extreme_but_valid_inputs_give_finite_results_without_warnings():
    body = Body(mass=[1e-50, 1e50, 1.0], radius=[1e-50, 1e50, 1e-7], gyration=[1e-50, 1e50, 1.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with np.errstate(over="raise", divide="raise", invalid="raise"):  # underflow is benign
            imp = solve(
                body,
                [1e50, -1e-50, 0.0],
                [-1e-50, -1e50, -1.0],
                [1e50, 0.0, 1e-50],
                mu=[1e-300, 1e6, 0.5],
                kappa=[0.0, 1.0, 0.5],
            )
    for value in (imp.after.vx, imp.after.omega, imp.dissipated_energy, imp.min_kinetic_energy):
        assert np.all(np.isfinite(value))
    assert np.all(imp.min_kinetic_energy >= 0) and np.all(imp.dissipated_energy >= 0)


def test_inputs_are_copied_and_results_are_read_only():
    mass = np.array([1.0, 2.0])
    vx = np.array([1.0, 2.0])
    body = Body(mass=mass, radius=0.1, gyration=0.05)
    imp = solve(body, vx, -1.0, 0.0, mu=0.2, kappa=0.5)
    mass[1], vx[0] = -5.0, 99.0
    assert body.mass[1] == 2.0 and imp.before.vx[0] == 1.0
    with pytest.raises(ValueError, match="read-only"):
        imp.after.vx[0] = 0.0
    with pytest.raises(TypeError):
        Body(mass=1.0, radius=1.0, gyration=1.0, _zeta=7.0)


def test_len_and_iteration():
    imp = solve(Body.ring(mass=1.0, radius=0.1), [1.0, 2.0, 3.0], -1.0, 0.0, mu=0.2, kappa=0.5)
    assert len(imp) == 3
    assert [float(i.before.vx) for i in imp] == [1.0, 2.0, 3.0]
    with pytest.raises(TypeError, match="single impact"):
        len(imp[0])


@pytest.mark.slow
def test_cli_without_arguments_prints_help_and_succeeds():
    out = subprocess.run(
        [sys.executable, "-m", "spinimpact"], capture_output=True, text=True, timeout=60
    )
    assert out.returncode == 0
    assert "Usage:" in out.stdout and "solve" in out.stdout and out.stderr == ""


@pytest.mark.parametrize("name", [None, 5, b"ring", ["ring"]])
def test_body_name_must_be_a_string(name):
    """A name that is not text would reach the reports (HTML, Rich, figure titles)."""
    with pytest.raises(TypeError, match="name must be a str"):
        Body(mass=1.0, radius=0.1, gyration=0.05, name=name)
    assert Body(mass=1.0, radius=0.1, gyration=0.05, name=np.str_("spool")).name == "spool"


def test_results_print_plain_python_numbers():
    """No ``np.float64(...)`` or ``np.False_`` in what a user sees at the prompt."""
    from spinimpact import solve_particle

    imp = solve(Body.ring(mass=1.0, radius=0.1), 1.0, -2.0, 0.0, mu=0.2, kappa=0.5)
    particle = solve_particle(1.0, -2.0, mu=0.2, kappa=0.5)
    for obj in (imp.outcome, imp.before, imp.after, particle, particle.after):
        text = repr(obj)
        assert "np." not in text and "float64" not in text, text
    assert repr(imp.outcome) == (
        "Outcome(backward=False, reversed_spin=False, vertical=False, spinning=True, rolling=True)"
    )
    assert repr(particle.before) == "State(vx=1.0, vy=-2.0, omega=0.0)"
    assert repr(particle).startswith("ParticleImpact(mass=1.0, mu=0.2, kappa=0.5, before=State(")
    assert "creates_energy=False" in repr(particle)
    many = solve(Body.ring(mass=1.0, radius=0.1), [1.0, 2.0], -2.0, 0.0, mu=0.2, kappa=0.5)
    assert (
        repr(many.before)
        == "State(vx=array([1., 2.]), vy=array([-2., -2.]), omega=array([0., 0.]))"
    )
