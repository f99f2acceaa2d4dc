"""Errors that mean "the user gave us something wrong".

Every user mistake (bad file, bad key, impossible value) is raised as a :class:`BoatlandInputError`
whose message is one line naming the file, the key / line / dataset, and what would be valid. The CLI
prints that line and exits with status 2, without a traceback. Anything else is a bug and keeps its
traceback.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["BoatlandInputError", "BoatlandWarning", "HydroDataError"]


class BoatlandInputError(ValueError):
    """A user mistake: one clear line, exit status 2 from the CLI."""

    exit_status = 2


class BoatlandWarning(UserWarning):
    """Something a user should know but that does not stop the work (e.g. a γ outside the usual range)."""


class HydroDataError(BoatlandInputError):
    """A hydrodynamic input (file or arrays) that cannot be used.

    Parameters
    ----------
    source : str or Path or None
        The file (or object) the problem is in.
    where : str or None
        The dataset, key, or line inside the source (e.g. ``"line 12"``, ``"/body1/hydro_coeffs"``).
    message : str
        What is wrong and what would be valid.
    """

    def __init__(self, source: str | Path | None, where: str | None, message: str):
        self.source = None if source is None else str(source)
        self.where = where
        self.message = message
        head = ": ".join(p for p in (self.source, where) if p)
        super().__init__(f"{head}: {message}" if head else message)
