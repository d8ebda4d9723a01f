"""The two notations of the report tables: plain ASCII labels for a terminal
(``omega``, ``tau1``, ``mu_hat``) and their typeset Unicode forms for a page
(``ω``, ``τ₁``, ``μ̂``). :mod:`spinimpact.viz.tables` writes every label once, in
ASCII, and asks :func:`notation` for the form a renderer wants.
"""

from __future__ import annotations

from collections.abc import Callable

__all__ = ["TYPESET", "notation"]

#: Labels and headings whose typeset (Unicode) form differs from the plain (ASCII) one.
TYPESET: dict[str, str] = {
    "radius of gyration rho": "radius of gyration ρ",
    "zeta = 1 + R^2/rho^2": "ζ = 1 + R²/ρ²",
    "friction mu": "friction μ",
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
    "leaves rolling (u+ = 0)": "leaves rolling (u⁺ = 0)",
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
