"""Random sphere impacts in 3D on tilted, moving planes, over the regimes."""

import numpy as np


def random_sphere_cases(n, seed):
    """Random 3D impacts on tilted, moving planes, spread over the regimes by ``mu``."""
    rng = np.random.default_rng(seed)
    normal = rng.normal(size=(n, 3))
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    vs = rng.normal(0, 1, (n, 3)) * (rng.random((n, 1)) < 0.5)
    t = rng.normal(0, 3, (n, 3))
    t -= np.sum(t * normal, axis=1)[:, None] * normal  # along the surface
    v = t - (0.1 + rng.exponential(3.0, (n, 1))) * normal + vs
    w = rng.normal(0, 40, (n, 3)) * (rng.random((n, 1)) < 0.8)
    mu = rng.choice([0.0, 0.05, 0.3, 1.0, 3.0], n)
    still = rng.random(n) < 0.1  # straight down on a level plane: no slip at all
    normal[still], vs[still], w[still] = (0.0, 1.0, 0.0), 0.0, 0.0
    v[still] = np.outer(-(0.5 + rng.random(still.sum())), normal[0] * 0 + (0.0, 1.0, 0.0))
    mu[still] = 0.4
    kappa = rng.uniform(0, 1, n)
    return normal, vs, v, w, mu, kappa
