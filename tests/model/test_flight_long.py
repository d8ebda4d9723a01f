"""A flight that would run for hours is refused before it runs, naming its estimate; one
that may take minutes says its estimate first (``announce``); ``force=True`` runs it, with
the same numbers. The estimate is measured on the run's own first steps and trials of its
first chunk (spinimpact.model.flight_cost). Thresholds are lowered where a test needs a
long run, so that the runs stay short; the margins are wide (a run of several seconds
against a limit of one)."""

import numpy as np
import pytest

from spinimpact import _long, flight
from spinimpact._long import Estimate, TooLong

SERVE = dict(speed=30.0, angle=0.0)


def test_a_step_of_a_tenth_of_a_microsecond_is_refused_with_its_estimate():
    with pytest.raises(ValueError, match=r"would take about .* force=True runs it anyway") as e:
        flight("tennis", "hard", **SERVE, dt=1e-7)
    assert isinstance(e.value, TooLong)
    assert e.value.estimate.seconds > _long.REFUSE_SECONDS
    assert "this flight (1 ball, dt = 1e-07 s)" in str(e.value)


@pytest.mark.slow
def test_a_run_over_the_limit_is_refused_and_forced_it_gives_the_same_numbers(monkeypatch):
    plain = flight("tennis", "hard", **SERVE, dt=1e-3)
    monkeypatch.setattr(_long, "ANNOUNCE_SECONDS", 0.0)
    monkeypatch.setattr(_long, "REFUSE_SECONDS", 0.01)
    with pytest.raises(TooLong, match=r"this flight \(1 ball, dt = 0\.001 s\) would take"):
        flight("tennis", "hard", **SERVE, dt=1e-3)
    seen = []
    forced = flight("tennis", "hard", **SERVE, dt=1e-3, force=True, announce=seen.append)
    assert len(seen) == 1 and isinstance(seen[0], Estimate) and seen[0].seconds > 0.01
    np.testing.assert_array_equal(forced.bounces.time, plain.bounces.time)
    np.testing.assert_array_equal(forced.final_position.array, plain.final_position.array)


@pytest.mark.slow
def test_a_short_run_is_not_announced_and_reports_progress_by_chunk():
    seen, calls = [], []
    flight("tennis", "hard", speed=[30.0, 31.0, 32.0], angle=0.0, chunk=2,
           announce=seen.append, progress=lambda d, n: calls.append((d, n)))  # fmt: skip
    assert seen == [] and calls == [(2, 3), (3, 3)]
