"""Text fields of one impact (the regime, the case of the minimum energy) are plain Python
strings, so the REPL shows ``'slip'`` and not ``np.str_('slip')``; arrays of impacts keep
NumPy string arrays, and the text is a column like any other."""

import dataclasses

import numpy as np
import pytest

from spinimpact import (
    Body,
    PlanarBody,
    Walton,
    solve,
    solve_pair,
    solve_particle,
    solve_planar,
    solve_sphere,
)

BALL = Body.solid_sphere(mass=1.0, radius=0.1)
ROD = PlanarBody.rod(mass=1.0, length=1.0, angle=0.5)

ONE = {
    "solve": lambda: solve(BALL, 1.0, -1.0, 0.0, mu=0.2, kappa=0.5),
    "solve, 0-d arrays": lambda: solve(
        BALL, np.array(1.0), np.array(-1.0), 0.0, mu=0.2, kappa=0.5
    ),  # fmt: skip
    "solve, tangential": lambda: solve(
        BALL, 1.0, -1.0, 0.0, mu=0.2, kappa=0.5, tangential=Walton(0.3)
    ),  # fmt: skip
    "solve_sphere": lambda: solve_sphere(BALL, [1.0, -1.0, 0.0], [0, 0, 0], mu=0.2, kappa=0.5),
    "solve_pair": lambda: solve_pair(
        BALL,
        BALL,
        velocity1=[0, 0, -1.0],
        spin1=[0, 0, 0],
        velocity2=[0, 0, 0],
        spin2=[0, 0, 0],
        normal=[0, 0, 1],
        mu=0.1,
        kappa=0.9,
    ),  # fmt: skip
    "solve_planar": lambda: solve_planar(ROD, 1.0, -1.0, 0.0, mu=0.2, kappa=0.5),
    "solve_particle": lambda: solve_particle(1.0, -1.0, mu=0.2, kappa=0.5, mass=1.0),
    "one of many": lambda: solve(BALL, [1.0, 2.0], -1.0, 0.0, mu=0.2, kappa=0.5)[1],
}


def _texts(result):
    """Every text field of ``result`` and of the results nested in it."""
    for f in dataclasses.fields(result):
        value = getattr(result, f.name)
        if dataclasses.is_dataclass(value) and hasattr(value, "columns"):
            yield from _texts(value)
        elif isinstance(value, str) and f.name != "name":
            yield f.name, value


@pytest.mark.parametrize("name", ONE)
def test_one_impacts_text_is_a_plain_str(name):
    imp = ONE[name]()
    texts = dict(_texts(imp))
    assert "regime" in texts or name == "solve_particle"  # a particle has no regime
    for field, value in texts.items():
        assert type(value) is str, field
        assert repr(value) == repr(str(value))  # 'slip', not np.str_('slip')
        assert imp.to_dict()[field] == value
    if "regime" in texts:
        assert imp.columns()["regime"].shape == ()


def test_the_regime_of_one_impact_is_a_column():
    imp = ONE["solve"]()
    column = imp.columns()["regime"]
    assert column.shape == () and column.dtype.kind == "U" and column[()] == imp.regime


def test_arrays_of_impacts_keep_numpy_text():
    many = solve(BALL, [1.0, 2.0], -1.0, 0.0, mu=0.2, kappa=0.5)
    assert isinstance(many.regime, np.ndarray) and many.regime.dtype.kind == "U"
    one = solve(BALL, [1.0], -1.0, 0.0, mu=0.2, kappa=0.5)  # one-element input: an array
    assert isinstance(one.regime, np.ndarray) and one.regime.shape == (1,)
