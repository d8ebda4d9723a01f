"""The hook by which ``solve`` and ``solve_sphere`` hand an impact to a tangential law.

Kept apart from :mod:`spinimpact.model.compliance` (which imports the solvers' result
types) so that the solvers can accept a law without importing it: no import cycle.
"""

from __future__ import annotations

from typing import Any

__all__ = ["tangential_law"]


def tangential_law(law: Any) -> Any:
    """``law`` if it is a tangential compliance law (it can solve an impact), else
    ``TypeError`` naming what was given."""
    laws = "spinimpact.Walton, spinimpact.Stronge or spinimpact.MindlinDeresiewicz"
    if isinstance(law, type):  # the class itself, not a law with its parameters
        raise TypeError(f"tangential must be a law, an instance such as {law.__name__}(...) "
                        f"with its parameters, got the class {law.__name__}")  # fmt: skip
    if not (callable(getattr(law, "_solve_plane", None)) and callable(
            getattr(law, "_solve_sphere", None))):  # fmt: skip
        raise TypeError(f"tangential must be a tangential compliance law ({laws}) or None, "
                        f"got {law!r}")  # fmt: skip
    return law
