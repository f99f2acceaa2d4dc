"""Write files so that nothing half-written is ever left behind (temp file in the same folder + fsync +
rename + fsync of the folder), and clear what an interrupted write left."""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import Iterator

__all__ = ["atomic_path", "atomic_hdf5", "fsync_path", "stale_parts", "remove_stale_parts", "CHECKSUM_MAGIC",
           "TRAILER", "hdf5_trailer"]

#: HDF5 files boatland writes end with a trailer after the HDF5 data — this tag, the SHA-256 of everything
#: before the trailer (hex) and a newline — which HDF5, netCDF4, h5netcdf and xarray ignore (bytes past the
#: file's end address): a reader finds damage (a flipped byte) before the HDF5 library parses the file, which
#: a damaged file can crash rather than fail. A tool that edits the file in place truncates it to its end
#: address, dropping the trailer: the edited file is then read as any HDF5 file.
CHECKSUM_MAGIC = b"\nboatland-sha256:"
TRAILER = len(CHECKSUM_MAGIC) + 64 + 1


def hdf5_trailer(image) -> bytes:
    """The trailer of an HDF5 file image: the tag, the SHA-256 of the image (hex), a newline."""
    import hashlib

    return CHECKSUM_MAGIC + hashlib.sha256(image).hexdigest().encode() + b"\n"


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
        try:
            yield tmp_path
        except OSError as exc:        # named by the file the user asked for, not the temporary one
            if exc.errno is not None and exc.filename in (None, str(tmp_path), tmp_path):
                raise OSError(exc.errno, exc.strerror, str(target)) from None
            raise
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp_path, 0o666 & ~umask)
        fsync_path(tmp_path)
        os.replace(tmp_path, target)
        fsync_path(target.parent)
    finally:
        if tmp_path.exists():
            tmp_path.unlink()


@contextlib.contextmanager
def atomic_hdf5(target: str | os.PathLike, mode: str = "w", **file_kwargs):
    """Yield an ``h5py.File`` built in memory, then write it to ``target`` whole (:func:`atomic_path`).

    HDF5 itself never writes to the disk: a full disk or a file-size limit (``ulimit -f``) is then one
    ``OSError`` of the final Python write, with nothing left behind — where HDF5's own I/O failing mid-file
    leaves the library in a state that can crash the process as it exits. ``mode`` ``"w"`` starts empty;
    ``"r+"`` starts from ``target``'s contents (to change an existing file). The whole file is in memory
    while it is made. The file ends with its checksum (:func:`hdf5_trailer`; checked by
    :func:`boatland.inputs.open_hdf5`).
    """
    import io

    import h5py

    target = Path(target)
    if mode not in ("w", "r+"):
        raise ValueError(f"mode must be 'w' or 'r+', got {mode!r}")
    buffer = io.BytesIO()
    if mode == "r+":
        with open(target, "rb") as fh:
            buffer.write(fh.read())
    with h5py.File(buffer, mode, **file_kwargs) as f:
        yield f
    data = buffer.getvalue()
    image = data + hdf5_trailer(data)
    with atomic_path(target) as tmp:
        with open(tmp, "wb") as fh:
            fh.write(image)
