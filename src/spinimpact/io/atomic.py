"""File output that never leaves a half-written file behind."""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path

__all__ = ["atomic_path", "current_umask"]


def current_umask() -> int:
    """The process's file-creation mask, read without changing it.

    Files written under a temporary name are created with mode ``0o600``; they get
    the mode an ordinary new file would have (``0o666 & ~umask``) before the rename.

    Returns
    -------
    int
        The mask, e.g. ``0o022``.
    """
    mask = os.umask(0)
    os.umask(mask)
    return mask


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary path beside ``target``, renamed onto it only if the block succeeds.

    An existing ``target`` is never half-overwritten and keeps its permissions; a
    new one gets an ordinary file's (``0o666 & ~umask``). The data are flushed to
    disk before the rename. A target that exists but is not a regular file
    (``/dev/null``, a named pipe) is written directly: renaming onto it would
    replace the device.

    Parameters
    ----------
    target : str or os.PathLike
        The file to write.

    Yields
    ------
    pathlib.Path
        Where to write: a hidden ``.NAME.*.part`` file in the target's directory,
        deleted if the block raises (or is interrupted).

    Raises
    ------
    ValueError
        If ``target`` is the empty string.
    IsADirectoryError
        If ``target`` is a directory.
    FileNotFoundError
        If the directory of ``target`` does not exist.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> with atomic_path(out) as tmp:
    ...     _ = tmp.write_text("done")
    >>> out.read_text()
    'done'
    """
    target = Path(target)
    if str(target) == "":
        raise ValueError("the output file name is empty")
    if target.exists() and not target.is_file():
        if target.is_dir():
            raise IsADirectoryError(21, "Is a directory", str(target))
        yield target  # a device or pipe: nothing to protect, nothing to rename
        return
    parent = target.parent
    if not parent.is_dir():
        raise FileNotFoundError(2, "No such directory", str(parent))
    mode = stat.S_IMODE(target.stat().st_mode) if target.exists() else 0o666 & ~current_umask()
    fd, name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=parent)
    os.close(fd)
    tmp = Path(name)
    try:
        yield tmp
        fd = os.open(tmp, os.O_RDONLY)
        try:
            os.fsync(fd)  # the data is on disk before the name points at it
        finally:
            os.close(fd)
        os.chmod(tmp, mode)
        os.replace(tmp, target)
    finally:
        tmp.unlink(missing_ok=True)
