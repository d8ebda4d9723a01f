"""The fused one-pass rebound kernel (optional Numba) against the NumPy path."""

import sys

import numpy as np
import pytest

from spinimpact._validation import require
from spinimpact.core import fused, rebound

from tests.cases import random_cases

needs_numba = pytest.mark.skipif(
    not fused.HAVE_NUMBA, reason="the [fast] extra (numba) is not installed"
)


@pytest.fixture(scope="module")
def cases():
    return random_cases(30_000, seed=99)


@needs_numba
def test_array_parameters_bit_identical(cases):
    c = cases
    args = [c[k] for k in ("vx", "vy", "omega", "mass", "radius", "zeta", "mu", "kappa")]
    fast = fused.rebound(*args, fused=True)
    plain = rebound(*args)[:3]
    for a, b in zip(fast, plain, strict=True):
        np.testing.assert_array_equal(a, b)  # same IEEE operations in the same order


@needs_numba
@pytest.mark.parametrize(
    ("zeta", "mu", "kappa"), [(3.5, 0.3, 0.8), (2.0, 0.0, 1.0), (1.2, 1.5, 0.0)]
)
def test_scalar_parameters_bit_identical(cases, zeta, mu, kappa):
    c = cases
    fast = fused.rebound(c["vx"], c["vy"], c["omega"], 2.0, 0.1, zeta, mu, kappa, fused=True)
    plain = rebound(c["vx"], c["vy"], c["omega"], 2.0, 0.1, zeta, mu, kappa)[:3]
    for a, b in zip(fast, plain, strict=True):
        np.testing.assert_array_equal(a, b)


@needs_numba
def test_shapes_and_out(cases):
    vx = cases["vx"][:12].reshape(3, 4)
    out = tuple(np.empty((3, 4)) for _ in range(3))
    got = fused.rebound(vx, -1.0, 0.0, 1.0, 0.1, 3.5, 0.3, 0.8, out=out)
    assert all(g is o for g, o in zip(got, out, strict=True))
    np.testing.assert_array_equal(got[0], rebound(vx, -1.0, 0.0, 1.0, 0.1, 3.5, 0.3, 0.8)[0])
    with pytest.raises(ValueError, match="out must be three"):
        fused.rebound(vx, -1.0, 0.0, 1.0, 0.1, 3.5, 0.3, 0.8, out=out[:2])


def test_fallback_without_numba(monkeypatch, cases):
    monkeypatch.setattr(fused, "HAVE_NUMBA", False)
    monkeypatch.setitem(sys.modules, "numba", None)  # any import of numba now fails
    # a missing optional package is an ImportError naming the extra that installs it,
    # in the words of _validation.require for every extra
    with pytest.raises(ImportError, match=r"needs numba.*pip install 'spinimpact\[fast\]'") as got:
        fused.rebound(1.0, -1.0, 0.0, 1.0, 0.1, 3.5, 0.3, 0.8, fused=True)
    with pytest.raises(ImportError) as want:
        require("numba", "fused=True")
    assert str(got.value) == str(want.value) and got.value.name == want.value.name == "numba"
    got = fused.rebound(cases["vx"], -1.0, 0.0, 1.0, 0.1, 3.5, 0.3, 0.8)  # NumPy path
    np.testing.assert_array_equal(
        got[0], rebound(cases["vx"], -1.0, 0.0, 1.0, 0.1, 3.5, 0.3, 0.8)[0]
    )


@needs_numba
def test_mixed_scalar_and_array_parameters(cases):
    c = cases
    args = (c["vx"], c["vy"], c["omega"], c["mass"], 0.1, c["zeta"], 0.3, 0.8)
    for a, b in zip(fused.rebound(*args, fused=True), rebound(*args)[:3], strict=True):
        np.testing.assert_array_equal(a, b)


@needs_numba
def test_callers_arrays_and_output_dtype():
    n = 50
    mass, radius = np.full(n, 1.0), np.full(n, 0.1)
    x = np.linspace(-1, 1, n)
    fused.rebound(x, -1.0 - x**2, x, mass, radius, 3.5, 0.3, 0.8)
    assert mass.flags.writeable and radius.flags.writeable  # untouched
    out = tuple(np.empty(n, dtype=np.int64) for _ in range(3))
    with pytest.raises(ValueError, match="float64"):
        fused.rebound(x, -1.0, x, 1.0, 0.1, 3.5, 0.3, 0.8, out=out)
