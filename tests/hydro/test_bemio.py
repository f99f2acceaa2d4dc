"""BEMIO HDF5: write → read exact, WEC-Sim/HydroChrono files, bad input."""

import h5py
import numpy as np
import pytest

from boatland.errors import HydroDataError
from boatland.hydro import detect_format, read_hydro
from boatland.hydro.bemio import read_bemio, write_bemio
from boatland.vessel.database import HullMesh, Provenance

FIELDS = ("omega", "A", "B", "X", "C", "A_inf", "A_0", "M", "wave_dir_deg", "ref_point", "cog", "cob")


def assert_same_db(a, b):
    for name in FIELDS:
        x, y = getattr(a, name), getattr(b, name)
        assert (x is None) == (y is None), name
        if x is not None:
            assert np.array_equal(x, y), name
    for name in ("disp_vol", "water_depth", "rho", "g", "name", "provenance"):
        assert getattr(a, name) == getattr(b, name), name
    assert (a.mesh is None) == (b.mesh is None)
    if a.mesh is not None:
        assert np.array_equal(a.mesh.vertices, b.mesh.vertices) and np.array_equal(a.mesh.faces, b.mesh.faces)


@pytest.fixture
def sphere(refdata):
    return read_bemio(refdata / "bemio_sphere" / "sphere.h5")


def test_hydrochrono_sphere_reads(sphere):
    """HydroChrono's sphere.h5: normalised arrays un-normalised (B carries ρω), depth, A∞."""
    assert sphere.n_freq == 240 and sphere.n_dir == 1
    assert sphere.rho == 1000.0 and sphere.water_depth == 200.0
    with h5py.File(sphere.provenance.source) as f:
        b_norm = f["body1/hydro_coeffs/radiation_damping/all"][2, 2, 10]
    assert np.isclose(sphere.B[2, 2, 10], b_norm * 1000.0 * sphere.omega[10], rtol=1e-14)
    assert np.isclose(sphere.A_inf[2, 2] / 1000.0, 130.8768, rtol=1e-6)
    assert sphere.provenance.solver == "WAMIT"


def test_write_read_exact(sphere, tmp_path):
    path = write_bemio(sphere, tmp_path / "db.h5")
    assert_same_db(sphere, read_bemio(path))


def test_write_read_exact_with_extras(sphere, tmp_path):
    from boatland.vessel.database import rigid_body_mass_matrix

    db = sphere.replace(
        M=rigid_body_mass_matrix(261800.0, (0, 0, -2), (1e6, 1e6, 2e6)), A_0=sphere.A_inf * 1.3,
        water_depth=np.inf, ref_point=np.array([0.1, 0, 0]), name="ball",
        mesh=HullMesh(np.array([[0, 0, 0], [1, 0, 0], [1, 1, -1.0], [0, 1, -1]]), np.array([[0, 1, 2, 3]])),
        provenance=Provenance("x.nc", "CAPYTAINE", "2026-01-01", "test", ("a note",)))
    back = read_bemio(write_bemio(db, tmp_path / "db.h5"))
    assert_same_db(db, back)
    assert detect_format(tmp_path / "db.h5") == "bemio"


def test_file_edited_by_another_tool_is_read_from_bemio_arrays(sphere, tmp_path):
    path = write_bemio(sphere, tmp_path / "db.h5")
    with h5py.File(path, "r+") as f:
        f["body1/hydro_coeffs/added_mass/all"][2, 2, :] *= 2.0
    db = read_bemio(path)
    assert np.allclose(db.A[2, 2], 2 * sphere.A[2, 2], rtol=1e-12)
    assert any("disagrees" in n for n in db.provenance.notes)


def test_bad_input(tmp_path, sphere):
    with pytest.raises(HydroDataError, match="missing.h5: file not found"):
        read_bemio(tmp_path / "missing.h5")
    garbled = tmp_path / "garbled.h5"
    garbled.write_bytes(b"\x89HDF\r\n\x1a\n" + b"\x00" * 40)
    with pytest.raises(HydroDataError, match="garbled.h5: not a readable HDF5 file"):
        read_bemio(garbled)
    good = write_bemio(sphere, tmp_path / "good.h5")
    truncated = tmp_path / "truncated.h5"
    truncated.write_bytes(good.read_bytes()[: good.stat().st_size // 2])
    with pytest.raises(HydroDataError, match="truncated.h5"):
        read_bemio(truncated)
    wrong = tmp_path / "wrong.h5"
    with h5py.File(wrong, "w") as f:
        f["something"] = 1
    with pytest.raises(HydroDataError, match=r"wrong.h5: /simulation_parameters/rho: dataset missing"):
        read_bemio(wrong)
    shape = tmp_path / "shape.h5"
    write_bemio(sphere, shape)
    with h5py.File(shape, "r+") as f:
        del f["body1/hydro_coeffs/added_mass/all"]
        f["body1/hydro_coeffs/added_mass/all"] = np.zeros((6, 6, 3))
    with pytest.raises(HydroDataError, match=r"added_mass/all: expected shape \(6, 6, 240\)"):
        read_bemio(shape)
    nan = tmp_path / "nan.h5"
    write_bemio(sphere, nan)
    with h5py.File(nan, "r+") as f:
        del f["body1/boatland/exact"]
        f["body1/hydro_coeffs/radiation_damping/all"][2, 2, 5] = np.nan
    with pytest.raises(HydroDataError, match=r"nan.h5: B: 1 value\(s\) are NaN"):
        read_bemio(nan)
    dec = tmp_path / "dec.h5"
    write_bemio(sphere, dec)
    with h5py.File(dec, "r+") as f:
        f["simulation_parameters/w"][5, 0] = 0.01
    with pytest.raises(HydroDataError, match="dec.h5: omega: frequencies must be strictly increasing"):
        read_hydro(dec)


def test_failed_write_leaves_nothing(sphere, tmp_path):
    target = tmp_path / "db.h5"
    target.write_bytes(b"previous")

    class Boom(Exception):
        pass

    import boatland.hydro.bemio as bemio

    orig = bemio.np.bytes_
    try:
        def bad(*a):
            raise Boom()
        bemio.np.bytes_ = bad
        with pytest.raises(Boom):
            write_bemio(sphere, target)
    finally:
        bemio.np.bytes_ = orig
    assert target.read_bytes() == b"previous"
    assert [p.name for p in tmp_path.iterdir()] == ["db.h5"]


def test_written_file_has_ordinary_permissions(sphere, tmp_path):
    import os
    import stat

    umask = os.umask(0)
    os.umask(umask)
    path = write_bemio(sphere, tmp_path / "db.h5")
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask
