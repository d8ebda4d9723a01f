"""Batch files of any registered problem, read and checked from its declaration.

:func:`~spinimpact.io.batch.run_batch` solves a file of spheres, of pairs, or of any
problem registered with :func:`spinimpact.register`, through :class:`ProblemBatch`: the
problem's :class:`~spinimpact.Input` declarations say which columns the file must have,
which it may have (and their defaults), each column's rules, and which columns make a
vector (given whole or not at all); its solver solves the good rows of a chunk at once,
and its result's columns are written after the file's own, each with its unit.

A bad row (a cell that is not a number or breaks its input's rule, a preset that does
not exist, a row the solver refuses, a result that is not finite) is named by its row,
line and column; the solver's refusal is found by halving the chunk's rows until the
row that breaks it is alone, so one bad row costs a few solves of the chunk, not one per
row.
"""

from __future__ import annotations

import functools
import json
import os
import re
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..model.registry import Problem, detect, problems
from ..model.registry import problem as get_problem
from ._tables import BatchError, Chunk, RowNotes, check_header, column_or_default
from .planar_batch import body_kind

__all__ = ["ProblemBatch", "TWO_D", "problem_of", "result_kinds", "units_file", "write_units"]

_INDEX = re.compile(r" \(first offending index [0-9, ()]*\)")
_KIND = {"b": "flag", "U": "text", "S": "text", "O": "text"}


#: The problems solved by their own chunk solvers (this module's and
#: :class:`~spinimpact.io.planar_batch.PlanarBatch`), kept for their speed and messages;
#: every other registered problem goes through :class:`~spinimpact.io.problem_batch.ProblemBatch`.
TWO_D = ("paper", "planar", "pendulum")


def units_file(output: str | os.PathLike[str]) -> Path:
    """The side file that names the units of a CSV output's columns: ``out.csv`` ->
    ``out.units.json``."""
    output = Path(output)
    return output.with_name(f"{output.stem}.units.json")


def write_units(path: Path, chosen: Problem, columns: Sequence[str]) -> None:
    """Write the units side file of a CSV output: the problem and each column's SI unit
    (``null`` for text, flags and columns the package does not know)."""
    units = {name: chosen.unit(name) for name in columns}
    text = json.dumps({"problem": chosen.name, "summary": chosen.summary, "units": units},
                      indent=2)  # fmt: skip
    path.write_text(text + "\n", encoding="utf-8")


def problem_of(header: list[str], name: str | Problem | None) -> Problem:
    """The problem a file holds: ``name`` if given (checked against the columns), else the
    one its columns describe (:func:`spinimpact.detect`)."""
    try:
        found = detect(header)
    except ValueError as exc:
        if name is None:
            if not any(c in header for p in problems() if p.name not in TWO_D for c in p.marks):
                body_kind(header)  # the planar files' own, more detailed, messages first
            raise BatchError(str(exc)) from None
        found = None
    chosen = found if name is None else get_problem(name)
    if found is not None and chosen is not found:
        raise BatchError(f"the columns of the file describe problem {found.name!r} "
                         f"({found.summary}), not {chosen.name!r}")  # fmt: skip
    if chosen.name in TWO_D:
        body_kind(header)  # its checks of a planar file's geometry
    return chosen


@functools.cache
def _kinds(problem: Problem, law: Any) -> dict[str, str]:
    columns = problem.solve(tangential=law, **problem.example).columns()
    return {n: _KIND.get(np.asarray(c).dtype.kind, "float") for n, c in columns.items()}


def result_kinds(problem: Problem, tangential: Any = None) -> dict[str, str]:
    """Each result column of ``problem`` -> ``"float"``, ``"text"`` or ``"flag"``, from its
    example (:attr:`Problem.example`) solved once under the ``tangential`` law."""
    return _kinds(problem, tangential)


def _text(cells: np.ndarray) -> np.ndarray:
    out = np.empty(cells.size, dtype=object)  # cell by cell: no fixed-width copy
    out[:] = [("" if c is None else str(c)).strip() for c in cells.tolist()]
    return out


class ProblemBatch:
    """How :func:`~spinimpact.io.batch.run_batch` solves a file of one registered problem.

    Parameters
    ----------
    problem : Problem
        The problem the file holds.
    header : list of str
        The file's columns.
    skip : bool
        Whether bad rows are written with an ``error`` column (else the first stops the run).
    defaults : dict
        Values for inputs a file lacks or leaves empty, by input name; a vector's name
        (``normal``) may give all its components as a 3-sequence. ``None`` values and
        missing keys take the declaration's defaults; ``tangential`` is the tangential law.

    Raises
    ------
    BatchError
        For a vector given in part, a required column that is missing (without a default),
        or a header the run cannot use.

    Attributes
    ----------
    kinds : dict
        Output column -> ``"float"``, ``"text"`` or ``"flag"``, in the order written.
    numeric : tuple of str
        The numeric input columns the file holds (typed ``float64`` in Parquet output).
    """

    def __init__(self, problem: Problem, header: list[str], skip: bool, defaults: dict) -> None:
        self.problem, self.header = problem, list(header)
        self.law = defaults.get("tangential")
        if self.law is not None and not problem.tangential:
            raise BatchError(
                f"a tangential law does not apply to problem {problem.name!r} ({problem.summary})"
            )
        self.defaults = self._defaults(defaults)
        for vector, parts in problem.vectors().items():
            have = [p for p in parts if p in header]
            if have and len(have) < len(parts):
                missing = [p for p in parts if p not in header]
                if any(self.defaults.get(p) is None for p in parts):
                    raise BatchError(
                        f"missing column {missing[0]!r}: columns {', '.join(have)} "
                        f"give the {vector} in part; it needs {', '.join(parts)}"
                    )
                raise BatchError(
                    f"columns {', '.join(have)} give the {vector} in part: add "
                    f"{', '.join(missing)}, or drop them to use the default "
                    f"{self._shown(parts)}"
                )
        required = tuple(
            i.name for i in problem.inputs if i.required and self.defaults.get(i.name) is None
        )
        self.numeric = tuple(i.name for i in problem.inputs if not i.text and i.name in header)
        kinds = result_kinds(problem, self.law)
        given = [c for c in header if c in problem.names]
        self.kinds = {n: kinds[n] for n in problem.outputs(given, kinds)}
        check_header(header, skip, self.kinds, required)

    def _defaults(self, given: dict[str, Any]) -> dict[str, Any]:
        out = {}
        vectors = self.problem.vectors()
        for vector, parts in vectors.items():
            value = given.get(vector)
            if value is not None and (np.ndim(value) != 1 or len(value) != len(parts)):
                raise ValueError(
                    f"default {vector} must have {len(parts)} components "
                    f"({', '.join(parts)}), got {value!r}"
                )
            have = [p for p in parts if given.get(p) is not None]
            if have and len(have) < len(parts):
                raise ValueError(
                    f"defaults give the {vector} in part ({', '.join(have)}): "
                    f"give all of {', '.join(parts)}, or the vector by its name"
                )
        for each in self.problem.inputs:
            value = given.get(each.name)
            if value is None and each.vector in given and given[each.vector] is not None:
                value = list(given[each.vector])[vectors[each.vector].index(each.name)]
            if value is not None:
                found = each.problems(np.asarray([value], dtype=object if each.text else float))
                if found[0]:
                    raise ValueError(f"default {found[0]}")
            out[each.name] = each.default if value is None else value
        return out

    def _shown(self, parts: tuple[str, ...]) -> str:
        values = [self.defaults.get(p) for p in parts]
        return "(" + ", ".join(f"{float(v):g}" for v in values) + ")"

    def solve(self, chunk: Chunk) -> tuple[dict, dict, np.ndarray]:
        """Solve one chunk: (input numbers, output columns, error message per row)."""
        n = chunk.messages.size
        note = RowNotes()
        values: dict[str, np.ndarray] = {}
        for each in self.problem.inputs:
            default = self.defaults.get(each.name)
            if each.text:
                values[each.name] = self._names(chunk, each, default, note)
            else:
                values[each.name] = column_or_default(chunk, each.name, default, note,
                                                      each.problems, not each.optional)  # fmt: skip
        self._presets(chunk, values, note)
        messages = note.messages(chunk)
        numeric = {k: v for k, v in values.items() if k in self.numeric}
        if (messages == "").all():  # every row read well: solve them as they are, no copies
            whole = self._whole(values)
            if whole is not None:
                return numeric, whole, messages
        results = {
            name: np.full(n, np.nan) if kind == "float" else np.full(n, None, object)
            for name, kind in self.kinds.items()
        }
        self._solve_rows(np.flatnonzero(messages == ""), chunk, values, results, messages)
        return numeric, results, messages

    def _whole(self, values: dict) -> dict | None:
        """Every row solved at once, the solver's columns as they are (float, text and flag
        arrays), or ``None`` where a row fails (then :meth:`_solve_rows` names it)."""
        try:
            with np.errstate(all="ignore"):
                columns = self.problem.solver(values, tangential=self.law).columns()
        except (ValueError, TypeError, ArithmeticError):
            return None
        out = {}
        for name, kind in self.kinds.items():
            column = np.asarray(columns[name])
            if kind == "float" and not self._finite(name, column).all():
                return None
            out[name] = column
        return out

    def _finite(self, name: str, column: np.ndarray) -> np.ndarray:
        """Where a float result column holds what it may: a finite number, or the infinity
        or NaN its problem allows there."""
        ok = np.isfinite(column)
        if name in self.problem.may_be_infinite:
            ok |= np.isinf(column)
        if name in self.problem.may_be_nan:
            ok |= np.isnan(column)
        return ok

    def _names(self, chunk: Chunk, each: Any, default: Any, note: Callable) -> np.ndarray:
        n = chunk.messages.size
        one = np.array("" if default is None else default, dtype=object)
        if each.name not in chunk.columns:  # one name for every row: a read-only view
            return np.broadcast_to(one, (n,))
        names = np.full(n, one[()], dtype=object)
        if each.name in chunk.columns:
            cells = _text(chunk.columns[each.name])
            given = ~chunk.empty[each.name] & (cells != "")
            names[given] = cells[given]
            for i in np.flatnonzero(given & ~np.isin(names, each.choices)):
                note(
                    i,
                    f"{chunk.where(i, each.name)}: must be one of {', '.join(each.choices)}; "
                    f"got {str(cells[i])!r}",
                )
        return names

    def _presets(self, chunk: Chunk, values: dict, note: Callable) -> None:
        """A row gives a preset or its own radius of gyration, not both; a preset in the row
        wins over a default radius of gyration."""
        for each in self.problem.inputs:
            if not (each.name.startswith("gyration") and each.optional):
                continue
            preset = "body" + each.name[len("gyration") :]
            if preset not in values:
                continue
            own = (each.name in chunk.columns) & ~chunk.empty.get(each.name, True)
            if preset in chunk.columns:
                given = ~chunk.empty[preset]
                for i in np.flatnonzero(given & own):
                    note(
                        i,
                        f"{chunk.where(i, preset)}: give either {preset} or {each.name}, not both",
                    )
                values[each.name] = np.where(given & ~own, np.nan, values[each.name])

    def _solve_rows(self, rows, chunk, values, results, messages) -> None:
        """Solve ``rows`` at once; where that fails, halve them to name the bad rows."""
        if rows.size == 0:
            return
        try:
            with np.errstate(all="ignore"):
                columns = self.problem.solver(
                    {k: v[rows] for k, v in values.items()}, tangential=self.law
                ).columns()
        except (ValueError, TypeError, ArithmeticError) as exc:
            if rows.size == 1:
                text = _INDEX.sub("", str(exc))  # one row: no index within it to name
                messages[rows[0]] = f"{chunk.where(int(rows[0]))}: {text}"
                return
            half = rows.size // 2
            for part in (rows[:half], rows[half:]):
                self._solve_rows(part, chunk, values, results, messages)
            return
        bad = np.zeros(rows.size, bool)
        first: list[str | None] = [None] * rows.size
        for name, column in results.items():
            solved = np.asarray(columns[name])
            if self.kinds[name] == "float":
                column[rows] = solved
                wrong = ~self._finite(name, solved)
                for k in np.flatnonzero(wrong & ~bad):
                    first[k] = f"{name} is {float(solved[k])!r}"
                bad |= wrong
            else:
                column[rows] = solved.tolist()
        for k in np.flatnonzero(bad):
            i = int(rows[k])
            messages[i] = (
                f"{chunk.where(i)}: {first[k]}, not a finite number: the row's "
                "numbers are too far apart in scale for double precision"
            )
            for name, column in results.items():
                column[i] = np.nan if self.kinds[name] == "float" else None
