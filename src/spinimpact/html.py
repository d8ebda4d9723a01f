"""Old home of :mod:`spinimpact.viz.html`: importing it gives that module itself, so
existing imports (``from spinimpact.html import ...``) keep working."""

import sys

from .viz import html as _module

sys.modules[__name__] = _module
