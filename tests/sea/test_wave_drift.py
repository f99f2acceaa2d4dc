"""The wave drift of a sea on the vessel (boatland.sea.drift): the mean Σ a_i² D_i and Newman's slowly varying
force by hand on a synthetic drift table, and the drift in a trial."""

import numpy as np
import pytest

from boatland.sea.drift import drift_at, drift_series, mean_drift
from boatland.sea.spectra import SpectrumPart
from boatland.sea.states import SeaState
from boatland.trial.simulate import simulate


@pytest.fixture(scope="module")
def drift_db(box_db):
    """The box vessel with a drift table: surge −(1 + ω) kN/m², sway 0, yaw a sign-changing 10 (ω − 1) kN m/m²."""
    w = box_db.omega
    D = np.zeros((6, box_db.n_dir, w.size))
    D[0] = -1e3 * (1 + w)
    D[5] = 1e4 * (w - 1.0)
    return box_db.replace(drift=D)


def sea(Hs=1.0, direction=180.0):
    return SeaState(parts=SpectrumPart(Hs=Hs, Tp=7.0, direction_deg=direction))


def test_mean_drift_is_the_sum_of_the_components_by_hand(drift_db):
    comps = sea().realise(3, 600.0)
    D = drift_at(drift_db, comps, 0.0)
    w = comps.omega
    inside = w <= drift_db.omega[-1]
    expect = -1e3 * (1 + w) * inside                 # linear in ω: the table's interpolation is exact
    assert np.allclose(D[0], np.where(w >= drift_db.omega[0], expect, D[0]), rtol=1e-12)
    assert mean_drift(drift_db, comps, 0.0)[0] == pytest.approx(float(np.sum(comps.a ** 2 * D[0])))
    F = drift_series("mean", drift_db, comps, dt=0.05, n_steps=100, x0=0.0, y0=0.0, heading_deg=0.0)
    assert np.all(F[:, 0] == F[0, 0]) and F[0, 0] < 0 and np.all(F[:, 1] == 0)


def test_newman_in_a_regular_wave_and_in_a_sea_by_direct_sums(drift_db):
    from boatland.sea.states import RegularWave

    # a regular wave: F = a² D (1 + cos 2φ(t)), its mean over whole periods exactly a² D
    reg = RegularWave(H=1.0, T=8.0, direction_deg=180.0).realise(0, 800.0)
    F = drift_series("newman", drift_db, reg, dt=0.05, n_steps=16000, x0=0.0, y0=0.0, heading_deg=0.0)
    aD = mean_drift(drift_db, reg, 0.0)
    assert F[:-1, 0].mean() == pytest.approx(aD[0], rel=1e-9) and F[:, 0].max() == pytest.approx(0.0, abs=1e-9)
    assert F[:, 0].min() == pytest.approx(2 * aD[0], rel=1e-6)
    # a sea: 2 s(t) σ(t) by direct sums at a few times, the phases at the reference point (x0, y0)
    comps = sea().realise(5, 600.0)
    x0, y0 = 10.0, -3.0
    F = drift_series("newman", drift_db, comps, dt=0.1, n_steps=3000, x0=x0, y0=y0, heading_deg=0.0)
    D = drift_at(drift_db, comps, 0.0)
    ph = comps.phi - comps.k * (x0 * np.cos(comps.theta) + y0 * np.sin(comps.theta))
    for k in (0, 777, 4321, 6000):
        t = 0.05 * k
        c = comps.a * np.cos(comps.omega * t + ph)
        for j in (0, 5):
            s = np.sum(np.sqrt(np.abs(D[j])) * c)
            sig = np.sum(np.sign(D[j]) * np.sqrt(np.abs(D[j])) * c)
            assert F[k, j] == pytest.approx(2 * s * sig, rel=1e-9, abs=1e-9 * np.abs(D[j]).max())
    assert np.all(F[:, 0] <= 1e-9)                   # D ≤ 0 everywhere: 2 s σ = −2 s² never pushes the other way


def test_drift_in_a_trial_is_added_to_the_excitation(drift_db):
    import box_vessel

    drift_db = drift_db.replace(drift=np.where(np.arange(6)[:, None, None] == 0, drift_db.drift, 0.0))  # surge only
    base = box_vessel.make({"simulation.duration": 60.0})
    with_drift = box_vessel.make({"simulation.duration": 60.0, "sea.drift": "mean"})
    r0 = simulate(base, drift_db)
    r1 = simulate(with_drift, drift_db)
    d = r1.F_exc - r0.F_exc
    late = r0.t > 40
    assert np.all(d[late, 0] < 0) and np.allclose(d[late, 0], d[late, 0][0])
    assert d[r0.t < 9.0, 0].max() == 0.0             # before the waves start, no drift either
    with pytest.raises(Exception, match="no mean drift coefficients"):
        simulate(with_drift, box_vessel.box_vessel_db())
