"""The registry of impact problems: each problem declared once, every consumer derived from it.

An impact problem (the paper's bodies on a plane, a free planar body, a pendulum, a sphere
in 3D, two spheres, a ball's flight with its bounces, or one of your own) is a
:class:`Problem`: its inputs (:class:`Input`:
name, SI unit, default, validation rule, the vector it is a component of, the presets
that may fill it), its solver (named input columns in, a result object out, vectorized
over rows) and its result type, whose columns carry their units
(:mod:`spinimpact.model.units`). Batch files (``spinimpact batch``), sweeps (``spinimpact
sweep --problem``), fits (:func:`spinimpact.fit_problem`), the command line's options and
the files' metadata are built from the declaration, so a new problem is one
:func:`register` call beside its solver.

Examples
--------
>>> from spinimpact import problems, problem
>>> [p.name for p in problems()]
['paper', 'planar', 'pendulum', 'sphere', 'pair', 'flight', 'rigid']
>>> sphere = problem("sphere")
>>> sphere.input("wx").unit, sphere.input("wx").vector
('rad/s', 'spin')
>>> result = sphere.solve(vx=2.0, vy=-3.0, vz=0.0, wx=0.0, wy=0.0, wz=30.0)
>>> round(float(result.columns()["after_vy"][0]), 6)
2.4
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._validation import RULES, rule_problems
from .units import unit_of

__all__ = ["Input", "Problem", "register", "unregister", "problems", "problem", "detect"]


@dataclass(frozen=True)
class Input:
    """One input of a problem: a column of a batch file, an axis of a sweep, an option.

    Parameters
    ----------
    name : str
        The column and keyword name (``vx``, ``mu``, ``normal_x``).
    unit : str or None
        Its SI unit (``"1"``: a number without dimension; ``None``: text).
    description : str
        One line, for help texts and tables.
    default : float, str or None
        The value used where a file, a sweep or a command gives none; ``None``: the input
        must be given (unless ``optional``).
    rule : str, optional
        A rule of :data:`spinimpact._validation.RULES` (``"mu"``, ``"kappa"``, ``"mass"``,
        ``"radius"``, ``"gyration"``, ``"inertia"``, ``"vy"``...); every number is
        checked to be finite and at most ``1e50`` in magnitude in any case.
    vector : str, optional
        The vector this number is a component of (``"velocity"``, ``"spin"``,
        ``"normal"``): a file gives all of a vector's components or none.
    choices : tuple of str, optional
        For a text input (a preset or a law): the names allowed.
    optional : bool
        An input that may stay empty without a default (a radius of gyration that a
        ``body`` preset replaces).
    fittable : bool
        Whether a fit may estimate it (a parameter of the surface or the body, not an
        incidence).
    """

    name: str
    unit: str | None
    description: str
    default: float | str | None = None
    rule: str | None = None
    vector: str | None = None
    choices: tuple[str, ...] | None = None
    optional: bool = False
    fittable: bool = False

    @property
    def text(self) -> bool:
        """Whether the input is text (a preset or a law name) rather than a number."""
        return self.choices is not None

    @property
    def rule_text(self) -> str:
        """The input's rules in words (``">= 0, <= 1e6"``; ``"one of a, b"`` for text)."""
        if self.text:
            return "one of " + ", ".join(self.choices or ())
        return ", ".join(text for _, text in RULES.get(self.rule or "", ())) or "finite"

    @property
    def required(self) -> bool:
        """Whether a value must be given (no default, not optional)."""
        return self.default is None and not self.optional

    def problems(self, values: np.ndarray) -> np.ndarray:
        """Per-element message of what breaks this input's rules ('' where nothing).

        Parameters
        ----------
        values : numpy.ndarray
            Numbers (text inputs: names).

        Returns
        -------
        numpy.ndarray of str (object)
        """
        values = np.asarray(values)
        if not self.text:
            return rule_problems(self.name, values, RULES.get(self.rule or "", ()))
        bad = ~np.isin(values, self.choices)
        if not bad.any():  # the common case: a cheap array of ''
            return np.zeros(values.shape, dtype="U1")
        out = np.full(values.shape, "", dtype=object)
        for i in np.flatnonzero(bad):
            out[i] = (
                f"{self.name} must be one of {', '.join(self.choices or ())}, got {values[i]!r}"
            )
        return out


@dataclass(frozen=True, eq=False)
class Problem:
    """An impact problem, declared once (see the module docstring).

    Parameters
    ----------
    name : str
        Short name (``"sphere"``): ``--problem`` on the command line.
    summary : str
        One line saying what it solves.
    inputs : tuple of Input
        Every input, in the order files and options list them.
    solver : callable
        ``solver(columns, tangential=None) -> Result``: ``columns`` maps each input's
        name to an array (all of one length, text inputs as object arrays), and the
        result's fields have that length. Raise ``ValueError`` for a row the problem
        cannot solve (a contact that does not approach).
    result : type
        The result class (a :class:`~spinimpact.model.result.Result`): its
        ``column_names()`` are the output columns.
    marks : tuple of str
        Columns whose presence in a file makes it a file of this problem (checked in the
        registry's order, the most specific first); ``()`` for the fallback problem.
    tangential : bool
        Whether a tangential compliance law (``tangential=``) applies.
    units : dict
        Units of result columns the package vocabulary does not know (``unit_of``).
    may_be_infinite, may_be_nan : tuple of str
        Result columns allowed to be infinite (``tau_star``: a slip that never stops) or
        undefined (an angle without a direction); any other non-finite result is a bad row.
    echoes : dict
        Result columns that repeat an input (``before1_vx`` of a pair repeats ``vx``): a
        batch does not write them again when the file gives the input. ``before_NAME``
        repeats input ``NAME`` without being declared.
    example : dict
        One valid impact (the inputs without defaults): documentation, and the probe that
        tells each result column's kind (number, text or flag) before a file is read.
    regimes : tuple of str
        The names the result's ``regime`` column takes under the rigid law (a tangential
        law's are :data:`~spinimpact.core.compliance.COMPLIANT_REGIMES`): a sweep counts
        the points in each and writes ``regime`` as indices into them.
    check_ranges : callable, optional
        ``check_ranges(ranges) -> str or None``: given each numeric input's ``(low, high)``
        over a box of inputs (a sweep's), why some point of the box cannot be solved (a
        contact point that does not approach the surface somewhere in it), else ``None``.
        A sweep calls it before it computes, so that it refuses the whole box at once, in
        the problem's own words.
    partial : tuple, optional
        ``(columns, solver)``: some of the result's columns and a cheaper solver, called as
        :attr:`solver` is, whose result's ``columns()`` hold them alone (the impact process
        without its works and energies), the very numbers of :attr:`solver` (``regime`` as
        names or as indices into :attr:`regimes`). A sweep that asks for these columns
        only, under the rigid law, calls it instead of :attr:`solver`.
    """

    name: str
    summary: str
    inputs: tuple[Input, ...]
    solver: Callable[..., Any]
    result: type
    marks: tuple[str, ...] = ()
    tangential: bool = False
    units: Mapping[str, str] = field(default_factory=dict)
    may_be_infinite: tuple[str, ...] = ("tau_star",)
    may_be_nan: tuple[str, ...] = ()
    echoes: Mapping[str, str] = field(default_factory=dict)
    example: Mapping[str, Any] = field(default_factory=dict)
    regimes: tuple[str, ...] = ()
    check_ranges: Callable[[Mapping[str, tuple[float, float]]], str | None] | None = None
    partial: tuple[tuple[str, ...], Callable[..., Any]] | None = None

    def __post_init__(self) -> None:
        names = [i.name for i in self.inputs]
        if len(set(names)) != len(names):
            raise ValueError(f"problem {self.name!r}: an input is declared twice in {names}")
        for mark in self.marks:
            if mark not in names:
                raise ValueError(f"problem {self.name!r}: mark {mark!r} is not an input")
        for name in self.example:
            if name not in names:
                raise ValueError(f"problem {self.name!r}: example input {name!r} is not declared")

    @property
    def names(self) -> tuple[str, ...]:
        """The inputs' names, in order."""
        return tuple(i.name for i in self.inputs)

    def input(self, name: str) -> Input:
        """The input called ``name`` (a ``ValueError`` lists the valid names otherwise)."""
        for each in self.inputs:
            if each.name == name:
                return each
        raise ValueError(
            f"problem {self.name!r} has no input {name!r}; its inputs are {', '.join(self.names)}"
        )

    def vectors(self) -> dict[str, tuple[str, ...]]:
        """Each vector's name -> its components' input names."""
        out: dict[str, list[str]] = {}
        for each in self.inputs:
            if each.vector:
                out.setdefault(each.vector, []).append(each.name)
        return {k: tuple(v) for k, v in out.items()}

    def unit(self, name: str) -> str | None:
        """The SI unit of an input or result column ``name`` (``None``: text or a flag)."""
        for each in self.inputs:
            if each.name == name:
                return each.unit
        return unit_of(name, dict(self.units))

    def result_columns(self) -> tuple[str, ...]:
        """The result's columns (:meth:`Result.column_names`)."""
        return tuple(self.result.column_names())

    def outputs(
        self, given: Iterable[str] = (), columns: Iterable[str] | None = None
    ) -> tuple[str, ...]:
        """The columns a batch writes after a file's own: the result's columns that are not
        inputs the file gives (nor their ``before_`` copies), ``regime`` first.

        Parameters
        ----------
        given : iterable of str
            The input columns the file holds.
        columns : iterable of str, optional
            The result's columns, if not :meth:`result_columns` (a result under a tangential
            law has columns of its own).
        """
        given = set(given)
        skip = given | {f"before_{n}" for n in given}
        skip |= {column for column, name in self.echoes.items() if name in given}
        every = self.result_columns() if columns is None else tuple(columns)
        names = [n for n in every if n not in skip]
        return tuple(["regime"] * ("regime" in names) + [n for n in names if n != "regime"])

    def defaults(self, **overrides: Any) -> dict[str, Any]:
        """Each input's default, with ``overrides`` (unknown names are a ``ValueError``)."""
        out = {i.name: i.default for i in self.inputs}
        for name, value in overrides.items():
            self.input(name)
            out[name] = value
        return out

    def columns(self, values: Mapping[str, Any]) -> dict[str, np.ndarray]:
        """Every input as a 1-D array of one length: ``values`` broadcast, defaults filled.

        Raises
        ------
        ValueError
            For an unknown name, a required input without a value, or a vector given in
            part.
        """
        for name in values:
            self.input(name)
        for vector, parts in self.vectors().items():
            have = [p for p in parts if values.get(p) is not None]
            if have and len(have) < len(parts):
                missing = [p for p in parts if p not in have]
                raise ValueError(
                    f"the {vector} of problem {self.name!r} is given in part: "
                    f"{', '.join(have)} without {', '.join(missing)}; give all of "
                    f"{', '.join(parts)} or none"
                )
        merged: dict[str, Any] = {}
        for each in self.inputs:
            value = values.get(each.name, each.default)
            if value is None and each.required:
                raise ValueError(f"problem {self.name!r} needs {each.name} ({each.description})")
            merged[each.name] = value
        try:
            shape = np.broadcast_shapes(*(np.shape(v) for v in merged.values() if v is not None))
        except ValueError:
            shapes = ", ".join(f"{k} {np.shape(v)}" for k, v in merged.items() if np.ndim(v))
            raise ValueError(f"input shapes do not broadcast together: {shapes}") from None
        n = math.prod(shape)
        arrays = {}
        for each in self.inputs:
            value = merged[each.name]
            if each.text:
                value = np.asarray("" if value is None else value, dtype=object)
            else:
                value = np.asarray(np.nan if value is None else value, dtype=float)
            arrays[each.name] = np.broadcast_to(value, shape).reshape(n)
        return arrays

    def solve(self, *, tangential: Any = None, **values: Any) -> Any:
        """Solve the problem for ``values`` (each input by name; defaults fill the rest).

        Returns
        -------
        Result
            The problem's result over the broadcast inputs (flattened to one axis).
        """
        if tangential is not None and not self.tangential:
            raise ValueError(f"a tangential law does not apply to problem {self.name!r}")
        columns = self.columns(values)
        for name, column in columns.items():
            each = self.input(name)
            if each.optional:  # left empty (NaN, ""): the problem fills it (a preset's gyration)
                column = column[column != ""] if each.text else column[~np.isnan(column)]
            found = each.problems(column)
            if (found != "").any():
                raise ValueError(str(found[int(np.argmax(found != ""))]))
        return self.solver(columns, tangential=tangential)


#: The registered problems by name; the built-in ones are declared in
#: :mod:`spinimpact.model.problems`, which ``import spinimpact`` loads.
_REGISTRY: dict[str, Problem] = {}


def register(declared: Problem, *, replace: bool = False) -> Problem:
    """Add ``declared`` to the registry (its name must be new unless ``replace``).

    Returns
    -------
    Problem
        ``declared``, so that ``register`` can wrap a declaration.
    """
    if not isinstance(declared, Problem):
        raise TypeError(f"problem must be a Problem, got {declared!r}")
    if declared.name in _REGISTRY and not replace:
        raise ValueError(f"a problem called {declared.name!r} is already registered")
    _REGISTRY[declared.name] = declared
    return declared


def unregister(name: str) -> None:
    """Remove the problem called ``name`` (for problems registered by tests or plug-ins)."""
    _REGISTRY.pop(name, None)


def problems() -> tuple[Problem, ...]:
    """Every registered problem, in registration order."""
    return tuple(_REGISTRY.values())


def problem(name: str | Problem) -> Problem:
    """The registered problem called ``name`` (a :class:`Problem` is returned as it is).

    Raises
    ------
    TypeError
        For a name that is not a str.
    ValueError
        For an unknown name (the message lists the registered ones).
    """
    if isinstance(name, Problem):
        return name
    if not isinstance(name, str):
        raise TypeError(f"problem must be a name (str), got {name!r}")
    if name not in _REGISTRY:
        raise ValueError(f"problem must be one of {', '.join(_REGISTRY)}; got {name!r}")
    return _REGISTRY[name]


def detect(header: Iterable[str]) -> Problem:
    """The problem a file's columns describe.

    Among the problems whose marks (:attr:`Problem.marks`) appear among the columns, the
    one whose inputs hold the most columns is chosen (a file of two balls holds ``vz``, a
    sphere's mark, but also ``vx2``); with none, the problem without marks (the paper's
    bodies). A column that is an input of another problem but not of the
    chosen one is an error: a file never mixes problems silently.

    Raises
    ------
    ValueError
        For columns of two problems, or when no problem fits.
    """
    header = list(header)
    ordered = list(_REGISTRY.values())
    marked = [p for p in ordered if any(m in header for m in p.marks)]
    if marked:  # the one whose inputs hold the most of the file's columns
        cover = {p.name: sum(c in p.names for c in header) for p in marked}
        best = max(cover.values())
        tied = [p for p in marked if cover[p.name] == best]
        if len(tied) > 1:
            raise ValueError(
                f"the columns fit problems {tied[0].name!r} and {tied[1].name!r} alike; "
                "choose one (--problem)"
            )
        chosen = tied[0]
    else:
        chosen = next((p for p in ordered if not p.marks), None)
    if chosen is None:
        raise ValueError(f"no registered problem has the columns {', '.join(header)}")
    mine = set(chosen.names)
    for name in header:
        if name in mine:
            continue
        for other in ordered:
            if other is not chosen and name in other.names:
                marks = [m for m in chosen.marks if m in header]
                why = f"columns {', '.join(marks)} make" if marks else "its columns make"
                raise ValueError(
                    f"column {name!r} is an input of problem {other.name!r}, but {why} this a "
                    f"file of problem {chosen.name!r} ({chosen.summary}); drop or rename it"
                )
    return chosen
