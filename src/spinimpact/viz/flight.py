"""Tables, figures and animations of :func:`spinimpact.flight` results.

:func:`flight_tables` builds the bounce table and the summary as plain
:class:`~spinimpact.viz.tables.Table` data (the terminal prints them with Rich);
:func:`plot_flight` draws the side view ``(x, y)`` and the top view ``(x, z)`` of the
recorded paths with every bounce marked; :func:`animate_flight` moves the ball along its path
(GIF through Matplotlib's Pillow writer; MP4 where an ffmpeg writer is installed). Nothing
here computes physics: every number is a field of the :class:`~spinimpact.Flight`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, BinaryIO

import numpy as np

from ..model.flight_result import Flight
from .tables import Table, number

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["flight_tables", "plot_flight", "animate_flight", "ANIMATIONS"]

#: Suffixes :func:`animate_flight` writes, with the Matplotlib writer each needs.
ANIMATIONS = {".gif": "pillow", ".mp4": "ffmpeg"}
_MAX_PATHS = 200  # paths drawn for many balls (the bounce marks are drawn for all)


def _one(flight: Flight) -> None:
    if not isinstance(flight, Flight):
        raise TypeError(f"expected a spinimpact.Flight, got {type(flight).__name__}")


def flight_tables(flight: Flight) -> tuple[Table, Table]:
    """The bounce table (s, m, m/s, degrees, rpm, in / out; skids or grips) and the summary,
    of one ball."""
    _one(flight)
    rows = []
    for r in flight.bounce_rows():
        rows.append((
            f"{r['bounce']}{'w' if r['surface'] == 'wall' else ''}", f"{r['time_s']:.3f}",
            f"{r['x_m']:.2f}", f"{r['z_m']:.2f}",
            f"{r['speed_before_m_s']:.1f} / {r['speed_after_m_s']:.1f}",
            f"{r['angle_before_deg']:.1f} / {r['angle_after_deg']:.1f}",
            f"{r['spin_before_rpm']:.0f} / {r['spin_after_rpm']:.0f}",
            "grips" if r["grips"] else "skids",
        ))  # fmt: skip
    bounces = Table(
        "bounces", f"Bounces: {flight.ball.name} ball on {flight.ground.name} (in / out)",
        ("#", "t (s)", "x (m)", "z (m)", "speed (m/s)", "angle (deg)", "spin (rpm)", "contact"),
        tuple(rows),
        note="x, z: the centre at impact; angles towards / away from the surface; w: the wall",
    )  # fmt: skip
    fp = flight.final_position
    summary = Table("summary", "Flight", ("quantity", "value"), (
        ("apex height (m)", number(float(flight.apex_height))),
        ("apex time (s)", number(float(flight.apex_time))),
        ("first bounce at (s)", number(float(flight.flight_time))),
        ("bounces", str(int(flight.bounce_count))),
        ("stopped", str(flight.stop)),
        ("final time (s)", number(float(flight.final_time))),
        ("final position x, z (m)", f"{number(float(fp.x))}, {number(float(fp.z))}"),
        ("tangential law", "rigid" if flight.tangential is None else repr(flight.tangential)),
    ))  # fmt: skip
    return bounces, summary


def _paths(flight: Flight) -> tuple[np.ndarray, np.ndarray]:
    """Recorded times and positions as ``(balls, k)`` and ``(balls, k, 3)``."""
    t = np.asarray(flight.path_time, float)
    p = np.asarray(flight.path_position, float)
    n = int(np.prod(flight.shape))  # 1 for one ball
    return t.reshape(n, t.shape[-1]), p.reshape(n, t.shape[-1], 3)


def plot_flight(flight: Flight, *, roll: bool = False) -> Figure:
    """Side view (height ``y`` against ``x``) and top view (``z`` against ``x``) of the
    recorded paths, the bounces marked; for many balls, the first 200 paths and every
    bounce.

    The view frames the flight and the bounces: a ball that ends rolling (often far
    beyond its last bounce) is shown up to a little after its last airborne point, and
    where the roll-out goes on beyond the view, the side view's title says where it ends.
    ``roll=True`` shows the whole path instead.
    """
    _one(flight)
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8.0, 6.0), layout="constrained")
    side, top = fig.subplots(2, 1, sharex=True, height_ratios=(1.2, 1.0))
    _, pts = _paths(flight)
    b = flight.bounces
    bx, by, bz = (np.asarray(c, float).ravel() for c in (b.position.x, b.position.y, b.position.z))
    many = pts.shape[0] > 1
    for i in range(min(len(pts), _MAX_PATHS)):
        kw = {"lw": 0.6, "alpha": 0.35} if many else {"lw": 1.4}
        side.plot(pts[i, :, 0], pts[i, :, 1], color="tab:blue", **kw)
        top.plot(pts[i, :, 0], pts[i, :, 2], color="tab:blue", **kw)
    hits = ~np.isnan(bx)
    marks = {"s": 8 if many else 30, "color": "tab:red", "zorder": 3, "label": "bounces"}
    side.scatter(bx[hits], by[hits], **marks)
    top.scatter(bx[hits], bz[hits], **marks)
    fx, fz = (
        np.asarray(flight.final_position.x).ravel(),
        np.asarray(flight.final_position.z).ravel(),
    )
    clipped = False if roll else _frame(flight, side, top, pts, bz)
    rest = np.asarray(flight.stop).ravel() == "rest"
    if rest.any() and not clipped:  # else the side view's title says where it rests
        top.scatter(fx[rest], fz[rest], marker="x", s=30, color="k", zorder=3, label="at rest")
    side.axhline(0.0, color="0.4", lw=0.8)
    if flight.wall is not None:  # the wall seen from above: the line h . p = distance
        _wall_line(top, flight.wall, np.concatenate([pts[..., 2].ravel(), bz, [0.0]]))
    side.set_ylabel("height of the centre $y$ (m)")
    top.set_ylabel("$z$ (m)")
    top.set_xlabel("distance $x$ (m)")
    top.invert_yaxis()  # seen from above with y towards the viewer: +z points down the page
    side.set_title("side view", loc="left", fontsize=10)
    top.set_title("top view (from above)", loc="left", fontsize=10)
    top.legend(loc="upper center", bbox_to_anchor=(0.5, -0.3), ncol=2, frameon=False)
    n = int(np.prod(flight.shape)) if flight.shape else 1
    what = f"{n} {flight.ball.name} balls" if many else f"{flight.ball.name} ball"
    fig.suptitle(f"{what} on {flight.ground.name}")
    return fig


def _frame(flight: Flight, side, top, pts: np.ndarray, bz: np.ndarray) -> bool:
    """Limit both views to the flight and the bounces (every point where a ball is off
    the ground, and every bounce, with a margin of 5 %) where the rolling goes beyond
    them, and say in the side view's title where the roll-out ends. Whether it did."""
    x, y, z = pts[..., 0], pts[..., 1], pts[..., 2]
    radius = np.asarray(flight.ball.radius, float).reshape(-1, 1)
    airborne = y > radius * (1 + 1e-9)  # a rolling ball's centre is at its radius
    bx = np.asarray(flight.bounces.position.x, float).ravel()
    xs = np.concatenate([x[airborne], x[:, :1].ravel(), bx])
    xs = xs[np.isfinite(xs)]
    if not xs.size:
        return False
    margin = 0.05 * max(float(np.ptp(xs)), 1e-3)
    low, high = float(xs.min()) - margin, float(xs.max()) + margin
    drawn = np.isfinite(x)
    beyond = drawn & ((x < low) | (x > high))
    if not beyond.any():
        return False
    side.set_xlim(low, high)
    inside = drawn & ~beyond
    zs = np.concatenate([z[inside], bz[np.isfinite(bz)]])
    pad = max(0.05 * float(np.ptp(zs)), 0.05)
    top.set_ylim(float(zs.min()) - pad, float(zs.max()) + pad)  # inverted by the caller
    fx = np.asarray(flight.final_position.x, float).ravel()
    ft = np.asarray(flight.final_time, float).ravel()
    arrow = "\u2192" if np.any(x > high) else "\u2190"
    if fx.size == 1:
        how = "to rest" if str(np.asarray(flight.stop).ravel()[0]) == "rest" else "on"
        fz = float(np.asarray(flight.final_position.z, float))
        where = f"$x$ = {fx[0]:.4g} m" + (f", $z$ = {fz:.3g} m" if abs(fz) >= 0.01 else "")
        note = f"then rolls {how} at {where} ($t$ = {ft[0]:.3g} s) {arrow}"
    else:
        far = fx[np.argmax(np.abs(fx - xs.mean()))]
        note = f"then roll on, the furthest to $x$ = {far:.4g} m {arrow}"
    side.set_title(note, loc="right", fontsize=9, color="0.3")
    return True


def _wall_line(ax, wall, zs: np.ndarray) -> None:
    """Draw the wall in the top view ``(x, z)`` across the range of ``zs``."""
    d = math.radians(wall.direction)
    heading = np.array([math.cos(d), -math.sin(d)])  # (x, z) of h
    along = np.array([-heading[1], heading[0]])
    zs = zs[np.isfinite(zs)]
    half = max(1.0, float(np.max(np.abs(zs))) * 1.2) if zs.size else 1.0
    centre = wall.distance * heading
    ends = np.array([centre - half * along, centre + half * along])
    ax.plot(ends[:, 0], ends[:, 1], color="0.3", lw=2.5, label="wall")


def animate_flight(flight: Flight, target: str | Path | BinaryIO, *, format: str | None = None,
                   fps: int = 20, dpi: int = 80,
                   progress: Callable[[int, int], None] | None = None) -> None:  # fmt: skip
    """Write the ball moving along its path (side and top views), in real time, to
    ``target``: a GIF (Pillow) or an MP4 (Matplotlib's ffmpeg writer, where ffmpeg is
    installed). ``format`` (``gif`` or ``mp4``) defaults to the suffix of ``target``, so a
    temporary file may be written under any name; a GIF may also be written to a binary
    file object (``io.BytesIO``). ``progress(done, frames)`` is called after each frame.
    A stop asked for on the command line (SIGINT, SIGTERM: :mod:`spinimpact.io._stop`)
    ends the rendering between two frames.

    Raises
    ------
    ValueError
        For another format, a flight of more than one ball, or one without a recorded path.
    ImportError
        For an MP4 where the ffmpeg writer is not installed.
    """
    _one(flight)
    if format is None and not isinstance(target, str | Path):
        raise ValueError("give the format (gif) of an animation written to a file object")
    kind = (format or Path(target).suffix.lstrip(".")).lower()
    if f".{kind}" not in ANIMATIONS:
        raise ValueError(f"the animation must be a .gif or .mp4, got {str(target)!r}")
    if flight.shape != ():
        raise ValueError("animate_flight() moves one ball: select one with flight[i]")
    times, pts = _paths(flight)
    ok = ~np.isnan(times[0])
    times, pts = times[0, ok], pts[0, ok]
    if len(times) < 2:
        raise ValueError("this Flight has no recorded path (run flight(..., path=True))")
    from matplotlib import animation
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from ..io._stop import check as stop_check

    if kind == "mp4" and not animation.writers.is_available("ffmpeg"):
        raise ImportError("writing .mp4 needs ffmpeg, which is not installed: write a .gif")
    frames = max(2, min(600, int(math.ceil(float(times[-1] - times[0]) * fps))))
    clock = np.linspace(times[0], times[-1], frames)
    xs, ys, zs = (np.interp(clock, times, pts[:, i]) for i in range(3))
    fig = plot_flight(flight, roll=True)  # the ball stays in view to its end
    canvas = FigureCanvasAgg(fig)
    side, top = fig.axes[:2]
    (ball_side,) = side.plot([xs[0]], [ys[0]], "o", color="tab:orange", ms=7, zorder=4)
    (ball_top,) = top.plot([xs[0]], [zs[0]], "o", color="tab:orange", ms=7, zorder=4)
    label = side.text(0.99, 0.95, "", transform=side.transAxes, ha="right", va="top")

    def draw(i: int) -> tuple:
        stop_check()  # a stop asked for (SIGINT, SIGTERM) ends the rendering between frames
        ball_side.set_data([xs[i]], [ys[i]])
        ball_top.set_data([xs[i]], [zs[i]])
        label.set_text(f"t = {clock[i]:.2f} s")
        if progress is not None:
            progress(i + 1, frames)
        return ball_side, ball_top, label

    if kind == "mp4":
        movie = animation.FuncAnimation(fig, draw, frames=frames, blit=False)
        writer = animation.FFMpegWriter(fps=fps, extra_args=["-f", "mp4"])
        movie.save(str(target), writer=writer, dpi=dpi)
        return
    from PIL import Image

    fig.set_dpi(dpi)
    canvas.draw()
    fig.set_layout_engine("none")  # the layout is fixed: each frame only moves the ball
    images = []
    for i in range(frames):
        draw(i)
        canvas.draw()
        images.append(Image.fromarray(np.asarray(canvas.buffer_rgba())[..., :3]))
    images[0].save(target, format="GIF", save_all=True, append_images=images[1:],
                   duration=round(1000 / fps), loop=0)  # fmt: skip
