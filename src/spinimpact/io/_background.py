"""Writing batch rows on a second thread while the next chunk is solved.

pyarrow releases the GIL while it formats and writes a table, so on a machine with two
or more cores the writing of chunk ``k`` (CSV text or Parquet pages) overlaps with the
reading and solving of chunk ``k + 1``. At most one chunk waits to be written, so memory
stays bounded by two chunks. An error of the writer (a full disk) is raised in the
caller's thread at the next :meth:`BackgroundRows.write` or at
:meth:`BackgroundRows.close`; a stop between chunks (:mod:`spinimpact.io._stop`) waits
for the write in progress, then closes the sink as a failed run does, so the atomic
output and its clean-up behave as without the thread.
"""

from __future__ import annotations

import contextlib
from concurrent.futures import Future, ThreadPoolExecutor
from typing import Any

__all__ = ["BackgroundRows"]


class BackgroundRows:
    """A batch sink (``write(chunk, values, results, messages)``, ``close(complete)``)
    whose writes run on one worker thread, one chunk at a time, in order."""

    def __init__(self, sink: Any) -> None:
        self.sink = sink
        self.pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="spinimpact-rows")
        self.pending: Future | None = None

    def _wait(self) -> None:
        pending, self.pending = self.pending, None
        if pending is not None:
            pending.result()  # the writer's exception, if any, is raised here

    def write(self, *rows: Any) -> None:
        """Wait for the previous chunk's write, then start this one's."""
        self._wait()
        self.pending = self.pool.submit(self.sink.write, *rows)

    def close(self, complete: bool = True) -> None:
        """Wait for the last write and close the sink; ``complete=False`` (a run that
        failed or stopped): a writer's error is not raised over the one in flight."""
        try:
            if complete:
                self._wait()
            else:
                with contextlib.suppress(Exception):
                    self._wait()
        except BaseException:
            complete = False  # the last chunk was not written: the sink closes as failed
            raise
        finally:
            self.pool.shutdown(wait=True)
            self.sink.close(complete)
