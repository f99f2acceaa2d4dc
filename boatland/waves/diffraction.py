r"""Linear diffraction of regular waves by a bottom-mounted vertical circular cylinder (MacCamy–Fuchs).

A monopile of radius :math:`a` stands on the sea bed in water of depth :math:`h` (or deep water,
:math:`h = \infty`), its axis on the global z axis (DESIGN.md §2: global frame, z up, origin on the
mean free surface at the pile axis). A regular wave of unit amplitude travels towards the direction
:math:`\beta` (global frame, radians; 0 travels along +x). Everything is written in the exp(+iωt)
convention of :mod:`boatland.conventions` with the phase measured at the global origin — the same as
:mod:`boatland.waves.synthesis`: the incident elevation is

.. math:: \hat\eta_0(x, y) = e^{-ik(x\cos\beta + y\sin\beta)}, \qquad
          \eta_0(t) = \mathrm{Re}\{\hat\eta_0 e^{i\omega t}\}.

Solution (MacCamy & Fuchs 1954; San Nicolás Méndez 2024 eq. 3.9–3.23; Ferreira González 2023 eq. 2.37–2.44, written there in
exp(−iωt) with :math:`H^{(1)}`). With polar coordinates :math:`x = r\cos\varphi,\ y = r\sin\varphi`
and the angle from the direction of travel :math:`\vartheta = \varphi - \beta` (so
:math:`\vartheta = \pi` is the up-wave face, :math:`\vartheta = 0` the lee), the Jacobi–Anger
expansion :math:`e^{-ikr\cos\vartheta} = \sum_m \varepsilon_m (-i)^m J_m(kr)\cos m\vartheta`
(San Nicolás Méndez 2024 eq. 3.13) and the no-flux condition :math:`\partial_r(\hat\eta_0 + \hat\eta_s) = 0` at
:math:`r = a` give the outgoing scattered wave (:math:`H_m = H_m^{(2)} = J_m - iY_m`, outgoing for
exp(+iωt), San Nicolás Méndez 2024 eq. 3.16–3.18, 3.23):

.. math::
    \hat\eta_s(r, \vartheta) = \sum_{m=0}^{M} A_m(ka)\, H_m(kr) \cos m\vartheta, \qquad
    A_m = -\varepsilon_m (-i)^m \frac{J_m'(ka)}{H_m'(ka)},

:math:`\varepsilon_0 = 1,\ \varepsilon_{m\ge1} = 2` (the complex conjugate of Ferreira González 2023 eq. 2.42,
:math:`E_m/(-i) = -n_m i^m J_m'/H_m^{(1)\prime}`, as the change of time convention requires; San Nicolás Méndez 2024
eq. 3.18 misprints :math:`H^{(1)\prime}` for :math:`H^{(2)\prime}`). Depth dependence and the other fields follow
from linear theory (:math:`\hat\eta = -\tfrac{1}{g}\,i\omega\,\hat\phi(z=0)`):

.. math::
    Z(z) = \frac{\cosh k(z+h)}{\cosh kh}\ (\to e^{kz}), \qquad
    \hat\phi = \frac{ig}{\omega} Z\,\hat\eta, \qquad
    \hat p = -\rho\,\partial_t\Phi = \rho g\, Z\, \hat\eta \ \text{(San Nicolás Méndez 2024 eq. 3.20–3.21)},

.. math::
    \hat{\mathbf u}_h = \frac{ig}{\omega} Z\, \nabla_h\hat\eta, \qquad
    \hat w = \frac{ig}{\omega} Z'\, \hat\eta, \quad Z' = \frac{k\sinh k(z+h)}{\cosh kh}\ (\to k e^{kz}).

The incident part is evaluated in closed form (not through its Bessel series), so only the scattered
series is truncated, and its truncation depends on :math:`ka` alone.

Truncation rule (:func:`n_terms`)
    The series is cut after the last order :math:`M` whose term *at the pile wall*,

    .. math:: t_m(ka) = \varepsilon_m \left|\frac{J_m'(ka)}{H_m'(ka)}\right| |H_m(ka)|
              \left(1 + \frac{m}{ka}\right),

    is ≥ ``tol`` (default 1e-6 per unit incident amplitude). :math:`|H_m(kr)|` decreases with
    :math:`r` (Nicholson's formula, Watson 1944 §13.73), so no omitted term exceeds ``tol`` anywhere
    outside the pile; beyond :math:`m \approx ka` the terms fall faster than geometrically, so the
    omitted tail is of the order of ``tol``. The factor :math:`1 + m/ka` covers the tangential
    velocity (:math:`m/kr` times the elevation term). Without that factor the rule gives
    M = 13 at ka = 4 and tol = 1e-6, the number San Nicolás Méndez 2024 (§3.2.1, Fig. 3.5) found; with it,
    M(ka = 0.5, 1, 2, 4, 8) = 6, 8, 10, 14, 20.

Numerics
    :math:`H_0, H_1` from ``scipy.special`` (cephes :math:`J_{0,1}, Y_{0,1}`), higher orders by the
    forward recurrence :math:`H_{m+1}(x) = (2m/x) H_m(x) - H_{m-1}(x)` — stable for the dominant
    :math:`Y_m` part; the :math:`J_m` part, which the recurrence loses once :math:`m > x`, is then
    below round-off of the term. The sum over orders and directions is a serial numba loop
    (no threads: results do not depend on the thread count).

References
    MacCamy, R.C. & Fuchs, R.A. (1954), *Wave forces on piles: a diffraction theory*, Beach Erosion
    Board Tech. Memo 69. Havelock, T.H. (1940), *Proc. R. Soc. A* 175. San Nicolás Méndez (2024) §3.1–3.2, §4.1;
    Ferreira González 2023 §2.4.1 eq. 2.37–2.44. Chakrabarti, S.K. (1987), *Hydrodynamics of Offshore Structures*, §6.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numba
import numpy as np
from scipy import special

from boatland.waves.dispersion import wavenumber

__all__ = ["WaveField", "n_terms", "scattering_coefficients", "depth_factor", "cylinder_field",
           "scattered_load", "pile_force", "arc_plate_force"]

#: Default accuracy of the truncated series, per unit incident amplitude.
TOL = 1e-6


class WaveField(NamedTuple):
    """Complex amplitudes per unit incident amplitude, exp(+iωt), phase at the pile axis.

    Attributes
    ----------
    eta : ndarray of complex, shape (P, Nf, Nd)
        Free-surface elevation above each point's (x, y) [m/m].
    p : ndarray of complex, shape (P, Nf, Nd)
        Linear dynamic pressure at the point [Pa/m].
    phi : ndarray of complex, shape (P, Nf, Nd)
        Velocity potential [m²/s per m].
    u : ndarray of complex, shape (3, P, Nf, Nd), or None
        Fluid velocity (global x, y, z) [m/s per m]; None unless asked for.
    """

    eta: np.ndarray
    p: np.ndarray
    phi: np.ndarray
    u: np.ndarray | None


def _eps(m):
    return np.where(np.asarray(m) == 0, 1.0, 2.0)


def _wall_terms(ka: float, m: np.ndarray) -> np.ndarray:
    """t_m(ka) of the truncation rule (module docstring)."""
    with np.errstate(all="ignore"):
        t = _eps(m) * np.abs(special.jvp(m, ka) / special.h2vp(m, ka)) * np.abs(special.hankel2(m, ka))
        t = t * (1.0 + m / ka)
    return np.where(np.isfinite(t), t, 0.0)


def n_terms(ka, tol: float = TOL) -> np.ndarray:
    r"""Highest order M of the scattered series for each ka (rule in the module docstring).

    Parameters
    ----------
    ka : array_like
        Non-dimensional wave number k·a (≥ 0; ka = 0 gives M = 0, no scattering).
    tol : float
        Largest omitted term at the pile wall, per unit incident amplitude.

    Returns
    -------
    ndarray of int, shape of ``ka``
    """
    kas = np.asarray(ka, dtype=float)
    out = np.zeros(kas.size, dtype=np.int64)
    for i, x in enumerate(kas.reshape(-1)):
        if not x > 0:
            continue
        m = np.arange(int(x + 10.0 * x ** (1.0 / 3.0) + 30))
        above = np.nonzero(_wall_terms(x, m) >= tol)[0]
        out[i] = int(above[-1]) if above.size else 0
    return out.reshape(kas.shape)


def scattering_coefficients(ka: float, M: int) -> np.ndarray:
    r""":math:`A_m = -\varepsilon_m (-i)^m J_m'(ka)/H_m^{(2)\prime}(ka)`, m = 0..M (complex, (M+1,))."""
    m = np.arange(M + 1)
    return -_eps(m) * (-1j) ** m * special.jvp(m, ka) / special.h2vp(m, ka)


def depth_factor(k, z, h: float):
    r"""Z(z) = cosh k(z+h)/cosh kh and Z'(z)/k = sinh k(z+h)/cosh kh (deep water: both e^{kz}).

    Broadcasting arrays ``k`` [rad/m] and ``z`` [m] (z ≤ 0 in the water); NaN below the bed.
    """
    k = np.asarray(k, dtype=float)
    z = np.asarray(z, dtype=float)
    e = np.exp(k * z)
    if not math.isfinite(h):
        return e, e
    with np.errstate(over="ignore", invalid="ignore"):
        q = np.exp(-2.0 * k * (z + h))
        d = 1.0 + np.exp(-2.0 * k * h)
        Z = e * (1.0 + q) / d
        Zs = e * (1.0 - q) / d
    below = z < -h
    return np.where(below, np.nan, Z), np.where(below, np.nan, Zs)


@numba.njit(cache=True, inline="always")
def _hankel_orders(H, h0, h1, x, M):
    """H[m] = H_m^{(2)}(x), m = 0 … M + 1, by the upward recurrence H_{m+1} = (2m/x) H_m − H_{m−1} from H_0, H_1."""
    H[0] = h0
    H[1] = h1
    for m in range(1, M + 1):
        H[m + 1] = (2.0 * m / x) * H[m] - H[m - 1]


def _series(r, phi_p, k, be, a: float, tol: float):
    """What both scattered-wave kernels take (module docstring): per frequency the truncation order M and the
    coefficients A_m, kr, H_0^{(2)}(kr), H_1^{(2)}(kr), and cos/sin mφ of the points and mβ of the directions."""
    M = n_terms(k * a, tol)
    Mmax = int(M.max()) if M.size else 0
    A = np.zeros((k.size, Mmax + 1), dtype=complex)
    for f in range(k.size):
        if k[f] > 0:
            A[f, : M[f] + 1] = scattering_coefficients(k[f] * a, int(M[f]))
    kr = np.ascontiguousarray(r[:, None] * k[None, :])
    with np.errstate(all="ignore"):
        H0 = special.j0(kr) - 1j * special.y0(kr)
        H1 = special.j1(kr) - 1j * special.y1(kr)
    mm = np.arange(Mmax + 1)
    return (kr, H0, H1, A, M.astype(np.int64), np.cos(np.outer(phi_p, mm)), np.sin(np.outer(phi_p, mm)),
            np.cos(np.outer(be, mm)), np.sin(np.outer(be, mm)))


@numba.njit(cache=True)
def _scattered_sums(x, H0, H1, A, M, cphi, sphi, cth, sth, grad, paired, eta, e_r, e_t):
    """Accumulate η_s, ∂η_s/∂(kr) and (1/kr) ∂η_s/∂ϑ at (P, Nf, Nd), or (P, Nf, 1) with direction f
    for frequency f when ``paired`` (buffers zeroed by the caller)."""
    P, Nf = x.shape
    Nd = cth.shape[0]
    H = np.empty(A.shape[1] + 1, dtype=np.complex128)
    for p in range(P):
        for f in range(Nf):
            xf = x[p, f]
            Mf = M[f]
            if not xf > 0.0:
                continue
            _hankel_orders(H, H0[p, f], H1[p, f], xf, Mf)
            for m in range(Mf + 1):
                t = A[f, m] * H[m]
                cp = cphi[p, m]
                sp = sphi[p, m]
                tr = 0j
                tt = 0j
                if grad:
                    dH = -H[1] if m == 0 else H[m - 1] - (m / xf) * H[m]
                    tr = A[f, m] * dH
                    tt = -(m / xf) * t
                d0, d1 = (f, f + 1) if paired else (0, Nd)
                for d in range(d0, d1):
                    o = 0 if paired else d
                    c = cp * cth[d, m] + sp * sth[d, m]  # cos m(φ − β)
                    eta[p, f, o] += t * c
                    if grad:
                        s = sp * cth[d, m] - cp * sth[d, m]  # sin m(φ − β)
                        e_r[p, f, o] += tr * c
                        e_t[p, f, o] += tt * s


@numba.njit(cache=True)
def _scattered_load(x, H0, H1, A, M, cphi, sphi, cth, sth, W, out):
    """out[j, d, f] += Σ_p W[p, f, j] η_s[p, f, d]: the scattered elevation at P points, weighted per point
    and frequency, summed over the points without forming η_s (P, Nf, Nd) (:func:`scattered_load`)."""
    P, Nf = x.shape
    Nd = cth.shape[0]
    J = W.shape[2]
    H = np.empty(A.shape[1] + 1, dtype=np.complex128)
    eta = np.empty(Nd, dtype=np.complex128)
    for p in range(P):
        for f in range(Nf):
            xf = x[p, f]
            Mf = M[f]
            if not xf > 0.0:
                continue
            _hankel_orders(H, H0[p, f], H1[p, f], xf, Mf)
            eta[:] = 0j
            for m in range(Mf + 1):
                t = A[f, m] * H[m]
                cp = cphi[p, m]
                sp = sphi[p, m]
                for d in range(Nd):
                    eta[d] += t * (cp * cth[d, m] + sp * sth[d, m])  # cos m(φ − β)
            for j in range(J):
                w = W[p, f, j]
                if w != 0.0:
                    for d in range(Nd):
                        out[j, d, f] += w * eta[d]


def scattered_load(x, y, omega, beta, a: float, weights, h: float = math.inf, *, g: float = 9.81,
                   tol: float = TOL) -> np.ndarray:
    r"""Weighted sums of the pile's scattered elevation over points: :math:`L_{jdf} = \sum_p W_{pfj}\,
    \eta_s(x_p, y_p; \omega_f, \beta_d)` — e.g. with :math:`W = -\rho g Z(z_p)\, n_{pj} A_p` the
    Froude–Krylov force of the scattered wave on a hull's panels — without forming the (P, Nf, Nd) field of
    :func:`cylinder_field` (same series, same truncation: module docstring).

    Parameters
    ----------
    x, y : array_like, shape (P,)
        Points in the global frame [m], outside the pile.
    omega : array_like, shape (Nf,)
    beta : array_like, shape (Nd,)
        Directions of travel [rad], global frame.
    a, h, g, tol
        As :func:`cylinder_field`.
    weights : ndarray, shape (P, Nf, J)
        Real weights per point, frequency and output.

    Returns
    -------
    ndarray of complex, shape (J, Nd, Nf)
    """
    x = np.atleast_1d(np.asarray(x, dtype=float)).reshape(-1)
    y = np.atleast_1d(np.asarray(y, dtype=float)).reshape(-1)
    om = np.atleast_1d(np.asarray(omega, dtype=float)).reshape(-1)
    be = np.atleast_1d(np.asarray(beta, dtype=float)).reshape(-1)
    W = np.ascontiguousarray(weights, dtype=float)
    k = wavenumber(om, h, g)
    out = np.zeros((W.shape[2], be.size, om.size), dtype=complex)
    _scattered_load(*_series(np.hypot(x, y), np.arctan2(y, x), k, be, a, tol), W, out)
    return out


def cylinder_field(x, y, z, omega, beta, a: float, h: float = math.inf, *, g: float = 9.81,
                   rho: float = 1025.0, part: str = "total", velocity: bool = False,
                   paired: bool = False, tol: float = TOL) -> WaveField:
    r"""Incident, scattered or total wave field around a bottom-mounted vertical cylinder.

    Equations and truncation rule: module docstring (MacCamy & Fuchs 1954; San Nicolás Méndez 2024 eq. 3.13–3.23).

    Parameters
    ----------
    x, y, z : array_like, shape (P,)
        Points in the global frame [m] (pile axis at x = y = 0, z = 0 on the mean free surface,
        −h ≤ z ≤ 0; z > 0 is linear extrapolation). Points inside the pile (r < a) or below the
        bed give NaN.
    omega : array_like, shape (Nf,)
        Wave frequencies [rad/s], > 0.
    beta : array_like, shape (Nd,)
        Directions of travel [rad], global frame. With ``paired``, shape (Nf,): one direction per
        frequency (wave components (ω_i, θ_i)).
    a : float
        Pile radius [m], > 0.
    h : float
        Water depth [m]; ``inf`` uses the deep-water form (k = ω²/g, Z = e^{kz}).
    g, rho : float
        Gravity [m/s²] and water density [kg/m³].
    part : {"total", "incident", "scattered"}
        Which field: η₀, η_s or η₀ + η_s.
    velocity : bool
        Also return the fluid velocity.
    paired : bool
        Pair ``omega[i]`` with ``beta[i]`` instead of taking all combinations: results (P, Nf)
        (velocity (3, P, Nf)).
    tol : float
        Accuracy of the scattered series per unit amplitude (:func:`n_terms`).

    Returns
    -------
    WaveField
        Arrays of shape (P, Nf, Nd) (velocity (3, P, Nf, Nd)), or (P, Nf) when ``paired``, per unit
        incident amplitude.
    """
    if part not in ("total", "incident", "scattered"):
        raise ValueError(f"part must be 'total', 'incident' or 'scattered', got {part!r}")
    x = np.atleast_1d(np.asarray(x, dtype=float)).reshape(-1)
    y = np.atleast_1d(np.asarray(y, dtype=float)).reshape(-1)
    z = np.atleast_1d(np.asarray(z, dtype=float)).reshape(-1)
    om = np.atleast_1d(np.asarray(omega, dtype=float)).reshape(-1)
    be = np.atleast_1d(np.asarray(beta, dtype=float)).reshape(-1)
    P, Nf, Nd = x.size, om.size, be.size
    if paired and Nd != Nf:
        raise ValueError(f"paired: expected one direction per frequency ({Nf}), got {Nd}")
    cb = np.cos(be)[None, :, None] if paired else np.cos(be)[None, None, :]  # broadcasts to (P, Nf, Nd')
    sb = np.sin(be)[None, :, None] if paired else np.sin(be)[None, None, :]
    Nd = 1 if paired else Nd
    k = wavenumber(om, h, g)
    r = np.hypot(x, y)
    phi_p = np.arctan2(y, x)

    eta = np.zeros((P, Nf, Nd), dtype=complex)
    gx = np.zeros((P, Nf, Nd), dtype=complex) if velocity else None
    gy = np.zeros((P, Nf, Nd), dtype=complex) if velocity else None
    if part != "scattered":
        kx = cb * x[:, None, None] + sb * y[:, None, None]
        eta += np.exp(-1j * k[None, :, None] * kx)
        if velocity:
            gx += -1j * k[None, :, None] * cb * eta
            gy += -1j * k[None, :, None] * sb * eta
    if part != "incident":
        es = np.zeros((P, Nf, Nd), dtype=complex)
        e_r = np.zeros_like(es) if velocity else np.zeros((1, 1, 1), dtype=complex)
        e_t = np.zeros_like(es) if velocity else np.zeros((1, 1, 1), dtype=complex)
        _scattered_sums(*_series(r, phi_p, k, be, a, tol), velocity, paired, es, e_r, e_t)
        eta += es
        if velocity:
            c, s = np.cos(phi_p)[:, None, None], np.sin(phi_p)[:, None, None]
            kk = k[None, :, None]
            gx += kk * (e_r * c - e_t * s)
            gy += kk * (e_r * s + e_t * c)
    inside = r < a * (1.0 - 1e-9)
    eta[inside] = np.nan

    Z, Zs = depth_factor(k[None, :], z[:, None], h)  # (P, Nf)
    p = rho * g * Z[:, :, None] * eta
    with np.errstate(divide="ignore", invalid="ignore"):
        ig_w = 1j * g / om  # (Nf,)
    phi = ig_w[None, :, None] * Z[:, :, None] * eta
    u = None
    if velocity:
        fac = ig_w[None, :, None] * Z[:, :, None]
        u = np.stack([fac * gx, fac * gy, ig_w[None, :, None] * (k[None, :] * Zs)[:, :, None] * eta])
        u[:, inside] = np.nan
    if paired:
        eta, p, phi = eta[..., 0], p[..., 0], phi[..., 0]
        u = None if u is None else u[..., 0]
    # surface elevation belongs to (x, y); the depth factor only enters p, φ, u
    return WaveField(eta=eta, p=p, phi=phi, u=u)


def pile_force(omega, a: float, h: float = math.inf, *, g: float = 9.81, rho: float = 1025.0) -> np.ndarray:
    r"""Closed-form MacCamy–Fuchs horizontal force on the whole pile, per unit amplitude.

    .. math:: \hat F_x = \frac{4\rho g}{k^2}\,\frac{\tanh kh}{H_1^{(2)\prime}(ka)}

    for a wave travelling along +x (phase at the pile axis, exp(+iωt)); deep water: tanh kh = 1.
    It is :math:`-\oint\!\int_{-h}^0 \hat p\, n_x\, dz\, a\,d\vartheta` with the wall pressure
    :math:`\hat p = \rho g Z \sum_m \varepsilon_m(-i)^m \frac{-2i}{\pi ka H_m'(ka)}\cos m\vartheta`
    (Wronskian :math:`J_m H_m' - J_m' H_m = -2i/(\pi x)`), of which only m = 1 survives
    (MacCamy & Fuchs 1954; Chakrabarti 1987 eq. 6.44). Long-wave limit :math:`2i\pi\rho g a^2\tanh kh`:
    the inertia force with C_M = 2, leading the crest by 90°.

    Returns
    -------
    ndarray of complex, shape of ``omega`` [N/m]
    """
    k = wavenumber(omega, h, g)
    th = np.tanh(k * h) if math.isfinite(h) else 1.0
    return 4.0 * rho * g * th / (k * k * special.h2vp(1, k * a))


def _arc_trig(m: np.ndarray, t1: float, t2: float) -> np.ndarray:
    r""":math:`\int_{\theta_1}^{\theta_2}\cos m\theta\cos\theta\,d\theta` (San Nicolás Méndez 2024 eq. 4.1–4.3)."""
    m = np.asarray(m, dtype=float)
    out = np.empty(m.shape)
    for i, mi in enumerate(m):
        if mi == 1:
            out[i] = 0.5 * (t2 - t1 + math.cos(t2) * math.sin(t2) - math.cos(t1) * math.sin(t1))
        else:
            out[i] = (math.cos(mi * t1) * math.sin(t1) - mi * math.cos(t1) * math.sin(mi * t1)
                      - math.cos(mi * t2) * math.sin(t2) + mi * math.cos(t2) * math.sin(mi * t2)) / (mi * mi - 1)
    return out


def arc_plate_force(omega, a: float, d: float, theta1: float, theta2: float, h: float, *,
                    part: str = "scattered", g: float = 9.81, rho: float = 1025.0,
                    tol: float = TOL) -> np.ndarray:
    r"""Closed-form x-force on a bottom-mounted arc plate r = d, θ₁ ≤ θ ≤ θ₂ (San Nicolás Méndez 2024 §4.1).

    Wave along +x (θ = 0 is the lee of the pile). With the plate normal
    :math:`\mathbf n = (\cos\theta, \sin\theta, 0)` and :math:`F_1 = \int p\, n_1\, dS` over one face
    (San Nicolás Méndez 2024 eq. 3.22, 4.1–4.4; Kagemoto-type closed form after San Nicolás Méndez 2024 ref. [7]):

    .. math::
        \frac{F_1}{\rho g h d} = \frac{\tanh kh}{kh}\sum_m c_m\,
        \int_{\theta_1}^{\theta_2}\cos m\theta\cos\theta\, d\theta,

    :math:`c_m = A_m H_m^{(2)}(kd)` for the scattered wave, :math:`c_m = \varepsilon_m(-i)^m J_m(kd)`
    for the incident (Froude–Krylov) wave, with the trigonometric integral of eq. 4.1–4.3. Note:
    San Nicolás Méndez 2024 writes eq. 4.1 without the minus sign of :math:`A_m` (its eq. 3.21 has it) and
    :math:`H'` without the kind; this function follows eq. 3.21, which the panel integration of
    :func:`cylinder_field` pressures confirms.

    Parameters
    ----------
    omega : array_like, shape (Nf,)
    a, d : float
        Pile radius and arc radius [m] (d > a).
    theta1, theta2 : float
        Arc ends [rad] (polar angle from the direction of travel).
    h : float
        Water depth [m]; the plate spans −h ≤ z ≤ 0 (``inf``: deep water, ∫ e^{kz} dz = 1/k).
    part : {"scattered", "incident"}

    Returns
    -------
    ndarray of complex, shape (Nf,) [N/m]
    """
    om = np.atleast_1d(np.asarray(omega, dtype=float))
    k = wavenumber(om, h, g)
    out = np.empty(om.size, dtype=complex)
    for f, kf in enumerate(k):
        if part == "scattered":
            M = int(n_terms(kf * a, tol))
            m = np.arange(M + 1)
            c = scattering_coefficients(kf * a, M) * special.hankel2(m, kf * d)
        elif part == "incident":
            M = int(kf * d + 4.0 * (kf * d) ** (1.0 / 3.0) + 15)
            m = np.arange(M + 1)
            c = _eps(m) * (-1j) ** m * special.jv(m, kf * d)
        else:
            raise ValueError(f"part must be 'scattered' or 'incident', got {part!r}")
        depth = math.tanh(kf * h) / kf if math.isfinite(h) else 1.0 / kf  # ∫ Z dz over the plate
        out[f] = rho * g * d * depth * np.sum(c * _arc_trig(m, theta1, theta2))
    return out
