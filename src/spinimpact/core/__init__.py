"""Pure numeric kernels of the impact theory (Lubarda 2010).

Arrays in, arrays out: every function broadcasts over any number of impacts
with NumPy and has no classes, no I/O and no input validation (that is the
model layer's job). Each docstring names the paper equations it implements;
``docs/theory.md`` maps every equation to its function.
"""

from .energetics import (
    MIN_ENERGY_CASES,
    dissipated_energy,
    kinetic_energy,
    kinetic_energy_at,
    min_energy_case,
    min_energy_impulse,
    phase_works,
    restitution_work,
    restitution_work_zero,
    work_normal,
    work_ratio_tangential,
    work_ratio_tangential_bounds,
    work_tangential,
)
from .kinematics import (
    REGIMES,
    compression_impulse,
    force_ratio_at,
    friction_impulse_at,
    impulse_ratio,
    incidence_ratio,
    rebound,
    rebound_slip,
    regime_code,
    regime_thresholds,
    restitution_coefficients,
    slip_at,
    slip_velocity,
    state_at,
    stick_impulse,
    sticks,
    sticks_in_compression,
    tangential_impulse,
    total_impulse,
    velocity_ratios,
)
from .outcomes import OUTCOMES, rebound_outcomes
from .particle import particle_energy_change, particle_energy_threshold, particle_rebound

__all__ = [
    "MIN_ENERGY_CASES",
    "OUTCOMES",
    "REGIMES",
    "compression_impulse",
    "force_ratio_at",
    "friction_impulse_at",
    "dissipated_energy",
    "impulse_ratio",
    "incidence_ratio",
    "kinetic_energy",
    "kinetic_energy_at",
    "min_energy_case",
    "min_energy_impulse",
    "particle_energy_change",
    "particle_energy_threshold",
    "particle_rebound",
    "phase_works",
    "rebound",
    "rebound_slip",
    "rebound_outcomes",
    "regime_code",
    "regime_thresholds",
    "restitution_coefficients",
    "restitution_work",
    "restitution_work_zero",
    "slip_at",
    "slip_velocity",
    "state_at",
    "stick_impulse",
    "sticks",
    "sticks_in_compression",
    "tangential_impulse",
    "total_impulse",
    "velocity_ratios",
    "work_normal",
    "work_ratio_tangential",
    "work_ratio_tangential_bounds",
    "work_tangential",
]
