"""The parts of a fit of any registered problem (:func:`spinimpact.fit_problem`): the
measured table read into columns, the model (the problem's solver over the free inputs),
the law and its parameter, the weights, and where each input of the body came from.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from .._validation import SMALLEST
from . import compliance
from .fit_models import LAWS, MU_INFINITY, Parameter
from .problems import SPHERE_PRESETS
from .registry import Input, Problem
from .result import Result

#: Rules of the inputs that describe a body (its mass, size, inertia), with the text
#: inputs named ``body`` (a preset): a fit needs them given, not taken from defaults.
BODY_RULES = ("mass", "radius", "gyration")
#: Regimes in which a bounce's contact stuck at some point (it only bounds ``mu``).


#: Regimes in which a bounce's contact stuck at some point (it only bounds ``mu``).
STICKING = ("stick-compression", "stick-restitution", "stick", "slip-reversal")


def body_inputs(declared: Problem) -> tuple[Input, ...]:
    """The inputs of ``declared`` that describe a body: its ``body`` preset, mass, radius,
    radius of gyration or moment of inertia (inputs whose rule is one of
    :data:`BODY_RULES`)."""
    return tuple(
        i
        for i in declared.inputs
        if i.rule in BODY_RULES or (i.text and i.name.rstrip("0123456789") == "body")
    )


def default_free(declared: Problem, given: Any, fixed: Any, tangential: Any = None) -> list[str]:
    """The parameters :func:`fit_problem` fits by default: each ``fittable`` input of
    ``declared`` that is neither among ``given`` (the columns) nor ``fixed``, nor part of
    the body; and the law's parameter when the law is given by name (``"walton"``:
    ``beta0``; ``"stronge"``: ``poisson_ratio``) and not fixed."""
    bodies = {i.name for i in body_inputs(declared)}
    out = [i.name for i in declared.inputs
           if i.fittable and i.name not in given and i.name not in fixed
           and i.name not in bodies]  # fmt: skip
    named = {"walton": "beta0", "stronge": "poisson_ratio", "mindlin-deresiewicz": "poisson_ratio"}
    if isinstance(tangential, str) and tangential in named and named[tangential] not in fixed:
        out.append(named[tangential])
    return out


class _Data:
    """Measured values ``(n, q)`` (NaN: not measured) and their sigmas, as
    :class:`~spinimpact.model.fit_profile.Problem` reads them."""

    def __init__(self, observed: np.ndarray, sigma: np.ndarray | None) -> None:
        self.observed, self.sigma = observed, sigma
        self.measured = ~np.isnan(observed)
        self.n_observations = int(self.measured.sum())


class _Model:
    """The problem's solver as a model of the parameter vector: ``predict(theta)`` sets
    the free inputs' columns (and the law's parameter) and calls the solver once over all
    bounces; ``theta`` entries of shape ``(g, 1)`` evaluate ``g`` values at once (the
    scan over ``mu``)."""

    def __init__(self, declared: Problem, columns: dict[str, np.ndarray],
                 parameters: tuple[Parameter, ...], law: Any, law_name: str | None,
                 quantities: tuple[str, ...], weights: np.ndarray) -> None:  # fmt: skip
        self.problem, self.base, self.parameters = declared, columns, parameters
        self.law, self.law_name, self.quantities = law, law_name, quantities
        self.weights = weights
        self.n = next(iter(columns.values())).size

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.parameters)

    def values(self, theta: Any) -> dict[str, Any]:
        return {n: float(v) if np.ndim(v) == 0 else np.asarray(v)
                for n, v in zip(self.names, theta, strict=True)}  # fmt: skip

    def solve(self, theta: Any) -> tuple[Any, tuple[int, ...]]:
        """The solver's result at ``theta`` and the shape of its rows (``(n,)``, or
        ``(g, n)`` for a grid)."""
        p = self.values(theta)
        law = self.law
        if self.law_name is not None:
            keep = (
                {"springs": law.springs, "steps": law.steps, "method": law.method}
                if isinstance(law, compliance.MindlinDeresiewicz)
                else {}
            )  # its resolution
            law = type(self.law)(**{self.law_name: p.pop(self.law_name)}, **keep)
        shape = np.broadcast_shapes((self.n,), *(np.shape(v) for v in p.values()))
        cols = {}
        for name, column in self.base.items():
            value = p.get(name, column)
            cols[name] = np.broadcast_to(value, shape).reshape(-1)
        return self.problem.solver(cols, tangential=law), shape

    def predict(self, theta: Any, data: Any = None) -> np.ndarray:
        """Predicted measured columns, ``(n, q)`` (``(g, n, q)`` for a grid)."""
        result, shape = self.solve(theta)
        return np.stack(
            [np.asarray(_column(result, q), dtype=float).reshape(shape) for q in self.quantities],
            axis=-1,
        )

    def regime(self, theta: Any) -> np.ndarray | None:
        out = self.solve(theta)[0].columns()
        return None if "regime" not in out else np.asarray(out["regime"]).astype(str)

    def scale(self) -> np.ndarray:
        return self.weights


def _column(result: Any, name: str) -> Any:
    """Result column ``name`` without building every column: a field (``tau0``), or a
    field of a nested result (``after_vx``: ``result.after.vx``); else from ``columns()``."""
    if isinstance(getattr(type(result), "__dataclass_fields__", None), dict):
        if name in result.__dataclass_fields__:
            value = getattr(result, name)
            if isinstance(value, np.ndarray | np.generic | float):
                return value
        parts = name.split("_")
        for i in range(1, len(parts)):
            head, rest = "_".join(parts[:i]), "_".join(parts[i:])
            inner = getattr(result, head, None) if head in result.__dataclass_fields__ else None
            if isinstance(inner, Result):
                return _column(inner, rest)
    return result.columns()[name]


def _law(tangential: Any, declared: Problem) -> tuple[Any, Parameter | None, float, bool]:
    """``(law, its parameter, the parameter's value, whether given by name)``."""
    if tangential is None or tangential == "rigid":
        return None, None, math.nan, False
    if not declared.tangential:
        raise ValueError(
            f"a tangential law does not apply to problem {declared.name!r}; "
            "fit it with the rigid law (tangential=None)"
        )
    named = isinstance(tangential, str)
    if named:
        laws = {
            "walton": compliance.Walton(0.0),
            "stronge": compliance.Stronge(0.3),
            "mindlin-deresiewicz": compliance.MindlinDeresiewicz(poisson_ratio=0.3),
        }
        if tangential not in laws:
            raise ValueError(
                "tangential must be 'rigid', 'walton', 'stronge', 'mindlin-deresiewicz' or a "
                f"Walton, Stronge or MindlinDeresiewicz law, got {tangential!r}"
            )
        tangential = laws[tangential]
    if isinstance(tangential, type):
        raise TypeError(
            f"tangential must be a law, not its class: write {tangential.__name__}(...)"
        )
    if isinstance(tangential, compliance.Walton | compliance.Stronge
                  | compliance.MindlinDeresiewicz):  # fmt: skip
        name = "beta0" if isinstance(tangential, compliance.Walton) else "poisson_ratio"
        if name == "poisson_ratio" and tangential.poisson_ratio is None:
            spec = Parameter("stiffness_ratio", 1e-6, 1e6, "1", "tangential over normal stiffness")
        else:
            _, _, low, high, meaning = LAWS[tangential.name]
            spec = Parameter(name, low, high, "1", meaning)
        return tangential, spec, float(getattr(tangential, spec.name)), named
    if isinstance(tangential, compliance.TangentialLaw):
        raise ValueError(
            f"a fit takes the rigid law, Walton, Stronge or MindlinDeresiewicz; {tangential!r} "
            "is not offered"
        )
    raise TypeError(
        "tangential must be None (the rigid law), 'walton', 'stronge', 'mindlin-deresiewicz', "
        f"or a Walton, Stronge or MindlinDeresiewicz law, got {tangential!r}"
    )


def _table(measured: Any) -> dict[str, np.ndarray]:
    """A mapping or a table with ``columns`` (a pandas DataFrame) as named 1-D arrays."""
    if isinstance(measured, Mapping):
        names = list(measured)
    elif hasattr(measured, "columns") and hasattr(measured, "__getitem__"):
        names = [str(c) for c in measured.columns]
    else:
        raise TypeError(
            "measured must be a mapping of column name to values, or a table with named "
            f"columns (a pandas DataFrame), got {type(measured).__name__}"
        )
    out = {}
    for name in names:
        if not isinstance(name, str):
            raise TypeError(f"measured column names must be str, got {name!r}")
        value = np.asarray(measured[name])
        if value.ndim != 1 and not (value.ndim == 0 and name.startswith("sigma_")):
            raise ValueError(f"column {name} must be one value per bounce (1-D), got shape "
                             f"{value.shape}")  # fmt: skip
        out[name] = value
    lengths = {v.size for v in out.values() if v.ndim == 1}
    if not lengths or lengths == {0}:
        raise ValueError("no bounces given: measured holds no rows")
    if len(lengths) > 1:
        sizes = ", ".join(f"{k} {v.size}" for k, v in out.items() if v.ndim == 1)
        raise ValueError(f"measured columns must be of one length, got {sizes}")
    n = lengths.pop()
    return {k: np.broadcast_to(v, (n,)) for k, v in out.items()}  # one sigma for all


def _numbers(name: str, value: Any, *, missing_ok: bool) -> np.ndarray:
    if np.asarray(value).dtype.kind not in "iuf":
        raise TypeError(f"column {name} must hold numbers, got {np.asarray(value)[:3]!r}...")
    arr = np.asarray(value, dtype=float)
    bad = np.isinf(arr) if missing_ok else ~np.isfinite(arr)
    if bad.any():
        i = int(np.argmax(bad))
        what = "finite or NaN (not measured)" if missing_ok else "finite (an input of each bounce)"
        raise ValueError(f"{name} must be {what}, got {arr[i]!r} at index {i}")
    return arr


def _names(what: str, value: Any) -> tuple[str, ...]:
    if isinstance(value, str):
        return (value,)  # one name, not its letters
    if not isinstance(value, Sequence) or not all(isinstance(v, str) for v in value):
        raise TypeError(f"{what} must be a parameter name or a sequence of names, got {value!r}")
    return tuple(value)


def _parameter(declared: Problem, each: Input, radius: dict[str, np.ndarray]) -> Parameter:
    """A free input's bounds, from its rule (``mu``: 0 to 1e6; ``kappa``: 0 to 1; a
    gyration: from a thousandth of the radius to a thin shell's ``sqrt(2/3) R`` for
    problems of spheres; masses and radii: positive)."""
    unit = each.unit or ""
    if each.rule == "mu":
        return Parameter(each.name, 0.0, MU_INFINITY, unit, each.description)
    if each.rule == "kappa":
        return Parameter(each.name, 0.0, 1.0, unit, each.description)
    if each.rule == "gyration":
        suffix = each.name[len("gyration") :]
        r = radius.get("radius" + suffix)
        if r is None or not np.isfinite(r).all():
            return Parameter(each.name, SMALLEST, math.inf, unit, each.description)
        preset = f"body{suffix}"
        spheres = preset in declared.names and set(declared.input(preset).choices or ()) <= set(
            SPHERE_PRESETS
        )
        high = math.sqrt(2.0 / 3.0) * float(np.min(r)) if spheres else math.inf
        return Parameter(each.name, 1e-3 * float(np.min(r)), high, unit, each.description)
    if each.rule in ("mass", "radius"):
        return Parameter(each.name, SMALLEST, math.inf, unit, each.description)
    return Parameter(each.name, -math.inf, math.inf, unit, each.description)


def _weights(declared: Problem, quantities: list[str], observed: np.ndarray,
             radius: dict[str, np.ndarray]) -> np.ndarray:  # fmt: skip
    """Weights without sigmas: m/s as they are, rad/s times the mean radius, others over
    their root-mean-square value."""
    r = [float(np.nanmean(v)) for v in radius.values() if np.isfinite(v).any()]
    out = []
    for j, q in enumerate(quantities):
        unit = declared.unit(q)
        if unit == "m/s":
            out.append(1.0)
        elif unit == "rad/s":
            out.append(float(np.mean(r)) if r else 1.0)
        else:
            rms = float(np.sqrt(np.nanmean(np.square(observed[:, j]))))
            out.append(1.0 / rms if rms > 0 else 1.0)
    return np.array(out)


def _normal(probe: dict[str, np.ndarray], quantities: list[str]) -> tuple | None:
    """The measured column that is the normal rebound of the contact, with the normal
    approach velocity of each bounce: ``normal_velocity_after``, or ``after_vy`` where it
    is that (the paper's bodies; a sphere on a level plane at rest)."""
    if "normal_velocity_after" in quantities and "normal_velocity_before" in probe:
        return "normal_velocity_after", np.asarray(probe["normal_velocity_before"]), (
            "normal_velocity_before")  # fmt: skip
    if "after_vy" in quantities and "before_vy" in probe:
        before = np.asarray(probe["before_vy"], dtype=float)
        if "normal_velocity_after" in probe:
            same = np.allclose(probe["after_vy"], probe["normal_velocity_after"], rtol=1e-12,
                               atol=0.0) and np.allclose(before, probe["normal_velocity_before"],
                                                         rtol=1e-12, atol=0.0)  # fmt: skip
            if not same:
                return None
        return "after_vy", before, "vy"
    return None


def _body_sources(declared: Problem, model: _Model, theta: np.ndarray,
                  per_bounce: dict, held: dict, chosen: list[str],
                  quantities: list[str]) -> dict[str, str]:  # fmt: skip
    """Where each body input comes from; refuse a body left to the declaration's defaults:
    wholly, or in an input the measured columns depend on (solved once with another
    value to tell)."""
    source = {}
    for each in body_inputs(declared):
        name = each.name
        if name in per_bounce:
            source[name] = "per bounce"
        elif name in held:
            source[name] = "fixed"
        elif name in chosen:
            source[name] = "fitted"
        elif each.default is not None:
            source[name] = "default"
    defaulted = [k for k, v in source.items() if v == "default"]
    if not defaulted:
        return source
    described = ", ".join(
        f"{k} = {declared.input(k).default!r}" + (f" {declared.unit(k)}" if declared.unit(k)
                                                  and declared.unit(k) != "1" else "")
        for k in defaulted
    )  # fmt: skip
    how = (
        "give them for each bounce (columns), in fixed=, or as body= (a spinimpact.Body "
        "or Ball); spinimpact fit --problem: --body, --radius, --gyration or --fix NAME=VALUE"
    )
    if len(defaulted) == len(source):
        raise ValueError(
            f"a fit needs its body: problem {declared.name!r} would take {described} from its "
            f"declared defaults; {how}"
        )
    base = model.predict(theta)
    for name in defaulted:
        each = declared.input(name)
        column = model.base[name]
        if each.text:
            other = next(c for c in each.choices or () if c != each.default)
            trial = np.full(column.shape, other, dtype=object)
        else:
            trial = np.asarray(column, dtype=float) * 1.5
        saved = model.base[name]
        model.base[name] = trial
        try:
            moved = model.predict(theta)
            depends = not np.allclose(moved, base, rtol=1e-9, atol=1e-12, equal_nan=True)
        except ValueError:
            depends = True
        finally:
            model.base[name] = saved
        if depends:
            unit = declared.unit(name)
            value = f"{each.default!r}" + (f" {unit}" if unit and unit != "1" else "")
            raise ValueError(
                f"the measured columns ({', '.join(quantities)}) depend on {name} "
                f"({each.description}), which is not given: its declared default {value} "
                "would be used silently; "
                f"{how}"
            )
        source[name] = "default (no part in the measured columns)"
    return source


def _body_record(inputs: dict, source: dict, given: str | None) -> dict:
    """The body as the fit used it: a name, each body input's value and its source."""
    record: dict[str, Any] = {}
    for name in source:
        value = inputs[name]
        if isinstance(value, np.ndarray):
            uniform = value.size and (value == value[0]).all()
            value = (value[0] if isinstance(value[0], str) else float(value[0])) if uniform else (
                value.tolist())  # fmt: skip
        record[name] = value
    gyration = [k for k in source if k.startswith("gyration")]
    if not source:
        name = "none (the problem declares no body)"
    elif given is not None:
        name = given
    elif gyration and any(source[g] == "fitted" for g in gyration):
        name = "gyration fitted"
    elif gyration and any(source[g] in ("fixed", "per bounce") for g in gyration):
        name = "given by its gyration"
    else:
        presets = [record[k] for k in source if k.rstrip("0123456789") == "body"]
        name = ", ".join(str(p) for p in presets) or "given by its inputs"
    return {"name": name, **record, "source": dict(source)}
