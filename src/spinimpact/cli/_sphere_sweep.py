"""``spinimpact sweep --sphere``: the options and the sweep of one sphere in 3D.

``--sphere solid-sphere|spherical-shell`` (``--mass``, ``--radius``; ``--gyration`` gives
any sphere, a thick shell) on the surface of ``--normal`` and ``--surface-velocity``, over
the axes ``--vx, --vy, --vz`` (m/s), ``--wx, --wy, --wz`` (rad/s), ``--mu, --kappa``: the
:class:`~spinimpact.io.problem_sweep.ProblemSweep` of problem ``sphere`` with the body and
the surface held fixed. The fields are the :class:`~spinimpact.SphereImpact` columns and
the regimes the paper sweep's.
"""

from __future__ import annotations

from typing import Any

import click

from ._common import _options
from ._vocabulary import help as _help
from .sphere import SPHERES, VECTOR

__all__ = ["SPHERE_ONLY", "sphere_options", "sphere_sweep"]

#: Options that only a --sphere sweep takes.
SPHERE_ONLY = ("vz", "wx", "wy", "wz", "normal", "surface_velocity")
#: Options a --sphere sweep refuses: the paper's and the planar bodies'.
_NOT_SPHERE = ("body", "planar", "omega", "law", "inertia", "rx", "ry", "length", "width",
               "height", "offset", "angle", "angle_deg")  # fmt: skip
_FIELDS = "after_vx,after_vy,after_vz,after_wx,after_wy,after_wz,regime"


def _given(ctx: click.Context, name: str) -> bool:
    source = ctx.get_parameter_source(name)
    return source not in (None, click.core.ParameterSource.DEFAULT)


def _axis(name: str) -> Any:
    return click.option(
        f"--{name}", default=None, help=_help(name, "--sphere: as --vx (default 0).")
    )


sphere_options = _options(
    click.option(
        "--sphere",
        type=click.Choice(list(SPHERES)),
        default=None,
        help=_help("sphere", "Axes --vx --vy --vz --wx --wy --wz --mu --kappa; --mass, "
        "--radius; --gyration for any other sphere (a thick shell)."),
    ),
    _axis("vz"),
    *(_axis(n) for n in ("wx", "wy", "wz")),
    click.option("--normal", type=VECTOR, default=None,
                 help=_help("normal", "--sphere (default 0,1,0).")),
    click.option("--surface-velocity", type=VECTOR, default=None,
                 help=_help("surface-velocity", "--sphere (default at rest).")),
)  # fmt: skip


def sphere_sweep(
    ctx: click.Context, o: dict[str, Any], samples: int | None, seed: int, chunk_size: int
) -> tuple[Any, str | None]:
    """The :class:`~spinimpact.io.problem_sweep.ProblemSweep` of the options (problem
    ``sphere``: the body and the surface held fixed), and the fields to write when
    ``--fields`` was not typed (else ``None``).

    Raises
    ------
    click.UsageError
        For an option of the paper's or the planar bodies.
    """
    from ..io.problem_sweep import ProblemSweep
    from ..io.sweep import parse_axis
    from ..model.body import Body

    for name in _NOT_SPHERE:
        if _given(ctx, name):
            flag = "--" + name.replace("_", "-")
            raise click.UsageError(f"{flag} does not apply to --sphere (a sphere in 3D)")
    if o["gyration"] is not None:
        body = Body(mass=o["mass"], radius=o["radius"], gyration=o["gyration"], name="custom")
    else:
        body = Body.preset(o["sphere"], mass=o["mass"], radius=o["radius"])
    names = ("vx", "vy", "vz", "wx", "wy", "wz", "mu", "kappa")
    typed = [o[n] for n in names if o[n] is not None]
    random = samples is not None or any(t.strip().startswith("uniform:") for t in typed)
    defaults = {"vx": "uniform:-5:5" if random else "-5:5:201"}
    texts = {n: o[n] if o[n] is not None else defaults.get(n, "0") for n in names}
    normal = (0.0, 1.0, 0.0) if o["normal"] is None else o["normal"]
    velocity = (0.0, 0.0, 0.0) if o["surface_velocity"] is None else o["surface_velocity"]
    fixed = {f"normal_{k}": float(x) for k, x in zip("xyz", normal, strict=True)}
    fixed |= {f"surface_velocity_{k}": float(x) for k, x in zip("xyz", velocity, strict=True)}
    size = {"chunk_size": chunk_size} if _given(ctx, "chunk_size") else {}
    sweep = ProblemSweep(problem="sphere", body=body, fixed=fixed, samples=samples, seed=seed,
                         axes={name: parse_axis(name, text) for name, text in texts.items()},
                         **size)  # fmt: skip
    return sweep, None if _given(ctx, "fields") else _FIELDS
