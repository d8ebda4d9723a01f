"""Fixtures for the command-line tests (a module's own fixture of the same name wins)."""

import signal

import pytest

from spinimpact.cli import main


@pytest.fixture
def cli(capsys):
    """Run ``spinimpact ...`` in this process: (exit status, stdout, stderr); the signal
    handlers the command installs are put back afterwards."""
    previous = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGALRM)}

    def call(*args):
        try:
            main(list(map(str, args)))
            status = 0
        except SystemExit as exit_:
            status = exit_.code
        out = capsys.readouterr()
        return status, out.out, out.err

    yield call
    for s, handler in previous.items():
        signal.signal(s, handler)
