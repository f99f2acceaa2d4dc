r"""Linear dispersion relation and the finite-depth factor of the TMA spectrum.

Dispersion of linear (Airy) waves in water of depth h (Ferreira González 2023 eq. 2.29; Dean & Dalrymple 1991 §3):

.. math:: \omega^2 = g\,k \tanh(k h), \qquad \omega^2 = g k \ \ (h = \infty).

Solved for k by Newton's method on :math:`f(x) = x \tanh x - \omega_h^2` in the non-dimensional
:math:`x = kh`, :math:`\omega_h^2 = \omega^2 h / g`, started from the explicit approximation of
Fenton & McKee (1990, *Coastal Eng.* 14, 1990, eq. 2),

.. math:: x_0 = \omega_h^2 \left[\tanh\left(\omega_h^{3/2}\right)\right]^{-2/3},

which is within 1.7 % everywhere; f is convex and increasing for x > 0, so every Newton iterate after
the first lies above the root and the iteration converges monotonically (4–5 steps to machine
precision). Deep water
(h = inf) is the exact limit k = ω²/g, not a large depth.
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = ["wavenumber", "wavenumber_scalar", "tma_depth_factor", "group_velocity_ratio"]


@numba.njit(cache=True)
def wavenumber_scalar(omega: float, h: float, g: float) -> float:
    """Wave number k [rad/m] of one frequency ω [rad/s] in depth h [m] (``inf``: deep water)."""
    if omega <= 0.0:
        return 0.0
    k_deep = omega * omega / g
    if not math.isfinite(h):
        return k_deep
    wh2 = k_deep * h  # ω² h / g
    if wh2 > 40.0:  # tanh(kh) = 1 to machine precision (kh > 20)
        return k_deep
    x = wh2 / math.tanh(wh2 ** 0.75) ** (2.0 / 3.0)
    for _ in range(50):
        th = math.tanh(x)
        step = (x * th - wh2) / (th + x * (1.0 - th * th))
        x -= step
        if abs(step) <= 4e-16 * x:
            break
    return x / h


@numba.njit(cache=True)
def _wavenumber_many(omega, h, g, out):
    for i in range(omega.size):
        out[i] = wavenumber_scalar(omega[i], h, g)


def wavenumber(omega, h: float = math.inf, g: float = 9.81) -> np.ndarray:
    r"""Wave number k(ω) from :math:`\omega^2 = g k \tanh(kh)` (vectorised, any shape).

    Parameters
    ----------
    omega : array_like
        Angular frequencies [rad/s], ≥ 0 (k = 0 at ω = 0).
    h : float
        Water depth [m]; ``inf`` for deep water (k = ω²/g exactly).
    g : float
        Gravity [m/s²].

    Returns
    -------
    ndarray
        k [rad/m], same shape as ``omega``; relative residual of the dispersion relation < 1e-14.
    """
    w = np.asarray(omega, dtype=float)
    out = np.empty(w.size)
    _wavenumber_many(np.ascontiguousarray(w.reshape(-1)), float(h), float(g), out)
    return out.reshape(w.shape)


def group_velocity_ratio(kh) -> np.ndarray:
    r"""n = c_g / c = ½ (1 + 2kh / sinh 2kh) (½ in deep water, 1 in shallow water)."""
    x = 2.0 * np.asarray(kh, dtype=float)
    with np.errstate(over="ignore", invalid="ignore"):
        G = np.where(x > 700.0, 0.0, x / np.sinh(np.where(x == 0.0, 1.0, x)))
    G = np.where(x == 0.0, 1.0, G)
    return 0.5 * (1.0 + G)


def tma_depth_factor(omega, h: float, g: float = 9.81) -> np.ndarray:
    r"""Kitaigorodskii depth factor φ(ω, h) of the TMA spectrum.

    .. math::
        \phi(\omega, h) = \frac{k(\omega, h)^{-3}\, \partial k / \partial \omega}
                               {k(\omega, \infty)^{-3}\, \partial k_\infty / \partial \omega}
                        = \frac{\tanh^2(kh)}{1 + 2kh / \sinh(2kh)}

    (Kitaigorodskii, Krasitskii & Zaslavskii 1975, *J. Phys. Oceanogr.* 5; Bouws, Günther, Rosenthal &
    Vincent 1985, *J. Geophys. Res.* 90(C1), eq. 5). It maps the ω⁻⁵ saturation range of deep water to
    finite depth: φ → 1 for kh → ∞, φ → ½ ω²h/g for kh → 0.

    (The appendix script of Grøtting 2015 uses cosh²(kh)/(cosh²(kh) + ω²h/g), which tends to 1 rather
    than 0 in shallow water; boatland uses the published form above.)

    Parameters
    ----------
    omega : array_like
        Angular frequencies [rad/s].
    h : float
        Water depth [m]; ``inf`` gives φ = 1.
    g : float
        Gravity [m/s²].
    """
    w = np.asarray(omega, dtype=float)
    if not math.isfinite(h):
        return np.ones_like(w)
    kh = wavenumber(w, h, g) * h
    return np.tanh(kh) ** 2 / (2.0 * group_velocity_ratio(kh))
