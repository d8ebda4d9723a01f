"""Old home of :mod:`spinimpact.io.batch`: importing it gives that module itself, so
existing imports (``from spinimpact.batch import ...``) keep working."""

import sys

from .io import batch as _module

sys.modules[__name__] = _module
