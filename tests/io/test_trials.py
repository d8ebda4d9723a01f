"""The trials a sweep's estimate is measured on grow only while they are cheap: a sweep
of fast points is timed up to 262,144 points and weighed on 16,384, as before; one of
slow points stops growing at the time budget and is extrapolated from what ran; a small
sweep spends about a tenth of its own time. A clock that counts each point's cost, set
by the test, makes the trials deterministic (no timed assertions)."""

import dataclasses
import math

import pytest

from spinimpact import _long as _trials
from spinimpact.io._runner import TRIAL_POINTS, estimate
from spinimpact.io.sweep import Sweep, parse_axis

from tests.io.test_sweep import BODY


@dataclasses.dataclass(frozen=True)
class Costly(Sweep):
    """A sweep whose chunks advance :data:`CLOCK` by ``per_chunk + per_point * points``."""

    per_point: float = 0.0
    per_chunk: float = 0.0

    def evaluate(self, k, fields):
        CLOCK[0] += self.per_chunk + self.per_point * self.chunk_length(k)
        return super().evaluate(k, fields)


CLOCK = [0.0]


@pytest.fixture(autouse=True)
def counted(monkeypatch):
    CLOCK[0] = 0.0
    monkeypatch.setattr(_trials, "clock", lambda: CLOCK[0])


def costly(grid, per_point, per_chunk=0.0, chunk_size=100_000):
    axes = dict(vx=f"-5:5:{grid}", vy="-4", omega=f"-50:50:{grid}", mu="0.3", kappa="0.8")
    axes = {k: parse_axis(k, v) for k, v in axes.items()}
    return Costly(BODY, axes, chunk_size=chunk_size, per_point=per_point, per_chunk=per_chunk)


def test_fast_points_are_timed_up_to_sixteen_times_the_weighed_trial():
    sweep = costly(1001, 1e-8, 1e-4, chunk_size=500_000)
    cost = estimate(sweep)
    assert cost.trial_points == (64, 256, 1024, 4096, 16384, 65536, 262144)
    assert cost.weighed_points == TRIAL_POINTS == 16384 and cost.measured_points == 262144
    assert sweep.chunks == 3
    assert cost.seconds == pytest.approx(3 * 1e-4 + 1_002_001 * 1e-8, rel=1e-9)
    assert str(cost).endswith("(measured on the sweep's first 262,144 points)")
    # a chunk smaller than the trials: the last trial is a whole chunk
    cost = estimate(costly(1001, 1e-8, 1e-4, chunk_size=40_000))
    assert cost.trial_points == (64, 256, 1024, 4096, 16384, 40000)
    assert cost.seconds == pytest.approx(26 * 1e-4 + 1_002_001 * 1e-8, rel=1e-9)


def test_slow_points_stop_the_trials_at_the_budget_and_are_extrapolated():
    # 1 ms a point, 40,401 points: 40 s of work. The trials of 64 and 256 points take
    # 0.64 s (two runs each), the one of 1,024 would take 3 s more (and its weighing): over
    # the 2 s budget. The old estimate ran 64 + 3 * 16,384 + 2 * 40,401 points (130 s).
    sweep = costly(201, 1e-3)
    cost = estimate(sweep)
    assert cost.trial_points == (64, 256) and cost.weighed_points == 256
    assert cost.seconds == pytest.approx(40401 * 1e-3, rel=1e-9)
    assert str(cost).startswith("40,401 points in 1 chunk: about 40 s here, ")
    assert str(cost).endswith("(measured on the sweep's first 256 points)")
    spent = CLOCK[0]  # compiling run (64 points), trials and the weighing run
    assert spent == pytest.approx(64e-3 + 2 * (64e-3 + 256e-3) + 256e-3, rel=1e-9)
    assert spent <= _trials.MAX_SECONDS + 64e-3 < 0.1 * cost.seconds
    # with a cost per chunk, the two trials separate it from the cost per point
    cost = estimate(costly(201, 1e-3, 0.05, chunk_size=10_000))
    assert cost.trial_points == (64, 256)
    assert cost.seconds == pytest.approx(5 * 0.05 + 40401 * 1e-3, rel=1e-9)


def test_a_small_sweep_spends_about_a_tenth_of_its_time():
    sweep = costly(41, 1e-3)  # 1,681 points, 1.7 s of work: a budget of 0.17 s
    cost = estimate(sweep)
    assert cost.trial_points == (64,) and cost.weighed_points == 64
    assert cost.seconds == pytest.approx(1681 * 1e-3, rel=1e-9)
    assert CLOCK[0] == pytest.approx(4 * 64e-3, rel=1e-9)  # compiling, two timed, weighing
    # points so cheap that the whole ladder fits in the least budget (0.05 s)
    cost = estimate(costly(41, 1e-9))
    assert cost.trial_points == (64, 256, 1024, 1681) and cost.weighed_points == 1681


def test_untimed_estimates_weigh_at_most_trial_points_and_stop_at_the_budget():
    cost = estimate(costly(1001, 1e-8, chunk_size=500_000), timed=False)
    assert cost.trial_points == () and math.isnan(cost.seconds)
    assert cost.weighed_points == cost.measured_points == TRIAL_POINTS
    assert str(cost).endswith("(measured on the sweep's first 16,384 points)")
    # one run a trial: 64 and 256 points (0.32 s), then 1,024 and its weighing would
    # take 2 s more
    CLOCK[0] = 0.0
    cost = estimate(costly(201, 1e-3), timed=False)
    assert cost.weighed_points == 256
    assert CLOCK[0] == pytest.approx(64e-3 + 64e-3 + 256e-3 + 256e-3, rel=1e-9)


def test_ladder_grows_four_times_up_to_the_chunk():
    assert _trials.ladder(10**6, 16 * TRIAL_POINTS) == [64, 256, 1024, 4096, 16384, 65536, 262144]
    assert _trials.ladder(1000, TRIAL_POINTS) == [64, 256, 1000]
    assert _trials.ladder(1024, TRIAL_POINTS) == [64, 256, 1024]
    assert _trials.ladder(10, TRIAL_POINTS) == [10]
