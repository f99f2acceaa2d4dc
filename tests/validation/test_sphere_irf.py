"""Hemisphere radiation IRF against the IRF stored in the same BEMIO file.

Data: NREL/HydroChrono demos/sphere/hydroData/sphere.h5 (WAMIT hemisphere, radius 5 m), whose
``impulse_response_fun`` was computed by BEMIO from the same B(ω): K33(0)/ρ = 96.70 m³/s².
Cummins relations: San Nicolás Méndez (2024), DTU MSc thesis, eq. 3.41–3.42. ``boatland validate``
(case sphere-irf) runs the same code.
"""

import pytest

from boatland.validation.hemisphere import irf_case, irf_errors


@pytest.fixture(scope="module")
def case(refdata):
    return irf_case(refdata)


def test_k33_at_zero_and_rms(case):
    db, mem, t_ref, K_ref = case
    assert K_ref[0] / db.rho == pytest.approx(96.70, abs=0.005)
    e = irf_errors(mem, t_ref, K_ref)
    assert e["K0"] < 0.005                            # measured 0.05 %
    assert e["rms"] < 0.01                            # measured 0.12 %


def test_round_trip_b_and_a(case):
    _, mem, _, _ = case
    assert mem.irf.err_B[2, 2] < 0.01                 # measured 0.06 %
    assert mem.irf.err_A[2, 2] < 0.02                 # measured 0.04 %
    assert mem.irf.A_inf_source == "solver"
