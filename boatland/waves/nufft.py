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
kernel. SIAM J. Sci. Comput. 41(5), C479–C504.
"""

from __future__ import annotations

import math

import numba
import numpy as np
from scipy import fft as sfft

__all__ = ["M_SP", "R_OVERSAMPLE", "nufft_grid", "harmonic_sum_nufft"]

#: Gaussian half-width in grid points (error ≈ exp(−π M_sp (R − 1)/(R − ½)) of Σ|c|).
M_SP = 16
#: Minimum oversampling of the grid, M ≥ R K.
R_OVERSAMPLE = 2.0

# 2π = _TWO_PI_HI + _TWO_PI_LO to ~1e-32 (Cody–Waite reduction of ω h)
_TWO_PI_HI = 2.0 * math.pi
_TWO_PI_LO = 2.4492935982947064e-16


def nufft_grid(n: int, M_sp: int = M_SP, R: float = R_OVERSAMPLE) -> tuple[int, int, int, float]:
    r"""Layout of the transform for ``n`` times: ``(n_c, K, M, tau)``.

    n_c = ⌊n/2⌋ is the centre sample, K = 2 max(n_c, n − n_c) the mode range (|k| ≤ K/2), M ≥ R K the
    FFT length (``scipy.fft.next_fast_len``), τ = π M_sp / (M (M − K/2)) the Gaussian's variance
    parameter (module docstring).
    """
    n_c = n // 2
    K = 2 * max(n_c, n - n_c)
    M = sfft.next_fast_len(max(int(math.ceil(R * K)), 8))
    tau = math.pi * M_sp / (M * (M - 0.5 * K))
    return n_c, K, M, tau


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


@numba.njit(cache=True)
def _extract(G, scale, n_c, s_a, j_a, s_b, j_b, out):
    """out[n, j_a] = s_a Re f, out[n, j_b] = s_b Im f (j_b < 0: none), f = scale[n] G[(n − n_c) mod M]."""
    M = G.size
    for n in range(out.shape[0]):
        idx = n - n_c
        if idx < 0:
            idx += M
        f = G[idx] * scale[n]
        out[n, j_a] = s_a * f.real
        if j_b >= 0:
            out[n, j_b] = s_b * f.imag


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
    n_c, K, M, tau = nufft_grid(n, M_sp, R)
    s = np.sum(np.abs(c), axis=1)                       # ℓ1 scale of each output
    out[:, ~np.isfinite(s)] = np.nan                    # NaN or infinite amplitudes: NaN, as the direct sum
    live = np.flatnonzero(np.isfinite(s) & (s > 0))     # (and kept apart from the other outputs)
    if live.size == 0:
        return out
    ct = c[live] * _centre_phasor(omega, float(t0), n_c, float(h))[None, :] / s[live, None]
    # points +x_i and −x_i in grid units u = x M/2π (no reduction of −x: an error of 2π's last bit
    # would become a phase error k·δx); Gaussian exp(−(x − 2πj/M)²/4τ) = exp(−α (u − j)²)
    # (in increasing u: the grid is written in order, cache-friendly on long grids)
    x = _reduced(omega, float(h))
    if not np.all(np.isfinite(x)):                      # NaN or infinite ω: NaN, as the direct sum
        out[:, live] = np.nan
        return out
    u = np.concatenate([x, -x]) * (M / _TWO_PI_HI)
    order = np.argsort(u, kind="stable")
    u = u[order]
    alpha = math.pi * (M - 0.5 * K) / (M * M_sp)
    # deconvolution 2π/φ̂(k) = √(π/τ) e^{k²τ} for k = −n_c .. n − 1 − n_c (at index k mod M of the FFT)
    k = np.arange(-n_c, n - n_c, dtype=float)
    scale = math.sqrt(math.pi / tau) * np.exp(k * k * tau)
    g = np.empty(M, dtype=complex)
    for pair in range(0, live.size, 2):
        ja = live[pair]
        jb = live[pair + 1] if pair + 1 < live.size else -1
        a = ct[pair]
        b = ct[pair + 1] if jb >= 0 else np.zeros_like(a)
        q = np.concatenate([0.5 * (a + 1j * b), 0.5 * (np.conj(a) + 1j * np.conj(b))])[order]
        g[:] = 0.0
        _spread(u, q, alpha, M_sp, g)
        G = sfft.ifft(g, workers=1, overwrite_x=False)
        _extract(G, scale, n_c, s[ja], ja, s[jb] if jb >= 0 else 0.0, jb, out)
    return out
