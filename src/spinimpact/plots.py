"""Old home of :mod:`spinimpact.viz.plots`: importing it gives that module itself, so
existing imports (``from spinimpact.plots import ...``) keep working."""

import sys

from .viz import plots as _module

sys.modules[__name__] = _module
