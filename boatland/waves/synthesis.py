r"""Sums of harmonic components on time grids: wave elevation and (through excitation) forces.

Linear superposition (San Nicolás Méndez 2024 eq. 3.32, Ferreira González 2023 eq. 2.45) in the exp(+iωt) convention of
:mod:`boatland.conventions`:

.. math::
    \eta(x, y, t) = \sum_i a_i \cos\left(\omega_i t - k_i (x\cos\theta_i + y\sin\theta_i) + \varphi_i\right)
                  = \mathrm{Re}\sum_i a_i e^{i(\varphi_i - k_i(x\cos\theta_i + y\sin\theta_i))} e^{i\omega_i t},

θ_i = direction of travel (global frame), φ_i = phase at the global origin.

Kernels, all serial (no ``parallel=True``, no threaded FFT), so results do not depend on the number
of threads:

- :func:`harmonic_series` on a uniform time grid — what callers use: the cheaper of the two sums below
  by the cost estimate of :func:`synthesis_costs` (both give the same numbers to ~1e-13 of the
  amplitudes).
- :func:`harmonic_sum` on a uniform time grid, the direct sum (and the tests' oracle):
  :math:`y_j(t_n) = \mathrm{Re}\sum_i c_{ji} e^{i\omega_i t_n}` by phasor rotation,
  :math:`z_i \leftarrow z_i e^{i\omega_i\Delta t}` (one complex multiply per component and step
  instead of a cos and a sin), re-anchored every :data:`REANCHOR` steps with the
  exact :math:`e^{i\omega_i t_n}` so the rounding error stays below ~1e-13 of the amplitude over any
  record length. The component sums are vectorised (reassociated) — same result on every run.
  Cost ∝ N n_t: with the non-repetition rule (N ∝ duration) quadratic in the duration.
- :func:`boatland.waves.nufft.harmonic_sum_nufft`: the same sums by a type-1 non-uniform FFT, cost
  O(N + n_t log n_t) (Greengard & Lee 2004).
- :func:`elevation` at arbitrary points and times by direct cosine evaluation.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from boatland.waves.nufft import harmonic_sum_nufft, nufft_grid

__all__ = ["REANCHOR", "METHODS", "harmonic_sum", "harmonic_sum_kernel", "harmonic_series", "synthesis_costs", "synthesis_method",
           "elevation", "elevation_series", "component_phasors"]

#: Summation methods of :func:`harmonic_series`.
METHODS = ("auto", "direct", "nufft")

#: Steps between exact re-evaluations of the phasors in :func:`harmonic_sum`.
REANCHOR = 256

_FAST = {"reassoc", "contract"}  # lets LLVM vectorise the component sums; deterministic per build


@numba.njit(cache=True, fastmath=_FAST)
def harmonic_sum_kernel(omega, c_re, c_im, t0, h, out):
    """The compiled core of :func:`harmonic_sum`: ``out[n, j] = Σ_i Re{(c_re + i c_im)[j, i] e^{iω_i (t0 + n h)}}``
    by phasor recurrence, re-anchored exactly every :data:`REANCHOR` steps."""
    n_t, m = out.shape
    N = omega.size
    zr = np.empty(N)
    zi = np.empty(N)
    rr = np.empty(N)
    ri = np.empty(N)
    for i in range(N):
        rr[i] = math.cos(omega[i] * h)
        ri[i] = math.sin(omega[i] * h)
    for n in range(n_t):
        if n % REANCHOR == 0:
            t = t0 + n * h
            for i in range(N):
                zr[i] = math.cos(omega[i] * t)
                zi[i] = math.sin(omega[i] * t)
        for j in range(m):
            s = 0.0
            for i in range(N):
                s += c_re[j, i] * zr[i] - c_im[j, i] * zi[i]
            out[n, j] = s
        for i in range(N):
            a = zr[i]
            zr[i] = a * rr[i] - zi[i] * ri[i]
            zi[i] = a * ri[i] + zi[i] * rr[i]


def harmonic_sum(omega, c, t0: float, h: float, n: int) -> np.ndarray:
    r"""Real sums :math:`y_j(t_n) = \mathrm{Re}\sum_i c_{ji}\, e^{i\omega_i t_n}`, :math:`t_n = t_0 + n h`.

    Parameters
    ----------
    omega : ndarray, shape (N,)
        Component frequencies [rad/s].
    c : ndarray of complex, shape (m, N)
        Complex amplitudes of each output j (exp(+iωt) convention).
    t0, h : float
        First time and step of the grid [s].
    n : int
        Number of time points.

    Returns
    -------
    ndarray, shape (n, m)
    """
    c = np.atleast_2d(np.asarray(c, dtype=complex))
    out = np.empty((int(n), c.shape[0]))
    harmonic_sum_kernel(np.ascontiguousarray(omega, dtype=float), np.ascontiguousarray(c.real),
                  np.ascontiguousarray(c.imag), float(t0), float(h), out)
    return out


# Cost model [s] of the two sums (CPU time, bench/bench_waves.py; bench/README.md "Wave synthesis"):
# direct n (N (_D_N + _D_NM m) + _D_M m): the phasor update per component and step, a multiply-add per
# output, the store per output; NUFFT _F_0 + ⌈m/2⌉ (_F_PAIR + _F_GRID M + _F_COMP N): fixed costs, the
# FFT, zeroing and read-out per grid point, the gridding per component.
_D_N = 0.8e-9
_D_NM = 0.45e-9
_D_M = 5e-9
_F_0 = 1e-4
_F_PAIR = 4e-5
_F_GRID = 6e-8
_F_COMP = 6e-7


def synthesis_costs(N: int, n: int, m: int) -> tuple[float, float]:
    r"""Estimated times [s] of the direct sum and of the NUFFT for N components, n times, m outputs.

    .. math::
        T_{direct} &= n\,\bigl(N(0.8 + 0.45\,m) + 5\,m\bigr)\ \mathrm{ns}, \\
        T_{NUFFT} &= 100\ \mu\mathrm{s} + \lceil m/2\rceil\,\bigl(40\ \mu\mathrm{s} + 60\ \mathrm{ns}\cdot M
                     + 0.6\ \mu\mathrm{s}\cdot N\bigr),

    M ≈ 2n the FFT length (:func:`boatland.waves.nufft.nufft_grid`). Constants fitted to CPU times
    on the project's 2-vCPU Xeon (bench/README.md, "Wave synthesis"). Both grow ∝ n, so for long
    series the rule is a number of components: the NUFFT from N ≈ 100 (m = 1 or 6, n ≥ 10⁴); short
    series need more (N ≈ 300 at n = 1 000) and below n ≈ 500 the direct sum always wins. Near the
    crossover both cost about the same, so the fit need not be sharp.
    """
    N, n, m = int(N), int(n), int(m)
    direct = n * (N * (_D_N + _D_NM * m) + _D_M * m)
    M = nufft_grid(max(n, 1))[2]
    nufft = _F_0 + (m + 1) // 2 * (_F_PAIR + _F_GRID * M + _F_COMP * N)
    return direct, nufft


def synthesis_method(N: int, n: int, m: int) -> str:
    """``"direct"`` or ``"nufft"``: the cheaper by :func:`synthesis_costs` (a fixed rule, the same on
    every machine and thread count, so the choice never changes a result between runs)."""
    direct, nufft = synthesis_costs(N, n, m)
    return "nufft" if nufft < direct else "direct"


def harmonic_series(omega, c, t0: float, h: float, n: int, method: str = "auto") -> np.ndarray:
    r"""Real sums :math:`y_j(t_n) = \mathrm{Re}\sum_i c_{ji}\, e^{i\omega_i t_n}` on :math:`t_n = t_0 + n h`.

    What callers use for long series: the direct sum (:func:`harmonic_sum`) or the non-uniform FFT
    (:func:`boatland.waves.nufft.harmonic_sum_nufft`), whichever :func:`synthesis_method` estimates
    cheaper. Both agree to ~1e-13 of :math:`\sum_i |c_{ji}|` (≲ 1e-11 of the series' RMS for
    thousands of components); the cost of the NUFFT is O(N + n log n), linear-logarithmic in the
    duration, against O(N n) for the direct sum.

    Parameters
    ----------
    omega, c, t0, h, n
        As :func:`harmonic_sum`.
    method : {"auto", "direct", "nufft"}
        Force one sum (tests, benchmarks) or choose by cost (default).

    Returns
    -------
    ndarray, shape (n, m)
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(map(repr, METHODS))}, got {method!r}")
    c = np.atleast_2d(np.asarray(c, dtype=complex))
    omega = np.asarray(omega, dtype=float)
    if method == "auto":
        method = synthesis_method(omega.size, n, c.shape[0])
    if method == "nufft":
        return harmonic_sum_nufft(omega, c, t0, h, n)
    return harmonic_sum(omega, c, t0, h, n)


@numba.njit(cache=True)
def _elevation(omega, k, a, theta, phi, x, y, t, out):
    N = omega.size
    for p in range(x.size):
        for i in range(N):
            psi = phi[i] - k[i] * (x[p] * math.cos(theta[i]) + y[p] * math.sin(theta[i]))
            for n in range(t.size):
                out[n, p] += a[i] * math.cos(omega[i] * t[n] + psi)


def elevation(components, x, y, t) -> np.ndarray:
    r"""Surface elevation η(x, y, t) [m] of a set of components at points and times.

    Parameters
    ----------
    components : Components
        From :mod:`boatland.waves.realisation` (omega, k, a, theta, phi).
    x, y : array_like, shape (P,) or scalars
        Horizontal positions in the global frame [m].
    t : array_like, shape (T,) or scalar
        Times [s].

    Returns
    -------
    ndarray, shape (T, P)
        Elevation, direct evaluation of the sum in the module docstring (cost T·P·N cosines; use
        :func:`elevation_series` for uniform records).
    """
    xs = np.atleast_1d(np.asarray(x, dtype=float)).ravel()
    ys = np.atleast_1d(np.asarray(y, dtype=float)).ravel()
    xs, ys = np.broadcast_arrays(xs, ys)
    ts = np.atleast_1d(np.asarray(t, dtype=float)).ravel()
    out = np.zeros((ts.size, xs.size))
    cp = components
    _elevation(np.asarray(cp.omega, float), np.asarray(cp.k, float), np.asarray(cp.a, float),
               np.asarray(cp.theta, float), np.asarray(cp.phi, float),
               np.ascontiguousarray(xs), np.ascontiguousarray(ys), ts, out)
    return out


def component_phasors(components, x, y) -> np.ndarray:
    r"""Complex amplitudes :math:`a_i e^{i(\varphi_i - k_i(x\cos\theta_i + y\sin\theta_i))}` of the
    components at global points: (P, N) for P points (a scalar point gives P = 1)."""
    cp = components
    x = np.atleast_1d(np.asarray(x, dtype=float))[:, None]
    y = np.atleast_1d(np.asarray(y, dtype=float))[:, None]
    return cp.a * np.exp(1j * (cp.phi - cp.k * (x * np.cos(cp.theta) + y * np.sin(cp.theta))))


def elevation_series(components, x: float, y: float, t0: float, h: float, n: int,
                     method: str = "auto") -> np.ndarray:
    """Elevation [m] at one point (x, y) on the uniform grid t_n = t0 + n h, n < ``n``
    (:func:`harmonic_series` with ``method``)."""
    return harmonic_series(components.omega, component_phasors(components, x, y), t0, h, n, method)[:, 0]
