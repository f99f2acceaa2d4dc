"""What a command writes, checked before the work (:func:`check_outputs`).

Every command lists its inputs (the files it reads, including those a scenario refers to) and its
outputs (files, figures, folders) and calls :func:`check_outputs` before loading or computing
anything heavy. An output is refused, with one line naming its flag and what would be valid, when it
is a folder where a file is meant (or a file where a folder is meant), a symbolic link (writing would change
the file it points to), a FIFO, device or socket (which it would replace), its folder does not exist or
cannot be written, a figure's suffix is not a format matplotlib writes, it is the same file as an
input (resolved paths and ``os.path.samefile``), or it is the same file as another output.

Writing itself is :mod:`boatland.atomic`'s (temp file + rename: nothing half-written)."""

from __future__ import annotations

import os
import stat
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Sequence

from boatland.errors import BoatlandInputError
from boatland.inputs import file_kind

__all__ = ["Output", "check_outputs", "figure_formats", "same_file"]


@dataclass(frozen=True)
class Output:
    """One output of a command: its flag (for messages), path and kind.

    ``kind``: ``"file"`` (replaced if it exists), ``"figure"`` (a file whose suffix names a matplotlib
    format), ``"folder"`` (created if missing; ``contents`` are the names written into it).
    """

    flag: str
    path: Path | None
    kind: str = "file"
    contents: tuple[str, ...] = ()


def figure_formats() -> set[str]:
    """File suffixes (without the dot) matplotlib can write."""
    from matplotlib.backend_bases import FigureCanvasBase

    return set(FigureCanvasBase.get_supported_filetypes())


def same_file(a: Path, b: Path) -> bool:
    """``a`` and ``b`` name the same file: equal resolved paths, or ``os.path.samefile`` when both exist
    (hard links, bind mounts)."""
    try:
        if Path(a).resolve() == Path(b).resolve():
            return True
        return Path(a).exists() and Path(b).exists() and os.path.samefile(a, b)
    except (OSError, RuntimeError):      # RuntimeError: a symlink loop (pathlib's resolve)
        return False


def _probe(folder: Path) -> str | None:
    """None if a file can be created in ``folder``, else the reason."""
    try:
        fd, name = tempfile.mkstemp(prefix=".boatland-probe-", dir=folder)
    except OSError as exc:
        return exc.strerror or str(exc)
    os.close(fd)
    os.unlink(name)
    return None


def _existing_ancestor(path: Path) -> Path:
    p = path.resolve()
    while not p.exists() and p != p.parent:
        p = p.parent
    return p


def _check_one(out: Output) -> None:
    p, flag = Path(out.path), out.flag
    if out.kind == "folder":
        if p.exists() and not p.is_dir():
            raise BoatlandInputError(f"{flag} {p}: is a file, not a folder; give a folder name")
        where = p if p.is_dir() else _existing_ancestor(p)
        if not where.is_dir():
            raise BoatlandInputError(f"{flag} {p}: {where} is a file, not a folder")
        why = _probe(where)
        if why:
            raise BoatlandInputError(f"{flag} {p}: cannot write in {where} ({why})")
        return
    if p.is_dir():
        raise BoatlandInputError(f"{flag} {p}: is a folder; give a file name")
    if p.exists() and not stat.S_ISREG(p.stat().st_mode):
        raise BoatlandInputError(f"{flag} {p}: is {file_kind(p.stat().st_mode)}, which an output would replace; "
                                 "give a file name")
    if not p.name or p.name in (".", ".."):
        raise BoatlandInputError(f"{flag} {p}: not a file name")
    if out.kind == "figure":
        fmt = p.suffix[1:].lower()
        known = figure_formats()
        if fmt not in known:
            raise BoatlandInputError(f"{flag} {p}: unknown figure format {p.suffix or '(no suffix)'!r}; use one of "
                                     + ", ".join(f".{f}" for f in sorted(known)))
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        anc = next((a for a in parent.parents if a.exists()), None) if not parent.exists() else parent
        if anc is not None and anc.exists() and not anc.is_dir():
            raise BoatlandInputError(f"{flag} {p}: {anc} is a file, not a folder")
        raise BoatlandInputError(f"{flag} {p}: the folder {parent} does not exist")
    why = _probe(parent)
    if why:
        raise BoatlandInputError(f"{flag} {p}: cannot write in {parent} ({why})")
    if p.exists() and not os.access(p, os.W_OK):
        raise BoatlandInputError(f"{flag} {p}: the file exists and is not writable")


def _files_of(out: Output) -> list[Path]:
    """The files an output stands for (a folder: the files it writes into it)."""
    if out.kind == "folder":
        return [Path(out.path) / name for name in out.contents]
    return [Path(out.path)]


def check_outputs(outputs: Sequence[Output], inputs: Iterable[Path | str | None] = ()) -> None:
    """Refuse, before any work, outputs that cannot be written or would destroy an input.

    Parameters
    ----------
    outputs : sequence of Output
        What the command will write (entries with ``path=None`` are skipped).
    inputs : iterable of path
        Every file (or folder) the command reads. A folder input protects every file under it.

    Raises
    ------
    BoatlandInputError
        One line naming the flag, the path and what would be valid.
    """
    outs = [o for o in outputs if o.path is not None]
    ins = [Path(i) for i in inputs if i is not None and str(i) != ""]
    for out in outs:                     # a link is never written through (nor resolved: it may loop)
        for f in _files_of(out):
            if f.is_symlink():
                raise BoatlandInputError(f"{out.flag} {f}: is a symbolic link (to {os.readlink(f)}); boatland "
                                         "writes only files it names itself — give the target's own path or "
                                         "another name")
    for out in outs:
        for f in _files_of(out) + ([Path(out.path)] if out.kind == "folder" else []):
            for i in ins:
                if same_file(f, i):
                    raise BoatlandInputError(f"{out.flag} {out.path}: is the input {i}; an output never replaces "
                                             "an input — give another name")
                if i.is_dir() and f.exists() and f.resolve().is_relative_to(i.resolve()) and out.kind != "folder":
                    raise BoatlandInputError(f"{out.flag} {out.path}: is a file of the input folder {i}; give "
                                             "a name outside it")
    for k, a in enumerate(outs):
        for b in outs[k + 1:]:
            for fa in _files_of(a):
                for fb in _files_of(b):
                    if same_file(fa, fb):
                        raise BoatlandInputError(f"{a.flag} {a.path} and {b.flag} {b.path} are the same file "
                                                 f"({fa}); give them different names")
    for out in outs:          # (symbolic links refused above)
        _check_one(out)
