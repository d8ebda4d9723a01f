"""Headless Chromium for the HTML-page tests (skipped, with a reason, where it is missing)."""

import os
import shutil
import subprocess
from collections.abc import Iterator
from typing import Any

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
needs_browser = pytest.mark.skipif(
    CHROMIUM is None, reason="no chromium installed (.ci/run installs Debian's chromium)"
)


def chromium(tmp_path, *args):
    """Run headless Chromium with a fresh profile in ``tmp_path`` and no network chatter."""
    flags = [
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--hide-scrollbars",
        f"--user-data-dir={tmp_path / 'profile'}",
    ]
    return subprocess.run([CHROMIUM, *flags, *args], capture_output=True, text=True, timeout=120)


def launched(*, required_in_ci: bool = False) -> Iterator[Any]:
    """Yield a Playwright browser on Debian's Chromium (no browser download), closed after;
    skipped where Chromium or Playwright is missing, or failed under CI where
    ``required_in_ci`` (CI installs Chromium: a page it must test is not left untested)."""
    if CHROMIUM is None:
        if required_in_ci and os.environ.get("CI"):
            pytest.fail("no chromium installed, and CI must test the site in a browser")
        pytest.skip("no chromium installed (.ci/run installs Debian's chromium)")
    sync_api = pytest.importorskip("playwright.sync_api", reason="needs the playwright package")
    with sync_api.sync_playwright() as p:
        chromium = p.chromium.launch(
            executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"]
        )
        yield chromium
        chromium.close()
