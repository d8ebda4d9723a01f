"""The README's examples and every docstring example run, and print what they show."""

import doctest
import importlib
import pkgutil
from pathlib import Path

import pytest

import spinimpact

ROOT = Path(__file__).resolve().parents[1]
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def test_readme_examples():
    result = doctest.testfile(str(ROOT / "README.md"), module_relative=False, optionflags=FLAGS)
    assert result.attempted >= 6
    assert result.failed == 0


MODULES = sorted(
    m.name
    for m in pkgutil.walk_packages(spinimpact.__path__, "spinimpact.")
    if m.name != "spinimpact.__main__"
)


@pytest.mark.parametrize("name", ["spinimpact", *MODULES])
def test_docstring_examples(name):
    module = importlib.import_module(name)
    for needed in getattr(module, "__doctest_requires__", ()):  # optional extras
        pytest.importorskip(needed, reason=f"{name}'s examples need {needed}")
    result = doctest.testmod(module, optionflags=FLAGS)
    assert result.failed == 0


def test_readme_names_the_test_command_that_ci_runs():
    readme = (ROOT / "README.md").read_text()
    ci = (ROOT / ".ci" / "run").read_text()
    assert "make test" in readme and "make test" in ci
