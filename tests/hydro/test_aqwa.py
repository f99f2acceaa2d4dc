"""AQWA reader on WEC-Sim's floating cylinder (tests/data/refdata/aqwa_cylinder, Apache-2.0; see its README.md)."""

from __future__ import annotations

import shutil

import numpy as np
import pytest

from boatland.errors import HydroDataError
from boatland.hydro import read_hydro
from boatland.hydro.aqwa import read_aqwa


@pytest.fixture(scope="module")
def cyl(refdata):
    return read_aqwa(refdata / "aqwa_cylinder" / "cylinder.AH1")


@pytest.fixture
def run(refdata, tmp_path):
    for f in (refdata / "aqwa_cylinder").iterdir():
        shutil.copy(f, tmp_path / f.name)
        (tmp_path / f.name).chmod(0o644)
    return tmp_path


def _lines(path):
    return path.read_text().splitlines(keepends=True)


def _line_of(path, keyword):
    return next(n for n, s in enumerate(_lines(path), start=1) if s.strip() == keyword)


def _edit_line(path, lineno, fn):
    lines = _lines(path)
    lines[lineno - 1] = fn(lines[lineno - 1])
    path.write_text("".join(lines))


def test_reads_completely(cyl):
    nf = 50
    assert cyl.omega.shape == (nf,) and cyl.omega[0] == pytest.approx(0.04) and cyl.omega[-1] == 10.4999771
    # −180, 0, 180 in the file: −180 and 180 are one direction
    assert cyl.wave_dir_deg.tolist() == [0.0, 180.0]
    assert cyl.A.shape == cyl.B.shape == (6, 6, nf) and cyl.X.shape == (6, 2, nf)
    for arr in (cyl.A, cyl.B, cyl.X, cyl.C, cyl.M, cyl.A_inf, cyl.A_0):
        assert np.all(np.isfinite(arr))
    assert cyl.provenance.solver == "AQWA" and cyl.provenance.created == "2021-11-07T22:45:50"
    assert cyl.rho == 1025.0 and cyl.g == 9.807 and cyl.water_depth == 3.0
    assert cyl.disp_vol == pytest.approx(0.24173) and cyl.cob == pytest.approx([0, 0, -0.315])
    assert np.array_equal(cyl.ref_point, cyl.cog)                    # AQWA works about the COG
    # hydrostatics: C33 = ρ g A_wp, and the file's roll/pitch restoring is negative (COG on the waterline)
    assert cyl.C[2, 2] == 3.8569e3 and cyl.C[3, 3] == -6.4766e2
    # mass matrix from the MASS block: mass = ρ V
    assert cyl.mass == pytest.approx(247.77) and cyl.mass == pytest.approx(cyl.rho * cyl.disp_vol, rel=1e-4)
    assert cyl.M[3, 3] == pytest.approx(247.77)
    assert cyl.A_inf[2, 2] == pytest.approx(8.5189e1)
    assert any("ADDEDMASS_HF) at 100.0 rad/s" in n for n in cyl.provenance.notes)
    assert any("directions -180°, 180° are the same" in n for n in cyl.provenance.notes)


def test_known_phases(cyl):
    """Lowest ω = 0.04 rad/s in 3 m depth: kR ≈ (ω/√(gh))·0.35 m ≈ 0.003, phase corrections ≈ 0.2°.

    AQWA gives surge phase +90.04° at heading −180° and −90.04° at 0° (lags); conjugated, a wave
    travelling along +x leads by +90° and one travelling along −x by −90°.
    """
    X0, X180 = cyl.X[:, 0, 0], cyl.X[:, 1, 0]
    assert np.angle(X0[2], deg=True) == pytest.approx(0.0, abs=1.0)
    assert np.angle(X180[2], deg=True) == pytest.approx(0.0, abs=1.0)
    assert np.angle(X0[0], deg=True) == pytest.approx(90.0, abs=1.0)
    assert np.angle(X180[0], deg=True) == pytest.approx(-90.0, abs=1.0)


def test_direction_180_is_the_files_minus_180(cyl, refdata):
    """FORCERAO '1 1 1' (direction −180°): surge amplitude 31.120, phase 90.04° → conjugated."""
    assert cyl.X[0, 1, 0] == pytest.approx(31.120 * np.exp(-1j * np.deg2rad(90.04)))


def test_lis_path_and_read_hydro(refdata, cyl):
    db = read_aqwa(refdata / "aqwa_cylinder" / "cylinder.LIS")
    assert np.array_equal(db.X, cyl.X)
    db, fmt = read_hydro(refdata / "aqwa_cylinder" / "cylinder.AH1")
    assert fmt == "aqwa" and np.array_equal(db.A, cyl.A)


def test_mass_from_lis_when_ah1_has_none(run, cyl):
    p = run / "cylinder.AH1"
    lines = _lines(p)
    k = _line_of(p, "MASS")
    p.write_text("".join(lines[:k - 1] + lines[k + 6:]))        # drop the MASS block (7 lines)
    db = read_aqwa(p)
    assert db.M == pytest.approx(cyl.M, rel=1e-3)
    assert any("from cylinder.LIS" in n for n in db.provenance.notes)
    (run / "cylinder.LIS").unlink()
    db = read_aqwa(p)
    assert db.M is None


# ------------------------------------------------------------------------------ bad input
def test_missing_file(tmp_path):
    with pytest.raises(HydroDataError, match=r"none\.AH1: file not found"):
        read_aqwa(tmp_path / "none.AH1")
    (tmp_path / "lonely.LIS").write_text("x")
    with pytest.raises(HydroDataError, match=r"lonely\.AH1: file not found"):
        read_aqwa(tmp_path / "lonely.LIS")


def test_truncated(run):
    p = run / "cylinder.AH1"
    lines = _lines(p)
    k = _line_of(p, "FORCERAO")
    p.write_text("".join(lines[:k + 40]))
    with pytest.raises(HydroDataError, match=rf"cylinder\.AH1: line {k + 40}: FORCERAO: ends early; expected "
                                             r".*\(truncated file\?\)"):
        read_aqwa(p)


def test_garbled_number(run):
    p = run / "cylinder.AH1"
    k = _line_of(p, "ADDEDMASS") + 3
    _edit_line(p, k, lambda s: s.replace("E", "#", 1))
    with pytest.raises(HydroDataError, match=rf"cylinder\.AH1: line {k}: expected .* in ADDEDMASS, found '"):
        read_aqwa(p)


def test_nan_value(run):
    p = run / "cylinder.AH1"
    k = _line_of(p, "DAMPING") + 2
    _edit_line(p, k, lambda s: s.replace(s.split()[2], "NaN", 1))
    with pytest.raises(HydroDataError, match=rf"cylinder\.AH1: line {k}: expected finite .* in DAMPING, found 'NaN'"):
        read_aqwa(p)


def test_duplicate_frequency(run):
    p = run / "cylinder.AH1"
    _edit_line(p, 7, lambda s: s.replace("0.2534700", "0.0400000"))
    with pytest.raises(HydroDataError, match=r"cylinder\.AH1: line 7: header: frequency 0\.04 rad/s appears twice"):
        read_aqwa(p)


def test_wrong_kind_of_file(run, refdata):
    shutil.copy(refdata / "wamit_sphere" / "sphere.1", run / "cylinder.AH1")
    with pytest.raises(HydroDataError, match=r"cylinder\.AH1: line 1: found 'WAMIT' where the header"):
        read_aqwa(run / "cylinder.AH1")


def test_missing_block(run):
    p = run / "cylinder.AH1"
    _edit_line(p, _line_of(p, "FORCERAO"), lambda s: "FORCEXXX\n")
    with pytest.raises(HydroDataError, match=r"cylinder\.AH1: no FORCERAO block"):
        read_aqwa(p)


def test_units_other_than_si(run):
    p = run / "cylinder.AH1"
    k = _line_of(p, "GENERAL") + 1
    _edit_line(p, k, lambda s: s.replace("1025.000", "   1.025"))
    with pytest.raises(HydroDataError, match=rf"cylinder\.AH1: line {k - 1}: GENERAL: .*expected SI units"):
        read_aqwa(p)


# ------------------------------------------------------------------------------ mean drift
def test_lis_drift_tables(cyl):
    """Default: the .LIS wave-drift tables (near field here: all six DOFs), N/m² and N·m/m² about the COG;
    at 4.096 rad/s the SURGE(X) row reads −4.73E+02 4.73E+02 −4.73E+02 for −180°, 0°, 180°."""
    D = cyl.drift
    assert D.shape == (6, 2, 50) and np.all(np.isfinite(D))
    k = int(np.argmin(np.abs(cyl.omega - 4.096)))
    assert D[0, 0, k] == 4.73e2 and D[0, 1, k] == -4.73e2              # 0° and 180° (= the file's −180°)
    assert D[2, :, k].tolist() == [1.82e2, 1.82e2] and D[4, 0, k] == 2.20e2 and D[4, 1, k] == -2.19e2
    assert D[5, 1, 0] == 2.54e-3                                       # YAW(RZ) at 0.040 rad/s
    note = next(n for n in cyl.provenance.notes if n.startswith("mean drift:"))
    assert "cylinder.LIS" in note and "near-field pressure integration: all six DOFs" in note
    assert any(n.startswith("mean drift at -180°, 180°: kept -180°") for n in cyl.provenance.notes)


def test_farfield_block_on_request_or_without_lis(refdata, run, cyl):
    """drift="momentum": the .AH1 FARFIELD block (AQWA's far field: surge, sway, yaw); '1 2 20' is
    5.0423E+02 5.0658E-02 0 0 0 −6.1438E-04 (0°, 4.096 rad/s)."""
    far = read_aqwa(refdata / "aqwa_cylinder" / "cylinder.AH1", drift="momentum")
    assert far.drift[:, 0, 19].tolist() == [5.0423e02, 5.0658e-02, 0.0, 0.0, 0.0, -6.1438e-04]
    assert far.drift[0, 1, 19] == -5.0422e02                            # the file's −180°
    assert np.all(far.drift[[2, 3, 4]] == 0)
    assert any("FARFIELD block" in n and "surge, sway and yaw only" in n for n in far.provenance.notes)
    assert read_aqwa(refdata / "aqwa_cylinder" / "cylinder.AH1", drift="none").drift is None
    (run / "cylinder.LIS").unlink()
    assert np.array_equal(read_aqwa(run / "cylinder.AH1").drift, far.drift)          # auto without a .LIS
    alone = read_aqwa(run / "cylinder.AH1", drift="pressure")
    assert alone.drift is None and any("mean drift: none read" in n for n in alone.provenance.notes)
    with pytest.raises(HydroDataError, match="drift: unknown choice 'near'"):
        read_aqwa(run / "cylinder.AH1", drift="near")


def test_bad_lis_drift_table(run):
    p = run / "cylinder.LIS"
    lines = _lines(p)
    k = next(n for n, s in enumerate(lines, start=1) if s.strip() == "HEAVE(Z)")
    p.write_text("".join(lines[:k + 20] + lines[k + 23:]))              # three HEAVE(Z) rows lost
    with pytest.raises(HydroDataError, match=r"cylinder\.LIS: wave-drift tables: no HEAVE\(Z\) value at -180°, 4\.309 rad/s"):
        read_aqwa(run / "cylinder.AH1")
    p.write_text("".join(lines))
    _edit_line(p, k, lambda s: "   SURGEX\n")
    with pytest.raises(HydroDataError, match=rf"cylinder\.LIS: line {k}: wave-drift table .*expected one of SURGE\(X\)"):
        read_aqwa(run / "cylinder.AH1")
    p.write_text("".join(lines))
    _edit_line(p, k + 5, lambda s: s.replace("0.894", "0.999"))
    with pytest.raises(HydroDataError, match=rf"line {k + 5}: wave-drift table: frequency 0\.999 rad/s is not one"):
        read_aqwa(run / "cylinder.AH1")
