"""Bodies and settings shared by the engine tests."""

import pytest

from spinimpact import Body
from spinimpact import engines as E

SPHERE = Body.solid_sphere(mass=1.0, radius=0.1)

BODIES = [
    SPHERE,
    Body.solid_disk(mass=2.0, radius=0.05),
    Body.spherical_shell(mass=0.5, radius=0.2),
    Body.solid_sphere(mass=1e-5, radius=1e-3),  # a small fast ball: MuJoCo's contact scales
]

#: PyBullet with no contact margin, position correction or restitution threshold.
PYBULLET_EXACT = {
    "contact_breaking_threshold": 0.0,
    "contact_erp": 0.0,
    "restitution_velocity_threshold": 0.0,
}


def needs(engine):
    """Skip the calling test unless ``engine`` is installed."""
    if not E.available(engine):
        pytest.skip(f"{engine} is not installed (the [engines] extra)")
