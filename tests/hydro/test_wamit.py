"""WAMIT reader on WEC-Sim's hemisphere (tests/data/refdata/wamit_sphere, Apache-2.0; see its README.md)."""

from __future__ import annotations

import re
import shutil

import numpy as np
import pytest

from boatland.errors import HydroDataError
from boatland.hydro import read_hydro
from boatland.hydro.wamit import read_wamit


@pytest.fixture(scope="module")
def sphere(refdata):
    return read_wamit(refdata / "wamit_sphere" / "sphere.1")


@pytest.fixture
def run(refdata, tmp_path):
    """A writable copy of the WAMIT run; returns the folder."""
    for f in (refdata / "wamit_sphere").iterdir():
        shutil.copy(f, tmp_path / f.name)
    return tmp_path


def _lines(path):
    return path.read_text().splitlines(keepends=True)


def _edit_line(path, lineno, fn):
    lines = _lines(path)
    lines[lineno - 1] = fn(lines[lineno - 1])
    path.write_text("".join(lines))


def test_shapes_and_metadata(sphere):
    nf = 420
    assert sphere.omega.shape == (nf,)
    assert sphere.omega[0] == pytest.approx(0.02, rel=1e-5) and sphere.omega[-1] == pytest.approx(8.4, rel=1e-5)
    assert np.all(np.diff(sphere.omega) > 0)
    assert sphere.A.shape == sphere.B.shape == (6, 6, nf)
    assert sphere.X.shape == (6, 1, nf)
    assert np.all(np.isfinite(sphere.A)) and np.all(np.isfinite(sphere.X))
    assert sphere.wave_dir_deg.tolist() == [0.0]
    assert sphere.provenance.solver == "WAMIT"
    assert sphere.provenance.created == "2016-12-05T10:06:31"
    assert sphere.M is None
    # .out: g, depth, ZBODY = -2 (body origin 2 m below the waterline), volumes, centres
    assert sphere.g == 9.81 and sphere.water_depth == 50.0
    assert sphere.ref_point == pytest.approx([0, 0, -2])
    assert sphere.cog == pytest.approx([0, 0, -2])
    assert sphere.cob == pytest.approx([0, 0, -2 + 0.126361])
    assert sphere.disp_vol == pytest.approx(261.363)


def test_assumed_rho_is_noted(sphere):
    assert sphere.rho == 1025.0
    assert "ρ not stored in WAMIT files: assumed 1025 kg/m³ (pass rho=...)" in sphere.provenance.notes


def test_dimensional_scaling(sphere, refdata):
    """A = Ā ρ L^k, B = B̄ ρ ω L^k, C = C̄ ρ g L^m with ULEN = 1: check against the raw file rows."""
    rho = sphere.rho
    # .1 line 75: first row of PER = 314.1593 (ω = 0.02): "1 1 1.309067E+02 3.143692E-04"
    assert sphere.A[0, 0, 0] == pytest.approx(1.309067e2 * rho, rel=1e-6)
    assert sphere.B[0, 0, 0] == pytest.approx(3.143692e-4 * rho * 2 * np.pi / 314.1593, rel=1e-5)
    assert sphere.C[2, 2] == pytest.approx(7.848768e1 * rho * 9.81, rel=1e-6)
    assert sphere.A_inf[2, 2] == pytest.approx(1.308590e2 * rho)     # PER = 0 → ω = ∞
    assert sphere.A_0[2, 2] == pytest.approx(2.015387e2 * rho)       # PER = -1 → ω = 0
    # hemisphere: A∞33 = ρ V / 2 (half the displaced mass), V = 2/3 π a³
    assert sphere.A_inf[2, 2] / (rho * 2 / 3 * np.pi * 5**3) == pytest.approx(0.5, rel=2e-3)
    db1000 = read_wamit(refdata / "wamit_sphere" / "sphere.1", rho=1000.0)
    assert db1000.A == pytest.approx(sphere.A * 1000 / 1025)
    assert not any("ρ not stored" in n for n in db1000.provenance.notes)


def test_known_phases(sphere):
    """Lowest ω = 0.02 rad/s: kR = ω²R/g = 2e-4, so finite-size phase corrections are O(kR) rad ≈ 0.01°.

    1° is far above that and far below the 90°/180° of a mixed-up convention.
    """
    X = sphere.X[:, 0, 0]
    assert np.angle(X[2], deg=True) == pytest.approx(0.0, abs=1.0)      # heave in phase with the crest
    assert np.angle(X[0], deg=True) == pytest.approx(90.0, abs=1.0)     # surge leads by 90° (β = 0)


def test_negative_damping_above_8_2_rad_s_is_kept(sphere):
    """Reference WAMIT data really has B33 < 0 above ~8.2 rad/s (tests/data/refdata/README.md): the reader keeps it."""
    neg = sphere.omega[sphere.B[2, 2] < 0]
    assert neg.size > 0 and neg.min() > 8.1


@pytest.mark.parametrize("name", ["sphere.3", "sphere.hst", "sphere.out"])
def test_any_file_of_the_run(refdata, sphere, name):
    db = read_wamit(refdata / "wamit_sphere" / name)
    assert np.array_equal(db.A, sphere.A) and np.array_equal(db.X, sphere.X)


def test_files_without_header_line(run, sphere):
    for name in ("sphere.1", "sphere.3", "sphere.hst"):
        p = run / name
        p.write_text("".join(_lines(p)[1:]))
    db = read_wamit(run / "sphere.1")
    assert np.array_equal(db.A, sphere.A) and np.array_equal(db.X, sphere.X) and np.array_equal(db.C, sphere.C)


def test_without_out_file(run, sphere):
    (run / "sphere.out").unlink()
    db = read_wamit(run / "sphere.1", g=9.81)
    assert db.A == pytest.approx(sphere.A) and db.water_depth == np.inf
    assert any("no sphere.out" in n for n in db.provenance.notes)
    db = read_wamit(run / "sphere.1")
    assert any("assumed g = 9.81" in n for n in db.provenance.notes)


def test_length_scale_exponents(run, sphere):
    """ULEN = 2: A, B scale with L^3, L^4, L^5; C with L^2, L^3, L^4; X with L^2 (forces), L^3 (moments)."""
    p = run / "sphere.out"
    p.write_text(p.read_text().replace("Length scale:        1.00000", "Length scale:        2.00000"))
    db = read_wamit(run / "sphere.1")
    for (i, j), k in {(0, 0): 3, (0, 4): 4, (4, 0): 4, (3, 3): 5, (2, 2): 3}.items():
        assert db.A[i, j] == pytest.approx(sphere.A[i, j] * 2.0**k)
        assert db.B[i, j] == pytest.approx(sphere.B[i, j] * 2.0**k)
    for (i, j), m in {(2, 2): 2, (2, 4): 3, (3, 3): 4}.items():
        assert db.C[i, j] == pytest.approx(sphere.C[i, j] * 2.0**m)
    assert db.X[0] == pytest.approx(sphere.X[0] * 4) and db.X[4] == pytest.approx(sphere.X[4] * 8)


def test_directions_mapped_and_merged(run, sphere):
    """A heading of 360° is 0°; −90° is 270°: mapped to [0, 360), merged, sorted, and noted."""
    p = run / "sphere.3"
    lines = p.read_text().splitlines(keepends=True)
    rows = lines[1:]
    p.write_text("".join(lines + [r.replace("0.000000E+00", "3.600000E+02", 1) for r in rows]
                         + [r.replace("0.000000E+00", "-9.000000E+01", 1) for r in rows]))
    db = read_wamit(run / "sphere.1")
    assert db.wave_dir_deg.tolist() == [0.0, 270.0]
    assert np.array_equal(db.X[:, 0], sphere.X[:, 0])
    assert any("directions 0°, 360° are the same" in n for n in db.provenance.notes)


def test_read_hydro_detects_wamit(refdata):
    db, fmt = read_hydro(refdata / "wamit_sphere" / "sphere.1", rho=1000.0)
    assert fmt == "wamit" and db.rho == 1000.0


# ------------------------------------------------------------------------------ bad input
def test_missing_file(tmp_path):
    with pytest.raises(HydroDataError, match=r"nothing\.1: file not found"):
        read_wamit(tmp_path / "nothing.1")


def test_missing_dot3_is_named(run):
    (run / "sphere.3").unlink()
    with pytest.raises(HydroDataError, match=r"sphere\.3: file not found; expected the WAMIT \.3 file"):
        read_wamit(run / "sphere.1")


def test_truncated_dot1(run):
    p = run / "sphere.1"
    lines = _lines(p)
    p.write_text("".join(lines[:1000]) + lines[1000][:20])      # cut in the middle of line 1001
    with pytest.raises(HydroDataError, match=r"sphere\.1: line 1001: expected 'PER I J Abar Bbar'") as exc:
        read_wamit(p)
    assert exc.value.where == "line 1001"


def test_truncated_dot3(run):
    p = run / "sphere.3"
    p.write_text("".join(_lines(p)[:1201]))                     # whole lines: frequencies missing
    with pytest.raises(HydroDataError, match=r"sphere\.3: line 1201: the data end here without excitation"):
        read_wamit(run / "sphere.1")


def test_garbled_number(run):
    _edit_line(run / "sphere.1", 100, lambda s: s.replace("E", "x", 1))
    with pytest.raises(HydroDataError, match=r"sphere\.1: line 100: expected .*found '"):
        read_wamit(run / "sphere.1")


def test_wrong_kind_of_file(run, refdata):
    shutil.copy(refdata / "nemoh_sphere" / "Nemoh.cal", run / "sphere.1")
    with pytest.raises(HydroDataError, match=r"sphere\.1: line 2: expected 'PER I J Abar Bbar'"):
        read_wamit(run / "sphere.1")


def test_dot3_in_place_of_hst(run):
    shutil.copy(run / "sphere.3", run / "sphere.hst")
    with pytest.raises(HydroDataError, match=r"sphere\.hst: line 2: expected 'I J Cbar' \(3 columns\), found 7"):
        read_wamit(run / "sphere.1")


def test_nan_value(run):
    _edit_line(run / "sphere.3", 50, lambda s: re.sub(r"\S+$", "NaN", s.rstrip()) + "\n")
    with pytest.raises(HydroDataError, match=r"sphere\.3: line 50: expected finite .*'NaN'"):
        read_wamit(run / "sphere.1")


def test_duplicate_frequency(run):
    p = run / "sphere.1"
    lines = _lines(p)
    block = [ln for ln in lines[1:] if ln.split()[0] == "3.141593E+02"]
    p.write_text("".join(lines + block))                        # ω = 0.02 appears twice
    with pytest.raises(HydroDataError, match=rf"sphere\.1: line {len(lines) + 1}: duplicate entry PER=314\.159"):
        read_wamit(p)


def test_dof_beyond_6_is_refused(run):
    _edit_line(run / "sphere.hst", 3, lambda s: s.replace("     1     2", "     1     7", 1))
    with pytest.raises(HydroDataError, match=r"sphere\.hst: line 3: J = 7: multi-body"):
        read_wamit(run / "sphere.1")


def test_not_a_wamit_suffix(tmp_path):
    with pytest.raises(HydroDataError, match=r"run\.txt: not a WAMIT output file"):
        read_wamit(tmp_path / "run.txt")
