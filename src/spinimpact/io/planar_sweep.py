"""Sweeps of one planar body (a rod, a block, an eccentric disk, any ``PlanarBody``) or one
pendulum over incidences, in bounded memory.

A :class:`PlanarSweep` is a :class:`~spinimpact.io.sweep.Sweep` whose body is a
:class:`~spinimpact.PlanarBody` (axes ``vx, vy, omega, mu, kappa``) or a
:class:`~spinimpact.Pendulum` (axes ``omega, mu, kappa``: its centre moves with the
spin), with one restitution ``law``. :func:`~spinimpact.io.sweep.run_sweep` runs it as any
sweep: chunk by chunk, to Parquet or ``.npy`` files, folding regime fractions and
histograms on the fly, locally or on Dask.

Each chunk is solved by :func:`~spinimpact.solve_planar` (or
:func:`~spinimpact.solve_pendulum`) at once, so the fields are the
:class:`~spinimpact.PlanarImpact` columns of the same names (:func:`planar_fields`), the
very numbers the function gives. ``regime`` is computed as its index into
:data:`~spinimpact.core.planar.PLANAR_REGIMES` and written as names (a dictionary column
in Parquet, text in CSV; in ``.npy`` files the index, the names in ``metadata.json``,
with the body and the law); ``creates_energy`` as a flag.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import as_real_array, validated, whole
from ..core import planar as kernels
from ..core.planar import PLANAR_REGIMES
from ..model.planar import LAWS, PendulumImpact, PlanarImpact, solve_pendulum, solve_planar
from ..model.planar_body import Pendulum, PlanarBody
from ._axes import INPUTS, positive_int
from ._fields import ALIASES, regime_codes
from .sweep import Sweep

__all__ = ["PENDULUM_INPUTS", "PROCESS_FIELDS", "PlanarSweep", "planar_fields"]

#: The inputs a pendulum's sweep varies: its centre's velocity follows ``omega``.
PENDULUM_INPUTS = ("omega", "mu", "kappa")
#: Fields of the impact process alone (no works, no energies): computed without the rest.
PROCESS_FIELDS = (
    "before_vx",
    "before_vy",
    "after_vx",
    "after_vy",
    "after_omega",
    "slip_before",
    "slip_after",
    "normal_velocity_before",
    "normal_velocity_after",
    "regime",
    "tau0",
    "tau_star",
    "tau1",
    "tangential_impulse",
)


@functools.cache
def planar_fields(pendulum: bool = False) -> tuple[str, ...]:
    """The fields of a planar sweep: the result's columns that are not inputs.

    Parameters
    ----------
    pendulum : bool
        For a :class:`~spinimpact.Pendulum` (its ``before_vx, before_vy`` are fields).

    Returns
    -------
    tuple of str
        :meth:`PlanarImpact.column_names <spinimpact.model.result.Result.column_names>`
        less the body's columns, ``mu, kappa`` and the incidence.

    Examples
    --------
    >>> planar_fields()[:4]
    ('after_vx', 'after_vy', 'after_omega', 'slip_before')
    >>> planar_fields(pendulum=True)[:2]
    ('before_vx', 'before_vy')
    """
    result, body = (PendulumImpact, Pendulum) if pendulum else (PlanarImpact, PlanarBody)
    incidence = PENDULUM_INPUTS if pendulum else INPUTS
    inputs = {*body.COLUMNS, "mu", "kappa", *(f"before_{n}" for n in incidence)}
    return tuple(n for n in result.column_names() if n not in inputs)


@dataclass(frozen=True)
class PlanarSweep(Sweep):
    """A sweep over the incidences of one planar body or pendulum (see the module docstring).

    Parameters
    ----------
    body : PlanarBody or Pendulum
        One body (scalar mass, inertia and geometry).
    axes : dict
        ``name -> Axis`` for each of ``vx, vy`` (m/s), ``omega`` (rad/s), ``mu, kappa``;
        for a pendulum ``omega, mu, kappa`` only.
    samples, seed
        As for :class:`~spinimpact.io.sweep.Sweep`.
    chunk_size : int
        Points evaluated at a time (default 100,000: a chunk solved whole holds about
        60 MB); memory is bounded by it.
    law : {"poisson", "newton", "energetic"}
        The restitution law (:func:`~spinimpact.solve_planar`).

    Raises
    ------
    TypeError
        For a body that is neither, or a bad ``samples``, ``chunk_size`` or ``law``.
    ValueError
        For an array of bodies, a missing or extra axis, an unknown law, grid and
        random axes mixed, an axis value that is not finite (or ``mu < 0``, ``kappa``
        outside ``[0, 1]``), or any point of the sweep whose contact point does not
        approach the surface.

    Examples
    --------
    >>> import math
    >>> from spinimpact import PlanarBody
    >>> from spinimpact.io.sweep import parse_axis, run_sweep
    >>> rod = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(45))
    >>> spec = dict(vx="-1:1:5", vy="-1", omega="0", mu="0.5", kappa="0.5")
    >>> sweep = PlanarSweep(rod, {n: parse_axis(n, v) for n, v in spec.items()}, law="newton")
    >>> result = run_sweep(sweep)
    >>> result.points
    5
    >>> {name: share for name, share in result.regime_fractions.items() if share}
    {'slip': 0.4, 'reverse-compression': 0.2, 'reverse-restitution': 0.2, 'slip-from-rest': 0.2}
    """

    body: PlanarBody | Pendulum  # type: ignore[assignment]
    #: Points per chunk: solve_planar holds about 600 bytes a point (60 MB a chunk).
    chunk_size: int = 100_000
    law: str = "poisson"

    def __post_init__(self) -> None:
        object.__setattr__(self, "seed", whole("seed", self.seed, 0))
        b = self.body
        if not isinstance(b, PlanarBody | Pendulum):
            raise TypeError(
                f"body must be a spinimpact.PlanarBody or Pendulum, got {type(b).__name__}"
            )
        if any(np.ndim(getattr(b, n)) for n in b.COLUMNS):
            raise ValueError("a sweep needs a single body, not an array of bodies")
        if not isinstance(self.law, str):
            raise TypeError(f"law must be one of {', '.join(LAWS)}, got {self.law!r}")
        if self.law not in LAWS:
            raise ValueError(f"law must be one of {', '.join(LAWS)}, got {self.law!r}")
        extra = (
            [n for n in self.axes if n not in self.inputs] if isinstance(self.axes, dict) else []
        )
        if extra and self.pendulum and set(extra) <= {"vx", "vy"}:
            raise ValueError(
                f"a pendulum's sweep has no {' or '.join(extra)} axis: its centre moves with "
                f"omega (its inputs are {', '.join(self.inputs)})"
            )
        self._check_axes()
        positive_int("chunk_size", self.chunk_size)
        for a in self.axes.values():  # the contact point's approach is checked below
            for x in [a.lo] if a.kind == "fixed" else [a.lo, a.hi]:
                validated(a.name, x) if a.name in ("mu", "kappa") else as_real_array(a.name, x)
        self._check_approach()
        object.__setattr__(self, "_body", {})

    @property
    def pendulum(self) -> bool:
        """Whether the body is a pendulum on a pivot."""
        return isinstance(self.body, Pendulum)

    @property
    def inputs(self) -> tuple[str, ...]:  # type: ignore[override]
        """``vx, vy, omega, mu, kappa``; a pendulum's ``omega, mu, kappa``."""
        return PENDULUM_INPUTS if self.pendulum else INPUTS

    regimes = PLANAR_REGIMES

    def _range(self, name: str) -> tuple[float, float]:
        a = self.axes[name]
        return (a.lo, a.lo) if a.kind == "fixed" else (a.lo, a.hi)

    def _check_approach(self) -> None:
        """The contact's normal velocity is affine in the inputs: its largest value over
        the sweep is at a corner, and must be < 0."""
        b = self.body
        if self.pendulum:
            lever, what, others = float(b.px), "omega*px", {}
        else:
            lever, what = float(b.rx), "vy + omega*rx"
            others = {"vy": self._range("vy")[1]}
        omega = max(self._range("omega"), key=lambda w: w * lever)
        worst = sum(others.values()) + omega * lever
        if not worst < 0:
            at = ", ".join(f"{n} = {v:g}" for n, v in {**others, "omega": omega}.items())
            arm = "px" if self.pendulum else "rx"
            raise ValueError(
                f"the contact point must approach the surface at every point of the sweep, "
                f"but its normal velocity {what} reaches {worst:.6g} m/s at {at} "
                f"({arm} = {lever:.6g} m); narrow the range of "
                + ("omega" if self.pendulum else "vy or omega")
            )

    def field_name(self, name: str, role: str = "fields") -> str:
        """The field ``name`` stands for: itself (:func:`planar_fields`) or an alias's field."""
        fields = planar_fields(self.pendulum)
        if name in fields:
            return name
        if ALIASES.get(name) in fields:
            return ALIASES[name]
        aliases = ", ".join(f"{a} for {f}" for a, f in ALIASES.items())
        raise ValueError(f"{role} must be among {', '.join(fields)} (or {aliases}); got {name!r}")

    def column_dtype(self, name: str) -> np.dtype:
        """``int8`` regime codes, ``bool`` for ``creates_energy``, else ``float64``."""
        if name not in self.inputs and self.field_name(name, "column") == "creates_energy":
            return np.dtype(bool)
        return super().column_dtype(name)

    def description(self) -> dict[str, Any]:
        """The regimes' names, the body, the axes and the law."""
        return super().description() | {"law": self.law}

    def evaluate(self, k: int, fields: tuple[str, ...]) -> dict[str, np.ndarray]:
        """As :meth:`Sweep.evaluate <spinimpact.io.sweep.Sweep.evaluate>`, the fields named
        by :func:`planar_fields` (or aliases)."""
        c = self.chunk(k)
        out: dict[str, Any] = dict(c)
        wanted = {name: self.field_name(name) for name in fields}
        if set(wanted.values()) <= set(PROCESS_FIELDS):  # the process alone (5x faster)
            columns = self._process(c)
        elif wanted:
            columns = self._solve(c)
            columns["regime"] = regime_codes(columns["regime"], PLANAR_REGIMES)
        for name, f in wanted.items():
            out[name] = columns[f]
        n = self.chunk_length(k)
        return {name: np.broadcast_to(value, (n,)) for name, value in out.items()}

    def _process(self, c: dict[str, Any]) -> dict[str, Any]:
        """:data:`PROCESS_FIELDS` by the steps of :func:`~spinimpact.solve_planar`, without
        the works and energies: the same kernels on the same numbers."""
        b, omega = self.body, c["omega"]
        vx, vy = b.centre_velocity(omega) if self.pendulum else (c["vx"], c["vy"])  # type: ignore[union-attr]
        u, v = b.contact_velocity(vx, vy, omega)
        w = b.collision_matrix
        p = kernels.planar_process(
            u, v, w.tt, w.tn, w.nn, c["mu"], c["kappa"], LAWS.index(self.law)
        )
        after = b.apply_impulse(vx, vy, omega, p.friction_impulse, p.tau_end)
        values = (
            vx,
            vy,
            *after,
            u,
            p.slip_after,
            v,
            p.normal_after,
            p.regime,
            p.tau_compression,
            p.tau_slip,
            p.tau_end,
            p.friction_impulse,
        )
        return dict(zip(PROCESS_FIELDS, values, strict=True)) | {
            "regime": np.asarray(p.regime, np.int8)
        }

    def _solve(self, c: dict[str, Any]) -> dict[str, np.ndarray]:
        surface = {"mu": c["mu"], "kappa": c["kappa"], "law": self.law}
        if self.pendulum:
            return solve_pendulum(self.body, c["omega"], **surface).columns()  # type: ignore[arg-type]
        return solve_planar(self.body, c["vx"], c["vy"], c["omega"], **surface).columns()
