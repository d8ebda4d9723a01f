"""One result vocabulary: the base every result object of the package shares.

A result is a frozen dataclass whose fields are named in words. Numeric fields
hold NumPy scalars for one impact or read-only arrays of one broadcast shape for
many; nested results (the velocity states, the outcome flags) are results too.
The base gives them all the same behaviour:

* ``shape``, ``len()``, iteration and ``result[i]`` over the impacts;
* ``to_dict()``: plain Python values (floats, lists, str, bool, nested dicts), for JSON;
* ``columns()``: flat named columns, one array per column, for files and tables
  (``after`` of :class:`~spinimpact.Impact` becomes ``after_vx, after_vy,
  after_omega``); :meth:`Result.column_names` lists them without computing anything.

Batch files and sweeps take their column names from here, so a field is named
once, where it is defined.
"""

from __future__ import annotations

import typing
from dataclasses import dataclass, fields
from typing import Any, ClassVar

import numpy as np

__all__ = ["Result", "BodyColumns", "freeze", "plain_repr"]

Array = Any  # float or ndarray: scalar inputs give NumPy scalars, arrays give arrays


def freeze(x: Any) -> Array:
    """Freeze a value for a result field: read-only, and a NumPy scalar when 0-d (text:
    a plain Python ``str``, which the REPL shows as ``'slip'``, not ``np.str_('slip')``).

    Parameters
    ----------
    x : array_like
        A number or array (copied, so the caller's array stays writable).

    Returns
    -------
    numpy.generic, str or numpy.ndarray
        A NumPy scalar (``str`` for text) for 0-d input, otherwise a read-only copy of ``x``.

    Examples
    --------
    >>> freeze(2.0)
    np.float64(2.0)
    >>> a = freeze([1.0, 2.0])
    >>> a, a.flags.writeable
    (array([1., 2.]), False)
    >>> freeze(np.asarray(["slip", "stick"])[0])
    'slip'
    """
    arr = np.array(x)
    arr.setflags(write=False)
    out = arr[()]
    return str(out) if type(out) is np.str_ else out


def regime_counts(regime: Any) -> str:
    """``"name: count, ..."`` of the regimes of an array of impacts, for one-line reprs."""
    names, counts = np.unique(regime, return_counts=True)
    return ", ".join(f"{n}: {c}" for n, c in zip(names, counts, strict=True))


def plain_repr(obj: Any) -> str:
    """``Name(field=value, ...)`` with NumPy scalars shown as the Python numbers and
    booleans they hold: ``vx=1.0`` and ``backward=False``, not ``np.float64(1.0)`` and
    ``np.False_``; arrays keep NumPy's repr."""
    pairs = [(f.name, getattr(obj, f.name)) for f in fields(obj) if f.repr]
    plain = (f"{k}={v.item() if np.ndim(v) == 0 and hasattr(v, 'item') else v!r}" for k, v in pairs)
    return f"{type(obj).__name__}({', '.join(plain)})"


@dataclass(frozen=True, eq=False)
class Result:
    """Base of the package's result objects (a frozen dataclass of named fields).

    Subclasses are frozen dataclasses whose fields are NumPy scalars, read-only arrays
    (see :func:`freeze`), nested results, or other objects (a body, a string). Class
    attributes tune the flat columns:

    ``_shape_field``
        The field whose shape is the shape of the result (default: the broadcast
        shape of every array field).
    ``_column_prefix``
        ``True`` (default): a nested result's columns are prefixed with the
        field's name (``after_vx``); ``False``: they keep their own names
        (the outcome flags ``backward``, ``rolling``, ...).
    ``_body_prefix``
        ``True``: a body's columns are prefixed with the field's name (two balls:
        ``ball1_mass``, ``ball2_mass``); ``False`` (default): they keep their names.
    ``_per_impact``
        Whether each array field holds one value per impact, so that
        ``result[i]`` may index every array field. Results of one impact over
        time (a history) set it to ``False``.

    Examples
    --------
    >>> import numpy as np
    >>> from spinimpact import Body, solve
    >>> imp = solve(Body.solid_disk(mass=1.0, radius=0.1), vx=np.array([1.0, 2.0]),
    ...             vy=-1.0, omega=0.0, mu=0.2, kappa=0.5)
    >>> imp.shape, len(imp), imp[1].shape
    ((2,), 2, ())
    >>> [str(r) for r in imp.regime]
    ['slip', 'slip']
    >>> list(imp.after.columns())
    ['vx', 'vy', 'omega']
    """

    _shape_field: ClassVar[str | None] = None
    _column_prefix: ClassVar[bool] = True
    _per_impact: ClassVar[bool] = True
    _body_prefix: ClassVar[bool] = False  #: prefix a body's columns with its field's name

    # -- the impacts ---------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, ...]:
        """Broadcast shape of the impacts (``()`` for a single impact).

        Returns
        -------
        tuple of int
            The shape of the ``_shape_field`` field if the class names one, otherwise
            the broadcast shape of every array field and nested result.
        """
        if self._shape_field is not None:
            return np.shape(getattr(self, self._shape_field))
        shapes = [np.shape(v) for _, v in self._items() if _is_array(v)]
        shapes += [v.shape for _, v in self._items() if isinstance(v, Result)]
        return np.broadcast_shapes(*shapes) if shapes else ()

    def __len__(self) -> int:
        if self.shape == ():
            raise TypeError(f"len() of a single impact (a {type(self).__name__} of shape ())")
        return self.shape[0]

    def __iter__(self):  # type: ignore[no-untyped-def]
        return (self[i] for i in range(len(self)))

    def __getitem__(self, index: Any) -> Any:
        if not self._per_impact:
            raise TypeError(f"a {type(self).__name__} describes one impact; it is not indexable")
        values = {}
        for name, v in self._items():
            if isinstance(v, Result):
                values[name] = v[index]
            elif hasattr(v, "_at"):  # a Body whose parameters may be arrays: index them too
                values[name] = v._at(self.shape, index)
            elif _is_array(v):
                values[name] = freeze(np.asarray(v)[index])
            else:
                values[name] = v
        return type(self)(**values)

    # -- plain values and flat columns ------------------------------------------------
    def to_dict(self) -> dict[str, Any]:
        """Fields as plain Python values, for JSON.

        Returns
        -------
        dict
            One entry per field: floats, bools and strings for 0-d fields, (nested)
            lists for arrays, nested dicts for nested results and for objects with a
            ``to_dict`` method (a :class:`~spinimpact.Body`); other values as they are.

        Examples
        --------
        >>> from spinimpact import Body, solve
        >>> imp = solve(Body.solid_disk(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.2, kappa=0.5)
        >>> {name: round(value, 12) for name, value in imp.after.to_dict().items()}
        {'vx': 0.7, 'vy': 0.5, 'omega': -6.0}
        """
        out: dict[str, Any] = {}
        for name, v in self._items():
            if isinstance(v, Result):
                out[name] = v.to_dict()
            elif _is_array(v):
                out[name] = np.asarray(v).tolist()
            elif hasattr(v, "to_dict"):
                out[name] = v.to_dict()
            else:
                out[name] = v
        return out

    def columns(self) -> dict[str, np.ndarray]:
        """Every per-impact quantity as a flat named column of the result's shape.

        Nested results are flattened (``after_vx``; the outcome flags keep their
        names); objects with a ``columns(shape)`` method (a :class:`~spinimpact.Body`)
        contribute theirs. Non-numeric, non-per-impact fields are left out.

        Returns
        -------
        dict of str to numpy.ndarray
            Column name to an array of :attr:`shape` (read-only broadcast views), in the
            order of :meth:`column_names`.
        """
        shape = self.shape
        out: dict[str, np.ndarray] = {}
        for name, v in self._items():
            if isinstance(v, Result):
                prefix = f"{name}_" if v._column_prefix else ""
                nested = v.columns().items()
                out.update({prefix + k: np.broadcast_to(c, shape) for k, c in nested})
            elif _is_array(v) or (isinstance(v, str) and name in self._text_fields()):
                out[name] = np.broadcast_to(np.asarray(v), shape)
            elif hasattr(v, "columns"):
                prefix = f"{name}_" if self._body_prefix else ""
                out.update({prefix + k: c for k, c in v.columns(shape).items()})
        return out

    @classmethod
    def column_names(cls) -> tuple[str, ...]:
        """Names of :meth:`columns`, in order, from the field declarations alone.

        Read from the field annotations: a nested :class:`Result` contributes its
        own names, a type with a ``COLUMNS`` tuple (:class:`~spinimpact.Body`)
        those, and a field annotated ``Array`` (or ``np.ndarray``) its own name.

        Returns
        -------
        tuple of str
            The column names, computed without any result at hand.

        Examples
        --------
        >>> from spinimpact.model.impact import State
        >>> State.column_names()
        ('vx', 'vy', 'omega')
        """
        hints = typing.get_type_hints(cls)
        names: list[str] = []
        for f in fields(cls):  # type: ignore[arg-type]
            kind = hints[f.name]
            if isinstance(kind, type) and issubclass(kind, Result):
                prefix = f"{f.name}_" if kind._column_prefix else ""
                names += [prefix + n for n in kind.column_names()]
            elif isinstance(kind, type) and hasattr(kind, "COLUMNS"):
                prefix = f"{f.name}_" if cls._body_prefix else ""
                names += [prefix + n for n in kind.COLUMNS]
            elif kind is Array or kind is np.ndarray:
                names.append(f.name)
        return tuple(names)

    @classmethod
    def _text_fields(cls) -> frozenset[str]:
        """The fields declared ``Array`` (columns), which hold a ``str`` for one impact."""
        known = _ARRAY_FIELDS.get(cls)
        if known is None:
            hints = typing.get_type_hints(cls)
            known = frozenset(
                f.name for f in fields(cls) if hints[f.name] is Array or hints[f.name] is np.ndarray
            )
            _ARRAY_FIELDS[cls] = known
        return known

    def _items(self):  # type: ignore[no-untyped-def]
        return ((f.name, getattr(self, f.name)) for f in fields(self))  # type: ignore[arg-type]


_ARRAY_FIELDS: dict[type, frozenset[str]] = {}


def _is_array(v: Any) -> bool:
    return isinstance(v, np.ndarray | np.generic)


class BodyColumns:
    """Mixin for body classes: their ``COLUMNS`` as result columns and as plain values.

    A body names its per-impact numbers in ``COLUMNS`` (``mass``, ``radius``, ...); a
    result holding the body repeats them as columns (:meth:`Result.columns`).
    """

    COLUMNS: ClassVar[tuple[str, ...]] = ()
    name: str

    def columns(self, shape: tuple[int, ...]) -> dict[str, np.ndarray]:
        """The ``COLUMNS`` broadcast to ``shape``."""
        return {n: np.broadcast_to(np.asarray(getattr(self, n)), shape) for n in self.COLUMNS}

    def to_dict(self) -> dict[str, object]:
        """The name and the ``COLUMNS`` as plain Python values."""
        out: dict[str, object] = {"name": self.name}
        out.update({n: np.asarray(getattr(self, n)).tolist() for n in self.COLUMNS})
        return out
