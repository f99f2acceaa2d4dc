"""The Gaussian sea driven by standard-normal coefficients (boatland.sea.gaussian): its fixed grid,
its variance, its FFT series against the components' cosines, and the time-domain trial running on
exactly its components (simulate(waves=...))."""

import math
import warnings

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.hydro.builtin import load_builtin
from boatland.sea.gaussian import GaussianSea, fft_length
from boatland.scenario.scenario import scenario_from_dict
from boatland.sea.spectra import SpectrumPart
from boatland.sea.states import SeaState, wave_excitation
from boatland.trial.simulate import simulate, wave_ramp
from boatland.landing.setup import Setup


def sea(**kw):
    return SeaState(parts=(SpectrumPart(Hs=1.0, Tp=7.0, direction_deg=180.0),
                           SpectrumPart(Hs=0.5, Tp=12.0, kind="pm", direction_deg=135.0)), **kw)


def test_fft_lengths_are_small_primes_and_not_short():
    for n in (1, 7, 97, 1201, 36001):
        m = fft_length(n)
        assert m >= n and m < 1.25 * n + 2
        while m % 2 == 0:
            m //= 2
        for p in (3, 5):
            while m % p == 0:
                m //= p
        assert m == 1


def test_grid_is_deterministic_covers_the_band_and_does_not_repeat_within_the_record():
    g = GaussianSea(sea=sea(), dt=0.05, n_steps=2400)
    assert g.delta_omega <= 2 * math.pi / (2400 * 0.05) and g.period >= 2400 * 0.05
    np.testing.assert_allclose(g.omega, (g.m + 0.5) * g.delta_omega, rtol=0, atol=1e-15)
    for i, p in enumerate(g.sea.parts):
        lo, hi = g.sea.band(i)
        w = g.omega[g.part == i]
        assert w.min() - g.delta_omega / 2 <= lo and w.max() + g.delta_omega / 2 >= hi
        # variance of the part in its bins: Hs 4√m0 of the spectrum, less the band's tail (0.2 %)
        assert 4 * math.sqrt(np.sum(g.sigma[g.part == i] ** 2)) == pytest.approx(p.Hs, rel=2e-3)
    np.testing.assert_array_equal(GaussianSea(sea=sea(), dt=0.05, n_steps=2400).omega, g.omega)
    assert g.n_coefficients == 2 * g.size


def test_fft_series_is_the_sum_of_the_components_cosines():
    g = GaussianSea(sea=sea(), dt=0.1, n_steps=1500)
    u = np.random.default_rng(2).standard_normal(g.n_coefficients)
    c = g.with_u(u).components()
    t = np.arange(g.n_steps + 1) * g.dt
    direct = np.cos(np.outer(t, c.omega) + c.phi) @ c.a
    np.testing.assert_allclose(g.elevation_series(u), direct, rtol=0, atol=1e-12 * np.abs(direct).max())
    # η = Σ σ (u_2i cos ωt + u_2i+1 sin ωt) at the origin
    manual = np.cos(np.outer(t, g.omega)) @ (g.sigma * u[0::2]) + np.sin(np.outer(t, g.omega)) @ (g.sigma * u[1::2])
    np.testing.assert_allclose(direct, manual, rtol=0, atol=1e-12 * np.abs(direct).max())


def test_u_standard_normal_gives_the_spectrum_variance():
    g = GaussianSea(sea=SeaState(parts=SpectrumPart(Hs=2.0, Tp=8.0)), dt=0.2, n_steps=600)
    rng = np.random.default_rng(8)
    eta = np.array([g.elevation_series(rng.standard_normal(g.n_coefficients))[::50] for _ in range(2000)])
    var = np.sum(g.sigma ** 2)
    # 2000 × 13 nearly independent values: the sample variance is within 3 % (4 standard errors)
    assert eta.var() == pytest.approx(var, rel=0.03)


def test_bad_input_is_refused():
    with pytest.raises(BoatlandInputError, match="long-crested"):
        GaussianSea(sea=SeaState(parts=SpectrumPart(Hs=1.0, Tp=7.0, spreading=10.0)), dt=0.05, n_steps=100)
    g = GaussianSea(sea=sea(), dt=0.05, n_steps=100)
    with pytest.raises(BoatlandInputError, match="coefficients"):
        g.with_u(np.zeros(3))
    with pytest.raises(BoatlandInputError, match="finite"):
        g.with_u(np.full(g.n_coefficients, np.nan))
    with pytest.raises(ValueError, match="no coefficients"):
        g.realise()
    with pytest.raises(ValueError, match="longer than"):
        g.with_u(np.zeros(g.n_coefficients)).realise(duration=10 * g.period)
    with pytest.raises(BoatlandInputError, match="n_steps"):
        GaussianSea(sea=sea(), dt=0.05, n_steps=0)


@pytest.mark.slow
def test_the_trial_runs_on_exactly_these_components():
    """simulate(waves=GaussianSea) applies the excitation of exactly the sea's components (ramped as the
    scenario says), and records which sea it was."""
    s = scenario_from_dict({
        "name": "gauss", "simulation": {"duration": 30.0, "seed": 1, "dt": 0.05},
        "vessel": {"database": "ctv24"}, "radiation": {"method": "state_space"},
        "sea": {"kind": "jonswap", "Hs": 0.5, "Tp": 6.0, "relative_direction_deg": 150.0}})
    db = load_builtin("ctv24")
    setup = Setup.of(s, db)
    dt, n = setup.dt, setup.n_steps
    g = GaussianSea(sea=setup.waves, dt=dt, n_steps=n)
    u = np.random.default_rng(1).standard_normal(g.n_coefficients)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = simulate(s, db, waves=g.with_u(u))
    x0, y0, psi = s.start_pose()
    F = wave_excitation(g.with_u(u).components(), db, dt=dt, n_steps=n, x0=x0, y0=y0,
                        heading_deg=math.degrees(psi)) * wave_ramp(s, dt, n)[:, None]
    np.testing.assert_array_equal(r.F_exc, F[0:2 * len(r.t):2])
    assert r.provenance["waves"] == f"GaussianSea {g.with_u(u).digest()}"
    with pytest.raises(BoatlandInputError, match="without a sea"):
        simulate(s.replace({"sea": None}), db, waves=g.with_u(u))
