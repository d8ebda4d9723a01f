"""Sweeps of any registered impact problem, built from its declaration.

A :class:`ProblemSweep` is a :class:`~spinimpact.io.sweep.Sweep` over any problem of the
registry (:func:`spinimpact.problems`: the paper's bodies, planar bodies, pendulums, a
sphere in 3D, two spheres, or one registered later): any numeric input may be an axis
(fixed, an evenly spaced grid, or uniform random: :class:`~spinimpact.io.sweep.Axis`), the
others stay at the values given or else at the declaration's defaults, and text inputs
(a body preset, a restitution law) are fixed. :func:`~spinimpact.io.sweep.run_sweep` runs
it as any sweep: chunk by chunk, to Parquet, CSV or ``.npy`` files, folding regime
fractions and histograms on the fly, locally or on Dask.

The files hold a column for each axis; inputs held at one value for the whole sweep
(``fixed=``, and a body object's numbers, ``body=``) are written in the files'
description instead (``"fixed"``, ``"body"``), with the problem, the regimes' names, the
axes and the tangential law. So it runs the sweeps of ``spinimpact sweep --sphere``,
``--planar`` and ``--tangential`` (a sphere on a surface, a planar body or a pendulum under
a restitution law, one of the paper's bodies under a tangential law), with the numbers and
the columns of the per-problem sweeps it replaces (:mod:`~spinimpact.io.sphere_sweep`,
:mod:`~spinimpact.io.planar_sweep`, :mod:`~spinimpact.io.compliant_sweep`: deprecated
aliases).

Each chunk is solved by the problem's own solver at once (:attr:`Problem.solver
<spinimpact.Problem>`), so the fields are the result's columns that are not inputs
(:meth:`Problem.outputs <spinimpact.Problem.outputs>`), the very numbers the problem's
function gives, each with the unit the declaration gives it (:meth:`Problem.unit
<spinimpact.Problem.unit>`). ``regime`` is written as names (a dictionary column in
Parquet, text in CSV; in ``.npy`` files the index into the ``"regimes"`` of
``metadata.json``); true/false columns as flags. Text columns other than the regime
(``min_energy_case``) are left to ``spinimpact batch``. Where the problem declares a
cheaper solver for some columns (:attr:`Problem.partial <spinimpact.Problem>`: a planar
body's impact process without its works), a sweep asking for those alone calls it, and
where it declares a check of a box of inputs (:attr:`Problem.check_ranges
<spinimpact.Problem>`: a contact point that must approach everywhere), a sweep is refused
in its words before it computes.

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
from ..model.body import Body, as_body
from ..model.registry import Input, Problem
from ..model.registry import problem as get_problem
from ..model.result import BodyColumns
from ._axes import Axis, parse_axis
from ._fields import ALIASES, regime_codes
from .problem_batch import result_kinds
from .sweep import Sweep

__all__ = ["ProblemSweep", "problem_fields"]

#: The regimes of a problem that declares none: every regime the package's laws name.
_ALL_REGIMES = tuple(dict.fromkeys((*core.REGIMES, *PLANAR_REGIMES, *COMPLIANT_REGIMES)))
#: The most corners of a sweep solved before it runs (12 varying inputs).
_CORNERS = 4096
#: The text input that a body's preset name fills (``body``: ``"solid-sphere"``).
_PRESET = "body"


@functools.cache
def _fields(declared: Problem, law: Any) -> dict[str, str]:
    kinds = result_kinds(declared, law)
    return {
        n: kinds[n]
        for n in declared.outputs(declared.names, columns=kinds)
        if kinds[n] != "text" or n == "regime"
    }


def problem_fields(
    problem: str | Problem, tangential: Any = None, body: Any = None
) -> tuple[str, ...]:
    """The fields of a problem's sweep: its result's columns that are not inputs (text
    columns other than ``regime`` left out), under the ``tangential`` law.

    Parameters
    ----------
    problem : str or Problem
    tangential : TangentialLaw, optional
    body : optional
        A body, or its class (:class:`~spinimpact.Body`, :class:`~spinimpact.PlanarBody`,
        :class:`~spinimpact.Pendulum`), that the sweep is given: its columns (a sphere's
        ``zeta``) are the body's, in the files' description, not fields.

    Examples
    --------
    >>> problem_fields("pair")[:3]
    ('regime', 'ball1_mass', 'ball1_radius')
    >>> problem_fields("sphere", body=Body)[:3]
    ('regime', 'after_vx', 'after_vy')
    """
    skip = getattr(body, "COLUMNS", ())
    return tuple(n for n in _fields(get_problem(problem), tangential) if n not in skip)


def _text_value(each: Input, value: Any) -> str:
    """``value`` of text input ``each``: one of its choices, else an error naming them."""
    if not isinstance(value, str):
        raise TypeError(
            f"{each.name} must be one of {', '.join(each.choices or ())}, got {value!r}"
        )
    if value not in (each.choices or ()):
        raise ValueError(
            f"{each.name} must be one of {', '.join(each.choices or ())}, got {value!r}"
        )
    return value


def _is_preset(body: Body) -> bool:
    """Whether ``body`` is its named preset, to the last bit of its gyration and zeta."""
    try:
        preset = Body.preset(body.name, mass=body.mass, radius=body.radius)
    except (TypeError, ValueError):
        return False
    return bool(preset.gyration == body.gyration and preset.zeta == body.zeta)


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
        Each numeric input given here, or left to its default, is a column of the files.
        Inputs given nowhere take the declaration's defaults; an input without one must be
        given.
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
    fixed : dict, optional
        Inputs held at one value for the whole sweep (a number, or a name for a text
        input), written in the files' description (``"fixed"``) instead of as columns:
        ``fixed={"normal_x": 0.2, ...}`` for a tilted surface, ``fixed={"law": "newton"}``.
    body : Body, Ball, PlanarBody or Pendulum, optional
        One body, whose numbers are held fixed: its columns (``Body.COLUMNS``,
        ``PlanarBody.COLUMNS``...) that are inputs of the problem take its values, a body
        that is one of the presets of the problem's ``body`` input is given by that name
        (so the solver uses the preset's exact ``zeta``), and the files' description holds
        it whole (``"body"``: :meth:`~spinimpact.Body.to_dict`). A
        :meth:`Body.from_zeta <spinimpact.Body.from_zeta>` body is given by its radius of
        gyration, whose ``zeta`` can differ from its own in the last bit.

    Raises
    ------
    TypeError
        For a ``problem`` that is neither a name nor a Problem, ``axes``, ``text`` or
        ``fixed`` that is not a dict, a value of the wrong type (a number for a text input),
        a ``body`` that is not a body, or a bad ``samples`` or ``chunk_size``.
    ValueError
        For an unknown problem or input (the message lists the valid ones), a required
        input without a value (all of them named), an input given twice with two values, a
        vector given in part, an array of bodies, a value that breaks its input's rule at
        an end of its axis (``mu < 0``), grid and random axes mixed, a tangential law the
        problem does not take, a box of inputs the problem refuses (:attr:`Problem.check_ranges
        <spinimpact.Problem>`: a contact that does not approach somewhere), or a corner of
        the sweep the problem's solver refuses.

    Examples
    --------
    >>> from spinimpact.io.sweep import run_sweep
    >>> sweep = ProblemSweep(problem="paper", axes=dict(vx="-2:2:5", vy=-1, omega=0))
    >>> sweep.inputs
    ('vx', 'vy', 'omega', 'mu', 'kappa', 'mass', 'radius')
    >>> run_sweep(sweep).points
    5

    A body and a surface held fixed: the columns are the incidence, ``mu`` and ``kappa``.

    >>> ball = Body.spherical_shell(mass=0.057, radius=0.033)
    >>> tilted = dict(normal_x=0.2, normal_y=1.0, normal_z=-0.1)
    >>> at_rest = dict(surface_velocity_x=0, surface_velocity_y=0, surface_velocity_z=0)
    >>> spec = dict(vx="-2:2:5", vy=-3, vz=0, wx=0, wy=0, wz=30, mu=0.3, kappa=0.8)
    >>> sweep = ProblemSweep(problem="sphere", body=ball, axes=spec, fixed=tilted | at_rest)
    >>> sweep.inputs
    ('vx', 'vy', 'vz', 'wx', 'wy', 'wz', 'mu', 'kappa')
    >>> sweep.description()["fixed"]["normal_x"], sweep.description()["body"]["name"]
    (0.2, 'spherical-shell')
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
    #: Inputs held at one value, not columns (numbers, or names for text inputs).
    fixed: dict[str, Any] = field(default_factory=dict)
    #: The numeric inputs held fixed (from ``body`` and ``fixed``) -> their value.
    _held: dict[str, float] = field(init=False, repr=False, default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "seed", whole("seed", self.seed, 0))
        if self.problem is None:
            raise TypeError("problem must be a registered problem's name or a Problem, got None")
        declared = get_problem(self.problem)
        object.__setattr__(self, "problem", declared)
        if self.tangential is not None and not declared.tangential:
            raise ValueError(
                f"a tangential law does not apply to problem {declared.name!r} ({declared.summary})"
            )
        for name in ("axes", "text", "fixed"):
            if not isinstance(getattr(self, name), dict):
                raise TypeError(
                    f"{name} must be a dict of input name -> value, got {getattr(self, name)!r}"
                )
        twice = sorted(set(self.axes) & set(self.text))
        if twice:
            raise ValueError(f"{', '.join(twice)} given in both axes and text: give each once")
        held = self._held_values(declared)
        axes, text = self._values(declared, held)
        object.__setattr__(self, "axes", axes)
        object.__setattr__(self, "text", text)
        numbers_ = {n: v for n, v in held.items() if not declared.input(n).text}
        object.__setattr__(self, "_held", numbers_)
        self._check_axes()  # kinds, samples, chunk size, size (Sweep's checks)
        for name, a in axes.items():  # the rules hold over [lo, hi] where they hold at its ends
            ends = np.asarray([a.lo] if a.kind == "fixed" else [a.lo, a.hi])
            found = declared.input(name).problems(ends)
            if (found != "").any():
                raise ValueError(str(found[int(np.argmax(found != ""))]))
        if declared.check_ranges is not None:
            ranges = {n: (a.lo, a.lo if a.kind == "fixed" else a.hi) for n, a in axes.items()}
            message = declared.check_ranges(ranges | {n: (v, v) for n, v in numbers_.items()})
            if message:
                raise ValueError(message)
        self._check_corners()
        object.__setattr__(self, "_body", {})

    def _from_body(self, declared: Problem) -> dict[str, Any]:
        """The inputs ``body`` holds fixed: its columns that are inputs of the problem, a
        preset by its name."""
        b = self.body
        if b is None:
            return {}
        if not isinstance(b, BodyColumns):
            try:
                b = as_body(b)
            except TypeError:
                raise TypeError(
                    "body must be a spinimpact.Body, Ball, PlanarBody or Pendulum, got "
                    f"{type(b).__name__}"
                ) from None
            object.__setattr__(self, "body", b)
        out: dict[str, Any] = {}
        for name in b.COLUMNS:
            if name in declared.names:
                value = np.asarray(getattr(b, name), dtype=float)
                if value.ndim:
                    raise ValueError("a sweep needs a single body, not an array of bodies")
                out[name] = float(value)
        if not out:
            raise ValueError(
                f"problem {declared.name!r} has no input of a {type(b).__name__} "
                f"({', '.join(b.COLUMNS)}): give the body's inputs in fixed"
            )
        choices = declared.input(_PRESET).choices if _PRESET in declared.names else None
        if isinstance(b, Body) and b.name in (choices or ()) and _is_preset(b):
            out = {n: v for n, v in out.items() if not declared.input(n).optional}
            out[_PRESET] = b.name  # the preset's exact zeta, not 1 + (R/rho)**2
        return out

    def _held_values(self, declared: Problem) -> dict[str, Any]:
        """The inputs held fixed, from ``body`` and ``fixed``, checked, in the declaration's
        order."""
        held = self._from_body(declared)
        for name, value in self.fixed.items():
            each = declared.input(name)  # a ValueError listing the inputs
            if each.text:
                value = _text_value(each, value)
            elif isinstance(value, numbers.Real) and not isinstance(value, bool):
                value = float(value)
                found = each.problems(np.asarray([value]))[0]
                if found:
                    raise ValueError(found)
            else:
                raise TypeError(f"fixed[{name!r}] must be a number, got {value!r}")
            if name in held and held[name] != value:
                raise ValueError(f"{name} is given twice: {held[name]!r} by the body and "
                                 f"{value!r} in fixed")  # fmt: skip
            held[name] = value
        return {n: held[n] for n in declared.names if n in held}

    def _values(
        self, declared: Problem, held: dict[str, Any]
    ) -> tuple[dict[str, Axis], dict[str, str]]:
        """Every input's axis (numeric) or value (text): given, else the default."""
        axes: dict[str, Axis] = {}
        text: dict[str, str] = {}
        for name, value in {**self.axes, **self.text}.items():
            each = declared.input(name)  # a ValueError listing the inputs
            if each.text:
                text[name] = _text_value(each, value)
                if name in held and held[name] != value:
                    raise ValueError(f"{name} is given twice: {value!r} and {held[name]!r}")
            elif name in self.text:
                raise TypeError(f"text gives text inputs only; {name} is a number: give it in axes")
            elif name in held:
                raise ValueError(f"{name} is given twice: as an axis and held fixed (by fixed "
                                 "or the body); give it once")  # fmt: skip
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
        text.update({n: v for n, v in held.items() if declared.input(n).text})
        missing = []
        for each in declared.inputs:
            if each.text:
                default = "" if each.default is None else str(each.default)
                text.setdefault(each.name, default)
            elif each.name in axes or each.name in held:
                continue
            elif each.default is not None:
                axes[each.name] = Axis(each.name, "fixed", float(each.default))
            elif each.required:
                missing.append(each.name)
        if missing:
            raise ValueError(
                f"problem {declared.name!r} needs a value or range for {', '.join(missing)} "
                "(they have no default)"
            )
        given = [n for n in self.axes if n in axes] + [n for n in held if n not in text]
        declared.columns(dict.fromkeys(given, 0.0))  # a vector given in part is refused
        order = {n: k for k, n in enumerate(declared.names)}
        return dict(sorted(axes.items(), key=lambda item: order[item[0]])), text

    @property
    def inputs(self) -> tuple[str, ...]:  # type: ignore[override]
        """The inputs that are axes (columns of the files), in the declaration's order: the
        points' order."""
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
        """Each field -> ``"float"``, ``"flag"`` or ``"text"``: the result's columns that
        are not inputs, nor the body's own (:func:`problem_fields`)."""
        kinds = _fields(self.problem, self.tangential)
        if self.body is None:
            return kinds
        return {n: k for n, k in kinds.items() if n not in self.body.COLUMNS}

    @property
    def default_fields(self) -> tuple[str, ...]:
        """The fields written when none are named: the state after the impact and the regime."""
        after = tuple(n for n in self._kinds if n.startswith("after"))
        return (*after, "regime") if "regime" in self._kinds else after

    def field_name(self, name: str, role: str = "fields") -> str:
        """The field ``name`` stands for: itself (:func:`problem_fields`) or an alias's field.

        Raises
        ------
        ValueError
            For any other name, listing the fields in the result's order and the aliases.
        """
        kinds = self._kinds
        if name in kinds or (name == "regime" and self.regimes == ("all",)):
            return name
        if ALIASES.get(name) in kinds:
            return ALIASES[name]
        fields = [n for n in result_kinds(self.problem, self.tangential) if n in kinds]
        aliases = ", ".join(f"{a} for {f}" for a, f in ALIASES.items() if f in kinds)
        also = f" (or {aliases})" if aliases else ""
        raise ValueError(f"{role} must be among {', '.join(fields)}{also}; got {name!r}")

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
        """The problem, the regimes' names, the body, the axes, the inputs held fixed, the
        law, and the samples and seed of random points."""
        axes = {}
        for n, a in self.axes.items():
            ends = {"lo": a.lo, "hi": a.hi} | ({"num": a.num} if a.kind == "grid" else {})
            axes[n] = {"kind": a.kind} | ({"value": a.lo} if a.kind == "fixed" else ends)
        out: dict[str, Any] = {
            "problem": self.problem.name,
            "summary": self.problem.summary,
            "regimes": list(self.regimes),
        }
        if self.body is not None:
            out["body"] = self.body.to_dict()
        # the body's inputs are in "body"; its preset input too, even where it is unused
        body = set(self._from_body(self.problem)) | ({_PRESET} if self.body is not None else set())
        held = {**self.text, **self._held}
        out |= {
            "axes": axes,
            "fixed": {
                n: held[n] for n in self.problem.names if held.get(n, "") != "" and n not in body
            },  # fmt: skip
        }
        if self.tangential is not None:
            out["tangential"] = self.tangential.to_dict()
        return out | ({"samples": self.samples, "seed": self.seed} if self.random else {})

    def _columns(self, values: dict[str, Any], n: int) -> dict[str, np.ndarray]:
        """The solver's input columns, each of length ``n``: a value held for every point is
        one value broadcast (a read-only view of stride 0, no copy)."""
        out: dict[str, np.ndarray] = {}
        for each in self.problem.inputs:
            if each.text:
                value = np.empty((), dtype=object)
                value[()] = self.text[each.name]
            elif each.name in values:
                value = np.asarray(values[each.name], float)
            else:
                value = np.asarray(self._held.get(each.name, np.nan), float)
            out[each.name] = np.broadcast_to(value, (n,))
        return out

    def _solve(self, values: dict[str, Any], n: int, fields: Any = None) -> dict[str, Any]:
        """The result's columns at the points ``values``: from the problem's cheaper solver
        (:attr:`Problem.partial <spinimpact.Problem>`) where ``fields`` are all among its
        columns, else from its solver."""
        solver = self.problem.solver
        partial = self.problem.partial
        if partial is not None and self.tangential is None and fields is not None:
            if set(fields) <= set(partial[0]):
                solver = partial[1]
        return solver(self._columns(values, n), tangential=self.tangential).columns()

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
                columns = self._solve(c, n, wanted.values())
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
        """Regime names -> their indices into :attr:`regimes` (int8), in one pass; indices
        (a cheaper solver's) as they are."""
        regime = np.asarray(regime)
        if regime.dtype.kind in "iu":
            return regime.astype(np.int8, copy=False)
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
