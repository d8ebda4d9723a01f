"""The built documentation site, opened page by page in headless Chromium (Playwright).

The site is the one ``make docs`` builds into ``build/docs/html`` (``make test`` builds it
first); where it is missing, the fixture builds it once into a temporary folder. It is
served over HTTP on the loopback interface, as a reader's browser would get it, and
Chromium is the system's (``shutil.which("chromium")``): nothing is downloaded.

Checked on every page: each internal link reaches a file of the site and each anchor an
id in it, each image exists and decodes, the console shows no error, and nothing is wider
than the window at 1280 px (a desktop) and at 390 px (a phone). The search page finds
the API page of ``solve_sphere``.
"""

from __future__ import annotations

import functools
import html.parser
import http.server
import re
import subprocess
import sys
import threading
from pathlib import Path
from urllib.parse import unquote, urljoin, urlsplit

import pytest

from tests.viz.browser import launched

pytestmark = [pytest.mark.browser, pytest.mark.slow]

ROOT = Path(__file__).resolve().parents[2]
BUILT = ROOT / "build" / "docs" / "html"
WIDTHS = (1280, 390)


# --- The site, built and served -----------------------------------------------------------


@pytest.fixture(scope="session")
def site(tmp_path_factory) -> Path:
    """The built site: ``build/docs/html`` if ``make docs`` made it, else built here once."""
    if (BUILT / "index.html").exists():
        return BUILT
    pytest.importorskip("sphinx", reason="the site needs the [docs] extra")
    out = tmp_path_factory.mktemp("site") / "html"
    cmd = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html"]
    subprocess.run([*cmd, str(ROOT / "docs"), str(out)], check=True, cwd=ROOT)
    return out


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:  # the test output stays readable
        pass


class _Server(http.server.ThreadingHTTPServer):
    def handle_error(self, request, client_address) -> None:
        """A page left before its last file was sent (the browser moved on) is not an
        error of the site; anything else is printed, as the standard server does."""
        if not isinstance(sys.exc_info()[1], ConnectionError):
            super().handle_error(request, client_address)


@pytest.fixture(scope="session")
def server(site):
    """The site over HTTP on 127.0.0.1 (a free port); yields its base address."""
    handler = functools.partial(_Quiet, directory=str(site))
    httpd = _Server(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    httpd.shutdown()
    httpd.server_close()
    thread.join()


@pytest.fixture(scope="session")
def browser():
    yield from launched(required_in_ci=True)


def pages(site: Path) -> list[str]:
    """Every HTML page of the site, as paths relative to its root."""
    skip = ("_static", "_sources", "_downloads", "_images", ".doctrees")
    return sorted(
        p.relative_to(site).as_posix()
        for p in site.rglob("*.html")
        if p.relative_to(site).parts[0] not in skip
    )


# --- Links, anchors and images, read from the files ----------------------------------------


class _Links(html.parser.HTMLParser):
    """The ids, link targets and image sources of one page."""

    def __init__(self) -> None:
        super().__init__()
        self.ids: set[str] = set()
        self.hrefs: list[str] = []
        self.images: list[str] = []

    def handle_starttag(self, tag, attrs) -> None:
        attrs = dict(attrs)
        for key in ("id", "name"):
            if attrs.get(key):
                self.ids.add(attrs[key])
        if tag == "a" and attrs.get("href"):
            self.hrefs.append(attrs["href"])
        if tag == "img" and attrs.get("src"):
            self.images.append(attrs["src"])


@functools.cache
def _parsed(path: Path) -> _Links:
    parser = _Links()
    parser.feed(path.read_text(encoding="utf-8"))
    return parser


def broken_links(site: Path, page: str) -> list[str]:
    """The internal links and images of ``page`` that reach no file or no anchor."""
    base = f"http://site/{page}"
    found = _parsed(site / page)
    broken = []
    for target in [*found.hrefs, *found.images]:
        parts = urlsplit(urljoin(base, target))
        if parts.scheme in ("mailto", "javascript", "data") or parts.netloc != "site":
            continue  # outside the site (the pages have no external links to check here)
        path = site / unquote(parts.path).lstrip("/")
        if path.is_dir():
            path = path / "index.html"
        if not path.exists():
            broken.append(f"{target} (no such file)")
        elif parts.fragment and path.suffix == ".html":
            if unquote(parts.fragment) not in _parsed(path).ids:
                broken.append(f"{target} (no such anchor)")
    return broken


def test_every_link_and_image_resolves(site):
    everything = pages(site)
    assert len(everything) > 50, "the site is missing pages"
    broken = {page: b for page in everything if (b := broken_links(site, page))}
    assert not broken, broken


def test_broken_links_are_found(tmp_path):
    (tmp_path / "a.html").write_text(
        '<a id="top" href="b.html">b</a> <a href="a.html#top">ok</a> '
        '<a href="a.html#nowhere">x</a> <img src="missing.png">'
    )
    assert broken_links(tmp_path, "a.html") == [
        "b.html (no such file)",
        "a.html#nowhere (no such anchor)",
        "missing.png (no such file)",
    ]


# --- Every page in the browser ---------------------------------------------------------------

_OVERFLOW = """() => {
    const doc = document.documentElement;
    if (doc.scrollWidth <= doc.clientWidth + 1) {  // the common case: no element to name
        return {scroll: doc.scrollWidth, client: doc.clientWidth, wide: []};
    }
    const wide = [...document.querySelectorAll('body *')].filter(e => {
        const r = e.getBoundingClientRect();
        return r.width > 0 && r.right > doc.clientWidth + 1
            && getComputedStyle(e).position !== 'fixed';
    }).slice(0, 3).map(e => e.tagName.toLowerCase() + (e.className ? '.' + e.className : ''));
    return {scroll: doc.scrollWidth, client: doc.clientWidth, wide: wide};
}"""

_IMAGES = """() => [...document.images]
    .filter(i => i.complete && i.naturalWidth === 0 && i.getAttribute('src'))
    .map(i => i.getAttribute('src'))"""


def test_every_page_loads_cleanly_at_desktop_and_phone_widths(site, server, browser):
    problems: dict[str, list[str]] = {}
    context = browser.new_context(viewport={"width": WIDTHS[0], "height": 900})
    page = context.new_page()
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    for path in pages(site):
        found = []
        errors.clear()
        page.set_viewport_size({"width": WIDTHS[0], "height": 900})
        page.goto(server + path, wait_until="load")
        if errors:
            found.append(f"console: {errors[:3]}")
        if missing := page.evaluate(_IMAGES):
            found.append(f"images that do not load: {missing}")
        for width in WIDTHS:  # the page reflows as the window narrows, as a reader's does
            page.set_viewport_size({"width": width, "height": 900})
            box = page.evaluate(_OVERFLOW)
            if box["scroll"] > box["client"] + 1:
                found.append(f"{width} px: {box['scroll']} px wide, by {box['wide']}")
        if found:
            problems[path] = found
    context.close()
    assert not problems, "\n".join(f"{path}: {found}" for path, found in problems.items())


def test_search_finds_the_api_page_of_solve_sphere(server, browser):
    page = browser.new_page(viewport={"width": WIDTHS[0], "height": 900})
    page.goto(server + "search.html?q=solve_sphere", wait_until="load")
    link = page.locator("ul.search li a[href*='spinimpact.solve_sphere.html']").first
    link.wait_for(timeout=30_000)
    assert "solve_sphere" in link.inner_text()
    page.close()


def test_every_command_option_and_problem_input_is_in_the_cli_reference(site):
    """The CLI reference names every visible option of every command, and each registered
    problem's inputs as ``--problem NAME`` takes them."""
    import html

    import click

    from spinimpact import problems
    from spinimpact.cli import cli

    text = html.unescape(re.sub(r"<[^>]+>", "", (site / "cli.html").read_text()))
    missing = []
    for name, command in cli.commands.items():
        if getattr(command, "hidden", False):
            continue
        if f"spinimpact {name}" not in text:
            missing.append(name)
        for param in command.params:
            if isinstance(param, click.Option) and not param.hidden:
                missing += [o for o in param.opts if o not in text]
    for declared in problems():
        assert f"--problem {declared.name}" in text
        missing += [f"--{i.name.replace('_', '-')}" for i in declared.inputs
                    if f"--{i.name.replace('_', '-')}" not in text]  # fmt: skip
    assert missing == []
