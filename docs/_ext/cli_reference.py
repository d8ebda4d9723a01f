"""``.. cli-reference::``: every command of ``spinimpact`` and every option, from the commands.

The page is generated from the Click commands themselves (their help, each visible
option's names, help text (which carries its unit), default and choices), so it cannot
disagree with ``spinimpact COMMAND --help``. Hidden options (deprecated aliases) are left
out, as ``--help`` leaves them out.
"""

from __future__ import annotations

import click
from docutils import nodes
from docutils.statemachine import StringList
from sphinx.util.docutils import SphinxDirective


def _default(param: click.Parameter) -> str:
    if param.is_flag if isinstance(param, click.Option) else False:
        return ""
    value = param.default
    if value is None or callable(value) or value == () or value == "":
        return ""
    return f"``{value}``"


def _kind(param: click.Parameter) -> str:
    kind = param.type
    if isinstance(kind, click.Choice):
        return "one of " + ", ".join(f"``{c}``" for c in kind.choices)
    if isinstance(param, click.Option) and param.is_flag:
        return "flag"
    return kind.name


def _escape(text: str) -> str:
    return text.replace("*", "\\*").replace("`", "\\`").replace("|", "\\|")


def command_lines(name: str, command: click.Command) -> list[str]:
    """The reST of one command: its help, then a table of its visible options."""
    title = f"spinimpact {name}"
    lines = [f".. _cli-{name}:", "", title, "-" * len(title), ""]
    text = (command.help or "").replace("\b\n", "").strip()
    lines += [".. code-block:: text", ""] + [f"   {line}" for line in text.splitlines()] + [""]
    params = [p for p in command.params if not getattr(p, "hidden", False)]
    arguments = [p for p in params if isinstance(p, click.Argument)]
    if arguments:
        shown = " ".join(p.human_readable_name for p in arguments)
        lines += [f"Arguments: ``{shown}``", ""]
    options = [p for p in params if isinstance(p, click.Option)]
    if options:
        lines += [
            ".. list-table::",
            "   :header-rows: 1",
            "   :widths: 25 15 12 48",
            "",
            "   * - option",
            "     - takes",
            "     - default",
            "     - meaning",
        ]
        for p in options:
            names = ", ".join(f"``{o}``" for o in p.opts + p.secondary_opts)
            lines += [
                f"   * - {names}",
                f"     - {_kind(p)}",
                f"     - {_default(p)}",
                f"     - {_escape(' '.join((p.help or '').split()))}",
            ]
        lines.append("")
    return lines


def problem_lines() -> list[str]:
    """The reST of every registered problem's inputs, as ``--problem NAME`` takes them:
    ``sweep --problem NAME`` options (``--name`` for input ``name``) and ``--set name=...``
    on ``batch``, ``solve``, ``report`` and ``fit``."""
    from spinimpact import problems

    title = "The inputs of each problem"
    lines = [
        ".. _cli-problems:",
        "",
        title,
        "-" * len(title),
        "",
        "With ``--problem NAME``, ``spinimpact sweep`` takes each input of the problem",
        "as an option (a value, a grid ``START:STOP:NUM`` or random ``uniform:LOW:HIGH``),",
        "and ``batch``, ``solve``, ``report`` and ``fit`` take ``--set INPUT=VALUE``.",
        "",
    ]
    for declared in problems():
        lines += [
            f"``--problem {declared.name}``: {declared.summary}",
            "",
            ".. list-table::",
            "   :header-rows: 1",
            "   :widths: 22 18 10 14 36",
            "",
            "   * - option",
            "     - ``--set`` name",
            "     - unit",
            "     - default",
            "     - meaning and rule",
        ]
        for each in declared.inputs:
            flag = "--" + each.name.replace("_", "-")
            default = (
                "required"
                if each.required
                else ("" if each.default is None else f"``{each.default}``")
            )
            lines += [
                f"   * - ``{flag}``",
                f"     - ``{each.name}``",
                f"     - {each.unit or ''}",
                f"     - {default}",
                f"     - {_escape(each.description)} ({_escape(each.rule_text)})",
            ]
        lines.append("")
    return lines


class CliReference(SphinxDirective):
    """Every command of the ``spinimpact`` group, in order."""

    def run(self) -> list[nodes.Node]:
        from spinimpact.cli import cli

        lines: list[str] = []
        for name in sorted(cli.commands):
            command = cli.commands[name]
            if getattr(command, "hidden", False):
                continue
            lines += command_lines(name, command)
        lines += problem_lines()
        node = nodes.section()
        node.document = self.state.document
        self.state.nested_parse(StringList(lines, "cli-reference"), 0, node)
        return node.children


def setup(app):  # noqa: ANN001, ANN201 - Sphinx's signature
    app.add_directive("cli-reference", CliReference)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
