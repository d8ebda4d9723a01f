"""The README's examples and every docstring example run, and print what they show."""

import doctest
import importlib
import math
import os
import pkgutil
import re
import shlex
import subprocess
import sys
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


# --- Every other code block runs too ----------------------------------------------------
#
# The Python blocks run above. A shell block (```console, ```bash, ```sh, ```shell) holds
# commands, one a line (a trailing backslash continues it, `#` starts a comment); written
# with prompts (`$ spinimpact ...`), the lines after a command are the output it prints. A
# ```text block right after a shell block is output of that block's last command. Each
# `spinimpact ...` and `python -m ...` command runs in a temporary folder, with the input
# files the page describes, and must exit with status 0 and print the output shown. A
# `make` command builds the environment, the site or the figures and is not run here: each
# one is listed in NOT_RUN with the reason. MyST directives (```{toctree}) are not code.
# Any other block, or a command with no rule, fails `test_every_code_block_has_a_rule`.

SHELL = {"console", "bash", "sh", "shell", "shell-session"}

#: The commands the pages show that are not run here, and why (each is a Makefile target).
NOT_RUN = {
    "make demo": "creates .venv and installs the package: the environment these tests run in",
    "make test": "builds the site and runs the whole suite, this test among them",
    "make images": "redraws every figure of the site, engines included (minutes)",
    "make images IMAGES=docs/images": "the same, rewriting the figures the repository tracks",
    "make validation": "every model against every benchmark (minutes); "
    "tests/test_validation.py checks what it prints",
}

PAGES = sorted([*MARKDOWN, *START_PAGES])
_OPEN = re.compile(r"^ {0,3}(`{3,}|~{3,})\s*([^`\s]*)")


def fenced_blocks(text):
    """The fenced code blocks of Markdown ``text``, as ``(line, info, body)``."""
    blocks, lines, k = [], text.splitlines(), 0
    while k < len(lines):
        match = _OPEN.match(lines[k])
        if not match:
            k += 1
            continue
        fence, info, start = match.group(1), match.group(2), k
        k += 1
        while k < len(lines) and not re.fullmatch(
            rf" {{0,3}}{re.escape(fence[0])}{{{len(fence)},}}\s*", lines[k]
        ):
            k += 1
        blocks.append((start + 1, info, "\n".join(lines[start + 1 : k])))
        k += 1
    return blocks


def shell_commands(body):
    """The commands of a shell block, each as ``(command, output lines it shows)``."""
    lines = body.splitlines()
    prompted = any(line.startswith("$ ") for line in lines)
    found, k = [], 0
    while k < len(lines):
        line = lines[k]
        k += 1
        if prompted and not line.startswith("$ "):
            if found:
                found[-1][1].append(line)
            continue
        command = line[2:] if prompted else line
        while command.rstrip().endswith("\\") and k < len(lines):
            command = command.rstrip()[:-1] + " " + lines[k].strip()
            k += 1
        words = shlex.split(command, comments=True)
        if words:
            found.append((" ".join(words), []))
    return found


def argv_of(command):
    """The process that runs ``command`` here, or None for a command with no rule."""
    words = shlex.split(command)
    if words[0] in ("spinimpact", ".venv/bin/spinimpact"):
        return [sys.executable, "-m", "spinimpact", *words[1:]]
    if words[0] in ("python", "python3", ".venv/bin/python") and words[1:2] == ["-m"]:
        return [sys.executable, *words[1:]]
    return None


def code_blocks(path):
    """Every fenced block of ``path`` with its rule: ``(where, rule, commands)``.

    The rule is "python", "directive", "shell", "output" (a text block after a shell
    block), or "no rule" with the reason; ``commands`` are a shell block's commands (its
    output lines, and a following text block's, attached)."""
    found = []
    for line, info, body in fenced_blocks(path.read_text(encoding="utf-8")):
        where = f"{_rel(path) if path.is_relative_to(ROOT) else path.name}:{line}"
        if info == "python":
            found.append((where, "python", []))
        elif info.startswith("{") and info.endswith("}"):
            found.append((where, "directive", []))
        elif info in SHELL:
            commands = shell_commands(body)
            unknown = [c for c, _ in commands if argv_of(c) is None and c not in NOT_RUN]
            rule = f"no rule: commands {unknown}" if unknown or not commands else "shell"
            found.append((where, rule, commands))
        elif info == "text" and found and found[-1][1] == "shell":
            found[-1][2][-1][1].extend(body.splitlines())
            found.append((where, "output", []))
        else:
            found.append((where, f"no rule: a ```{info} block", []))
    return found


def test_every_code_block_has_a_rule():
    """No page holds a block that nothing runs: a new kind of block, or a new command
    that is neither runnable here nor listed in NOT_RUN, fails until it has a rule."""
    lost = [
        f"{where}: {rule}"
        for path in PAGES
        for where, rule, _ in code_blocks(path)
        if rule.startswith("no rule")
    ]
    assert lost == []


def test_the_commands_not_run_are_on_the_pages_and_in_the_makefile():
    """NOT_RUN lists no command the pages no longer show, and each is a Makefile target."""
    shown = {
        command
        for path in PAGES
        for _, rule, commands in code_blocks(path)
        if rule == "shell"
        for command, _ in commands
    }
    assert sorted(set(NOT_RUN) - shown) == []
    targets = re.findall(r"^([\w-]+):", (ROOT / "Makefile").read_text(), re.M)
    assert all(command.split()[1] in targets for command in NOT_RUN)


def _paper_bounces(path):
    """docs/fitting.md's first example as the file `spinimpact fit bounces.csv` reads: 40
    bounces of a 58 g solid ball, the rebound with noise, the spin of every fourth missing."""
    import numpy as np

    ball = spinimpact.Body.solid_sphere(mass=0.058, radius=0.033)
    rng = np.random.default_rng(1)
    vy = -rng.uniform(2.0, 6.0, 40)
    vx = np.linspace(0.3, 4.0, 40) * -vy
    om = rng.normal(0.0, 20.0, 40)
    true = spinimpact.solve(ball, vx, vy, om, mu=0.35, kappa=0.75).after
    cols = {"vx": vx, "vy": vy, "omega": om}
    for name, sigma in (("vx", 0.05), ("vy", 0.05), ("omega", 3.0)):
        cols[f"after_{name}"] = getattr(true, name) + rng.normal(0.0, sigma, 40)
    cols["after_omega"][::4] = np.nan  # an empty cell: not measured
    for name, sigma in (("vx", 0.05), ("vy", 0.05), ("omega", 3.0)):
        cols[f"sigma_after_{name}"] = np.full(40, sigma)
    _write_csv(path, cols)


def _sphere_bounces(path):
    """docs/fitting.md's "Any problem" example as `spinimpact fit --problem sphere` reads it:
    30 bounces of a tennis ball in 3D, the rebound velocity and spin with noise."""
    import numpy as np

    ball = spinimpact.BALLS["tennis"]
    rng = np.random.default_rng(2)
    v = np.stack([rng.uniform(4, 20, 30), -rng.uniform(3, 8, 30), rng.uniform(-3, 3, 30)], -1)
    w = rng.normal(0.0, 50.0, (30, 3))
    true = spinimpact.solve_sphere(ball.body, v, w, mu=0.62, kappa=0.75).after
    cols = {name: v[:, k] for k, name in enumerate(("vx", "vy", "vz"))}
    cols |= {name: w[:, k] for k, name in enumerate(("wx", "wy", "wz"))}
    for name in ("vx", "vy", "vz", "wx", "wy", "wz"):
        sigma = 0.05 if name.startswith("v") else 3.0  # m/s, rad/s
        cols[f"after_{name}"] = getattr(true, name) + rng.normal(0.0, sigma, 30)
        cols[f"sigma_after_{name}"] = np.full(30, sigma)
    _write_csv(path, cols)


def _rods(path):
    """docs/planar.md's rods.csv: columns mass, inertia, rx, ry, vx, vy, omega, one uniform
    rod (1 kg, 1 m) per row, touching with its lower end."""
    end = 0.5 * math.sqrt(0.5)  # the end of a 1 m rod at 45 degrees
    cols = {
        "mass": [1.0, 1.0],
        "inertia": [1 / 12, 1 / 12],
        "rx": [-end, end],
        "ry": [-end, -end],
        "vx": [0.5, 1.0],
        "vy": [-1.0, -2.0],
        "omega": [0.0, 3.0],
    }
    _write_csv(path, cols)


def _write_csv(path, cols):
    """Columns as a CSV file; NaN is an empty cell."""
    rows = zip(*(list(map(float, c)) for c in cols.values()), strict=True)
    text = ",".join(cols) + "\n"
    text += "".join(",".join("" if x != x else repr(x) for x in row) + "\n" for row in rows)
    path.write_text(text)


def write_inputs(argv, folder):
    """Write the input file a page's command reads, as the page describes it."""
    if "rods.csv" in argv:
        _rods(folder / "rods.csv")
    if "bounces.csv" in argv:
        sphere = "--problem" in argv and argv[argv.index("--problem") + 1] == "sphere"
        (_sphere_bounces if sphere else _paper_bounces)(folder / "bounces.csv")


RUN = [
    pytest.param(command, shown, id=f"{where} {command[:60]}")
    for path in PAGES
    for where, rule, commands in code_blocks(path)
    if rule == "shell"
    for command, shown in commands
    if command not in NOT_RUN
]


@pytest.mark.parametrize(("command", "shown"), RUN)
@pytest.mark.slow
def test_every_command_on_a_page_runs(command, shown, tmp_path):
    """Each command a page shows exits with status 0 and prints the lines the page shows."""
    argv = argv_of(command)
    write_inputs(argv, tmp_path)
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(ROOT))  # `-m benchmarks...`
    done = subprocess.run(argv, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"{command}\n{done.stderr[-3000:]}"
    printed = {line.strip() for line in (done.stdout + done.stderr).splitlines()}
    assert [line for line in shown if line.strip() and line.strip() not in printed] == []


def test_the_pages_show_commands_that_run():
    assert len(RUN) >= 10  # README 2, planar.md 2, sphere3d.md 2, flight.md 1, fitting.md 3


def test_code_block_rules_find_what_has_none(tmp_path):
    page = tmp_path / "page.md"
    page.write_text(
        "```python\nx = 1\n```\n\n```{toctree}\nindex\n```\n\n"
        "```console\nspinimpact solve --vx 1 \\\n    --vy -2   # a comment\nmake test\n```\n"
        "```text\nshown\n```\n\n"
        "````console\n$ python -m spinimpact problems\npaper\n````\n\n"
        "```console\nrm -rf build\nmake nothing\n```\n\n"
        "```text\nalone\n```\n\n```\nbare\n```\n"
    )
    found = [(rule, commands) for _, rule, commands in code_blocks(page)]
    assert found == [
        ("python", []),
        ("directive", []),
        ("shell", [("spinimpact solve --vx 1 --vy -2", []), ("make test", ["shown"])]),
        ("output", []),
        ("shell", [("python -m spinimpact problems", ["paper"])]),
        (
            "no rule: commands ['rm -rf build', 'make nothing']",
            [("rm -rf build", []), ("make nothing", [])],
        ),
        ("no rule: a ```text block", []),
        ("no rule: a ``` block", []),
    ]
    assert argv_of("spinimpact solve")[1:] == ["-m", "spinimpact", "solve"]
    assert argv_of(".venv/bin/python -m benchmarks.flight_bench")[1:] == [
        "-m",
        "benchmarks.flight_bench",
    ]
    assert argv_of("pip install spinimpact") is None


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
