"""What ships with the package and what is optional.

- :func:`shipped_scenarios`: the scenario, vessel and campaign files installed with boatland
  (``boatland/scenarios/``; the source checkout's ``scenarios/`` is a link to the same folder), found
  through :mod:`importlib.resources`, so a wheel installed anywhere runs its default trial;
  :func:`shipped_file` and :func:`shipped_names`: a shipped scenario or campaign by its name (what
  ``boatland.simulate("ctv_landing")`` and ``boatland campaign demo`` take).
- :func:`require`: an optional dependency (Capytaine, xarray, netCDF4: the ``bem`` and ``xarray``
  extras), imported where a command needs it, or one line saying which extra installs it.
"""

from __future__ import annotations

import importlib
from importlib.resources import files
from pathlib import Path

from boatland.errors import BoatlandInputError

__all__ = ["shipped_scenarios", "shipped_file", "shipped_names", "path_or_shipped", "require", "EXTRAS"]

#: Optional module → the extra that installs it (``pip install 'boatland[<extra>]'``).
EXTRAS = {"capytaine": "bem", "netCDF4": "bem", "xarray": "xarray"}


def shipped_scenarios() -> Path:
    """Folder of the shipped scenario files (``ctv_landing.toml``, ``vessels/``, ``campaigns/``)."""
    return Path(str(files("boatland") / "scenarios"))


def _shipped_folder(kind: str) -> Path:
    if kind not in ("scenario", "campaign"):
        raise ValueError(f"kind must be 'scenario' or 'campaign', got {kind!r}")
    return shipped_scenarios() / "campaigns" if kind == "campaign" else shipped_scenarios()


def shipped_names(kind: str = "scenario") -> list[str]:
    """The names of the scenarios (``kind`` "scenario") or campaigns ("campaign") shipped with boatland."""
    return sorted(p.stem for p in _shipped_folder(kind).glob("*.toml"))


def shipped_file(name: str, kind: str = "scenario") -> Path | None:
    """The shipped scenario or campaign file ``name`` (with or without ``.toml``; a bare name, no folder),
    or None when there is none of that name."""
    if "/" in name or "\\" in name:
        return None
    folder = _shipped_folder(kind)
    return next((c for c in (folder / name, folder / f"{name}.toml") if c.is_file()), None)


def path_or_shipped(name: str | Path, kind: str = "scenario") -> Path | None:
    """``name`` as a path when it exists, else the shipped file of that name (:func:`shipped_file`), else
    None — the one lookup behind every "a file or a shipped name" argument."""
    path = Path(name)
    if path.exists():
        return path
    return shipped_file(str(name), kind)


def require(module: str, what: str):
    """Import the optional ``module`` for ``what`` (e.g. "boatland hydro build").

    Raises
    ------
    BoatlandInputError
        One line naming the command, the missing module and the extra that installs it (exit 2: the user
        can fix it).
    """
    try:
        return importlib.import_module(module)
    except ImportError:
        extra = EXTRAS.get(module.split(".")[0], "all")
        raise BoatlandInputError(f"{what} needs {module.split('.')[0]}, an optional dependency: "
                                 f"pip install 'boatland[{extra}]'") from None
