"""How the scalar paths of the solvers put one impact's numbers into a result object.

The scalar paths (:mod:`spinimpact.model._fast`, :mod:`~spinimpact.model._fast_sphere`,
:mod:`~spinimpact.model._fast_planar`, :mod:`~spinimpact.model._fast_tangential`) compute
every field of one impact as Python floats and bools with the per-contact law on floats.
A :class:`Layout` says which field of a result class each of them fills, so that one
function makes the result either of NumPy scalars (the inputs were plain numbers) or of
read-only arrays whose lengths are all 1 (one-element arrays in, as the array path returns
them): the floats become one ``float64`` buffer and each field a view of one row of it.

The result classes have no ``__post_init__`` (checked when a layout is made), so an
instance is its ``__dict__``: a layout writes, once, a function that fills each object's
``__dict__`` with one dict display, instead of the frozen dataclass's ``__init__``, which
sets each field through ``object.__setattr__``. The 30 fields of an
:class:`~spinimpact.Impact`, their NumPy scalars included, took about 7 us this way on the
development machine (2 cores, under load; ``benchmarks/scalar_calls.py`` times whole calls).
"""

from __future__ import annotations

from dataclasses import fields
from typing import Any

import numpy as np

__all__ = ["Layout", "layout_for"]

_FLOAT = np.float64
_TRUE, _FALSE = np.True_, np.False_
_new = object.__new__


def _flag(x: bool) -> np.bool_:
    return _TRUE if x else _FALSE


class Layout:
    """Which field of a frozen result class each value of one impact fills.

    Parameters
    ----------
    kind : type
        The result class (a frozen dataclass without ``__post_init__``).
    floats : tuple of str
        Its float fields, in the order the scalar path gives their values.
    nested : tuple of (str, Layout)
        Fields that are results themselves; their floats (and flags) follow this class's
        own in the flat sequences, in this order.
    flags : tuple of str
        Its boolean fields, in the order of the flat sequence of flags.
    text : dict of str to tuple of str
        Its text fields and the names each may take: the array path writes them as
        ``numpy.asarray(names)[codes]``, whose dtype a one-element result keeps.
    given : tuple of str
        Fields passed on as they are, in both forms (a body, a law).

    Raises
    ------
    TypeError
        When the names are not exactly the class's fields, or the class has a
        ``__post_init__`` (its instances would not be their ``__dict__``).
    """

    def __init__(self, kind: type, floats: tuple[str, ...], *,
                 nested: tuple[tuple[str, Layout], ...] = (), flags: tuple[str, ...] = (),
                 text: dict[str, tuple[str, ...]] | None = None,
                 given: tuple[str, ...] = ()) -> None:  # fmt: skip
        text = text or {}
        names = [*floats, *(n for n, _ in nested), *flags, *text, *given]
        if hasattr(kind, "__post_init__") or sorted(names) != sorted(
            f.name for f in fields(kind)
        ):  # fmt: skip
            raise TypeError(f"the layout of {kind.__name__} must name each of its fields once")
        self.kind = kind
        self.floats = floats
        self.nested = nested
        self.flags = flags
        self.text = {name: (_table(values), {v: i for i, v in enumerate(values)})
                     for name, values in text.items()}  # fmt: skip
        self.given = given
        self._make = self._compile()
        self._all_texts = self._texts()

    def _compile(self) -> Any:
        """A function ``make(f, b, rest)`` building the result from the sequence of float
        values ``f``, of flag values ``b`` and the dict ``rest``: written out for this layout
        and compiled once, as :mod:`dataclasses` writes ``__init__`` (a dict display with
        constant keys per object is the cheapest way to fill its fields)."""
        namespace: dict[str, Any] = {"_new": _new, "_set": object.__setattr__}
        lines: list[str] = []
        at = [0, 0]  # next float, next flag

        def emit(layout: Layout) -> str:
            var = f"o{len(namespace)}"
            namespace[f"K{var}"] = layout.kind
            items = []
            for name in layout.floats:
                items.append(f"{name!r}: f[{at[0]}]")
                at[0] += 1
            for name, sub in layout.nested:
                items.append(f"{name!r}: {emit(sub)}")
            for name in layout.flags:
                items.append(f"{name!r}: b[{at[1]}]")
                at[1] += 1
            items += [f"{name!r}: rest[{name!r}]" for name in (*layout.given, *layout.text)]
            lines.append(f"    {var} = _new(K{var})")
            lines.append(f"    _set({var}, '__dict__', {{{', '.join(items)}}})")
            return var

        top = emit(self)
        source = "def make(f, b, rest):\n" + "\n".join(lines) + f"\n    return {top}\n"
        exec(compile(source, f"<layout of {self.kind.__name__}>", "exec"), namespace)
        return namespace["make"]

    def _texts(self) -> list[tuple[str, np.ndarray, dict[str, int]]]:
        """Every text field of the tree: ``(name, table of its names, name -> row)``."""
        out = [(name, table, codes) for name, (table, codes) in self.text.items()]
        for _, sub in self.nested:
            out += sub._texts()
        return out

    def scalars(self, floats: tuple, flags: tuple, rest: dict[str, Any]) -> Any:
        """The result of one impact: each float a ``numpy.float64``, each flag a
        ``numpy.bool_``, each text a ``str`` (``rest`` holds the texts and the given
        fields by name)."""
        return self._make(list(map(_FLOAT, floats)), list(map(_flag, flags)), rest)

    def arrays(self, floats: tuple, flags: tuple, rest: dict[str, Any],
               shape: tuple[int, ...]) -> Any:  # fmt: skip
        """The same result with every field a read-only array of ``shape`` (all lengths 1),
        of the dtype the array path gives; ``rest`` is changed in place."""
        values = np.array(floats, dtype=_FLOAT)
        values.shape = (len(floats), *shape)
        values.setflags(write=False)  # and so every row of it
        for name, table, codes in self._all_texts:
            rest[name] = _row(table, codes[rest[name]], shape)
        return self._make(list(values), [_row(_BITS, 1 if x else 0, shape) for x in flags], rest)

    def result(self, floats: tuple, flags: tuple, rest: dict[str, Any],
               shape: tuple[int, ...] | None) -> Any:  # fmt: skip
        """:meth:`scalars` for ``shape`` ``None``, else :meth:`arrays`."""
        if shape is None:
            return self.scalars(floats, flags, rest)
        return self.arrays(floats, flags, rest, shape)


def _table(values: Any, dtype: Any = None) -> np.ndarray:
    """``values`` as an array that can never be written: its memory is a ``bytes`` object,
    so views of it can be handed out in results."""
    a = np.asarray(values, dtype=dtype)
    return np.frombuffer(a.tobytes(), dtype=a.dtype)


def _row(table: np.ndarray, i: int, shape: tuple[int, ...]) -> np.ndarray:
    """Element ``i`` of ``table`` as a read-only view of ``shape`` (all lengths 1)."""
    a = table[i : i + 1]
    return a if shape == (1,) else a.reshape(shape)


#: The values of a flag, indexed by the flag: a one-element flag is a view of a row.
_BITS = _table([False, True])
_LAYOUTS: dict[tuple, Layout] = {}


def layout_for(make: Any, *kinds: type) -> Layout:
    """``make(*kinds)``, made once (the result classes are passed in by the solvers, so a
    layout is made on the first call that needs it)."""
    layout = _LAYOUTS.get((make, *kinds))
    if layout is None:
        layout = _LAYOUTS[(make, *kinds)] = make(*kinds)
    return layout
