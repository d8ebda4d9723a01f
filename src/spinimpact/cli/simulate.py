"""``spinimpact simulate``: one impact integrated in time with a compliant contact law."""

from __future__ import annotations

from typing import Any

import click

from ._common import DEFAULTS, body_options, image_format, incidence_options, make_body

__all__ = ["simulate_command"]

#: The options of each contact law (Python names); any other law option is an error.
_LAW_OPTIONS = {
    "hertz": {"youngs_modulus", "poisson_ratio", "alpha"},
    "linear": {"stiffness", "damping"},
    "hunt-crossley": {"stiffness", "exponent", "alpha"},
}
#: Default stiffness of the laws that take one: N/m (linear), N/m^n (hunt-crossley).
_DEFAULT_STIFFNESS = {"linear": 1e6, "hunt-crossley": 1e8}


def _contact_law(o: dict[str, Any], radius: float) -> Any:
    """The contact law described by the options (``o`` is updated with the defaults).

    Parameters
    ----------
    o : dict
        The command's options: ``contact``, the law's settings (``youngs_modulus``
        in Pa, ``poisson_ratio``, ``stiffness`` in N/m or N/m^n, ``damping`` in
        N s/m, ``exponent``, ``alpha`` in s/m), ``target_kappa``, ``mass`` in kg
        and ``vy`` in m/s.
    radius : float
        Contact radius R of the body, m (Hertz's stiffness depends on it).

    Returns
    -------
    ContactLaw
        With ``--target-kappa``, a law whose damping is calibrated to give that
        restitution at the impact speed ``|vy|``.

    Raises
    ------
    click.UsageError
        For an option that does not apply to the law, or damping given together
        with ``--target-kappa``.
    """
    from ..model.contact import HertzContact, HuntCrossleyContact, LinearContact

    speed, target = abs(o["vy"]), o["target_kappa"]
    allowed = _LAW_OPTIONS[o["contact"]]
    for name in ("youngs_modulus", "poisson_ratio", "stiffness", "damping", "exponent", "alpha"):
        flag = "--" + name.replace("_", "-")
        if o[name] is not None and name not in allowed:
            raise click.UsageError(f"{flag} does not apply to --contact {o['contact']}")
        if o[name] is not None and target is not None and name in ("damping", "alpha"):
            raise click.UsageError(f"give either {flag} or --target-kappa, not both")
    o["youngs_modulus"] = 2e9 if o["youngs_modulus"] is None else o["youngs_modulus"]
    o["poisson_ratio"] = 0.35 if o["poisson_ratio"] is None else o["poisson_ratio"]
    o["damping"] = o["damping"] or 0.0
    o["alpha"] = o["alpha"] or 0.0
    o["exponent"] = 1.5 if o["exponent"] is None else o["exponent"]
    if o["contact"] == "hertz":
        if o["stiffness"] is not None:
            raise click.UsageError(
                "--stiffness is for linear and hunt-crossley; hertz uses E and nu"
            )
        law = HertzContact(o["youngs_modulus"], o["poisson_ratio"], radius, o["alpha"])
        if target is not None:
            law = HuntCrossleyContact.calibrated(
                stiffness=law.stiffness, kappa=target, mass=o["mass"], speed=speed
            )
        return law
    k = o["stiffness"] if o["stiffness"] is not None else _DEFAULT_STIFFNESS[o["contact"]]
    if o["contact"] == "linear":
        if target is not None:
            return LinearContact.calibrated(stiffness=k, kappa=target, mass=o["mass"])
        return LinearContact(k, o["damping"])
    if target is not None:
        return HuntCrossleyContact.calibrated(
            stiffness=k, kappa=target, mass=o["mass"], speed=speed, exponent=o["exponent"]
        )
    return HuntCrossleyContact(k, o["exponent"], o["alpha"])


@click.command("simulate")
@body_options
@incidence_options
@click.option("--mu", type=float, default=DEFAULTS["mu"], show_default=True, help="Friction >= 0.")
@click.option(
    "--contact",
    type=click.Choice(["hertz", "hunt-crossley", "linear"]),
    default="hertz",
    show_default=True,
    help="Normal contact law.",
)
@click.option("--youngs-modulus", type=float, default=None, help="E, Pa (hertz; default 2e9).")
@click.option("--poisson-ratio", type=float, default=None, help="nu (hertz; default 0.35).")
@click.option(
    "--stiffness", type=float, default=None, help="k: N/m (linear) or N/m^n (hunt-crossley)."
)
@click.option("--damping", type=float, default=None, help="c, N s/m (linear; default 0).")
@click.option("--exponent", type=float, default=None, help="n (hunt-crossley; default 1.5).")
@click.option(
    "--alpha", type=float, default=None, help="Damping, s/m (hertz, hunt-crossley; default 0)."
)
@click.option(
    "--target-kappa",
    type=float,
    default=None,
    help="Calibrate the damping so the law gives this restitution at the impact speed.",
)
@click.option("--rtol", type=float, default=1e-10, show_default=True, help="Integrator tolerance.")
@click.option("--plot", "plot_file", default=None, help="Write N(t), F(t) and the velocities here.")
def simulate_command(plot_file: str | None, **o: Any) -> None:
    """Integrate one impact in time with a compliant contact law and compare it
    with the rigid-body closed form at the law's own restitution."""
    from ..model.dynamics import simulate

    fmt = (
        image_format(plot_file, "--plot") if plot_file else None
    )  # a bad name fails before the work
    body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
    law = _contact_law(o, float(body.radius))
    sim = simulate(body, o["vx"], o["vy"], o["omega"], mu=o["mu"], contact=law, rtol=o["rtol"])
    from ..viz.report import print_simulation

    print_simulation(sim)
    if plot_file:
        from ..io import atomic_path
        from ..viz.plots import plot_simulation

        with atomic_path(plot_file) as tmp:
            plot_simulation(sim).savefig(tmp, format=fmt, dpi=110)
        click.echo(f"wrote {plot_file}")
