"""Words for counts in messages and reports: ``count(1, "row")`` is ``"1 row"``,
``count(2000, "row")`` is ``"2,000 rows"``."""

from __future__ import annotations

__all__ = ["count"]


def count(n: int, noun: str, plural: str | None = None) -> str:
    """``n`` with thousands separators and ``noun`` in the number it agrees with.

    Parameters
    ----------
    n : int
        How many.
    noun : str
        The noun for one (``"row"``); ``plural`` for other counts, by default ``noun + "s"``.

    Examples
    --------
    >>> count(1, "row"), count(0, "row"), count(12345, "point"), count(2, "bounce")
    ('1 row', '0 rows', '12,345 points', '2 bounces')
    """
    return f"{n:,} {noun if n == 1 else plural or noun + 's'}"
