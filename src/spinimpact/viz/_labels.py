"""The two notations of the report tables: plain ASCII labels for a terminal
(``omega``, ``tau1``, ``mu_hat``) and their typeset Unicode forms for a page
(``ω``, ``τ₁``, ``μ̂``). :mod:`spinimpact.viz.tables` writes every label once, in
ASCII, and asks :func:`notation` for the form a renderer wants.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..model.impact import Impact

__all__ = ["TYPESET", "notation", "mathtext_escape", "report_title", "min_energy_words"]

#: Labels and headings whose typeset (Unicode) form differs from the plain (ASCII) one.
TYPESET: dict[str, str] = {
    "radius of gyration rho": "radius of gyration ρ",
    "zeta = 1 + R^2/rho^2": "ζ = 1 + R²/ρ²",
    "friction mu": "friction μ",
    "mu": "μ",
    "restitution kappa": "restitution κ",
    "omega (rad/s)": "ω (rad/s)",
    "slip u = vx + R*omega (m/s)": "slip u = vx + Rω (m/s)",
    "end of compression, tau0": "end of compression τ₀",
    "end of slip, tau*": "end of slip τ*",
    "end of impact, tau1": "end of impact τ₁",
    "friction impulse, f1": "friction impulse f₁",
    "of E-": "of E⁻",
    "kinetic energy before, E-": "kinetic energy before E⁻",
    "kinetic energy after, E+": "kinetic energy after E⁺",
    "dissipated, E- - E+": "dissipated ΔE = E⁻ − E⁺",
    "minimum during impact, Em": "minimum during impact E_m",
    "tau_m": "τ_m",
    "Newton restitution -v+/v-": "Newton restitution −v⁺/v⁻",
    "Poisson restitution (tau1-tau0)/tau0": "Poisson restitution (τ₁ − τ₀)/τ₀",
    "energetic restitution sqrt(-Wr^n/Wc^n)": "energetic restitution √(−W_r^n/W_c^n)",
    "tangential impact coefficient mu_hat = f1/tau1": "tangential impact coefficient μ̂ = f₁/τ₁",
    "friction work ratio Wr^t/Wc^t": "friction work ratio W_r^t/W_c^t",
    "leaves without slip (u+ = 0)": "leaves without slip (u⁺ = 0)",
    "vx+ (m/s)": "vx⁺ (m/s)",
    "vy+ (m/s)": "vy⁺ (m/s)",
    "energy change E+ - E- (J)": "energy change E⁺ − E⁻ (J)",
    "mu and kappa": "μ and κ",
    "|u-/v-|": "|u⁻/v⁻|",
    "<= zeta*mu": "≤ ζμ",
    "<= (1+kappa)*zeta*mu": "≤ (1+κ)ζμ",
}


def notation(typeset: bool) -> Callable[[str], str]:
    """The function giving a plain (ASCII) label in the chosen notation.

    Parameters
    ----------
    typeset : bool
        ``True``: the Unicode form from :data:`TYPESET` (labels not listed read
        the same in both); ``False``: the label unchanged.

    Examples
    --------
    >>> notation(True)("omega (rad/s)"), notation(False)("omega (rad/s)")
    ('ω (rad/s)', 'omega (rad/s)')
    """
    if typeset:
        return lambda text: TYPESET.get(text, text)
    return lambda text: text


def mathtext_escape(text: str) -> str:
    r"""User text (a body's name) for a Matplotlib label, shown as typed.

    Matplotlib reads text between two ``$`` as mathtext; each ``$`` is escaped so a
    name can neither start math nor make a figure fail to draw.

    Examples
    --------
    >>> mathtext_escape("$5 ball")
    '\\$5 ball'
    """
    return str(text).replace("$", r"\$")


def report_title(imp: Impact, *, typeset: bool = False) -> str:
    """The heading of a report: the body and the surface, ``rough`` only with friction.

    Examples
    --------
    >>> from spinimpact import Body, solve
    >>> ring = Body.ring(mass=1.0, radius=0.1)
    >>> report_title(solve(ring, 1.0, -1.0, 0.0, mu=0.0, kappa=1.0))
    'Impact of a ring body on a smooth surface (mu = 0)'
    """
    mu = notation(typeset)("mu")
    surface = "rough surface" if float(imp.mu) > 0 else f"smooth surface ({mu} = 0)"
    return f"Impact of a {imp.body.name} body on a {surface}"


def min_energy_words(imp: Impact) -> str:
    """Which case of the paper's Fig. 5 holds for the kinetic-energy minimum, in words
    that are true of this impact: with no slip at incidence (``u^- = 0``) the body does
    not roll, it has no slip before or after, and the minimum is at the end of
    compression; otherwise :attr:`Impact.min_energy_case` (eqs. 8.1-8.6)."""
    if imp.regime == "no-slip":
        return "at the end of compression (no slip before or after)"
    return str(imp.min_energy_case)
