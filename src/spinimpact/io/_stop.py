"""Stopping a run on SIGINT or SIGTERM without damaging a file.

Raising an exception from a signal handler is unreliable: some NumPy calls
(``text.astype(np.float64)``) swallow it, and one raised inside a clean-up leaves a
temporary file behind. So the command line's handler (:func:`stop_on_signals`)
first records the signal. While no temporary output exists it also raises
:class:`Stopped` at once (a pure computation stops promptly); while one exists (a
*critical* section, :func:`critical`) it only records it, and the writer stops at
its next :func:`check` (between chunks, and always before an output is renamed into
place), so the clean-up in ``finally`` runs undisturbed. A second signal during a
critical section raises at once (the way out of a blocked read); the temporary it
may leave is removed by the next run (:mod:`spinimpact.io.atomic`).

Without :func:`stop_on_signals` (the Python API) nothing is recorded and
:func:`check` never raises: Ctrl-C is Python's ``KeyboardInterrupt``, as usual.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator
from typing import Any

__all__ = ["Stopped", "check", "critical", "stop_on_signals"]

_SIGNALS = tuple(getattr(signal, n) for n in ("SIGINT", "SIGTERM") if hasattr(signal, n))


class Stopped(BaseException):  # noqa: N818 (like KeyboardInterrupt: not an error of the input)
    """The run was stopped by a signal; :attr:`signum` says which.

    A ``BaseException``, so ``except Exception`` does not swallow it.
    """

    def __init__(self, signum: int) -> None:
        self.signum = signum
        super().__init__(f"stopped by {signal.Signals(signum).name}")


class _State:
    signum = 0  # the first signal received, 0 if none
    raised = False  # whether a Stopped was raised already (at most one from the handler)
    depth = 0  # critical sections open (temporary outputs alive)


_state = _State()


def check() -> None:
    """Raise :class:`Stopped` if a stop was asked; call it where stopping is safe."""
    if _state.signum:
        _state.raised = True
        raise Stopped(_state.signum)


@contextlib.contextmanager
def critical() -> Iterator[None]:
    """A section during which a signal is only recorded (see the module's notes)."""
    enter()
    try:
        yield
    finally:
        leave()


def enter() -> None:
    """Open a critical section (a temporary output now exists)."""
    _state.depth += 1


def leave() -> None:
    """Close a critical section opened by :func:`enter`."""
    _state.depth -= 1


def _handler(signum: int, _frame: Any) -> None:
    second = bool(_state.signum)
    if not second:
        _state.signum = signum
    if not _state.raised and (_state.depth == 0 or second):
        _state.raised = True
        raise Stopped(_state.signum)


@contextlib.contextmanager
def stop_on_signals() -> Iterator[None]:
    """Handle SIGINT and SIGTERM as the module's notes describe, then restore the handlers.

    Outside the main thread (where handlers cannot be installed) it does nothing.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {s: signal.getsignal(s) for s in _SIGNALS}
    _state.signum, _state.raised, _state.depth = 0, False, 0
    for s in _SIGNALS:
        signal.signal(s, _handler)
    try:
        yield
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
        _state.signum, _state.raised = 0, False
