"""Time domain against frequency domain: steady regular-wave response equals the RAO (seed 000 eq. 3.31).

.. math:: \\hat x(\\omega) = \\left[-\\omega^2 (M + A(\\omega)) + i\\omega B(\\omega) + C\\right]^{-1} X(\\omega, \\beta)\\, a

The frequency domain is :func:`boatland.freqdomain.free_rao`. Both from the same database: the
hemisphere of HydroChrono's sphere.h5 (WAMIT), mass ρV, free floating, no additional damping. The
time-domain amplitude and phase come from a least-squares fit of c₀ + c₁t + Re{x̂ e^{iωt}} over the
last 10 periods (:func:`boatland.freqdomain.first_harmonic`; the trend absorbs the slow surge drift
of the start-up: surge has no restoring).
"""

import numpy as np
import pytest

from boatland.freqdomain import first_harmonic, free_rao
from boatland.hydro.bemio import read_bemio
from boatland.irf.impulse import IRFSettings
from boatland.model.hydrodb import rigid_body_mass_matrix
from boatland.model.motion import compile_motion
from boatland.model.radiation import radiation_memory
from boatland.model.seastate import RegularWave


@pytest.fixture(scope="module")
def hemisphere(refdata):
    db = read_bemio(refdata / "bemio_sphere" / "sphere.h5")
    m = db.rho * db.disp_vol
    db = db.replace(M=rigid_body_mass_matrix(m, db.cog, 2 / 5 * m * 25 * np.ones(3), np.zeros(3)))
    return db, radiation_memory(db, IRFSettings(t_max=30.0, dt=0.01), fit=False)


@pytest.mark.parametrize("w", [0.5, 0.8, 1.1, 1.4, 1.8, 2.4, 3.0])
def test_heave_surge_pitch_raos(hemisphere, w):
    db, mem = hemisphere
    dt = min(0.05, 2 * np.pi / w / 60)
    T = 2 * np.pi / w
    n = int(round((6 * T + 40 * T) / dt))
    wave = RegularWave(H=0.2, T=T, direction_deg=0.0, water_depth=db.water_depth, g=db.g)
    F = wave.excitation(db, dt=dt, n_steps=n, ramp_time=6 * T)
    r = compile_motion(db, mem, dt).run(dt, n, F_ext=F)
    t, x = r["t"], r["x"]
    assert r["status"] == 0
    expected = 0.1 * free_rao(db, w, beta_deg=0.0)[0, 0]  # a = 0.1 m (linear: the amplitude only scales)
    for d in (0, 2, 4):
        got = first_harmonic(t, x[:, d], w)
        assert abs(got - expected[d]) < 0.02 * abs(expected[d]), (d, got, expected[d])
