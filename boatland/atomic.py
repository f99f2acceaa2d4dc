"""Write files so that nothing half-written is ever left behind (temp file in the same folder + fsync +
rename + fsync of the folder), and clear what an interrupted write left."""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import Iterator

__all__ = ["atomic_path", "fsync_path", "stale_parts", "remove_stale_parts"]


def fsync_path(path: str | os.PathLike) -> None:
    """Flush a file's (or a folder's) data to the disk."""
    flags = os.O_RDONLY | (os.O_DIRECTORY if Path(path).is_dir() and hasattr(os, "O_DIRECTORY") else 0)
    try:
        fd = os.open(path, flags)
    except OSError:
        return                        # a folder that cannot be opened (other platforms): nothing to do
    try:
        os.fsync(fd)
    except OSError:
        if not Path(path).is_dir():   # some filesystems refuse fsync on folders; a file's must succeed
            raise
    finally:
        os.close(fd)


def stale_parts(target: str | os.PathLike) -> list[Path]:
    """Temporary files an interrupted :func:`atomic_path` of ``target`` left beside it."""
    target = Path(target)
    if not target.parent.is_dir():
        return []
    return sorted(target.parent.glob(f".{target.name}.*.part"))


def remove_stale_parts(target: str | os.PathLike) -> list[Path]:
    """Delete the leftovers of interrupted writes of ``target``; only call it where no other process can
    be writing ``target`` (e.g. under the campaign store's lock). Returns what was removed."""
    removed = []
    for p in stale_parts(target):
        try:
            p.unlink()
            removed.append(p)
        except FileNotFoundError:
            pass
    return removed


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path next to ``target``; rename it onto ``target`` only on success.

    The temporary file is flushed to the disk before the rename and the folder after it, so a crash
    (power loss included) leaves either the old ``target`` or the complete new one. On any exception
    the temporary file is removed and ``target`` is left as it was. The file gets the permissions a
    plain ``open(target, "w")`` would give (mkstemp's are private).
    """
    target = Path(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=target.parent)
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        yield tmp_path
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp_path, 0o666 & ~umask)
        fsync_path(tmp_path)
        os.replace(tmp_path, target)
        fsync_path(target.parent)
    finally:
        if tmp_path.exists():
            tmp_path.unlink()
