"""The SI unit of every named quantity the package writes: one vocabulary for all problems.

A column's unit follows from its name, so every problem's inputs and results, present and
future, are described the same way in files (Parquet field metadata, the CSV side file),
tables and the registry of problems (:mod:`spinimpact.model.registry`):

* a leading ``before_``, ``after_``, ``before1_``, ``after2_``, ``ball1_`` ... names a
  state or a ball and does not change the unit (``after2_wx`` is a spin, rad/s);
* a trailing ``2`` names the second ball of a pair (``vx2``, ``mass2``);
* components ``_x, _y, _z`` of a vector share the vector's unit (``friction_impulse_x``).

Text and true/false columns (``regime``, ``law``, the outcome flags) have no unit; a
number without dimension has ``"1"``.
"""

from __future__ import annotations

import re

__all__ = ["UNITS", "unit_of"]

_GROUPS = {
    "m/s": "vx vy vz slip_before slip_after normal_velocity_before normal_velocity_after "
    "slip_before_x slip_before_y slip_before_z slip_after_x slip_after_y slip_after_z "
    "surface_velocity_x surface_velocity_y surface_velocity_z rebound_speed speed",
    "rad/s": "omega wx wy wz topspin sidespin gyrospin",
    "kg": "mass",
    "m": "radius gyration rx ry gx gy px py",
    "kg m^2": "inertia",
    "N s": "tau0 tau_star tau1 tangential_impulse tau_min_energy "
    "friction_impulse_x friction_impulse_y friction_impulse_z",
    "J": "kinetic_energy_before kinetic_energy_after dissipated_energy min_kinetic_energy "
    "work_compression_normal work_compression_tangential work_restitution_normal "
    "work_restitution_tangential",
    "rad": "rebound_angle angle_between_paths",
    "1": "mu kappa zeta incidence_ratio impulse_ratio dissipated_fraction energy_loss "
    "work_ratio_tangential newton_restitution poisson_restitution energetic_restitution "
    "tangential_restitution centre_tangential_restitution normal_x normal_y normal_z beta0 "
    "poisson_ratio stiffness_ratio",
}

#: Base name -> its SI unit (``"1"``: a number without dimension).
UNITS: dict[str, str] = {name: unit for unit, names in _GROUPS.items() for name in names.split()}

_PREFIX = re.compile(r"^(?:before|after|ball)[12]?_")


def unit_of(name: str, extra: dict[str, str] | None = None) -> str | None:
    """The SI unit of the quantity or column ``name``, or ``None`` for text and flags.

    Parameters
    ----------
    name : str
        A column name (``after2_wx``, ``vx2``, ``ball1_mass``, ``friction_impulse_z``).
    extra : dict, optional
        Units a problem declares for names of its own, looked up first (with the same
        prefixes and suffixes removed).

    Returns
    -------
    str or None

    Examples
    --------
    >>> unit_of("after2_wx"), unit_of("vx2"), unit_of("ball1_mass"), unit_of("regime")
    ('rad/s', 'm/s', 'kg', None)
    """
    table = UNITS if not extra else {**UNITS, **extra}
    for candidate in (name, _PREFIX.sub("", name)):
        for base in (candidate, candidate[:-1] if candidate.endswith("2") else candidate):
            if base in table:
                return table[base]
    return None
