"""Imported databases with their mass properties: a vessel file with a ``[bem]`` table, or flags.

:func:`read_vessel_file` reads the BEM output a vessel file names (any format :func:`boatland.hydro.read_hydro`
reads) and gives it the file's mass, centre of gravity and inertia with the checks of
:mod:`boatland.model.imported`. A scenario may name such a vessel file as its ``vessel.database``; so
may ``boatland hydro info``, ``irf`` and ``hydro build`` (which writes the database with its mass).
"""

from __future__ import annotations

from pathlib import Path

from boatland.errors import BoatlandInputError
from boatland.model.hydrodb import HydroDB
from boatland.model.imported import ImportedVesselSpec, apply_mass_properties
from boatland.model.vessel import load_vessel

__all__ = ["read_vessel_file", "database_of"]


def database_of(spec: ImportedVesselSpec) -> HydroDB:
    """The database of an imported vessel file: its BEM output read and given its mass properties."""
    from boatland.hydro import read_hydro

    db, fmt = read_hydro(spec.bem_file, fmt=spec.fmt, rho=spec.rho, g=spec.g)
    db = apply_mass_properties(db, spec.mass_properties, source=spec.source)
    return db.replace(name=spec.name, provenance=db.provenance.with_note(
        f"vessel file {spec.source}: {spec.bem_file} read with the {fmt} reader"))


def read_vessel_file(path: str | Path) -> HydroDB:
    """The database of the vessel file ``path`` (a ``[bem]`` vessel file).

    Raises
    ------
    BoatlandInputError
        Problems of the file (every one, with its key), of the BEM output, of the mass properties; or
        the file describes a hull to build (``[hull]``), whose database must be built first.
    """
    spec = load_vessel(path)
    if not isinstance(spec, ImportedVesselSpec):
        raise BoatlandInputError(f"{path}: a vessel file with a [hull] describes a hull to build, not a database: "
                                 f"build it first (boatland hydro build {path} -o db.h5, minutes of Capytaine) and "
                                 "name that database")
    return database_of(spec)
