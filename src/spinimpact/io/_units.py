"""Each column's SI unit in a file's metadata (the vocabulary: :mod:`spinimpact.model.units`).

Parquet output carries each column's unit in its field metadata (``{"unit": "m/s"}``),
and CSV output a side file (``out.units.json`` beside ``out.csv``,
:func:`~spinimpact.io.problem_batch.units_file`), so a file read years later still
says what its numbers are. Text and true/false columns (``regime``, ``law``, the outcome
flags) have no unit; a number without dimension has ``"1"``.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping

from ..model import units as _vocabulary
from ..model.units import unit_of

__all__ = ["UNITS", "unit_metadata", "unit_of"]


class _Units(Mapping):
    """Column name -> SI unit, for every column name the vocabulary knows (``after2_wx``
    too, read by :func:`unit_of`); iterating lists the base names."""

    def __getitem__(self, name: str) -> str:
        unit = unit_of(name)
        if unit is None:
            raise KeyError(name)
        return unit

    def __iter__(self) -> Iterator[str]:
        return iter(_vocabulary.UNITS)

    def __len__(self) -> int:
        return len(_vocabulary.UNITS)


#: Column name -> its SI unit (``"1"``: a number without dimension).
UNITS: Mapping[str, str] = _Units()


def unit_metadata(name: str) -> dict[bytes, bytes] | None:
    """Arrow field metadata naming the unit of column ``name``, or ``None`` if it has none.

    Examples
    --------
    >>> unit_metadata("after_vx"), unit_metadata("after2_wz"), unit_metadata("regime")
    ({b'unit': b'm/s'}, {b'unit': b'rad/s'}, None)
    """
    unit = unit_of(name)
    return None if unit is None else {b"unit": unit.encode()}
