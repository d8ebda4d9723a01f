"""What a sweep computes at its points, and how its files store them.

Each field is the :class:`~spinimpact.Impact` column of the same name, computed
from a chunk's inputs with the same core kernels that :func:`~spinimpact.solve`
calls, without building the whole result (so a sweep keeps the fused one-pass
rebound kernel). ``regime`` is computed as the integer code of the Impact's text,
``spinimpact.core.REGIMES[code]``.

Files name the regimes (:func:`output_kind`, :class:`TableColumns`): a Parquet file
holds ``regime`` as a dictionary column (read back as names: a pandas ``Categorical``,
strings in ``to_pylist()``), a CSV file as names; a directory of ``.npy`` files holds
the codes in ``regime.npy`` and the names in ``metadata.json`` (``"regimes"``), with
the body, each column's unit and dtype.
"""

from __future__ import annotations

import contextlib
import functools
import json
import math
import numbers
import os
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .. import core
from .._validation import require, whole
from ..core import fused
from . import _stop
from ._sinks import ArrowWriter
from ._units import unit_metadata, unit_of
from .atomic import atomic_path

__all__ = [
    "ALIASES",
    "DEFAULT_FIELDS",
    "FIELDS",
    "REBOUND_FIELDS",
    "TableColumns",
    "field_name",
    "npy_encoded_size",
    "npy_folder",
    "output_kind",
    "plan",
    "rebound_fields",
    "table_columns",
    "write_npy_metadata",
]

REBOUND_FIELDS = ("after_vx", "after_vy", "after_omega")


def _incidence(c: dict[str, Any], b: dict[str, float]) -> tuple[Any, ...]:
    """The kernels' arguments ``(vx, vy, omega, m, R, zeta, mu, kappa)`` of a chunk."""
    return (c["vx"], c["vy"], c["omega"], b["mass"], b["radius"], b["zeta"], c["mu"], c["kappa"])


def _slip(c: dict[str, Any], b: dict[str, float]) -> Any:
    return core.slip_velocity(c["vx"], c["omega"], b["radius"])


def rebound_fields(c: dict[str, Any], b: dict[str, float]) -> tuple[np.ndarray, ...]:
    """``after_vx, after_vy, after_omega`` of a chunk in one pass (:func:`fused.rebound`).

    Parameters
    ----------
    c : dict
        The chunk's inputs ``vx, vy`` (m/s), ``omega`` (rad/s), ``mu, kappa``.
    b : dict
        The body's ``mass`` (kg), ``radius`` (m), ``zeta`` and ``inertia`` (kg m^2).
    """
    return fused.rebound(*_incidence(c, b))  # one pass over memory (Numba) or NumPy


def _regime(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.regime_code(_slip(c, b), c["vy"], b["zeta"], c["mu"], c["kappa"])


def _dissipated_energy(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.dissipated_energy(*_incidence(c, b))


def _dissipated_fraction(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    before = core.kinetic_energy(c["vx"], c["vy"], c["omega"], b["mass"], b["inertia"])
    return _dissipated_energy(c, b) / before


def _impulse_ratio(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.impulse_ratio(_slip(c, b), c["vy"], b["zeta"], c["mu"], c["kappa"])


def _slip_after(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.rebound_slip(_slip(c, b), c["vy"], b["zeta"], c["mu"], c["kappa"])


#: Fields a sweep can write or reduce, each named as the :class:`~spinimpact.Impact`
#: column it equals, and how it is computed from a chunk's inputs ``c`` and body ``b``.
FIELDS: dict[str, Callable[[dict, dict], Any]] = {
    "after_vx": lambda c, b: rebound_fields(c, b)[0],  # m/s
    "after_vy": lambda c, b: rebound_fields(c, b)[1],  # m/s
    "after_omega": lambda c, b: rebound_fields(c, b)[2],  # rad/s
    "slip_before": _slip,  # m/s
    "slip_after": _slip_after,  # m/s
    "regime": _regime,  # integer code: spinimpact.core.REGIMES[code]
    "impulse_ratio": _impulse_ratio,  # 1
    "dissipated_energy": _dissipated_energy,  # J
    "dissipated_fraction": _dissipated_fraction,  # dissipated / incidence kinetic energy, 1
}

#: Older field names, still accepted: alias -> the field it means. A field asked
#: for by an alias is written under the alias, so existing scripts find their columns.
ALIASES: dict[str, str] = {"energy_loss": "dissipated_fraction"}


@functools.cache
def _lookup(regimes: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray]:
    order = np.argsort(regimes)
    return order, np.asarray(regimes)[order]


def regime_codes(regime: np.ndarray, regimes: Sequence[str]) -> np.ndarray:
    """Regime names -> their indices into ``regimes`` (int8), in one pass: how every sweep
    stores its regimes (the names go into the file's description).

    Raises
    ------
    ValueError
        For a name not among ``regimes``.
    """
    order, names = _lookup(tuple(regimes))
    regime = np.asarray(regime).astype(str)
    at = np.clip(np.searchsorted(names, regime), 0, names.size - 1)
    unknown = names[at] != regime
    if unknown.any():
        raise ValueError(f"regime {str(regime[np.argmax(unknown)])!r} is not among the regimes "
                         f"{', '.join(regimes)}")  # fmt: skip
    return order[at].astype(np.int8)


def field_name(name: str, role: str = "fields") -> str:
    """The :data:`FIELDS` name of ``name`` (itself, or what an alias stands for).

    Parameters
    ----------
    name : str
        A field or an alias.
    role : str
        What ``name`` was given as, for the message (``"fields"``, ``"histogram field"``).

    Raises
    ------
    ValueError
        For a name that is neither a field nor an alias.

    Examples
    --------
    >>> field_name("energy_loss")
    'dissipated_fraction'
    """
    if name in FIELDS:
        return name
    if name in ALIASES:
        return ALIASES[name]
    aliases = ", ".join(f"{a} for {f}" for a, f in ALIASES.items())
    raise ValueError(f"{role} must be among {', '.join(FIELDS)} (or {aliases}); got {name!r}")


# -- files ------------------------------------------------------------------------------


def output_kind(output: str | os.PathLike[str]) -> str:
    """What ``output`` names: ``"parquet"``, ``"csv"`` or ``"npy"`` (a new directory).

    A name ending in ``.parquet`` or ``.csv`` (any case) is a file; a name without a
    suffix, or ending in ``/``, is a directory of ``.npy`` files.

    Raises
    ------
    ValueError
        For any other suffix (``x.txt``, ``x.npy``): it would otherwise become a
        directory the user did not ask for.

    Examples
    --------
    >>> output_kind("s.parquet"), output_kind("s.CSV"), output_kind("run1"), output_kind("v1.5/")
    ('parquet', 'csv', 'npy', 'npy')
    """
    text = os.fspath(output)
    suffix = Path(text).suffix.lower()
    if suffix in (".parquet", ".csv"):
        return suffix[1:]
    if text.endswith(("/", os.sep)) or not suffix:
        return "npy"
    raise ValueError(
        f"output {text!r}: a sweep writes FILE.parquet, FILE.csv or a new directory of .npy "
        f"files (a name without a suffix, or ending in '/'), not a {suffix} file"
    )


class TableColumns:
    """Sweep columns to one Parquet or CSV file through pyarrow, chunk by chunk.

    ``regime`` (integer codes) becomes a dictionary column whose dictionary is the
    regimes' names, so a reader gets names; each column with a unit names it in its
    Parquet field metadata (``{"unit": "m/s"}``: ``units(name)``, by default the package's
    vocabulary), and the file's metadata says what the sweep was
    (:meth:`Sweep.metadata <spinimpact.io.sweep.Sweep.metadata>`).
    """

    def __init__(
        self,
        out: Any,
        fmt: str,
        metadata: dict[str, str],
        regimes: Sequence[str],
        units: Callable[[str], str | None] | None = None,
    ) -> None:
        self.pa = require("pyarrow", "Parquet and CSV output")
        self.writer = ArrowWriter(out, fmt)
        self.metadata = metadata if fmt == "parquet" else None
        self.names = self.pa.array(list(regimes), self.pa.string())
        self.units = units

    def table(self, data: dict[str, np.ndarray]) -> Any:
        """One chunk's columns as a pyarrow table."""
        pa = self.pa
        fields, arrays = [], []
        for name, values in data.items():
            if name == "regime":
                array = pa.DictionaryArray.from_arrays(
                    pa.array(np.asarray(values, np.int8)), self.names
                )
            else:
                array = pa.array(np.ascontiguousarray(values))
            arrays.append(array)
            unit = None if self.units is None else self.units(name)
            meta = unit_metadata(name) if self.units is None else unit and {b"unit": unit.encode()}
            fields.append(pa.field(name, array.type, metadata=meta or None))
        return pa.Table.from_arrays(arrays, schema=pa.schema(fields, self.metadata))

    def write(self, data: dict[str, np.ndarray]) -> None:
        """Append one chunk's columns; first stop if a signal asked to
        (:func:`spinimpact.io._stop.check`: a sweep stops between chunks)."""
        _stop.check()
        self.writer.write(self.table(data))

    def close(self) -> None:
        self.writer.close()

    @classmethod
    def encoded_size(
        cls, data: dict[str, np.ndarray], fmt: str, metadata: dict, regimes: Sequence[str]
    ) -> tuple[int, int]:
        """Bytes of ``data`` written as a file of format ``fmt`` (in memory), and the bytes
        pyarrow held meanwhile (outside Python's allocator)."""
        pa = require("pyarrow", "Parquet and CSV output")
        before = pa.total_allocated_bytes()
        sink = pa.BufferOutputStream()
        columns = cls(sink, fmt, metadata, regimes)
        columns.write(data)
        columns.close()
        return sink.getvalue().size, pa.total_allocated_bytes() - before


@contextlib.contextmanager
def table_columns(
    path: str | os.PathLike[str],
    fmt: str,
    metadata: dict[str, str],
    regimes: Sequence[str],
    units: Callable[[str], str | None] | None = None,
) -> Iterator[TableColumns]:
    """A :class:`TableColumns` writing the file ``path``, renamed into place on success
    (:func:`~spinimpact.io.atomic.atomic_path`); ``units(name)`` names each column's unit.

    Raises
    ------
    ImportError
        Without pyarrow, naming the ``[parquet]`` extra.
    ValueError
        If ``path`` is a directory or its directory does not exist.
    """
    what = {"parquet": "Parquet output", "csv": "CSV output"}[fmt]
    require("pyarrow.parquet" if fmt == "parquet" else "pyarrow.csv", what)
    target = Path(path)
    if target.is_dir():
        raise ValueError(f"output {str(target)!r} is a directory")
    if not target.absolute().parent.is_dir():
        raise ValueError(f"the directory of the output {str(target)!r} does not exist")
    with atomic_path(target) as tmp:
        columns = TableColumns(tmp, fmt, metadata, regimes, units)
        try:
            yield columns
        finally:
            columns.close()


def write_npy_metadata(
    directory: str | os.PathLike[str],
    description: dict[str, Any],
    dtypes: dict[str, np.dtype],
    units: Callable[[str], str | None] | None = None,
) -> None:
    """Write ``metadata.json`` into a sweep's directory of ``.npy`` files (while it is
    built under its temporary name).

    It holds ``description`` (the regimes' names, ``regime.npy`` holding indices into
    them; the body; the inputs a problem's sweep holds fixed, a restitution law among them)
    and, for each column, its file, dtype and unit (``units(name)``, by default the
    package's vocabulary).
    """
    units = units or unit_of
    columns = {
        name: {"file": f"{name}.npy", "dtype": str(dtype)}
        | ({"unit": units(name)} if units(name) is not None else {})
        | ({"values": "index into regimes"} if name == "regime" else {})
        for name, dtype in dtypes.items()
    }
    text = json.dumps(description | {"columns": columns}, indent=2) + "\n"
    (Path(directory) / "metadata.json").write_text(text, encoding="utf-8")


#: The fields a sweep writes unless told otherwise.
DEFAULT_FIELDS = ("after_vx", "after_vy", "after_omega", "regime")


#: The most bins a histogram may have.
MAX_BINS = 10**6


def _field_names(fields: Any) -> tuple[str, ...]:
    """``fields`` as a tuple of names: one name (a string) or a sequence of them."""
    if isinstance(fields, str):
        return (fields,)
    if not isinstance(fields, Sequence) or not all(isinstance(f, str) for f in fields):
        raise TypeError(f"fields must be a field's name or a sequence of them, got {fields!r}")
    return tuple(fields)


def _check_histogram(sweep: Any, histogram: Any) -> None:
    """``histogram`` is ``(field, low, high, bins)``: a field of ``sweep``, finite ends
    ``low < high`` and a whole number of bins in ``[1, MAX_BINS]``; else an error naming
    the part and its value."""
    if isinstance(histogram, str) or not isinstance(histogram, Sequence):
        raise TypeError(f"histogram must be (field, low, high, bins), got {histogram!r}")
    if len(histogram) != 4:
        raise ValueError(f"histogram must be (field, low, high, bins), got {histogram!r}")
    name, lo, hi, bins = histogram
    if not isinstance(name, str):
        raise TypeError(f"histogram's field must be a field's name, got {name!r}")
    sweep.field_name(name, "histogram field")
    for part, x in (("low", lo), ("high", hi)):
        if isinstance(x, bool) or not isinstance(x, numbers.Real):
            raise TypeError(f"histogram's {part} must be a real number, got {x!r}")
        if not math.isfinite(x):
            raise ValueError(f"histogram's {part} must be finite, got {x!r}")
    if not lo < hi:
        raise ValueError(f"histogram's low must be < high, got {lo!r} and {hi!r}")
    if whole("histogram's bins", bins, 1) > MAX_BINS:
        raise ValueError(f"histogram's bins must be an integer <= {MAX_BINS}, got {bins!r}")


def plan(
    sweep: Any,
    fields: tuple[str, ...],
    histogram: tuple[str, float, float, int] | None,
    output: str | os.PathLike[str] | None,
) -> tuple[str | None, tuple[str, ...]]:
    """Check the fields and the histogram; the output's kind and the columns it holds.
    Fields left at :data:`DEFAULT_FIELDS` are the sweep's ``default_fields`` where it has
    them (a sphere's: it has no ``after_omega``)."""
    if fields is DEFAULT_FIELDS:
        fields = getattr(sweep, "default_fields", fields)
    fields = _field_names(fields)
    for name in fields:
        sweep.field_name(name)
    if histogram is not None:
        _check_histogram(sweep, histogram)
    if output is None:
        return None, ()
    return output_kind(output), tuple(dict.fromkeys(sweep.inputs + tuple(fields)))


def npy_folder(writer: Any) -> Any:
    """The temporary folder that :func:`~spinimpact.io._sinks.npy_columns` fills and renames
    onto the output on success (``metadata.json`` goes in with the columns)."""
    folder = getattr(writer, "directory", None)
    if folder is None:
        handle, _ = next(iter(writer.files.values()))
        folder = os.path.dirname(handle.name)
    return folder


def npy_encoded_size(data: dict[str, np.ndarray], dtypes: dict[str, np.dtype]) -> int:
    """Bytes of ``data`` in ``.npy`` files, each column converted as the writer does."""
    size = 0
    for name, values in data.items():
        size += len(np.ascontiguousarray(values, dtype=dtypes[name]).tobytes())
    return size
