"""Shared pytest configuration.

``tests`` is a package (each folder has an ``__init__.py``), so pytest puts the
repository root on the import path by itself and the shared helpers import as
``tests.cases`` and ``tests.reference``; nothing edits ``sys.path``.
"""

import os

import pytest
from hypothesis import settings

# Deterministic property tests: the same examples on every run and machine. `make test`
# (what CI runs) tries 200 examples a property; `make check`, the everyday quick subset,
# sets SPINIMPACT_HYPOTHESIS=quick for 25.
settings.register_profile("repro", derandomize=True, max_examples=200, deadline=None)
settings.register_profile("quick", derandomize=True, max_examples=25, deadline=None)
settings.load_profile(os.environ.get("SPINIMPACT_HYPOTHESIS", "repro"))


@pytest.fixture
def toy():
    """The toy problem of tests/toy_problem.py, registered for one test, then removed."""
    from spinimpact import register, unregister

    from .toy_problem import TOY

    register(TOY)
    yield TOY
    unregister(TOY.name)
