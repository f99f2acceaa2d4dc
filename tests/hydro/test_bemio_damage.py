"""A BEMIO database damaged inside (a database written elsewhere, no checksum) is one line naming the file and
the dataset, never a traceback: an empty ρ, provenance notes that are not JSON, mesh faces that are text, a
mass of 1e300."""

import shutil
from pathlib import Path

import h5py
import numpy as np
import pytest

from boatland.errors import HydroDataError
from boatland.hydro.bemio import read_bemio

SHIPPED = Path(__file__).resolve().parents[2] / "boatland" / "data" / "ctv24.h5"


def replace(f, name, value):
    del f[name]
    f[name] = value


@pytest.mark.parametrize("edit, said", [
    (lambda f: replace(f, "simulation_parameters/rho", np.zeros(0)), "/simulation_parameters/rho: expected one number"),
    (lambda f: f["body1/boatland"].attrs.__setitem__("provenance_notes", "not json {"), "provenance_notes attribute is not JSON"),
    (lambda f: replace(f, "body1/boatland/mesh/faces", np.array([b"a b c", b"d e f"])), "mesh.faces: expected (Np, 4)"),
    (lambda f: replace(f, "body1/boatland/mass_matrix", np.full((6, 6), 1e300)), "M: entries up to 1e+300: beyond 1e+12"),
], ids=["empty-rho", "notes", "faces", "mass"])
def test_damage_inside_a_database_is_one_line(tmp_path, edit, said):
    path = tmp_path / "db.h5"
    shutil.copyfile(SHIPPED, path)
    with h5py.File(path, "r+") as f:
        edit(f)
    with pytest.raises(HydroDataError) as err:
        read_bemio(path)
    text = str(err.value)
    assert text.startswith(str(path)) and said in text and "\n" not in text, text
