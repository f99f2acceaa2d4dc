"""Hydrodynamic databases at the edge: BEM readers, the BEMIO writer, and the Capytaine builder.

Every reader converts units and the phase convention to boatland's (:mod:`boatland.conventions`)
and returns a validated :class:`boatland.model.HydroDB`. :func:`read_hydro` picks the reader from
the input and says which one it used.
"""

from __future__ import annotations

from pathlib import Path

from boatland.errors import HydroDataError
from boatland.hydro.bemio import read_bemio, write_bemio
from boatland.model.hydrodb import HydroDB

__all__ = ["FORMATS", "detect_format", "read_hydro", "read_bemio", "write_bemio"]

#: Format name → what the input looks like (for messages and ``--help``).
FORMATS = {
    "bemio": "BEMIO HDF5 file (.h5/.hdf5): boatland's own, WEC-Sim's, HydroChrono's",
    "wamit": "WAMIT output: .1 (+ .3, .hst, .out beside it) or the .out file",
    "nemoh": "NEMOH v2/v3 run folder (Nemoh.cal, Mesh/, Results/)",
    "aqwa": "AQWA .AH1 (+ .LIS beside it)",
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
    with path.open("rb") as fh:
        head = fh.read(8)
    if head.startswith(b"\x89HDF"):
        return "capytaine" if suffix == ".nc" else "bemio"
    if head.startswith(b"CDF"):
        return "capytaine"
    if suffix in (".h5", ".hdf5", ".nc"):
        raise HydroDataError(path, None, "not an HDF5/NetCDF file (empty, truncated or of another kind); "
                                         "expected a BEMIO HDF5 database or a Capytaine NetCDF dataset")
    if suffix == ".toml":
        return "vessel"
    if suffix in (".1", ".3", ".hst", ".out"):
        return "wamit"
    if suffix in (".ah1", ".lis"):
        return "aqwa"
    if suffix == ".cal" or (suffix == ".tec" and path.parent.name.lower() == "results"):
        return "nemoh"
    raise HydroDataError(path, None, f"unrecognised file kind {suffix or '(no suffix)'!r}; expected one of: "
                         + "; ".join(FORMATS.values()))


def read_hydro(path: str | Path, *, fmt: str | None = None, rho: float | None = None,
               g: float | None = None, **options) -> tuple[HydroDB, str]:
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
        return read_wamit(path, rho=rho, g=g), fmt
    if fmt == "nemoh":
        from boatland.hydro.nemoh import read_nemoh
        return read_nemoh(path), fmt
    if fmt == "aqwa":
        from boatland.hydro.aqwa import read_aqwa
        return read_aqwa(path), fmt
    if fmt == "capytaine":
        from boatland.hydro.capytaine_nc import read_capytaine
        return read_capytaine(path, **options), fmt
    if fmt == "vessel":
        from boatland.hydro.imported import read_vessel_file
        return read_vessel_file(path), fmt
    raise HydroDataError(path, None, f"unknown format {fmt!r}; expected one of {', '.join(FORMATS)}")
