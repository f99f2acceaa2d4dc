r"""Seeded realisations of a sea state as wave components (ω_i, k_i, a_i, θ_i, φ_i).

The sea surface is the sum of :math:`N` linear components (San Nicolás Méndez 2024 eq. 3.32–3.33, Ferreira González 2023
eq. 2.45–2.47, Tucker & Pitt 2001 §5):

.. math::
    \eta(x, y, t) = \sum_i a_i \cos\left(\omega_i t - k_i (x\cos\theta_i + y\sin\theta_i) + \varphi_i\right),
    \qquad \omega_i^2 = g k_i \tanh(k_i h).

Frequencies — "random frequency in equal bins" (the rule)
    The band [ω_lo, ω_hi] is cut into N bins of equal width Δω = (ω_hi − ω_lo)/N with

    .. math:: N \ge N_{rep} = \left\lceil \frac{T_{dur}\,(\omega_{hi} - \omega_{lo})}{2\pi} \right\rceil
              \iff \Delta\omega \le \frac{2\pi}{T_{dur}},

    so the period 2π/Δω after which an equal-step record would repeat is at least the duration
    :math:`T_{dur}` (:func:`n_components_for`); and each ω_i is drawn uniformly inside its bin, so the
    frequencies are incommensurate and the record never repeats exactly.
Amplitudes
    :math:`a_i = \sqrt{2 V_i}` with :math:`V_i = \int_{bin\,i} S\,d\omega \approx S(\omega_i)\Delta\omega`
    (deterministic, the default: :math:`\sum a_i^2/2` is the spectrum's variance in the band
    exactly), or Rayleigh-distributed :math:`a_i = \sqrt{2 V_i \cdot(-\ln u_i)}` (then
    :math:`E[a_i^2] = 2V_i` and η is a Gaussian process; Tucker et al. 1984).
Phases
    :math:`\varphi_i = 2\pi u_i`, uniform.
Directions
    Long-crested: θ_i = θ̄. Short-crested (cos-2s spreading): :math:`\theta_i = \bar\theta + F^{-1}(p_i)`
    with stratified :math:`p_i = (\pi_i + u_i)/N` (π a random permutation of 0..N−1): every
    equal-probability direction sector is used once, assigned to frequencies at random (one
    direction per frequency, so there is no phase locking of directions).

Randomness
    One ``numpy.random.Generator`` (PCG64) per spectral part, drawn in the fixed order
    bin offsets, phases, [Rayleigh variates], [permutation, sector offsets]. A seed is an int or a
    ``numpy.random.SeedSequence``; part p uses the child sequence
    ``SeedSequence(entropy, spawn_key=(*seed.spawn_key, p))`` — what ``seed.spawn`` would give as its
    p-th child, built without advancing the caller's sequence (so the same sequence always gives
    the same sea). Serial numpy only: the result depends on nothing but the seed.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from boatland.waves.dispersion import wavenumber
from boatland.waves.spectra import spreading_quantile

__all__ = ["Components", "concatenate", "as_seed_sequence", "part_rng", "n_components_for",
           "random_frequency_components", "regular_components"]


class Components(NamedTuple):
    """Linear wave components, all shape (N,), SI units.

    Attributes
    ----------
    omega : ndarray
        Angular frequency ω_i [rad/s].
    k : ndarray
        Wave number k_i [rad/m] (dispersion relation at the sea's depth).
    a : ndarray
        Amplitude a_i [m].
    theta : ndarray
        Direction of travel θ_i [rad], global frame (0 = towards +x).
    phi : ndarray
        Phase φ_i [rad] at the global origin: η = Σ a_i cos(ω_i t − k_i·x + φ_i).
    """

    omega: np.ndarray
    k: np.ndarray
    a: np.ndarray
    theta: np.ndarray
    phi: np.ndarray

    @property
    def size(self) -> int:
        return int(self.omega.size)

    @property
    def variance(self) -> float:
        """Σ a_i²/2 [m²], the time-average variance of η."""
        return float(0.5 * np.sum(self.a ** 2))


def concatenate(parts) -> Components:
    """One :class:`Components` holding all components of ``parts`` (in order)."""
    parts = list(parts)
    return Components(*(np.concatenate([getattr(p, f) for p in parts]) for f in Components._fields))


def as_seed_sequence(seed) -> np.random.SeedSequence:
    """The seed as a ``SeedSequence``: an int ≥ 0 or a ``SeedSequence`` (returned unchanged)."""
    if isinstance(seed, np.random.SeedSequence):
        return seed
    if isinstance(seed, (int, np.integer)) and not isinstance(seed, bool) and seed >= 0:
        return np.random.SeedSequence(int(seed))
    raise TypeError(f"seed must be an int ≥ 0 or a numpy.random.SeedSequence, got {seed!r}")


def part_rng(seed, part: int) -> np.random.Generator:
    """Generator of spectral part ``part``: the ``part``-th child of the seed sequence (not advancing it)."""
    ss = as_seed_sequence(seed)
    child = np.random.SeedSequence(ss.entropy, spawn_key=(*ss.spawn_key, int(part)), pool_size=ss.pool_size)
    return np.random.default_rng(child)


def n_components_for(duration: float, omega_lo: float, omega_hi: float) -> int:
    r"""Smallest N with Δω = (ω_hi − ω_lo)/N ≤ 2π/duration (the non-repetition rule)."""
    return max(1, int(math.ceil(duration * (omega_hi - omega_lo) / (2.0 * math.pi) - 1e-9)))


def random_frequency_components(edges, variance, theta_mean: float, s: float, rng: np.random.Generator,
                                rayleigh: bool = False, h: float = math.inf, g: float = 9.81) -> Components:
    r"""Components of one spectral part, one per frequency bin (module docstring).

    Parameters
    ----------
    edges : ndarray, shape (N+1,)
        Bin edges [rad/s], increasing (equal bins for the non-repetition rule).
    variance : ndarray, shape (N,)
        Variance V_i = ∫ S dω of each bin [m²].
    theta_mean : float
        Mean direction of travel θ̄ [rad], global frame.
    s : float
        cos-2s spreading exponent; 0 (or less) for long-crested waves.
    rng : numpy.random.Generator
        The part's stream (:func:`part_rng`).
    rayleigh : bool
        Rayleigh-distributed amplitudes instead of deterministic ones.
    h, g : float
        Water depth [m] (``inf`` deep) and gravity [m/s²] for k_i.
    """
    e = np.asarray(edges, dtype=float)
    V = np.asarray(variance, dtype=float)
    N = V.size
    omega = e[:-1] + rng.random(N) * np.diff(e)
    phi = 2.0 * math.pi * rng.random(N)
    a2 = 2.0 * V
    if rayleigh:
        a2 = a2 * -np.log1p(-rng.random(N))  # −ln(1 − u), u in [0, 1): finite
    theta = np.full(N, float(theta_mean))
    if s > 0:
        p = (rng.permutation(N) + rng.random(N)) / N
        theta = theta + spreading_quantile(p, s)
    return Components(omega, wavenumber(omega, h, g), np.sqrt(a2), np.mod(theta, 2.0 * math.pi), phi)


def regular_components(H: float, T: float, theta: float, phase: float = 0.0, h: float = math.inf,
                       g: float = 9.81) -> Components:
    r"""One regular (Airy) wave: η(0, 0, t) = (H/2) cos(2π t/T + phase).

    Parameters
    ----------
    H, T : float
        Wave height (crest to trough) [m] and period [s].
    theta : float
        Direction of travel [rad], global frame.
    phase : float
        Phase at the global origin [rad].
    """
    omega = np.array([2.0 * math.pi / T])
    return Components(omega, wavenumber(omega, h, g), np.array([0.5 * H]),
                      np.array([math.fmod(theta, 2 * math.pi) % (2 * math.pi)]), np.array([float(phase)]))
