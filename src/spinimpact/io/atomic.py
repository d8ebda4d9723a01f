"""File output that never damages an existing file and leaves no temporary behind.

Every output is written under a temporary name beside it and renamed onto it only when
the whole run succeeded (:func:`atomic_path` for a file, :func:`atomic_directory` for a
directory). Inside :func:`atomic_outputs` (the command line wraps every command in it)
the renames wait until the command has finished, its standard output included, so a
run that fails late (a full standard output, a stop) leaves every old output as it was.

A temporary is named ``.NAME.spinimpact-partial-XXXXXXXX`` and holds an advisory lock
(``flock``) as long as its process lives. A run that was killed (SIGKILL, a power cut)
leaves its temporary unlocked; the next run writing into that directory removes it
(:func:`remove_stale`). Outputs are written as ``cp`` would: through a symbolic link
onto its target, never onto a file the user may not write, and keeping an existing
file's permissions (and, where the process may, its owner).
"""

from __future__ import annotations

import contextlib
import os
import shutil
import stat
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

from . import _stop

try:
    import fcntl
except ImportError:  # pragma: no cover (Windows: no flock; stale temporaries stay)
    fcntl = None  # type: ignore[assignment]

__all__ = [
    "TEMPORARY_TAG",
    "atomic_directory",
    "atomic_outputs",
    "atomic_path",
    "current_umask",
    "remove_stale",
]

#: Part of every temporary's name: ``.NAME.spinimpact-partial-XXXXXXXX``.
TEMPORARY_TAG = "spinimpact-partial"
_NEWBORN = "spinimpact-new"  # the name before the lock is taken (a stale one is removed late)
_NEWBORN_AGE = 60.0  # seconds after which an unlocked newborn temporary is stale
_transactions: list[list[_Temporary]] = []
#: Every temporary of this process not yet renamed into place or removed.
_live: set[_Temporary] = set()


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


def _locked(fd: int) -> bool:
    """Take the lock on ``fd``; False if another process holds it."""
    if fcntl is None:
        return True
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        return False
    return True


def remove_stale(directory: str | os.PathLike[str]) -> list[str]:
    """Remove the temporaries that killed runs left in ``directory``.

    A temporary is stale when no process holds its lock: its run ended without
    renaming or removing it (SIGKILL, a power cut). Temporaries of running processes
    keep their locks and are left alone, as is everything not named as a temporary.

    Parameters
    ----------
    directory : str or os.PathLike
        Where to look (not recursively).

    Returns
    -------
    list of str
        The names removed.
    """
    removed: list[str] = []
    if fcntl is None:
        return removed
    try:
        entries = list(os.scandir(directory))
    except OSError:
        return removed
    for entry in entries:
        name = entry.name
        if not name.startswith("."):
            continue
        if f".{_NEWBORN}-" in name:
            try:
                if time.time() - entry.stat(follow_symlinks=False).st_mtime < _NEWBORN_AGE:
                    continue
            except OSError:
                continue
        elif f".{TEMPORARY_TAG}-" not in name:
            continue
        try:
            fd = os.open(entry.path, os.O_RDONLY | os.O_NOFOLLOW)
        except OSError:  # a link, gone meanwhile, or not ours to read
            continue
        try:
            if not _locked(fd):
                continue  # its run is alive
            if stat.S_ISDIR(os.fstat(fd).st_mode):
                shutil.rmtree(entry.path, ignore_errors=True)
            else:
                with contextlib.suppress(FileNotFoundError):
                    os.unlink(entry.path)
            removed.append(name)
        except OSError:
            continue
        finally:
            os.close(fd)
    return removed


class _Temporary:
    """A locked temporary file or directory beside ``target``, inside a critical section."""

    def __init__(self, target: Path, directory: bool) -> None:
        self.target, self.directory = target, directory
        parent = target.parent
        remove_stale(parent)
        prefix = f".{target.name[:120]}.{_NEWBORN}-"
        self.fd, born = -1, ""
        _stop.enter()
        try:
            try:
                if directory:
                    born = tempfile.mkdtemp(prefix=prefix, dir=parent)
                    self.fd = os.open(born, os.O_RDONLY)
                else:
                    self.fd, born = tempfile.mkstemp(prefix=prefix, dir=parent)
            except PermissionError:
                raise PermissionError(
                    13, "Permission denied (cannot create a temporary file there)", str(parent)
                ) from None
            _locked(self.fd)
            name = Path(born).name.replace(f".{_NEWBORN}-", f".{TEMPORARY_TAG}-", 1)
            self.path = Path(born).with_name(name)
            os.rename(born, self.path)
            _live.add(self)
        except BaseException:
            if born and directory:
                shutil.rmtree(born, ignore_errors=True)
            elif born:
                Path(born).unlink(missing_ok=True)
            if self.fd >= 0:
                os.close(self.fd)
            _stop.leave()
            raise

    def commit(self) -> None:
        """Rename onto the target (the lock is released after, so no cleaner sees it free)."""
        os.replace(self.path, self.target)
        self._release()

    def discard(self) -> None:
        """Remove the temporary, whatever happened to it."""
        if self.directory:
            shutil.rmtree(self.path, ignore_errors=True)
        else:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(self.path)
        self._release()

    def _release(self) -> None:
        _live.discard(self)
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1
            _stop.leave()


def discard_all() -> None:
    """Remove every temporary of this process still alive: for a process that ends at once,
    without the interpreter's shutdown, after a failure (every old output stays as it
    was)."""
    for temporary in list(_live):
        with contextlib.suppress(OSError):
            temporary.discard()


def _hand_over(temporary: _Temporary) -> None:
    """Rename now, or at the end of the enclosing :func:`atomic_outputs`."""
    if _transactions:
        _transactions[-1].append(temporary)
    else:
        _stop.check()
        temporary.commit()


@contextlib.contextmanager
def atomic_outputs() -> Iterator[None]:
    """Outputs written inside this block are renamed into place when it ends without error.

    :func:`atomic_path` and :func:`atomic_directory` inside the block keep their
    temporaries until the block ends; then, if no exception and no stop
    (:mod:`spinimpact.io._stop`) came, they are renamed onto their targets one after
    the other; otherwise all are removed and every old output stays as it was. The
    command line runs each command inside it, so a command that fails after writing
    (its standard output full, say) changes no file. When the outermost block has
    renamed them all, a signal no longer stops the run but ends the process with
    128 + its number (:func:`spinimpact.io._stop.finished`).

    Raises
    ------
    spinimpact.io._stop.Stopped
        If a stop was asked during the block (the outputs are not renamed).
    """
    pending: list[_Temporary] = []
    _transactions.append(pending)
    try:
        yield
        _stop.check()
        with _stop.critical():  # a signal while renaming is recorded, then acted on
            while pending:
                pending[0].commit()
                pending.pop(0)
            if len(_transactions) == 1:  # the outermost block: the run's outputs are in place
                _stop.finished()
    finally:
        _transactions.pop()
        for temporary in pending:
            temporary.discard()


def _target(target: str | os.PathLike[str]) -> tuple[Path, Path]:
    """``target`` as given (for messages) and the path to write: links followed."""
    given = Path(target)
    if str(given) == "":
        raise ValueError("the output file name is empty")
    return given, Path(os.path.realpath(given))


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary path beside ``target``, renamed onto it only if the block succeeds.

    Written as ``cp`` would write: a symbolic link is followed and its target
    replaced (the link stays a link); an existing file the process may not write is
    refused; an existing file keeps its permissions (and owner, where the process may
    change it); a new one gets an ordinary file's (``0o666 & ~umask``). The data are
    flushed to disk before the rename. A target that exists but is not a regular file
    (``/dev/null``, a named pipe, a link to one) is written directly: renaming onto it
    would replace the device. Inside :func:`atomic_outputs` the rename waits for the
    end of that block.

    Parameters
    ----------
    target : str or os.PathLike
        The file to write.

    Yields
    ------
    pathlib.Path
        Where to write: a hidden ``.NAME.spinimpact-partial-XXXXXXXX`` file in the
        directory of the (link-resolved) target, deleted if the block raises or is
        stopped, and removed by a later run if the process is killed.

    Raises
    ------
    ValueError
        If ``target`` is the empty string.
    IsADirectoryError
        If ``target`` is a directory.
    FileNotFoundError
        If the directory of ``target`` does not exist.
    PermissionError
        If ``target`` exists and may not be written, or its directory does not let a
        temporary file be created.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> with atomic_path(out) as tmp:
    ...     _ = tmp.write_text("done")
    >>> out.read_text()
    'done'
    """
    given, real = _target(target)
    try:
        existing: os.stat_result | None = real.stat()
    except FileNotFoundError:
        existing = None
    if existing is not None and not stat.S_ISREG(existing.st_mode):
        if stat.S_ISDIR(existing.st_mode):
            raise IsADirectoryError(21, "Is a directory", str(given))
        if not os.access(real, os.W_OK):
            raise PermissionError(13, "Permission denied", str(given))
        yield real  # a device or pipe: nothing to protect, nothing to rename
        return
    if not real.parent.is_dir():
        raise FileNotFoundError(2, "No such directory", str(real.parent))
    if existing is not None and not os.access(real, os.W_OK):
        raise PermissionError(13, "Permission denied", str(given))
    temporary = _Temporary(real, directory=False)
    try:
        yield temporary.path
        fd = os.open(temporary.path, os.O_RDONLY)
        try:
            os.fsync(fd)  # the data is on disk before the name points at it
        finally:
            os.close(fd)
        if existing is None:
            os.chmod(temporary.path, 0o666 & ~current_umask())
        else:
            with contextlib.suppress(PermissionError):  # cp keeps the owner where it may
                os.chown(temporary.path, existing.st_uid, existing.st_gid)
            os.chmod(temporary.path, stat.S_IMODE(existing.st_mode))
        _hand_over(temporary)
        temporary = None
    finally:
        if temporary is not None:
            temporary.discard()


@contextlib.contextmanager
def atomic_directory(target: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary directory beside ``target``, renamed to it only if the block succeeds.

    Like :func:`atomic_path`, for an output that is a new directory: its temporary
    is locked and named ``.NAME.spinimpact-partial-XXXXXXXX``; on success it and the
    files in it get an ordinary new directory's and files' permissions.

    Parameters
    ----------
    target : str or os.PathLike
        The directory to create.

    Yields
    ------
    pathlib.Path
        The temporary directory to fill.

    Raises
    ------
    FileExistsError
        If ``target`` exists.
    FileNotFoundError
        If the directory of ``target`` does not exist.
    """
    given, real = _target(target)
    if os.path.lexists(given):
        raise FileExistsError(17, "File exists", str(given))
    if not real.parent.is_dir():
        raise FileNotFoundError(2, "No such directory", str(real.parent))
    temporary = _Temporary(real, directory=True)
    try:
        yield temporary.path
        umask = current_umask()
        for child in temporary.path.iterdir():
            os.chmod(child, 0o666 & ~umask)
        os.chmod(temporary.path, 0o777 & ~umask)
        _hand_over(temporary)
        temporary = None
    finally:
        if temporary is not None:
            temporary.discard()
