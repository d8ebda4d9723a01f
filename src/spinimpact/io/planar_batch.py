"""Batch files of planar bodies and pendulums: every row solved by :func:`~spinimpact.solve_planar`
or :func:`~spinimpact.solve_pendulum`, in chunks.

:func:`~spinimpact.io.batch.run_batch` reads the header and asks :func:`body_kind` what
the file holds; the columns decide, so a file says what it describes and no option can
contradict it:

* columns ``rx, ry``: free planar bodies, one per row, with columns ``mass`` (kg),
  ``inertia`` (kg m^2, about the centre of mass), ``rx, ry`` (m, the contact point from
  the centre of mass) and the incidence ``vx, vy`` (m/s), ``omega`` (rad/s);
* columns ``gx, gy, px, py``: pendulums on a fixed pivot, with ``mass, inertia``, the
  centre of mass ``gx, gy`` and the contact point ``px, py`` from the pivot (m), and
  ``omega`` (rad/s) alone (the centre moves with it: no ``vx, vy``);
* neither: the paper's bodies (:mod:`spinimpact.io.batch`).

So a file of rods can never be solved, silently, as the default sphere. ``mu, kappa``
(1) and ``law`` (``newton``, ``poisson`` or ``energetic``) are optional per row; an empty
cell or a missing column takes the run's default. The output holds the input columns,
then ``law``, ``mu`` and ``kappa`` where the file lacks them (the values each row was
solved with), then every column of :class:`~spinimpact.PlanarImpact` (or
:class:`~spinimpact.PendulumImpact`) that is not an input (:meth:`PlanarBatch.outputs`;
a pendulum's ``before_vx, before_vy`` are outputs). A row is bad, and named with its
line and column, if a cell is not a number or breaks a rule (``mass, inertia > 0``,
``ry < 0``, ``py < 0``, ``mu >= 0``, ``kappa`` in ``[0, 1]``), if its contact point does
not approach the surface, or if its numbers are so far apart in scale that a result is
not finite in double precision.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np

from .._validation import SMALLEST, row_problems, rule_problems, validated
from ..model.planar import LAWS, PendulumImpact, PlanarImpact, solve_pendulum, solve_planar
from ..model.planar_body import Pendulum, PlanarBody
from ._tables import BatchError, Chunk, RowNotes, check_header, column_or_default

__all__ = ["GEOMETRY", "INCIDENCE", "SETTINGS", "PlanarBatch", "body_kind"]

#: Geometry columns of each kind of file (the bodies' own names for them).
GEOMETRY = {"planar": PlanarBody.COLUMNS, "pendulum": Pendulum.COLUMNS}
#: Incidence columns of each kind of file.
INCIDENCE = {"planar": ("vx", "vy", "omega"), "pendulum": ("omega",)}
#: Per-row settings with a default; written as outputs where the file lacks them.
SETTINGS = ("law", "mu", "kappa")
_MARKS = {"planar": ("rx", "ry"), "pendulum": ("gx", "gy", "px", "py")}
_WHAT = {"planar": "free planar bodies", "pendulum": "pendulums"}
_PAPER_ONLY = ("radius", "gyration", "body")
#: Results that may be infinite: the slip that never stops has ``tau_star = inf``.
_MAY_BE_INFINITE = ("tau_star",)


def body_kind(header: list[str]) -> str:
    """What a batch file describes, from its column names.

    Parameters
    ----------
    header : list of str
        The input's columns.

    Returns
    -------
    str
        ``"planar"`` (columns ``rx, ry``), ``"pendulum"`` (columns ``gx, gy, px, py``)
        or ``"paper"`` (the paper's bodies: neither).

    Raises
    ------
    BatchError
        For columns of both kinds, an incomplete geometry, ``inertia`` without a contact
        offset, a column of the paper's bodies (``radius``, ``gyration``, ``body``) in a
        planar file, or ``vx``/``vy`` in a pendulum file.

    Examples
    --------
    >>> body_kind(["mass", "inertia", "rx", "ry", "vx", "vy", "omega"])
    'planar'
    >>> body_kind(["vx", "vy", "omega", "body"])
    'paper'
    """
    found = {kind: [c for c in marks if c in header] for kind, marks in _MARKS.items()}
    if found["planar"] and found["pendulum"]:
        raise BatchError(
            f"columns {', '.join(found['planar'])} (a free planar body) and "
            f"{', '.join(found['pendulum'])} (a pendulum) do not go together in one file"
        )
    kind = "pendulum" if found["pendulum"] else "planar" if found["planar"] else "paper"
    if kind == "paper":
        if "inertia" in header:
            raise BatchError(
                "column 'inertia' describes a planar body, which also needs its contact "
                "point: columns rx, ry (a free body) or gx, gy, px, py (a pendulum)"
            )
        return kind
    marks = ", ".join(found[kind])
    missing = [c for c in GEOMETRY[kind] if c not in header]
    if missing:
        raise BatchError(
            f"missing column {missing[0]!r}: a file of {_WHAT[kind]} (columns {marks}) "
            f"needs columns {', '.join(GEOMETRY[kind] + INCIDENCE[kind])}"
        )
    for name in _PAPER_ONLY:
        if name in header:
            raise BatchError(
                f"column {name!r} belongs to the paper's bodies, but columns {marks} make this "
                f"a file of {_WHAT[kind]}; drop or rename it"
            )
    if kind == "pendulum":
        for name in ("vx", "vy"):
            if name in header:
                raise BatchError(
                    f"column {name!r} does not apply to a pendulum: its centre moves with "
                    "omega (the output gives before_vx, before_vy)"
                )
    return kind


def _problems(name: str, rules: tuple[tuple[Callable, str], ...] = ()) -> Callable:
    """``values -> messages``: finite, at most ``LARGEST``, and ``rules``, for column ``name``."""
    return functools.partial(rule_problems, name, rules=rules)


_POSITIVE = ((lambda a: a > 0, "> 0"), (lambda a: a >= SMALLEST, f">= {SMALLEST:g}"))
#: The rules of each numeric input column (the bodies' and solve_planar's rules).
RULES: dict[str, Callable[[np.ndarray], np.ndarray]] = {
    "mass": functools.partial(row_problems, "mass"),
    "inertia": _problems("inertia", _POSITIVE),
    "ry": _problems("ry", ((lambda y: y < 0, "< 0 (the contact point lies below the centre)"),)),
    "py": _problems("py", ((lambda y: y < 0, "< 0 (the pivot lies above the surface)"),)),
    "mu": functools.partial(row_problems, "mu"),
    "kappa": functools.partial(row_problems, "kappa"),
    **{n: _problems(n) for n in ("rx", "gx", "gy", "px", "vx", "vy", "omega")},
}


@functools.cache
def _result_kinds() -> dict[str, str]:
    """Each PlanarImpact column's kind (``float``, ``text``, ``flag``), from one solved impact."""
    probe = solve_planar(PlanarBody(1.0, 1.0, 0.5, -1.0), 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)
    kinds = {"b": "flag", "U": "text", "S": "text", "O": "text"}
    return {n: kinds.get(np.asarray(c).dtype.kind, "float") for n, c in probe.columns().items()}


class PlanarBatch:
    """How :func:`~spinimpact.io.batch.run_batch` solves a file of planar bodies or pendulums.

    Parameters
    ----------
    kind : {"planar", "pendulum"}
        What the file holds (:func:`body_kind`).
    header : list of str
        Its columns.
    skip : bool
        Whether bad rows are written with an ``error`` column (else the first stops the run).
    defaults : dict
        ``mu``, ``kappa`` and ``law`` for rows (or files) that lack them; ``law`` defaults
        to ``"poisson"``. Other keys (the paper's body options) are not used.

    Raises
    ------
    BatchError
        For a header the run cannot use (:func:`~spinimpact.io._tables.check_header`), or
        a missing column without a default.
    ValueError, TypeError
        For a bad default.

    Attributes
    ----------
    kinds : dict
        Output column -> ``"float"``, ``"text"`` or ``"flag"``, in the order written.
    numeric : tuple of str
        The numeric input columns (typed ``float64`` in Parquet output).
    """

    def __init__(self, kind: str, header: list[str], skip: bool, defaults: dict[str, Any]) -> None:
        self.kind, self.header = kind, list(header)
        law = defaults.get("law") or "poisson"
        if law not in LAWS:
            raise ValueError(f"law must be one of {', '.join(LAWS)}, got {law!r}")
        self.defaults: dict[str, Any] = {"law": law}
        for name in ("mu", "kappa"):
            value = defaults.get(name)
            self.defaults[name] = None if value is None else float(validated(name, value))
            if value is None and name not in header:
                raise BatchError(f"the file has no column {name!r} and no default {name} was given")
        self.inputs = GEOMETRY[kind] + INCIDENCE[kind] + ("mu", "kappa")
        self.numeric = tuple(n for n in self.inputs if n in header)
        self.kinds = self.outputs()
        check_header(header, skip, self.kinds, INCIDENCE[kind] + GEOMETRY[kind])

    def outputs(self) -> dict[str, str]:
        """The columns written after the input's, each with its kind.

        The settings (``law, mu, kappa``) the file lacks, then the result's columns
        (:meth:`~spinimpact.model.result.Result.column_names`) that are not inputs,
        ``regime`` first.
        """
        result = PendulumImpact if self.kind == "pendulum" else PlanarImpact
        inputs = set(self.inputs) | {f"before_{n}" for n in INCIDENCE[self.kind]}
        names = [n for n in result.column_names() if n not in inputs]
        kinds = _result_kinds()
        out = {n: ("text" if n == "law" else "float") for n in SETTINGS if n not in self.header}
        out.update({n: kinds[n] for n in ["regime"] + [n for n in names if n != "regime"]})
        return out

    def solve(self, chunk: Chunk) -> tuple[dict, dict, np.ndarray]:
        """Solve one chunk: (input numbers, output columns, error message per row)."""
        n = chunk.messages.size
        note = RowNotes()
        values = {
            name: column_or_default(chunk, name, self.defaults.get(name), note, RULES[name])
            for name in self.inputs
        }
        law = self._laws(chunk, note)
        self._check_approach(chunk, values, note)
        messages = note.messages(chunk)
        good = messages == ""
        one_law = law.size > 0 and (law.strides[0] == 0 or (law == law[0]).all())
        if good.all() and one_law:  # one solve of the rows as they are
            whole = self._whole(values, law)
            if whole is not None:
                return values, whole, messages
        results = {
            name: np.full(n, np.nan) if kind == "float" else np.full(n, None, dtype=object)
            for name, kind in self.kinds.items()
        }
        for name in ("mu", "kappa"):
            if name in results:
                results[name][good] = values[name][good]
        if "law" in results:
            results["law"][good] = law[good]
        for each in LAWS:  # one vectorized solve per law
            rows = good & (law == each)
            if rows.any():
                columns = self._solve_rows({k: v[rows] for k, v in values.items()}, each)
                for name, column in results.items():
                    if name in SETTINGS:
                        continue
                    solved = np.asarray(columns[name])
                    column[rows] = solved if self.kinds[name] == "float" else solved.tolist()
        self._check_finite(chunk, results, messages)
        return values, results, messages

    def _whole(self, values: dict[str, np.ndarray], law: np.ndarray) -> dict | None:
        """Every row solved at once under its one law, the solver's columns as they are, or
        ``None`` where a result is not finite (then :meth:`_check_finite` names its row)."""
        columns = self._solve_rows(values, str(law[0]))
        out = {}
        for name, kind in self.kinds.items():
            if name in SETTINGS:
                out[name] = law if name == "law" else values[name]
                continue
            column = np.asarray(columns[name])
            if kind == "float" and not self._finite(name, column).all():
                return None
            out[name] = column
        return out

    @staticmethod
    def _finite(name: str, column: np.ndarray) -> np.ndarray:
        ok = np.isfinite(column)
        if name in _MAY_BE_INFINITE:
            ok |= np.isinf(column)
        return ok

    def _solve_rows(self, v: dict[str, np.ndarray], law: str) -> dict[str, np.ndarray]:
        surface = {"mu": v["mu"], "kappa": v["kappa"], "law": law}
        with np.errstate(all="ignore"):  # a non-finite result is reported per row
            if self.kind == "pendulum":
                body = Pendulum(*(v[n] for n in Pendulum.COLUMNS))
                return solve_pendulum(body, v["omega"], **surface).columns()
            body = PlanarBody(*(v[n] for n in PlanarBody.COLUMNS))
            return solve_planar(body, v["vx"], v["vy"], v["omega"], **surface).columns()

    def _laws(self, chunk: Chunk, note: Callable[[int, str], None]) -> np.ndarray:
        one = np.array(self.defaults["law"], dtype=object)
        if "law" not in chunk.columns:  # one law for every row: a read-only view
            return np.broadcast_to(one, (chunk.messages.size,))
        law = np.full(chunk.messages.size, one[()], dtype=object)
        if "law" in chunk.columns:
            cells = chunk.columns["law"]
            text = np.empty(cells.size, dtype=object)  # cell by cell: no fixed-width copy
            text[:] = [("" if c is None else str(c)).strip().lower() for c in cells.tolist()]
            given = ~chunk.empty["law"] & (text != "")  # a blank Parquet string is empty too
            law[given] = text[given]
            for i in np.flatnonzero(given & ~np.isin(law, LAWS)):
                note(
                    i,
                    f"{chunk.where(i, 'law')}: must be one of {', '.join(LAWS)}; "
                    f"got {str(cells[i])!r}",
                )
        return law

    def _check_approach(self, chunk: Chunk, v: dict, note: Callable[[int, str], None]) -> None:
        """Each row's contact point must approach the surface (normal velocity < 0)."""
        if self.kind == "pendulum":
            names, text = ("omega", "px"), "omega*px"
            with np.errstate(all="ignore"):
                normal = v["omega"] * v["px"]
        else:
            names, text = ("vy", "omega", "rx"), "vy + omega*rx"
            with np.errstate(all="ignore"):
                normal = v["vy"] + v["omega"] * v["rx"]
        known = np.logical_and.reduce([np.isfinite(v[n]) for n in names])
        for i in np.flatnonzero(known & ~(normal < 0)):
            note(
                i,
                f"{chunk.where(i)}, columns {', '.join(names)}: the contact point must "
                f"approach the surface, but its normal velocity {text} is "
                f"{float(normal[i])!r} m/s",
            )

    def _check_finite(self, chunk: Chunk, results: dict, messages: np.ndarray) -> None:
        """Rows with a non-finite result (inputs too far apart in scale) become bad rows."""
        bad = np.zeros(messages.size, bool)
        good = messages == ""
        for name, kind in self.kinds.items():
            if kind != "float" or name in SETTINGS:
                continue
            column = results[name]
            wrong = good & ~bad & ~self._finite(name, column)
            for i in np.flatnonzero(wrong):
                messages[i] = (
                    f"{chunk.where(i)}: {name} is {float(column[i])!r}, not a finite number: the "
                    "row's numbers are too far apart in scale for double precision"
                )
            bad |= wrong
        if bad.any():
            for name, column in results.items():
                column[bad] = np.nan if self.kinds[name] == "float" else None
