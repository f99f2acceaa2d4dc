"""Results that take seconds to make and depend only on their inputs, kept on disk between runs.

A campaign's start used to spend ~3 s before its first trial making what the previous run had made
already: the radiation memory (IRFs and the state-space fit, 2.2 s for ctv27) and the tables of the pile's
scattered wave (0.9 s). Both are pure functions of their inputs, so they are kept here, one HDF5 file per
entry, named by a digest of everything the result depends on:

- the inputs' **content** (the arrays' bytes, the settings), never a file name or a time;
- the **code** that makes them — the source of each module named by the caller — so that editing the
  method makes a new entry rather than serving an old result;
- the **machine's arithmetic**: numpy's and scipy's versions, the CPU architecture and the SIMD features
  numpy dispatches on (LAPACK and numpy's kernels may round differently elsewhere; results must be the
  bits this machine would compute).

The entry holds its own key, checked on reading. Entries are written to a temporary file and renamed
(:func:`boatland.atomic.atomic_path`): concurrent campaigns making the same entry both write whole files
and one wins; a reader never sees half a file. Anything unreadable — a damaged or foreign file, a
symlink, a FIFO, a file larger than :data:`MAX_ENTRY_BYTES` — is a miss: the result is computed again and
the entry rewritten. The folder is kept below :data:`MAX_BYTES` (least recently used entries go first).

Where: ``$BOATLAND_CACHE_DIR``, else ``$XDG_CACHE_HOME/boatland``, else ``~/.cache/boatland``; the
variable set to an empty string, ``off`` or ``none`` turns the cache off. A folder that cannot be written
turns it off silently (it only saves time).
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import json
import os
import platform
import stat
from pathlib import Path
from typing import Callable, Iterable, TypeVar

import numpy as np

from boatland.atomic import atomic_hdf5

__all__ = ["cache_dir", "cache_key", "cached", "lookup", "store", "MAX_BYTES", "MAX_ENTRY_BYTES", "ENV"]

#: Environment variable naming the cache folder ("", "off" or "none": no cache).
ENV = "BOATLAND_CACHE_DIR"
#: Size of the folder above which the least recently used entries are removed [bytes].
MAX_BYTES = 512 * 2 ** 20
#: A file larger than this is not an entry of this cache (the largest, a radiation memory, is ~2 MB).
MAX_ENTRY_BYTES = 64 * 2 ** 20
#: Version of the entries' layout (a change makes new names).
FORMAT = 1

T = TypeVar("T")


def cache_dir() -> Path | None:
    """The cache folder (created), or None when the cache is off or the folder cannot be made."""
    raw = os.environ.get(ENV)
    if raw is not None and raw.strip().lower() in ("", "off", "none"):
        return None
    if raw:
        path = Path(raw).expanduser()
    else:
        base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        path = Path(base) / "boatland"
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError:
        return None
    return path if os.access(path, os.W_OK | os.X_OK) else None


@functools.lru_cache(maxsize=None)
def _machine() -> str:
    """numpy/scipy versions, the architecture and the SIMD features numpy dispatches on."""
    import scipy

    try:
        from numpy._core._multiarray_umath import __cpu_features__ as feats
    except ImportError:                                   # older numpy layouts
        feats = {}
    on = sorted(k for k, v in feats.items() if v)
    return json.dumps([np.__version__, scipy.__version__, platform.machine(), on])


@functools.lru_cache(maxsize=None)
def _source_digest(modules: tuple[str, ...]) -> str:
    h = hashlib.blake2b(digest_size=16)
    for name in modules:
        spec = importlib.util.find_spec(name)
        if spec is None or spec.origin is None:
            raise ValueError(f"no source for module {name!r}")
        h.update(name.encode())
        h.update(Path(spec.origin).read_bytes())
    return h.hexdigest()


def cache_key(kind: str, parts: Iterable, code: Iterable[str]) -> str:
    """Digest naming an entry of ``kind`` made from ``parts`` (arrays by their dtype, shape and bytes;
    anything else by its ``repr``) by the modules ``code`` (their source is hashed)."""
    h = hashlib.blake2b(digest_size=20)
    h.update(f"{FORMAT}|{kind}|{_machine()}|{_source_digest(tuple(code))}".encode())
    for p in parts:
        if isinstance(p, np.ndarray):
            a = np.ascontiguousarray(p)
            h.update(f"|{a.dtype.str}{a.shape}".encode())
            h.update(a.tobytes())
        else:
            h.update(f"|{p!r}".encode())
    return f"{kind}-{h.hexdigest()}"


def _read(path: Path, key: str, read: Callable):
    import h5py

    try:   # no symlink followed, no blocking on a FIFO; what was checked is what is read (the same descriptor)
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
    except OSError:
        return None
    with os.fdopen(fd, "rb") as fh:
        st = os.fstat(fh.fileno())
        if not stat.S_ISREG(st.st_mode) or st.st_size > MAX_ENTRY_BYTES:
            return None                          # a FIFO, device or a foreign giant: not ours
        try:
            with h5py.File(fh, "r") as f:
                if f.attrs.get("boatland_cache_key") != key:
                    return None
                value = read(f)
        except Exception:                        # damaged or foreign: a miss, made again  # noqa: BLE001
            return None
    try:
        os.utime(path)                           # recently used
    except OSError:
        pass
    return value


def _write(folder: Path, path: Path, key: str, write: Callable, value) -> None:

    try:
        with atomic_hdf5(path) as f:
            f.attrs["boatland_cache_key"] = key
            write(f, value)
    except OSError:
        return                                   # a full or read-only disk: no entry, nothing lost
    _prune(folder)


def _prune(folder: Path) -> None:
    entries = []
    for p in folder.glob("*.h5"):
        try:
            st = os.lstat(p)
        except OSError:
            continue
        if stat.S_ISREG(st.st_mode):
            entries.append((st.st_mtime, st.st_size, p))
    total = sum(e[1] for e in entries)
    for _, size, p in sorted(entries):
        if total <= MAX_BYTES:
            break
        try:
            p.unlink()
            total -= size
        except OSError:
            pass


def lookup(key: str, read: Callable):
    """The entry ``key`` read back by ``read(h5file)``, or None (a miss, or no cache)."""
    folder = cache_dir()
    return None if folder is None else _read(folder / f"{key}.h5", key, read)


def store(key: str, value, write: Callable) -> None:
    """Keep ``value`` as the entry ``key``, written by ``write(h5file, value)`` (nothing without a cache or
    when the disk refuses)."""
    folder = cache_dir()
    if folder is not None:
        _write(folder, folder / f"{key}.h5", key, write, value)


def cached(key: str, make: Callable[[], T], write: Callable, read: Callable) -> T:
    """The entry ``key`` (:func:`cache_key`) read back by ``read(h5file)``, or ``make()`` stored by
    ``write(h5file, value)`` and returned. Without a cache folder: ``make()``."""
    value = lookup(key, read)
    if value is None:
        value = make()
        store(key, value, write)
    return value
