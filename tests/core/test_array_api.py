"""The core kernels on other array libraries: the strict array-API reference
implementation (array_api_strict) and Dask arrays give the NumPy numbers."""

import numpy as np
import pytest

import spinimpact.core as core

from tests.cases import random_cases

strict = pytest.importorskip("array_api_strict", reason="array-api-strict is not installed")

NAMES = ("vx", "vy", "omega", "mass", "radius", "zeta", "mu", "kappa")


@pytest.fixture(scope="module")
def case_arrays():
    c = random_cases(3000, seed=17)
    return [c[k] for k in NAMES]


def kernels(args):
    """Every vectorized kernel, on one set of incidence arrays."""
    vx, vy, omega, mass, radius, zeta, mu, kappa = args
    slip = core.slip_velocity(vx, omega, radius)
    tau = 0.5 * core.total_impulse(mass, vy, kappa)
    inertia = mass * radius**2 / (zeta - 1.0)
    ratio = core.incidence_ratio(slip, vy)
    return {
        "rebound": core.rebound(*args),
        "regime": core.regime_code(slip, vy, zeta, mu, kappa),
        "stick_impulse": core.stick_impulse(mass, slip, zeta, mu),
        "impulse_ratio": core.impulse_ratio(slip, vy, zeta, mu, kappa),
        "rebound_slip": core.rebound_slip(slip, vy, zeta, mu, kappa),
        "phase_works": core.phase_works(*args),
        "dissipated": core.dissipated_energy(*args),
        "state_at": core.state_at(tau, vx, vy, omega, mass, radius, zeta, mu),
        "force_ratio_at": core.force_ratio_at(tau, mass, slip, zeta, mu),
        "slip_at": core.slip_at(tau, mass, slip, zeta, mu),
        "energy_at": core.kinetic_energy_at(tau, vx, vy, omega, mass, radius, zeta, mu, inertia),
        "tau_m": core.min_energy_impulse(*args),
        "min_case": core.min_energy_case(*args),
        "work_ratio": core.work_ratio_tangential(ratio, zeta, mu, kappa),
        "bounds": core.work_ratio_tangential_bounds(ratio, zeta, mu, kappa),
        "restitution_work": core.restitution_work(ratio, zeta, mu, kappa),
        "restitution_work_zero": core.restitution_work_zero(zeta, mu, kappa),
        "outcomes": core.rebound_outcomes(vx, vy, omega, radius, zeta, mu, kappa),
        "velocity_ratios": core.velocity_ratios(vx, vy, omega, radius, zeta, mu, kappa),
        "particle": core.particle_rebound(vx, vy, mu, kappa),
        "particle_energy": core.particle_energy_change(vx, vy, mass, mu, kappa),
        "particle_threshold": core.particle_energy_threshold(mu, kappa),
    }


def flatten(value):
    return [np.asarray(v) for v in value] if isinstance(value, tuple) else [np.asarray(value)]


def compare(got, expected):
    for name in expected:
        for a, b in zip(flatten(got[name]), flatten(expected[name]), strict=True):
            # the same IEEE operations: equal to the last bit (NaN where NumPy has NaN)
            np.testing.assert_array_equal(a, b, err_msg=name)


def test_array_api_strict(case_arrays):
    expected = kernels(case_arrays)
    got = kernels([strict.asarray(a) for a in case_arrays])
    for name, value in got.items():
        for v in value if isinstance(value, tuple) else (value,):
            assert type(v).__module__.startswith("array_api_strict"), name  # stayed in the library
    compare(
        {
            k: tuple(np.asarray(x) for x in (v if isinstance(v, tuple) else (v,)))
            for k, v in got.items()
        },
        {k: v if isinstance(v, tuple) else (v,) for k, v in expected.items()},
    )


@pytest.mark.slow
def test_dask_arrays(case_arrays):
    da = pytest.importorskip("dask.array", reason="dask is not installed")
    expected = kernels(case_arrays)
    lazy = kernels([da.from_array(a, chunks=700) for a in case_arrays])
    for name, value in lazy.items():
        for v in value if isinstance(value, tuple) else (value,):
            assert isinstance(v, da.Array), name  # lazy until computed
    # Dask evaluates where() branches later, outside any np.errstate of the kernels:
    # the kernels must not compute a warning branch at all (pytest turns warnings
    # into errors), e.g. velocity_ratios guards its divisors where vx or omega is 0.
    got = {}
    for k, v in lazy.items():
        parts = v if isinstance(v, tuple) else (v,)
        got[k] = tuple(np.asarray(x.compute(scheduler="synchronous")) for x in parts)
    compare(got, {k: v if isinstance(v, tuple) else (v,) for k, v in expected.items()})


def test_scalars_still_give_numpy_scalars():
    assert isinstance(core.work_ratio_tangential(1.0, 3.0, 0.25, 0.5), np.floating)
    assert core.regime_code(1.0, -1.0, 3.0, 0.2, 0.5).dtype == np.int8


@pytest.fixture(scope="module")
def jax():
    jax = pytest.importorskip("jax", reason="jax is not installed (the [jax] extra)")
    before = jax.config.jax_enable_x64
    jax.config.update("jax_enable_x64", True)  # float64, as NumPy computes
    yield jax
    jax.config.update("jax_enable_x64", before)  # other tests see JAX as configured


@pytest.mark.slow
def test_jax_arrays_eager(case_arrays, jax):
    """Op by op (no jit), JAX performs NumPy's IEEE operations: the same bits."""
    jnp = jax.numpy
    expected = kernels(case_arrays)
    got = kernels([jnp.asarray(a) for a in case_arrays])
    for name, value in got.items():
        for v in value if isinstance(value, tuple) else (value,):
            assert isinstance(v, jax.Array), name  # stayed in JAX
    compare(
        {k: tuple(np.asarray(x) for x in flatten(v)) for k, v in got.items()},
        {k: v if isinstance(v, tuple) else (v,) for k, v in expected.items()},
    )


@pytest.mark.slow
def test_jax_jit(case_arrays, jax):
    """Compiled by XLA, which may fuse and reorder operations: equal to rounding."""
    vx, vy, omega, mass, radius, zeta, mu, kappa = case_arrays
    compiled = jax.jit(core.rebound)
    got = compiled(*(jax.numpy.asarray(a) for a in case_arrays))
    expected = core.rebound(*case_arrays)
    scale = np.maximum.reduce([np.abs(vx), np.abs(vy), np.abs(radius * omega)])
    for g, e, s in zip(got, expected, (scale, scale, scale / radius, mass * scale), strict=True):
        np.testing.assert_allclose(np.asarray(g) / s, e / s, rtol=0, atol=1e-13)


@pytest.mark.slow
def test_jax_gradients_are_the_closed_form_derivatives(jax):
    """jax.grad through the kernels: in a sliding impact vx+ = vx - (1+kappa) mu |vy|
    sign(u), so d vx+/d vx = 1 and d vx+/d omega = 0; in a sticking one
    vx+ = vx - u/zeta, so d vx+/d vx = 1 - 1/zeta and d vx+/d omega = -R/zeta."""
    jnp = jax.numpy
    radius, zeta, mu, kappa = 0.1, 3.5, 0.3, 0.8
    vx = jnp.array([3.0, 0.2, -1.0, 2.0])
    vy = jnp.array([-1.0, -2.0, -0.5, -3.0])
    omega = jnp.array([0.0, 5.0, -40.0, -10.0])

    def vx_after(a, b, c):
        return core.rebound(a, b, c, 1.0, radius, zeta, mu, kappa)[0]

    d_vx, d_vy, d_omega = jax.vmap(jax.grad(vx_after, argnums=(0, 1, 2)))(vx, vy, omega)
    regime = np.asarray(
        core.regime_code(core.slip_velocity(vx, omega, radius), vy, zeta, mu, kappa)
    )
    slip = regime == core.REGIMES.index("slip")
    assert slip.any() and (~slip).any()
    u = np.asarray(vx + radius * omega)
    np.testing.assert_allclose(np.asarray(d_vx), np.where(slip, 1.0, 1.0 - 1.0 / zeta))
    np.testing.assert_allclose(np.asarray(d_omega), np.where(slip, 0.0, -radius / zeta), atol=1e-15)
    # d/d vy of -(1+kappa) mu sign(u) |vy| = (1+kappa) mu sign(u); nothing when sticking
    np.testing.assert_allclose(
        np.asarray(d_vy), np.where(slip, (1 + kappa) * mu * np.sign(u), 0.0), atol=1e-15
    )
