"""Sweeps of any registered impact problem, built from its declaration.

A :class:`ProblemSweep` is a :class:`~spinimpact.io.sweep.Sweep` over any problem of the
registry (:func:`spinimpact.problems`: the paper's bodies, planar bodies, pendulums, a
sphere in 3D, two spheres, or one registered later): any numeric input may be an axis
(fixed, an evenly spaced grid, or uniform random: :class:`~spinimpact.io.sweep.Axis`), the
others stay at the values given or else at the declaration's defaults, and text inputs
(a body preset, a restitution law) are fixed. :func:`~spinimpact.io.sweep.run_sweep` runs
it as any sweep: chunk by chunk, to Parquet, CSV or ``.npy`` files, folding regime
fractions and histograms on the fly, locally or on Dask.

Each chunk is solved by the problem's own solver at once (:attr:`Problem.solver
<spinimpact.Problem>`), so the fields are the result's columns that are not inputs
(:meth:`Problem.outputs <spinimpact.Problem.outputs>`), the very numbers the problem's
function gives, each with the unit the declaration gives it (:meth:`Problem.unit
<spinimpact.Problem.unit>`). ``regime`` is written as names (a dictionary column in
Parquet, text in CSV; in ``.npy`` files the index into the ``"regimes"`` of
``metadata.json``); true/false columns as flags. Text columns other than the regime
(``min_energy_case``) are left to ``spinimpact batch``.

Random points depend on the seed alone, as in every sweep: each uniform input draws from
its own stream (:func:`~spinimpact.io._axes.uniform_stream`).

Examples
--------
>>> from spinimpact.io.sweep import run_sweep
>>> spec = dict(vx="0.5:2:4", vy=0, vz=0, wx=0, wy=20, wz=0, vx2=0, vy2=0, vz2=0,
...             wx2=0, wy2=0, wz2=0, normal_x=-1, normal_y=0, normal_z=0)
>>> result = run_sweep(ProblemSweep(problem="pair", axes=spec))
>>> result.points, {name: share for name, share in result.regime_fractions.items() if share}
(4, {'stick-restitution': 0.25, 'slip': 0.75})
"""

from __future__ import annotations

import functools
import itertools
import numbers
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import core
from .._validation import whole
from ..core.compliance import COMPLIANT_REGIMES
from ..core.planar import PLANAR_REGIMES
from ..model.registry import Problem
from ..model.registry import problem as get_problem
from ._axes import Axis, parse_axis
from ._fields import ALIASES, regime_codes
from .problem_batch import result_kinds
from .sweep import Sweep

__all__ = ["ProblemSweep", "problem_fields"]

#: The regimes of a problem that declares none: every regime the package's laws name.
_ALL_REGIMES = tuple(dict.fromkeys((*core.REGIMES, *PLANAR_REGIMES, *COMPLIANT_REGIMES)))
#: The most corners of a sweep solved before it runs (12 varying inputs).
_CORNERS = 4096


@functools.cache
def _fields(declared: Problem, law: Any) -> dict[str, str]:
    kinds = result_kinds(declared, law)
    return {
        n: kinds[n]
        for n in declared.outputs(declared.names)
        if kinds.get(n, "float") != "text" or n == "regime"
    }


def problem_fields(problem: str | Problem, tangential: Any = None) -> tuple[str, ...]:
    """The fields of a problem's sweep: its result's columns that are not inputs (text
    columns other than ``regime`` left out), under the ``tangential`` law.

    Examples
    --------
    >>> problem_fields("pair")[:3]
    ('regime', 'ball1_mass', 'ball1_radius')
    """
    return tuple(_fields(get_problem(problem), tangential))


@dataclass(frozen=True)
class ProblemSweep(Sweep):
    """A sweep over the inputs of one registered problem (see the module docstring).

    Parameters
    ----------
    problem : str or Problem
        The problem, by its registered name (``"pair"``) or as a :class:`~spinimpact.Problem`.
    axes : dict
        Input name -> its value: an :class:`~spinimpact.io.sweep.Axis` built under that
        name, an axis's text (``"2"``, ``"-5:5:101"``, ``"grid:-5:5:101"``,
        ``"uniform:-5:5"``: :func:`~spinimpact.io.sweep.parse_axis`) or a number, for a
        numeric input; a name among its choices for a text input (``body="spherical-shell"``).
        Inputs not given take the declaration's defaults; an input without one must be given.
    samples, seed
        As for :class:`~spinimpact.io.sweep.Sweep`.
    chunk_size : int
        Points evaluated at a time (default 100,000: a chunk is solved whole); memory is
        bounded by it.
    tangential : TangentialLaw, optional
        A tangential compliance law, for a problem that takes one (:attr:`Problem.tangential
        <spinimpact.Problem>`).
    text : dict, optional
        Text inputs' values, as ``axes`` may also give them.
    body
        Unused: a problem's body is among its inputs.

    Raises
    ------
    TypeError
        For a ``problem`` that is neither a name nor a Problem, ``axes`` that is not a dict,
        a value of the wrong type (a number for a text input), or a bad ``samples`` or
        ``chunk_size``.
    ValueError
        For an unknown problem or input (the message lists the valid ones), a required
        input without a value (all of them named), a vector given in part, a value that
        breaks its input's rule at an end of its axis (``mu < 0``), grid and random axes
        mixed, a tangential law the problem does not take, or a corner of the sweep the
        problem's solver refuses (a contact that does not approach).

    Examples
    --------
    >>> from spinimpact.io.sweep import run_sweep
    >>> sweep = ProblemSweep(problem="paper", axes=dict(vx="-2:2:5", vy=-1, omega=0))
    >>> sweep.inputs
    ('vx', 'vy', 'omega', 'mu', 'kappa', 'mass', 'radius')
    >>> run_sweep(sweep).points
    5
    """

    body: Any = None
    axes: dict[str, Any] = field(default_factory=dict)
    #: Points per chunk: a problem's solver holds its whole result (kilobytes a point).
    chunk_size: int = 100_000
    problem: Any = None
    tangential: Any = None
    #: Text inputs -> their value (a preset, a law), as ``axes`` may give them too; after
    #: construction every text input's (``""`` for an optional one unset).
    text: dict[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "seed", whole("seed", self.seed, 0))
        if self.body is not None:
            raise TypeError("a problem's sweep takes its body from the problem's inputs, not body=")
        if self.problem is None:
            raise TypeError("problem must be a registered problem's name or a Problem, got None")
        declared = get_problem(self.problem)
        object.__setattr__(self, "problem", declared)
        if self.tangential is not None and not declared.tangential:
            raise ValueError(
                f"a tangential law does not apply to problem {declared.name!r} ({declared.summary})"
            )
        for name in ("axes", "text"):
            if not isinstance(getattr(self, name), dict):
                raise TypeError(
                    f"{name} must be a dict of input name -> value, got {getattr(self, name)!r}"
                )
        twice = sorted(set(self.axes) & set(self.text))
        if twice:
            raise ValueError(f"{', '.join(twice)} given in both axes and text: give each once")
        axes, text = self._values(declared)
        object.__setattr__(self, "axes", axes)
        object.__setattr__(self, "text", text)
        self._check_axes()  # kinds, samples, chunk size, size (Sweep's checks)
        for name, a in axes.items():  # the rules hold over [lo, hi] where they hold at its ends
            ends = np.asarray([a.lo] if a.kind == "fixed" else [a.lo, a.hi])
            found = declared.input(name).problems(ends)
            if (found != "").any():
                raise ValueError(str(found[int(np.argmax(found != ""))]))
        self._check_corners()
        object.__setattr__(self, "_body", {})

    def _values(self, declared: Problem) -> tuple[dict[str, Axis], dict[str, str]]:
        """Every input's axis (numeric) or value (text): given, else the default."""
        axes: dict[str, Axis] = {}
        text: dict[str, str] = {}
        for name, value in {**self.axes, **self.text}.items():
            each = declared.input(name)  # a ValueError listing the inputs
            if each.text:
                if not isinstance(value, str):
                    raise TypeError(
                        f"{name} must be one of {', '.join(each.choices)}, got {value!r}"
                    )
                if value not in each.choices:
                    raise ValueError(
                        f"{name} must be one of {', '.join(each.choices)}, got {value!r}"
                    )
                text[name] = value
            elif name in self.text:
                raise TypeError(f"text gives text inputs only; {name} is a number: give it in axes")
            elif isinstance(value, Axis):
                if value.name != name:
                    raise ValueError(
                        f"axes[{name!r}] is an axis of {value.name}: build it as Axis({name!r}, "
                        f"...) or parse_axis({name!r}, ...)"
                    )
                axes[name] = value
            elif isinstance(value, str):
                axes[name] = parse_axis(name, value)
            elif isinstance(value, numbers.Real) and not isinstance(value, bool):
                axes[name] = Axis(name, "fixed", float(value))
            else:
                raise TypeError(
                    f"{name} must be a number, an Axis or an axis's text (START:STOP:NUM, "
                    f"uniform:LOW:HIGH), got {value!r}"
                )
        missing = []
        for each in declared.inputs:
            if each.text:
                default = "" if each.default is None else str(each.default)
                text.setdefault(each.name, default)
            elif each.name not in axes and each.default is not None:
                axes[each.name] = Axis(each.name, "fixed", float(each.default))
            elif each.name not in axes and each.required:
                missing.append(each.name)
        if missing:
            raise ValueError(
                f"problem {declared.name!r} needs a value or range for {', '.join(missing)} "
                "(they have no default)"
            )
        given = [n for n in self.axes if n in axes]
        declared.columns(dict.fromkeys(given, 0.0))  # a vector given in part is refused
        order = {n: k for k, n in enumerate(declared.names)}
        return dict(sorted(axes.items(), key=lambda item: order[item[0]])), text

    @property
    def inputs(self) -> tuple[str, ...]:  # type: ignore[override]
        """The numeric inputs with a value, in the declaration's order: the points' order."""
        return tuple(self.axes)

    @property
    def regimes(self) -> tuple[str, ...]:  # type: ignore[override]
        """The regimes' names: the compliance laws' under a tangential law, else those the
        problem declares (if it declares none, its example's and every regime the package
        names)."""
        if "regime" not in self._kinds:
            return ("all",)
        if self.tangential is not None:
            return COMPLIANT_REGIMES
        return tuple(getattr(self.problem, "regimes", ())) or _undeclared(self.problem)

    @property
    def _kinds(self) -> dict[str, str]:
        return _fields(self.problem, self.tangential)

    @property
    def default_fields(self) -> tuple[str, ...]:
        """The fields written when none are named: the state after the impact and the regime."""
        after = tuple(n for n in self._kinds if n.startswith("after"))
        return (*after, "regime") if "regime" in self._kinds else after

    def field_name(self, name: str, role: str = "fields") -> str:
        """The field ``name`` stands for: itself (:func:`problem_fields`) or an alias's field."""
        if name in self._kinds or (name == "regime" and self.regimes == ("all",)):
            return name
        if ALIASES.get(name) in self._kinds:
            return ALIASES[name]
        aliases = ", ".join(f"{a} for {f}" for a, f in ALIASES.items() if f in self._kinds)
        also = f" (or {aliases})" if aliases else ""
        raise ValueError(
            f"{role} must be among {', '.join(self._kinds)}{also} for problem "
            f"{self.problem.name!r}; got {name!r}"
        )

    def column_dtype(self, name: str) -> np.dtype:
        """``int8`` regime codes, ``bool`` for flags, else ``float64``."""
        if name not in self.inputs and self._kinds.get(self.field_name(name, "column")) == "flag":
            return np.dtype(bool)
        return super().column_dtype(name)

    def unit(self, name: str) -> str | None:
        """The unit the problem's declaration gives column ``name`` (an alias: its field's)."""
        if name not in self.inputs and name in ALIASES:
            name = ALIASES[name]
        return self.problem.unit(name)

    def description(self) -> dict[str, Any]:
        """The problem, the regimes' names, the axes, the fixed text inputs, the law, and the
        samples and seed of random points."""
        axes = {}
        for n, a in self.axes.items():
            ends = {"lo": a.lo, "hi": a.hi} | ({"num": a.num} if a.kind == "grid" else {})
            axes[n] = {"kind": a.kind} | ({"value": a.lo} if a.kind == "fixed" else ends)
        out: dict[str, Any] = {
            "problem": self.problem.name,
            "summary": self.problem.summary,
            "regimes": list(self.regimes),
            "axes": axes,
            "fixed": {k: v for k, v in self.text.items() if v},
        }
        if self.tangential is not None:
            out["tangential"] = self.tangential.to_dict()
        return out | ({"samples": self.samples, "seed": self.seed} if self.random else {})

    def _columns(self, values: dict[str, Any], n: int) -> dict[str, np.ndarray]:
        """The solver's input columns, each of length ``n``."""
        out: dict[str, np.ndarray] = {}
        for each in self.problem.inputs:
            if each.text:
                out[each.name] = np.full(n, self.text[each.name], dtype=object)
            elif each.name in values:
                out[each.name] = np.broadcast_to(np.asarray(values[each.name], float), (n,))
            else:
                out[each.name] = np.full(n, np.nan)
        return out

    def _solve(self, values: dict[str, Any], n: int) -> dict[str, Any]:
        return self.problem.solver(self._columns(values, n), tangential=self.tangential).columns()

    def _check_corners(self) -> None:
        """Solve the sweep's corners (each varying input at its ends; the first
        :data:`_CORNERS` of them): a point the problem refuses there is refused now, named."""
        ends = {n: (a.lo,) if a.kind == "fixed" else (a.lo, a.hi) for n, a in self.axes.items()}
        corners = list(itertools.islice(itertools.product(*ends.values()), _CORNERS))
        values = {n: np.asarray(c) for n, c in zip(ends, zip(*corners, strict=True), strict=True)}
        try:
            with np.errstate(all="ignore"):
                self._solve(values, len(corners))
        except (ValueError, ArithmeticError) as exc:
            for corner in corners:  # name one corner the solver refuses
                try:
                    with np.errstate(all="ignore"):
                        self._solve(dict(zip(ends, corner, strict=True)), 1)
                except (ValueError, ArithmeticError) as one:
                    at = ", ".join(f"{k} = {v:g}" for k, v in zip(ends, corner, strict=True))
                    raise ValueError(
                        f"problem {self.problem.name!r} cannot be solved at the corner {at} "
                        f"of the sweep: {one}; narrow the ranges"
                    ) from None
            raise ValueError(
                f"problem {self.problem.name!r} cannot be solved at the corners of the sweep: "
                f"{exc}; narrow the ranges"
            ) from None

    def evaluate(self, k: int, fields: tuple[str, ...]) -> dict[str, np.ndarray]:
        """Inputs and ``fields`` (:func:`problem_fields` or aliases) of chunk ``k``, as
        :meth:`Sweep.evaluate <spinimpact.io.sweep.Sweep.evaluate>` returns them.

        Raises
        ------
        ValueError
            For a point the solver refuses, or a field that is not a finite number where
            the problem allows none (naming the point).
        """
        c = self.chunk(k)
        n = self.chunk_length(k)
        out: dict[str, Any] = dict(c)
        wanted = {name: self.field_name(name) for name in fields}
        if wanted:
            with np.errstate(all="ignore"):  # non-finite results are checked below, named
                columns = self._solve(c, n)
            columns["regime"] = (
                self._codes(columns["regime"]) if "regime" in columns else np.zeros(n, np.int8)
            )
            for name, f in wanted.items():
                value = columns[f]
                if self._kinds.get(f) == "float":
                    self._check_finite(f, np.asarray(value), k)
                out[name] = value
        return {name: np.broadcast_to(value, (n,)) for name, value in out.items()}

    def _codes(self, regime: np.ndarray) -> np.ndarray:
        """Regime names -> their indices into :attr:`regimes` (int8), in one pass."""
        try:
            return regime_codes(regime, self.regimes)
        except ValueError as exc:
            raise ValueError(f"problem {self.problem.name!r}: {exc}: declare them "
                             "(Problem(regimes=...))") from None  # fmt: skip

    def _check_finite(self, name: str, value: np.ndarray, k: int) -> None:
        bad = ~np.isfinite(value)
        if name in self.problem.may_be_infinite:
            bad &= ~np.isinf(value)
        if name in self.problem.may_be_nan:
            bad &= ~np.isnan(value)
        if bad.any():
            i = int(np.argmax(bad))
            point = self.chunk(k)
            at = ", ".join(f"{n} = {float(np.broadcast_to(v, bad.shape)[i]):g}"
                           for n, v in point.items() if self.axes[n].kind != "fixed")  # fmt: skip
            raise ValueError(
                f"{name} is {float(value[i])!r} at point {k * self.chunk_size + i:,} of the "
                f"sweep ({at or 'its only point'}): not a finite number"
            )


@functools.cache
def _undeclared(declared: Problem) -> tuple[str, ...]:
    """The regimes of a problem that declares none: those of its example, then every regime
    the package's laws name."""
    found = declared.solve(**declared.example).columns().get("regime", ())
    return tuple(dict.fromkeys((*map(str, np.unique(np.asarray(found))), *_ALL_REGIMES)))
