"""Direction coverage of a database and its port–starboard completion (boatland.vessel.directions).

The reference twin: the built-in ctv24 is computed on 0–180° and mirrored by the builder, so ctv24
restricted to 0–180° is the half database a WAMIT/AQWA/NEMOH user would have, and the full ctv24 is
its mirrored 0–355° twin written out explicitly. Both must give the same excitation everywhere.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.freqdomain.rao import excitation_force, free_rao
from boatland.hydro.builtin import load_builtin
from boatland.scenario.scenario import load_scenario
from boatland.sea.spectra import SpectrumPart
from boatland.sea.states import RegularWave, SeaState, excitation_table
from boatland.vessel.directions import (SYMMETRY_RTOL, direction_coverage, direction_problem,
                                            full_circle_excitation, port_starboard_symmetry)
from boatland.checks.physical import check_against
from boatland.landing.setup import Setup


@pytest.fixture(scope="module")
def full():
    return load_builtin("ctv24")


def restrict(db, keep):
    return db.replace(X=db.X[:, keep], wave_dir_deg=db.wave_dir_deg[keep])


@pytest.fixture(scope="module")
def half(full):
    """ctv24 on 0, 5, ..., 180° only."""
    return restrict(full, np.flatnonzero(full.wave_dir_deg <= 180.0))


@pytest.fixture(scope="module")
def asymmetric(half):
    """The half database with a 3 % sway–heave coupling in B (relative to √(B22 B33))."""
    B = half.B.copy()
    c = 0.03 * math.sqrt(np.abs(B[1, 1]).max() * np.abs(B[2, 2]).max())
    B[1, 2] += c * np.exp(-half.omega)
    B[2, 1] += c * np.exp(-half.omega)
    return half.replace(B=B)


def rel_diff(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


# ---------------------------------------------------------------------------------------- coverage
def test_ctv24_is_exactly_symmetric_and_its_half_is_completed(full, half):
    assert direction_coverage(full).kind == "full"
    sym = port_starboard_symmetry(half)
    assert sym.symmetric and sym.coupling < 1e-13          # 2e-15 measured (B's heave–roll round-off)
    cov = direction_coverage(half)
    assert cov.kind == "mirrored" and cov.periodic and cov.step == 5.0
    assert cov.describe().startswith("database directions 0–180° every 5°, completed to 360° by "
                                     "port–starboard symmetry (checked: max coupling ")


def test_completed_table_is_the_mirrored_twin(full, half):
    beta, X = full_circle_excitation(half)
    assert np.array_equal(beta, full.wave_dir_deg)
    assert rel_diff(X, full.X) <= 1e-15
    om_h, b_h, X_h = excitation_table(half)
    om_f, b_f, X_f = excitation_table(full)
    assert np.array_equal(om_h, om_f) and np.array_equal(b_h, b_f) and rel_diff(X_h, X_f) <= 1e-15
    assert half.wave_dir_deg.size == 37  # the database object is unchanged


@pytest.mark.parametrize("beta", [225.0, 270.0, 315.0, -45.0, 187.5, 359.0])
def test_half_and_twin_give_the_same_excitation(full, half, beta):
    w = np.linspace(0.05, 5.0, 61)
    Xh, Xf = excitation_force(half, w, beta), excitation_force(full, w, beta)
    assert rel_diff(Xh, Xf) <= 1e-9
    sway = np.abs(Xh[:, 0, 1]).max()
    assert beta in (187.5, 359.0, -45.0) or sway > 1e5  # 127–288 kN/m in sway, not the periodic-wrap 0


def test_half_and_twin_agree_on_a_dense_grid(full, half):
    w = np.linspace(0.02, 5.0, 97)
    b = np.arange(-360.0, 720.0, 0.37)
    assert rel_diff(excitation_force(half, w, b), excitation_force(full, w, b)) <= 1e-9
    assert rel_diff(free_rao(half, w, [225.0, 300.0]), free_rao(full, w, [225.0, 300.0])) <= 1e-9


def test_half_and_twin_agree_in_the_time_domain(full, half):
    """A short-crested sea (all directions) through wave_excitation: the same force series."""
    sea = SeaState(parts=(SpectrumPart(Hs=1.5, Tp=6.0, direction_deg=200.0, spreading=2.0),))
    kw = dict(seed=4, dt=0.1, n_steps=300, x0=-17.0, y0=3.0, heading_deg=-20.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        Fh, Ff = sea.excitation(half, **kw), sea.excitation(full, **kw)
    assert np.all(np.isfinite(Fh)) and rel_diff(Fh, Ff) <= 1e-9


def test_other_half_circle_180_to_360(full):
    """180, 185, ..., 355, 360°: the half on the other side (360° ≡ 0°) completes too."""
    k = np.flatnonzero(full.wave_dir_deg >= 180.0)
    other = full.replace(X=np.concatenate([full.X[:, k], full.X[:, :1]], axis=1),
                         wave_dir_deg=np.append(full.wave_dir_deg[k], 360.0))
    assert direction_coverage(other).kind == "mirrored"
    w = np.linspace(0.05, 5.0, 41)
    b = np.arange(0.0, 360.0, 2.5)
    assert rel_diff(excitation_force(other, w, b), excitation_force(full, w, b)) <= 1e-9


def test_a_quarter_circle_is_an_interval(full):
    quarter = restrict(full, np.flatnonzero(full.wave_dir_deg <= 90.0))
    cov = direction_coverage(quarter)
    assert cov.kind == "interval" and cov.symmetry is None
    assert "180° gap, 90–270°" in cov.describe()
    assert direction_problem(quarter, [45.0, 90.0]) is None
    assert "valid: 0–90°" in direction_problem(quarter, [135.0])


# ---------------------------------------------------------------------------------------- asymmetric
def test_asymmetric_half_is_refused_outside_and_works_inside(full, asymmetric):
    cov = direction_coverage(asymmetric)
    assert cov.kind == "interval" and not cov.symmetry.symmetric
    assert cov.symmetry.text == "sway–heave coupling 3e-2 in B"
    assert cov.describe() == ("database directions 0–180° every 5°, asymmetric (sway–heave coupling 3e-2 in B): "
                              "directions outside 0–180° refused")
    msg = direction_problem(asymmetric, [90.0, 225.0], name="'x.h5'")
    assert msg == ("225° is outside the directions of database 'x.h5' (0–180°, not port–starboard symmetric: "
                   "sway–heave coupling 3e-2 in B); valid: 0–180°")
    for beta in (225.0, 270.0, 315.0, -1.0, 180.5):
        with pytest.raises(BoatlandInputError, match=r"^beta_deg: .* outside the directions of database"):
            excitation_force(asymmetric, 1.0, beta)
    w = np.linspace(0.05, 5.0, 41)
    b = np.array([0.0, 1e-12, 37.3, 90.0, 179.9, 180.0, 360.0, -360.0, 540.0 - 1e-11])
    assert rel_diff(excitation_force(asymmetric, w, b), excitation_force(full, w, b)) <= 1e-12


def test_asymmetric_half_time_domain_is_refused(asymmetric):
    wave = RegularWave(H=1.0, T=6.0, direction_deg=225.0)
    with pytest.raises(BoatlandInputError, match="225° is outside"):
        wave.excitation(asymmetric, dt=0.1, n_steps=10)
    F = RegularWave(H=1.0, T=6.0, direction_deg=150.0).excitation(asymmetric, dt=0.1, n_steps=10)
    assert np.all(np.isfinite(F))


def test_excitation_at_the_mirror_line_is_checked(half):
    """A sway force in head seas (β = 180°, its own mirror image) is an asymmetry of X itself."""
    X = half.X.copy()
    X[1, -1, :] += 0.01 * np.abs(X[:3]).max()
    cov = direction_coverage(half.replace(X=X))
    assert cov.kind == "interval" and cov.symmetry.text == "sway excitation 1e-2 at 180°"
    assert SYMMETRY_RTOL < 1e-2


def test_bem_round_off_still_counts_as_symmetric(half):
    """Couplings at the level of text output (6 digits) leave the database symmetric."""
    rng = np.random.default_rng(2)
    d = np.abs(np.diagonal(half.A)).max(axis=0)          # largest A_ii per DOF
    noise = 1e-7 * np.sqrt(np.outer(d, d))[:, :, None]   # solver noise in a "zero" coupling, per unit
    A = half.A * (1 + 1e-6 * rng.standard_normal(half.A.shape)) + noise * rng.standard_normal(half.A.shape)
    X = half.X * (1 + 1e-6 * rng.standard_normal(half.X.shape))
    X[1::2, [0, -1]] = 1e-7 * np.abs(half.X).max()  # sway, roll, yaw at 0° and 180°: round-off
    cov = direction_coverage(half.replace(A=A, X=X))
    assert cov.kind == "mirrored" and cov.symmetry.coupling < 1e-5


# ---------------------------------------------------------------------------------------- single direction
def test_single_direction_is_exact_only(full):
    single = restrict(full, [36])  # 180°
    cov = direction_coverage(single)
    assert cov.kind == "single" and cov.describe() == "database with a single direction 180°: other directions refused"
    X = excitation_force(single, 1.0, [180.0, -180.0, 540.0, 180.0 + 1e-10])
    assert np.all(X == X[:, :1])
    assert direction_problem(single, [170.0], name="'one.h5'") == (
        "170° is outside the directions of database 'one.h5' (single direction 180°); valid: 180° only")
    with pytest.raises(BoatlandInputError, match="170° is outside"):
        free_rao(single, 1.0, 170.0)


# ---------------------------------------------------------------------------------------- scenario check
@pytest.fixture(scope="module")
def scenario(repo_root):
    return load_scenario(repo_root / "scenarios" / "ctv24_landing.toml")   # the landing of the ctv24 twins


def test_scenario_check_names_the_direction_key(scenario, asymmetric, half, full):
    sc = scenario.replace({"sea.relative_direction_deg": 225.0})
    check = check_against(Setup.of(sc, asymmetric))
    assert ("sea.relative_direction_deg",
            "225° is outside the directions of database 'ctv24' (0–180°, not port–starboard symmetric: "
            "sway–heave coupling 3e-2 in B); valid: 0–180°") in check.problems
    assert any("asymmetric (sway–heave coupling 3e-2 in B)" in n for n in check.notes)
    assert check_against(Setup.of(sc, half)).ok and check_against(Setup.of(sc, full)).ok
    assert "completed to 360° by port–starboard symmetry" in " ".join(check_against(Setup.of(sc, half)).notes)
    assert "database directions 0–355° every 5°: full circle" in check_against(Setup.of(sc, full)).notes
    assert check_against(Setup.of(scenario.replace({"sea.relative_direction_deg": 135.0}), asymmetric)).ok


def test_scenario_check_global_direction_parts_and_spreading(scenario, asymmetric):
    sea = {"parts": [{"kind": "jonswap", "Hs": 1.0, "Tp": 6.0, "direction_deg": 90.0},
                     {"kind": "pm", "Hs": 0.8, "Tp": 9.0, "relative_direction_deg": 150.0, "spreading": 10.0}]}
    problems = dict(check_against(Setup.of(scenario.replace({"sea": sea}), asymmetric)).problems)
    # heading 0°: global 90° is relative 90° (inside); the spread part covers the whole circle
    assert set(problems) == {"sea.parts[1].spreading"}
    assert "short-crested waves (cos-2s, s = 10) about 150° spread over the whole circle" in problems[
        "sea.parts[1].spreading"]
    sea["parts"][0]["direction_deg"] = 250.0
    problems = dict(check_against(Setup.of(scenario.replace({"sea": sea}), asymmetric)).problems)
    assert problems["sea.parts[0].direction_deg"].startswith(
        "250° (250° relative to the vessel's heading 0°) is outside the directions of database 'ctv24'")
