"""A batch follows the rule of every long run (spinimpact._long): measured on its own first
rows, it says its estimate first over a minute and is refused over an hour unless forced.

The clock is replaced by one that a slow solver advances (seconds per row), so the tests
are fast and deterministic: no timing of this machine is asserted."""

import numpy as np
import pytest

import spinimpact._long as long
from spinimpact import Problem, register, unregister
from spinimpact._long import TooLong
from spinimpact.io.batch import run_batch

from tests.toy_problem import TOY, ToyImpact, solve_toy


@pytest.fixture
def slow_toy(monkeypatch):
    """The toy problem whose solver 'takes' ``slow_toy.per_row`` seconds a row on a clock
    that only it advances."""
    now = [0.0]
    monkeypatch.setattr(long, "clock", lambda: now[0])

    def solve(columns, tangential=None):
        now[0] += state.per_row * columns["speed"].size
        return solve_toy(columns, tangential)

    class State:
        per_row = 1.0

    state = State()
    declared = Problem("slowtoy", TOY.summary, TOY.inputs, solve, ToyImpact,
                       marks=("speed",), units=TOY.units, example=TOY.example)  # fmt: skip
    register(declared)
    yield state
    unregister("slowtoy")


def write(path, rows):
    np.savetxt(path, -1.0 - np.arange(rows)[:, None] % 7, header="speed", comments="",
               fmt="%g")  # fmt: skip
    return path


def test_a_batch_over_an_hour_is_refused_unless_forced(tmp_path, slow_toy):
    slow_toy.per_row = 10.0  # 1,000 rows: about 10,000 s
    source, out = write(tmp_path / "in.csv", 1000), tmp_path / "out.csv"
    out.write_text("kept")
    with pytest.raises(TooLong, match=r"this batch \(1,000 rows of problem 'slowtoy'\) would "
                       r"take about 2\.8 h here, over the limit of 1 h"):  # fmt: skip
        run_batch(source, out, defaults={})
    assert out.read_text() == "kept" and sorted(p.name for p in tmp_path.iterdir()) == [
        "in.csv", "out.csv"]  # fmt: skip
    summary = run_batch(source, out, defaults={}, force=True)
    assert summary.rows == 1000


def test_a_batch_over_a_minute_says_its_estimate_first(tmp_path, slow_toy):
    slow_toy.per_row = 0.5  # 200 rows: about 100 s
    heard = []
    run_batch(write(tmp_path / "in.csv", 200), tmp_path / "out.csv", defaults={},
              announce=heard.append)  # fmt: skip
    (estimate,) = heard
    assert 90 < estimate.seconds < 110 and "measured on its first 64 rows" in str(estimate)
    slow_toy.per_row = 0.001  # 200 rows: 0.2 s, nothing to say
    heard.clear()
    run_batch(write(tmp_path / "in.csv", 200), tmp_path / "out.csv", defaults={},
              announce=heard.append)  # fmt: skip
    assert heard == []


def cli(capsys, *args):
    """``spinimpact ...`` in this process (the fake clock holds): (status, stderr)."""
    import signal

    from spinimpact.cli import main

    kept = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        main([str(a) for a in args])
        status = 0
    except SystemExit as exit_:
        status = exit_.code
    finally:
        for s, handler in kept.items():
            signal.signal(s, handler)
    return status, capsys.readouterr().err


def test_the_command_line_refuses_in_one_line_naming_force(tmp_path, slow_toy, capsys):
    slow_toy.per_row = 10.0
    source = write(tmp_path / "in.csv", 1000)
    status, err = cli(capsys, "batch", source, "--output", tmp_path / "out.csv")
    assert status != 0 and err.count("\n") == 1 and "--force runs it anyway" in err
    assert not (tmp_path / "out.csv").exists()
    slow_toy.per_row = 0.5
    status, err = cli(capsys, "batch", write(source, 200), "--output", tmp_path / "out.csv")
    assert status == 0 and "will take about 1.7 min here" in err
