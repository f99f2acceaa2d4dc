"""One floating hemisphere, three BEM codes, three boatland readers: do they tell the same story?

Data (tests/data/refdata, described in its README.md; public, Apache-2.0, from WEC-Sim/WEC-Sim):

- ``wamit_sphere/``: WAMIT 7.2, examples/BEMIO/WAMIT/Sphere — irregular-frequency removal on
  (``IRR = 1`` in sphere.out);
- ``nemoh_sphere/``: NEMOH v3.0.2, examples/BEMIO/NEMOH/NEMOH_v3.0.2/Sphere — no irregular-frequency
  removal;
- ``capytaine_sphere/sphere_hydrodynamics.nc``: Capytaine 2.3, examples/BEMIO/CAPYTAINE/sphere.

Hemisphere of radius 5 m floating with its centre on the free surface, water depth 50 m, ρ = 1000 kg/m³
(WAMIT is non-dimensional in ρ: read with ``rho=1000``), the same 420 frequencies 0.02–8.4 rad/s,
β = 0. The comparison exercises each reader's units (WAMIT's ρ, ρω, ρg scaling) and phase convention
(NEMOH's and Capytaine's exp(−iωt) conjugated to boatland's exp(+iωt)): a reader that forgets ω on B
is off by a factor ω, one that forgets the conjugation has the opposite heave phase above ~0.5 rad/s.
WAMIT, with irregular frequencies removed, is the reference each other code is compared with.
"""

from __future__ import annotations

import numpy as np
import pytest

from boatland.validation.hemisphere import NEMOH_IRREGULAR, PHASE_TOL, RTOL, band_grid, heave, read_codes
from boatland.validation.hemisphere import compare_codes as compare


@pytest.fixture(scope="module")
def codes(refdata):
    return read_codes(refdata)


@pytest.fixture(scope="module")
def grid(codes):
    """Capytaine's frequencies in the band (the three grids agree to ~1e-7 rad/s)."""
    return band_grid(codes)


def test_units_agree(codes):
    assert {db.rho for db in codes.values()} == {1000.0}
    assert {db.g for db in codes.values()} == {9.81}
    assert {db.water_depth for db in codes.values()} == {50.0}
    for db in codes.values():
        assert db.C[2, 2] == pytest.approx(1000 * 9.81 * np.pi * 5**2, rel=0.005)    # ρ g π a²


def test_capytaine_matches_wamit(codes, grid):
    d = compare(codes["CAPYTAINE"], codes["WAMIT"], grid, np.ones(grid.size, bool))
    # measured: A33 1.9 %, B33 2.6 % (at 3 rad/s), |X3| 1.0 %, phase 0.017 rad (1.0°)
    assert max(d["A33"], d["B33"], d["|X3|"]) < RTOL, d
    assert d["phase"] < PHASE_TOL, d


def test_nemoh_matches_wamit_outside_irregular_frequency(codes, grid):
    mask = (grid < NEMOH_IRREGULAR[0]) | (grid > NEMOH_IRREGULAR[1])
    d = compare(codes["NEMOH"], codes["WAMIT"], grid, mask)
    # measured: A33 1.8 %, B33 2.1 %, |X3| 1.9 % (all near the window or at 3 rad/s), phase 0.012 rad
    assert max(d["A33"], d["B33"], d["|X3|"]) < RTOL, d
    assert d["phase"] < PHASE_TOL, d


def test_nemoh_irregular_frequency(codes, grid):
    """The excluded window holds NEMOH's irregular-frequency resonance, and only NEMOH's."""
    window = (grid >= NEMOH_IRREGULAR[0]) & (grid <= NEMOH_IRREGULAR[1])
    n, w, c = (heave(codes[k], grid) for k in ("NEMOH", "WAMIT", "CAPYTAINE"))
    err_nemoh = np.abs(n["B33"] - w["B33"]) / w["B33"]
    err_cpt = np.abs(c["B33"] - w["B33"]) / w["B33"]
    peak = grid[np.argmax(np.where(window, err_nemoh, 0))]
    assert err_nemoh[window].max() > 0.5 and err_cpt[window].max() < RTOL
    assert peak**2 * 5.0 / 9.81 == pytest.approx(2.56, abs=0.05)          # Ka of the spike


def test_long_wave_phases(codes):
    """At the lowest frequency of each file the heave force is in phase with the crest (all three)."""
    for name, db in codes.items():
        assert abs(np.angle(db.X[2, 0, 0], deg=True)) < 1.0, name
        assert np.angle(db.X[0, 0, 0], deg=True) == pytest.approx(90.0, abs=1.0), name
