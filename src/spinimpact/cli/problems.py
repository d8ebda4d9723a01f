"""``spinimpact problems``: the registered impact problems, their inputs and result columns.

Every problem that ``spinimpact batch`` and ``spinimpact sweep --problem`` accept is
listed here from its declaration (:mod:`spinimpact.model.registry`), so the list cannot
fall behind the code.
"""

from __future__ import annotations

import json

import click

__all__ = ["problems_command"]


@click.command("problems")
@click.argument("name", required=False)
@click.option("--json", "as_json", is_flag=True, help="Print as JSON: the declaration.")
def problems_command(name: str | None, as_json: bool) -> None:
    """List the registered problems, or with NAME the inputs (unit, default, rule, vector)
    and result columns (unit) of one of them."""
    from ..model.registry import problem, problems
    from ..viz.problems import problem_tables, registry_table
    from ..viz.report import print_tables

    chosen = [problem(name)] if name is not None else list(problems())
    if as_json:
        out = [
            {
                "name": p.name,
                "summary": p.summary,
                "marks": list(p.marks),
                "tangential": p.tangential,
                "inputs": [
                    {
                        "name": i.name,
                        "unit": i.unit,
                        "description": i.description,
                        "default": i.default,
                        "rule": i.rule,
                        "vector": i.vector,
                        "choices": None if i.choices is None else list(i.choices),
                        "fittable": i.fittable,
                    }  # fmt: skip
                    for i in p.inputs
                ],
                "outputs": {n: p.unit(n) for n in p.outputs(p.names)},
            }
            for p in chosen
        ]
        click.echo(json.dumps(out if name is None else out[0], indent=2))
        return
    print_tables(problem_tables(chosen[0]) if name is not None else (registry_table(),))
