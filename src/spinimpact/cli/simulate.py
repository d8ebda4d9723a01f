"""``spinimpact simulate``: one impact integrated in time with a compliant contact law."""

from __future__ import annotations

from typing import Any

import click

from ._common import DEFAULTS, body_options, image_format, incidence_options, make_body
from ._vocabulary import deprecated
from ._vocabulary import help as _help

__all__ = ["simulate_command"]

#: The options of each contact law (Python names); any other law option is an error.
_LAW_OPTIONS = {
    "hertz": {"youngs_modulus", "poisson_ratio", "alpha"},
    "linear": {"stiffness", "damping"},
    "hunt-crossley": {"stiffness", "exponent", "alpha"},
}
#: Default stiffness of the laws that take one: N/m (linear), N/m^n (hunt-crossley).
_DEFAULT_STIFFNESS = {"linear": 1e6, "hunt-crossley": 1e8}


def _g(x: float) -> str:
    """``2e9`` rather than ``2e+09`` in the help."""
    return f"{x:g}".replace("e+0", "e").replace("e+", "e")


#: Default material of the Hertz law: E in Pa, nu.
_HERTZ = {"youngs_modulus": 2e9, "poisson_ratio": 0.35}


def _target(o: dict[str, Any]) -> tuple[float | None, str]:
    """The restitution to calibrate the law to, and the option that set it (in words).

    ``--kappa`` (or its older name ``--target-kappa``) when given; else the
    documented default ``kappa`` (as ``spinimpact solve``) unless the damping was
    given (``--damping``, ``--alpha``): then ``None``, the law as typed.
    """
    kappa, target = o["kappa"], o["target_kappa"]
    if kappa is not None and target is not None:
        raise click.UsageError("give either --kappa or --target-kappa (its older name), not both")
    value, flag = (kappa, "--kappa") if target is None else (target, "--target-kappa")
    for name in ("damping", "alpha"):
        if value is not None and o[name] is not None:
            raise click.UsageError(f"give either --{name} or {flag}, not both")
    if value is None:
        damped = o["damping"] is not None or o["alpha"] is not None
        return (None, "") if damped else (DEFAULTS["kappa"], "the default of --kappa, as solve's")
    if not 0.0 < value <= 1.0:  # also NaN
        raise click.UsageError(f"{flag} must be in (0, 1], got {value!r}")
    return value, flag


def _contact_law(o: dict[str, Any], radius: float) -> Any:
    """The contact law described by the options (``o`` is updated with the defaults).

    Parameters
    ----------
    o : dict
        The command's options: ``contact``, the law's settings (``youngs_modulus``
        in Pa, ``poisson_ratio``, ``stiffness`` in N/m or N/m^n, ``damping`` in
        N s/m, ``exponent``, ``alpha`` in s/m), ``kappa`` or ``target_kappa``,
        ``mass`` in kg and ``vy`` in m/s.
    radius : float
        Contact radius R of the body, m (Hertz's stiffness depends on it).

    Returns
    -------
    ContactLaw
        Of the kind ``--contact`` names. With a restitution to reach (:func:`_target`),
        its damping is calibrated to give it at the impact speed ``|vy|``: a Hertz
        law stays a :class:`HertzContact` (with Hunt-Crossley damping ``alpha``).

    Raises
    ------
    click.UsageError
        For an option that does not apply to the law, damping given together
        with a restitution, or a restitution outside ``(0, 1]``.
    """
    from ..model.contact import HertzContact, HuntCrossleyContact, LinearContact

    allowed = _LAW_OPTIONS[o["contact"]]
    for name in ("youngs_modulus", "poisson_ratio", "stiffness", "damping", "exponent", "alpha"):
        if o[name] is not None and name not in allowed:
            flag = "--" + name.replace("_", "-")
            raise click.UsageError(f"{flag} does not apply to --contact {o['contact']}")
    target, _ = _target(o)
    speed, mass = abs(o["vy"]), o["mass"]
    e = _HERTZ["youngs_modulus"] if o["youngs_modulus"] is None else o["youngs_modulus"]
    nu = _HERTZ["poisson_ratio"] if o["poisson_ratio"] is None else o["poisson_ratio"]
    n = 1.5 if o["exponent"] is None else o["exponent"]
    k = o["stiffness"] if o["stiffness"] is not None else _DEFAULT_STIFFNESS.get(o["contact"])
    if o["contact"] == "hertz":
        if target is None:
            return HertzContact(e, nu, radius, o["alpha"] or 0.0)
        return HertzContact.calibrated(youngs_modulus=e, poisson_ratio=nu, radius=radius,
                                       kappa=target, mass=mass, speed=speed)  # fmt: skip
    if o["contact"] == "linear":
        if target is None:
            return LinearContact(k, o["damping"] or 0.0)
        return LinearContact.calibrated(stiffness=k, kappa=target, mass=mass)
    if target is None:
        return HuntCrossleyContact(k, n, o["alpha"] or 0.0)
    return HuntCrossleyContact.calibrated(
        stiffness=k, kappa=target, mass=mass, speed=speed, exponent=n
    )


def _tangential_law(o: dict[str, Any]) -> Any:
    """The tangential law the options describe (``None`` for ``--tangential none``)."""
    from ..model.mindlin import Mindlin

    if o["tangential"] == "none":
        for name in ("stiffness_ratio", "spring"):
            if o[name] is not None:
                flag = "--" + name.replace("_", "-")
                raise click.UsageError(f"{flag} needs --tangential mindlin")
        return None
    spring = o["spring"] or "scaled"
    if o["stiffness_ratio"] is not None:
        return Mindlin(stiffness_ratio=o["stiffness_ratio"], spring=spring)
    if o["contact"] != "hertz":
        raise click.UsageError(
            f"--tangential mindlin with --contact {o['contact']} needs --stiffness-ratio "
            "(Poisson's ratio belongs to the hertz law)"
        )
    nu = _HERTZ["poisson_ratio"] if o["poisson_ratio"] is None else o["poisson_ratio"]
    return Mindlin(poisson_ratio=nu, spring=spring)


def _print_tangential(sim: Any) -> None:
    """The rebound with tangential compliance beside the rigid closed form."""
    from ..viz.tables import duration

    rigid = sim.rigid()
    spring = sim.tangential.spring
    click.echo(f"impact with {sim.contact!r} and a Mindlin spring ({spring} rule), "
               f"k_t/k_n = {sim.stiffness_ratio:.6g}")  # fmt: skip
    switches = f"{sim.switches} stick/slip switch{'' if sim.switches == 1 else 'es'}"
    click.echo(f"contact duration {duration(sim.contact_duration)}, peak normal force "
               f"{sim.peak_force:.6g} N, {switches}")  # fmt: skip
    click.echo(f"{'':24s}{'compliant':>14s}{'rigid':>14s}")
    rows = (("vx+ (m/s)", sim.after.vx, rigid.after.vx),
            ("vy+ (m/s)", sim.after.vy, rigid.after.vy),
            ("omega+ (rad/s)", sim.after.omega, rigid.after.omega),
            ("beta = -u+/u-", sim.tangential_restitution, _beta(sim, rigid)))  # fmt: skip
    for name, a, b in rows:
        click.echo(f"{name:24s}{float(a):14.6g}{float(b):14.6g}")


def _beta(sim: Any, rigid: Any) -> float:
    """The rigid law's ``beta = -u+/u-``: exactly 0 where its slip stops (a stick regime;
    the closed form leaves ``u+ = 0``, which the velocities give only to rounding)."""
    if str(rigid.regime).startswith("stick"):
        return 0.0
    b = sim.before
    u0 = float(b.vx + sim.body.radius * b.omega)
    u1 = float(rigid.after.vx + sim.body.radius * rigid.after.omega)
    return -u1 / u0 if u0 != 0 else float("nan")


@click.command("simulate")
@body_options
@incidence_options
@click.option("--mu", type=float, default=DEFAULTS["mu"], show_default=True, help=_help("mu"))
@click.option(
    "--contact",
    type=click.Choice(["hertz", "hunt-crossley", "linear"]),
    default="hertz",
    show_default=True,
    help=_help("contact"),
)
@click.option(
    "--youngs-modulus",
    type=float,
    default=None,
    help=_help("youngs-modulus", f"Hertz; default {_g(_HERTZ['youngs_modulus'])}."),
)
@click.option(
    "--poisson-ratio",
    type=float,
    default=None,
    help=_help("poisson-ratio", f"Hertz; default {_HERTZ['poisson_ratio']:g}."),
)
@click.option(
    "--stiffness",
    type=float,
    default=None,
    help=_help(
        "stiffness",
        f"N/m for linear (default {_g(_DEFAULT_STIFFNESS['linear'])}), "
        f"N/m^n for hunt-crossley (default {_g(_DEFAULT_STIFFNESS['hunt-crossley'])}); Hertz's "
        "comes from E, nu and the radius.",
    ),
)
@click.option(
    "--damping", type=float, default=None, help=_help("damping", "Linear; instead of --kappa.")
)
@click.option("--exponent", type=float, default=None, help=_help("exponent", "Default 1.5."))
@click.option(
    "--alpha",
    type=float,
    default=None,
    help=_help("alpha", "Hertz, hunt-crossley; instead of --kappa."),
)
@click.option(
    "--kappa",
    type=float,
    default=None,
    help=_help(
        "kappa",
        "Here in (0, 1]: the law's at the impact speed |vy|, to which its "
        "damping (--damping or --alpha) is calibrated; 1 is elastic. Default "
        f"{DEFAULTS['kappa']:g}, as solve, unless --damping or --alpha is given.",
    ),
)
@deprecated("--target-kappa", "--kappa", type=float)
@click.option("--rtol", type=float, default=1e-10, show_default=True, help=_help("rtol"))
@click.option(
    "--tangential",
    type=click.Choice(["none", "mindlin"]),
    default="none",
    show_default=True,
    help=_help(
        "tangential",
        "none (a rigid contact point, as the paper) or mindlin "
        "(a tangential spring k_t = 8 G* a with Coulomb slip).",
    ),
)
@click.option(
    "--stiffness-ratio",
    type=float,
    default=None,
    help=_help(
        "stiffness-ratio",
        "Of the mindlin spring (default 2(1-nu)/(2-nu) from "
        "--poisson-ratio with --contact hertz; needed with linear and hunt-crossley).",
    ),
)
@click.option(
    "--spring",
    type=click.Choice(["scaled", "incremental", "total", "history"]),
    default=None,
    help=_help(
        "spring",
        "scaled (default; its energy never grows), incremental, total "
        "(displacement times the current stiffness), or history (the exact no-slip elastic rule: "
        "the force unloads along its loading history).",
    ),
)
@click.option(
    "--plot", "plot_file", default=None, help=_help("plot", "N(t), F(t) and the velocities.")
)
def simulate_command(plot_file: str | None, **o: Any) -> None:
    """Integrate one impact in time with a compliant contact law and compare it
    with the rigid-body closed form at the law's own restitution."""
    from ..model.dynamics import simulate

    fmt = (
        image_format(plot_file, "--plot") if plot_file else None
    )  # a bad name fails before the work
    tangential = _tangential_law(o)
    body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
    law = _contact_law(o, float(body.radius))
    if tangential is not None:
        sim = simulate(body, o["vx"], o["vy"], o["omega"], mu=o["mu"], contact=law,
                       rtol=o["rtol"], tangential=tangential)  # fmt: skip
        _print_tangential(sim)
        if plot_file:
            from ..io import atomic_path
            from ..viz.tangential import plot_tangential

            with atomic_path(plot_file) as tmp:
                plot_tangential(sim).savefig(tmp, format=fmt, dpi=110)
            click.echo(f"wrote {plot_file}")
        return
    sim = simulate(body, o["vx"], o["vy"], o["omega"], mu=o["mu"], contact=law, rtol=o["rtol"])
    from ..viz.report import print_simulation

    target, source = _target(o)
    if target == 1.0:
        click.echo(f"{o['contact']} contact law, elastic: no damping for kappa = 1 ({source})")
    elif target is not None:  # say what was calibrated, and to what
        what = "damping c" if o["contact"] == "linear" else "Hunt-Crossley damping alpha"
        click.echo(f"{o['contact']} contact law, its {what} calibrated to give kappa = "
                   f"{target:g} at |vy| = {abs(o['vy']):g} m/s ({source})")  # fmt: skip
    print_simulation(sim)
    if plot_file:
        from ..io import atomic_path
        from ..viz.plots import plot_simulation

        with atomic_path(plot_file) as tmp:
            plot_simulation(sim).savefig(tmp, format=fmt, dpi=110)
        click.echo(f"wrote {plot_file}")
