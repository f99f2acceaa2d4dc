"""The edge's guard: argument types that refuse impossible values, and the check of every output path
before a command does any work.

Every command lists its inputs (the files it reads, including those a scenario refers to) and its
outputs (files, figures, folders) and calls :func:`check_outputs` before loading or computing
anything heavy. An output is refused, with one line naming its flag and what would be valid, when it
is a folder where a file is meant (or a file where a folder is meant), its folder does not exist or
cannot be written, a figure's suffix is not a format matplotlib writes, it is the same file as an
input (resolved paths and ``os.path.samefile``), or it is the same file as another output.
"""

from __future__ import annotations

import argparse
import math
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Sequence

from boatland.errors import BoatlandInputError

__all__ = ["Output", "check_outputs", "same_file", "finite", "positive", "in_range", "integer", "seed",
           "figure_formats", "OneLineParser", "SEED_MAX", "no_subcommand"]

#: Seeds are stored as signed 64-bit integers (campaign store, run logs).
SEED_MAX = 2 ** 63 - 1


class OneLineParser(argparse.ArgumentParser):
    """An argument parser whose errors are one line (``boatland CMD: error: ...``) and exit status 2."""

    def error(self, message: str):  # noqa: D401 - argparse's API
        self.exit(2, f"{self.prog}: error: {message} (see '{self.prog} --help')\n")


def no_subcommand(parser):
    """The ``func`` of a command group called without its sub-command: usage on stderr, exit status 2."""
    def func(args) -> int:
        import sys

        parser.print_usage(sys.stderr)
        print(f"{parser.prog}: error: a command is needed (see '{parser.prog} --help')", file=sys.stderr)
        return 2
    return func


# ------------------------------------------------------------------------------------ argument types
def finite(text: str) -> float:
    """A finite float (``nan`` and ``inf`` are refused)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text} is not a finite number")
    return value


def in_range(lo: float | None = None, hi: float | None = None, *, lo_open: bool = True, hi_open: bool = False,
             unit: str = ""):
    """Argument type: a finite float in (lo, hi] (bounds and openness configurable)."""
    def parse(text: str) -> float:
        value = finite(text)
        bad_lo = lo is not None and (value <= lo if lo_open else value < lo)
        bad_hi = hi is not None and (value >= hi if hi_open else value > hi)
        if bad_lo or bad_hi:
            left = "(" if lo_open else "["
            right = ")" if hi_open or hi is None else "]"
            raise argparse.ArgumentTypeError(
                f"{text}{unit}: must lie in {left}{'-∞' if lo is None else f'{lo:g}'}, "
                f"{'∞' if hi is None else f'{hi:g}'}{right}")
        return value
    parse.__name__ = "number"
    return parse


def positive(unit: str = "", hi: float | None = None):
    """Argument type: a finite float > 0 (and ≤ ``hi``)."""
    return in_range(0.0, hi, unit=f" {unit}" if unit else "")


def integer(lo: int | None = None, hi: int | None = None):
    """Argument type: an integer in [lo, hi]."""
    def parse(text: str) -> int:
        try:
            value = int(text, 10)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
        if (lo is not None and value < lo) or (hi is not None and value > hi):
            raise argparse.ArgumentTypeError(f"{text}: must lie in {lo if lo is not None else '-∞'} … "
                                             f"{hi if hi is not None else '∞'}")
        return value
    parse.__name__ = "integer"
    return parse


seed = integer(0, SEED_MAX)


def accept_arg(text: str) -> float:
    """Argument type: an accepted probability per access, in (0, 1), or a preset name of Grøtting (2015) Table
    2.1 (:func:`boatland.freqdomain.statistics.accept_probability`)."""
    from boatland.errors import BoatlandInputError
    from boatland.freqdomain.statistics import accept_probability

    try:
        return accept_probability(text)
    except BoatlandInputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


# ------------------------------------------------------------------------------------ outputs
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
    except OSError:
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
    for out in outs:
        _check_one(out)
