"""``--problem NAME`` and ``--set INPUT=VALUE``: any registered problem on the command line.

``spinimpact batch`` takes the defaults of any input this way; ``spinimpact solve`` and
``spinimpact report`` solve one impact of any problem (:mod:`spinimpact.model.registry`),
so a problem registered later is reachable without new options.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from ..model.registry import Problem, problem
from ._vocabulary import help as _help

__all__ = ["problem_options", "problem_name", "settings", "solve_problem"]


def problem_options(problem_help: str, set_help: str) -> Callable:
    """The ``--problem`` and ``--set`` options, their help completed by the two texts."""

    def wrap(function: Callable) -> Callable:
        function = click.option(
            "--set",
            "set_items",
            multiple=True,
            metavar="INPUT=VALUE",
            help=_help("set", set_help),
        )(function)
        return click.option(
            "--problem",
            default=None,
            metavar="NAME",
            help=_help("problem", problem_help),
        )(function)

    return wrap


def problem_name(name: str) -> str:
    """``--problem``'s value, checked against the registry."""
    try:
        return problem(name).name
    except ValueError as exc:
        raise click.UsageError(f"--problem: {exc}") from None


def settings(items: tuple[str, ...]) -> dict[str, Any]:
    """``--set INPUT=VALUE`` items: numbers, a comma list for a vector, or text."""
    out: dict[str, Any] = {}
    for item in items:
        name, sep, text = item.partition("=")
        name = name.strip()
        if not sep or not name or not text.strip():
            raise click.UsageError(f"--set takes INPUT=VALUE, got {item!r}")
        parts = [t.strip() for t in text.split(",")]
        try:
            numbers = [float(t) for t in parts]
        except ValueError:
            if len(parts) > 1:
                raise click.UsageError(f"--set {name}: {text!r} is not a list of numbers") from None
            out[name] = text.strip()
            continue
        out[name] = numbers if len(parts) > 1 else numbers[0]
    return out


def _expanded(declared: Problem, given: dict[str, Any]) -> dict[str, Any]:
    """``given`` with each vector named by its name split into its components."""
    vectors = declared.vectors()
    out: dict[str, Any] = {}
    for name, value in given.items():
        if name in vectors:
            parts = vectors[name]
            if not isinstance(value, list) or len(value) != len(parts):
                raise click.UsageError(f"--set {name} takes {len(parts)} numbers "
                                       f"({', '.join(parts)}), got {value!r}")  # fmt: skip
            out.update(zip(parts, value, strict=True))
        elif name in declared.names:
            out[name] = value
        else:
            raise click.UsageError(
                f"--set {name}: problem {declared.name!r} has no input {name!r}; its inputs are "
                f"{', '.join(declared.names)} (vectors: {', '.join(vectors) or 'none'})"
            )
    return out


def solve_problem(
    ctx: click.Context, name: str, items: tuple[str, ...], others: tuple[str, ...]
) -> tuple[Problem, dict[str, Any], Any]:
    """One impact of problem ``name`` with the ``--set`` values; the command's own options
    ``others`` (those of the paper's bodies) may not be typed with it.

    Returns
    -------
    (Problem, dict, Result)
        The problem, the inputs given, and its result for one impact.
    """
    declared = problem(problem_name(name))
    for option in others:
        source = ctx.get_parameter_source(option)
        if source not in (None, click.core.ParameterSource.DEFAULT):
            flag = "--" + option.replace("_", "-")
            raise click.UsageError(f"{flag} describes the paper's bodies; with --problem "
                                   f"give every input as --set INPUT=VALUE")  # fmt: skip
    values = _expanded(declared, settings(items))
    result = declared.solve(**values)
    return declared, values, result
