"""The "Internals" pages: one autodoc page per module that the API pages do not cover.

Docstrings of the public API name the kernels and helpers they call
(``spinimpact.core.compliance.walton_slip``, ``spinimpact.io.sweep.Sweep``...). So that
every such name is a link, each module of the package that is not already documented under
``docs/api/`` gets a page under ``docs/internals/`` (generated when the build starts, so a
new module gets its page without anyone editing the docs; the folder is git-ignored).
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import re
import sys
from pathlib import Path

from sphinx.util.nodes import make_refnode

import spinimpact

_AUTOMODULE = re.compile(r"^\.\. (?:auto|py:)?module:: (\S+)", re.M)
_SKIP = ("spinimpact.__main__",)


def _documented(api: Path) -> set[str]:
    """The modules the hand-written API pages already document."""
    names: set[str] = set()
    for page in api.glob("*.rst"):
        names.update(_AUTOMODULE.findall(page.read_text(encoding="utf-8")))
    return names


_MEMBERS = re.compile(r"^\.\. automodule:: (\S+)\n((?:   :.*\n)*)", re.M)


def _public(module) -> list[str]:  # noqa: ANN001 - a module
    names = getattr(module, "__all__", None)
    if names is None:
        names = [n for n in vars(module) if not n.startswith("_")]
    return list(names)


def _api_classes(api: Path) -> set[int]:
    """The classes the API pages document: a class has one page, under its public name.

    Documenting it again on its defining module's page would describe one object twice
    (Sphinx refuses); links to its defining module's name still reach the API page.
    """
    objects = [getattr(spinimpact, n) for n in spinimpact.__all__]
    for page in api.glob("*.rst"):
        for name, options in _MEMBERS.findall(page.read_text(encoding="utf-8")):
            module = importlib.import_module(name)
            listed = re.search(r":members:(.*)", options)
            if listed is None:
                continue
            names = [n.strip() for n in listed.group(1).split(",") if n.strip()]
            objects += [getattr(module, n) for n in names or _public(module)]
    return {id(o) for o in objects if inspect.isclass(o)}


def _excluded(name: str, api_classes: set[int]) -> list[str]:
    """Classes of a module's page that have their page elsewhere."""
    module = importlib.import_module(name)
    package = hasattr(module, "__path__")
    out = []
    for member in _public(module):
        obj = getattr(module, member, None)
        if not inspect.isclass(obj):
            continue
        if id(obj) in api_classes or (package and obj.__module__ != name):
            out.append(member)
    return out


def _modules() -> list[str]:
    """Every module of the package under its own name (an old name that hands over another
    module, such as ``spinimpact.sweep`` for ``spinimpact.io.sweep``, is left out)."""
    found = []
    for info in pkgutil.walk_packages(spinimpact.__path__, prefix="spinimpact."):
        if info.name in _SKIP:
            continue
        if importlib.import_module(info.name).__name__ == info.name:
            found.append(info.name)
    return sorted(found)


def _write(path: Path, text: str) -> None:
    """Write only when the text changes, so that an unchanged page is not rebuilt."""
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def generate(app) -> None:  # noqa: ANN001 - Sphinx's application
    src = Path(app.srcdir)
    out = src / "internals"
    out.mkdir(exist_ok=True)
    documented = _documented(src / "api")
    names = [m for m in _modules() if m not in documented and m != "spinimpact"]
    api_classes = _api_classes(src / "api")
    for name in names:
        title = f"``{name}``"
        text = f"{title}\n{'=' * len(title)}\n\n.. automodule:: {name}\n   :members:\n"
        text += "   :undoc-members:\n"
        if not hasattr(importlib.import_module(name), "__path__"):
            # A module's page shows every public name it defines; a package's, what it
            # exports (its __all__).
            text += "   :ignore-module-all:\n"
        excluded = _excluded(name, api_classes)
        if excluded:
            text += f"   :exclude-members: {', '.join(excluded)}\n"
        _write(out / f"{name}.rst", text)
    for stale in out.glob("*.rst"):
        if stale.stem not in names and stale.stem != "index":
            stale.unlink()
    toc = "\n".join(f"   {name}" for name in names)
    _write(
        out / "index.rst",
        "Internals\n=========\n\n"
        "The modules under the public API, one page each, made from their docstrings: the\n"
        "kernels of ``spinimpact.core`` (each quoting the equations it implements), the\n"
        "models and results of ``spinimpact.model``, the file machinery of ``spinimpact.io``,\n"
        "the command line's modules. Their names may change between versions; import from\n"
        ":mod:`spinimpact` and the modules of the :doc:`API reference <../api/index>`.\n\n"
        f".. toctree::\n   :maxdepth: 1\n\n{toc}\n",
    )


def _resolve(path: str):  # noqa: ANN202 - any object
    """The object a dotted path names, or None."""
    parts = path.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for part in parts[k:]:
            obj = getattr(obj, part, None)
            if obj is None:
                return None
        return obj
    return None


def public_names() -> dict[int, str]:
    """Each class of ``spinimpact.__all__``, by id, with its public name."""
    return {
        id(getattr(spinimpact, n)): f"spinimpact.{n}"
        for n in spinimpact.__all__
        if inspect.isclass(getattr(spinimpact, n))
    }


def _defined_in(name: str) -> list[str]:
    """The modules of the package whose source assigns or defines ``name``, as paths."""
    pattern = re.compile(rf"^(?:{re.escape(name)}\s*[:=]|(?:def|class) {re.escape(name)}\b)", re.M)
    out = []
    for module_name, module in list(sys.modules.items()):
        if not module_name.startswith("spinimpact") or module is None:
            continue
        try:
            source = inspect.getsource(module)
        except (OSError, TypeError):
            continue
        if pattern.search(source):
            out.append(f"{module_name}.{name}")
    return out


def to_public_page(app, env, node, contnode):  # noqa: ANN001, ANN201 - Sphinx's event
    """Send a link to a class by its defining module's name to the class's public page.

    ``spinimpact.model.fit_result.FitResult`` is documented once, as
    ``spinimpact.FitResult``: a docstring that names it (or one of its members) by where it
    is defined, or by its bare name inside that module, links there.
    """
    if node.get("refdomain") != "py":
        return None
    target = node["reftarget"].lstrip("~.")
    module, cls = node.get("py:module"), node.get("py:class")
    candidates = [target]
    if module:
        candidates.append(f"{module}.{target}")
        if cls:
            candidates.append(f"{module}.{cls}.{target}")
    names = public_names()
    domain = env.get_domain("py")
    for candidate in candidates:
        if not candidate.startswith("spinimpact"):
            continue
        parts = candidate.split(".")
        for k in range(len(parts), 1, -1):
            obj = _resolve(".".join(parts[:k]))
            if obj is None or id(obj) not in names:
                continue
            new = ".".join([names[id(obj)], *parts[k:]])
            found = domain.resolve_xref(
                env, node["refdoc"], app.builder, node["reftype"], new, node, contnode
            )
            if found is not None:
                return found
    # A name used in a docstring of a module that re-exports it (``spinimpact.io``), or a
    # class's member named after the class: the one documented object of that name.
    matches = domain.find_obj(env, None, None, target, node["reftype"], 1)
    if len(matches) == 1:
        _, entry = matches[0]
        return make_refnode(app.builder, node["refdoc"], entry.docname, entry.node_id, contnode)
    if "." not in target:
        candidates += _defined_in(target)
    # A name that exists but has no entry of its own (a module's constant or private
    # helper): the link goes to the nearest documented object that holds it, its class or
    # its module.
    objects = domain.objects
    for candidate in candidates:
        if not candidate.startswith("spinimpact") or _resolve(candidate) is None:
            continue
        parts = candidate.split(".")
        for k in range(len(parts) - 1, 0, -1):
            entry = objects.get(".".join(parts[:k]))
            if entry is not None:
                return make_refnode(
                    app.builder, node["refdoc"], entry.docname, entry.node_id, contnode
                )
    return None


def setup(app):  # noqa: ANN001, ANN201 - Sphinx's extension entry point
    app.connect("builder-inited", generate)
    app.connect("missing-reference", to_public_page)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
