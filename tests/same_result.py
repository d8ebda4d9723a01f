"""Helpers for the fast paths' tests: a solver's array path, and results compared field by
field, bit for bit."""

import numpy as np


def array_path(monkeypatch, module, hook, solver, *args, **kwargs):
    """``solver(*args, **kwargs)`` with the fast path ``module.hook`` switched off."""
    with monkeypatch.context() as m:
        m.setattr(module, hook, lambda *a: None)
        return solver(*args, **kwargs)


def _bits_equal(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype != np.float64:
        return np.array_equal(a, b)
    nan = np.isnan(a) & np.isnan(b)  # a NaN is a NaN, whatever its payload
    return np.array_equal(
        np.where(nan, 0.0, a).view(np.uint64), np.where(nan, 0.0, b).view(np.uint64)
    )


def assert_same(fast, slow):
    """The same result class; every field of the same type (and for arrays the same dtype,
    shape and read-only flag) holding the same bits (signed zeros included; NaN equals NaN)."""
    assert type(fast) is type(slow)
    for (name, a), (_, b) in zip(fast._items(), slow._items(), strict=True):
        if name in ("body", "ball1", "ball2"):
            assert a is b
        elif hasattr(a, "_items"):
            assert_same(a, b)
        elif isinstance(a, np.ndarray):
            assert type(b) is np.ndarray, name
            assert (a.dtype, a.shape, a.flags.writeable) == (b.dtype, b.shape, b.flags.writeable)
            assert _bits_equal(a, b), name
        else:
            assert type(a) is type(b), (name, type(a), type(b))
            assert _bits_equal(a, b) if isinstance(a, np.floating) else a == b, (name, a, b)
