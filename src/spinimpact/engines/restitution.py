r"""The restitution answer: which engine setting bounces a ball head-on with a given e.

Neither engine's restitution is simply a number to type in. PyBullet has one
(``changeDynamics(restitution=...)``, Newton's ratio), but at its default contact
parameters the ball bounces with less, or not at all, depending on the speed and on
where in a time step it arrives. MuJoCo has none: its contact is a soft constraint whose
``solref = (timeconst, dampratio)`` makes, per unit of the impedance, a damped spring; a
damped linear oscillator of damping ratio :math:`\xi` bounces with
:math:`e = \exp(-\pi\xi/\sqrt{1-\xi^2})`, but MuJoCo's impedance, which changes with the
depth (``solimp``), and a contact that lasts only a few time steps move the bounce away
from it, by an amount that changes with the speed.

:func:`restitution_settings` measures instead of guessing: it bounces a ball head-on at
the given speed and time step, at contact phases spread over a step, and solves for the
one setting (MuJoCo: the damping ratio of ``solref``; PyBullet: the ball's
``restitution``) that makes the mean rebound ratio ``e``, every other setting held at
the engine's default or at the value given. :func:`restitution_curve` measures the
restitution that settings produce across speeds.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import as_real_array, check, scalar
from ..model.body import Body
from ..model.result import Array, Result, freeze
from . import configure
from .common import CONFIGURABLE, check_engine, one_body, whole_number

__all__ = ["RestitutionCurve", "restitution_curve", "restitution_settings"]

#: How close the mean head-on rebound ratio is made to ``e``.
TOLERANCE = 1e-6
#: The grid on which the setting is first scanned for a bracket of ``e``.
_GRID = {"mujoco": np.geomspace(0.005, 1.5, 25), "pybullet": np.linspace(0.0, 1.0, 21)}


@dataclass(frozen=True, eq=False)
class RestitutionCurve(Result):
    """Head-on restitution of one engine set-up across impact speeds.

    Attributes
    ----------
    engine, version : str
        The engine and its version.
    settings : Mapping
        The engine settings measured (its defaults filled in).
    speed : ndarray
        Impact speeds, m/s.
    restitution : ndarray
        Mean of ``vy+ / |vy-|`` over the contact phases, at each speed.
    low, high : ndarray
        Its least and greatest value over the phases.
    phases : int
        Contact phases per speed, ``(j + 1/2) / phases``.
    """

    engine: str
    version: str
    settings: Mapping[str, Any]
    speed: Array
    restitution: Array
    low: Array
    high: Array
    phases: int

    _shape_field = "speed"

    def to_dict(self) -> dict[str, Any]:
        """Fields as plain values, for JSON (the settings' tuples as lists)."""
        out = super().to_dict()
        out["settings"] = {
            k: list(v) if isinstance(v, tuple) else v for k, v in self.settings.items()
        }
        return out


def _ratios(engine: str, body: Body, speed: np.ndarray, phases: int, settings) -> np.ndarray:
    """``vy+ / |vy-|`` of head-on bounces, shape ``(speeds, phases)``."""
    phase = (np.arange(phases) + 0.5) / phases
    vy = -np.repeat(speed, phases)
    zero = np.zeros_like(vy)
    out = configure.run(engine, body, zero, vy, zero, np.tile(phase, speed.size), settings)
    return (out.vy / -vy).reshape(speed.size, phases)


def _check_body(body: Any) -> Body:
    return one_body(body, "an engine run takes one body size")


def restitution_curve(
    engine: str, settings: Mapping[str, Any], body: Body, speed: Any, *, phases: int = 8
) -> RestitutionCurve:
    """The head-on restitution that engine settings produce at each impact speed.

    Parameters
    ----------
    engine : {"pybullet", "mujoco"}
        The engine.
    settings : Mapping
        The engine's settings (keys of
        :data:`~spinimpact.engines.configure.MUJOCO_SETTINGS` or
        :data:`~spinimpact.engines.configure.PYBULLET_SETTINGS`, the time step
        ``timestep`` among them); the missing ones take the engine's defaults.
    body : Body
        The ball (a sphere of its radius and inertia).
    speed : float or array_like
        Impact speeds, m/s, ``> 0``.
    phases : int
        Contact phases per speed.

    Returns
    -------
    RestitutionCurve
        The mean, least and greatest ``vy+ / |vy-|`` over the phases at each speed.

    Raises
    ------
    TypeError, ValueError
        For an unknown engine or setting, a value of the wrong type or out of range.
    RuntimeError
        If a MuJoCo ball has not left the surface after 40 of the contact's time
        constants.
    """
    check_engine(engine, CONFIGURABLE)
    body = _check_body(body)
    speeds = as_real_array("speed", speed)
    if speeds.size == 0:
        raise ValueError("speed must hold at least one speed, got none")
    check("speed", speeds, lambda v: np.isfinite(v) & (v > 0), "> 0 (m/s)")
    phases = whole_number("phases", phases)
    if not isinstance(settings, Mapping):
        raise TypeError(f"settings must be a mapping of setting names to values, got "
                        f"{type(settings).__name__}")  # fmt: skip
    used = configure.checked(engine, settings)
    ratios = _ratios(engine, body, np.ravel(speeds), phases, used)
    shape = speeds.shape
    return RestitutionCurve(
        engine=engine, version=configure.version(engine), settings=used,
        speed=freeze(speeds), restitution=freeze(ratios.mean(axis=1).reshape(shape)),
        low=freeze(ratios.min(axis=1).reshape(shape)),
        high=freeze(ratios.max(axis=1).reshape(shape)), phases=phases,
    )  # fmt: skip


def _with(engine: str, settings: dict[str, Any], value: float) -> dict[str, Any]:
    """``settings`` with the solved-for setting at ``value``."""
    out = dict(settings)
    if engine == "mujoco":
        out["solref"] = (settings["solref"][0], float(value))
    else:
        out["restitution"] = float(value)
    return out


def restitution_settings(
    engine: str, e: float, speed: float, dt: float, body: Body, *, phases: int = 8, **fixed: Any
) -> dict[str, Any]:
    """Engine settings that bounce ``body`` head-on at ``speed`` with restitution ``e``.

    Parameters
    ----------
    engine : {"pybullet", "mujoco"}
        The engine.
    e : float
        The restitution wanted, in ``[0, 1]``.
    speed : float
        The impact speed at which it is wanted, m/s, ``> 0``.
    dt : float
        The time step, s.
    body : Body
        The ball.
    phases : int
        Contact phases over which the rebound ratio is averaged.
    **fixed
        Other settings, held (keys of
        :data:`~spinimpact.engines.configure.MUJOCO_SETTINGS` or
        :data:`~spinimpact.engines.configure.PYBULLET_SETTINGS`; MuJoCo's ``solref``
        gives the time constant, its damping ratio being solved for). The rest take the
        engine's defaults.

    Returns
    -------
    dict
        Every setting, ``timestep = dt``: MuJoCo's ``solref = (timeconst, dampratio)``
        or PyBullet's ``restitution`` solved so that the mean head-on ``vy+ / |vy-|``
        over the phases is ``e`` to :data:`TOLERANCE`.

    Raises
    ------
    TypeError
        For a value of the wrong type.
    ValueError
        For an unknown engine or setting, a value out of range, or an ``e`` the engine
        cannot reach at this speed and time step (the message gives the range it can).

    Examples
    --------
    >>> from spinimpact import Body
    >>> from spinimpact.engines import restitution_settings
    >>> ball = Body.solid_sphere(mass=0.06, radius=0.033)
    >>> s = restitution_settings("pybullet", 0.75, 2.0, 1 / 240, ball)
    >>> round(s["restitution"], 3)  # at PyBullet's default contact parameters
    0.727
    """
    from scipy.optimize import brentq

    check_engine(engine, CONFIGURABLE)
    body = _check_body(body)
    e = scalar("e", e, "kappa")  # the rule of a restitution coefficient: in [0, 1]
    v = scalar("speed", speed, "vx")  # finite; its sign checked below, with its unit
    if not v > 0:
        raise ValueError(f"speed must be > 0 (m/s), got {speed!r}")
    if "timestep" in fixed:
        raise ValueError("the time step is dt; give it there, not as timestep=")
    dt = configure._number("dt", dt, zero=False)
    phases = whole_number("phases", phases)
    base = configure.checked(engine, {**fixed, "timestep": dt})
    grid = _GRID[engine]
    speeds = np.array([v])

    def ratio(value: float) -> float:
        try:
            return float(_ratios(engine, body, speeds, phases, _with(engine, base, value)).mean())
        except RuntimeError:
            return float("nan")

    values = np.array([ratio(g) for g in grid])
    ok = np.isfinite(values)
    stable = ok & (values <= 1.0)  # a mean above 1: unstable at this step
    if not stable.any():
        raise ValueError(
            f"no {engine} setting bounced stably at speed {v!r} m/s and time step {dt!r} s"
        )
    if np.any(values[ok] == e):
        return _with(engine, base, float(grid[ok][np.flatnonzero(values[ok] == e)[0]]))
    above = (values - e) > 0
    cross = np.flatnonzero(ok[:-1] & ok[1:] & (above[:-1] != above[1:]))
    if cross.size == 0:
        raise ValueError(
            f"e = {e!r} cannot be reached by {engine} at speed {v!r} m/s and time step {dt!r} s "
            f"by its {'solref damping ratio' if engine == 'mujoco' else 'restitution'} "
            f"(it reaches {np.min(values[stable]):.3g} to {np.max(values[stable]):.3g})"
        )
    # MuJoCo: the crossing at the most damping, furthest from an unstable contact
    j = cross[-1] if engine == "mujoco" else cross[0]
    found = brentq(lambda g: ratio(g) - e, grid[j], grid[j + 1], xtol=1e-12, rtol=1e-12)
    return _with(engine, base, found)
