"""The results of :func:`spinimpact.flight`: :class:`Flight` and its :class:`Bounces`.

Units SI (angles in rad, spins in rad/s); the tables print degrees and rpm. Positions are
those of the ball's centre (``y = R`` on the ground).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._words import count
from .presets import Ball, Ground
from .result import Array, Result
from .sphere3d import State3, Vector

__all__ = ["Bounces", "Flight"]

_RPM = 60.0 / (2.0 * np.pi)


@dataclass(frozen=True, eq=False)
class Bounces(Result):
    """Every bounce of every ball: arrays of shape ``(..., B)`` (``B``: the most bounces of
    any ball; NaN, ``""`` and ``False`` past a ball's last bounce).

    Attributes
    ----------
    time : s
    position : Vector
        Centre at the impact (``y = R``), m.
    before, after : State3
        Velocity (m/s) and spin (rad/s) just before and just after.
    speed_before, speed_after : m/s
    angle_before, angle_after : rad
        Towards the surface before, away from it after (below and above the ground).
    regime : str
        The impact's regime (:func:`~spinimpact.solve`'s names).
    grips : bool
        The ball leaves without slip (the slip stopped during the impact); otherwise it skids.
    surface : str
        What it hit: ``ground`` or ``wall``.
    next_apex_height : m
        Top of the centre's arc after the bounce (NaN when there is none).
    """

    time: Array
    position: Vector
    before: State3
    after: State3
    speed_before: Array
    speed_after: Array
    angle_before: Array
    angle_after: Array
    regime: Array
    grips: Array
    surface: Array
    next_apex_height: Array

    _shape_field = "time"


@dataclass(frozen=True, eq=False)
class Flight(Result):
    """Everything :func:`~spinimpact.flight` computes, for one ball (shape ``()``) or many.

    Attributes
    ----------
    ball, ground : Ball, Ground
    tangential : Walton, Stronge or None
        The tangential compliance law of the bounces (``None``: the rigid law).
    wall : Wall or None
        The wall the ball may bounce off.
    launch_position : Vector
        m.
    launch : State3
        Launch velocity (m/s) and spin (rad/s).
    bounce_count : int
        Bounces of each ball.
    bounces : Bounces
        Per bounce, arrays ``(..., B)``.
    apex_height, apex_time : m, s
        Top of the first arc (the launch point if launched downwards).
    flight_time : s
        Time of the first bounce (NaN if none).
    final_time : s
        Time the ball came to rest, or the stopping time.
    final_position, final_velocity, final_spin : Vector
        State then (m, m/s, rad/s).
    stop : str
        ``rest``, ``time`` (stopping time reached) or ``bounces`` (``max_bounces`` reached).
    path_time, path_position : ndarray
        The recorded path of the centre, ``(..., k)`` and ``(..., k, 3)`` (NaN-padded; empty
        unless recorded).
    """

    ball: Ball
    ground: Ground
    tangential: Any
    wall: Any
    launch_position: Vector
    launch: State3
    bounce_count: Array
    bounces: Bounces
    apex_height: Array
    apex_time: Array
    flight_time: Array
    final_time: Array
    final_position: Vector
    final_velocity: Vector
    final_spin: Vector
    stop: Array
    path_time: np.ndarray
    path_position: np.ndarray

    _shape_field = "final_time"

    def columns(self) -> dict[str, np.ndarray]:
        """Flat per-ball columns: those of :meth:`column_names`, then ``bounce1_time``,
        ``bounce1_before_vx``, ... for each bounce ``k`` of :attr:`bounces`."""
        shape = self.shape
        out: dict[str, np.ndarray] = {}
        for name in ("launch_position", "launch", "final_position", "final_velocity",
                     "final_spin"):  # fmt: skip
            out.update({f"{name}_{k}": c for k, c in getattr(self, name).columns().items()})
        for name in ("bounce_count", "apex_height", "apex_time", "flight_time", "final_time",
                     "stop"):  # fmt: skip
            out[name] = np.broadcast_to(np.asarray(getattr(self, name)), shape)
        per = self.bounces.columns()
        for k in range(np.shape(self.bounces.time)[-1]):
            out.update({f"bounce{k + 1}_{name}": c[..., k] for name, c in per.items()})
        return out

    @classmethod
    def column_names(cls) -> tuple[str, ...]:
        """The per-ball column names (the bounce columns follow them in :meth:`columns`)."""
        names = []
        for name, kind in (("launch_position", Vector), ("launch", State3),
                           ("final_position", Vector), ("final_velocity", Vector),
                           ("final_spin", Vector)):  # fmt: skip
            names += [f"{name}_{k}" for k in kind.column_names()]
        return (*names, "bounce_count", "apex_height", "apex_time", "flight_time",
                "final_time", "stop")  # fmt: skip

    def bounce_rows(self) -> list[dict[str, Any]]:
        """One ball's bounces as rows of plain numbers in the units a person reads: s, m,
        m/s, degrees, rpm (spin magnitude), and the regime and grip."""
        if self.shape != ():
            raise ValueError(f"bounce_rows() describes one ball; this Flight has shape "
                             f"{self.shape}: select one with flight[i]")  # fmt: skip
        b = self.bounces
        rows = []
        for k in range(int(self.bounce_count)):
            wb, wa = b.before.spin[k], b.after.spin[k]
            rows.append({
                "bounce": k + 1, "time_s": float(b.time[k]), "x_m": float(b.position.x[k]),
                "z_m": float(b.position.z[k]),
                "speed_before_m_s": float(b.speed_before[k]),
                "speed_after_m_s": float(b.speed_after[k]),
                "angle_before_deg": float(np.degrees(b.angle_before[k])),
                "angle_after_deg": float(np.degrees(b.angle_after[k])),
                "spin_before_rpm": float(np.linalg.norm(wb) * _RPM),
                "spin_after_rpm": float(np.linalg.norm(wa) * _RPM),
                "regime": str(b.regime[k]), "grips": bool(b.grips[k]),
                "surface": str(b.surface[k]),
                "next_apex_m": float(b.next_apex_height[k]),
            })  # fmt: skip
        return rows

    def table(self) -> str:
        """The bounce table and the summary as plain text (one ball)."""
        rows = self.bounce_rows()
        head = (f"{'#':>2} {'t s':>7} {'x m':>7} {'z m':>7} {'v in':>6} {'v out':>6} "
                f"{'in deg':>7} {'out deg':>7} {'rpm in':>7} {'rpm out':>7}  contact")  # fmt: skip
        law = "" if self.tangential is None else f" ({self.tangential!r})"
        lines = [f"{self.ball.name} ball on {self.ground.name}{law}", head]
        for r in rows:
            lines.append(
                f"{r['bounce']:>2} {r['time_s']:7.3f} {r['x_m']:7.2f} {r['z_m']:7.2f} "
                f"{r['speed_before_m_s']:6.1f} {r['speed_after_m_s']:6.1f} "
                f"{r['angle_before_deg']:7.1f} {r['angle_after_deg']:7.1f} "
                f"{r['spin_before_rpm']:7.0f} {r['spin_after_rpm']:7.0f}  "
                f"{'grips' if r['grips'] else 'skids'}"
                f"{' (wall)' if r['surface'] == 'wall' else ''}"
            )
        fp = self.final_position
        lines.append(
            f"apex {float(self.apex_height):.2f} m at {float(self.apex_time):.3f} s; "
            f"{count(int(self.bounce_count), 'bounce')}; stopped ({self.stop}) at "
            f"{float(self.final_time):.2f} s, "
            f"x {float(fp.x):.2f} m, z {float(fp.z):.2f} m"
        )
        return "\n".join(lines)

    def __repr__(self) -> str:
        if self.shape == ():
            return f"Flight(\n{self.table()}\n)"
        stops = {s: int(np.sum(self.stop == s)) for s in ("rest", "time", "bounces")}
        said = ", ".join(f"{k} {v}" for k, v in stops.items() if v)
        return (f"Flight of {self.shape} {self.ball.name} balls on {self.ground.name}: "
                f"bounces {int(np.min(self.bounce_count))}-{int(np.max(self.bounce_count))}; "
                f"stopped: {said}")  # fmt: skip
