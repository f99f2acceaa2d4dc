"""The hydrodynamic databases shipped with boatland (``boatland/data/*.h5``).

All were made with :mod:`boatland.hydro.build` from the vessel files in ``scenarios/vessels/``
(same name); their provenance notes say how (mesh, frequencies, checks). Rebuild one with::

    boatland hydro build scenarios/vessels/ctv27.toml -o boatland/data/ctv27.h5

(which also computes the mean drift, :mod:`boatland.hydro.drift`, from the same solves; the build's time is in
each database's provenance notes).
"""

from __future__ import annotations

from importlib.resources import files
from pathlib import Path

from boatland.errors import BoatlandInputError
from boatland.vessel.database import HydroDB

__all__ = ["BUILTIN", "builtin_path", "load_builtin", "vessel_file"]

#: Built-in database name → one-line description.
BUILTIN: dict[str, str] = {
    "ctv27": "27 m CTV catamaran after the published particulars of Incat Crowther's 27 m CTV class: transom "
             "stern, hard-chine demihulls 25.5 × 2.7 × 1.71 m, 5.87 m apart, 132 t; sea water, deep; boatland's "
             "default vessel",
    "ctv24": "generic full-scale 24 m CTV catamaran (two Wigley-type demihulls 24 × 2.8 × 1.4 m, 6.2 m apart, "
             "90 t, fore–aft symmetric), sea water, deep; the first default",
    "model2": "TUHH tank-test catamaran 'Model 2' (Ferreira González 2023, TU Hamburg, Table 4.2: 2.13 m, 60 kg), model scale ~1:10, "
              "fresh water, deep",
}


def _check(name: str) -> str:
    if name not in BUILTIN:
        raise BoatlandInputError(f"unknown built-in vessel {name!r}; valid names: {', '.join(BUILTIN)}")
    return name


def builtin_path(name: str) -> Path:
    """Path of the shipped database ``name`` (a key of :data:`BUILTIN`).

    Raises
    ------
    BoatlandInputError
        Unknown name (the message lists the valid ones), or the file is missing from the installation.
    """
    res = files("boatland").joinpath("data", f"{_check(name)}.h5")
    path = Path(str(res))
    if not path.is_file():
        raise BoatlandInputError(f"built-in database {name!r} is missing from the installation ({path}); "
                                 "reinstall boatland or rebuild it with 'boatland.hydro.build'")
    return path


def load_builtin(name: str) -> HydroDB:
    """The shipped database ``name`` as a :class:`HydroDB`."""
    from boatland.hydro.bemio import read_bemio

    return read_bemio(builtin_path(name))


def vessel_file(name: str) -> Path:
    """The vessel file the database ``name`` was built from (``scenarios/vessels/<name>.toml``).

    Only available in a source checkout (the scenarios folder is not part of the installed package).

    Raises
    ------
    BoatlandInputError
        Unknown name, or no source checkout around the package.
    """
    from boatland.resources import shipped_scenarios

    path = shipped_scenarios() / "vessels" / f"{_check(name)}.toml"
    if not path.is_file():
        raise BoatlandInputError(f"the vessel file of {name!r} is not available ({path} not found): "
                                 "it is in the scenarios/vessels folder of the boatland source")
    return path
