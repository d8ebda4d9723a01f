"""Old home of :mod:`spinimpact.io.sweep`: importing it gives that module itself, so
existing imports (``from spinimpact.sweep import ...``) keep working."""

import sys

from .io import sweep as _module

sys.modules[__name__] = _module
