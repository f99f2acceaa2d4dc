"""The NUFFT harmonic sum against the direct sum (the oracle) and an extended-precision reference.

Edge cases: one component, short grids, components exactly on a node of the FFT grid or halfway
between two, on the bin edges of a realisation, at ω = 0, at and above the Nyquist frequency of the
grid (both sums alias the same way: a sample only sees ω h modulo 2π), negative start times; and
independence of the thread count (numba and scipy.fft).
"""

import math

import numba
import numpy as np
import pytest
from scipy import fft as sfft

from boatland.sea.spectra import SpectrumPart
from boatland.sea.states import SeaState
from boatland.waves.nufft import M_SP, R_OVERSAMPLE, harmonic_sum_nufft, nufft_grid, nufft_layout
from boatland.waves.synthesis import harmonic_sum

RTOL = 1e-9  # of each output's RMS (issue 16)


def rel_error(fast, direct):
    rms = np.sqrt(np.mean(direct ** 2, axis=0))
    return np.max(np.abs(fast - direct), axis=0) / rms


def phase_bound(w, t_max):
    """Round-off bound relative to Σ|c|: a few roundings of the largest phase ω t (both sums round
    ω t or ω h once; ulp(ω t) grows with t), plus a floor for the sums themselves."""
    return 4 * 1.1e-16 * float(np.max(np.abs(w))) * t_max + 1e-14


def random_sum(rng, N, m=2, lo=0.3, hi=3.0):
    w = np.sort(rng.uniform(lo, hi, N))
    return w, rng.normal(size=(m, N)) + 1j * rng.normal(size=(m, N))


def reference(w, c, t0, h, idx):
    """Re Σ c e^{iω t} in 80-bit long double at t = t0 + n h, n in idx (exact grid times)."""
    L = np.longdouble
    t = L(t0) + np.asarray(idx).astype(L) * L(h)
    ph = np.outer(t, np.asarray(w, dtype=L))
    return (np.cos(ph) @ c.real.T.astype(L) - np.sin(ph) @ c.imag.T.astype(L)).astype(float)


# ---------------------------------------------------------------------- accuracy
def test_error_is_round_off_of_the_amplitudes_against_an_extended_precision_sum():
    """Against Re Σ c e^{iωt} in long double on the exact grid t0 + n h: at the centre sample t_c the
    NUFFT is exact to round-off (its phase there is formed in double-double); away from it, the one
    rounding of x = ω h (1.1e-16 relative) turns into a phase error ω |t − t_c| 1.1e-16 — the same size
    as the direct sum's, whose phases ω t are rounded the same way (measured: 4e-17 Σ|c| at the centre,
    ≤ 5e-14 Σ|c| at the ends of 10 000 s, direct ≤ 7e-14). Truncation and aliasing of the Gaussian
    (~3e-15, module docstring) stay below that."""
    rng = np.random.default_rng(2)
    w, c = random_sum(rng, 500)
    l1 = np.sum(np.abs(c), axis=1)
    for t0, n in ((-3.0, 2001), (0.0, 40_001), (12.5, 400_001)):
        idx = np.r_[0:100, n // 2 - 50:n // 2 + 50, n - 100:n]
        ref = reference(w, c, t0, 0.025, idx)
        err = np.max(np.abs(harmonic_sum_nufft(w, c, t0, 0.025, n)[idx] - ref) / l1, axis=1)
        direct = np.max(np.abs(harmonic_sum(w, c, t0, 0.025, n)[idx] - ref) / l1, axis=1)
        assert np.max(err[100:200]) < 1e-16                       # the centre (n = n_c ± 50)
        phase = w.max() * (n * 0.025 / 2) * 1.1e-16               # largest phase error of one component
        assert np.max(err) < phase + 5e-15
        assert np.max(err) < 2.0 * np.max(direct) + 5e-15          # no worse than the oracle


def test_gaussian_parameters_follow_greengard_and_lee():
    n_c, K, M, tau = nufft_grid(24_001)
    assert (n_c, K) == (12_000, 24_002) and M >= R_OVERSAMPLE * K and M == sfft.next_fast_len(M)
    assert tau == pytest.approx(math.pi * M_SP / (M * (M - K / 2)), rel=1e-15)
    # balanced truncation and aliasing: exp(−π M_sp (R − 1)/(R − ½)) at R = 2 is ~3e-15
    assert math.exp(-math.pi * M_SP * (2 - 1) / (2 - 0.5)) < 1e-14


def test_the_fft_is_split_where_the_points_fill_an_arc():
    """Sea frequencies fill an arc |x| ≤ ω_max h of the circle: M = M1 M2 with M2 transforms of a fast
    length M1 that holds the window of grid points the Gaussians reach; points anywhere: one FFT."""
    n = 401_361                                            # a 10 000-s trial's half-step grid
    lay = nufft_layout(n, 6.72 * 0.025)
    assert lay.M2 > 1 and lay.M1 == sfft.next_fast_len(lay.M1) and lay.M >= R_OVERSAMPLE * lay.K
    assert lay.M1 >= 2 * lay.S + 1 and lay.S >= 6.72 * 0.025 * lay.M / (2 * math.pi) + M_SP
    one = nufft_layout(n, math.pi)
    assert one.M2 == 1 and one.M == sfft.next_fast_len(int(math.ceil(R_OVERSAMPLE * one.K)))
    assert nufft_grid(n) == (one.n_c, one.K, one.M, one.tau)


def test_split_and_single_fft_agree_to_round_off():
    """The same sums with the FFT split (a sea's arc) and whole (one zero-amplitude component near the
    Nyquist frequency widens the arc to the circle): equal to round-off of Σ|c| over a 10 000-s grid —
    both share the rounding of x = ω h; they differ by the Gaussian's truncation and the FFTs' round-off
    on different grids. (The realisation is the same; the bits of long series changed with the split in
    issue 16.)"""
    rng = np.random.default_rng(8)
    w, c = random_sum(rng, 3000, m=3, lo=0.4, hi=4.0)
    n, h = 400_001, 0.025
    split = harmonic_sum_nufft(w, c, 0.0, h, n)
    w1 = np.append(w, 0.99 * math.pi / h)
    whole = harmonic_sum_nufft(w1, np.concatenate([c, np.zeros((3, 1))], axis=1), 0.0, h, n)
    assert nufft_layout(n, float(w.max() * h)).M2 > 1 and nufft_layout(n, 0.99 * math.pi).M2 == 1
    l1 = np.sum(np.abs(c), axis=1)
    assert np.all(np.max(np.abs(split - whole), axis=0) / l1 < 2e-13)       # measured 6e-14


@pytest.mark.parametrize("n", [1, 2, 3, 4, 17, 1000, 1001])
def test_one_component_and_short_grids(n):
    w = np.array([1.234])
    c = np.array([[0.7 - 0.2j]])
    fast = harmonic_sum_nufft(w, c, 2.5, 0.05, n)
    direct = harmonic_sum(w, c, 2.5, 0.05, n)
    assert fast.shape == (n, 1)
    assert np.max(np.abs(fast - direct)) < phase_bound(w, 2.5 + 0.05 * n) * abs(c[0, 0])
    assert harmonic_sum_nufft(w, c, 2.5, 0.05, 0).shape == (0, 1)


def test_components_on_grid_nodes_halfway_between_and_on_bin_edges():
    """x = ω h on a node 2πj/M of the FFT grid, exactly halfway (the nearest node is a tie), at 0 and
    next to 2π (the Gaussian wraps round the period); and a sea whose frequencies are the bin edges of
    the non-repetition rule (what a draw u = 0 would give)."""
    h, n = 0.025, 24_001
    _, _, M, _ = nufft_grid(n)
    j = np.array([1.0, 37.0, 37.5, 1000.0, 1000.5, M / 4 + 0.5, M - 0.5, M - 1.0])
    w = np.concatenate([j * 2 * math.pi / M / h, [0.0]])
    rng = np.random.default_rng(3)
    c = rng.normal(size=(3, w.size)) + 1j * rng.normal(size=(3, w.size))
    fast = harmonic_sum_nufft(w, c, 0.0, h, n)
    assert np.all(rel_error(fast, harmonic_sum(w, c, 0.0, h, n)) < RTOL)
    bound = phase_bound(w, n * h) * np.sum(np.abs(c), 1)  # ω up to 2π/h: ulp(ω t) ~ 3e-11 at 600 s
    assert np.all(np.max(np.abs(fast - harmonic_sum(w, c, 0.0, h, n)), axis=0) < bound)
    sea = SeaState(parts=SpectrumPart(Hs=1.5, Tp=7.0))
    lo, hi = sea.band()
    N = sea.n_components_for(600.0)[0]
    edges = np.linspace(lo, hi, N + 1)
    cc = (rng.normal(size=(2, N + 1)) + 1j * rng.normal(size=(2, N + 1))) * 0.1
    assert np.all(rel_error(harmonic_sum_nufft(edges, cc, 0.0, h, n), harmonic_sum(edges, cc, 0.0, h, n)) < RTOL)


def test_frequencies_at_and_above_the_nyquist_frequency_alias_like_the_direct_sum():
    """ω h = π (Nyquist), just below and above it, and ω + 2π/h: the samples of cos(ω t_n) cannot
    tell ω from its alias, and neither sum tries to — both give the aliased series."""
    h, n = 0.025, 20_001
    nyq = math.pi / h
    w = np.array([0.9 * nyq, nyq, 1.1 * nyq, 1.7, 1.7 + 2 * math.pi / h, 1.7 + 6 * math.pi / h])
    rng = np.random.default_rng(5)
    c = rng.normal(size=(2, w.size)) + 1j * rng.normal(size=(2, w.size))
    fast = harmonic_sum_nufft(w, c, 0.0, h, n)
    direct = harmonic_sum(w, c, 0.0, h, n)
    assert np.all(rel_error(fast, direct) < RTOL)
    # the alias: 1.7 + 2π/h sampled every h is 1.7 sampled every h (to the rounding of ω t)
    one = harmonic_sum_nufft(w[[3]], c[:, [3]], 0.0, h, n)
    for k in (4, 5):
        bound = phase_bound(w[[k]], n * h) * np.abs(c[:, 3])  # ω t ~ 4e5 rad: ulp 6e-11
        assert np.all(np.max(np.abs(harmonic_sum_nufft(w[[k]], c[:, [3]], 0.0, h, n) - one), axis=0) < bound)
        assert np.all(np.max(np.abs(harmonic_sum(w[[k]], c[:, [3]], 0.0, h, n) - one), axis=0) < bound)
    # the Nyquist component is a pure alternation: Re(c e^{iπ n}) = Re(c) (−1)^n
    nq = harmonic_sum_nufft(w[[1]], c[:1, [1]], 0.0, h, 11)[:, 0]
    assert np.allclose(nq, c[0, 1].real * (-1.0) ** np.arange(11), rtol=0, atol=1e-14)


def test_offset_start_and_odd_output_counts():
    rng = np.random.default_rng(6)
    for m, t0 in ((1, 0.0), (3, -123.4), (6, 7777.7)):
        w, c = random_sum(rng, 800, m=m)
        fast = harmonic_sum_nufft(w, c, t0, 0.05, 12_345)
        assert fast.shape == (12_345, m)
        assert np.all(rel_error(fast, harmonic_sum(w, c, t0, 0.05, 12_345)) < RTOL)


# ---------------------------------------------------------------------- determinism
def test_result_does_not_depend_on_numba_threads_or_scipy_fft_workers():
    rng = np.random.default_rng(7)
    w, c = random_sum(rng, 700, m=3)
    ref = harmonic_sum_nufft(w, c, 0.0, 0.025, 50_001)
    old = numba.get_num_threads()
    try:
        numba.set_num_threads(min(2, numba.config.NUMBA_NUM_THREADS))
        with sfft.set_workers(4):
            again = harmonic_sum_nufft(w, c, 0.0, 0.025, 50_001)
    finally:
        numba.set_num_threads(old)
    assert np.array_equal(ref, again)
    assert np.array_equal(ref, harmonic_sum_nufft(w, c, 0.0, 0.025, 50_001))


def test_nan_in_nan_out_like_the_direct_sum():
    """A NaN amplitude or frequency gives a NaN series, as the direct sum does (never a silent zero or a
    write outside the grid); the other outputs are untouched by a NaN amplitude."""
    w = np.array([1.0, 2.0])
    c = np.array([[np.nan, 1.0], [1.0, 0.5j]])
    fast = harmonic_sum_nufft(w, c, 0.0, 0.1, 50)
    assert np.all(np.isnan(fast[:, 0])) and np.all(np.isnan(harmonic_sum(w, c, 0.0, 0.1, 50)[:, 0]))
    assert np.max(np.abs(fast[:, 1] - harmonic_sum(w, c, 0.0, 0.1, 50)[:, 1])) < 1e-14
    assert np.all(np.isnan(harmonic_sum_nufft(np.array([np.nan, 2.0]), c[1:], 0.0, 0.1, 50)))
