"""Shared pytest configuration.

``tests`` is a package (each folder has an ``__init__.py``), so pytest puts the
repository root on the import path by itself and the shared helpers import as
``tests.cases`` and ``tests.reference``; nothing edits ``sys.path``.
"""

import os
from pathlib import Path

import pytest
from hypothesis import settings

# Deterministic property tests: the same examples on every run and machine. `make test`
# (what CI runs) tries 200 examples a property; `make check`, the everyday quick subset,
# sets SPINIMPACT_HYPOTHESIS=quick for 25.
settings.register_profile("repro", derandomize=True, max_examples=200, deadline=None)
settings.register_profile("quick", derandomize=True, max_examples=25, deadline=None)
settings.load_profile(os.environ.get("SPINIMPACT_HYPOTHESIS", "repro"))

# Numba's parallel kernels run on OpenMP threads, which by default spin for a while after
# each kernel, waiting for the next. Between two tests' processes (and the commands they
# start) on two cores, the spinning threads took the cores from the work: the fit of 40 data
# sets in tests/model/test_fit_problem.py used 69 s of processor time instead of 15 s. Idle
# threads that sleep instead change no number (the thread count stays); a value the user has
# set is kept. Set before any test loads Numba's OpenMP layer, and inherited by the commands
# the tests run.
os.environ.setdefault("OMP_WAIT_POLICY", "passive")


@pytest.fixture
def toy():
    """The toy problem of tests/toy_problem.py, registered for one test, then removed."""
    from spinimpact import register, unregister

    from .toy_problem import TOY

    register(TOY)
    yield TOY
    unregister(TOY.name)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    """Under pytest-xdist (``make test`` runs two workers), a test marked ``alone`` runs
    while no other test runs: it measures how soon a command stops after a signal, and a
    second test loading the two cores at the same time would stretch those times. The
    workers share two lock files in the run's temporary folder: every test holds ``run``
    shared, an ``alone`` test holds it exclusive, and ``gate`` (taken before ``run``) keeps
    the other worker from starting a test while an ``alone`` one waits for its turn.
    Without xdist (one process) nothing is locked."""
    basetemp = item.config.option.basetemp
    if not hasattr(item.config, "workerinput") or not basetemp:
        yield
        return
    import fcntl  # POSIX, as are the tests marked alone

    folder = Path(basetemp).parent  # xdist gives worker gwN the run's basetemp / "popen-gwN"
    alone = item.get_closest_marker("alone") is not None
    with open(folder / "gate.lock", "a") as gate, open(folder / "run.lock", "a") as run:
        fcntl.flock(gate, fcntl.LOCK_EX)
        fcntl.flock(run, fcntl.LOCK_EX if alone else fcntl.LOCK_SH)
        if not alone:
            fcntl.flock(gate, fcntl.LOCK_UN)
        try:
            yield
        finally:
            fcntl.flock(run, fcntl.LOCK_UN)
            fcntl.flock(gate, fcntl.LOCK_UN)
