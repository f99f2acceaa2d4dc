"""Reading a site's weather (boatland.site.weather): scatter diagrams and hindcasts from CSV, a hindcast from a
real netCDF-4 file written by xarray (h5netcdf), the shipped example made by its script, and bad input as one
line naming the file and the line or column."""

from __future__ import annotations

import importlib.util
import warnings

import numpy as np
import pytest

from boatland.errors import BoatlandInputError, BoatlandWarning
from boatland.site import read_weather
from tests.site.conftest import HINDCAST, ROOT


def write(tmp_path, text, name="w.csv"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_the_shipped_example_is_what_its_script_makes():
    spec = importlib.util.spec_from_file_location("make_example_hindcast", ROOT / "docs" / "make_example_hindcast.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert mod.make() == HINDCAST.read_text(encoding="utf-8")


def test_the_shipped_example_reads_as_a_year_with_partitions():
    w = read_weather(HINDCAST)
    assert w.n == 2920 and w.step_hours == 3.0 and set(w.parts) == {"wind_sea", "swell"}
    assert str(w.time[0]) == "2021-01-01T00:00:00" and str(w.time[-1]) == "2021-12-31T21:00:00"
    assert w.months.tolist().count(2) == 28 * 8 and set(w.years.tolist()) == {2021}
    Hw, _, _ = w.parts["wind_sea"]
    Hsw, _, _ = w.parts["swell"]
    np.testing.assert_allclose(np.hypot(Hw, Hsw), w.Hs, atol=0.006)       # rounded to 1 cm each


def test_a_hindcast_from_netcdf_written_by_xarray(tmp_path):
    xr = pytest.importorskip("xarray")
    csv = read_weather(HINDCAST)
    ds = xr.Dataset(
        {"hs": ("time", csv.Hs, {"standard_name": "sea_surface_wave_significant_height", "units": "m"}),
         "tp": ("time", csv.Tp, {"standard_name": "sea_surface_wave_period_at_variance_spectral_density_maximum"}),
         "mwd": ("time", csv.from_deg, {"standard_name": "sea_surface_wave_from_direction", "units": "degree"}),
         **{f"{p}_{c}": ("time", v) for p, cols in csv.parts.items()
            for c, v in zip(("Hs", "Tp", "direction_from_deg"), cols)}},
        coords={"time": csv.time.astype("datetime64[ns]")})
    path = tmp_path / "hindcast.nc"
    ds.to_netcdf(path, engine="h5netcdf", encoding={"time": {"units": "hours since 2021-01-01 00:00:00"}})
    nc = read_weather(path)
    np.testing.assert_array_equal(nc.time, csv.time)
    for a, b in ((nc.Hs, csv.Hs), (nc.Tp, csv.Tp), (nc.from_deg, csv.from_deg)):
        np.testing.assert_array_equal(a, b)
    for p in csv.parts:
        for a, b in zip(nc.parts[p], csv.parts[p]):
            np.testing.assert_array_equal(a, b)


def test_packed_netcdf_as_era5_writes_it(tmp_path):
    """Hs, Tp and direction packed in 16-bit integers with a scale and an offset, missing values as _FillValue
    (how ERA5 files come): read as CF says; a missing sea state is refused naming its time."""
    xr = pytest.importorskip("xarray")
    csv = read_weather(HINDCAST)
    n = 240
    ds = xr.Dataset({"Hs": ("time", csv.Hs[:n]), "Tp": ("time", csv.Tp[:n]),
                     "direction_from_deg": ("time", csv.from_deg[:n])},
                    coords={"time": csv.time[:n].astype("datetime64[ns]")})
    enc = {k: {"dtype": "int16", "scale_factor": sf, "add_offset": off, "_FillValue": -32767}
           for k, sf, off in (("Hs", 0.001, 10.0), ("Tp", 0.001, 15.0), ("direction_from_deg", 0.01, 180.0))}
    path = tmp_path / "packed.nc"
    ds.to_netcdf(path, engine="h5netcdf", encoding=enc)
    w = read_weather(path)
    np.testing.assert_allclose(w.Hs, csv.Hs[:n], atol=0.0005 + 1e-12)
    np.testing.assert_allclose(w.Tp, csv.Tp[:n], atol=0.0005 + 1e-12)
    np.testing.assert_allclose(w.from_deg, csv.from_deg[:n], atol=0.005 + 1e-9)
    ds["Hs"][17] = np.nan
    ds.to_netcdf(tmp_path / "gap.nc", engine="h5netcdf", encoding=enc)
    with pytest.raises(BoatlandInputError, match=r"gap\.nc: variable 'Hs' \(Hs\) has no value at time "
                                                 r"2021-01-03T03:00:00 \(1 missing in all\)"):
        read_weather(tmp_path / "gap.nc")


def test_netcdf_in_another_calendar_is_refused(tmp_path):
    import h5py

    path = tmp_path / "model.nc"
    with h5py.File(path, "w") as f:
        f["time"] = np.arange(4.0)
        f["time"].attrs.update({"units": "days since 2021-01-01", "calendar": "360_day"})
        for k, v in (("Hs", 1.0), ("Tp", 7.0), ("direction_from_deg", 180.0)):
            f[k] = np.full(4, v)
    with pytest.raises(BoatlandInputError, match="calendar '360_day' is not read"):
        read_weather(path)


def test_netcdf_without_a_wave_height_names_it(tmp_path):
    xr = pytest.importorskip("xarray")
    t = np.arange(np.datetime64("2021-01-01"), np.datetime64("2021-01-02"), np.timedelta64(1, "h"))
    path = tmp_path / "bad.nc"
    xr.Dataset({"Tp": ("time", np.full(t.size, 7.0))}, coords={"time": t}).to_netcdf(path, engine="h5netcdf")
    with pytest.raises(BoatlandInputError, match=r"bad\.nc: no variable 'Hs' \(or standard_name "
                                                 r"'sea_surface_wave_significant_height'\)"):
        read_weather(path)


def test_a_hindcast_from_csv(tmp_path):
    p = write(tmp_path, "# a comment\ntime,Hs,Tp,direction_from_deg\n2021-05-01T00:00,0.5,6,270\n"
                        "2021-05-01T01:00,0.6,6.5,265\n2021-05-01 02:00,0.7,7,260\n")
    w = read_weather(p)
    assert w.step_hours == 1.0 and w.time is not None and w.weight.tolist() == [1 / 3] * 3
    assert w.from_deg.tolist() == [270.0, 265.0, 260.0] and not w.parts


def test_sum_far_from_one_is_normalised_with_a_warning(tmp_path):
    p = write(tmp_path, "Hs,Tp,direction_from_deg,occurrence\n1,7,180,300\n1.5,8,180,100\n")
    with pytest.warns(BoatlandWarning, match="sum to 400"):
        sc = read_weather(p)
    np.testing.assert_allclose(sc.weight, [0.75, 0.25])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_weather(write(tmp_path, "Hs,Tp,direction_from_deg,occurrence\n1,7,180,0.7\n1.5,8,180,0.3001\n", "ok.csv"))


@pytest.mark.parametrize("text, match", [
    ("Hs,Tp,occurrence\n1,7,1\n", r"line 1: missing column\(s\) direction_from_deg"),
    ("Hs,Tp,direction_deg,occurrence\n1,7,180,1\n", "'direction_deg' .global, towards. is not read"),
    ("Hs,Tp,direction_from_deg\n1,7,180\n", "neither time .a hindcast. nor occurrence"),
    ("time,Hs,Tp,direction_from_deg,occurrence\n2021-01-01,1,7,180,1\n", "both time and occurrence"),
    ("Hs,Tp,direction_from_deg,occurrence\n1,x,180,1\n", "line 2: Tp = 'x' is not a number"),
    ("Hs,Tp,direction_from_deg,occurrence\n1,7,180\n", "line 2: 3 fields for 4 columns"),
    ("Hs,Tp,direction_from_deg,occurrence\n0,7,180,1\n", "line 2: Hs = 0 must be > 0"),
    ("Hs,Tp,direction_from_deg,occurrence\n1,7,180,0\n", "no sea states with a positive occurrence"),
    ("# c\nHs,Tp,direction_from_deg,occurrence\n1,7,180,0.6\n1.5,8,180,-0.1\n", "line 4: occurrence = -0.1 is negative"),
    ("# only a comment\n", "empty weather file"),
    ("time,Hs,Tp,direction_from_deg\n2021-01-01T00:00,1,7,180\n2021-01-01T01:00,1,7,180\n2021-01-01T03:00,1,7,180\n",
     r"line 4: time 2021-01-01T03:00:00 is 2 h after the previous one, not 1 h"),
    ("time,Hs,Tp,direction_from_deg\n2021-01-01T00:00+02:00,1,7,180\n", "line 2: time '2021-01-01T00:00\\+02:00' is not"),
    ("time,Hs,Tp,direction_from_deg\n2021-02-30T00:00,1,7,180\n2021-03-01T00:00,1,7,180\n", "not a valid date"),
    ("time,Hs,Tp,direction_from_deg\n2021-01-01T00:00,1,7,180\n", "at least two times"),
    ("Hs,Tp,direction_from_deg,occurrence,swell_Hs\n1,7,180,1,0.5\n", "partition swell: need all of"),
    ("Hs,Tp,direction_from_deg,occurrence,Hs\n1,7,180,1,1\n", "column 'Hs' appears twice"),
    ("Hs,Tp,direction_from_deg,occurrence,swell_Hs,swell_Tp,swell_direction_from_deg\n1,7,180,1,0.5,0,20\n",
     "line 2: swell_Tp = 0 is not valid"),
    ("# c\ntime,Hs,Tp,direction_from_deg,current_speed,current_direction_from_deg\n2021-01-01T00:00,1,7,180,0.5,0\n"
     "2021-01-01T01:00,1,7,180,-0.5,0\n", "line 4: current_speed = -0.5"),
    ("time,Hs,Tp,direction_from_deg\n2021-01-01T00:00,1,7,180\n2021-01-01T02:00,1,7,180\n2021-01-01T03:00,1,7,180\n"
     "2021-01-01T04:00,1,7,180\n", r"line 3: time 2021-01-01T02:00:00 is 2 h after the previous one, not 1 h"),
])
def test_bad_weather_files(tmp_path, text, match):
    with pytest.raises(BoatlandInputError, match=match):
        read_weather(write(tmp_path, text))


def test_missing_file(tmp_path):
    with pytest.raises(BoatlandInputError, match="no such file \\(the weather file\\)"):
        read_weather(tmp_path / "nope.csv")


def test_a_byte_order_mark_is_not_a_column(tmp_path):
    p = tmp_path / "bom.csv"
    p.write_bytes("\ufeffHs,Tp,direction_from_deg,occurrence\n1,7,180,1\n".encode("utf-8"))
    assert read_weather(p).Hs.tolist() == [1.0]


def test_an_absent_part_is_empty_fields(tmp_path):
    p = write(tmp_path, "Hs,Tp,direction_from_deg,occurrence,swell_Hs,swell_Tp,swell_direction_from_deg\n"
                        "1,7,180,0.5,0.4,10,330\n1,7,180,0.5,,,\n")
    w = read_weather(p)
    H, T, d = w.parts["swell"]
    assert H.tolist() == [0.4, 0.0] and T.tolist() == [10.0, 1.0] and d.tolist() == [330.0, 0.0]
