"""The screenshots of docs/explorer.md: the explorer's page in headless Chromium.

The page is served by the app in this process on 127.0.0.1 (a free port) and opened by
the system's Chromium through Playwright (nothing is downloaded); each screenshot is
written through a temporary file, renamed into place when complete.

Usage: python docs/scripts/explorer.py OUTPUT_DIRECTORY
"""

import shutil
import sys
import threading
from pathlib import Path

from playwright.sync_api import sync_playwright
from werkzeug.serving import make_server

from spinimpact.explore.app import create_app
from spinimpact.io import atomic_path

#: (file, address query, window width, what to capture: "page" or an element's id)
SHOTS = (
    ("explorer_ball.png", "?problem=sphere&ball=tennis&surface=hard&speed=90&speed_unit=km/h"
     "&angle=16&heading=0&spin=2500&spin_axis=topspin", 1280, "page"),
    ("explorer_map.png", "?problem=paper&speed=5&angle=53.13&spin=95.5&mu=0.2&kappa=0.8",
     1280, "map"),
    ("explorer_rod.png", "?problem=planar&shape=rod&orientation=45&speed=2&angle=80&spin=0"
     "&mu=0.3&kappa=0.8&law=newton", 1280, "process"),
    ("explorer_phone.png", "?problem=paper", 390, "page"),
)  # fmt: skip


def main(folder: str) -> None:
    out = Path(folder)
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise SystemExit("the screenshots need Debian's chromium (apt-get install chromium)")
    httpd = make_server("127.0.0.1", 0, create_app().server, threaded=True)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{httpd.server_port}/"
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=chromium,
                                        args=["--no-sandbox", "--disable-gpu"])  # fmt: skip
            for name, query, width, what in SHOTS:
                page = browser.new_page(viewport={"width": width, "height": 900})
                page.goto(base + query)
                page.wait_for_selector("#table-result")
                page.wait_for_timeout(1500)  # the graphs drawn and resized
                with atomic_path(out / name) as tmp:
                    target = page if what == "page" else page.locator(f"#{what}")
                    target.screenshot(path=str(tmp), type="png")
                page.close()
            browser.close()
    finally:
        httpd.shutdown()


if __name__ == "__main__":
    main(sys.argv[1])
