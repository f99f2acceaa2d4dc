"""State-space fits: stable by construction, passive, impulse response matches K."""

import numpy as np
import pytest

from boatland.hydro.bemio import read_bemio
from boatland.irf.impulse import IRFSettings
from boatland.irf.statespace import fit_pair, frequency_response, impulse_response
from boatland.vessel.radiation import radiation_memory


@pytest.fixture(scope="module")
def sphere_memory(refdata):
    db = read_bemio(refdata / "bemio_sphere" / "sphere.h5")
    return db, radiation_memory(db, IRFSettings(t_max=15, dt=0.015, check_band=(0.3, 5.0)))


def test_hemisphere_heave_fit_order_and_r2(sphere_memory):
    db, mem = sphere_memory
    fit = mem.state_space.pairs[(2, 2)]
    assert fit.order <= 6 and fit.r2 >= 0.99
    assert np.max(np.linalg.eigvals(fit.A).real) < 0
    # the realisation's impulse response is the fitted K
    Kfit = impulse_response(fit, mem.irf.t)
    r2 = 1 - np.sum((Kfit - mem.irf.K[2, 2]) ** 2) / np.sum((mem.irf.K[2, 2] - mem.irf.K[2, 2].mean()) ** 2)
    assert r2 == pytest.approx(fit.r2, abs=1e-9)


def test_every_fit_stable_and_passive(sphere_memory):
    db, mem = sphere_memory
    ss = mem.state_space
    assert set(ss.pairs) == {(i, j) for i in range(6) for j in range(6) if mem.irf.significant[i, j]}
    assert all(f.stable for f in ss.pairs.values())
    assert np.nanmin(ss.passivity) >= -0.01
    for (i, j), f in ss.pairs.items():
        assert abs(frequency_response(f, np.array([1e-9]))[0]) < 1e-6 * np.max(np.abs(db.B[i, j]))  # B̂(0) = 0


def test_unstable_poles_are_reflected():
    """A growing oscillation cannot be fitted by an unstable system: poles end in the left half-plane."""
    t = np.linspace(0, 10, 1001)
    K = np.exp(0.05 * t) * np.cos(2 * t) - np.exp(-t)
    fit = fit_pair(t, K, target_r2=0.999, max_order=6)
    assert fit.stable
