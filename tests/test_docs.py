"""The README's examples and every docstring example run, and print what they show."""

import doctest
import importlib
import pkgutil
import re
from pathlib import Path

import pytest

import spinimpact

ROOT = Path(__file__).resolve().parents[1]
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def test_readme_examples():
    result = doctest.testfile(str(ROOT / "README.md"), module_relative=False, optionflags=FLAGS)
    assert result.attempted >= 6
    assert result.failed == 0


START_PAGES = sorted((ROOT / "docs" / "start").glob("*.md"))


#: The site's other pages that hold Python blocks (the start pages are run above).
CODE_PAGES = sorted(p for p in (ROOT / "docs").glob("*.md") if "```python" in p.read_text())


@pytest.fixture
def registry_kept():
    """The problems a page registers (docs/architecture.md registers "toy") are removed
    afterwards: left registered, they changed what later tests in the same process saw."""
    before = {p.name for p in spinimpact.problems()}
    yield
    for name in {p.name for p in spinimpact.problems()} - before:
        spinimpact.unregister(name)


@pytest.mark.parametrize("path", CODE_PAGES, ids=lambda p: p.name)
@pytest.mark.slow
def test_every_python_block_of_a_page_runs(path, tmp_path, monkeypatch, registry_kept):
    """Each Python block of a page runs, in the page's order, each seeing what the blocks
    before it defined: a block of ``>>>`` examples prints what the page shows (doctest),
    any other block runs without error. Files it writes land in a temporary folder."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    blocks = re.findall(r"```python\n(.*?)```", path.read_text(), re.S)
    names: dict = {"__name__": f"docs_{path.stem}"}
    parser, runner = doctest.DocTestParser(), doctest.DocTestRunner(optionflags=FLAGS)
    for k, block in enumerate(blocks):
        where = f"{path.name}, Python block {k + 1}"
        if ">>>" not in block:
            exec(compile(block, where, "exec"), names)  # noqa: S102 - the page's own code
            continue
        test = parser.get_doctest(block, names, where, str(path), 0)
        result = runner.run(test, clear_globs=False)
        assert result.failed == 0, where
        names = test.globs
    assert blocks


@pytest.mark.parametrize("path", START_PAGES, ids=lambda p: p.name)
@pytest.mark.slow
def test_start_pages_run(path, tmp_path, monkeypatch, registry_kept):
    """Each start page's Python blocks run and print what the page shows (the figures they
    save land in a temporary folder)."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    result = doctest.testfile(str(path), module_relative=False, optionflags=FLAGS)
    assert result.attempted >= 8
    assert result.failed == 0


MODULES = sorted(
    m.name
    for m in pkgutil.walk_packages(spinimpact.__path__, "spinimpact.")
    if m.name != "spinimpact.__main__"
)


@pytest.mark.parametrize("name", ["spinimpact", *MODULES])
@pytest.mark.slow
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


# --- Docs stay inside the repository ---------------------------------------------------
#
# A user of the package has the repository and nothing beside it, so no document or
# docstring may point at the project's working folders (the paper's seed text, shared
# notes); the paper is cited instead (docs/references.md). Every relative link must reach
# a file of the repository, every anchor a heading or id in it, and every file path or
# dotted name a doc quotes must still exist after code moves.


OUTSIDE = ("../shared", "/work/", "shared/seed")
MARKDOWN = sorted([ROOT / "README.md", *(ROOT / "docs").glob("*.md")])
SOURCES = sorted((ROOT / "src" / "spinimpact").rglob("*.py"))
SCRIPTS = sorted([*(ROOT / "docs").rglob("*.py"), *(ROOT / "benchmarks").glob("*.py")])


def _rel(path):
    return path.relative_to(ROOT).as_posix()


def outside_pointers(text):
    """Lines of ``text`` naming a place outside the repository, as ``(line, pattern)``."""
    return [
        (number, pattern)
        for number, line in enumerate(text.splitlines(), 1)
        for pattern in OUTSIDE
        if pattern in line
    ]


@pytest.mark.parametrize("path", [*MARKDOWN, *SOURCES, *SCRIPTS], ids=_rel)
def test_nothing_points_outside_the_repository(path):
    found = outside_pointers(path.read_text(encoding="utf-8"))
    assert not found, f"{_rel(path)} points outside the repository: {found}"


_FENCE = re.compile(r"^(```|~~~).*?^\1", re.S | re.M)
_CODE = re.compile(r"`[^`\n]*`")
_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
_REFDEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)", re.M)
_HTML = re.compile(r"<(?:a|img)\b[^>]*?\b(?:href|src)\s*=\s*\"([^\"]*)\"", re.I)
_SCHEME = re.compile(r"^[a-z][a-z0-9+.-]*:", re.I)


def _prose(text):
    """Markdown without code blocks and inline code, where link syntax is literal."""
    return _CODE.sub("", _FENCE.sub("", text))


def link_targets(text):
    prose = _prose(text)
    return [*_LINK.findall(prose), *_REFDEF.findall(prose), *_HTML.findall(prose)]


_TARGET = re.compile(r"^\s*(?:- )?\(([\w\-]+)\)=\s*$", re.M)


def anchors(text):
    """Anchors a page offers: GitHub's heading slugs (duplicates numbered), explicit ids and
    MyST targets (``(name)=`` on a line of its own, as references.md marks each work)."""
    found, seen = set(), {}
    for heading in re.findall(r"^#{1,6}\s+(.*?)\s*#*\s*$", _FENCE.sub("", text), re.M):
        slug = re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        found.add(slug if count == 0 else f"{slug}-{count}")
    found.update(re.findall(r"\b(?:id|name)\s*=\s*\"([^\"]+)\"", text))
    found.update(_TARGET.findall(text))
    return found


def broken_links(path, root=ROOT):
    """Relative links in the markdown file ``path`` that do not reach a file of ``root``."""
    text = path.read_text(encoding="utf-8")
    broken = []
    for target in link_targets(text):
        if not target or _SCHEME.match(target):  # web addresses are not repository paths
            continue
        where, _, fragment = target.partition("#")
        dest = (path.parent / where).resolve() if where else path.resolve()
        if not dest.is_relative_to(root.resolve()):
            broken.append(f"{target} (leaves the repository)")
        elif not dest.exists():
            broken.append(f"{target} (no such file)")
        elif fragment and dest.suffix == ".md":
            if fragment not in anchors(dest.read_text(encoding="utf-8")):
                broken.append(f"{target} (no such anchor)")
    return broken


@pytest.mark.parametrize("path", MARKDOWN, ids=_rel)
def test_relative_links_resolve(path):
    assert broken_links(path) == []


_REPO_PATH = re.compile(r"^(?:docs|tests|src|benchmarks|\.ci)/[\w./-]*\w$")


@pytest.mark.parametrize("path", MARKDOWN, ids=_rel)
def test_quoted_repository_paths_exist(path):
    """A file path quoted as code (`tests/paper/test_errata.py`) names a file that exists."""
    quoted = {span.strip("`") for span in _CODE.findall(_FENCE.sub("", path.read_text()))}
    missing = sorted(q for q in quoted if _REPO_PATH.match(q) and not (ROOT / q).exists())
    assert missing == [], f"{_rel(path)} names files that do not exist: {missing}"


def _attribute(obj, name):
    """``getattr``, also for a dataclass field without a default (``Impact.regime``)."""
    fields = getattr(obj, "__dataclass_fields__", {})
    return fields[name] if name in fields and not hasattr(obj, name) else getattr(obj, name)


def resolve(dotted, base=None):
    """The object a dotted name such as ``spinimpact.io.sweep.run_sweep`` refers to.

    With ``base``, the name is looked up as attributes of that object instead.
    AttributeError or ImportError: the name refers to nothing (any more).
    """
    parts = dotted.split(".")
    if base is not None:
        obj = base
        for attr in parts:
            obj = _attribute(obj, attr)
        return obj
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for attr in parts[cut:]:
            obj = _attribute(obj, attr)
        return obj
    raise ImportError(dotted)


_DOTTED = re.compile(r"^((?:spinimpact|core)(?:\.[A-Za-z_]\w*)+)(?:\(.*\))?$")


@pytest.mark.parametrize("path", MARKDOWN, ids=_rel)
def test_quoted_package_names_exist(path):
    """`spinimpact.x.y` and `core.x` in a doc name modules, functions or fields that exist."""
    missing = []
    for span in _CODE.findall(_FENCE.sub("", path.read_text())):
        match = _DOTTED.match(span.strip("`"))
        if not match:
            continue
        name = match.group(1)
        full = name if name.startswith("spinimpact.") else f"spinimpact.{name}"
        try:
            resolve(full)
        except (ImportError, AttributeError):
            missing.append(name)
    assert missing == [], f"{_rel(path)} names what the package does not have: {missing}"


def test_equation_map_names_functions_that_exist():
    """Every name in docs/theory.md's equation map is in `spinimpact.core` (or the API)."""
    text = (ROOT / "docs" / "theory.md").read_text()
    table = text.split("## Equation map", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in table.splitlines() if line.startswith("|") and "---" not in line]
    names = {
        re.sub(r"\(.*\)$", "", span.strip("`"))
        for row in rows[1:]
        for span in _CODE.findall(row.strip("|").split("|")[-1])
    }
    assert len(names) >= 30  # the map covers the paper: a truncated table is a failure
    missing = []
    for name in sorted(names):
        # A kernel of `spinimpact.core`, or the user API (`Impact.energetic_restitution`),
        # or a field of Impact named after one ("`Impact.x`, `poisson_restitution`").
        for base in (spinimpact.core, spinimpact, spinimpact.Impact):
            try:
                resolve(name, base)
                break
            except AttributeError:
                pass
        else:
            missing.append(name)
    assert missing == []


# --- The bibliography -------------------------------------------------------------------

REFERENCES = ROOT / "docs" / "references.md"


def _entry(key):
    text = REFERENCES.read_text(encoding="utf-8")
    start = text.index(f"({key})=")
    end = text.find("\n- ", start)
    return " ".join(text[start : end if end > 0 else None].split())


@pytest.mark.parametrize(
    ("key", "facts"),
    [
        (
            "lubarda-2010",
            [
                "On the frictional impact of a spinning disk against a fixed surface",
                "Proceedings of the Section of Natural Sciences, Montenegrin Academy of "
                "Sciences and Arts",
                "Glasnik Odjeljenja prirodnih nauka, Crnogorska akademija nauka i umjetnosti",
                "19 (2010)",
            ],
        ),
        ("lubarda-2010-pendulum", ["rigid pendulum against a fixed surface", "77 (2010) 011006"]),
        ("keller-1986", ["J. B. Keller", "Impact with friction", "53 (1986) 1–4"]),
        ("stronge-1990", ["Rigid body collisions with friction", "431 (1990) 169–181"]),
        ("stronge-2000", ["Impact Mechanics", "Cambridge University Press"]),
        ("routh-1905", ["Dynamics of a System of Rigid Bodies", "7th ed."]),
        ("whittaker-1961", ["Analytical Dynamics of Particles and Rigid Bodies"]),
        (
            "wang-mason-1992",
            ["Two-dimensional rigid-body collisions with friction", "59 (1992) 635–642"],
        ),
        ("hunt-crossley-1975", ["vibroimpact", "42 (1975) 440–445"]),
        ("maw-barber-fawcett-1976", ["Wear", "38 (1976) 101–114"]),
        ("kharaz-2001", ["Powder Technology", "120 (2001) 281–291"]),
        ("chung-ooi-2011", ["Granular Matter", "13 (2011) 643–656"]),
    ],
)
def test_references_give_full_citations(key, facts):
    entry = _entry(key)
    for fact in facts:
        assert fact in entry, f"{key}: {fact!r} missing"
    assert "Used for:" in entry or "Cited for:" in entry or "Measured here" in entry


def test_lubarda_citation_invents_no_pages():
    """The paper's header prints the journal and volume, not the pages: none are cited."""
    entry = _entry("lubarda-2010")
    assert not re.search(r"\d\s*[–-]\s*\d", entry.split("Used for:")[0]), entry


@pytest.mark.parametrize("name", ["theory.md", "errata.md", "dynamics.md", "performance.md"])
def test_docs_cite_through_the_bibliography(name):
    links = link_targets((ROOT / "docs" / name).read_text(encoding="utf-8"))
    assert any(target.partition("#")[0] == "references.md" for target in links)


# --- The checks above can fail ----------------------------------------------------------


def test_outside_pointers_are_found():
    text = "fine\nseed text in `../shared/seed/000.txt`\nsee /work/main/docs\n"
    assert outside_pointers(text) == [(2, "../shared"), (2, "shared/seed"), (3, "/work/")]
    assert outside_pointers("docs/references.md#lubarda-2010") == []


def test_broken_links_are_found(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "there.md").write_text('# A heading, with `code`\n<a id="x"></a>\n')
    page = tmp_path / "docs" / "page.md"
    page.write_text(
        "[ok](there.md) [ok](there.md#a-heading-with-code) [ok](there.md#x) "
        "[ok](https://example.org/a.md) ![gone](images/gone.png) [out](../../elsewhere.md) "
        "[anchor](there.md#nowhere) `[in code](missing.md)`\n"
        "```\n[in a block](missing.md)\n```\n[ref]: missing-too.md\n"
    )
    assert broken_links(page, root=tmp_path) == [
        "images/gone.png (no such file)",
        "../../elsewhere.md (leaves the repository)",
        "there.md#nowhere (no such anchor)",
        "missing-too.md (no such file)",
    ]


def test_resolve_fails_on_moved_names():
    assert resolve("spinimpact.io.sweep.run_sweep") is not None
    with pytest.raises(AttributeError):
        resolve("spinimpact.core.no_such_kernel")
