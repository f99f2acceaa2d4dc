r"""Harmonic sums on a uniform time grid by a type-1 non-uniform FFT (Gaussian gridding).

The sums of :func:`boatland.waves.synthesis.harmonic_sum`,

.. math::
    y_j(t_n) = \mathrm{Re}\sum_{i=1}^{N} c_{ji}\, e^{i\omega_i t_n}, \qquad t_n = t_0 + n h,\quad n = 0..n_t-1,

cost :math:`N n_t` summed directly; with the non-repetition rule N grows with the duration and so the
direct sum grows with its square. The component frequencies are not on a uniform grid (random within
bins, truncated measured spectra, regular waves, sums of parts), so a plain inverse FFT does not
apply. Written with the centre time :math:`t_c = t_0 + n_c h` (:math:`n_c = \lfloor n_t/2\rfloor`),
:math:`x_i = \omega_i h \bmod 2\pi` and :math:`k = n - n_c`,

.. math::
    f(k) = \sum_i \tilde c_i\, e^{i k x_i}, \qquad \tilde c_i = c_i e^{i\omega_i t_c}, \qquad |k| \le K/2,

is a type-1 NUFFT (non-uniform points :math:`x_i`, uniform modes k). Gaussian gridding (Dutt &
Rokhlin 1993; Greengard & Lee 2004): convolve the point sources with the periodised Gaussian
:math:`\varphi(x) = e^{-x^2/4\tau}` on a grid of M = R K points (R ≥ 2), truncated at
:math:`M_{sp}` grid points on each side; one FFT of the grid gives
:math:`G(k) = \frac{1}{2\pi}\hat\varphi(k) f(k)`, :math:`\hat\varphi(k) = \sqrt{4\pi\tau}\,e^{-k^2\tau}`,
and dividing by :math:`\hat\varphi` gives f. With Greengard & Lee's
:math:`\tau = \pi M_{sp} / (M (M - K/2))` truncation and aliasing errors are balanced at

.. math:: \epsilon \approx e^{-\pi M_{sp} (R - 1)/(R - 1/2)} \quad (R = 2,\ M_{sp} = 16:\ 3\cdot 10^{-15})

relative to :math:`\sum_i |\tilde c_i|`. Cost: :math:`(2M_{sp}+1)\,N` for the gridding plus one FFT of
:math:`M \approx 2 n_t` points per two outputs — :math:`O(N + n_t \log n_t)`, linear-logarithmic in
the duration whatever N.

The FFT of a grid whose points fill an arc (four steps, pruned input)
    Sea-state frequencies fill only an arc of the circle: :math:`|x_i| \le w` with
    :math:`w = \omega_{max} h` (0.17 rad for 6.7 rad/s at h = 0.025 s, against 2π), so the gridded
    sequence g is zero outside the window :math:`|j| \le S = \lceil wM/2\pi\rceil + M_{sp} + 1`. With
    :math:`M = M_1 M_2`, :math:`M_1 \ge 2S + 1` and :math:`k = k_2 + M_2 k_1`,

    .. math:: G(k_2 + M_2 k_1) = \frac{1}{M}\sum_{j=-S}^{M_1-S-1} \Big[g_j\, e^{2\pi i j k_2/M}\Big]
              e^{2\pi i j k_1/M_1},

    i.e. :math:`M_2` FFTs of length :math:`M_1` of the twiddled window — the four-step FFT (Bailey
    1990) whose first step is trivial because the input has one nonzero block. The same M log M work
    in transforms of a few hundred kB that stay in cache (≈ 3× faster here than one transform of
    12.8 MB for a 10 000-s record). The twiddle :math:`e^{2\pi i j k_2/M}` is the product of two
    tabulated factors, each rounded once from the exact integer phase :math:`(j k_2 \bmod M)`; with
    :math:`M_2 = 1` (points all round the circle, or short records) it is the plain FFT.

Round-off
    The centre phase :math:`\omega_i t_c` is formed in two doubles (Dekker's exact product, Knuth's
    sum): at :math:`t_c \sim 5000` s a double holds :math:`\omega t_c` only to ~1e-12 rad, and every
    sample would inherit that. What is left is the one rounding of :math:`x_i = \omega_i h`, a phase
    error :math:`\omega_i |t - t_c| \cdot 1.1\cdot 10^{-16}` that grows away from the centre — the same
    size as the direct sum's, whose phases :math:`\omega_i t` are rounded the same way (at 10 000 s
    both are ~1e-12 of the series' RMS; the time stamps themselves are only known to ulp(10⁴ s)
    ≈ 2e-12 s).
Two real outputs per complex FFT
    :math:`y_a + i\,y_b = \sum_i \tfrac12(\hat c_{ai} + i\hat c_{bi}) e^{i\omega_i t}
    + \tfrac12(\bar{\hat c}_{ai} + i\bar{\hat c}_{bi}) e^{-i\omega_i t}`: the points :math:`\pm x_i`
    carry both outputs; the real and imaginary parts of the result are :math:`y_a` and :math:`y_b`.
    Each output is scaled by its own :math:`s_j = \sum_i |c_{ji}|` first (:math:`\hat c = c/s`), so the
    error of each is relative to its own amplitudes, not to its partner's (forces and moments differ
    by orders of magnitude; a zero output stays exactly zero).
Frequencies above the grid's Nyquist :math:`\pi/h`
    alias onto :math:`x_i = \omega_i h \bmod 2\pi`, exactly as the samples of the direct sum do
    (:math:`\cos\omega_i t_n` only sees :math:`\omega_i h` modulo 2π). The reduction uses 2π in two
    parts (Cody–Waite), so it adds an error of the order of the rounding of :math:`\omega_i h` itself;
    the points :math:`-x_i` are not reduced at all (the gridding is periodic).
Why not a library
    finufft (Barnett, Magland & af Klinteberg 2019) does the same with a narrower
    exponential-of-semicircle kernel and R = 1.25, i.e. FFTs ~1.6× shorter — but it is a compiled
    dependency with OpenMP threads (to be pinned to one) for a 1-D transform whose cost here is one
    pocketfft call per two outputs; the Gaussian's Fourier transform is closed-form, so the whole
    method is these ~100 lines of numpy, numba and ``scipy.fft``.
Determinism
    Serial numba gridding and ``scipy.fft`` with ``workers=1`` (one transform at a time): the result
    depends on nothing but the inputs — bit-identical on 1 or N cores, whatever
    ``scipy.fft.set_workers`` says.

References
----------
Dutt, A. & Rokhlin, V. (1993). Fast Fourier transforms for nonequispaced data. SIAM J. Sci. Comput.
14(6), 1368–1393. Greengard, L. & Lee, J.-Y. (2004). Accelerating the nonuniform fast Fourier
transform. SIAM Review 46(3), 443–454. Dekker, T. J. (1971). A floating-point technique for extending
the available precision. Numer. Math. 18, 224–242. Barnett, A. H., Magland, J. & af Klinteberg, L.
(2019). A parallel nonuniform fast Fourier transform library based on an "exponential of semicircle"
kernel. SIAM J. Sci. Comput. 41(5), C479–C504. Bailey, D. H. (1990). FFTs in external or hierarchical
memory. J. Supercomputing 4(1), 23–35.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import NamedTuple

import numba
import numpy as np
from scipy import fft as sfft

__all__ = ["M_SP", "R_OVERSAMPLE", "Layout", "nufft_grid", "nufft_layout", "harmonic_sum_nufft"]

#: Gaussian half-width in grid points (error ≈ exp(−π M_sp (R − 1)/(R − ½)) of Σ|c|).
M_SP = 16
#: Minimum oversampling of the grid, M ≥ R K.
R_OVERSAMPLE = 2.0

# 2π = _TWO_PI_HI + _TWO_PI_LO to ~1e-32 (Cody–Waite reduction of ω h)
_TWO_PI_HI = 2.0 * math.pi
_TWO_PI_LO = 2.4492935982947064e-16


class Layout(NamedTuple):
    """How :func:`harmonic_sum_nufft` lays out the transform of ``n`` times (module docstring): centre
    sample ``n_c``, mode range ``K`` (|k| ≤ K/2), FFT length ``M = M1 M2`` (``M2`` transforms of length
    ``M1``), the half-width ``S`` of the window of grid points the Gaussians reach, and τ."""

    n_c: int
    K: int
    M1: int
    M2: int
    S: int
    tau: float

    @property
    def M(self) -> int:
        return self.M1 * self.M2


def nufft_layout(n: int, half_width: float = math.pi, M_sp: int = M_SP, R: float = R_OVERSAMPLE) -> Layout:
    r"""Layout of the transform for ``n`` times and points within ``half_width`` [rad] of 0 on the circle.

    n_c = ⌊n/2⌋, K = 2 max(n_c, n − n_c), τ = π M_sp / (M (M − K/2)) (Greengard & Lee 2004) as for one
    FFT; M = M1 M2 ≥ R K with M1 a fast FFT length (``scipy.fft.next_fast_len``) that holds the window
    |j| ≤ S = ⌈half_width M/2π⌉ + M_sp + 1 (M1 ≥ 2S + 1), as many transforms M2 as that allows.
    ``half_width = π`` (points anywhere) gives M2 = 1 and M = next_fast_len(R K): one FFT.
    """
    n_c = n // 2
    K = 2 * max(n_c, n - n_c)
    target = max(int(math.ceil(R * K)), 8)
    frac = min(max(float(half_width), 0.0), math.pi) / math.pi
    M2 = max(1, int(target // (frac * target + 2 * M_sp + 4)))
    while True:
        M1 = sfft.next_fast_len(-(-target // M2))
        S = int(math.ceil(half_width * (M1 * M2) / _TWO_PI_HI)) + M_sp + 1
        if M2 == 1 or M1 >= 2 * S + 1:
            break
        M2 -= 1
    M = M1 * M2
    return Layout(n_c, K, M1, M2, min(S, M1), math.pi * M_sp / (M * (M - 0.5 * K)))


def nufft_grid(n: int, M_sp: int = M_SP, R: float = R_OVERSAMPLE,
               half_width: float = math.pi) -> tuple[int, int, int, float]:
    r"""``(n_c, K, M, tau)`` of :func:`nufft_layout` (M = M1 M2 the length of the whole FFT grid)."""
    lay = nufft_layout(n, half_width, M_sp, R)
    return lay.n_c, lay.K, lay.M, lay.tau


def _reduced(omega, h):
    """x = ω h mod 2π in [0, 2π), reduced with 2π in two parts."""
    wh = omega * h
    q = np.floor(wh / _TWO_PI_HI)
    x = (wh - q * _TWO_PI_HI) - q * _TWO_PI_LO
    return np.where(x < 0.0, x + _TWO_PI_HI, np.where(x >= _TWO_PI_HI, x - _TWO_PI_HI, x))


def _two_product(a, b):
    """p + e = a b exactly, p = fl(a b) (Dekker 1971; no FMA needed). Scalars or arrays."""
    p = a * b
    split = 134217729.0  # 2^27 + 1
    x = split * a
    a_hi = x - (x - a)
    a_lo = a - a_hi
    y = split * b
    b_hi = y - (y - b)
    b_lo = b - b_hi
    return p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo


def _centre_phasor(omega, t0: float, n_c: int, h: float):
    r""":math:`e^{i\omega (t_0 + n_c h)}` with the phase carried in two doubles.

    Near t ~ 10⁴ s a double holds t only to ~1e-12 s and ωt only to ~1e-12 rad; every sample of the
    NUFFT inherits the centre's phase, so :math:`t_c = t_0 + n_c h` and :math:`\omega t_c` are formed
    exactly (Dekker products, Knuth sum) and only the final sum is rounded.
    """
    p1, e1 = _two_product(float(n_c), h)
    t_hi = t0 + p1                                    # Knuth's two-sum of t0 and p1
    v = t_hi - t0
    t_lo = ((t0 - (t_hi - v)) + (p1 - v)) + e1
    p, e = _two_product(omega, t_hi)
    return np.exp(1j * p) * np.exp(1j * (e + omega * t_lo))


@numba.njit(cache=True)
def _spread(u, q, alpha, M_sp, g):
    r"""g[j mod M] += q_p exp(−α (u_p − j)²) for the nodes j within M_sp of each point (serial).

    Fast Gaussian gridding (Greengard & Lee 2004, §3): with d = u − near ∈ [−½, ½],
    :math:`e^{-\alpha(d-l)^2} = e^{-\alpha d^2}\,(e^{2\alpha d})^l\,e^{-\alpha l^2}`: three
    exponentials per point instead of 2M_sp + 1.
    """
    M = g.size
    L = 2 * M_sp + 1
    E3 = np.empty(L)
    for l in range(L):
        E3[l] = math.exp(-alpha * (l - M_sp) ** 2)
    w = np.empty(L)
    for p in range(u.size):
        near = math.floor(u[p] + 0.5)
        d = u[p] - near
        E1 = math.exp(-alpha * d * d)
        E2 = math.exp(2.0 * alpha * d)
        w[M_sp] = E1 * E3[M_sp]
        up = E1
        dn = E1
        E2i = 1.0 / E2
        for l in range(1, M_sp + 1):
            up *= E2
            dn *= E2i
            w[M_sp + l] = up * E3[M_sp + l]
            w[M_sp - l] = dn * E3[M_sp - l]
        base = int(near) - M_sp
        base %= M
        qp = q[p]
        if base + L <= M:
            for l in range(L):
                g[base + l] += w[l] * qp
        else:
            for l in range(L):
                g[(base + l) % M] += w[l] * qp


@lru_cache(maxsize=8)
def _twiddles(M1: int, M2: int, S: int) -> tuple[int, np.ndarray, np.ndarray]:
    r"""``(P, T_lo, T_hi)`` with :math:`e^{2\pi i j k_2/M} = T_{lo}[k_2, l]\,T_{hi}[k_2, q]` for
    :math:`j + S = qP + l`, :math:`0 \le l < P`: each factor rounded once from its exact integer phase
    (the phase reduced mod M in integers). Kept per layout: a campaign's trials share their length."""
    M = M1 * M2
    P = max(1, math.isqrt(M1))
    k2 = np.arange(M2, dtype=np.int64)[:, None]
    lo = np.arange(P, dtype=np.int64)[None, :]
    hi = np.arange(-(-M1 // P), dtype=np.int64)[None, :] * P - S
    T_lo = np.exp(1j * (_TWO_PI_HI / M) * ((lo * k2) % M))
    T_hi = np.exp(1j * (_TWO_PI_HI / M) * ((hi * k2) % M))
    return P, T_lo, T_hi


@lru_cache(maxsize=8)
def _deconvolution(n: int, n_c: int, tau: float, M2: int) -> np.ndarray:
    r""":math:`2\pi/\hat\varphi(k)\,/M_2 = \sqrt{\pi/\tau}\,e^{k^2\tau}/M_2` for k = −n_c … n − 1 − n_c
    (the 1/M2 completes the 1/M1 of each transform to the 1/M of the whole). Read only."""
    k = np.arange(-n_c, n - n_c, dtype=float)
    scale = (math.sqrt(math.pi / tau) / M2) * np.exp(k * k * tau)
    scale.flags.writeable = False
    return scale


@numba.njit(cache=True)
def _twiddled(g, S, P, T_lo, T_hi, rows):
    r"""rows[k2, j mod M1] = g[j mod M1] e^{2πi j k2/M} for j = −S … M1 − S − 1 (the window)."""
    M2, M1 = rows.shape
    tw = np.empty(T_hi.shape[1] * P, dtype=np.complex128)   # e^{2πi j k2/M} at j + S = 0 … M1 − 1
    for k2 in range(M2):
        for q in range(T_hi.shape[1]):
            th = T_hi[k2, q]
            for l in range(P):
                tw[q * P + l] = T_lo[k2, l] * th
        for jj in range(M1 - S):                  # j = jj ≥ 0
            rows[k2, jj] = g[jj] * tw[jj + S]
        for jj in range(M1 - S, M1):              # j = jj − M1 < 0
            rows[k2, jj] = g[jj] * tw[jj + S - M1]


@numba.njit(cache=True)
def _extract(G, scale, n_c, s_a, j_a, s_b, j_b, out):
    """out[n, j_a] = s_a Re f, out[n, j_b] = s_b Im f (j_b < 0: none), f = scale[n] G(k), k = (n − n_c) mod M,
    G(k2 + M2 k1) = G[k2, k1]."""
    M2, M1 = G.shape
    k = M1 * M2 - n_c if n_c > 0 else 0
    k1, k2 = k // M2, k % M2
    for n in range(out.shape[0]):
        f = G[k2, k1] * scale[n]
        out[n, j_a] = s_a * f.real
        if j_b >= 0:
            out[n, j_b] = s_b * f.imag
        k2 += 1
        if k2 == M2:
            k2 = 0
            k1 += 1
            if k1 == M1:
                k1 = 0


def harmonic_sum_nufft(omega, c, t0: float, h: float, n: int, M_sp: int = M_SP,
                       R: float = R_OVERSAMPLE) -> np.ndarray:
    r"""Real sums :math:`y_j(t_n) = \mathrm{Re}\sum_i c_{ji}\, e^{i\omega_i t_n}`, :math:`t_n = t_0 + n h`, by NUFFT.

    Same arguments and result as :func:`boatland.waves.synthesis.harmonic_sum` (the direct sum), to
    round-off: ≲ 1e-13 of :math:`\sum_i |c_{ji}|` per output over 10⁴ s (module docstring).

    Parameters
    ----------
    omega : ndarray, shape (N,)
        Component frequencies [rad/s] (any; those above π/h alias as in the direct sum).
    c : ndarray of complex, shape (m, N)
        Complex amplitudes of each output j (exp(+iωt) convention).
    t0, h : float
        First time and step of the grid [s].
    n : int
        Number of time points.
    M_sp : int
        Gaussian half-width in grid points.
    R : float
        Minimum oversampling of the FFT grid (≥ 2 for the error estimate).

    Returns
    -------
    ndarray, shape (n, m)
    """
    c = np.atleast_2d(np.asarray(c, dtype=complex))
    omega = np.ascontiguousarray(omega, dtype=float)
    m, n = c.shape[0], int(n)
    out = np.zeros((n, m))
    if n == 0 or omega.size == 0 or m == 0:
        return out
    s = np.sum(np.abs(c), axis=1)                       # ℓ1 scale of each output
    out[:, ~np.isfinite(s)] = np.nan                    # NaN or infinite amplitudes: NaN, as the direct sum
    live = np.flatnonzero(np.isfinite(s) & (s > 0))     # (and kept apart from the other outputs)
    if live.size == 0:
        return out
    x = _reduced(omega, float(h))
    if not np.all(np.isfinite(x)):                      # NaN or infinite ω: NaN, as the direct sum
        out[:, live] = np.nan
        return out
    # the arc |x| ≤ w the points ±x_i fill decides how the FFT is split (module docstring)
    lay = nufft_layout(n, float(np.max(np.minimum(x, _TWO_PI_HI - x))), M_sp, R)
    n_c, K, M, tau = lay.n_c, lay.K, lay.M, lay.tau
    ct = c[live] * _centre_phasor(omega, float(t0), n_c, float(h))[None, :] / s[live, None]
    # points +x_i and −x_i in grid units u = x M/2π (no reduction of −x: an error of 2π's last bit
    # would become a phase error k·δx); Gaussian exp(−(x − 2πj/M)²/4τ) = exp(−α (u − j)²), written at
    # j mod M1 (the window |j| ≤ S fits in M1) in increasing u: in order, cache-friendly
    u = np.concatenate([x, -x]) * (M / _TWO_PI_HI)
    order = np.argsort(u, kind="stable")
    u = u[order]
    alpha = math.pi * (M - 0.5 * K) / (M * M_sp)
    scale = _deconvolution(n, n_c, tau, lay.M2)
    P, T_lo, T_hi = _twiddles(lay.M1, lay.M2, lay.S)
    g = np.empty(lay.M1, dtype=complex)
    rows = np.empty((lay.M2, lay.M1), dtype=complex)
    for pair in range(0, live.size, 2):
        ja = live[pair]
        jb = live[pair + 1] if pair + 1 < live.size else -1
        a = ct[pair]
        b = ct[pair + 1] if jb >= 0 else np.zeros_like(a)
        q = np.concatenate([0.5 * (a + 1j * b), 0.5 * (np.conj(a) + 1j * np.conj(b))])[order]
        g[:] = 0.0
        _spread(u, q, alpha, M_sp, g)
        _twiddled(g, lay.S, P, T_lo, T_hi, rows)
        G = sfft.ifft(rows, axis=1, workers=1, overwrite_x=True)   # G(k2 + M2 k1) = G[k2, k1]
        _extract(G, scale, n_c, s[ja], ja, s[jb] if jb >= 0 else 0.0, jb, out)
    return out
