"""docs/fitting.md: its Python examples run as written and print what the page shows."""

from __future__ import annotations

import doctest
from pathlib import Path

import pytest

DOC = Path(__file__).resolve().parents[2] / "docs" / "fitting.md"


@pytest.mark.slow
def test_the_examples_of_the_fitting_page_run():
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    result = doctest.testfile(str(DOC), module_relative=False, optionflags=flags)
    assert result.attempted >= 15 and result.failed == 0


def test_the_incidence_range_the_page_gives_is_that_of_the_stored_points():
    """The page says the fitted Kharaz points run from 2 to 60 degrees: so they do."""
    import re

    import numpy as np

    root = DOC.parents[1] / "benchmarks" / "data" / "kharaz2001"
    angles = np.array([
        float(line.split(",")[0])
        for name in ("tangential_restitution.csv", "omega.csv")
        for line in (root / name).read_text(encoding="utf-8").splitlines()[1:]
        if line.strip() and not line.startswith(("#", "impact_angle_deg"))
    ])  # fmt: skip
    text = " ".join(DOC.read_text(encoding="utf-8").split())
    low, high = map(float, re.search(r"run from (\d+) to (\d+) degrees", text).groups())
    assert round(angles.min()) == low and round(angles.max()) == high
