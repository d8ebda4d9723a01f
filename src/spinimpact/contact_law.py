"""The compiled per-contact law, at a short path: :mod:`spinimpact.core.law`.

Scalar impact functions (one contact: floats in, floats out) that your own ``numba.njit``
code can call, and plain Python can too (``docs/compiled.md``).

>>> from spinimpact import contact_law as law
>>> vx, vy, omega, f1 = law.rebound(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8)
>>> round(vx, 6), law.regime(2.0, -3.0, 0.0, 0.1, 3.5, 0.5, 0.8)
(1.428571, 2)
"""

from .core.law import *  # noqa: F403
from .core.law import __all__  # noqa: F401
