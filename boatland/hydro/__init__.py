"""Hydrodynamic databases: BEM readers (WAMIT, NEMOH, AQWA, Capytaine, BEMIO HDF5), the BEMIO writer,
the Capytaine builder and the built-in vessels. They produce a :class:`boatland.vessel.database.HydroDB`
and need nothing above :mod:`boatland.vessel`.

:func:`load_database` takes a built-in name or a path; :func:`read_hydro` reads any supported BEM
output and says which reader it used (:mod:`boatland.hydro.read`); :func:`write_bemio` writes boatland's
own format (:mod:`boatland.hydro.bemio`).
"""

from boatland.hydro.bemio import read_bemio, write_bemio
from boatland.hydro.read import FORMATS, detect_format, load_database, read_hydro, read_vessel_file

__all__ = ["FORMATS", "detect_format", "load_database", "read_bemio", "read_hydro", "read_vessel_file",
           "write_bemio"]
