"""Seeded realisations: reproducibility, the frequency rule, amplitudes, directions, and statistics.

The statistical checks use one fixed seed and tolerances derived from the components themselves:

- variance: for random phases φ_i the time-average variance s² = (1/T)∫η² dt has mean V = Σ a_i²/2
  and, from the difference-frequency cross terms,
  Var(s²) = Σ_{i<j} a_i² a_j² · ½ sinc²((ω_i − ω_j) T/2)  (each pair's phase difference is uniform
  and independent of the others'); checked within 4 standard deviations;
- Welch: for a Gaussian process the Welch estimate (Hann, 50 % overlap, K segments) is
  S·χ²_ν/ν with ν = 2K / (1 + 2 ρ²) and ρ = 0.167 the overlap correlation of the Hann window
  (Welch 1967; Percival & Walden 1993 §6.17); deterministic amplitudes only make the estimate less
  variable, so these bounds are conservative. Every frequency with S > 5 % of the peak must lie within
  the two-sided χ² interval at a total false-alarm probability of 1e-3 (Bonferroni over the bins).
"""

import math

import numba
import numpy as np
import pytest
from scipy import signal, special, stats

from boatland.sea.spectra import SpectrumPart
from boatland.sea.states import SeaState
from boatland.waves.realisation import (as_seed_sequence, n_components_for, part_rng,
                                        random_frequency_components, regular_components)
from boatland.waves.spectra import bin_variance, spectrum_band
from boatland.waves.synthesis import harmonic_sum_kernel, elevation, elevation_series, harmonic_sum

SEED = 20240917


def fields_equal(a, b):
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in a._fields)


def one_part(seed, n=300, s=0.0, rayleigh=False):
    lo, hi = spectrum_band(7.0, 3.3)
    edges = np.linspace(lo, hi, n + 1)
    V = bin_variance(edges, 1.5, 7.0, 3.3)
    return edges, V, random_frequency_components(edges, V, 0.4, s, part_rng(seed, 0), rayleigh=rayleigh)


# ---------------------------------------------------------------------- reproducibility
def test_same_seed_same_components_bitwise_and_different_seeds_differ():
    sea = SeaState(parts=(SpectrumPart(Hs=1.2, Tp=5.0, spreading=8.0), SpectrumPart(Hs=0.8, Tp=11.0, kind="pm",
                                                                                     direction_deg=60.0)),
                   amplitudes="rayleigh")
    a, b = sea.realise(7, 600.0), sea.realise(7, 600.0)
    assert fields_equal(a, b)
    c = sea.realise(8, 600.0)
    assert not np.array_equal(a.phi, c.phi) and not np.array_equal(a.omega, c.omega)
    assert not np.array_equal(a.theta, c.theta) and not np.array_equal(a.a, c.a)


def test_seed_sequence_is_accepted_and_not_advanced():
    master = np.random.SeedSequence(12345)
    trial = master.spawn(3)[1]
    sea = SeaState(parts=SpectrumPart(Hs=1.0, Tp=6.0))
    a = sea.realise(trial, 300.0)
    assert trial.n_children_spawned == 0
    assert fields_equal(a, sea.realise(trial, 300.0))  # the same sequence object again
    assert fields_equal(a, sea.realise(np.random.SeedSequence(12345).spawn(3)[1], 300.0))  # rebuilt
    # part p draws from the p-th child, as SeedSequence.spawn would make it
    ref = np.random.default_rng(np.random.SeedSequence(99).spawn(3)[2]).random(4)
    assert np.array_equal(part_rng(99, 2).random(4), ref)
    assert np.array_equal(part_rng(np.random.SeedSequence(99), 2).random(4), ref)
    with pytest.raises(TypeError, match="seed must be"):
        as_seed_sequence(-1)
    with pytest.raises(ValueError, match="needs a seed"):
        sea.realise(None, 300.0)


def test_changing_one_part_leaves_the_other_parts_phases():
    swell = SpectrumPart(Hs=1.0, Tp=11.0, direction_deg=45.0)
    a = SeaState(parts=(SpectrumPart(Hs=1.3, Tp=5.0), swell)).realise(3, 900.0)
    b = SeaState(parts=(SpectrumPart(Hs=0.5, Tp=5.0), swell)).realise(3, 900.0)
    assert np.array_equal(a.phi, b.phi) and np.array_equal(a.omega, b.omega)
    n1 = SeaState(parts=(SpectrumPart(Hs=1.3, Tp=5.0), swell)).n_components_for(900.0)[0]
    assert np.allclose(b.a[:n1] / a.a[:n1], 0.5 / 1.3, rtol=1e-12)  # same phases, scaled amplitudes


@pytest.mark.parametrize("threads", [1, 2])
def test_result_does_not_depend_on_thread_count(threads):
    """The kernels are serial (no parallel=True): the sum is the same whatever numba's thread count."""
    assert not harmonic_sum_kernel.targetoptions.get("parallel", False)
    sea = SeaState(parts=SpectrumPart(Hs=1.0, Tp=6.0, spreading=5.0))
    c = sea.realise(SEED, 200.0)
    ref = elevation_series(c, 3.0, -2.0, 0.0, 0.1, 2001)
    if threads > numba.config.NUMBA_NUM_THREADS:
        pytest.skip(f"numba has only {numba.config.NUMBA_NUM_THREADS} thread(s) here")
    old = numba.get_num_threads()
    try:
        numba.set_num_threads(threads)
        again = elevation_series(sea.realise(SEED, 200.0), 3.0, -2.0, 0.0, 0.1, 2001)
    finally:
        numba.set_num_threads(old)
    assert np.array_equal(ref, again)


# ---------------------------------------------------------------------- frequency rule and amplitudes
def test_one_random_frequency_per_bin_and_the_non_repetition_rule():
    duration = 1800.0
    sea = SeaState(parts=SpectrumPart(Hs=1.5, Tp=7.0), n_components=16)
    lo, hi = sea.band()
    N = sea.n_components_for(duration)[0]
    assert N == n_components_for(duration, lo, hi) and (hi - lo) / N <= 2 * math.pi / duration
    assert (hi - lo) / (N - 1) > 2 * math.pi / duration  # the smallest such N
    c = sea.realise(SEED, duration)
    edges = np.linspace(lo, hi, N + 1)
    assert c.size == N and np.all((c.omega >= edges[:-1]) & (c.omega < edges[1:]))
    # offsets inside the bins are uniform (Kolmogorov–Smirnov at 1e-3)
    u = (c.omega - edges[:-1]) / np.diff(edges)
    assert stats.kstest(u, "uniform").pvalue > 1e-3
    assert stats.kstest(c.phi / (2 * math.pi), "uniform").pvalue > 1e-3
    # more components when asked for
    assert SeaState(parts=SpectrumPart(Hs=1.5, Tp=7.0), n_components=5000).realise(SEED, duration).size == 5000


def test_deterministic_amplitudes_carry_the_band_variance_exactly():
    edges, V, c = one_part(SEED)
    assert np.allclose(c.a ** 2 / 2, V, rtol=1e-15)
    sea = SeaState(parts=SpectrumPart(Hs=2.0, Tp=8.0))
    assert sea.realise(SEED, 1200.0).variance == pytest.approx((1 - sea.band_tail) * 2.0 ** 2 / 16, rel=1e-7)  # band: closed-form tails


def test_rayleigh_amplitudes_have_the_right_mean_square():
    """a_i² / (2 V_i) ~ Exp(1): mean 1 ± 1/√N (checked at 4σ) and an exponential distribution (KS)."""
    edges, V, c = one_part(SEED, n=4000, rayleigh=True)
    x = c.a ** 2 / (2 * V)
    assert abs(x.mean() - 1) < 4 / math.sqrt(x.size)
    assert stats.kstest(x, "expon").pvalue > 1e-3


def test_short_crested_directions_follow_the_spreading():
    """Stratified inverse-CDF sampling: the empirical CDF of θ − θ̄ is within 1/N of F (each sector once)."""
    s, N = 6.0, 2000
    edges, V, c = one_part(SEED, n=N, s=s)
    u = np.sort(np.angle(np.exp(1j * (c.theta - 0.4))))
    F = 0.5 + 0.5 * np.sign(u) * special.betainc(0.5, s + 0.5, np.sin(u / 2) ** 2)
    assert np.max(np.abs(F - (np.arange(N) + 0.5) / N)) <= 0.5 / N + 1e-12
    # directions are not ordered with frequency (random assignment of sectors)
    assert abs(stats.spearmanr(c.omega, c.theta).statistic) < 4 / math.sqrt(N)
    # long-crested: one direction
    assert np.all(one_part(SEED, s=0.0)[2].theta == 0.4)


def test_regular_wave_component():
    c = regular_components(2.0, 8.0, math.radians(30.0), math.radians(20.0), h=25.0)
    t = np.linspace(0, 16, 33)
    eta = elevation(c, 0.0, 0.0, t)[:, 0]
    assert np.allclose(eta, np.cos(2 * math.pi * t / 8.0 + math.radians(20.0)), atol=1e-14)
    assert 9.81 * c.k[0] * math.tanh(c.k[0] * 25.0) == pytest.approx((2 * math.pi / 8) ** 2, rel=1e-14)


# ---------------------------------------------------------------------- elevation kernels
def test_phasor_sum_equals_direct_evaluation_over_long_records():
    sea = SeaState(parts=SpectrumPart(Hs=1.0, Tp=6.0, spreading=4.0))
    c = sea.realise(SEED, 300.0)
    x, y, dt, n = 40.0, -15.0, 0.05, 12_001  # 600 s: crosses 47 re-anchorings
    fast = elevation_series(c, x, y, 0.0, dt, n)
    idx = np.arange(0, n, 97)
    direct = elevation(c, x, y, idx * dt)[:, 0]
    assert np.max(np.abs(fast[idx] - direct)) < 1e-12 * np.sum(c.a)
    # a general harmonic sum with an offset start
    w = np.array([0.3, 1.7, 2.9])
    cc = np.array([[1 + 2j, -0.5j, 0.25], [0.0, 1.0, -1.0]])
    t = 5.0 + 0.3 * np.arange(500)
    ref = (cc[None] * np.exp(1j * w[None, None, :] * t[:, None, None])).real.sum(-1)
    assert np.allclose(harmonic_sum(w, cc, 5.0, 0.3, 500), ref, rtol=0, atol=1e-12)


def test_elevation_moves_with_the_waves():
    """Long-crested waves towards θ: η(x + c_p Δt cosθ, t + Δt) = η(x, t) for each component."""
    c = regular_components(1.0, 7.0, math.radians(35.0), 0.3)
    cp = c.omega[0] / c.k[0]
    dt = 2.3
    x0, y0 = np.array([0.0, 10.0]), np.array([0.0, -4.0])
    t = np.linspace(0, 20, 41)
    a = elevation(c, x0, y0, t)
    b = elevation(c, x0 + cp * dt * math.cos(c.theta[0]), y0 + cp * dt * math.sin(c.theta[0]), t + dt)
    assert np.allclose(a, b, atol=1e-12)


# ---------------------------------------------------------------------- statistics of a long record
def test_long_realisation_variance_and_welch_spectrum_match_the_target():
    Hs, Tp, T, dt = 2.0, 8.0, 3 * 3600.0, 0.5
    sea = SeaState(parts=SpectrumPart(Hs=Hs, Tp=Tp))
    c = sea.realise(SEED, T)
    n = int(T / dt)
    eta = elevation_series(c, 0.0, 0.0, 0.0, dt, n)

    # variance: mean V = (1 − band_tail) m0 exactly; std from the pair formula (module docstring),
    # summed over |i − j| < 400 bins (farther pairs add < 0.1 % of the variance: sinc² ~ 1/(π m)²)
    V = c.variance
    assert V == pytest.approx((1 - sea.band_tail) * Hs ** 2 / 16, rel=1e-7)
    a2, w = c.a ** 2, c.omega
    var = sum(np.sum(a2[m:] * a2[:-m] * 0.5 * np.sinc((w[m:] - w[:-m]) * T / 2 / np.pi) ** 2) for m in range(1, 400))
    s2 = float(np.mean(eta ** 2))
    assert abs(s2 - V) < 4 * math.sqrt(var)

    # Welch: χ²_ν bounds per frequency, Bonferroni over the bins with S > 5 % of the peak
    nper = 1024  # 512 s segments: Δf = 2 mHz, five times finer than the peak's width σ_a f_p
    f, P = signal.welch(eta, fs=1 / dt, window="hann", nperseg=nper, noverlap=nper // 2)
    K = (n - nper) // (nper // 2) + 1
    nu = 2 * K / (1 + 2 * (1 - 1 / K) * 0.167 ** 2)
    om = 2 * math.pi * f
    S = sea.spectrum(om)
    band = S > 0.05 * S.max()
    ratio = P[band] / (2 * math.pi) / S[band]  # one-sided per Hz → per rad/s
    alpha = 1e-3 / band.sum()
    lo, hi = stats.chi2.ppf(alpha / 2, nu) / nu, stats.chi2.ppf(1 - alpha / 2, nu) / nu
    assert band.sum() > 50
    assert lo < ratio.min() and ratio.max() < hi
