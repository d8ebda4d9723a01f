"""Pure numeric kernels of the impact theory (Lubarda 2010; Keller 1986).

Arrays in, arrays (or named tuples of arrays) out: every function broadcasts over
any number of impacts, on NumPy or any array-API library, and has no classes
beyond named tuples, no I/O and no input validation (that is the model layer's
job). Each docstring names the paper equations it implements;
``docs/theory.md`` maps every equation to its function.

Modules
-------
impulse
    The contact seam: Keller's method at one contact point, from the contact
    velocity and the collision matrix ``W`` (impulses, regimes, slip, rebound).
works
    Works, dissipated energy and the energy minimum at the contact point.
kinematics, energetics
    The paper's bodies (contact straight below the centre): body velocities in,
    body velocities and energies out, through the seam.
outcomes, particle
    Qualitative rebound outcomes; Whittaker's particle model.
contact
    Compliant contact laws integrated in time.
fused
    One-pass rebound kernels (optional Numba).
scalar, scalar3d, scalar_planar, law
    The same law on plain numbers, one contact per call, bit for bit the kernels'
    results; ``law`` registers it for users' ``numba.njit`` code
    (``spinimpact.contact_law``, ``docs/compiled.md``).
"""

from .energetics import (
    MIN_ENERGY_CASES,
    PhaseWorks,
    WorkRatioBounds,
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
from .impulse import (
    CollisionMatrix,
    ContactParameters,
    RegimeThresholds,
    RestitutionCoefficients,
    contact_parameters,
    planar_collision_matrix,
    rebound_normal_velocity,
)
from .kinematics import (
    REGIMES,
    Rebound,
    Velocities,
    VelocityRatios,
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
from .outcomes import OUTCOMES, OutcomeFlags, rebound_outcomes
from .particle import (
    ParticleRebound,
    particle_energy_change,
    particle_energy_threshold,
    particle_rebound,
)
from .restitution import restitution_by_definition
from .works import (
    contact_dissipated_energy,
    contact_min_energy_case,
    contact_min_energy_impulse,
    contact_phase_works,
)

__all__ = [
    "CollisionMatrix",
    "ContactParameters",
    "OutcomeFlags",
    "ParticleRebound",
    "PhaseWorks",
    "Rebound",
    "RegimeThresholds",
    "RestitutionCoefficients",
    "Velocities",
    "VelocityRatios",
    "WorkRatioBounds",
    "contact_dissipated_energy",
    "contact_min_energy_case",
    "contact_min_energy_impulse",
    "contact_parameters",
    "contact_phase_works",
    "planar_collision_matrix",
    "rebound_normal_velocity",
    "restitution_by_definition",
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
