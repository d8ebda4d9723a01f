"""Old home of :mod:`spinimpact.viz.report`: importing it gives that module itself, so
existing imports (``from spinimpact.report import ...``) keep working."""

import sys

from .viz import report as _module

sys.modules[__name__] = _module
