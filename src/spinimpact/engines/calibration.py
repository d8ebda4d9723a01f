r"""calibrate(): search an engine's contact settings for the rebounds closest to the exact ones.

A user of PyBullet or MuJoCo who wants a ball to bounce with a restitution
:math:`\kappa` and a Coulomb friction :math:`\mu` has to translate them into the engine's
own contact parameters, which neither engine defines the same way. :func:`calibrate`
does it by measurement: it bounces a set of incidences (velocities, spins, contact
phases) in the engine at the user's time step, and moves a few well-scaled contact
parameters with SciPy's Nelder-Mead simplex until the engine's rebound velocity and spin
are closest to :func:`spinimpact.solve`'s. It then measures the settings found on
held-out incidences drawn from the same ranges with another seed, which the search never
saw, and returns the settings with both sets of errors and the engine's own
configuration text (:meth:`Calibration.mjcf`, :meth:`Calibration.pybullet_source`).

The error of one rebound is :attr:`EngineRun.error <spinimpact.engines.EngineRun.error>`:
the largest of the errors of :math:`v_x^+`, :math:`v_y^+` and :math:`R\omega^+`, over the
incidence speed scale. The search minimises their median plus a tenth of their mean, plus
whatever their maximum exceeds the start's maximum by: the median is the figure reported,
and the other two terms keep the search from trading a few cases away for it (measured
without the last term, MuJoCo's search raised the friction coefficient to four times
``mu``, which made every contact stick: a median of 0.4 % and a worst case of 38 %).

What is searched, per engine (``x`` are the simplex's coordinates, each about 1 in size):

* **PyBullet**: the ball's ``restitution`` and ``lateralFriction`` (as multiples of
  ``kappa`` and ``mu``), its rolling and spinning friction, and the global
  ``contactBreakingThreshold``, ``contactERP``, ``restitutionVelocityThreshold`` and
  ``contactSlop`` (as multiples of their defaults), each ``max(x, 0)`` times its scale,
  from PyBullet's defaults with ``restitution = kappa``, ``lateralFriction = mu``.
* **MuJoCo**: a contact pair's ``solref`` (time constant and damping ratio),
  ``solreffriction`` (time constant and damping ratio), a flat impedance ``solimp``
  (``dmin = dmax = d``) and the sliding friction (a multiple of ``mu``), with the elliptic
  cone. MuJoCo's own default contact (``solref`` 0.02 s, critically damped) bounces at
  about 0.14 whatever ``kappa`` is, so the search starts instead from a contact lasting
  about 100 time steps (the time constant of the damped linear oscillator whose damping
  ratio :math:`\xi = -\ln\kappa / \sqrt{\pi^2 + \ln^2\kappa}` bounces with
  :math:`\kappa`), a friction time constant of 60 steps, and the damping ratio that
  :func:`~spinimpact.engines.restitution_settings` solves for a head-on restitution
  ``kappa`` at the cases' median speed.

After the simplex, each setting is tried at simpler values (0, the engine's default,
fewer significant digits) and kept there where the calibration error is no larger, so
that exact settings come out as the round numbers they are.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import as_real_array, check, scalar, validated
from ..model.body import Body
from ..model.impact import solve
from ..model.result import Result
from . import configure
from .common import CONFIGURABLE, EngineRun, check_engine, one_body, shaped, whole_number

__all__ = ["Calibration", "calibrate", "calibration_cases"]

#: The ranges of :func:`calibration_cases`: m/s, m/s, rim speed m/s, fraction of a step.
RANGES = {"vx": (-2.0, 3.0), "vy": (-3.0, -1.0), "rim": (-3.0, 2.0), "phase": (0.0, 1.0)}
#: The mean's weight beside the median in the calibration error.
_MEAN_WEIGHT = 0.1
#: Most passes of the final simplification over the settings.
_SNAP_PASSES = 3
#: The calibration error of settings the engine cannot run (a contact that never ends).
_PENALTY = 10.0


def calibration_cases(n: int = 48, seed: int = 0, radius: float = 0.1) -> dict[str, np.ndarray]:
    """Incidences drawn uniformly from the ranges of :func:`~spinimpact.engines.standard_cases`.

    Parameters
    ----------
    n : int
        Number of incidences, ``>= 1``.
    seed : int
        Seed of NumPy's default generator.
    radius : float
        The body's radius, m: the spin is drawn as a rim speed ``R omega``.

    Returns
    -------
    dict
        Flat arrays ``vx`` in [-2, 3] m/s, ``vy`` in [-3, -1] m/s, ``omega`` (rim speed
        ``R omega`` in [-3, 2] m/s), and ``phase`` in [0, 1).
    """
    n = whole_number("n", n)
    seed = whole_number("seed", seed, low=0)
    radius = scalar("radius", radius)
    rng = np.random.default_rng(seed)
    draw = {k: rng.uniform(lo, hi, n) for k, (lo, hi) in RANGES.items()}
    return {
        "vx": draw["vx"],
        "vy": draw["vy"],
        "omega": draw["rim"] / radius,
        "phase": draw["phase"],
    }


# -- the search spaces --------------------------------------------------------------------
@dataclass(frozen=True)
class _Space:
    """Simplex coordinates ``x`` to engine settings, and where the simplex starts."""

    names: tuple[str, ...]
    start: np.ndarray
    steps: np.ndarray
    settings: Callable[[np.ndarray], dict[str, Any]]


def _clean(value: float) -> float:
    """``value`` to 15 significant digits: 0.3 * 1.1 is written 0.33, not 0.33000000000000004."""
    return float(f"{value:.15g}")


def _pybullet_space(mu: float, kappa: float, dt: float) -> _Space:
    d = configure.PYBULLET_SETTINGS
    scales = {
        "restitution": kappa or 1.0,
        "lateral_friction": mu or 1.0,
        "rolling_friction": 0.01,
        "spinning_friction": 0.01,
        "contact_breaking_threshold": d["contact_breaking_threshold"],
        "contact_erp": d["contact_erp"],
        "restitution_velocity_threshold": d["restitution_velocity_threshold"],
        "contact_slop": d["contact_slop"],
    }
    start = np.array([1.0 if kappa else 0.0, 1.0 if mu else 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0])

    def settings(x: np.ndarray) -> dict[str, Any]:
        out = {k: _clean(max(v, 0.0) * s) for (k, s), v in zip(scales.items(), x, strict=True)}
        return {"timestep": dt, **out}

    return _Space(tuple(scales), start, np.full(start.size, 0.5), settings)


def _mujoco_space(mu: float, kappa: float, dt: float) -> _Space:
    log = math.log(min(max(kappa, 1e-3), 0.999))
    xi = -log / math.sqrt(math.pi**2 + log**2)
    # a contact of 100 steps: its duration is about pi * timeconst * dampratio
    start = np.array(
        [math.log(100.0 / (math.pi * xi)), xi, math.log(60.0), 0.0, math.log(0.01), 1.0]
    )
    names = ("solref_timeconst", "solref_dampratio", "solreffriction_timeconst",
             "solreffriction_dampratio", "solimp", "friction")  # fmt: skip

    def settings(x: np.ndarray) -> dict[str, Any]:
        d = 1.0 - min(math.exp(x[4]), 0.9)
        slide = _clean(max(x[5], 0.0) * mu)
        return {
            "timestep": dt,
            "solref": (math.exp(x[0]) * dt, max(x[1], 1e-4)),
            "solreffriction": (math.exp(x[2]) * dt, math.exp(x[3])),
            "solimp": (d, d, 0.001, 0.5, 2.0),
            "friction": (slide, slide, 0.0, 0.0, 0.0),
            "condim": 3,
            "impratio": 1.0,
            "cone": "elliptic",
        }

    return _Space(names, start, np.array([0.5, 0.3 * xi, 0.5, 0.5, 1.0, 0.2]), settings)


# -- the result ---------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class Calibration(Result):
    """Contact settings found by :func:`calibrate`, with their errors measured.

    Attributes
    ----------
    engine : str
        ``"pybullet"`` or ``"mujoco"``.
    version : str
        The engine's version (``mujoco.__version__``; PyBullet's API version).
    settings : Mapping
        The settings found, in the engine's terms (keys of
        :data:`~spinimpact.engines.configure.MUJOCO_SETTINGS` or
        :data:`~spinimpact.engines.configure.PYBULLET_SETTINGS`).
    start : Mapping
        The settings the search started from.
    mu, kappa : float
        The Coulomb friction coefficient and restitution the settings stand for.
    timestep : float
        The time step, s (fixed: never searched).
    calibration, held_out : EngineRun
        The engine's rebounds at ``settings`` beside the exact answer, on the
        incidences the search used and on held-out ones it never saw.
    start_held_out : EngineRun
        The same held-out incidences at the ``start`` settings.
    evaluations : int
        Batches the engine ran during the search.
    seconds : float
        Wall time of the whole calibration, s.
    """

    engine: str
    version: str
    settings: Mapping[str, Any]
    start: Mapping[str, Any]
    mu: float
    kappa: float
    timestep: float
    calibration: EngineRun
    held_out: EngineRun
    start_held_out: EngineRun
    evaluations: int
    seconds: float

    _per_impact = False

    @property
    def shape(self) -> tuple[int, ...]:
        """``()``: a calibration is one set of settings."""
        return ()

    def errors(self) -> dict[str, dict[str, float]]:
        """Median and worst error of each rebound quantity, on each set of incidences.

        Returns
        -------
        dict
            ``{"calibration" | "held_out" | "start_held_out": {"vx" | "vy" | "omega" |
            "worst": {"median", "max"}}}``, floats; each error is relative to the
            incidence speed scale (:meth:`EngineRun.errors`).
        """
        runs = {"calibration": self.calibration, "held_out": self.held_out,
                "start_held_out": self.start_held_out}  # fmt: skip
        return {
            name: {k: {"median": v["median"], "max": v["max"]} for k, v in run.summary().items()}
            for name, run in runs.items()
        }

    def _note(self) -> str:
        return (
            f"contact calibrated by spinimpact.engines.calibrate for mu={self.mu!r}, "
            f"kappa={self.kappa!r}, time step {self.timestep!r} s; held-out rebound error "
            f"median {self.held_out.summary()['worst']['median']:.2g}, "
            f"worst {self.held_out.summary()['worst']['max']:.2g} of the speed scale"
        )

    def mjcf(self) -> str:
        """The MuJoCo settings as an MJCF fragment (:func:`~spinimpact.engines.configure.mjcf`).

        Raises
        ------
        ValueError
            If the calibration is not MuJoCo's.
        """
        if self.engine != "mujoco":
            raise ValueError(f"mjcf() writes MuJoCo settings; this calibration is {self.engine}'s")
        return configure.mjcf(self.settings, note=self._note())

    def pybullet_source(self) -> str:
        """The PyBullet settings as Python calls.

        See :func:`~spinimpact.engines.configure.pybullet_source`.

        Raises
        ------
        ValueError
            If the calibration is not PyBullet's.
        """
        if self.engine != "pybullet":
            raise ValueError(
                f"pybullet_source() writes PyBullet settings; this calibration is {self.engine}'s"
            )
        return configure.pybullet_source(self.settings, note=self._note())

    def configuration(self) -> str:
        """The engine's own configuration text: :meth:`mjcf` or :meth:`pybullet_source`."""
        return self.mjcf() if self.engine == "mujoco" else self.pybullet_source()

    def to_dict(self) -> dict[str, Any]:
        """The engine, version, settings, inputs, errors and cost as plain values (JSON)."""
        return {
            "engine": self.engine,
            "version": self.version,
            "settings": _plain(self.settings),
            "start": _plain(self.start),
            "mu": self.mu,
            "kappa": self.kappa,
            "timestep": self.timestep,
            "cases": int(self.calibration.batch_size),
            "held_out_cases": int(self.held_out.batch_size),
            "errors": self.errors(),
            "evaluations": self.evaluations,
            "seconds": self.seconds,
        }


def _plain(settings: Mapping[str, Any]) -> dict[str, Any]:
    return {k: list(v) if isinstance(v, tuple) else v for k, v in settings.items()}


# -- the search -------------------------------------------------------------------------------
def _cases(name: str, cases: Any, n: int, seed: int, radius: float) -> dict[str, np.ndarray]:
    """Validated flat incidences: given (a mapping with vx, vy, omega, phase) or drawn."""
    if cases is None:
        return calibration_cases(n, seed, radius)
    if not isinstance(cases, Mapping):
        raise TypeError(
            f"{name} must be a mapping of vx, vy, omega and phase arrays, got {cases!r}"
        )
    missing = {"vx", "vy", "omega", "phase"} - set(cases)
    if missing:
        raise ValueError(f"{name} lacks {', '.join(sorted(missing))}")
    out = {k: validated(k, cases[k]) for k in ("vx", "vy", "omega")}
    out["phase"] = as_real_array("phase", cases["phase"])
    check("phase", out["phase"], lambda p: (p >= 0) & (p < 1), "in [0, 1)")
    arrays = np.broadcast_arrays(*out.values())
    return {k: np.ravel(a).astype(np.float64) for k, a in zip(out, arrays, strict=True)}


class _Bench:
    """One set of incidences, its exact answer, and the engine's runs on it."""

    def __init__(self, engine: str, body: Body, cases: dict[str, np.ndarray], mu, kappa):
        self.engine, self.body, self.cases = engine, body, cases
        self.exact = solve(body, cases["vx"], cases["vy"], cases["omega"], mu=mu, kappa=kappa)
        after, radius = self.exact.after, float(body.radius)
        self.target = np.stack([after.vx, after.vy, radius * after.omega])
        rim = np.abs(radius * cases["omega"])
        self.scale = np.maximum.reduce([np.abs(cases["vx"]), np.abs(cases["vy"]), rim])
        self.ceiling = np.inf  # a worst error above it is added to the calibration error

    def stepped(self, settings: Mapping[str, Any]):
        c = self.cases
        return configure.run(
            self.engine, self.body, c["vx"], c["vy"], c["omega"], c["phase"], settings
        )

    def error(self, settings: Mapping[str, Any]) -> float:
        """The calibration error: median + a tenth of the mean of the worst of three."""
        try:
            out = self.stepped(settings)
        except RuntimeError:
            return _PENALTY
        got = np.stack([out.vx, out.vy, float(self.body.radius) * out.omega])
        worst = np.max(np.abs(got - self.target), axis=0) / self.scale
        if not np.all(np.isfinite(worst)):
            return _PENALTY
        excess = max(float(np.max(worst)) - self.ceiling, 0.0)
        return float(np.median(worst) + _MEAN_WEIGHT * np.mean(worst) + excess)

    def run(self, settings: Mapping[str, Any]) -> EngineRun:
        out = self.stepped(settings)
        shape = (self.cases["vx"].size,)
        return EngineRun(
            engine=self.engine, settings=out.settings, vx=shaped(out.vx, shape),
            vy=shaped(out.vy, shape), omega=shaped(out.omega, shape), exact=self.exact,
            phase=shaped(self.cases["phase"], shape), steps=out.steps, seconds=out.seconds,
            batch_size=shape[0],
        )  # fmt: skip


def _simpler(value: float, default: float) -> list[float]:
    """Simpler values to try for one coordinate's setting: 0, the default, fewer digits."""
    out = [0.0, default] + [float(f"{value:.{d}g}") for d in range(1, 7)]
    return [v for i, v in enumerate(out) if v not in out[:i]]


def _head_on_dampratio(space: _Space, bench: _Bench, kappa: float, dt: float) -> float:
    """MuJoCo's start: the damping ratio giving a head-on restitution ``kappa`` at the cases'
    median speed (:func:`~spinimpact.engines.restitution_settings`), or the damped
    oscillator's where none does."""
    from .restitution import restitution_settings

    fixed = {k: v for k, v in space.settings(space.start).items() if k != "timestep"}
    speed = float(np.median(np.abs(bench.cases["vy"])))
    try:
        found = restitution_settings("mujoco", kappa, speed, dt, bench.body, **fixed)
    except ValueError:
        return float(space.start[1])
    return float(found["solref"][1])


def _full(start: np.ndarray, free: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The coordinates: ``start`` with the free ones from ``y``."""
    x = start.copy()
    x[free] = y
    return x


def _snap(
    space: _Space, bench: _Bench, x: np.ndarray, best: float, free: np.ndarray
) -> tuple[np.ndarray, float, int]:
    """Move each free coordinate to a simpler value where the calibration error is no larger.

    Passes over the coordinates repeat (at most :data:`_SNAP_PASSES`) while one moves: a
    value that was best beside the others' unsnapped values may not be after they moved.
    """
    x, runs = x.copy(), 0
    for _ in range(_SNAP_PASSES):
        moved = False
        for i in np.flatnonzero(free):
            for value in _simpler(x[i], space.start[i]):
                if value == x[i]:
                    break  # already as simple as this
                trial = x.copy()
                trial[i] = value
                err = bench.error(space.settings(trial))
                runs += 1
                if err <= best * (1 + 1e-9) + 1e-15:
                    x, best, moved = trial, min(best, err), True
                    break
        if not moved:
            break
    return x, best, runs


def calibrate(
    engine: str,
    body: Body,
    *,
    mu: float,
    kappa: float,
    dt: float,
    cases: Mapping[str, Any] | None = None,
    held_out: Mapping[str, Any] | None = None,
    n: int = 48,
    seed: int = 0,
    max_evaluations: int = 300,
    hold: tuple[str, ...] = (),
) -> Calibration:
    """Search the engine's contact settings for rebounds closest to :func:`~spinimpact.solve`.

    Parameters
    ----------
    engine : {"pybullet", "mujoco"}
        The engine (the ``[engines]`` extra).
    body : Body
        The body, with scalar mass (kg), radius (m) and gyration (m); the engine sees a
        sphere of its radius with isotropic inertia ``mass * gyration**2``.
    mu : float
        Coulomb friction coefficient, ``>= 0``.
    kappa : float
        Coefficient of restitution in ``[0, 1]``.
    dt : float
        The engine's time step, s (the user's, fixed: never searched).
    cases : mapping, optional
        Incidences to calibrate on: arrays ``vx``, ``vy`` (m/s, ``< 0``), ``omega``
        (rad/s) and ``phase`` (in [0, 1)); by default ``n`` drawn by
        :func:`calibration_cases` with ``seed``.
    held_out : mapping, optional
        Incidences to measure the settings found on, never searched on; by default
        ``n`` drawn with ``seed + 1``.
    n : int
        Number of incidences drawn for each default set.
    seed : int
        Seed of the calibration incidences.
    max_evaluations : int
        Batches the simplex may run (the final simplification adds a few).
    hold : tuple of str
        Settings held at the start, not searched: PyBullet's ``"restitution"``,
        ``"lateral_friction"``, ``"rolling_friction"``, ``"spinning_friction"``,
        ``"contact_breaking_threshold"``, ``"contact_erp"``,
        ``"restitution_velocity_threshold"``, ``"contact_slop"``; MuJoCo's
        ``"solref_timeconst"``, ``"solref_dampratio"``, ``"solreffriction_timeconst"``,
        ``"solreffriction_dampratio"``, ``"solimp"``, ``"friction"`` (``hold=("friction",)``
        keeps MuJoCo's sliding friction at ``mu``).

    Returns
    -------
    Calibration
        The settings found, the engine's version, the engine's rebounds on both sets of
        incidences beside the exact answer, and the held-out rebounds at the start.

    Raises
    ------
    TypeError
        For an input of the wrong type.
    ValueError
        For an unknown engine, a value out of range, or incidences that are not
        approaching (``vy >= 0``).
    ImportError
        If the engine is not installed.

    Examples
    --------
    >>> from spinimpact import Body
    >>> from spinimpact.engines import calibrate
    >>> ball = Body.solid_sphere(mass=1.0, radius=0.1)
    >>> cal = calibrate("pybullet", ball, mu=0.3, kappa=0.8, dt=1 / 240, n=8,
    ...                 max_evaluations=120)
    >>> errors = cal.errors()
    >>> bool(errors["held_out"]["worst"]["max"] < errors["start_held_out"]["worst"]["max"])
    True
    """
    began = time.perf_counter()
    check_engine(engine, CONFIGURABLE)
    body = one_body(body, "a calibration takes one body size")
    mu, kappa = scalar("mu", mu), scalar("kappa", kappa)
    dt = configure._number("dt", dt, zero=False)
    seed = whole_number("seed", seed, low=0)
    budget = whole_number("max_evaluations", max_evaluations)
    radius = float(body.radius)
    benches = [
        _Bench(engine, body, _cases(name, given, n, s, radius), mu, kappa)
        for name, given, s in (("cases", cases, seed), ("held_out", held_out, seed + 1))
    ]
    space = (_mujoco_space if engine == "mujoco" else _pybullet_space)(mu, kappa, dt)
    if isinstance(hold, str) or not all(isinstance(h, str) for h in hold):
        raise TypeError(f"hold must be a tuple of setting names, got {hold!r}")
    unknown = sorted(set(hold) - set(space.names))
    if unknown:
        raise ValueError(
            f"hold names no {engine} setting searched: {', '.join(unknown)} "
            f"(those are {', '.join(space.names)})"
        )
    steps = np.where(np.isin(np.array(space.names), list(hold)), 0.0, space.steps)
    from scipy.optimize import minimize

    bench = benches[0]
    if engine == "mujoco" and "solref_dampratio" not in hold:
        space.start[1] = _head_on_dampratio(space, bench, kappa, dt)
    try:  # no worse in the worst case than the start
        bench.ceiling = float(np.max(bench.run(space.settings(space.start)).error))
    except RuntimeError:
        pass
    free = steps != 0
    simplex = np.vstack([space.start, space.start + np.diag(steps)[free]])
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        found = minimize(
            lambda y: bench.error(space.settings(_full(space.start, free, y))), space.start[free],
            method="Nelder-Mead",
            options={"maxfev": budget, "initial_simplex": simplex[:, free], "xatol": 1e-6,
                     "fatol": 1e-14},
        )  # fmt: skip
        x = _full(space.start, free, found.x)
        x, best, snaps = _snap(space, bench, x, float(found.fun), free)
    settings = configure.checked(engine, space.settings(x))
    start = configure.checked(engine, space.settings(space.start))
    return Calibration(
        engine=engine, version=configure.version(engine), settings=settings, start=start,
        mu=mu, kappa=kappa, timestep=dt, calibration=bench.run(settings),
        held_out=benches[1].run(settings), start_held_out=benches[1].run(start),
        evaluations=int(found.nfev) + snaps, seconds=time.perf_counter() - began,
    )  # fmt: skip
