"""A trial as an xarray Dataset, and the ``-o`` file that xarray opens as the same Dataset."""

import re

import h5py
import numpy as np
import pytest
import xarray as xr

from boatland.trial.simulate import simulate


@pytest.fixture(scope="module")
def trial(landing):
    scenario, db = landing
    return simulate(scenario.replace({"simulation.duration": 40.0}), db)


def test_named_dimensions_units_and_inputs(trial):
    ds = trial.to_xarray()
    assert dict(ds.sizes) == {"time": len(trial.t), "dof": 6, "contact": 2, "tangent": 2,
                              "event": len(trial.events), "episode": len(trial.episodes)}
    assert ds.normal_force.dims == ("time", "contact") and ds.friction_force.dims == ("time", "contact", "tangent")
    mixed = ("motion", "velocity", "wave_force")               # their units differ per DOF: dof_units names them
    for name, v in ds.variables.items():
        if name not in ("dof", "dof_units", "tangent", "contact", "event", "episode", *mixed):
            assert v.attrs.get("units"), name
        if "units" in v.attrs:                                  # CF/UDUNITS strings a tool can read
            assert re.fullmatch(r"1|s|m|deg|N|J|m/s|rad|N m", v.attrs["units"]), (name, v.attrs["units"])
        # short labels: xarray's plot puts "long_name [units]" on an axis
        assert 0 < len(v.attrs.get("long_name", "x")) <= 24, (name, v.attrs.get("long_name"))
    assert all("units" not in ds[n].attrs and "dof_units" in ds[n].attrs["comment"] for n in mixed)
    assert ds.friction_utilisation.long_name == "friction utilisation" and "slips" in ds.friction_utilisation.comment
    np.testing.assert_array_equal(ds.motion.sel(dof="heave"), trial.x[:, 2])
    np.testing.assert_allclose(ds.pitch, np.degrees(trial.x[:, 4]))
    assert ds.pitch.units == "deg" and str(ds.dof_units.sel(dof="pitch").values) == "rad"
    assert ds.attrs["input_Hs_m"] == 1.5 and ds.attrs["input_thrust_N"] == 80e3
    assert ds.attrs["input_relative_direction_deg"] == 180.0 and ds.attrs["outcome"] == "slipped"
    assert list(ds.event_kind.values[:2]) == ["contact made", "contact made"]
    assert ds.event_time.units == "s"


def test_output_file_opens_in_xarray_as_the_same_dataset(trial, tmp_path):
    path = trial.to_hdf5(tmp_path / "run.h5")
    with xr.open_dataset(path) as back:
        back.load()
        xr.testing.assert_identical(back, trial.to_xarray())
        assert not [d for d in back.dims if d.startswith("phony_dim")]
        assert isinstance(back.event_kind.values[0], str)
    with h5py.File(path) as f:                                   # still plain HDF5 for h5py users
        np.testing.assert_array_equal(f["motion"][:, 2], trial.x[:, 2])


def test_campaign_store_keeps_a_trial_xarray_can_open(trial, tmp_path):
    from boatland.netcdf_h5 import copy_group

    src = trial.to_hdf5(tmp_path / "trial.h5")
    with h5py.File(tmp_path / "store.h5", "w", track_order=True) as f, h5py.File(src) as s:
        f.create_dataset("trials", data=np.zeros(3))
        copy_group(s, f.create_group("series/trial_000001", track_order=True))
    with xr.open_dataset(tmp_path / "store.h5", group="series/trial_000001") as back:
        xr.testing.assert_identical(back.load(), trial.to_xarray())


def test_run_writes_its_file_without_xarray(tmp_path):
    """``boatland run -o`` in an install without the optional xarray (a real subprocess in which importing it
    fails) writes its file — h5py alone — and xarray opens it with its dimensions, units and inputs (the
    file is the dataset itself: test_output_file_opens_in_xarray_as_the_same_dataset)."""
    import subprocess
    import sys
    from pathlib import Path

    scen = Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml"
    out = tmp_path / "run.h5"
    code = ("import sys; sys.modules['xarray'] = None\n"
            "from boatland.cli import main\n"
            f"sys.exit(main(['run', {str(scen)!r}, '--duration', '30', '--no-log', '-o', {str(out)!r}]))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with xr.open_dataset(out) as back:
        back.load()
        assert back.attrs["input_Hs_m"] == 1.5 and back.motion.dims == ("time", "dof")
        assert back.sizes["time"] == 601 and back.friction_force.units == "N"
        assert "xarray" not in r.stderr
