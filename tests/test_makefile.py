"""The Makefile's commands as ``make -n`` prints them: ``make images`` and ``make
validation`` draw into git-ignored folders unless given another, so a plain run never
modifies a tracked file; ``make check`` runs the tests but the slow and browser ones."""

import shlex
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
MAKE = shutil.which("make")
pytestmark = pytest.mark.skipif(MAKE is None, reason="make is not installed")


def dry_run(*args):
    """The commands ``make -n ARGS`` would run, one list of words each."""
    out = subprocess.run(
        [MAKE, "-n", "--no-print-directory", "-C", str(ROOT), *args],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert out.returncode == 0, out.stderr
    return [shlex.split(line) for line in out.stdout.splitlines() if line.strip()]


def outputs(commands):
    """The paths the commands write: every word naming a path but the programs, the
    scripts they run and ``/dev/null``."""
    return [
        word
        for words in commands
        for word in words
        if "/" in word
        and not word.startswith((".venv/", "/dev/"))
        and not word.endswith(".py")
        and "pip" not in words
    ]


def ignored_folders():
    lines = (ROOT / ".gitignore").read_text().splitlines()
    return [line.strip() for line in lines if line.strip().endswith("/")]


@pytest.mark.parametrize("target", ["images", "validation"])
def test_a_plain_run_writes_only_into_ignored_folders(target):
    """Both once wrote docs/images, rewriting the figures the repository tracks."""
    paths = outputs(dry_run(target))
    assert paths, "no output found: the dry run changed its shape"
    folders = ignored_folders()
    for path in paths:
        assert not path.startswith("docs"), path
        assert any(path.startswith(folder) for folder in folders), (path, folders)


def test_the_tracked_figures_are_refreshed_when_asked(tmp_path):
    for target, variable in (("images", "IMAGES"), ("validation", "VALIDATION")):
        paths = outputs(dry_run(target, f"{variable}={tmp_path}"))
        assert paths and all(p.startswith(str(tmp_path)) for p in paths), paths
        published = outputs(dry_run(target, f"{variable}=docs/images"))
        assert all(p.startswith("docs/images") for p in published), published


@pytest.mark.slow  # two collections of a test module in fresh interpreters
def test_check_leaves_out_the_slow_and_browser_tests():
    (command,) = [words for words in dry_run("check") if "pytest" in words]
    after = command[command.index("pytest") + 1 :]  # python -m pytest ... -m EXPRESSION
    assert after[after.index("-m") + 1] == "not slow and not browser"
    options = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]
    names = {line.split(":")[0].strip() for line in options["ini_options"]["markers"]}
    assert {"slow", "browser"} <= names
    # the browser tests are marked: collected by the whole suite, left out by the subset,
    # which leaves out exactly the tests marked browser or slow
    target = "tests/viz/test_html_report.py"
    found = {}
    for key, select in (("all", []), ("quick", ["-m", "not slow and not browser"]),
                        ("browser", ["-m", "browser"]), ("slow", ["-m", "slow"])):  # fmt: skip
        out = subprocess.run(
            [sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider",
             *select, target],
            capture_output=True, text=True, cwd=ROOT, timeout=120,
        )  # fmt: skip
        assert out.returncode in (0, 5), out.stdout[-2000:]  # 5: none selected
        found[key] = {line for line in out.stdout.splitlines() if "::" in line}
    browser = {t for t in found["all"] if "browser" in t}
    assert browser and browser <= found["browser"] and not browser & found["quick"]
    assert found["quick"] == found["all"] - found["browser"] - found["slow"]
