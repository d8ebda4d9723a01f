"""One table builder for both reports: the terminal report and the HTML page show
the same rows, with the same value strings, taken from ``viz.tables``."""

import io
import re
from html.parser import HTMLParser

import pytest
from rich.console import Console

from spinimpact import Body, solve, solve_particle
from spinimpact.dynamics import LinearContact, simulate
from spinimpact.viz.report import print_report, print_simulation
from spinimpact.viz.tables import impact_tables, number, regime_summary, simulation_table

pytest.importorskip("matplotlib")

# (body, vx, vy, omega, mu, kappa): one case per regime the report words differently
CASES = {
    "stick-restitution": (Body.solid_sphere(mass=1.0, radius=0.1), 3.0, -4.0, 10.0, 0.2, 0.8),
    "slip": (Body.solid_disk(mass=2.0, radius=0.05), 1.5, -2.0, -80.0, 0.1, 0.6),
    "frictionless": (Body.ring(mass=1.0, radius=0.1), 0.5, -1.0, 0.0, 0.0, 1.0),
    "energy-creating particle": (Body.solid_sphere(mass=1.0, radius=0.1), 0.1, -1.0, 0.0, 0.5, 0.8),
}


def _case(name):
    body, vx, vy, omega, mu, kappa = CASES[name]
    imp = solve(body, vx, vy, omega, mu=mu, kappa=kappa)
    return imp, solve_particle(vx, vy, mu=mu, kappa=kappa, mass=body.mass)


def _terminal(printer, *args):
    out = io.StringIO()
    printer(*args, console=Console(file=out, width=200, highlight=False, soft_wrap=True))
    return out.getvalue()


class _Cells(HTMLParser):
    """The text of every ``<h2>`` and every ``<tbody>`` row of a page."""

    def __init__(self):
        super().__init__()
        self.headings, self.rows = [], []
        self._where, self._text = None, ""

    def handle_starttag(self, tag, attrs):
        if tag == "h2":
            self._where, self._text = "h2", ""
        elif tag == "tr":
            self._row = []
        elif tag == "td":
            self._where, self._text = "td", ""

    def handle_endtag(self, tag):
        if tag == "h2":
            self.headings.append(self._text)
        elif tag == "td":
            self._row.append(self._text)
        elif tag == "tr" and self._row:
            self.rows.append(tuple(self._row))
        if tag in ("h2", "td"):
            self._where = None

    def handle_data(self, data):
        if self._where:
            self._text += data


def _terminal_rows(text):
    """Every table row of a Rich report, as a tuple of stripped cells."""
    return [tuple(c.strip() for c in line.split("│")) for line in text.splitlines() if "│" in line]


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.slow
def test_terminal_and_page_show_the_same_rows(name):
    from spinimpact.viz.html import impact_report_html

    imp, particle = _case(name)
    plain = impact_tables(imp, particle)
    typeset = impact_tables(imp, particle, typeset=True)
    terminal = _terminal(print_report, imp, particle)
    page = _Cells()
    page.feed(impact_report_html(imp, particle))

    # the two notations differ in their labels only: the same tables, rows and values
    assert [t.key for t in plain] == [t.key for t in typeset]
    assert [t.key for t in plain][-1] == "particle"
    for a, b in zip(plain, typeset, strict=True):
        assert a.title == b.title and len(a.rows) == len(b.rows)
        assert a.values() == b.values()
        assert all(row[0].isascii() for row in a.rows)  # the terminal's labels are plain ASCII

    # the page: every table, its title, and exactly the builder's rows in order
    for table in typeset:
        assert table.title in page.headings
    # (the page sets a label's scripts as <sub>/<sup>: W_r^n reads W, r, n in its text)
    scripts = [(re.sub(r"[_^]", "", row[0]), *row[1:]) for t in typeset for row in t.rows]
    assert page.rows == scripts

    # the terminal: every row with its label and values in the same cells; the outcome
    # flags as one line
    rows = _terminal_rows(terminal)
    for table in plain:
        if table.key == "outcome":
            line = ", ".join(f"{label}: {value}" for label, value in table.rows)
            assert f"Outcome: {line}" in terminal
        else:
            assert table.title in terminal
            for row in table.rows:
                assert row in rows, (table.key, row)
        if table.note:
            assert table.note in terminal
    assert regime_summary(imp) in terminal


def test_tables_hold_the_impact_numbers():
    imp, _ = _case("stick-restitution")
    tables = {t.key: t for t in impact_tables(imp)}
    assert tables["rebound"].rows[0] == ("vx (m/s)", "3", "1.85714")  # 3 - 4/3.5
    assert tables["rebound"].rows[2] == ("omega (rad/s)", "10", "-18.5714")  # -vx+/R
    assert tables["inputs"].rows[1] == ("mass m", "1 kg")
    works = tables["works"].rows
    assert works[2][1:] == tuple(
        number(x)
        for x in (
            imp.work_compression_normal + imp.work_restitution_normal,
            imp.work_compression_tangential + imp.work_restitution_tangential,
            -imp.dissipated_energy,  # the total work of the contact forces is -Delta E
        )
    )
    assert tables["energy"].rows[2][2] == f"{float(imp.dissipated_fraction):.2%}"


def test_undefined_and_infinite_values_read_the_same_everywhere():
    imp, _ = _case("frictionless")
    tables = {t.key: t for t in impact_tables(imp)}
    assert ("end of slip, tau*", "inf") in tables["impulses"].rows
    assert tables["coefficients"].rows[-1][1] == "undefined"  # no friction work
    assert tables["rebound"].rows[2] == ("omega (rad/s)", "0", "0")  # never "-0"
    assert number(-0.0) == "0" and number(float("-inf"), "N s") == "-inf N s"


def test_energy_verdicts():
    imp, particle = _case("energy-creating particle")
    table = impact_tables(imp, particle)[-1]
    assert table.rows[-1] == ("energy", "dissipates energy", "creates energy")
    assert "whenever |vx/vy| < 0.25" in table.note  # [(1+kappa) mu^2 + kappa - 1]/(2 mu)
    imp, particle = _case("frictionless")  # kappa = 1, mu = 0: nothing is lost
    assert impact_tables(imp, particle)[-1].rows[-1][1:] == ("conserves energy",) * 2


def test_builder_rejects_arrays():
    imp = solve(Body.ring(mass=1.0, radius=0.1), [1.0, 2.0], -1.0, 0.0, mu=0.2, kappa=0.5)
    with pytest.raises(ValueError, match="one impact"):
        impact_tables(imp)


def test_simulation_report_prints_the_builder_rows():
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    sim = simulate(body, 3.0, -4.0, 10.0, mu=0.2, contact=LinearContact(1e6, 0.0))
    table = simulation_table(sim)
    text = _terminal(print_simulation, sim)
    rows = _terminal_rows(text)
    for row in table.rows:
        assert row in rows, row
    assert table.note in text
    # the rigid column is the closed form at the law's restitution (here 1)
    assert table.rows[0][2] == number(sim.rigid().after.vx)
    assert re.search(r"contact duration [\d.]+ ms", text)


def test_every_label_has_its_typeset_form():
    """No ASCII symbol name is left on the page, and no typeset form is unused (a
    misspelt key would silently leave its label in ASCII)."""
    from spinimpact.viz._labels import TYPESET

    used = set()
    for name in CASES:
        imp, particle = _case(name)
        for table in impact_tables(imp, particle, typeset=True):
            text = " ".join([*table.columns, *(row[0] for row in table.rows), table.note])
            for ascii_name in ("omega", "tau", "rho", "zeta", "kappa", "mu_hat", "sqrt", "<="):
                assert ascii_name not in text, (name, table.key, ascii_name)
        assert "zeta" not in regime_summary(imp, typeset=True)
        plain = impact_tables(imp, particle)
        used |= {c for t in plain for c in t.columns} | {row[0] for t in plain for row in t.rows}
        used |= {key for key in TYPESET if any(key in t.note for t in plain)}
        used |= {key for key in TYPESET if key in regime_summary(imp)}
    assert set(TYPESET) <= used, set(TYPESET) - used


def test_times_in_a_unit_that_suits_them():
    """A 6 µs Hertz contact is printed in µs (not '0.00618 ms'), with its stick time."""
    from spinimpact.dynamics import HertzContact
    from spinimpact.viz.tables import duration

    assert [duration(t) for t in (6.18087e-6, 9.99e-4, 1e-3, 0.5, 1.0, -0.0)] == [
        "6.18087 µs", "999 µs", "1 ms", "500 ms", "1 s", "0 µs"]  # fmt: skip
    ball = Body.solid_sphere(mass=2.618e-4, radius=0.0025)
    law = HertzContact(youngs_modulus=3.8e11, poisson_ratio=0.23, radius=0.0025)
    sim = simulate(ball, 1.334, -3.665, 0.0, mu=0.092, contact=law)
    text = _terminal(print_simulation, sim)
    assert f"contact duration {sim.contact_duration * 1e6:.6g} µs," in text
    assert f"slip stops at t = {sim.stick_time * 1e6:.6g} µs" in text
