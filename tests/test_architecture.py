"""The shape of the package (docs/architecture.md), checked from its source.

* Layers: ``core`` <- ``model`` <- ``io`` / ``viz`` / ``engines`` <- ``cli``; imports
  point down only (every import counts, also those inside functions).
* No import cycles among the package's modules.
* Each module imports on its own in a fresh interpreter.
* No module over 600 lines: a smell detector, not a target (a module holds one idea whole;
  split by concept, never to meet the number).
* The old module paths (``spinimpact.batch``, ...) still work, and nothing inside the
  package imports them.
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "spinimpact"

#: Modules kept at their old paths so existing imports keep working; each is an alias
#: of its new home. Nothing inside the package may import them.
ALIASES = {
    "spinimpact.batch": "spinimpact.io.batch",
    "spinimpact.sweep": "spinimpact.io.sweep",
    "spinimpact.plots": "spinimpact.viz.plots",
    "spinimpact.html": "spinimpact.viz.html",
    "spinimpact.report": "spinimpact.viz.report",
}
#: Public facades: short import paths for users, never imported by the package itself.
FACADES = {"spinimpact.dynamics", "spinimpact.contact_law"}

#: What each layer may import from the package (besides itself).
ALLOWED = {
    "core": {"core", "_validation"},  # _validation imports nothing of the package
    "model": {"core", "model", "_validation"},
    "io": {"core", "model", "io", "_validation", "__init__"},
    "viz": {"core", "model", "viz", "io", "_validation", "__init__"},
    "engines": {"core", "model", "engines", "_validation", "__init__"},
    "cli": {"core", "model", "io", "viz", "engines", "cli", "explore", "_validation", "__init__"},
    # the explorer's web page, beside cli: it reads input with cli's converters
    "explore": {"core", "model", "io", "viz", "cli", "explore", "_validation", "__init__"},
    "_validation": set(),
}
#: Modules at the top level that import nothing of the package, so every layer may use them.
_LEAVES = ("_limits", "_long", "_words")
for _layer_name in ALLOWED:
    ALLOWED[_layer_name] = ALLOWED[_layer_name] | set(_LEAVES)
for _leaf in _LEAVES:
    ALLOWED[_leaf] = set()


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


MODULES = {_module_name(p): p for p in sorted(SRC.rglob("*.py"))}


def _imports(name: str, path: Path) -> set[str]:
    """The package modules that ``name`` imports, anywhere in its source."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                stem = ".".join(base + ([node.module] if node.module else []))
            else:
                stem = node.module or ""
            # "from . import core" imports a module; "from .x import f" imports x
            targets = [f"{stem}.{a.name}" for a in node.names]
            if node.module:
                targets.append(stem)
        else:
            continue
        for t in targets:
            while t and t not in MODULES:
                t = t.rpartition(".")[0]
            if t.startswith("spinimpact") and t != name:
                found.add(t)
    return found


GRAPH = {name: _imports(name, path) for name, path in MODULES.items()}


def _layer(name: str) -> str | None:
    parts = name.split(".")
    if len(parts) == 1:
        return "__init__"
    return parts[1]


def test_the_source_tree_was_found():
    assert {"spinimpact.core.impulse", "spinimpact.model.impact", "spinimpact.cli"} <= set(GRAPH)


@pytest.mark.parametrize("name", sorted(GRAPH))
def test_imports_point_down_the_layers(name):
    layer = _layer(name)
    if layer not in ALLOWED:  # the top level, aliases and facades: checked below
        return
    wrong = {t for t in GRAPH[name] if _layer(t) not in ALLOWED[layer] | {layer}}
    wrong |= {t for t in GRAPH[name] if t in ALIASES or t in FACADES}
    assert not wrong, f"{name} ({layer}) imports {sorted(wrong)}"


def test_no_import_cycles():
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(node: str) -> None:
        state[node] = 1
        path.append(node)
        for nxt in sorted(GRAPH[node]):
            if state.get(nxt) == 1:
                cycle = path[path.index(nxt) :] + [nxt]
                raise AssertionError("import cycle: " + " -> ".join(cycle))
            if nxt not in state:
                visit(nxt)
        path.pop()
        state[node] = 2

    for node in sorted(GRAPH):
        if node not in state:
            visit(node)


def test_the_cycle_check_can_fail():
    """The checker sees a cycle written into a copy of the graph."""
    saved = dict(GRAPH)
    try:
        GRAPH["spinimpact.core.impulse"] = GRAPH["spinimpact.core.impulse"] | {
            "spinimpact.core.kinematics"
        }
        with pytest.raises(AssertionError, match="import cycle"):
            test_no_import_cycles()
    finally:
        GRAPH.clear()
        GRAPH.update(saved)


#: Run in one fresh interpreter: ``import spinimpact``, then one forked child per module named
#: in argv, at most two at a time; prints {module: the last line of its error} as JSON.
_IMPORT_EACH = r"""
import importlib, json, os, sys, traceback

import spinimpact  # noqa: F401  (what a fresh interpreter runs first for every module below)

def child(name, write):
    try:
        importlib.import_module(name)
    except BaseException as exc:  # what a fresh interpreter would print last
        line = traceback.format_exception_only(type(exc), exc)[-1].strip()
        os.write(write, line.encode())
        os._exit(1)
    os._exit(0)

failed, running, waiting = {}, {}, list(sys.argv[1:])
while waiting or running:
    while waiting and len(running) < 2:
        name = waiting.pop(0)
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(read)
            child(name, write)
        os.close(write)
        running[pid] = (name, read)
    pid, status = os.wait()
    name, read = running.pop(pid)
    with os.fdopen(read, "rb") as pipe:
        message = pipe.read().decode()
    if status:
        failed[name] = message or f"wait status {status}"
print(json.dumps(failed))
"""


@pytest.mark.slow
def test_each_module_imports_alone_in_a_fresh_interpreter():
    """Each module imports on its own: an import cycle that breaks at import time, or a
    missing name, fails here.

    Importing any ``spinimpact.x.y`` in a fresh interpreter first runs ``import spinimpact``
    (Python imports a module's parent packages first), always the same way. So one fresh
    interpreter runs that once, then forks a child per module, which imports it from
    exactly the state every fresh interpreter reaches there: the same check as an
    interpreter per module, without importing NumPy and the model 150 times. If
    ``import spinimpact`` itself fails, so does this test."""
    names = sorted(n for n in MODULES if n not in ALIASES and n != "spinimpact.__main__")
    out = subprocess.run(
        [sys.executable, "-c", _IMPORT_EACH, *names],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout) == {}


@pytest.mark.slow  # imports the package in a fresh interpreter
def test_the_fresh_import_check_can_fail():
    """Modules that fail to import are reported, with the last line of their error; the
    others are not."""
    out = subprocess.run(
        [sys.executable, "-c", _IMPORT_EACH, "spinimpact.core.impulse", "spinimpact.no_such",
         "os", "this_module_is_missing"],
        capture_output=True, text=True, timeout=120, check=True,
    )  # fmt: skip
    failed = json.loads(out.stdout)
    assert set(failed) == {"spinimpact.no_such", "this_module_is_missing"}
    assert (
        failed["spinimpact.no_such"] == "ModuleNotFoundError: No module named 'spinimpact.no_such'"
    )


@pytest.mark.parametrize("old", sorted(ALIASES))
def test_old_module_paths_are_the_new_modules(old):
    import importlib

    assert importlib.import_module(old) is importlib.import_module(ALIASES[old])


@pytest.mark.parametrize("name", sorted(MODULES))
def test_no_module_over_600_lines(name):
    lines = MODULES[name].read_text().count("\n")
    assert lines <= 600, f"{name} has {lines} lines"


@pytest.mark.slow
def test_importing_the_package_stays_light():
    code = (
        "import sys, spinimpact\n"
        "heavy = [m for m in ('matplotlib', 'rich', 'click', 'scipy', 'numba', 'dask',\n"
        "         'pyarrow', 'jax', 'pybullet', 'mujoco') if m in sys.modules]\n"
        "print(','.join(heavy))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""
