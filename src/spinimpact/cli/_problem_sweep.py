"""``spinimpact sweep --problem NAME``: a sweep of any registered problem, its options built
from the declaration.

:class:`ProblemSweepCommand` is the ``sweep`` command: when ``--problem NAME`` is on the
command line, its options are the sweep's own (``--samples``, ``--seed``, ``--chunk-size``,
``--output``, ``--fields``, ``--histogram``, ``--tangential``, ``--dask``, ``--dry-run``,
``--force``) and one per input of ``NAME`` (:func:`spinimpact.problem`): ``--vx2`` for
``vx2``, ``--normal-x`` for ``normal_x``, each taking a number, ``START:STOP:NUM`` (a grid)
or ``uniform:LOW:HIGH`` (random, with ``--samples``), and a text input (``--body2``) one
of its choices. A problem registered later gets its options with no change here.
``spinimpact sweep --problem NAME --help`` lists them.
"""

from __future__ import annotations

from typing import Any

import click

from ..model.registry import problem as get_problem

__all__ = ["ProblemSweepCommand", "problem_sweep"]

#: The options of ``spinimpact sweep`` that a problem's sweep keeps (by parameter name).
SHARED = ("samples", "seed", "chunk_size", "output", "fields", "histogram", "tangential",
          "beta0", "poisson_ratio", "stiffness_ratio", "dask_address", "dry_run", "force",
          "problem")  # fmt: skip
_META = "spinimpact.problem"


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def _named(args: list[str]) -> str | None:
    """The value of ``--problem`` among the command line's arguments, if any."""
    for k, arg in enumerate(args):
        if arg == "--":
            return None
        if arg == "--problem" and k + 1 < len(args):
            return args[k + 1]
        if arg.startswith("--problem="):
            return arg.split("=", 1)[1]
    return None


def _declared(name: str) -> Any:
    try:
        return get_problem(name)
    except ValueError as exc:
        raise click.UsageError(f"--problem: {exc}") from None


def _input_option(each: Any) -> click.Option:
    """The option of one input: a choice for text, an axis's text for a number."""
    if each.text:
        choices = click.Choice(list(each.choices))
        help_ = f"{each.description} (default {each.default})."
        return click.Option([_flag(each.name)], type=choices, default=None, help=help_)
    default = "none: required" if each.required else each.default
    default = "the preset's" if default is None else default
    return click.Option(
        [_flag(each.name)],
        default=None,
        metavar="X|START:STOP:NUM|uniform:LOW:HIGH",
        help=f"{each.description}, {each.unit} (default {default}).",
    )


class ProblemSweepCommand(click.Command):
    """A command whose ``--problem NAME`` replaces its body options by ``NAME``'s inputs."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        name = _named(args)
        if name is not None:
            ctx.meta[_META] = _declared(name)
        return super().parse_args(ctx, args)

    def get_params(self, ctx: click.Context) -> list[click.Parameter]:
        params = super().get_params(ctx)
        declared = ctx.meta.get(_META)
        if declared is None:
            return params
        helps = self.get_help_option(ctx)
        kept = [p for p in params if p.name in SHARED]
        inputs = [_input_option(each) for each in declared.inputs if each.name not in SHARED]
        return [*kept, *inputs, *([helps] if helps is not None else [])]


def problem_sweep(
    ctx: click.Context, o: dict[str, Any], samples: int | None, seed: int, chunk_size: int,
    law: Any
) -> Any:  # fmt: skip
    """The :class:`~spinimpact.io.problem_sweep.ProblemSweep` the options describe.

    Raises
    ------
    click.UsageError
        For required inputs not given (every one named), or a value an input refuses
        (naming its option).
    """
    from ..io.problem_sweep import ProblemSweep
    from ..io.sweep import parse_axis

    declared = ctx.meta[_META]
    missing = [_flag(i.name) for i in declared.inputs if i.required and o.get(i.name) is None]
    if missing:
        raise click.UsageError(
            f"--problem {declared.name} needs {', '.join(missing)} (inputs without a default)"
        )
    axes: dict[str, Any] = {}
    text: dict[str, str] = {}
    for each in declared.inputs:
        value = o.get(each.name)
        if value is None:
            continue
        if each.text:
            text[each.name] = value
            continue
        try:
            axes[each.name] = parse_axis(each.name, value)
        except ValueError as exc:
            raise click.BadParameter(str(exc), param_hint=f"'{_flag(each.name)}'") from None
    size = {"chunk_size": chunk_size} if _given(ctx, "chunk_size") else {}
    try:
        return ProblemSweep(problem=declared, axes=axes, text=text, samples=samples, seed=seed,
                            tangential=law, **size)  # fmt: skip
    except ValueError as exc:
        message = str(exc)
        for each in declared.inputs:  # name the option of the input the message starts with
            if message.startswith(f"{each.name} must"):
                raise click.BadParameter(message, param_hint=f"'{_flag(each.name)}'") from None
        raise


def _given(ctx: click.Context, name: str) -> bool:
    source = ctx.get_parameter_source(name)
    return source not in (None, click.core.ParameterSource.DEFAULT)
