"""The explorer's page in headless Chromium (Playwright, the system's ``chromium``).

Twenty seeded settings are typed and clicked into the page; for each, the page's
downloaded JSON is compared with the library's solver called here on the same inputs (to
the last bit), the inputs with the speed, angle and spin typed (to rounding), and the
numbers shown with the solver's to six significant digits. A bad input shows its message
and leaves the last good view; an address opened in a new page gives the same view; the
console shows no error; nothing is wider than the window at 1280 px and 390 px.
"""

from __future__ import annotations

import json
import math
import random
import threading

import numpy as np
import pytest

from spinimpact import (
    BALLS,
    GROUNDS,
    Body,
    Pendulum,
    PlanarBody,
    Walton,
    solve,
    solve_pair,
    solve_pendulum,
    solve_planar,
    solve_sphere,
)
from spinimpact.explore import settings as st
from spinimpact.explore import views

from tests.viz.browser import launched

pytestmark = [pytest.mark.browser, pytest.mark.slow]

UNITS = {"m/s": 1.0, "km/h": 1 / 3.6, "mph": 0.44704}
RPM = 2 * math.pi / 60  # rad/s per rpm
_OVERFLOW = """() => {
    const doc = document.documentElement;
    const wide = [...document.querySelectorAll('body *')].filter(e => {
        const r = e.getBoundingClientRect();
        return r.width > 0 && r.right > doc.clientWidth + 1;
    }).slice(0, 3).map(e => e.tagName.toLowerCase() + '#' + e.id + '.' + e.className);
    return {scroll: doc.scrollWidth, client: doc.clientWidth, wide: wide};
}"""


@pytest.fixture(scope="module")
def server():
    pytest.importorskip("dash", reason="the explorer needs the [explore] extra")
    from werkzeug.serving import make_server

    from spinimpact.explore.app import create_app

    httpd = make_server("127.0.0.1", 0, create_app().server, threaded=True)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_port}/"
    httpd.shutdown()
    thread.join()


@pytest.fixture(scope="module")
def browser():
    yield from launched()


@pytest.fixture(scope="module")
def context(browser):
    """One browser profile for the module's pages (its cache keeps the page's scripts)."""
    context = browser.new_context(viewport={"width": 1280, "height": 900}, accept_downloads=True)
    yield context
    context.close()


@pytest.fixture
def page(context):
    page = context.new_page()
    page.errors = []
    page.on("console", lambda m: page.errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: page.errors.append(str(e)))
    page.on(
        "request",
        lambda r: (
            None
            if r.url.startswith("http://127.0.0.1")
            else page.errors.append(f"a request off this computer: {r.url}")
        ),
    )
    yield page
    page.close()


def draw(rng: random.Random, kind: str) -> dict[str, str]:
    """Random values for every field of ``kind`` (some may make an impossible setting)."""
    v = {
        "problem": kind,
        "speed": f"{rng.uniform(0.5, 30):.4g}",
        "speed_unit": rng.choice(list(UNITS)),
        "angle": f"{rng.uniform(5, 85):.4g}",
        "spin": f"{rng.uniform(-3000, 3000):.5g}",
        "mu": f"{rng.uniform(0, 1):.3g}",
        "kappa": f"{rng.uniform(0, 1):.3g}",
    }
    if kind == "paper":
        v |= {
            "body": rng.choice(st.FIELDS["body"].choices),
            "radius": f"{rng.uniform(0.02, 0.2):.3g}",
            "mass": f"{rng.uniform(0.1, 3):.3g}",
            "tangential": rng.choice(["rigid", "walton"]),
            "beta0": f"{rng.uniform(-1, 1):.3g}",
        }
    if kind == "sphere":
        v |= {
            "ball": rng.choice(["custom", "tennis", "golf"]),
            "surface": rng.choice(["custom", "clay", "table"]),
            "heading": f"{rng.uniform(-180, 180):.4g}",
            "spin_axis": rng.choice(["topspin", "backspin", "sidespin", "0.3,-1,2"]),
            "body": rng.choice(["solid-sphere", "spherical-shell"]),
            "radius": "0.04",
            "mass": "0.1",
            "tangential": rng.choice(["rigid", "rigid", "walton"]),
            "beta0": "0.3",
        }
        if v["surface"] != "custom" and rng.random() < 0.5:
            v |= {"mu": "", "kappa": ""}  # from the preset
    if kind == "pair":
        v |= {
            "ball": rng.choice(["custom", "tennis", "soccer"]),
            "body": "spherical-shell",
            "mass": "0.2",
            "radius": "0.03",
            "heading": f"{rng.uniform(-60, 60):.4g}",
            "spin_axis": rng.choice(["topspin", "sidespin", "1,1,0"]),
            "normal": rng.choice(["-1,0,0.3", "-1,0.2,-0.5", "-2,0,1"]),
        }
    if kind in ("planar", "pendulum"):
        v |= {
            "shape": rng.choice(["rod", "block"]),
            "length": f"{rng.uniform(0.2, 2):.3g}",
            "width": "0.3",
            "height": "0.1",
            "orientation": f"{rng.uniform(10, 80):.3g}",
            "law": rng.choice(["poisson", "newton", "energetic"]),
            "mass": "2",
        }
    if kind == "pendulum":
        v["spin"] = f"{-rng.uniform(5, 200):.4g}"
    return v


def seeded(seed: int, n: int = 20) -> list[dict[str, str]]:
    """``n`` random valid settings, each reached from the one before as a person would: a
    new problem with two of its fields typed, or one or two fields changed (a setting the
    library refuses is drawn again)."""
    rng = random.Random(seed)
    kinds = ["paper", "sphere", "planar", "pendulum", "pair", "sphere"]
    out: list[dict[str, str]] = []
    while len(out) < n:
        if not out or rng.random() < 0.25:
            kind = kinds[len(out) % len(kinds)] if out else "paper"
            fresh = draw(rng, kind)
            names = [k for k in st.relevant(st.defaults(kind)) if k != "problem"]
            v = st.defaults(kind) | {k: fresh[k] for k in rng.sample(names, 2)}
        else:
            now = out[-1]
            fresh = draw(rng, now["problem"])
            names = [k for k in st.relevant(now) if k != "problem" and k in fresh]
            v = now | {k: fresh[k] for k in rng.sample(names, rng.choice([1, 2]))}
        full = st.defaults(v["problem"]) | v  # every field that applies, given explicitly
        v = {k: full[k] for k in st.relevant(full)}
        if not st.evaluate(v).errors:
            out.append(v)
    return out


def open_page(page, address: str) -> None:
    """Open ``address`` and wait for its first view (before it, the page's first answer
    would overwrite what is typed)."""
    page.goto(address)
    page.wait_for_selector("#table-result", timeout=30_000)


def set_through_the_page(page, values: dict[str, str]) -> None:
    """Click the radio buttons and type into the boxes, as a person would."""
    order = ["problem", "ball", "surface", "shape", "tangential"]
    for name in sorted(values, key=lambda n: order.index(n) if n in order else len(order)):
        f = st.FIELDS[name]
        if f.choices is not None:
            box = page.locator(f"#in-{name} input[value='{values[name]}']")
            if not box.is_checked():
                box.check()
                if name == "problem":  # the page fills the new problem's defaults: wait
                    page.wait_for_function(
                        "k => location.search.startsWith('?problem=' + k)", arg=values[name]
                    )
        elif page.input_value(f"#in-{name}") != values[name]:
            page.fill(f"#in-{name}", values[name])
            page.press(f"#in-{name}", "Enter")


def wait_for(page, values: dict[str, str]) -> st.Setting:
    """Wait until the page shows ``values``' impact (its command line), else say what it shows."""
    s = st.evaluate(values).setting
    try:
        page.wait_for_function(
            "c => document.querySelector('#command')?.textContent === c",
            arg=s.command,
            timeout=30_000,
        )
    except Exception as exc:  # a timeout: what the page shows instead
        errors = page.locator(".error").all_inner_texts()
        raise AssertionError(
            f"the page shows {page.inner_text('#command')!r} at {page.url} "
            f"with messages {[e for e in errors if e]}, not {s.command!r}"
        ) from exc
    return s


def download(page) -> dict:
    with page.expect_download() as got:
        page.click("#get-json")
    with open(got.value.path()) as f:
        return json.load(f)


def shown(page) -> dict[str, str]:
    rows = page.locator("#table-result tbody tr").all_inner_texts()
    return {r.split("\t")[0]: r.split("\t")[1] for r in rows}


def expected(values: dict[str, str], inputs: dict) -> tuple[dict, object]:
    """The inputs typed, converted here, and the library's solver on the page's inputs."""
    v = defaults = st.defaults(values["problem"]) | values
    kind = v["problem"]
    preset = GROUNDS.get(v.get("surface", "")) if kind == "sphere" else None
    mu = float(v["mu"]) if v["mu"] else (preset.mu if preset else 0.2)  # the library's default
    kappa = float(v["kappa"]) if v["kappa"] else (preset.kappa if preset else 0.8)
    typed: dict = {"mu": mu, "kappa": kappa, "omega": float(v["spin"]) * RPM}
    if kind != "pendulum":
        speed = float(v["speed"]) * UNITS[v["speed_unit"]]
        a = math.radians(float(v["angle"])) if kind != "pair" else 0.0  # a pair: on a table
        h = math.radians(float(v.get("heading", "0")))
        # headings turn counter-clockwise seen from above (+y): 90 degrees is -z
        e = np.array([math.cos(h), 0.0, -math.sin(h)])
        vel = speed * (math.cos(a) * e - math.sin(a) * np.array([0.0, 1.0, 0.0]))
        typed |= {"vx": vel[0], "vy": vel[1]}
    if kind in ("sphere", "pair"):
        axis = {
            "topspin": np.cross([0, 1, 0], e),
            "backspin": -np.cross([0, 1, 0], e),
            "sidespin": np.array([0.0, 1.0, 0.0]),
        }.get(v["spin_axis"])
        if axis is None:
            axis = np.array([float(x) for x in v["spin_axis"].split(",")])
        spin = float(v["spin"]) * RPM * axis / np.linalg.norm(axis)
        typed = {"mu": mu, "kappa": kappa, "vx": vel[0], "vy": vel[1], "vz": vel[2]}
        typed |= {"wx": spin[0], "wy": spin[1], "wz": spin[2]}
    law = Walton(float(v["beta0"])) if v.get("tangential") == "walton" else None
    if kind == "paper":
        body = Body.preset(v["body"], mass=float(v["mass"]), radius=float(v["radius"]))
        res = solve(
            body, inputs["vx"], inputs["vy"], inputs["omega"], mu=mu, kappa=kappa, tangential=law
        )
    elif kind == "pair":
        body = (
            BALLS[v["ball"]].body
            if v["ball"] != "custom"
            else Body.preset(v["body"], mass=float(v["mass"]), radius=float(v["radius"]))
        )
        res = solve_pair(
            body,
            body,
            velocity1=[inputs[k] for k in ("vx", "vy", "vz")],
            spin1=[inputs[k] for k in ("wx", "wy", "wz")],
            velocity2=np.zeros(3),
            spin2=np.zeros(3),
            mu=mu,
            kappa=kappa,
            normal=[inputs[f"normal_{k}"] for k in "xyz"],
        )
    elif kind == "sphere":
        body = (
            BALLS[v["ball"]].body
            if v["ball"] != "custom"
            else Body.preset(v["body"], mass=float(v["mass"]), radius=float(v["radius"]))
        )
        velocity = [inputs["vx"], inputs["vy"], inputs["vz"]]
        res = solve_sphere(
            body,
            velocity,
            [inputs["wx"], inputs["wy"], inputs["wz"]],
            mu=mu,
            kappa=kappa,
            tangential=law,
        )
    else:
        angle = math.radians(float(v["orientation"]))
        m = float(v["mass"])
        if kind == "pendulum":
            body = Pendulum.rod(mass=m, length=float(v["length"]), angle=angle)
            res = solve_pendulum(body, inputs["omega"], mu=mu, kappa=kappa, law=v["law"])
        else:
            body = (
                PlanarBody.rod(mass=m, length=float(v["length"]), angle=angle)
                if v["shape"] == "rod"
                else PlanarBody.block(
                    mass=m, width=float(v["width"]), height=float(v["height"]), angle=angle
                )
            )
            res = solve_planar(
                body, inputs["vx"], inputs["vy"], inputs["omega"], mu=mu, kappa=kappa, law=v["law"]
            )
    del defaults
    return typed, res


def check_against_the_library(page, values: dict[str, str]) -> dict:
    data = download(page)
    typed, res = expected(values, data["inputs"])
    for name, x in typed.items():  # the page converted what was typed as we do, to rounding
        assert math.isclose(data["inputs"][name], x, rel_tol=1e-13, abs_tol=1e-13), name
    exact = res.columns()
    assert set(data["result"]) == set(exact)
    table = shown(page)
    for name, got in data["result"].items():
        want = np.asarray(exact[name]).reshape(-1)[0]
        if isinstance(got, str) and want.dtype.kind == "f":  # inf, -inf, nan
            assert got == str(float(want)), name
        elif isinstance(got, float):
            assert got == float(want), name  # the same solver on the same inputs: every bit
            if name in table:
                text = table[name]
                on_page = float(text)
                assert abs(on_page - got) <= 5e-6 * abs(got) + 1e-300, (name, text, got)
        else:
            assert got == want.item(), name
    return data


def test_twenty_seeded_settings_typed_in_match_the_library(server, page):
    open_page(page, server)
    page.wait_for_selector("#table-result")
    settings = seeded(58)  # a seed whose 20 settings cover every problem and law
    assert {v["problem"] for v in settings} == set(st.PROBLEMS)
    for values in settings:
        set_through_the_page(page, values)
        wait_for(page, values)
        check_against_the_library(page, values)
    assert page.errors == []


def test_a_bad_input_shows_its_message_and_keeps_the_last_good_view(server, page):
    open_page(page, server + "?problem=sphere")
    good = wait_for(page, {"problem": "sphere"})
    page.wait_for_selector("#table-result")
    table = page.inner_text("#tables")
    for name, text, words in (
        ("mu", "-0.5", "mu must be >= 0"),
        ("speed", "fast", "speed must be a number"),
        ("spin_axis", "up", "--spin-axis must be"),
    ):
        page.fill(f"#in-{name}", text)
        page.press(f"#in-{name}", "Enter")
        page.wait_for_function(
            "([n, w]) => document.querySelector('#err-' + n).textContent.includes(w)",
            arg=[name, words],
        )
        assert page.inner_text("#command") == good.command
        assert page.inner_text("#tables") == table
        page.fill(f"#in-{name}", st.defaults("sphere")[name])
        page.press(f"#in-{name}", "Enter")
        page.wait_for_function(
            "n => document.querySelector('#err-' + n).textContent === ''", arg=name
        )
    assert page.errors == []


def test_the_address_reproduces_the_view(server, page, context):
    open_page(page, server)
    values = {"problem": "planar", "shape": "block", "speed": "3.5", "law": "newton"}
    set_through_the_page(page, values)
    wait_for(page, values)
    first = download(page)
    other = context.new_page()
    open_page(other, page.url)
    wait_for(other, values)
    assert download(other) == first
    assert other.url == page.url
    assert page.errors == []


def test_pinning_shows_the_differences(server, page):
    open_page(page, server + "?problem=paper&mu=0.1")
    wait_for(page, {"problem": "paper", "mu": "0.1"})
    page.click("#pin")
    page.fill("#in-mu", "0.4")
    page.press("#in-mu", "Enter")
    wait_for(page, {"problem": "paper", "mu": "0.4"})
    page.wait_for_selector("#table-compare")
    rows = {
        r.split("\t")[0]: r.split("\t")
        for r in page.locator("#table-compare tbody tr").all_inner_texts()
    }
    assert rows["mu"][1:3] == ["0.1", "0.4"] if "mu" in rows else True
    data = download(page)
    assert data["pinned"]["inputs"]["mu"] == 0.1 and data["inputs"]["mu"] == 0.4
    assert page.errors == []


def test_nothing_is_wider_than_the_window(server, page, tmp_path):
    open_page(page, server)
    found = page.evaluate(_OVERFLOW)  # the paper's body, as the page opens
    assert found["scroll"] <= found["client"] + 1, ("paper", found)
    for width in (1280, 390):
        page.set_viewport_size({"width": width, "height": 900})
        for kind in ("sphere", "planar") if width == 1280 else ("planar", "paper", "sphere"):
            page.locator(f"#in-problem input[value='{kind}']").check()
            wait_for(page, {"problem": kind})
            page.wait_for_selector("#table-result")
            page.wait_for_timeout(300)  # the graphs' own resize
            found = page.evaluate(_OVERFLOW)
            assert found["scroll"] <= found["client"] + 1, (width, kind, found)
            if kind == "sphere":  # looked at when the page changes
                page.screenshot(path=str(tmp_path / f"{kind}-{width}.png"), full_page=True)
    assert page.errors == []


def test_a_click_on_the_map_moves_the_incidence_there(server, page):
    open_page(page, server + "?problem=paper")
    before = wait_for(page, {"problem": "paper"})
    page.wait_for_selector("#map .nsewdrag")
    page.locator("#map .nsewdrag").scroll_into_view_if_needed()
    box = page.locator("#map .nsewdrag").bounding_box()  # the plot area: a in [0, 3], b in [-3, 3]
    x, y = box["x"] + 0.5 * box["width"], box["y"] + 0.25 * box["height"]
    page.mouse.move(x - 5, y)  # Plotly reports a click on the point it hovers
    page.mouse.move(x, y)
    page.wait_for_timeout(200)
    page.mouse.click(x, y)
    page.wait_for_function(
        "c => document.querySelector('#command')?.textContent !== c", arg=before.command
    )
    moved = st.from_query(page.evaluate("location.search"))
    point = views.map_point(st.evaluate(moved).setting)
    # the middle of the plot, a quarter from its top: (1.5, 1.5) to a heatmap cell's width
    np.testing.assert_allclose(point, (1.5, 1.5), atol=0.05)
    assert page.errors == []
