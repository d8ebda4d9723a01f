"""The SI unit of every column a batch file or a sweep writes, for the files' metadata.

Parquet output carries each column's unit in its field metadata (``{"unit": "m/s"}``),
so a file read years later still says what its numbers are. Text and true/false
columns (``regime``, ``law``, the outcome flags) have no unit; a number without
dimension has ``"1"``.
"""

from __future__ import annotations

__all__ = ["UNITS", "unit_metadata"]

_GROUPS = {
    "m/s": "vx vy before_vx before_vy after_vx after_vy slip_before slip_after "
    "normal_velocity_before normal_velocity_after",
    "rad/s": "omega before_omega after_omega",
    "kg": "mass",
    "m": "radius gyration rx ry gx gy px py",
    "kg m^2": "inertia",
    "N s": "tau0 tau_star tau1 tangential_impulse tau_min_energy",
    "J": "kinetic_energy_before kinetic_energy_after dissipated_energy min_kinetic_energy "
    "work_compression_normal work_compression_tangential work_restitution_normal "
    "work_restitution_tangential",
    "1": "mu kappa zeta incidence_ratio impulse_ratio dissipated_fraction energy_loss "
    "work_ratio_tangential newton_restitution poisson_restitution energetic_restitution "
    "tangential_restitution centre_tangential_restitution",
}

#: Column name -> its SI unit (``"1"``: a number without dimension).
UNITS: dict[str, str] = {name: unit for unit, names in _GROUPS.items() for name in names.split()}


def unit_metadata(name: str) -> dict[bytes, bytes] | None:
    """Arrow field metadata naming the unit of column ``name``, or ``None`` if it has none.

    Examples
    --------
    >>> unit_metadata("after_vx"), unit_metadata("regime")
    ({b'unit': b'm/s'}, None)
    """
    unit = UNITS.get(name)
    return None if unit is None else {b"unit": unit.encode()}
