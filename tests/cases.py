"""Random impacts spread over all five regimes, for equation and property tests."""

from __future__ import annotations

import numpy as np

REGIME_NAMES = ("frictionless", "no-slip", "stick-compression", "stick-restitution", "slip")


#: The zetas of :func:`random_cases`: the four presets, spools (``rho > R``) and a compact body.
ZETAS = (3.0, 2.0, 3.5, 2.5, 1.2, 1.05, 5.0)
#: Those a sphere may have (``rho <= sqrt(2/3) R``, ``zeta >= 5/2``), for the 3D solvers.
SPHERE_ZETAS = (3.5, 2.5, 5.0)


def random_cases(n: int, seed: int = 0, zetas: tuple[float, ...] = ZETAS) -> dict[str, np.ndarray]:
    """``n`` impacts, a fifth of them aimed at each regime (by the paper's inequalities).

    Bodies range over ``zetas`` (by default the four presets and spools, ``rho > R``;
    :data:`SPHERE_ZETAS` for spheres); masses over three decades, radii over two; ``mu`` in
    (0, 1.5]; ``kappa`` in [0, 1] with its ends.
    """
    rng = np.random.default_rng(seed)
    target = np.arange(n) % 5
    mass = 10 ** rng.uniform(-2, 1, n)
    radius = 10 ** rng.uniform(-2, 0, n)
    zeta = rng.choice(zetas, n)
    gyration = radius / np.sqrt(zeta - 1.0)
    mu = rng.uniform(0.01, 1.5, n)
    mu[target == 0] = 0.0
    kappa = rng.uniform(0, 1, n)
    kappa[rng.random(n) < 0.05] = 0.0
    kappa[rng.random(n) < 0.05] = 1.0
    # kappa = 0 leaves no stick-restitution interval; keep those targets feasible.
    kappa[(target == 3) & (kappa == 0)] = 0.5
    vy = -(10 ** rng.uniform(-1, 1, n))
    w = np.abs(vy)
    lo = zeta * mu
    hi = (1 + kappa) * zeta * mu
    ratio = np.select(
        [target == 0, target == 1, target == 2, target == 3],
        [
            rng.uniform(0, 3, n),
            np.zeros(n),
            rng.uniform(0.02, 0.98, n) * lo,
            lo + rng.uniform(0.02, 0.98, n) * (hi - lo),
        ],
        hi * (1.02 + rng.exponential(2.0, n)),
    )
    sign = rng.choice([-1.0, 1.0], n)
    slip = sign * ratio * w
    vx = rng.normal(0, 3, n)
    omega = (slip - vx) / radius
    # Rolling incidence, exactly: vx = -R omega makes u = vx + R omega = 0 in floating point.
    omega[target == 1] = rng.normal(0, 30, n)[target == 1]
    vx[target == 1] = -radius[target == 1] * omega[target == 1]
    return dict(
        vx=vx,
        vy=vy,
        omega=omega,
        mass=mass,
        radius=radius,
        gyration=gyration,
        zeta=zeta,
        mu=mu,
        kappa=kappa,
        target=np.asarray(REGIME_NAMES)[target],
    )
