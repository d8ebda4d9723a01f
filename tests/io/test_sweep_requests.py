"""What a sweep is asked for: the histogram's four parts, the fields (one name or many) and
a grid's number of points are checked before anything is computed, with messages that name
the part, the value and the rule."""

import numpy as np
import pytest

from spinimpact import Body
from spinimpact.io.sweep import Sweep, estimate_sweep, parse_axis, run_sweep

BODY = Body.solid_sphere(mass=1.0, radius=0.1)


def make(**spec):
    axes = dict(vx="-2:2:5", vy="-1", omega="0", mu="0.5", kappa="0.8") | spec
    return Sweep(BODY, {k: parse_axis(k, v) for k, v in axes.items()})


@pytest.mark.parametrize("bins, error", [
    (2.7, TypeError), (4.0, TypeError), ("4", TypeError), (True, TypeError), (0, ValueError),
    (10**9, ValueError),
])  # fmt: skip
def test_histogram_bins_must_be_a_whole_number(bins, error):
    """2.7 bins used to become 2 without a word."""
    for call in (run_sweep, estimate_sweep):
        with pytest.raises(error, match="histogram's bins must be an integer") as err:
            call(make(), histogram=("energy_loss", 0, 1, bins))
        assert repr(bins) in str(err.value)


@pytest.mark.parametrize("histogram, error, words", [
    (("energy_loss", 0, 1), ValueError, "histogram must be (field, low, high, bins)"),
    ("energy_loss", TypeError, "histogram must be (field, low, high, bins)"),
    (("energy_loss", "a", 1, 3), TypeError, "histogram's low must be a real number, got 'a'"),
    (("energy_loss", 0, None, 3), TypeError, "histogram's high must be a real number"),
    (("energy_loss", 1, 0, 3), ValueError, "histogram's low must be < high, got 1 and 0"),
    (("energy_loss", 0, np.inf, 3), ValueError, "histogram's high must be finite, got inf"),
    ((3, 0, 1, 3), TypeError, "histogram's field must be a field's name, got 3"),
])  # fmt: skip
def test_histogram_parts_are_named(histogram, error, words):
    with pytest.raises(error) as err:
        run_sweep(make(), histogram=histogram)
    assert words in str(err.value)


def test_integral_numpy_bins_are_a_whole_number():
    result = run_sweep(make(), histogram=("energy_loss", 0, 1, np.int64(4)))
    assert result.histogram.tolist() == [0, 5, 0, 0]


def test_one_field_may_be_given_as_a_string(tmp_path):
    """fields="regime" is the field regime (it used to be read letter by letter)."""
    target = tmp_path / "sweep"
    run_sweep(make(), output=target, fields="regime")
    assert sorted(p.name for p in target.iterdir()) == sorted(
        ["metadata.json", "regime.npy", "vx.npy", "vy.npy", "omega.npy", "mu.npy", "kappa.npy"]
    )
    with pytest.raises(ValueError, match="fields must be among.*got 'regim'"):
        run_sweep(make(), output=tmp_path / "other", fields="regim")


@pytest.mark.parametrize("fields", [None, 5, ("regime", 5)])
def test_fields_that_are_not_names_are_refused(fields):
    with pytest.raises(TypeError, match="fields must be a field's name or a sequence of them"):
        run_sweep(make(), fields=fields)


def test_a_grid_beyond_numpys_index_is_refused_naming_the_axes():
    """2^63 points used to fail with "greater than 'intp'" when the first chunk ran."""
    big = "0:1:3037000500"
    with pytest.raises(ValueError) as err:
        make(vx=big, omega=big, mu=big)
    text = str(err.value)
    assert "28011" in text.replace(",", "")  # the number of points
    assert "vx 3037000500 x omega 3037000500 x mu 3037000500" in text
    assert "9223372036854775807" in text.replace(",", "")  # the most it can index


def test_random_samples_beyond_numpys_index_are_refused():
    spec = dict(vx="uniform:-2:2", vy="-1", omega="0", mu="0.5", kappa="0.8")
    axes = {k: parse_axis(k, v) for k, v in spec.items()}
    with pytest.raises(ValueError, match="samples must be at most 9,223,372,036,854,775,807"):
        Sweep(BODY, axes, samples=2**64)
    assert Sweep(BODY, axes, samples=2**40).size == 2**40  # large, but numbered
