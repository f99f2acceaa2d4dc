"""NEMOH reader on WEC-Sim's NEMOH v3.0.2 hemisphere (tests/data/refdata/nemoh_sphere, Apache-2.0;
see its README.md)."""

from __future__ import annotations

import re
import shutil

import numpy as np
import pytest

from boatland.errors import HydroDataError
from boatland.hydro import read_hydro
from boatland.hydro.nemoh import read_nemoh


@pytest.fixture(scope="module")
def sphere(refdata):
    return read_nemoh(refdata / "nemoh_sphere")


@pytest.fixture
def run(refdata, tmp_path):
    """A writable copy of the NEMOH run folder."""
    dst = tmp_path / "run"
    shutil.copytree(refdata / "nemoh_sphere", dst)
    for p in dst.rglob("*"):
        p.chmod(0o755 if p.is_dir() else 0o644)
    return dst


def _edit_line(path, lineno, fn):
    lines = path.read_text().splitlines(keepends=True)
    lines[lineno - 1] = fn(lines[lineno - 1])
    path.write_text("".join(lines))


def test_shapes_and_metadata(sphere):
    nf = 420
    assert sphere.omega.shape == (nf,)
    assert sphere.omega[0] == pytest.approx(0.02) and sphere.omega[-1] == pytest.approx(8.4)
    assert sphere.A.shape == sphere.B.shape == (6, 6, nf) and sphere.X.shape == (6, 1, nf)
    assert np.all(np.isfinite(sphere.A)) and np.all(np.isfinite(sphere.B)) and np.all(np.isfinite(sphere.X))
    assert sphere.provenance.solver == "NEMOH"
    assert sphere.rho == 1000.0 and sphere.g == 9.81 and sphere.water_depth == 50.0
    assert sphere.ref_point == pytest.approx([0, 0, -2])         # rotation centre of Nemoh.cal
    assert sphere.cog == pytest.approx([0, 0, -2]) and sphere.cob == pytest.approx([0, 0, -1.874])
    assert sphere.disp_vol == pytest.approx(261.3639)
    assert sphere.C[2, 2] == pytest.approx(0.7699646e6) and sphere.C[3, 3] == pytest.approx(0.5128180e7)
    assert sphere.M is None and sphere.A_inf is None
    assert any("mass 261364 kg" in n for n in sphere.provenance.notes)
    assert "NEMOH v3 Nemoh.cal layout" in sphere.provenance.notes


def test_zone_is_motion_dof_column_is_force(sphere, refdata):
    """Zone 'Motion of body 1 in DoF 1', column pair 5 is the pitch moment due to surge: A[4, 0]."""
    row = (refdata / "nemoh_sphere" / "Results" / "RadiationCoefficients.tec").read_text().splitlines()[8]
    vals = [float(v) for v in row.split()]
    assert sphere.A[4, 0, 0] == vals[1 + 2 * 4] and sphere.B[4, 0, 0] == vals[2 + 2 * 4]


def test_known_phases(sphere):
    """NEMOH gives surge phase −π/2 at ω = 0.02 rad/s; conjugated it is +90° (boatland's convention).

    kR = ω²R/g = 2e-4 there, so the finite-size phase correction is ≈ 0.01°; 1° is a safe bound that
    still catches a missing conjugation (±90°) or sign error (180°).
    """
    X = sphere.X[:, 0, 0]
    assert np.angle(X[2], deg=True) == pytest.approx(0.0, abs=1.0)
    assert np.angle(X[0], deg=True) == pytest.approx(90.0, abs=1.0)


def test_entry_points(refdata, sphere):
    for p in (refdata / "nemoh_sphere" / "Nemoh.cal",
              refdata / "nemoh_sphere" / "Results" / "ExcitationForce.tec"):
        assert np.array_equal(read_nemoh(p).X, sphere.X)
    db, fmt = read_hydro(refdata / "nemoh_sphere")
    assert fmt == "nemoh" and np.array_equal(db.A, sphere.A)


def test_windows_folder_names_and_line_ends(run, sphere):
    for p in list(run.rglob("*")):
        if p.is_file():
            p.write_bytes(p.read_bytes().replace(b"\n", b"\r\n"))
    (run / "Mesh").rename(run / "mesh")
    (run / "Results").rename(run / "results")
    (run / "Nemoh.cal").rename(run / "nemoh.cal")
    db = read_nemoh(run)
    assert np.array_equal(db.A, sphere.A) and np.array_equal(db.X, sphere.X) and np.array_equal(db.C, sphere.C)


def test_v2_layout(run, sphere):
    """NEMOH v2's Nemoh.cal: no frequency type, no RAO / output frequency type / QTF lines."""
    cal = run / "Nemoh.cal"
    text = cal.read_text()
    text = re.sub(r"^1\s+420\s+0\.02\s+8\.4", "420\t0.02\t8.4", text, flags=re.M)
    text = text.split("0                  ! Response Amplitude Operator")[0]
    cal.write_text(text)
    db = read_nemoh(run)
    assert "NEMOH v2 Nemoh.cal layout" in db.provenance.notes
    assert np.array_equal(db.A, sphere.A) and np.array_equal(db.X, sphere.X)


def test_infinite_depth(run):
    _edit_line(run / "Nemoh.cal", 4, lambda s: s.replace("50.", "0.", 1))
    assert read_nemoh(run).water_depth == np.inf


# ------------------------------------------------------------------------------ bad input
def test_missing_folder(tmp_path):
    with pytest.raises(HydroDataError, match=r"nowhere: file or folder not found"):
        read_nemoh(tmp_path / "nowhere")


def test_missing_nemoh_cal(run):
    (run / "Nemoh.cal").unlink()
    with pytest.raises(HydroDataError, match=r"Nemoh\.cal: file not found"):
        read_nemoh(run)


def test_missing_results(run):
    (run / "Results" / "ExcitationForce.tec").unlink()
    with pytest.raises(HydroDataError, match=r"ExcitationForce\.tec: file not found"):
        read_nemoh(run)


def test_truncated_tec(run):
    p = run / "Results" / "RadiationCoefficients.tec"
    lines = p.read_text().splitlines(keepends=True)
    p.write_text("".join(lines[:-100]))                         # last zone (yaw) loses 100 rows
    with pytest.raises(HydroDataError, match=r"RadiationCoefficients\.tec: line 2113: zone 'Motion of body    1 "
                                             r"in DoF   6' declares I=420 rows but has 320 \(truncated file\?\)"):
        read_nemoh(run)


def test_truncated_cal(run):
    p = run / "Nemoh.cal"
    p.write_text("".join(p.read_text().splitlines(keepends=True)[:12]))
    with pytest.raises(HydroDataError, match=r"Nemoh\.cal: ends early; expected"):
        read_nemoh(run)


def test_garbled_number(run):
    _edit_line(run / "Results" / "RadiationCoefficients.tec", 20, lambda s: s.replace("0.", "O.", 1))
    with pytest.raises(HydroDataError, match=r"RadiationCoefficients\.tec: line 20: expected numbers, found 'O\."):
        read_nemoh(run)


def test_garbled_cal(run):
    _edit_line(run / "Nemoh.cal", 2, lambda s: "water" + s)
    with pytest.raises(HydroDataError, match=r"Nemoh\.cal: line 2: expected ρ \[kg/m³\], found 'water1000"):
        read_nemoh(run)


def test_wrong_kind_of_file(run, refdata):
    shutil.copy(refdata / "wamit_sphere" / "sphere.hst", run / "Results" / "ExcitationForce.tec")
    with pytest.raises(HydroDataError, match=r"ExcitationForce\.tec: line 1: data before the first 'Zone' line"):
        read_nemoh(run)


def test_nan_value(run):
    _edit_line(run / "Results" / "ExcitationForce.tec", 30, lambda s: s.replace(s.split()[3], "NaN", 1))
    with pytest.raises(HydroDataError, match=r"ExcitationForce\.tec: line 30: expected finite numbers, found 'NaN'"):
        read_nemoh(run)


def test_duplicate_frequency(run):
    p = run / "Results" / "RadiationCoefficients.tec"
    lines = p.read_text().splitlines(keepends=True)
    w1 = lines[8].split()[0]
    lines[9] = lines[9].replace(lines[9].split()[0], w1, 1)     # row 2 of zone 1 repeats ω of row 1
    p.write_text("".join(lines))
    with pytest.raises(HydroDataError, match=r"RadiationCoefficients\.tec: line 10: frequency 0\.02 appears twice"):
        read_nemoh(run)


def test_multibody_refused(run):
    _edit_line(run / "Nemoh.cal", 7, lambda s: s.replace("1", "2", 1))
    with pytest.raises(HydroDataError, match=r"Nemoh\.cal: line 7: 2 bodies"):
        read_nemoh(run)
