"""Reading input files safely: regular files only, of a size proportionate to what they hold.

A FIFO, a device (``/dev/zero``, ``/dev/urandom``), a socket or a folder given where a file is meant would
block a reader or feed it forever; every reader of boatland opens its input through :func:`open_input` (or
reads it whole with :func:`read_input`), which refuses them in one line naming the file, before reading a
byte. The descriptor is opened non-blocking (opening a FIFO cannot hang) and checked with ``fstat``, so what
was checked is what is read. Each kind of input has a size limit (:data:`LIMITS`, an assumption: generous
for real files of that format, far below what would exhaust memory); a larger file is refused as not
being one.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path
from typing import BinaryIO

from boatland.errors import BoatlandInputError

__all__ = ["LIMITS", "HDF5_DAMAGE", "damage_text", "file_kind", "open_input", "read_input", "check_input", "read_text_input", "open_hdf5"]

_MiB = 1 << 20
#: Largest file [bytes] accepted per kind of input. Assumptions, not measurements of any standard: a
#: scenario or campaign (TOML) is a few kB; a hand-written or exported table (CSV, BEM text output) some MB;
#: an HDF5/NetCDF database or store and a run log (MCAP) may hold long series (GB).
LIMITS = {"toml": 16 * _MiB, "text": 512 * _MiB, "hdf5": 64 * 1024 * _MiB, "mcap": 64 * 1024 * _MiB}

_KINDS = ((stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"), (stat.S_ISDIR, "a folder"))


def file_kind(mode: int) -> str:
    """What a file that is not a regular one is, from its ``st_mode``: "a FIFO (named pipe)", "a character
    device", …, "a folder"."""
    return next((name for test, name in _KINDS if test(mode)), "not a regular file")


def open_input(path: str | os.PathLike, what: str, kind: str) -> BinaryIO:
    """Open the input ``path`` for reading (binary), after checking it is a regular file of at most
    ``LIMITS[kind]`` bytes.

    Parameters
    ----------
    path : path
    what : str
        What the file should be ("scenario file", "run log"), for messages.
    kind : str
        A key of :data:`LIMITS`.

    Raises
    ------
    BoatlandInputError
        Missing, unreadable, not a regular file, or larger than the limit — one line naming the file.
    """
    path = Path(path)
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        raise BoatlandInputError(f"{path}: no such file (the {what})") from None
    except IsADirectoryError:
        raise BoatlandInputError(f"{path}: a folder, not the {what}") from None
    except OSError as exc:
        raise BoatlandInputError(f"{path}: cannot read the {what} ({exc.strerror or exc})") from None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise BoatlandInputError(f"{path}: {file_kind(st.st_mode)}, not the {what}; give a regular file")
        limit = LIMITS[kind]
        if st.st_size > limit:
            raise BoatlandInputError(f"{path}: {st.st_size / _MiB:,.0f} MiB, more than a {what} can be "
                                     f"({limit / _MiB:,.0f} MiB); is it the right file?")
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise


def check_input(path: str | os.PathLike, what: str, kind: str) -> None:
    """:func:`open_input` and close: for readers that a library opens by name (h5py, netCDF) — they are then
    at least never handed a FIFO or a device."""
    open_input(path, what, kind).close()


def read_input(path: str | os.PathLike, what: str, kind: str) -> bytes:
    """The bytes of the input ``path`` (:func:`open_input`; read once, at most the limit even if the file
    grows while it is read)."""
    parts, size = [], 0
    with open_input(path, what, kind) as fh:
        while size <= LIMITS[kind]:
            part = fh.read(16 * _MiB)
            if not part:
                break
            parts.append(part)
            size += len(part)
    data = b"".join(parts)
    if len(data) > LIMITS[kind]:
        raise BoatlandInputError(f"{path}: grew past {LIMITS[kind] / _MiB:,.0f} MiB while read; not a {what}")
    return data


def read_text_input(path: str | os.PathLike, what: str, kind: str = "text", encoding: str = "utf-8") -> str:
    """The text of the input ``path`` (:func:`read_input`).

    Raises
    ------
    BoatlandInputError
        As :func:`read_input`, or not text in ``encoding`` (naming the first bad byte).
    """
    data = read_input(path, what, kind)
    try:
        return data.decode(encoding)
    except UnicodeDecodeError as exc:
        raise BoatlandInputError(f"{path}: not a text file (byte {exc.start} is not {encoding.upper()}); "
                                 f"expected the {what}") from None


#: What h5py (and the readers on it) raise meeting damage inside a file it could open — caught after
#: :class:`BoatlandInputError` (itself a ``ValueError``), which is re-raised as it is.
HDF5_DAMAGE = (OSError, KeyError, ValueError, TypeError, IndexError, RuntimeError, OverflowError)


def damage_text(exc: BaseException) -> str:
    """One line for an error met inside a damaged file: its type and the first line of its message."""
    return f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}"


def open_hdf5(path: str | os.PathLike, what: str):
    """An HDF5 input opened from its bytes, read once (:func:`read_input`), as an ``h5py.File`` (read only).

    A file boatland wrote ends with the SHA-256 of its contents (:func:`boatland.atomic.hdf5_trailer`): it is
    checked first, so that a damaged file (a flipped byte) is refused in one line before the HDF5 library —
    which a damaged file can crash — parses it. A truncated file has lost its trailer, and HDF5 itself refuses
    a file shorter than its end address; other HDF5 files (written elsewhere, or edited in place by another
    tool, which drops the trailer) are opened as they are.

    Raises
    ------
    BoatlandInputError
        As :func:`read_input`; the checksum does not match; not an HDF5 file.
    """
    import hashlib
    import io

    import h5py

    from boatland.atomic import CHECKSUM_MAGIC, TRAILER

    data = read_input(path, what, "hdf5")
    tail = data[-TRAILER:]
    if len(data) > TRAILER and tail.startswith(CHECKSUM_MAGIC):
        if hashlib.sha256(memoryview(data)[:-TRAILER]).hexdigest().encode() != tail[len(CHECKSUM_MAGIC):-1]:
            raise BoatlandInputError(f"{path}: damaged — its contents do not match the checksum boatland wrote with "
                                     f"it (changed since, not by a tool that rewrote it); not a usable {what}")
    try:
        return h5py.File(io.BytesIO(data), "r")
    except OSError as exc:
        raise BoatlandInputError(f"{path}: not a readable HDF5 file ({str(exc).splitlines()[0]}); expected the "
                                 f"{what}") from None
