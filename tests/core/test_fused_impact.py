"""The fused all-field kernel against the NumPy kernels, field by field."""

import sys

import numpy as np
import pytest

from spinimpact import core
from spinimpact._validation import require
from spinimpact.core import fused_impact

from tests.cases import random_cases

needs_numba = pytest.mark.skipif(
    not fused_impact.HAVE_NUMBA, reason="the [fast] extra (numba) is not installed"
)


def _numpy_fields(vx, vy, omega, mass, radius, gyration, zeta, mu, kappa):
    """A few fields straight from the NumPy kernels (the rest: tests/model)."""
    inc = (vx, vy, omega, mass, radius, zeta, mu, kappa)
    slip = core.slip_velocity(vx, omega, radius)
    vx1, vy1, om1, f1 = core.rebound(*inc)
    wcn, wct, wrn, wrt = core.phase_works(*inc)
    tau_m = core.min_energy_impulse(*inc)
    return dict(
        after_vx=vx1, after_vy=vy1, after_omega=om1, tangential_impulse=f1,
        tau_star=core.stick_impulse(mass, slip, zeta, mu),
        work_compression_tangential=wct, work_restitution_tangential=wrt,
        dissipated_energy=core.dissipated_energy(*inc), tau_min_energy=tau_m,
        min_kinetic_energy=core.kinetic_energy_at(tau_m, *inc[:-1], mass * gyration**2),
        regime=np.asarray(core.REGIMES)[core.regime_code(slip, vy, zeta, mu, kappa)],
        min_energy_case=np.asarray(core.MIN_ENERGY_CASES)[core.min_energy_case(*inc)],
        rolling=core.rebound_outcomes(vx, vy, omega, radius, zeta, mu, kappa).rolling,
    )  # fmt: skip


@needs_numba
def test_fields_bit_identical_to_the_numpy_kernels():
    c = random_cases(5_000, seed=21)
    args = [c[k] for k in fused_impact.INPUTS]
    got = fused_impact.impact_fields(*args)
    for name, want in _numpy_fields(*args).items():
        have = getattr(got, name)
        assert have.dtype == want.dtype, name
        if have.dtype.kind == "f":
            np.testing.assert_array_equal(have.view(np.int64), want.view(np.int64), name)
        else:
            np.testing.assert_array_equal(have, want, name)
    assert set(got._fields) == set(fused_impact.FLOATS) | {
        "regime", "min_energy_case", "backward", "reversed_spin", "vertical", "spinning",
        "rolling"}  # fmt: skip


@needs_numba
def test_scalars_broadcast_and_shape():
    c = random_cases(60, seed=2)
    vx = c["vx"].reshape(3, 4, 5)
    got = fused_impact.impact_fields(vx, -1.5, 0.0, 1.0, 0.1, 0.1 / np.sqrt(2.5), 3.5, 0.3, 0.8)
    assert all(np.shape(a) == (3, 4, 5) for a in got)
    want = _numpy_fields(vx, -1.5, 0.0, 1.0, 0.1, 0.1 / np.sqrt(2.5), 3.5, 0.3, 0.8)
    np.testing.assert_array_equal(got.after_vx, want["after_vx"])
    np.testing.assert_array_equal(got.regime, want["regime"])


def test_without_numba_names_the_extra(monkeypatch):
    monkeypatch.setattr(fused_impact, "HAVE_NUMBA", False)
    monkeypatch.setitem(sys.modules, "numba", None)
    with pytest.raises(ImportError) as got:
        fused_impact.impact_fields(1.0, -1.0, 0.0, 1.0, 0.1, 0.05, 5.0, 0.3, 0.8)
    with pytest.raises(ImportError) as want:
        require("numba", "the fused all-field kernel")
    assert str(got.value) == str(want.value)
