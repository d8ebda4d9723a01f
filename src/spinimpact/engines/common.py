"""What every engine shares: the result, the standard cases, the scene and the axes.

:class:`EngineRun` holds an engine's rebounds beside the exact
:class:`~spinimpact.Impact` and measures the error; :func:`standard_cases` is
the grid on which the engines are compared; :data:`CONFIGURATIONS` names the
set-ups compared in ``docs/performance.md``. The remaining helpers are for the
engine modules (:mod:`spinimpact.engines.pybullet`,
:mod:`spinimpact.engines.mujoco`): the layout of the scene, the mapping between
the paper's axes and the engines' z-up axes, and the checks of engine settings
that :mod:`spinimpact._validation` does not cover.
"""

from __future__ import annotations

import numbers
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from .. import _validation
from ..model.body import Body, as_body
from ..model.impact import Impact
from ..model.result import Array, Result

__all__ = [
    "CONFIGURATIONS",
    "ENGINES",
    "EngineRun",
    "available",
    "standard_cases",
]

#: The engines this package can drive, each from the ``[engines]`` extra.
ENGINES = ("pybullet", "mujoco", "drake")

#: The engines whose own contact settings :func:`~spinimpact.engines.calibrate`,
#: :func:`~spinimpact.engines.restitution_settings` and
#: :mod:`~spinimpact.engines.configure` search and write out.
CONFIGURABLE = ("pybullet", "mujoco")

#: Each engine's Python package (its import name).
MODULES = {"pybullet": "pybullet", "mujoco": "mujoco", "drake": "pydrake"}

#: The engine set-ups compared in ``docs/performance.md`` and by ``make bench``:
#: (label, engine, settings for :func:`~spinimpact.engines.bounce`), each engine's
#: defaults first.
CONFIGURATIONS = (
    ("PyBullet, 240 Hz (its default)", "pybullet", {}),
    ("PyBullet, 1000 Hz", "pybullet", {"hz": 1000.0}),
    (
        "PyBullet, 240 Hz, exact-contact settings",
        "pybullet",
        {
            "contact_breaking_threshold": 0.0,
            "contact_erp": 0.0,
            "restitution_velocity_threshold": 0.0,
        },
    ),
    ("MuJoCo, its default contact", "mujoco", {"contact": "default"}),
    ("MuJoCo, calibrated, pyramidal", "mujoco", {"friction_time": None}),
    ("MuJoCo, calibrated, elliptic + solreffriction", "mujoco", {}),
    ("Drake, its default contact (lagged, 1 ms)", "drake", {"contact": "default"}),
    ("Drake, calibrated Hunt-Crossley, lagged", "drake", {}),
    ("Drake, calibrated Hunt-Crossley, similar", "drake", {"approximation": "similar"}),
)

#: Whole time steps of free flight before the step in which contact begins.
LEAD_STEPS = 2


# -- the engines ---------------------------------------------------------------------
def check_engine(engine: Any, engines: tuple[str, ...] = ENGINES) -> str:
    """``engine`` itself if it names one of ``engines`` (by default :data:`ENGINES`).

    Raises
    ------
    TypeError
        If ``engine`` is not a string.
    ValueError
        If it names none of ``engines``.
    """
    text = f"engine must be one of {', '.join(engines)}; got {engine!r}"
    if not isinstance(engine, str):
        raise TypeError(text)
    if engine not in engines:
        raise ValueError(text)
    return engine


def available(engine: str) -> bool:
    """Whether ``engine`` can be imported here, without importing it.

    Parameters
    ----------
    engine : {"pybullet", "mujoco", "drake"}
        One of :data:`ENGINES`.

    Returns
    -------
    bool
        ``True`` if the engine's Python package is installed (the ``[engines]``
        extra, ``pip install 'spinimpact[engines]'``).

    Raises
    ------
    TypeError, ValueError
        If ``engine`` is not one of :data:`ENGINES`.
    """
    return _validation.available(MODULES[check_engine(engine)])


# -- settings that spinimpact._validation does not cover --------------------------------
def one_body(body: Any, why: str) -> Body:
    """``body`` (a :class:`~spinimpact.Body`, or a ball, as every solver takes it) as a Body
    of one size: ``TypeError`` for anything else, ``ValueError`` for arrays of sizes
    (``why`` says why one size)."""
    body = as_body(body)
    for name in ("mass", "radius", "gyration"):
        _validation.scalar(f"body.{name}", getattr(body, name), why=why)
    return body


def whole_number(name: str, value: Any, low: int = 1) -> int:
    """A whole-number setting ``>= low`` (a Python or NumPy integer, not a bool).

    Raises
    ------
    TypeError
        If ``value`` is not an integer (a float, a bool, a string, ``None``).
    ValueError
        If it is below ``low``.
    """
    rule = f"a whole number >= {low}"
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be {rule}, got {value!r}")
    if value < low:
        raise ValueError(f"{name} must be {rule}, got {value!r}")
    return int(value)


def choice(name: str, value: Any, options: tuple[str, ...]) -> str:
    """One of the strings ``options``.

    Raises
    ------
    TypeError
        If ``value`` is not a string.
    ValueError
        If it is none of ``options``; the message names them.
    """
    text = f"{name} must be {' or '.join(repr(o) for o in options)}, got {value!r}"
    if not isinstance(value, str):
        raise TypeError(text)
    if value not in options:
        raise ValueError(text)
    return value


def no_more(engine: str, settings: Mapping[str, Any]) -> None:
    """Raise ``ValueError`` naming the settings left over, which ``engine`` does not know."""
    if settings:
        raise ValueError(f"unknown {engine} setting(s): {', '.join(sorted(settings))}")


# -- the scene and the axes ---------------------------------------------------------------
def spacing(radius: float) -> float:
    """Distance between neighbouring spheres of one scene, m: they never touch."""
    return 4.0 * radius + 1.0


def start_heights(radius: float, vy: np.ndarray, phase: np.ndarray, dt: float) -> np.ndarray:
    """Heights of the spheres' centres at the start, m.

    Each sphere flies ``LEAD_STEPS + phase`` time steps of ``dt`` seconds at the
    speed ``|vy|`` before it touches the plane, so that contact begins at the
    fraction ``phase`` of the time step ``LEAD_STEPS + 1``.
    """
    return radius + np.abs(vy) * (LEAD_STEPS + phase) * dt


def to_engine(vx: np.ndarray, vy: np.ndarray, omega: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The engines' linear and angular velocities, ``(n, 3)`` each, in z-up axes.

    Paper axes map to the engines' as x -> x, y -> z; the spin ``omega``,
    counter-clockwise about the paper's z = x cross y, is the angular velocity
    ``(0, -omega, 0)`` (the paper's z is the engines' -y).
    """
    zero = np.zeros_like(vx)
    return np.stack([vx, zero, vy], axis=-1), np.stack([zero, -omega, zero], axis=-1)


def from_engine(
    linear: np.ndarray, angular: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(vx, vy, omega)`` in the paper's axes from ``(n, 3)`` engine velocities.

    The inverse of :func:`to_engine` in the plane of motion; the out-of-plane
    components are not read.
    """
    return linear[:, 0].copy(), linear[:, 2].copy(), -angular[:, 1]


class Stepped(NamedTuple):
    """What an engine module's ``run`` returns to :func:`~spinimpact.engines.bounce`."""

    vx: np.ndarray  #: rebound velocity along the surface, m/s (flat)
    vy: np.ndarray  #: rebound normal velocity, m/s (flat)
    omega: np.ndarray  #: rebound spin, rad/s (flat)
    steps: int  #: time steps taken
    seconds: float  #: wall time of the stepping, s
    settings: dict[str, Any]  #: every setting used, defaults included


def shaped(x: Any, shape: tuple[int, ...]) -> Any:
    """Read-only float array of ``shape``; a NumPy scalar for 0-d, as ``solve`` gives."""
    arr = np.reshape(np.array(x, dtype=np.float64), shape)
    arr.setflags(write=False)
    return arr[()]


# -- the result ---------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class EngineRun(Result):
    """An engine's rebounds of a batch of impacts, beside the exact answer.

    A :class:`~spinimpact.model.result.Result`: ``run.shape`` is the broadcast
    shape of the impacts, ``run[i]`` selects impacts (the engine's rebounds, the
    exact answer and the phase; ``settings``, ``steps``, ``seconds`` and
    ``batch_size`` keep describing the whole engine run), ``run.to_dict()`` gives
    plain values for JSON and ``run.columns()`` flat columns (``vx, vy, omega``,
    the exact answer's as ``exact_after_vx``, ..., and ``phase``).

    Attributes
    ----------
    engine : str
        ``"pybullet"``, ``"mujoco"`` or ``"drake"``.
    settings : Mapping
        The engine settings used (time step, solver options, ...); for the
        calibrated MuJoCo contact also its ``stiffness`` (1/s^2) and the flat
        array of each impact's calibrated ``damping`` (1/s), the negated
        ``solref`` of its contact pair.
    vx, vy : ndarray
        The engine's rebound velocity, in the paper's axes, m/s.
    omega : ndarray
        The engine's rebound spin, counter-clockwise positive, rad/s.
    exact : Impact
        :func:`spinimpact.solve` of the same impacts.
    phase : ndarray
        Where, as a fraction of the time step, the body reached the surface.
    steps : int
        Time steps the engine took for the batch.
    seconds : float
        Wall time of the engine's stepping for the whole batch (setting up the
        scene is not counted), s.
    batch_size : int
        Number of impacts the engine stepped together in one scene.
    """

    engine: str
    settings: Mapping[str, Any]
    vx: Array
    vy: Array
    omega: Array
    exact: Impact
    phase: Array
    steps: int
    seconds: float
    batch_size: int

    _shape_field = "vx"

    @property
    def scale(self) -> np.ndarray:
        """Speed scale of each impact: ``max(|vx|, |vy|, R |omega|)`` before it, m/s."""
        before, radius = self.exact.before, self.exact.body.radius
        return np.maximum.reduce(
            [np.abs(before.vx), np.abs(before.vy), np.abs(radius * before.omega)]
        )

    def errors(self) -> dict[str, np.ndarray]:
        """Error of each rebound quantity relative to the incidence speed scale.

        Returns
        -------
        dict
            ``"vx"``: ``|vx_engine - vx_exact| / scale``, ``"vy"`` the same for
            ``vy``, and ``"omega"``: the rim speed's ``R |omega_engine -
            omega_exact| / scale``, with :attr:`scale` ``= max(|vx|, |vy|, R
            |omega|)`` before the impact; dimensionless, of the shape of the run.

        Notes
        -----
        Errors relative to each exact value would blow up where it is near zero,
        as when a ball leaves rolling with ``omega`` about 0; the incidence speed
        scale is never zero (``vy < 0``).
        """
        exact, radius, scale = self.exact.after, self.exact.body.radius, self.scale
        return {
            "vx": np.abs(self.vx - exact.vx) / scale,
            "vy": np.abs(self.vy - exact.vy) / scale,
            "omega": np.abs(radius * (self.omega - exact.omega)) / scale,
        }

    @property
    def error(self) -> np.ndarray:
        """The largest of the three :meth:`errors` of each impact (dimensionless)."""
        return np.maximum.reduce(list(self.errors().values()))

    @property
    def seconds_per_impact(self) -> float:
        """Wall time of the engine's stepping per impact of the batch, s."""
        return self.seconds / max(self.batch_size, 1)

    def summary(self) -> dict[str, dict[str, float]]:
        """Median, 95th percentile and maximum of each error and of the worst of three.

        Returns
        -------
        dict
            ``{"vx" | "vy" | "omega" | "worst": {"median", "p95", "max"}}``, floats.
        """
        out = {}
        for name, err in {**self.errors(), "worst": self.error}.items():
            out[name] = {
                "median": float(np.median(err)),
                "p95": float(np.percentile(err, 95)),
                "max": float(np.max(err)),
            }
        return out

    def to_dict(self) -> dict[str, Any]:
        """Fields as plain Python values (floats, str, lists, nested dicts), for JSON.

        The settings' arrays (MuJoCo's ``damping``) become lists.
        """
        out = super().to_dict()
        out["settings"] = {
            k: np.asarray(v).tolist() if isinstance(v, np.ndarray | np.generic) else v
            for k, v in self.settings.items()
        }
        return out


# -- the standard cases -------------------------------------------------------------------
def standard_cases(phases: int = 8) -> dict[str, np.ndarray]:
    """The grid of impacts on which the engines are compared (documented figures).

    Parameters
    ----------
    phases : int
        Number of contact phases per impact, ``>= 1``.

    Returns
    -------
    dict
        Flat arrays ``vx, vy`` (m/s), ``omega`` (rad/s), ``mu``, ``kappa`` and
        ``phase`` (keyword arguments of :func:`~spinimpact.engines.bounce`),
        ``144 * phases`` long.

    Raises
    ------
    TypeError
        If ``phases`` is not an integer.
    ValueError
        If ``phases < 1``.

    Notes
    -----
    For a solid sphere of radius 0.1 m: ``vx`` in {-2, 0, 1, 3} m/s, ``vy`` in
    {-1, -3} m/s, rim speed ``R omega`` in {-3, 0, 2} m/s, ``mu`` in
    {0.1, 0.3, 0.6}, ``kappa`` in {0.5, 0.8}: 144 impacts spanning sticking and
    sliding, backspin and topspin, each at the contact phases
    ``(j + 1/2)/phases``, spread evenly over a time step.
    """
    phases = whole_number("phases", phases, low=1)
    radius = 0.1
    grid = np.meshgrid(
        [-2.0, 0.0, 1.0, 3.0],
        [-1.0, -3.0],
        [-3.0, 0.0, 2.0],
        [0.1, 0.3, 0.6],
        [0.5, 0.8],
        (np.arange(phases) + 0.5) / phases,
        indexing="ij",
    )
    vx, vy, rim, mu, kappa, phase = (g.ravel() for g in grid)
    return {"vx": vx, "vy": vy, "omega": rim / radius, "mu": mu, "kappa": kappa, "phase": phase}
