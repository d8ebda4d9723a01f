"""Tables describing the registry of problems (``spinimpact problems``), as plain data.

Built with the report's :class:`~spinimpact.viz.tables.Table`, so the terminal (Rich)
and any page render the same rows.

Examples
--------
>>> from spinimpact import problem
>>> inputs = problem_tables(problem("pair"))[0]
>>> inputs.columns
('input', 'unit', 'default', 'rule', 'part of')
>>> inputs.rows[0]
('vx', 'm/s', 'required', 'finite', 'velocity1')
"""

from __future__ import annotations

import html
from typing import Any

import numpy as np

from ..model.registry import Problem, problems
from .tables import Table, number

__all__ = ["registry_table", "problem_tables", "result_tables", "problem_report_html"]


def registry_table() -> Table:
    """One row per registered problem: its name, what it solves, the columns that mark it."""
    rows = tuple((p.name, p.summary, ", ".join(p.marks) or "(the default)") for p in problems())
    return Table("problems", "Registered problems", ("problem", "what it solves",
                 "a file holds it when it has"), rows)  # fmt: skip


def _default(value: object, required: bool) -> str:
    if value is None:
        return "required" if required else "(none)"
    return value if isinstance(value, str) else f"{value:g}"


def problem_tables(declared: Problem) -> tuple[Table, Table]:
    """The inputs of ``declared`` (unit, default, rule, vector) and its result's columns
    with their units."""
    inputs = tuple(
        (
            i.name,
            i.unit or "",
            _default(i.default, i.required),
            i.rule_text,
            i.vector or "",
        )
        for i in declared.inputs
    )
    given = [i.name for i in declared.inputs]
    outputs = tuple((n, declared.unit(n) or "") for n in declared.outputs(given))
    return (
        Table(
            "inputs",
            f"Inputs of {declared.name!r}: {declared.summary}",
            ("input", "unit", "default", "rule", "part of"),
            inputs,
        ),  # fmt: skip
        Table("outputs", "Result columns", ("column", "unit"), outputs),
    )


def _value(value: object) -> str:
    if isinstance(value, str | np.str_):
        return str(value)
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    return number(value)


def result_tables(declared: Problem, values: dict, result: Any) -> tuple[Table, Table]:
    """The report of one impact of any problem: its inputs (given or defaults) and every
    result column, each with its unit.

    Parameters
    ----------
    declared : Problem
    values : dict
        The inputs as given to :meth:`Problem.solve` (the others take their defaults).
    result : Result
        ``declared.solve(**values)``, one impact.
    """
    columns = declared.columns(values)
    inputs = tuple(
        (i.name, _value(columns[i.name][0]) if not (not i.text and np.isnan(columns[i.name][0]))
         else "(preset)", i.unit or "", "given" if i.name in values else "default")
        for i in declared.inputs
    )  # fmt: skip
    flat = result.columns()
    rows = tuple((n, _value(np.asarray(flat[n]).reshape(-1)[0]), declared.unit(n) or "")
                 for n in declared.outputs(declared.names))  # fmt: skip
    return (
        Table("inputs", "Inputs", ("input", "value", "unit", "from"), inputs),
        Table("result", "Result", ("column", "value", "unit"), rows),
    )


def problem_report_html(declared: Problem, values: dict, result: Any) -> str:
    """One impact of any problem as a self-contained HTML page (no network, no files)."""
    from .. import __version__
    from .html import _CSS, _section

    sections = "\n".join(_section(t) for t in result_tables(declared, values, result))
    title = html.escape(f"spinimpact: {declared.name}, {declared.summary}")
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title><style>{_CSS}</style></head>
<body><h1>{title}</h1>
{sections}
<footer>spinimpact {__version__}. SI units; the conventions: docs/conventions.md.</footer>
</body></html>
"""
