"""Capytaine NetCDF reader: WEC-Sim's Capytaine 2.3 hemisphere (tests/data/refdata/capytaine_sphere,
Apache-2.0; see its README.md) and small datasets written here by Capytaine 3.0."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from boatland.errors import HydroDataError
from boatland.hydro import read_hydro
from boatland.hydro.capytaine_nc import read_capytaine


@pytest.fixture(scope="module")
def nc23(refdata):
    return refdata / "capytaine_sphere" / "sphere_hydrodynamics.nc"


@pytest.fixture(scope="module")
def sphere(nc23):
    return read_capytaine(nc23)


@pytest.fixture
def ds23(nc23):
    with xr.open_dataset(nc23) as ds:
        return ds.load()


@pytest.fixture(scope="module")
def cpt3_dataset():
    """A coarse hemisphere solved by Capytaine 3.0 at ω = 0, 0.05, 0.5, 1, ∞ and β = 0, 90°, 180°."""
    cpt = pytest.importorskip("capytaine")
    cpt.set_logging("ERROR")
    mesh = cpt.mesh_sphere(radius=5.0, center=(0, 0, 0), resolution=(6, 12)).immersed_part()
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, -2)),
                            center_of_mass=(0, 0, -2), name="hemisphere")
    body.inertia_matrix = body.compute_rigid_body_inertia()
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness()
    test = xr.Dataset(coords={"omega": [0.0, 0.05, 0.5, 1.0, np.inf], "wave_direction": [0.0, np.pi / 2, np.pi],
                              "radiating_dof": list(body.dofs), "water_depth": [np.inf], "rho": [1025.0]})
    return cpt.BEMSolver().fill_dataset(test, body)


def test_shapes_and_metadata(sphere):
    assert sphere.omega.shape == (417,) and sphere.omega[0] == pytest.approx(0.08)
    assert sphere.A.shape == sphere.B.shape == (6, 6, 417) and sphere.X.shape == (6, 1, 417)
    assert np.all(np.isfinite(sphere.A)) and np.all(np.isfinite(sphere.X))
    assert sphere.provenance.solver == "CAPYTAINE"
    assert sphere.provenance.created == "2025-10-14T14:51:43.100954"
    assert sphere.rho == 1000.0 and sphere.g == 9.81 and sphere.water_depth == 50.0
    assert sphere.wave_dir_deg.tolist() == [0.0]
    assert sphere.M[0, 0] == pytest.approx(261363.975) and sphere.C[2, 2] == pytest.approx(769965.687)
    notes = sphere.provenance.notes
    assert "dropped 3 frequencies with NaN: 0.02, 0.04, 0.06 rad/s" in notes
    assert any("rotation centre not stored" in n for n in notes)


def test_known_phases(sphere):
    """Lowest kept ω = 0.08 rad/s: kR = ω²R/g ≈ 0.003 → phase corrections ≈ 0.2°; bound 1°.

    Capytaine uses exp(−iωt) and gives surge phase −90°; the reader conjugates to +90°.
    """
    X = sphere.X[:, 0, 0]
    assert np.angle(X[2], deg=True) == pytest.approx(0.0, abs=1.0)
    assert np.angle(X[0], deg=True) == pytest.approx(90.0, abs=1.0)


def test_a_is_influenced_by_radiating(ds23, sphere):
    k = 10 + 3                                           # three NaN frequencies dropped before
    ref = ds23["added_mass"].isel(omega=k).sel(influenced_dof="Pitch", radiating_dof="Surge").item()
    assert sphere.A[4, 0, 10] == ref


def test_dof_order_and_dimension_order_by_name(ds23, sphere, tmp_path):
    """Capytaine 2.3 writes (omega, radiating, influenced), 3.0 (omega, influenced, radiating)."""
    ds = ds23.isel(influenced_dof=slice(None, None, -1)).transpose("influenced_dof", "omega", ...)
    ds.to_netcdf(tmp_path / "shuffled.nc")
    db = read_capytaine(tmp_path / "shuffled.nc")
    assert np.array_equal(db.A, sphere.A) and np.array_equal(db.X, sphere.X) and np.array_equal(db.M, sphere.M)


def test_ref_point_keyword(nc23):
    db = read_capytaine(nc23, ref_point=(0, 0, -2))
    assert db.ref_point.tolist() == [0, 0, -2]
    assert any("given by the caller" in n for n in db.provenance.notes)


def test_capytaine3_export_dataset(cpt3_dataset, tmp_path):
    import capytaine as cpt

    cpt.export_dataset(tmp_path / "c3.nc", cpt3_dataset, format="netcdf")
    db = read_capytaine(tmp_path / "c3.nc")
    assert db.omega.tolist() == [0.05, 0.5, 1.0]          # ω = 0 and ω = ∞ are the limits
    assert db.A_0 is not None and db.A_inf is not None
    assert db.A_inf[2, 2] == cpt3_dataset["added_mass"].sel(omega=np.inf, influenced_dof="Heave",
                                                            radiating_dof="Heave").item()
    assert db.wave_dir_deg == pytest.approx([0.0, 90.0, 180.0])
    assert db.ref_point.tolist() == [0, 0, -2] and db.cog.tolist() == [0, 0, -2]
    assert db.disp_vol == pytest.approx(cpt3_dataset["disp_mass"].item() / 1025.0)
    assert db.M[0, 0] == pytest.approx(cpt3_dataset["inertia_matrix"].sel(influenced_dof="Surge",
                                                                          radiating_dof="Surge").item())
    assert db.water_depth == np.inf and db.rho == 1025.0
    # phases at ω = 0.05 rad/s (kR ≈ 0.001): surge +90° for β = 0, sway +90° for β = 90°
    assert np.angle(db.X[2, 0, 0], deg=True) == pytest.approx(0.0, abs=1.0)
    assert np.angle(db.X[0, 0, 0], deg=True) == pytest.approx(90.0, abs=1.0)
    assert np.angle(db.X[1, 1, 0], deg=True) == pytest.approx(90.0, abs=1.0)
    assert np.angle(db.X[0, 2, 0], deg=True) == pytest.approx(-90.0, abs=1.0)
    c = cpt3_dataset["excitation_force"].sel(omega=0.5, wave_direction=0.0, influenced_dof="Heave").item()
    assert db.X[2, 0, 1] == np.conj(c)
    assert read_hydro(tmp_path / "c3.nc")[1] == "capytaine"


def test_capytaine3_separate_complex_values_to_netcdf(cpt3_dataset, tmp_path):
    """``ds.to_netcdf`` after ``separate_complex_values``: Capytaine 3.0 keeps the DOF names as a
    pandas categorical index, which xarray cannot write; as strings it can."""
    from capytaine.io.xarray import separate_complex_values

    ds = separate_complex_values(cpt3_dataset)
    ds = ds.assign_coords(radiating_dof=[str(v) for v in ds.radiating_dof.values],
                          influenced_dof=[str(v) for v in ds.influenced_dof.values])
    ds.to_netcdf(tmp_path / "c3b.nc")
    db = read_capytaine(tmp_path / "c3b.nc")
    assert db.n_freq == 3 and db.A_inf is not None


def test_read_hydro_detects_netcdf3(nc23):
    db, fmt = read_hydro(nc23)
    assert fmt == "capytaine" and db.n_freq == 417


# ------------------------------------------------------------------------------ bad input
def test_missing_file(tmp_path):
    with pytest.raises(HydroDataError, match=r"none\.nc: file not found"):
        read_capytaine(tmp_path / "none.nc")


@pytest.mark.parametrize("fraction", [0.5, 0.95])
def test_truncated_file(nc23, tmp_path, fraction):
    data = nc23.read_bytes()
    (tmp_path / "cut.nc").write_bytes(data[:int(len(data) * fraction)])
    with pytest.raises(HydroDataError, match=r"cut\.nc: cannot be read as NetCDF .*truncated file\?"):
        read_capytaine(tmp_path / "cut.nc")


def test_truncated_netcdf4(ds23, tmp_path):
    ds23.to_netcdf(tmp_path / "full.nc", format="NETCDF4")
    data = (tmp_path / "full.nc").read_bytes()
    (tmp_path / "cut.nc").write_bytes(data[:len(data) // 2])
    with pytest.raises(HydroDataError, match=r"cut\.nc: cannot be read as NetCDF"):
        read_capytaine(tmp_path / "cut.nc")


def test_wrong_kind_of_file(refdata, tmp_path):
    (tmp_path / "text.nc").write_bytes((refdata / "wamit_sphere" / "sphere.hst").read_bytes())
    with pytest.raises(HydroDataError, match=r"text\.nc: cannot be read as NetCDF"):
        read_capytaine(tmp_path / "text.nc")


def test_not_a_capytaine_dataset(tmp_path):
    xr.Dataset({"temperature": ("x", [1.0, 2.0])}).to_netcdf(tmp_path / "other.nc")
    with pytest.raises(HydroDataError, match=r"other\.nc: added_mass: variable missing"):
        read_capytaine(tmp_path / "other.nc")


def test_nan_in_stiffness(ds23, tmp_path):
    ds23["hydrostatic_stiffness"][2, 2] = np.nan
    ds23.to_netcdf(tmp_path / "nan.nc")
    with pytest.raises(HydroDataError, match=r"nan\.nc: hydrostatic_stiffness: 1 value\(s\) are NaN"):
        read_capytaine(tmp_path / "nan.nc")


def test_garbled_dof_names(ds23, tmp_path):
    ds23 = ds23.assign_coords(radiating_dof=["Surge", "Sway", "Heave", "Roll", "Pitch", "Twist"])
    ds23.to_netcdf(tmp_path / "dofs.nc")
    with pytest.raises(HydroDataError, match=r"dofs\.nc: radiating_dof: DOFs .*'Twist'.*expected rigid-body DOFs"):
        read_capytaine(tmp_path / "dofs.nc")


def test_duplicate_frequency(ds23, tmp_path):
    xr.concat([ds23.isel(omega=[10]), ds23], dim="omega", data_vars="minimal").to_netcdf(tmp_path / "dup.nc")
    with pytest.raises(HydroDataError, match=r"dup\.nc: omega: frequency 0\.22 rad/s appears twice"):
        read_capytaine(tmp_path / "dup.nc")


def test_unlabelled_complex_dimension(ds23, tmp_path):
    ds23 = ds23.assign_coords(complex=["a", "b"])
    ds23.to_netcdf(tmp_path / "cplx.nc")
    with pytest.raises(HydroDataError, match=r"cplx\.nc: excitation_force: 'complex' dimension labelled"):
        read_capytaine(tmp_path / "cplx.nc")


def test_forward_speed_refused(ds23, tmp_path):
    ds23 = ds23.assign_coords(forward_speed=2.0)
    ds23.to_netcdf(tmp_path / "speed.nc")
    with pytest.raises(HydroDataError, match=r"speed\.nc: forward_speed: 2 m/s"):
        read_capytaine(tmp_path / "speed.nc")


def test_all_frequencies_nan(ds23, tmp_path):
    ds23["added_mass"][:] = np.nan
    ds23.to_netcdf(tmp_path / "allnan.nc")
    with pytest.raises(HydroDataError, match=r"allnan\.nc: omega: expected at least 2 frequencies"):
        read_capytaine(tmp_path / "allnan.nc")
