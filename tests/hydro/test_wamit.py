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


# ----------------------------------------------------------------- mean drift (.8 / .9)
# MSS's semi-submersible (tests/data/refdata/wamit_semisub, MIT; see its README.md): .1, .3, .hst and the
# pressure-integration mean drift .9, no .out (ULEN 1, deep water).

@pytest.fixture(scope="module")
def semisub(refdata):
    return read_wamit(refdata / "wamit_semisub" / "semisub.1", rho=1025.0, g=9.81)


@pytest.fixture
def semisub_run(refdata, tmp_path):
    for f in (refdata / "wamit_semisub").iterdir():
        shutil.copy(f, tmp_path / f.name)
    return tmp_path


def test_semisub_drift_is_read_and_scaled(semisub, refdata):
    """Re of the BETA1 = BETA2 rows times ρ g L (forces) and ρ g L² (moments); the body-fixed moments
    (I = −4, −5, −6: 29 periods × 19 headings × 3) are skipped and said so."""
    D = semisub.drift
    assert D.shape == (6, 19, 29) and semisub.wave_dir_deg.tolist() == list(range(0, 181, 10))
    k = int(np.argmin(np.abs(semisub.omega - 2 * np.pi / 4.5)))      # first rows of the file: PER 4.5 s, 0°
    rho_g = 1025.0 * 9.81
    assert D[0, 0, k] == pytest.approx(1.309227e01 * rho_g, rel=1e-12)
    assert D[2, 0, k] == pytest.approx(7.384665e00 * rho_g, rel=1e-12)
    assert D[4, 0, k] == pytest.approx(1.165086e02 * rho_g, rel=1e-12)
    assert D[5, 1, k] == pytest.approx(2.688983e01 * rho_g, rel=1e-12)   # 10°, I = 6 (not the −6 row)
    note = next(n for n in semisub.provenance.notes if n.startswith("mean drift:"))
    assert "pressure integration" in note and "semisub.9" in note and "1653 body-fixed moment rows" in note
    assert "DOFs given: surge, sway, heave, roll, pitch, yaw" in note


def test_semisub_drift_has_the_physics_of_a_symmetric_hull(semisub):
    """Down-wave in head, following and beam seas; no sway or yaw drift in them; fore–aft symmetry
    (β → 180° − β: F_x, M_z change sign, F_y, F_z keep it) to the file's precision."""
    D = semisub.drift
    big = np.abs(D).max(axis=(1, 2))
    i0, i90, i180 = 0, 9, 18
    assert np.all(D[0, i0] > -1e-6 * big[0]) and np.all(D[0, i180] < 1e-6 * big[0])
    assert np.all(D[1, i90] > -1e-3 * big[1])
    for i in (1, 5):
        assert np.abs(D[i, [i0, i180]]).max() < 1e-5 * big[i]
    assert np.abs(D[5, i90]).max() < 1e-5 * big[5]
    assert np.allclose(D[0], -D[0, ::-1], rtol=0, atol=1e-4 * big[0])
    assert np.allclose(D[1], D[1, ::-1], rtol=0, atol=1e-4 * big[1])
    assert np.allclose(D[5], -D[5, ::-1], rtol=0, atol=1e-3 * big[5])


def test_drift_file_as_the_path_and_read_hydro(refdata, semisub):
    db, fmt = read_hydro(refdata / "wamit_semisub" / "semisub.9", rho=1025.0, g=9.81)
    assert fmt == "wamit" and np.array_equal(db.drift, semisub.drift) and np.array_equal(db.X, semisub.X)
    assert read_hydro(refdata / "wamit_semisub" / "semisub.1", drift="none")[0].drift is None
    assert read_wamit(refdata / "wamit_semisub" / "semisub.1", drift="momentum").drift is None   # no .8
    assert read_wamit(refdata / "wamit_sphere" / "sphere.1").drift is None                       # no drift files


def test_momentum_file_is_preferred_on_request(semisub_run, semisub):
    """A .8 (momentum conservation) beside the .9. No public .8 was found: this one is the .9's own
    surge, sway and yaw rows (the same 8-column layout, WAMIT manual §4.8), halved to tell them apart."""
    rows = []
    for line in (semisub_run / "semisub.9").read_text().splitlines():
        t = line.split()
        if t[3] in ("1", "2", "6"):
            t[6] = f"{float(t[6]) / 2:.6E}"
            rows.append("  ".join(t))
    (semisub_run / "semisub.8").write_text("\n".join(rows) + "\n")
    auto = read_wamit(semisub_run / "semisub.1", rho=1025.0, g=9.81)
    assert np.array_equal(auto.drift, semisub.drift)                                  # .9 by default
    mom = read_wamit(semisub_run / "semisub.1", rho=1025.0, g=9.81, drift="momentum")
    assert np.allclose(mom.drift[[0, 1, 5]], semisub.drift[[0, 1, 5]] / 2, rtol=1e-6, atol=1e-9)
    assert np.all(mom.drift[[2, 3, 4]] == 0)
    note = next(n for n in mom.provenance.notes if n.startswith("mean drift:"))
    assert "momentum conservation" in note and "heave, roll, pitch not in the file (0)" in note
    (semisub_run / "semisub.9").unlink()
    assert np.array_equal(read_wamit(semisub_run / "semisub.1", rho=1025.0, g=9.81).drift, mom.drift)


def test_drift_length_scale(semisub_run, semisub):
    """ULEN = 2 (from a .out): drift forces × 2, moments × 4."""
    (semisub_run / "semisub.out").write_text(" Gravity:     9.81000                Length scale:        2.00000\n"
                                             " Water depth:        infinite\n")
    db = read_wamit(semisub_run / "semisub.1", rho=1025.0)
    assert np.allclose(db.drift[:3], semisub.drift[:3] * 2, rtol=1e-14)
    assert np.allclose(db.drift[3:], semisub.drift[3:] * 4, rtol=1e-14)


def test_bad_drift_files(semisub_run, refdata):
    p = semisub_run / "semisub.9"
    good = p.read_text()
    p.write_text("".join(good.splitlines(keepends=True)[:-200]))
    with pytest.raises(HydroDataError, match=r"semisub\.9: line \d+: the data end here without drift at PER"):
        read_wamit(semisub_run / "semisub.1")
    p.write_text(good.replace("0.450000E+01", "0.460000E+01", 1))
    with pytest.raises(HydroDataError, match=r"semisub\.9: line 1: period PER = 4\.6 s is not among the \.1"):
        read_wamit(semisub_run / "semisub.1")
    lines = good.splitlines(keepends=True)
    lines[4] = " ".join(lines[4].split()[:7]) + "\n"
    p.write_text("".join(lines))
    with pytest.raises(HydroDataError, match=r"line 5: expected 'PER BETA1 BETA2 I Mod Pha Re Im' \(8 columns\), found 7"):
        read_wamit(semisub_run / "semisub.1")
    with pytest.raises(HydroDataError, match="drift: unknown choice 'far'"):
        read_wamit(refdata / "wamit_semisub" / "semisub.1", drift="far")
