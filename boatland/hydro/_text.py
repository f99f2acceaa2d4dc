"""Small helpers shared by the text-file BEM readers (WAMIT, NEMOH, AQWA) and the Capytaine reader.

Everything here turns a malformed input into a :class:`~boatland.errors.HydroDataError` that names
the file and the line (or dataset), never a bare ``ValueError`` or ``IndexError``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from boatland.errors import BoatlandInputError, HydroDataError
from boatland.inputs import read_input
from boatland.vessel.database import HydroDB

__all__ = ["TextFile", "is_number", "find_sibling", "find_child", "normalise_directions", "build_db"]


def _to_float(token: str) -> float:
    """``float`` that also reads Fortran double-precision exponents (``1.0D+02``)."""
    return float(token.replace("D", "E").replace("d", "e"))


class TextFile:
    """The lines of a text file, with 1-based line numbers for error messages.

    Parameters
    ----------
    path : Path
        The file; a missing file raises :class:`HydroDataError` naming it and ``what`` it should hold.
    what : str
        What the file is (``"WAMIT .1 file (added mass and damping)"``), for messages.
    """

    def __init__(self, path: Path, what: str):
        self.path = Path(path)
        self.what = what
        if not self.path.is_file():
            raise HydroDataError(self.path, None, f"file not found; expected the {what}")
        try:
            raw = read_input(self.path, what, "text")
        except BoatlandInputError as exc:
            raise HydroDataError(self.path, None, str(exc).removeprefix(f"{self.path}: ")) from None
        if b"\x00" in raw[:4096]:
            raise HydroDataError(self.path, None, f"a binary file, not the {what} (a text file)")
        self.lines = raw.decode("utf-8", errors="replace").splitlines()

    def error(self, lineno: int | None, message: str) -> HydroDataError:
        """An error at 1-based line ``lineno`` (None: the whole file)."""
        return HydroDataError(self.path, None if lineno is None else f"line {lineno}", message)

    def numbers(self, lineno: int, tokens: list[str] | None = None, *, what: str = "numbers") -> np.ndarray:
        """Parse the whitespace-separated ``tokens`` of a line (default: the whole line) as finite floats.

        Raises
        ------
        HydroDataError
            A token is not a number, or is NaN/infinite; the message quotes it and says ``what`` was
            expected.
        """
        if tokens is None:
            tokens = self.lines[lineno - 1].split()
        try:
            values = np.array([_to_float(t) for t in tokens], dtype=float)
        except ValueError:
            bad = next(t for t in tokens if not is_number(t))
            raise self.error(lineno, f"expected {what}, found {bad!r:.40}") from None
        if not np.all(np.isfinite(values)):
            bad = tokens[int(np.argmax(~np.isfinite(values)))]
            raise self.error(lineno, f"expected finite {what}, found {bad!r}")
        return values

    def integer(self, lineno: int, token: str, *, what: str, lo: int | None = None,
                hi: int | None = None) -> int:
        """Parse an integer token (``"3"``; ``"3."`` is accepted as Fortran list-directed output)."""
        try:
            value = _to_float(token)
        except ValueError:
            raise self.error(lineno, f"expected {what} (an integer), found {token!r:.40}") from None
        if not np.isfinite(value) or value != int(value):
            raise self.error(lineno, f"expected {what} (an integer), found {token!r:.40}")
        value = int(value)
        if (lo is not None and value < lo) or (hi is not None and value > hi):
            span = f"{lo}..{hi}" if hi is not None else f"≥ {lo}"
            raise self.error(lineno, f"expected {what} in {span}, found {value}")
        return value


def is_number(token: str) -> bool:
    """True when ``token`` reads as a number (Fortran exponents included)."""
    try:
        _to_float(token)
    except ValueError:
        return False
    return True


def find_child(folder: Path, name: str) -> Path | None:
    """``folder / name``, matched case-insensitively (files written on Windows), or None."""
    exact = folder / name
    if exact.exists():
        return exact
    if not folder.is_dir():
        return None
    low = name.lower()
    for child in folder.iterdir():
        if child.name.lower() == low:
            return child
    return None


def find_sibling(path: Path, suffix: str) -> Path | None:
    """The file next to ``path`` with the same stem and ``suffix`` (case-insensitive), or None."""
    return find_child(path.parent, path.stem + suffix)


def normalise_directions(beta_deg, tol: float = 1e-6):
    """Map wave directions to [0, 360), sorted, with duplicates (e.g. −180° and 180°) merged.

    Parameters
    ----------
    beta_deg : array_like, shape (Nb_in,)
        Directions [deg] as the file gives them.
    tol : float
        Two directions closer than this [deg] (modulo 360) are the same.

    Returns
    -------
    unique : ndarray, shape (Nb,)
        Sorted directions in [0, 360).
    keep : ndarray of int, shape (Nb,)
        For each unique direction, the index of the first input direction it came from.
    groups : list of ndarray of int
        For each unique direction, all input indices that map to it (to check duplicates agree).
    """
    beta = np.mod(np.asarray(beta_deg, dtype=float), 360.0)
    beta[np.isclose(beta, 360.0, atol=tol)] = 0.0
    order = np.argsort(beta, kind="stable")
    unique, keep, groups = [], [], []
    for idx in order:
        if unique and abs(beta[idx] - unique[-1]) <= tol:
            groups[-1].append(int(idx))
            continue
        unique.append(float(beta[idx]))
        keep.append(int(idx))
        groups.append([int(idx)])
    return np.array(unique), np.array(keep, dtype=int), [np.array(g, dtype=int) for g in groups]


def build_db(source: Path, **fields) -> HydroDB:
    """``HydroDB(**fields)``, with its validation errors re-raised against ``source``."""
    try:
        return HydroDB(**fields)
    except HydroDataError as exc:
        raise HydroDataError(source, exc.where, exc.message) from None
