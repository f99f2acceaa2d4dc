"""Filon-type transforms: exact for piecewise-linear f, analytic transform pairs."""

import numpy as np
import pytest
from scipy.integrate import quad

from boatland.irf.quadrature import cos_transform, sin_transform


def test_exact_for_piecewise_linear_at_any_frequency():
    x = np.array([0.0, 0.3, 1.1, 1.2, 2.5])
    f = np.array([0.0, 2.0, -1.0, 0.5, 0.0])
    for y in (0.0, 1e-3, 0.7, 13.0, 250.0):
        fc = lambda s: np.interp(s, x, f) * np.cos(s * y)  # noqa: E731
        fs = lambda s: np.interp(s, x, f) * np.sin(s * y)  # noqa: E731
        ec = sum(quad(fc, a, b, limit=400)[0] for a, b in zip(x[:-1], x[1:]))
        es = sum(quad(fs, a, b, limit=400)[0] for a, b in zip(x[:-1], x[1:]))
        assert abs(cos_transform(x, f, [y])[0] - ec) < 1e-12
        assert abs(sin_transform(x, f, [y])[0] - es) < 1e-12


@pytest.mark.slow
def test_exponential_kernel_gives_lorentzian_damping_and_added_mass():
    """K = e^{-at}: B(ω) = a/(a²+ω²), A(ω) − A∞ = −1/(a²+ω²)  (Cummins/Ogilvie pair, San Nicolás Méndez 2024 eq. 3.41)."""
    a = 0.8
    t = np.linspace(0, 40, 40001)  # e^{-32} truncation, h = 1e-3
    K = np.exp(-a * t)
    w = np.linspace(0.05, 6, 50)
    B = cos_transform(t, K, w)
    dA = -sin_transform(t, K, w) / w
    assert np.max(np.abs(B - a / (a ** 2 + w ** 2))) / (1 / a) < 1e-4
    assert np.max(np.abs(dA + 1 / (a ** 2 + w ** 2))) / (1 / a ** 2) < 1e-4
