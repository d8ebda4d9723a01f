"""Running a sweep's chunks: in order, locally or on a Dask cluster, in bounded memory."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

from .._validation import require

__all__ = ["Discard", "chunks_in_order", "dask_client"]


def chunks_in_order(count: int, work: Callable[[int], Any], client: Any, window: int) -> Iterator:
    """Results of ``work(k)`` for each of ``count`` chunks, in order, locally or on a Dask client
    with at most ``window`` chunks in flight (bounded memory)."""
    if client is None:
        for k in range(count):
            yield work(k)
        return
    pending: dict[int, Any] = {}
    for k in range(count):
        pending[k] = client.submit(work, k, pure=False)
        if len(pending) >= window:
            first = min(pending)
            yield pending.pop(first).result()
    for k in sorted(pending):
        yield pending.pop(k).result()


def dask_client(address: str, *, timeout: float = 30) -> Any:
    """Connect to the Dask scheduler at ``address``, for ``run_sweep(..., client=...)``.

    Parameters
    ----------
    address : str
        The scheduler's address, e.g. ``"tcp://10.0.0.5:8786"``.
    timeout : float
        Seconds to wait for the connection.

    Returns
    -------
    distributed.Client

    Raises
    ------
    ImportError
        Without ``distributed``, naming the ``[dask]`` extra.
    """
    distributed = require("distributed", "sweeps on a Dask cluster")
    return distributed.Client(address, timeout=timeout)


class Discard:
    """The sink of a sweep without output: reductions only."""

    def __enter__(self) -> Discard:
        return self

    def __exit__(self, *exc: object) -> None:
        return None

    def write(self, data: dict) -> None:
        pass
