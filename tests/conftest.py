"""Shared pytest configuration.

``tests`` is a package (each folder has an ``__init__.py``), so pytest puts the
repository root on the import path by itself and the shared helpers import as
``tests.cases`` and ``tests.reference``; nothing edits ``sys.path``.
"""

from hypothesis import settings

# Deterministic property tests: the same examples on every run and machine.
settings.register_profile("repro", derandomize=True, max_examples=200, deadline=None)
settings.load_profile("repro")
