"""core.fused.rebound picks its path by size; every path gives the same bits, warns about
nothing, and fills ``out`` when given one."""

import warnings

import numpy as np
import pytest

from spinimpact.core import fused, rebound

from tests.cases import random_cases

PATHS = [None, False] + ([True] if fused.HAVE_NUMBA else [])


@pytest.fixture(scope="module")
def cases():
    return random_cases(fused.THRESHOLD + 500, seed=140)


def _inputs(c, n):
    return [c[k][:n] for k in ("vx", "vy", "omega", "mass", "radius", "zeta", "mu", "kappa")]


@pytest.mark.parametrize("n", [1, 7, fused.THRESHOLD - 1, fused.THRESHOLD + 500])
@pytest.mark.parametrize("path", PATHS)
def test_every_path_and_size_gives_the_numpy_bits(cases, n, path):
    args = _inputs(cases, n)
    want = rebound(*args)[:3]
    got = fused.rebound(*args, fused=path)
    for g, w in zip(got, want, strict=True):
        assert g.shape == (n,) and g.dtype == np.float64
        assert np.array_equal(g.view(np.uint64), w.view(np.uint64))


@pytest.mark.parametrize("path", PATHS)
@pytest.mark.parametrize(
    "value", [2.0, np.float64(2.0), np.array(2.0), np.array([2.0]), np.array([[2.0]])]
)
def test_one_impact_warns_nothing_and_keeps_its_shape(path, value):
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the FutureWarning on broadcast views, among others
        got = fused.rebound(value, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8, fused=path)
    want = rebound(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8)[:3]
    for g, w in zip(got, want, strict=True):
        assert type(g) is np.ndarray and g.shape == np.shape(value)
        assert g.reshape(()) == w


@pytest.mark.parametrize("path", PATHS)
def test_out_is_filled_on_every_path(path):
    out = tuple(np.full((1,), np.nan) for _ in range(3))
    got = fused.rebound(np.array([2.0]), -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8, fused=path, out=out)
    assert all(g is o for g, o in zip(got, out, strict=True))
    assert not np.isnan(np.concatenate(out)).any()
    with pytest.raises(ValueError, match="out must be three"):
        fused.rebound(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8, fused=path, out=out)


@pytest.mark.skipif(not fused.HAVE_NUMBA, reason="needs the [fast] extra (numba)")
@pytest.mark.parametrize(
    "n, kernel", [(7, "_rebound_serial"), (fused.THRESHOLD, "_rebound_arrays")]
)
def test_small_arrays_run_on_the_calling_thread(cases, monkeypatch, n, kernel):
    """Below THRESHOLD the automatic choice is the serial kernel (no thread pool to wake),
    from there on the parallel one; a counting wrapper sees which ran."""
    calls = []
    real = getattr(fused, kernel)
    monkeypatch.setattr(fused, kernel, lambda *a: calls.append(len(a)) or real(*a))
    fused.rebound(*_inputs(cases, n))
    assert calls == [11]
