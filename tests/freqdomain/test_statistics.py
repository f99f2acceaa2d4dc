"""Rayleigh, Rice and Vanmarcke formulas of boatland.freqdomain.screening against a directly simulated
stationary Gaussian process.

The process: x(t) = Σ_k Re{c_k e^{iω_k t}} on the FFT grid (2²¹ samples, dt = 0.1 s: 58 h), c_k complex
Gaussian with E|c_k|² = S(ω_k) Δω / 2 — exactly Gaussian and stationary (periodic), spectrum JONSWAP
Hs = 1 m, Tp = 8 s, cut at 3 rad/s (the theory uses the same discrete spectrum; at 20 samples per
shortest period no crossing is lost between samples). Seeded generator: the counts are reproducible.

Tolerances: 4 standard errors of the counted quantity — Poisson sqrt(E) for crossing counts,
binomial sqrt(p(1 − p)/n) for fractions of cycles or windows. Measured (seed 20261122): Rice
|z| ≤ 1.9 at levels 0.5–3.5 σ for γ = 1, 3.3, 10; Rayleigh |z| ≤ 1.9 at 2–3 σ (at 0.5–1 σ a broad-band
process has cycles whose peak is not Rayleigh: z = −23 at 0.5 σ, so those levels are not tested);
Vanmarcke |z| ≤ 1.5 for γ = 10 at 2.5–3 σ in 60 s windows, where Rice is off by 3–15 SE.
"""

from __future__ import annotations

import numpy as np
import pytest

from boatland.freqdomain.statistics import rayleigh_exceedance, rice_rate, vanmarcke_rate
from boatland.waves.spectra import jonswap

DT, N = 0.1, 2 ** 21
SEED = 20261122
Z = 4.0  # standard errors


def record(gamma: float, seed: int = SEED):
    """(x, (m0, m1, m2)) of one simulated record."""
    rng = np.random.default_rng(seed)
    w = 2 * np.pi * np.fft.rfftfreq(N, DT)
    dw = w[1]
    S = np.where((w > 0) & (w <= 3.0), jonswap(w, 1.0, 8.0, gamma), 0.0)
    c = (rng.standard_normal(w.size) + 1j * rng.standard_normal(w.size)) * np.sqrt(S * dw / 4)
    x = np.fft.irfft(c, N) * N      # = Σ 2 Re{c_k e^{iω_k t}}, variance Σ S Δω
    return x, tuple(float(np.sum(S * dw * w ** k)) for k in range(3))


def up_crossings(x, a):
    return np.flatnonzero((x[:-1] < a) & (x[1:] >= a))


@pytest.fixture(scope="module", params=[1.0, 3.3, 10.0], ids=lambda g: f"gamma{g:g}")
def process(request):
    return request.param, *record(request.param)


def test_record_has_the_spectrum_variance(process):
    _, x, (m0, _, _) = process
    assert abs(x.var() / m0 - 1) < 0.02


@pytest.mark.parametrize("r", [0.5, 1.0, 2.0, 3.0])
def test_rice_up_crossing_rate(process, r):
    """Number of up-crossings of a = rσ in the record against ν_a T (Rice 1945)."""
    _, x, (m0, _, m2) = process
    a = r * np.sqrt(m0)
    expected = float(rice_rate(a, m0, m2)) * N * DT
    counted = up_crossings(x, a).size
    assert abs(counted - expected) < Z * np.sqrt(expected), (counted, expected)


@pytest.mark.parametrize("r", [2.0, 3.0])
def test_rayleigh_peak_per_cycle(process, r):
    """Share of zero-up-crossing cycles whose maximum exceeds a against e^{−a²/2σ²} (Grøtting 2015 eq. 3.36)."""
    _, x, (m0, _, _) = process
    a = r * np.sqrt(m0)
    z = up_crossings(x, 0.0)
    peaks = np.maximum.reduceat(x, z)[:-1]
    p = float(rayleigh_exceedance(a, np.sqrt(m0)))
    frac = np.mean(peaks > a)
    assert abs(frac - p) < Z * np.sqrt(p * (1 - p) / peaks.size), (frac, p)


def first_passage_fraction(x, a, window):
    L = int(round(window / DT))
    nw = x.size // L
    return np.mean(np.any(x[:nw * L].reshape(nw, L) >= a, axis=1)), nw


@pytest.mark.parametrize("r", [2.5, 3.0])
def test_vanmarcke_first_passage_narrow_band(r):
    """γ = 10 (narrow band): crossings clump, Rice's Poisson estimate 1 − e^{−ν t} overstates the chance of
    a first passage in a 60 s window; Vanmarcke's rate matches the counted share of windows."""
    x, (m0, m1, m2) = record(10.0)
    a = r * np.sqrt(m0)
    frac, nw = first_passage_fraction(x, a, 60.0)
    p_vm = 1 - np.exp(-float(vanmarcke_rate(a, m0, m1, m2)) * 60.0)
    p_rice = 1 - np.exp(-float(rice_rate(a, m0, m2)) * 60.0)
    se = np.sqrt(p_vm * (1 - p_vm) / nw)
    assert abs(frac - p_vm) < Z * se, (frac, p_vm)
    assert p_rice - frac > 2 * abs(p_vm - frac)  # the correction is needed here
    assert float(vanmarcke_rate(a, m0, m1, m2)) <= float(rice_rate(a, m0, m2))


def test_vanmarcke_two_sided_tends_to_twice_rice_for_a_broad_band():
    """δ → 1 and high levels: no clumping; a double barrier is crossed twice as often."""
    m0, m1, m2 = 1.0, 0.0, 1.0  # δ = 1
    a = 6.0
    assert np.isclose(vanmarcke_rate(a, m0, m1, m2, two_sided=True), 2 * rice_rate(a, m0, m2), rtol=1e-3)
    assert np.isclose(vanmarcke_rate(a, m0, m1, m2), rice_rate(a, m0, m2), rtol=1e-3)


def test_formula_edge_cases():
    assert rayleigh_exceedance(-1.0, 1.0) == 1.0 and rayleigh_exceedance(1.0, 0.0) == 0.0
    assert np.isclose(rayleigh_exceedance(2.0, 1.0), np.exp(-2.0))
    assert np.isclose(rice_rate(0.0, 1.0, 4.0), 1 / np.pi)  # ν0 = √(m2/m0)/2π


def test_the_risk_in_words():
    """A probability as a planner reads it: odds to two significant figures, small ones as 1.19e-3, the
    presets named by their source (Grøtting 2015 Table 2.1)."""
    from boatland.errors import BoatlandInputError
    from boatland.freqdomain.statistics import one_in, probability_text, risk_in_words

    assert risk_in_words("best") == "1 access in 840 (1.19e-3 per 30-min access, Grøtting 2015 best estimate)"
    assert risk_in_words(0.00119) == risk_in_words("best")                       # the number is the preset
    assert risk_in_words("conservative") == "1 access in 50,000 (2e-5 per 30-min access, Grøtting 2015 conservative)"
    assert risk_in_words(0.005, 600.0) == "1 access in 200 (5e-3 per 10-min access, as given)"
    assert [one_in(p) for p in (0.5, 0.7, 0.05, 1e-6, 0.0, 1.0)] == ["1 in 2", "1 in 1.4", "1 in 20", "1 in 1,000,000",
                                                                     "none", "every one"]
    assert probability_text(0.0268) == "0.0268" and probability_text(1.19e-3) == "1.19e-3"
    with pytest.raises(BoatlandInputError, match="outside"):
        risk_in_words(1.5)
