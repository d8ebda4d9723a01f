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

from .._validation import setting
from .body import Body
from .fit import NoScatterError, estimate, refuse_impossible, scatter, summary
from .fit_models import Parameter
from .fit_problem_model import (
    STICKING,
    _body_record,
    _body_sources,
    _Data,
    _law,
    _Model,
    _names,
    _normal,
    _numbers,
    _parameter,
    _table,
    _weights,
    body_inputs,
    default_free,
)
from .fit_profile import Problem as LeastSquares
from .fit_result import FitResult, FitWarning
from .presets import Ball
from .registry import Problem
from .registry import problem as lookup

__all__ = ["fit_problem", "ProblemFit", "body_inputs", "default_free", "NoScatterError"]


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
    force: bool = False,
    announce: Any = None,
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
    tangential : None, "walton", "stronge", "mindlin-deresiewicz", or such a law
        The tangential law: ``None`` the rigid law; a law instance holds its parameter
        fixed (unless named in ``free``); a law's name fits its parameter (``beta0``;
        ``poisson_ratio``). Micro-slip (``MindlinDeresiewicz``) is read from its table where
        ``kappa >= 0.85`` and solved in time elsewhere, which makes each evaluation of
        the fit slower there.
    confidence : float
        Level of the profile-likelihood intervals, in ``(0.5, 1)``.
    start : dict, optional
        Starting values of free parameters (by default: their declared defaults,
        ``kappa`` from the measured normal rebound, and a scan over ``mu``).

    force, announce
        As for :func:`spinimpact.fit`: a fit estimated over an hour is refused unless
        ``force``; ``announce`` hears an estimate over a minute.

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
                   lambda p, chi2: scatter(p, chi2, size, names_sigma), force=force,
                   announce=announce)  # fmt: skip
    if est.warning is not None:
        warnings.warn(est.warning, FitWarning, stacklevel=2)
    return _result(prob, est, conf, declared, law, law_spec, held, per_bounce, source,
                   body_name)  # fmt: skip


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
