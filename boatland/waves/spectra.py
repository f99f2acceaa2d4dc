r"""Wave spectra (JONSWAP, Pierson–Moskowitz, TMA) and cos-2s directional spreading.

All spectra are one-sided variance densities :math:`S(\omega)` [m² s/rad] of the surface elevation,
:math:`m_0 = \int_0^\infty S\,d\omega = \sigma_\eta^2`, :math:`H_{m0} = 4\sqrt{m_0}` (San Nicolás Méndez 2024 eq. 3.35–3.36).

JONSWAP (Hasselmann et al. 1973), written about the Pierson–Moskowitz spectrum of the same Hs and Tp
(Sin Mon 2021 eq. 30–31, San Nicolás Méndez 2024 eq. 3.34, Ferreira González 2023 eq. 2.48):

.. math::
    S_{PM}(\omega) = \frac{5}{16} H_s^2 \omega_p^4\, \omega^{-5}
                     \exp\left[-\frac54\left(\frac{\omega_p}{\omega}\right)^4\right], \qquad
    S_J(\omega) = C(\gamma, \sigma_a, \sigma_b)\, S_{PM}(\omega)\, \gamma^{r(\omega)}, \qquad
    r = \exp\left[-\frac{(\omega - \omega_p)^2}{2\sigma^2\omega_p^2}\right],

with :math:`\omega_p = 2\pi/T_p`, σ = σ_a for ω ≤ ω_p and σ_b above. :math:`S_{PM}` has
:math:`m_0 = H_s^2/16` exactly (substitute :math:`u = (\omega_p/\omega)^4`), so the normalisation
is :math:`C = 1/I` with

.. math::
    I(\gamma, \sigma_a, \sigma_b) = 5\int_0^\infty x^{-5} e^{-\frac54 x^{-4}} \gamma^{r(x)} dx
      = 1 + 5\int_0^\infty x^{-5} e^{-\frac54 x^{-4}} \left(\gamma^{r(x)} - 1\right) dx,
      \qquad x = \omega/\omega_p .

The second integrand is confined to the Gaussian of the peak enhancement; it is integrated with
Gauss–Legendre quadrature on [1 − 12σ_a, 1] and [1, 1 + 12σ_b] (beyond 12σ, r < 1e-31), using
``expm1`` for γ^r − 1. The result is exact to ~1e-15 relative, so ``4 sqrt(m0) = Hs`` holds to
machine precision. San Nicolás Méndez (2024)'s closed-form :math:`A_\gamma = 1 - 0.287\ln\gamma` (DNV-RP-C205
§3.5.5) is within 0.3 % of C for 1 ≤ γ ≤ 5 (2 % at γ = 7, 7 % at γ = 10); Ferreira González 2023's
Lewandowski (2004) :math:`1/(1 + (\gamma-1)/6)` (eq. 2.49) is 10 % high at γ = 3.3.

Pierson–Moskowitz is JONSWAP with γ = 1 (C = 1). TMA (Bouws et al. 1985) is JONSWAP times the
Kitaigorodskii depth factor φ(ω, h) of :func:`boatland.waves.dispersion.tma_depth_factor`; as
published (and as DNV-RP-C205 §3.5.5.5 uses it) the JONSWAP part keeps its deep-water
normalisation, so in finite depth :math:`4\sqrt{m_0} < H_s` — the energy a shallow bottom removes.

Directional spreading (Longuet-Higgins, Cartwright & Smith 1963; Sin Mon 2021 eq. 33):

.. math::
    D(\theta) = \frac{\Gamma(s+1)}{2\sqrt\pi\,\Gamma(s+\frac12)}
                \cos^{2s}\left(\frac{\theta - \bar\theta}{2}\right), \qquad
    |\theta - \bar\theta| \le \pi, \qquad \int_{-\pi}^{\pi} D\,d\theta = 1,

identical to Sin Mon 2021's :math:`\frac{2^{2s-1}}{\pi}\frac{\Gamma^2(s+1)}{\Gamma(2s+1)}` by the
duplication formula. Its cumulative distribution is a regularised incomplete beta function (substitute
:math:`v = \sin^2(u/2)`, :math:`u = \theta - \bar\theta`):

.. math:: F(u) = \tfrac12 + \tfrac12\,\mathrm{sign}(u)\, I_{\sin^2(u/2)}\left(\tfrac12, s + \tfrac12\right),

inverted exactly with ``scipy.special.betaincinv`` for sampling directions.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

from boatland.waves.dispersion import tma_depth_factor

__all__ = [
    "SIGMA_A", "SIGMA_B", "jonswap_normalisation", "jonswap", "pierson_moskowitz", "tma", "gaussian_swell",
    "gaussian_band", "gaussian_bin_variance",
    "spectrum_band", "bin_variance", "spreading_cos2s", "spreading_constant", "spreading_quantile",
]

#: Spectral width parameters of the mean JONSWAP spectrum (Hasselmann et al. 1973).
SIGMA_A = 0.07
SIGMA_B = 0.09

_GL_X, _GL_W = np.polynomial.legendre.leggauss(96)
_N_SIGMA = 12.0


def jonswap_normalisation(gamma: float, sigma_a: float = SIGMA_A, sigma_b: float = SIGMA_B) -> float:
    r"""The factor C = 1/I that makes the JONSWAP spectrum's :math:`4\sqrt{m_0}` equal Hs.

    See the module docstring for I(γ, σ_a, σ_b). C(1, ·, ·) = 1 exactly; C(3.3, 0.07, 0.09) = 0.655760.
    """
    if gamma == 1.0:
        return 1.0
    lng = math.log(gamma)
    total = 0.0
    sides = ((max(1.0 - _N_SIGMA * sigma_a, 0.05), 1.0, sigma_a), (1.0, 1.0 + _N_SIGMA * sigma_b, sigma_b))
    for lo, hi, sigma in sides:
        x = 0.5 * (hi - lo) * _GL_X + 0.5 * (hi + lo)
        r = np.exp(-((x - 1.0) ** 2) / (2.0 * sigma * sigma))
        f = x ** -5 * np.exp(-1.25 * x ** -4) * np.expm1(r * lng)
        total += 0.5 * (hi - lo) * float(np.dot(_GL_W, f))
    return 1.0 / (1.0 + 5.0 * total)


def _pm_shape(omega: np.ndarray, omega_p: float) -> np.ndarray:
    """(5/16) ωp⁴ ω⁻⁵ exp(−5/4 (ωp/ω)⁴); exactly 0 below 0.05 ωp (where it is < e^−200000)."""
    x = np.where(omega > 0.05 * omega_p, omega / omega_p, 1.0)
    s = 0.3125 / omega_p * x ** -5 * np.exp(-1.25 * x ** -4)
    return np.where(omega > 0.05 * omega_p, s, 0.0)


def jonswap(omega, Hs: float, Tp: float, gamma: float = 3.3, sigma_a: float = SIGMA_A,
            sigma_b: float = SIGMA_B) -> np.ndarray:
    r"""JONSWAP spectrum S(ω) [m² s/rad], normalised so that :math:`4\sqrt{m_0} = H_s` exactly.

    Parameters
    ----------
    omega : array_like
        Angular frequencies [rad/s], ≥ 0.
    Hs : float
        Significant wave height H_m0 [m].
    Tp : float
        Peak period [s] (ω_p = 2π/Tp; S has its maximum at ω_p).
    gamma : float
        Peak enhancement factor γ (1 gives Pierson–Moskowitz).
    sigma_a, sigma_b : float
        Spectral widths below and above the peak.

    References
    ----------
    Hasselmann et al. (1973), *Dtsch. Hydrogr. Z.* A8(12); San Nicolás Méndez 2024 eq. 3.34, Ferreira González 2023 eq. 2.48,
    Sin Mon 2021 eq. 30–31; normalisation: module docstring.
    """
    w = np.asarray(omega, dtype=float)
    wp = 2.0 * math.pi / Tp
    S = Hs * Hs * _pm_shape(w, wp)
    if gamma != 1.0:
        sigma = np.where(w <= wp, sigma_a, sigma_b)
        r = np.exp(-((w - wp) ** 2) / (2.0 * (sigma * wp) ** 2))
        S = S * jonswap_normalisation(gamma, sigma_a, sigma_b) * gamma ** r
    return S


def pierson_moskowitz(omega, Hs: float, Tp: float) -> np.ndarray:
    r"""Pierson–Moskowitz spectrum :math:`\frac{5}{16}H_s^2\omega_p^4\omega^{-5}e^{-\frac54(\omega_p/\omega)^4}`
    [m² s/rad] (Pierson & Moskowitz 1964; Sin Mon 2021 eq. 30) — JONSWAP with γ = 1."""
    return jonswap(omega, Hs, Tp, 1.0)


def tma(omega, Hs: float, Tp: float, gamma: float = 3.3, sigma_a: float = SIGMA_A,
        sigma_b: float = SIGMA_B, h: float = math.inf, g: float = 9.81) -> np.ndarray:
    r"""TMA spectrum :math:`S_J(\omega; H_s, T_p, \gamma)\,\phi(\omega, h)` [m² s/rad].

    Bouws, Günther, Rosenthal & Vincent (1985), *J. Geophys. Res.* 90(C1), 975–986; DNV-RP-C205
    §3.5.5.5. ``Hs`` is the deep-water JONSWAP height; the finite-depth spectrum has less energy
    (φ ≤ 1). Tends to JONSWAP as kh → ∞ (``h = inf`` returns it exactly).
    """
    return jonswap(omega, Hs, Tp, gamma, sigma_a, sigma_b) * tma_depth_factor(omega, h, g)


def gaussian_swell(omega, Hs: float, Tp: float, sigma: float) -> np.ndarray:
    r"""Gaussian swell spectrum [m² s/rad]: a narrow peak of width σ [rad/s] at ω_p = 2π/Tp,

    .. math:: S(\omega) = \frac{H_s^2}{16}\,\frac{1}{\Phi(\omega_p/\sigma)\,\sigma\sqrt{2\pi}}
              \exp\left[-\frac{(\omega - \omega_p)^2}{2\sigma^2}\right], \qquad \omega \ge 0,

    normalised on ω ≥ 0 (Φ the standard normal distribution) so that :math:`4\sqrt{m_0} = H_s` exactly.
    The swell of a two-system sea (with a JONSWAP or Pierson–Moskowitz wind sea); the form of AQWA's
    ``GAUS`` record (σ in rad/s) and of Bunney et al. (2014), *Proc. 3rd IAHR Europe Congress*.
    """
    w = np.asarray(omega, dtype=float)
    wp = 2.0 * math.pi / Tp
    scale = Hs * Hs / 16.0 / (special.ndtr(wp / sigma) * sigma * math.sqrt(2.0 * math.pi))
    return np.where(w >= 0, scale * np.exp(-0.5 * ((w - wp) / sigma) ** 2), 0.0)


def gaussian_band(Tp: float, sigma: float, tail: float = 0.002) -> tuple[float, float]:
    """[ω_lo, ω_hi] of :func:`gaussian_swell` leaving ``tail``/2 of m0 out at each end (ω_lo ≥ 0)."""
    wp = 2.0 * math.pi / Tp
    z = float(special.ndtri(1.0 - 0.5 * tail))
    return max(wp - z * sigma, 1e-3 * wp), wp + z * sigma


def gaussian_bin_variance(edges, Hs: float, Tp: float, sigma: float) -> np.ndarray:
    r"""Variance of each frequency bin of :func:`gaussian_swell`, exactly:
    :math:`\frac{H_s^2}{16}\,[\Phi(u_{j+1}) - \Phi(u_j)]/\Phi(\omega_p/\sigma)`, :math:`u = (\omega - \omega_p)/\sigma`."""
    e = np.maximum(np.asarray(edges, dtype=float), 0.0)
    wp = 2.0 * math.pi / Tp
    cdf = special.ndtr((e - wp) / sigma)
    return Hs * Hs / 16.0 * np.diff(cdf) / special.ndtr(wp / sigma)


def spectrum_band(Tp: float, gamma: float = 3.3, tail: float = 0.002) -> tuple[float, float]:
    r"""Frequency band [ω_lo, ω_hi] of a JONSWAP spectrum leaving a fraction ``tail``/2 of m0 out at each end.

    In the tails the peak enhancement is negligible (γ^r − 1 < 1e-4 there for σ ≤ 0.09), and the
    JONSWAP variance outside :math:`x = \omega/\omega_p` is :math:`C e^{-\frac54 x^{-4}}` below and
    :math:`C(1 - e^{-\frac54 x^{-4}})` above (the PM integral of the module docstring), so

    .. math::
        x_{lo} = \left[\frac{-5/4}{\ln(\epsilon / 2C)}\right]^{1/4}, \qquad
        x_{hi} = \left[\frac{-5/4}{\ln(1 - \epsilon / 2C)}\right]^{1/4}.

    For γ = 3.3 and ε = 0.002: [0.66, 5.35] ω_p (the realised Hs is then √(1 − ε) ≈ 0.999 of the target).
    """
    C = jonswap_normalisation(gamma)
    half = min(0.5 * tail / C, 0.45)
    x_lo = (-1.25 / math.log(half)) ** 0.25
    x_hi = (-1.25 / math.log1p(-half)) ** 0.25
    wp = 2.0 * math.pi / Tp
    return x_lo * wp, x_hi * wp


def bin_variance(edges, Hs: float, Tp: float, gamma: float = 3.3, sigma_a: float = SIGMA_A,
                 sigma_b: float = SIGMA_B, h_tma: float = math.inf, g: float = 9.81) -> np.ndarray:
    r"""Variance :math:`\int_{\omega_j}^{\omega_{j+1}} S\,d\omega` [m²] of each frequency bin.

    ``edges`` (N+1,) increasing [rad/s]; S is JONSWAP (TMA when ``h_tma`` is finite). Each bin is cut
    into equal pieces no wider than σ_a ω_p / 2 (the narrowest feature of S), and at ω_p (where
    σ switches and S'' jumps); each piece is integrated by 8-point Gauss–Legendre: relative error
    ~1e-14 of m0.
    """
    e = np.asarray(edges, dtype=float)
    wp = 2.0 * math.pi / Tp
    width = np.diff(e)
    q = np.maximum(1, np.ceil(width / (0.5 * min(sigma_a, sigma_b) * wp))).astype(np.int64)
    starts = np.concatenate([[0], np.cumsum(q)[:-1]])
    j = np.repeat(np.arange(width.size), q)
    local = np.arange(int(q.sum())) - starts[j]
    fine = np.append(e[j] + width[j] * (local / q[j]), e[-1])
    if e[0] < wp < e[-1]:
        pos = int(np.searchsorted(fine, wp))
        if fine[pos] != wp:
            fine = np.insert(fine, pos, wp)
            starts = starts + (starts >= pos)
    x, w = np.polynomial.legendre.leggauss(8)
    lo, hi = fine[:-1, None], fine[1:, None]
    S = tma(0.5 * (hi - lo) * x + 0.5 * (hi + lo), Hs, Tp, gamma, sigma_a, sigma_b, h_tma, g)
    pieces = 0.5 * (fine[1:] - fine[:-1]) * (S @ w)
    return np.add.reduceat(pieces, starts)


def spreading_constant(s: float) -> float:
    r"""Normalisation :math:`\Gamma(s+1) / (2\sqrt\pi\,\Gamma(s+\frac12))` of the cos-2s spreading."""
    return math.exp(math.lgamma(s + 1.0) - math.lgamma(s + 0.5)) / (2.0 * math.sqrt(math.pi))


def spreading_cos2s(theta, theta_mean: float, s: float) -> np.ndarray:
    r"""Directional spreading D(θ) [1/rad] of the cos-2s model; ∫ D dθ over one turn = 1.

    Parameters
    ----------
    theta : array_like
        Directions [rad] (any turn: the difference to ``theta_mean`` is wrapped to [−π, π]).
    theta_mean : float
        Mean direction θ̄ [rad].
    s : float
        Spreading exponent s > 0 (larger = narrower; ISO 19901-1 suggests s ≈ 10 for wind sea).
    """
    u = np.angle(np.exp(1j * (np.asarray(theta, dtype=float) - theta_mean)))
    return spreading_constant(s) * np.cos(0.5 * u) ** (2.0 * s)


def spreading_quantile(p, s: float) -> np.ndarray:
    r"""Inverse CDF of the cos-2s spreading: the deviation u = θ − θ̄ [rad] with F(u) = p.

    .. math:: u(p) = \mathrm{sign}(2p - 1)\; 2\arcsin\sqrt{I^{-1}_{|2p-1|}(\tfrac12, s + \tfrac12)}

    (module docstring). ``p`` in [0, 1]; u in [−π, π].
    """
    q = 2.0 * np.asarray(p, dtype=float) - 1.0
    v = special.betaincinv(0.5, s + 0.5, np.abs(q))
    return np.sign(q) * 2.0 * np.arcsin(np.sqrt(v))
