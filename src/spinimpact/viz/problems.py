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

from ..model.registry import Problem, problems
from .tables import Table

__all__ = ["registry_table", "problem_tables"]


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
