"""Batch rows written on a worker thread: order, errors and closing as without it."""

import threading

import pytest

from spinimpact.io._background import BackgroundRows


class Sink:
    def __init__(self, fail_at=None):
        self.rows, self.closed, self.fail_at = [], None, fail_at
        self.threads = set()

    def write(self, k):
        self.threads.add(threading.current_thread().name)
        if k == self.fail_at:
            raise OSError("disk full")
        self.rows.append(k)

    def close(self, complete=True):
        self.closed = complete


def test_writes_in_order_on_one_worker_then_closes():
    sink = Sink()
    out = BackgroundRows(sink)
    for k in range(5):
        out.write(k)
    out.close(True)
    assert sink.rows == [0, 1, 2, 3, 4] and sink.closed is True
    assert len(sink.threads) == 1 and threading.current_thread().name not in sink.threads


def test_a_writers_error_is_raised_in_the_caller_and_the_sink_still_closes():
    sink = Sink(fail_at=2)
    out = BackgroundRows(sink)
    out.write(0)
    out.write(1)
    out.write(2)
    with pytest.raises(OSError, match="disk full"):
        out.write(3)  # the error of chunk 2 surfaces at the next write
    out.close(False)  # as run_batch's finally does after a failure
    assert sink.rows == [0, 1] and sink.closed is False


def test_close_after_a_failed_run_does_not_raise_over_it():
    sink = Sink(fail_at=0)
    out = BackgroundRows(sink)
    out.write(0)
    out.close(False)
    assert sink.closed is False
    sink = Sink(fail_at=0)
    out = BackgroundRows(sink)
    out.write(0)
    with pytest.raises(OSError):
        out.close(True)
    assert sink.closed is False  # the sink closes as after any failure
