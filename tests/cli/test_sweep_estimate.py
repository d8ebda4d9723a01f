"""spinimpact sweep --dry-run under a law that steps each impact in time
(mindlin-deresiewicz, about a millisecond a point): the estimate is measured on the
sweep's first points, grown only while cheap, so it says so and never runs a whole
chunk (it used to run 130,000 points for a grid of 40,401)."""

import re

import pytest

from tests.cli.test_errors import _keep_sigterm  # noqa: F401 (an autouse fixture)


@pytest.mark.slow
def test_a_dry_run_of_slow_points_is_measured_on_fewer_than_a_chunk(cli, tmp_path):
    status, out, err = cli("sweep", "--tangential", "mindlin-deresiewicz", "--poisson-ratio",
                           "0.23", "--output", tmp_path / "d", "--dry-run")  # fmt: skip
    assert status == 0, err
    assert out.startswith("estimate: 40,401 points in 1 chunk: about ")
    measured = re.search(r"\(measured on the sweep's first ([\d,]+) points\)\n$", out)
    assert measured, out
    assert 64 <= int(measured[1].replace(",", "")) < 40_401
    assert list(tmp_path.iterdir()) == []
