"""Hemisphere radiation IRF against the IRF stored in the same BEMIO file.

Data: NREL/HydroChrono demos/sphere/hydroData/sphere.h5 (WAMIT hemisphere, radius 5 m), whose
``impulse_response_fun`` was computed by BEMIO from the same B(ω): K33(0)/ρ = 96.70 m³/s².
Cummins relations: seed 000 eq. 3.41–3.42.
"""

import h5py
import numpy as np
import pytest

from boatland.hydro.bemio import read_bemio
from boatland.irf.impulse import IRFSettings
from boatland.model.radiation import radiation_memory


@pytest.fixture(scope="module")
def case(refdata):
    path = refdata / "bemio_sphere" / "sphere.h5"
    db = read_bemio(path)
    with h5py.File(path) as f:
        g = f["body1/hydro_coeffs/radiation_damping/impulse_response_fun"]
        t_ref, K_ref = g["t"][:, 0], g["K"][2, 2] * db.rho
    mem = radiation_memory(db, IRFSettings(t_max=15.0, dt=0.015, check_band=(0.3, 5.0)), fit=False)
    return db, mem, t_ref, K_ref


def test_k33_at_zero_and_rms(case):
    db, mem, t_ref, K_ref = case
    assert K_ref[0] / db.rho == pytest.approx(96.70, abs=0.005)
    K = np.interp(t_ref, mem.irf.t, mem.irf.K[2, 2])
    assert abs(K[0] / K_ref[0] - 1) < 0.005          # measured 0.05 %
    rms = np.sqrt(np.mean((K - K_ref) ** 2)) / np.sqrt(np.mean(K_ref ** 2))
    assert rms < 0.01                                 # measured 0.12 %


def test_round_trip_b_and_a(case):
    _, mem, _, _ = case
    assert mem.irf.err_B[2, 2] < 0.01                 # measured 0.06 %
    assert mem.irf.err_A[2, 2] < 0.02                 # measured 0.04 %
    assert mem.irf.A_inf_source == "solver"
