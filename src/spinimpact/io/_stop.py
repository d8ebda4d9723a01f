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

A signal that arrives while Python code runs as a callback from compiled code (llvmlite
calls back into Python while Numba compiles a kernel) cannot raise there: ctypes prints
the exception and swallows it. The handler then only records the signal and asks for it
again 20 ms later (``SIGALRM``, :func:`signal.setitimer`), until the program is back in
code where the exception propagates.

Once the outermost :func:`~spinimpact.io.atomic.atomic_outputs` has renamed every output
into place (:func:`finished`), a signal no longer says "no output was changed": the process
exits at once with 128 + the signal's number, one line on stderr saying the command had
finished. The command line keeps that handler for the rest of its process
(``stop_on_signals(keep=True)``) and, after a finished run, ends the process once the exit
handlers (:mod:`atexit`) have run, without the interpreter's module teardown: that takes up
to a second with SciPy and Matplotlib loaded, Python handles no signal during it, and a
signal then would kill the process (a status of -2 to its caller instead of 130).

Without :func:`stop_on_signals` (the Python API) nothing is recorded and
:func:`check` never raises: Ctrl-C is Python's ``KeyboardInterrupt``, as usual.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
import threading
from collections.abc import Iterator
from typing import Any

__all__ = ["Stopped", "check", "critical", "finished", "stop_on_signals"]

_SIGNALS = tuple(getattr(signal, n) for n in ("SIGINT", "SIGTERM") if hasattr(signal, n))
_ALARM = (signal.SIGALRM,) if hasattr(signal, "setitimer") and hasattr(signal, "SIGALRM") else ()


class Stopped(BaseException):  # noqa: N818 (like KeyboardInterrupt: not an error of the input)
    """The run was stopped by a signal; ``signum`` says which.

    A ``BaseException``, so ``except Exception`` does not swallow it.
    """

    def __init__(self, signum: int) -> None:
        self.signum = signum
        super().__init__(f"stopped by {signal.Signals(signum).name}")


class _State:
    signum = 0  # the first signal received, 0 if none
    raised = False  # whether a Stopped was raised already (at most one from the handler)
    depth = 0  # critical sections open (temporary outputs alive)
    finished = False  # every output is in place: a signal now exits at once (finished())
    exiting = False  # the block of stop_on_signals(keep=True) has ended: the process ends next
    installed = False  # stop_on_signals' handlers are in place
    deferred = False  # a Stopped is owed: it came inside a callback from compiled code


_RETRY_S = 0.02  # how soon a deferred Stopped is tried again
# Python code whose exceptions are swallowed, not propagated: what compiled code calls back,
# and the import system (its module locks' weak-reference callbacks run inside imports).
_CALLBACK_MODULES = ("llvmlite.", "ctypes.", "importlib.")


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


def finished() -> None:
    """The run is done and its outputs are in place: a signal from now on (or one recorded
    while they were renamed) exits at once with status 128 + its number, after one line on
    stderr. Only under :func:`stop_on_signals`; otherwise it does nothing."""
    if not _state.installed:
        return
    _state.finished = True
    if _state.signum:
        _exit(_state.signum)


def _exit(signum: int) -> None:
    name = signal.Signals(signum).name
    if _state.finished:
        line = f"spinimpact: {name} came after the command had finished; its output is complete\n"
    else:  # it failed or was stopped, and is exiting: every old output is as it was
        line = f"spinimpact: {name} came while it was exiting; no output was changed\n"
    os.write(2, line.encode())
    os._exit(128 + signum)  # nothing is left to clean up; skip the interpreter's shutdown


def _skip_teardown() -> None:
    """At exit after a finished run: flush the standard streams and end the process with
    status 0, skipping the module teardown during which no signal handler runs."""
    if not _state.finished:
        return
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):  # closed or broken: nothing more to say
            stream.flush()
    os._exit(0)


def _in_callback(frame: Any) -> bool:
    """Whether ``frame`` or a frame below it runs where an exception raised is printed and
    swallowed, not propagated: in a module that compiled code calls back, in the import
    system (a weak-reference callback of its module locks), or in a ``__del__``."""
    while frame is not None:
        if frame.f_globals.get("__name__", "").startswith(_CALLBACK_MODULES):
            return True
        if frame.f_code.co_name == "__del__":
            return True
        frame = frame.f_back
    return False


def _raise(frame: Any) -> None:
    """Raise the owed :class:`Stopped` now, or, inside a callback from compiled code,
    record that it is owed and try again shortly."""
    if _in_callback(frame):
        _state.deferred = True
        if hasattr(signal, "setitimer"):
            signal.setitimer(signal.ITIMER_REAL, _RETRY_S)
        return
    _state.deferred = False
    _state.raised = True
    raise Stopped(_state.signum)


def _retry(_signum: int, frame: Any) -> None:
    """SIGALRM: raise a :class:`Stopped` that a callback from compiled code deferred."""
    if _state.finished or _state.exiting:
        _exit(_state.signum)
    if _state.deferred and not _state.raised:
        _raise(frame)


def _handler(signum: int, frame: Any) -> None:
    if _state.finished or _state.exiting:
        _exit(signum)
    second = bool(_state.signum)
    if not second:
        _state.signum = signum
    if not _state.raised and (_state.depth == 0 or second):
        _raise(frame)


@contextlib.contextmanager
def stop_on_signals(*, keep: bool = False) -> Iterator[None]:
    """Handle SIGINT and SIGTERM as the module's notes describe, then restore the handlers.

    With ``keep=True`` (the command line's own process, which ends next) the handlers stay
    when the block ends: a signal from then on exits at once with 128 + its number, saying
    whether the run had finished (its output complete) or not (no output changed), instead
    of killing the process or being lost in a shutdown that hangs; and after a
    :func:`finished` run the process ends once the exit handlers have run, without the
    module teardown. Outside the main thread (where handlers cannot be installed) it does
    nothing.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {s: signal.getsignal(s) for s in (*_SIGNALS, *_ALARM)}
    _state.signum, _state.raised, _state.depth, _state.finished = 0, False, 0, False
    _state.exiting = _state.deferred = False
    for s in _SIGNALS:
        signal.signal(s, _handler)
    for s in _ALARM:
        signal.signal(s, _retry)
    _state.installed = True
    if keep:  # registered first, so it runs after the handlers the run's imports register
        atexit.register(_skip_teardown)
    try:
        yield
    finally:
        _state.exiting = keep
        if not keep:
            _state.installed = False
            if _ALARM:
                signal.setitimer(signal.ITIMER_REAL, 0)  # no retry outlives the block
            for s, handler in previous.items():
                signal.signal(s, handler)
            _state.signum, _state.raised, _state.finished = 0, False, False
            _state.deferred = False
