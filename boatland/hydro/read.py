"""Reading a hydrodynamic database: detect the format of BEM output, read it (:func:`read_hydro`), give
an imported vessel file's BEM output its mass properties (:func:`read_vessel_file`), or take a built-in
vessel by name (:func:`load_database`).

Every reader converts units and the phase convention to boatland's (:mod:`boatland.conventions`) and
returns a validated :class:`boatland.vessel.database.HydroDB`; :func:`read_hydro` says which one it used.
A vessel file with a ``[bem]`` table names the BEM output and gives the body's mass, centre of gravity
and inertia, with the checks of :mod:`boatland.vessel.imported`; a scenario may name such a file as its
``vessel.database``, and so may ``boatland hydro info``, ``irf`` and ``hydro build``.
"""

from __future__ import annotations

from pathlib import Path

from boatland.errors import BoatlandInputError, HydroDataError
from boatland.inputs import open_input
from boatland.hydro.bemio import read_bemio
from boatland.hydro.builtin import BUILTIN, load_builtin
from boatland.vessel.database import HydroDB
from boatland.vessel.files import load_vessel
from boatland.vessel.imported import ImportedVesselSpec, apply_mass_properties

__all__ = ["FORMATS", "database_of", "detect_format", "load_database", "read_hydro", "read_vessel_file"]

#: Format name → what the input looks like (for messages and ``--help``).
FORMATS = {
    "bemio": "BEMIO HDF5 file (.h5/.hdf5): boatland's own, WEC-Sim's, HydroChrono's",
    "wamit": "WAMIT output: .1 (+ .3, .hst, .out, .8/.9 mean drift beside it) or the .out file",
    "nemoh": "NEMOH v2/v3 run folder (Nemoh.cal, Mesh/, Results/)",
    "aqwa": "AQWA .AH1 (+ .LIS beside it; mean drift from its wave-drift tables or the FARFIELD block)",
    "capytaine": "Capytaine NetCDF dataset (.nc)",
    "vessel": "vessel file (.toml) with a [bem] table: any of the above plus its mass, centre of gravity, inertia",
}


def detect_format(path: str | Path) -> str:
    """Name of the reader for ``path`` (a key of :data:`FORMATS`).

    Raises
    ------
    HydroDataError
        The path does not exist or looks like none of the supported formats.
    """
    path = Path(path)
    if not path.exists():
        raise HydroDataError(path, None, "file or folder not found")
    if path.is_dir():
        if (path / "Nemoh.cal").exists() or (path / "Results" / "RadiationCoefficients.tec").exists():
            return "nemoh"
        raise HydroDataError(path, None, "a folder, but not a NEMOH run (no Nemoh.cal or "
                                         "Results/RadiationCoefficients.tec); expected one of: "
                             + "; ".join(FORMATS.values()))
    suffix = path.suffix.lower()
    try:
        with open_input(path, "hydrodynamic database", "hdf5") as fh:
            head = fh.read(8)
    except BoatlandInputError as exc:
        raise HydroDataError(path, None, str(exc).removeprefix(f"{path}: ")) from None
    if head.startswith(b"\x89HDF"):
        return "capytaine" if suffix == ".nc" else "bemio"
    if head.startswith(b"CDF"):
        return "capytaine"
    if suffix in (".h5", ".hdf5", ".nc"):
        raise HydroDataError(path, None, "not an HDF5/NetCDF file (empty, truncated or of another kind); "
                                         "expected a BEMIO HDF5 database or a Capytaine NetCDF dataset")
    if suffix == ".toml":
        return "vessel"
    if suffix in (".1", ".3", ".hst", ".out", ".8", ".9"):
        return "wamit"
    if suffix in (".ah1", ".lis"):
        return "aqwa"
    if suffix == ".cal" or (suffix == ".tec" and path.parent.name.lower() == "results"):
        return "nemoh"
    raise HydroDataError(path, None, f"unrecognised file kind {suffix or '(no suffix)'!r}; expected one of: "
                         + "; ".join(FORMATS.values()))


def read_hydro(path: str | Path, *, fmt: str | None = None, rho: float | None = None,
               g: float | None = None, drift: str = "auto", **options) -> tuple[HydroDB, str]:
    """Read any supported BEM output into a :class:`HydroDB`.

    Parameters
    ----------
    path : str or Path
        File or folder (see :data:`FORMATS`).
    fmt : str, optional
        Force a reader instead of detecting it.
    rho, g : float, optional
        Water density and gravity, for formats that do not store them (WAMIT is non-dimensional
        in ρ). Ignored by formats that do.
    drift : {"auto", "pressure", "momentum", "none"}
        Which mean drift output fills ``HydroDB.drift`` when it is beside the main file (WAMIT ``.9`` /
        ``.8``, AQWA ``.LIS`` tables / ``.AH1`` FARFIELD): ``"auto"`` the pressure-integration (six DOFs)
        one, else the momentum (far-field: surge, sway, yaw) one. BEMIO files carry their own drift (read
        whatever they hold); NEMOH and Capytaine NetCDF outputs are read without drift.
    **options
        Passed to the reader (e.g. ``ref_point=`` for Capytaine files, which do not store it).

    Returns
    -------
    db : HydroDB
    fmt : str
        The reader used.
    """
    fmt = fmt or detect_format(path)
    if fmt == "bemio":
        return read_bemio(path), fmt
    if fmt == "wamit":
        from boatland.hydro.wamit import read_wamit
        return read_wamit(path, rho=rho, g=g, drift=drift), fmt
    if fmt == "nemoh":
        from boatland.hydro.nemoh import read_nemoh
        return read_nemoh(path), fmt
    if fmt == "aqwa":
        from boatland.hydro.aqwa import read_aqwa
        return read_aqwa(path, drift=drift), fmt
    if fmt == "capytaine":
        from boatland.hydro.capytaine_nc import read_capytaine
        return read_capytaine(path, **options), fmt
    if fmt == "vessel":
        return read_vessel_file(path), fmt
    raise HydroDataError(path, None, f"unknown format {fmt!r}; expected one of {', '.join(FORMATS)}")


def database_of(spec: ImportedVesselSpec) -> HydroDB:
    """The database of an imported vessel file: its BEM output read and given its mass properties."""
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

def load_database(name_or_path: str | Path) -> HydroDB:
    """A hydrodynamic database by built-in name (:data:`boatland.hydro.builtin.BUILTIN`) or from a file or
    folder in any format :func:`read_hydro` reads (a :class:`~pathlib.Path` is always a file).

    Raises
    ------
    BoatlandInputError
        Neither an existing file nor a built-in name (the message lists the names), or the file's problems.
    """
    if isinstance(name_or_path, Path) or Path(name_or_path).exists():
        return read_hydro(name_or_path)[0]
    if name_or_path in BUILTIN:
        return load_builtin(name_or_path)
    raise BoatlandInputError(f"{name_or_path}: no such file, and not a built-in vessel "
                             f"(built-in: {', '.join(sorted(BUILTIN))})")
