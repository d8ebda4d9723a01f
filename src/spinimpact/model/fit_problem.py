r"""Fit any registered impact problem to measured impacts.

:func:`fit_problem` fits the inputs of a problem declared in the registry
(:mod:`spinimpact.model.registry`: the paper's bodies, a planar body, a pendulum, a sphere
in 3D, two spheres, or one of your own) to measured result columns, with the rigid law or
a tangential compliance law (:class:`~spinimpact.Walton`, :class:`~spinimpact.Stronge`).
Everything it needs comes from the declaration: which inputs a fit may estimate
(``fittable``), their rules (and so their bounds), the solver, and the result's columns
and units. The least squares, the curvature and the profile-likelihood intervals are
those of :func:`spinimpact.fit` (:mod:`spinimpact.model.fit_profile`); the model is the
problem's solver, called once over all bounces at each evaluation.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import SMALLEST, setting
from . import compliance
from .body import Body
from .fit import NoScatterError, estimate, refuse_impossible, scatter, summary
from .fit_models import LAWS, MU_INFINITY, Parameter
from .fit_profile import Problem as LeastSquares
from .fit_result import FitResult, FitWarning
from .presets import Ball
from .problems import SPHERE_PRESETS
from .registry import Input, Problem
from .registry import problem as lookup
from .result import Result

__all__ = ["fit_problem", "ProblemFit", "body_inputs", "default_free", "NoScatterError"]

#: Rules of the inputs that describe a body (its mass, size, inertia), with the text
#: inputs named ``body`` (a preset): a fit needs them given, not taken from defaults.
BODY_RULES = ("mass", "radius", "gyration")
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
    named = {"walton": "beta0", "stronge": "poisson_ratio"}
    if isinstance(tangential, str) and tangential in named and named[tangential] not in fixed:
        out.append(named[tangential])
    return out


@dataclass(frozen=True, eq=False, repr=False)
class ProblemFit(FitResult):
    """What :func:`fit_problem` found: a :class:`~spinimpact.model.fit_result.FitResult`
    whose ``(n, q)`` arrays hold one column per measured quantity (:attr:`quantities`),
    with the problem, its body and its law recorded.

    Attributes
    ----------
    problem : str
        The registered problem's name.
    law : dict or None
        The tangential law (``{"law": "walton", "beta0": 0.31}``, its parameter at the
        estimate when fitted); ``None`` for the rigid law.
    quantities : tuple of str
        The measured result columns, in the order of the columns of ``observed``,
        ``fitted``, ``residuals``, ``sigma``, ``fitted_low`` and ``fitted_high``.
    units : dict
        The unit of each quantity.
    incidence_names : tuple of str
        The inputs given for each bounce, in the order of the columns of ``incidence``
        (numeric ones; text inputs given per bounce are in :attr:`inputs` only).
    inputs : dict
        Every input as used by the fit: given per bounce (an array), fixed or taken from
        its default (a number or name), or fitted (the estimate).
    body : dict
        (From :class:`FitResult`.) The body's ``name``, each body input's value and, under
        ``source``, where each came from: ``per bounce``, ``fixed``, ``fitted``, or
        ``default (no part in the measured columns)``.
    """

    problem: str
    law: dict | None
    quantities: tuple
    units: dict
    incidence_names: tuple
    inputs: dict

    def _quantities(self) -> tuple[str, ...]:
        return tuple(self.quantities)

    def column_names(self) -> tuple[str, ...]:  # type: ignore[override]
        """Names of :meth:`columns`, in order."""
        return self._column_names(self.quantities)

    def to_dict(self) -> dict[str, Any]:
        """Every field as plain Python values (for JSON)."""
        out = super().to_dict()
        out["inputs"] = {k: np.asarray(v).tolist() for k, v in self.inputs.items()}
        out["quantities"] = list(self.quantities)
        out["incidence_names"] = list(self.incidence_names)
        return out

    def __repr__(self) -> str:
        parts = "; ".join(str(self[n]) for n in self.names)
        return (f"<ProblemFit {self.problem} ({self.model}), body {self.body['name']}: "
                f"{parts}; chi2/dof = {self.chi2:.4g}/{self.dof}>")  # fmt: skip


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
            law = type(self.law)(**{self.law_name: p.pop(self.law_name)})
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
        laws = {"walton": compliance.Walton(0.0), "stronge": compliance.Stronge(0.3)}
        if tangential not in laws:
            raise ValueError(
                f"tangential must be 'rigid', 'walton', 'stronge' or a Walton or Stronge "
                f"law, got {tangential!r}"
            )
        tangential = laws[tangential]
    if isinstance(tangential, type):
        raise TypeError(
            f"tangential must be a law, not its class: write {tangential.__name__}(...)"
        )
    if isinstance(tangential, compliance.Walton | compliance.Stronge):
        name = "beta0" if isinstance(tangential, compliance.Walton) else "poisson_ratio"
        if name == "poisson_ratio" and tangential.poisson_ratio is None:
            spec = Parameter("stiffness_ratio", 1e-6, 1e6, "1", "tangential over normal stiffness")
        else:
            _, _, low, high, meaning = LAWS[tangential.name]
            spec = Parameter(name, low, high, "1", meaning)
        return tangential, spec, float(getattr(tangential, spec.name)), named
    if isinstance(tangential, compliance.TangentialLaw):
        raise ValueError(
            f"a fit takes the rigid law, Walton or Stronge; {tangential!r} is not offered "
            "yet (its impacts are solved by stepping, too slow for the many evaluations of "
            "a fit)"
        )
    raise TypeError(
        "tangential must be None (the rigid law), 'walton', 'stronge', or a Walton or "
        f"Stronge law, got {tangential!r}"
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


def fit_problem(
    declared: str | Problem,
    measured: Any,
    *,
    free: str | Sequence[str] | None = None,
    fixed: Mapping[str, Any] | None = None,
    body: Body | Ball | None = None,
    tangential: Any = None,
    confidence: float = 0.95,
    start: Mapping[str, float] | None = None,
) -> ProblemFit:
    r"""Fit the inputs of any registered problem to measured impacts.

    Parameters
    ----------
    declared : str or Problem
        The problem (``"sphere"``, ``"paper"``, ``"planar"``... or a registered
        :class:`~spinimpact.Problem`).
    measured : mapping or table
        Named columns, one row per bounce (a dict of arrays or a pandas DataFrame): the
        problem's inputs given for each bounce (for ``"sphere"``: ``vx, vy, vz, wx, wy,
        wz``, and any other input, such as ``radius``), the measured result columns
        (any numeric column of the problem's result, such as ``after_vx`` ...
        ``after_wz``; NaN where not measured), and optionally the standard deviation of
        each measured column as ``sigma_<column>`` (all or none; one number stands for
        every bounce).
    free : str or sequence of str, optional
        The inputs to fit; each must be declared ``fittable``. By default every
        fittable input neither given per bounce, nor fixed, nor part of the body (for
        most problems ``mu`` and ``kappa``), and the law's parameter when the law is
        given by name.
    fixed : dict, optional
        Inputs held at given values (numbers, or a preset's name), e.g.
        ``{"kappa": 0.75, "radius": 0.033}``, or the law's parameter (``"beta0"``).
    body : Body or Ball, optional
        The body, for problems with body inputs: fixes ``mass``, ``radius`` and
        ``gyration`` (of the first body of a pair).
    tangential : None, "walton", "stronge", Walton or Stronge
        The tangential law: ``None`` the rigid law; a law instance holds its parameter
        fixed (unless named in ``free``); a law's name fits its parameter (``beta0``;
        ``poisson_ratio``).
    confidence : float
        Level of the profile-likelihood intervals, in ``(0.5, 1)``.
    start : dict, optional
        Starting values of free parameters (by default: their declared defaults,
        ``kappa`` from the measured normal rebound, and a scan over ``mu``).

    Returns
    -------
    ProblemFit
        Estimates with standard errors and intervals, residuals, goodness of fit, and
        the problem, body, law and inputs used (``to_dict()`` for JSON).

    Raises
    ------
    TypeError
        For arguments of the wrong kind, a column that is not numbers, a law's class
        instead of an instance.
    ValueError
        For an unknown column or parameter name; a free parameter that is not a
        fittable input (an incidence) or is given per bounce; a body taken from the
        declaration's defaults (the error names the inputs: give them per bounce, in
        ``fixed`` or as ``body``); a bad value (naming the input and the first bad
        bounce); measured normal rebounds no bounce can give (into the surface, or
        faster than the impact, beyond the noise, as :func:`spinimpact.fit` refuses
        them); fewer measured values than free parameters plus one.
    NoScatterError
        Without sigmas, for data that fit to rounding (no scatter to estimate a
        standard deviation from).

    Warns
    -----
    FitWarning
        When the optimizer does not converge.

    Notes
    -----
    The estimate minimizes :math:`\chi^2 = \sum ((y - f(\theta))/\sigma)^2` over the
    measured values, and the intervals are profile-likelihood intervals, exactly as in
    :func:`spinimpact.fit` (see its Notes). Without sigmas, columns in m/s are weighted
    as they are, spins (rad/s) times the body's mean radius (as speeds of the contact
    point), and columns of any other unit over their root-mean-square value; one common
    standard deviation is then estimated from the scatter.

    A body input left at its declared default is refused when all the body's inputs
    would be, and when the measured columns depend on it (checked by solving once with
    another value): a tennis ball fitted as the default solid sphere gives a wrong
    ``mu``. An input the measured columns do not depend on (the mass, for the
    velocities of one body on a fixed plane) may stay at its default; the result says
    so under ``body["source"]``.

    Examples
    --------
    Twenty bounces of a tennis ball in 3D, the rebound velocity measured with 0.05 m/s
    of noise:

    >>> import numpy as np
    >>> from spinimpact import BALLS, fit_problem, solve_sphere
    >>> ball = BALLS["tennis"]
    >>> rng = np.random.default_rng(2)
    >>> v = np.stack([rng.uniform(4, 20, 20), -rng.uniform(3, 8, 20), rng.uniform(-3, 3, 20)], -1)
    >>> w = rng.normal(0.0, 50.0, (20, 3))
    >>> after = solve_sphere(ball.body, v, w, mu=0.62, kappa=0.75).after
    >>> data = {"vx": v[:, 0], "vy": v[:, 1], "vz": v[:, 2],
    ...         "wx": w[:, 0], "wy": w[:, 1], "wz": w[:, 2]}
    >>> for q in ("vx", "vy", "vz"):
    ...     data[f"after_{q}"] = getattr(after, q) + rng.normal(0.0, 0.05, 20)
    >>> res = fit_problem("sphere", data, body=ball)
    >>> print(res["mu"])
    mu = 0.6149 +- 0.0033 [0.6075, 0.6215]
    """
    declared = lookup(declared)
    conf = setting("confidence", confidence, low=0.5, rule="in (0.5, 1)")
    if conf >= 1.0:
        raise ValueError(f"confidence must be in (0.5, 1), got {confidence!r}")
    table = _table(measured)
    n = next(iter(table.values())).size
    law, law_spec, law_value, law_named = _law(tangential, declared)
    law_names = () if law_spec is None else (law_spec.name,)

    # -- the columns: inputs per bounce, measured results, their sigmas ----------------------
    outputs = set(declared.result_columns())
    echo = set(declared.echoes) | {f"before_{n_}" for n_ in declared.names}
    per_bounce: dict[str, np.ndarray] = {}
    quantities: list[str] = []
    sigmas: dict[str, np.ndarray] = {}
    for name, column in table.items():
        if name in declared.names:
            each = declared.input(name)
            per_bounce[name] = column.astype(object) if each.text else _numbers(
                name, column, missing_ok=False)  # fmt: skip
        elif name.startswith("sigma_"):
            sigmas[name[len("sigma_") :]] = column
        elif name in echo:
            raise ValueError(f"column {name} repeats an input of problem {declared.name!r}; "
                             "give the input's own column instead")  # fmt: skip
        elif name in outputs:
            quantities.append(name)
        else:
            raise ValueError(
                f"unknown column {name!r} for problem {declared.name!r}: its inputs are "
                f"{', '.join(declared.names)}; its result columns "
                f"{', '.join(sorted(outputs - echo - set(declared.names)))}; a measured "
                "column's standard deviation is sigma_<column>"
            )
    if not quantities:
        raise ValueError(
            f"no measured column: give at least one result column of problem "
            f"{declared.name!r} (such as {', '.join(sorted(outputs - echo)[:4])}...)"
        )
    for q in sigmas:
        if q not in quantities:
            raise ValueError(f"column sigma_{q} is the standard deviation of {q}, which is "
                             "not a measured column")  # fmt: skip
    if sigmas and len(sigmas) != len(quantities):
        absent = [f"sigma_{q}" for q in quantities if q not in sigmas]
        raise ValueError(f"give the sigma of every measured column or none: "
                         f"{', '.join(absent)} missing")  # fmt: skip
    observed = np.stack([_numbers(q, table[q], missing_ok=True) for q in quantities], -1)
    if not (~np.isnan(observed)).any():
        raise ValueError(f"no measured value: the columns {', '.join(quantities)} are all empty")
    sigma = None
    if sigmas:
        sigma = np.stack([_numbers(f"sigma_{q}", sigmas[q], missing_ok=True)
                          for q in quantities], -1)  # fmt: skip
        bad = ~np.isnan(observed) & ~(sigma > 0)
        if bad.any():
            i, j = np.argwhere(bad)[0]
            raise ValueError(f"sigma_{quantities[j]} must be > 0 wherever {quantities[j]} is "
                             f"measured, got {sigma[i, j]!r} at index {i}")  # fmt: skip

    # -- fixed values, the body, the free parameters -----------------------------------------
    if fixed is not None and not isinstance(fixed, Mapping):
        raise TypeError(f"fixed must be a dict of name to value, got {fixed!r}")
    held: dict[str, Any] = dict(fixed or {})
    body_name = None
    if body is not None:
        if isinstance(body, Ball):
            body = body.body
        if not isinstance(body, Body):
            raise TypeError(f"body must be a spinimpact.Body or Ball, got {body!r}")
        body_name = body.name
        for name in ("mass", "radius", "gyration"):
            if name not in declared.names:
                raise ValueError(f"problem {declared.name!r} has no body input {name!r}: "
                                 "give its inputs in fixed instead of body")  # fmt: skip
            if name in held or name in per_bounce:
                raise ValueError(f"{name} is given twice: by body and by "
                                 f"{'fixed' if name in held else 'a column'}")  # fmt: skip
            value = np.asarray(getattr(body, name), dtype=float)
            if value.size != 1:
                raise ValueError(f"body must be one body (not an array of them) for a fit, "
                                 f"got {name} of shape {value.shape}")  # fmt: skip
            held[name] = float(value.reshape(()))
    fittable = [i.name for i in declared.inputs if i.fittable] + list(law_names)
    for name in list(held):
        if name in law_names:
            continue
        if name not in declared.names:
            raise ValueError(
                f"fixed names {name!r}, which is neither an input of problem "
                f"{declared.name!r} nor the parameter of its law; its inputs are "
                f"{', '.join(declared.names)}"
            )
        if name in per_bounce:
            raise ValueError(f"{name} is given both per bounce (a column) and in fixed")
        each = declared.input(name)
        value = held[name]
        if not each.text:
            value = setting(f"fixed[{name!r}]", value)
        found = each.problems(np.asarray([value], dtype=object if each.text else float))[0]
        if found:
            raise ValueError(f"fixed[{name!r}]: {found}")
        held[name] = value
    if free is None:
        chosen = default_free(declared, per_bounce, held, tangential)
    else:
        chosen = list(_names("free", free))
    for name in chosen:
        if name not in declared.names and name not in law_names:
            laws = {"beta0", "poisson_ratio", "stiffness_ratio"}
            hint = " (a tangential law's parameter: give tangential=)" if name in laws else ""
            raise ValueError(
                f"free names {name!r}, which is neither an input of problem "
                f"{declared.name!r} nor the parameter of its law{hint}; the parameters it "
                f"can fit are {', '.join(fittable)}"
            )
        if name not in law_names and not declared.input(name).fittable:
            raise ValueError(
                f"free names {name!r}, an input of problem {declared.name!r} that a fit does "
                f"not estimate ({declared.input(name).description}): give it per bounce or "
                f"in fixed; the parameters it can fit are {', '.join(fittable)}"
            )
        if name in per_bounce:
            raise ValueError(f"free names {name!r}, which is given per bounce (a column): "
                             "drop the column to fit it")  # fmt: skip
        if name in held:
            raise ValueError(f"{name} is both free and fixed: choose one")
    if len(set(chosen)) != len(chosen):
        raise ValueError(f"free names a parameter twice: {chosen}")
    if not chosen:
        raise ValueError("nothing to fit: every parameter is given or fixed")
    if law_spec is not None and law_spec.name in held:
        law_value = setting(f"fixed[{law_spec.name!r}]", held.pop(law_spec.name))
        law = type(law)(**{law_spec.name: law_value})

    # -- bounds and starting values ---------------------------------------------------------
    defaults = {i.name: i.default for i in declared.inputs}
    radius = {k: np.asarray(per_bounce.get(k, held.get(k, defaults.get(k))), dtype=float)
              for k in declared.names if k.rstrip("0123456789") == "radius"}  # fmt: skip
    specs = []
    for name in chosen:
        if name in law_names:
            specs.append(law_spec)
            continue
        specs.append(_parameter(declared, declared.input(name), radius))
    if start is not None and not isinstance(start, Mapping):
        raise TypeError(f"start must be a dict of parameter name to value, got {start!r}")
    begin = dict(start or {})
    for name, value in begin.items():
        if name not in chosen:
            raise ValueError(f"start names {name!r}, which is not a free parameter; the free "
                             f"ones are {', '.join(chosen)}")  # fmt: skip
        spec = specs[chosen.index(name)]
        v = setting(f"start[{name!r}]", value)
        if not spec.low <= v <= spec.high:
            raise ValueError(f"start[{name!r}] must be in [{spec.low:g}, {spec.high:g}], "
                             f"got {value!r}")  # fmt: skip
        begin[name] = v
    theta0 = []
    for name, spec in zip(chosen, specs, strict=True):
        if name in begin:
            theta0.append(begin[name])
        elif name in law_names:
            theta0.append(law_value)
        elif name == "mu":
            theta0.append(0.1)
        elif isinstance(defaults[name], float | int):
            theta0.append(float(np.clip(defaults[name], spec.low, spec.high)))
        elif declared.input(name).rule == "gyration":
            r = radius.get("radius" + name[len("gyration") :], np.asarray(1.0))
            theta0.append(float(np.clip(math.sqrt(0.4) * np.nanmean(r), spec.low, spec.high)))
        else:
            theta0.append(float(np.clip(1.0, spec.low, spec.high)))

    # -- the columns every evaluation shares; checked once ------------------------------------
    values: dict[str, Any] = {**held, **per_bounce}
    values.update({k: v for k, v in zip(chosen, theta0, strict=True) if k not in law_names})
    columns = declared.columns(values)
    for name, column in columns.items():
        each = declared.input(name)
        if each.text and each.optional and not any(column):
            continue
        if not each.text and np.isnan(column).all() and each.optional:
            continue
        found = each.problems(column)
        if (found != "").any():
            i = int(np.argmax(found != ""))
            where = f" at index {i}" if name in per_bounce else ""
            raise ValueError(f"{found[i]}{where}")
    parameters = list(specs)
    free_mask = [True] * len(specs)
    if law_spec is not None and law_spec.name not in chosen:
        parameters.append(law_spec)
        free_mask.append(False)
        theta0.append(law_value)
    weights = _weights(declared, quantities, observed, radius)
    model = _Model(declared, columns, tuple(parameters), law,
                   None if law_spec is None else law_spec.name, tuple(quantities),
                   weights)  # fmt: skip
    theta = np.array(theta0, dtype=float)
    probe = model.solve(theta)[0].columns()
    for q in quantities:
        kind = np.asarray(probe[q]).dtype.kind
        if kind not in "fiu":
            what = "a flag" if kind == "b" else "text"
            raise ValueError(f"column {q} of problem {declared.name!r} is not a number (it is "
                             f"{what}): it cannot be fitted")  # fmt: skip
    source = _body_sources(declared, model, theta, per_bounce, held, chosen, quantities)
    normal = _normal(probe, quantities)
    size = 0.0
    if normal is not None:
        up, before, before_name = normal
        j = quantities.index(up)
        refuse_impossible(before, observed[:, j], None if sigma is None else sigma[:, j],
                          after_name=up, before_name=before_name)  # fmt: skip
        size = float(np.mean(-before))
        if "kappa" in chosen and "kappa" not in begin:  # kappa from the measured rebound
            ratio = observed[:, j] / -before
            ok = np.isfinite(ratio) & (ratio > 0)
            if ok.any():
                theta[chosen.index("kappa")] = float(np.clip(np.median(ratio[ok]), 0.05, 0.99))

    # -- the fit ---------------------------------------------------------------------------
    data = _Data(observed, sigma)
    free_arr = np.array(free_mask)
    k = int(free_arr.sum())
    if data.n_observations <= k:
        raise ValueError(
            f"too few usable values: {data.n_observations} measured value(s) in {n} "
            f"bounce(s) for {k} free parameter(s) ({', '.join(chosen)}); need at least {k + 1}"
        )
    prob = LeastSquares(model, data, theta, free_arr)
    if "mu" in chosen and "mu" not in begin:
        prob.theta[chosen.index("mu")] = prob.scan_mu()
    names_sigma = [f"sigma_{q}" for q in quantities]
    est = estimate(prob, prob.theta[free_arr], conf,
                   lambda p, chi2: scatter(p, chi2, size, names_sigma))  # fmt: skip
    if est.warning is not None:
        warnings.warn(est.warning, FitWarning, stacklevel=2)
    return _result(prob, est, conf, declared, law, law_spec, held, per_bounce, source,
                   body_name)  # fmt: skip


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


def _result(prob: LeastSquares, est: Any, conf: float, declared: Problem, law: Any,
            law_spec: Parameter | None, held: dict, per_bounce: dict,
            source: dict, body_name: str | None) -> ProblemFit:  # fmt: skip
    model = prob.model

    def contact(theta: np.ndarray, measured: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        regime, counted = model.regime(theta), measured.any(axis=1)
        if regime is None:
            return np.zeros(counted.shape, dtype=bool), np.zeros(counted.shape, dtype=bool)
        return (regime == "slip") & counted, np.isin(regime, STICKING) & counted

    common = summary(prob, est, conf, contact)
    values = model.values(prob.full(est.x))
    free_names = common["names"]
    law_dict = None
    if law is not None:
        law_dict = {"law": law.name, law_spec.name: float(values[law_spec.name])}
    fixed_out = dict(held)
    if law_spec is not None and law_spec.name not in free_names:
        fixed_out[law_spec.name] = float(values[law_spec.name])
    inputs: dict[str, Any] = {}
    for name in declared.names:
        if name in per_bounce:
            inputs[name] = per_bounce[name]
        elif name in values:
            inputs[name] = values[name]
        else:
            first = model.base[name][0]
            inputs[name] = first if isinstance(first, str) else float(first)
    incidence_names = tuple(k for k, v in per_bounce.items() if v.dtype.kind == "f")
    n = len(common["observed"])
    incidence = (np.stack([per_bounce[k] for k in incidence_names], -1) if incidence_names
                 else np.empty((n, 0)))  # fmt: skip
    angle = np.full(n, np.nan)
    if {"vx", "vy"} <= set(per_bounce):
        along = np.hypot(per_bounce["vx"], per_bounce.get("vz", 0.0))
        angle = np.degrees(np.arctan2(along, -per_bounce["vy"]))
    tangential = "rigid" if law is None else f"{law.name}"
    if law_spec is not None:
        tangential += (f" ({law_spec.name} fitted)" if law_spec.name in free_names
                       else f" ({law_spec.name} = {float(values[law_spec.name]):.4g})")  # fmt: skip
    return ProblemFit(
        model=f"{declared.name}, {tangential}",
        body=_body_record(inputs, source, body_name),
        fixed=fixed_out,
        incidence=incidence,
        incidence_angle_deg=angle,
        problem=declared.name,
        law=law_dict,
        quantities=tuple(model.quantities),
        units={q: declared.unit(q) for q in model.quantities},
        incidence_names=incidence_names,
        inputs=inputs,
        **common,
    )


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
