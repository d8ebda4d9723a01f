"""One vocabulary: every visible option of every command has one name, one meaning and one
unit, from the table in :mod:`spinimpact.cli._vocabulary`; old names are hidden and warn."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from spinimpact.cli import cli, main
from spinimpact.cli._vocabulary import TERMS, Deprecated, concept

ROOT = Path(__file__).resolve().parents[2]


def _commands(group: click.Group, prefix: str = "") -> dict[str, click.Command]:
    """Every command, those of nested groups included (whatever built them)."""
    out = {}
    for name, command in group.commands.items():
        out[prefix + name] = command
        if isinstance(command, click.Group):
            out.update(_commands(command, f"{prefix}{name} "))
    return out


def _visible() -> list[tuple[str, str, click.Option]]:
    return [
        (cmd, opt, param)
        for cmd, command in _commands(cli).items()
        for param in command.params
        if isinstance(param, click.Option) and not param.hidden
        for opt in param.opts
        if opt.startswith("--") and opt != "--help"
    ]


def test_every_visible_option_is_in_the_table():
    missing = sorted({f"{cmd} {opt}" for cmd, opt, _ in _visible() if concept(opt) not in TERMS})
    assert not missing, f"options not in cli/_vocabulary.py TERMS: {missing}"


def test_no_two_names_share_a_meaning():
    seen: dict[str, str] = {}
    for name, term in TERMS.items():
        key = re.sub(r"\W+", " ", term.meaning.lower()).strip()
        assert key not in seen, f"--{name} and --{seen[key]} mean the same: {term.meaning!r}"
        seen[key] = name


def test_each_name_has_one_meaning_and_unit_everywhere():
    """Each option's help begins with its term's meaning and unit, on every command."""
    wrong = [
        f"{cmd} {opt}: {param.help!r} does not begin with {TERMS[concept(opt)].text!r}"
        for cmd, opt, param in _visible()
        if concept(opt) in TERMS and not (param.help or "").startswith(TERMS[concept(opt)].text)
    ]
    assert not wrong, "\n".join(wrong)


def test_units_in_names_agree_with_the_table():
    for name, term in TERMS.items():
        if name.endswith("-deg"):
            assert term.unit == "degrees", name
        if name.endswith("-rpm"):
            assert term.unit == "rpm", name
        # angles are in degrees on the command line: no option is in radians
        assert not re.search(r"\b(radians?|rad)\b(?!/)", term.text), name


def test_the_table_would_catch_a_new_name_for_an_old_concept():
    """The check above is not vacuous: a second name for spin rate is caught."""
    terms = dict(TERMS, rpm=TERMS["spin-rpm"])
    keys = [re.sub(r"\W+", " ", t.meaning.lower()).strip() for t in terms.values()]
    assert len(set(keys)) < len(keys)


def test_the_conventions_page_lists_every_option():
    page = (ROOT / "docs" / "conventions.md").read_text(encoding="utf-8")
    absent = [name for name in TERMS if f"`--{name}`" not in page]
    assert not absent, f"docs/conventions.md does not list: {absent}"


def test_the_conventions_page_is_linked():
    for doc in ("README.md", "docs/architecture.md"):
        assert "conventions.md" in (ROOT / doc).read_text(encoding="utf-8"), doc


# Each old name: the command with it and with the new name, which must agree.
ALIASES = [
    ("sphere", "--angle-deg 16", "--incidence-from-surface-deg 16", "--speed 20"),
    (
        "sphere",
        "--direction-deg 30",
        "--heading-deg 30",
        "--speed 20 --incidence-from-surface-deg 16",
    ),
    ("sphere", "--rpm 3000 --axis topspin", "--spin-rpm 3000 --spin-axis topspin", ""),
    ("pair", "--direction1-deg 10", "--heading1-deg 10", "--speed1 2"),
    ("pair", "--rpm2 600 --axis2 backspin", "--spin2-rpm 600 --spin2-axis backspin", "--speed2 1"),
    ("planar", "--angle-deg 30", "--orientation-deg 30", ""),
    ("planar", "--angle 0.5", "--orientation-deg 28.64788975654116", ""),
    (
        "flight",
        "--angle -6 --height 2.8",
        "--elevation-deg -6 --launch-height 2.8",
        "--max-bounces 1",
    ),
    ("flight", "--direction 20", "--heading-deg 20", "--max-bounces 1"),
    (
        "flight",
        "--wall-distance 5 --wall-direction 10",
        "--wall-distance 5 --wall-heading-deg 10",
        "--max-bounces 1",
    ),
    (
        "flight",
        "--samples 3 --angle-sd 1 --direction-sd 2 --spin-sd 30",
        "--samples 3 --elevation-sd-deg 1 --heading-sd-deg 2 --spin-sd-rpm 30",
        "--max-bounces 1",
    ),
    ("simulate", "--target-kappa 0.7", "--kappa 0.7", ""),
]


def _run(capsys, line: str) -> tuple[str, str]:
    main(line.split())
    out = capsys.readouterr()
    return out.out, out.err


@pytest.mark.parametrize(("command", "old", "new", "rest"), ALIASES)
@pytest.mark.slow
def test_an_old_name_still_works_and_warns_once(capsys, command, old, new, rest):
    as_json = "" if command == "simulate" else "--json"  # simulate prints a report
    old_out, old_err = _run(capsys, f"{command} {old} {rest} {as_json}")
    new_out, new_err = _run(capsys, f"{command} {new} {rest} {as_json}")
    if "--angle " in old and command == "planar":  # radians vs degrees: rounding apart
        a, b = json.loads(old_out), json.loads(new_out)
        assert a["after"] == pytest.approx(b["after"], rel=1e-12)
    else:  # simulate's report names the option that set kappa
        assert old_out.replace("--target-kappa", "--kappa") == new_out
    for flag in re.findall(r"--[a-z0-9-]+", old):
        if flag not in new:
            assert old_err.count(f"{flag} is deprecated; use --") == 1, old_err
    assert "deprecated" not in new_err


def test_old_names_are_hidden_and_deprecated():
    hidden = {
        opt
        for command in _commands(cli).values()
        for p in command.params
        if isinstance(p, Deprecated)
        for opt in p.opts
    }
    assert {"--angle-deg", "--rpm", "--axis", "--angle", "--direction", "--target-kappa"} <= hidden
    for command in _commands(cli).values():
        for p in command.params:
            if isinstance(p, Deprecated):
                assert p.hidden


def test_an_old_name_with_its_new_one_is_refused():
    result = CliRunner().invoke(
        cli, ["sphere", "--rpm", "1", "--spin-rpm", "2", "--spin-axis", "x"]
    )
    assert result.exit_code == 2
    assert "give --spin-rpm or its old name --rpm, not both" in result.output


def _json(capsys, line: str) -> dict:
    out, err = _run(capsys, line + " --json")
    assert err == ""
    return json.loads(out)


def test_sphere_presets_are_their_numbers(capsys):
    from spinimpact import BALLS, GROUNDS

    b, g = BALLS["tennis"], GROUNDS["clay"]
    person = "sphere --speed 20 --incidence-from-surface-deg 16 --spin-rpm 2000 --spin-axis topspin"
    preset = _json(capsys, f"{person} --ball tennis --surface clay")
    plain = _json(
        capsys,
        f"{person} --mass {b.mass!r} --radius {b.radius!r} --gyration {b.gyration!r} "
        f"--mu {g.mu!r} --kappa {g.kappa!r}",
    )
    assert preset["after"] == plain["after"]
    assert preset["after"] != _json(capsys, person)["after"]  # the default 1 kg ball differs
    mu = _json(capsys, f"{person} --ball tennis --surface clay --mu 0.1")
    assert mu["mu"] == 0.1 and mu["kappa"] == g.kappa  # a typed mu overrides the preset's


def test_speed_units_convert_once(capsys):
    base = "sphere --incidence-from-surface-deg 30 --heading-deg 0"
    si = _json(capsys, f"{base} --speed 20")
    assert _json(capsys, f"{base} --speed 72 --speed-unit km/h")["before"] == si["before"]
    mph = _json(capsys, f"{base} --speed 10 --speed-unit mph")
    assert mph["before"]["vx"] == pytest.approx(10 * 0.44704 * math.cos(math.radians(30)))


def test_a_combined_spin_axis_is_the_halfway_vector(capsys):
    base = "sphere --speed 10 --incidence-from-surface-deg 30"
    got = _json(capsys, f"{base} --spin-rpm 600 --spin-axis topspin+sidespin")["before"]
    w = 600 * 2 * math.pi / 60 * math.sqrt(0.5)  # topspin along +x is -z, sidespin +y
    assert (got["wx"], got["wy"], got["wz"]) == pytest.approx((0.0, w, -w), abs=1e-12)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["sphere", "--ball", "tennis", "--mass", "2"], "give either --ball or --mass, not both"),
        (["sphere", "--speed-unit", "mph"], "--speed-unit applies to --speed"),
        (["sphere", "--spin-rpm", "1", "--spin-axis", "topspin+backspin"], "has no direction"),
        (["flight", "--spin", "0,0,-9", "--spin-rpm", "4"], "give either --spin or --spin-rpm"),
    ],
)
def test_vocabulary_refusals_are_one_line(capsys, args, message):
    with pytest.raises(SystemExit) as stop:
        main(args)
    assert stop.value.code == 2
    out = capsys.readouterr()
    assert out.out == ""
    assert out.err.startswith("spinimpact: error: ") and out.err.count("\n") == 1, out.err
    assert message in out.err
