r"""A measured wave record (elevation at a gauge) as wave components, to replay a tank test.

Ferreira González (2023) §5.2.3 replays the tank's wave gauge through its FFT (20 dominant components there). The
record :math:`\eta_n = \eta(t_0 + n\Delta t)`, n = 0..M−1, is written exactly as its discrete Fourier
series (``numpy.fft.rfft``, :math:`C_m = \sum_n \eta_n e^{-2\pi i m n / M}`):

.. math::
    \eta_n = \frac{C_0}{M} + \sum_{m=1}^{\lfloor (M-1)/2 \rfloor} \frac{2|C_m|}{M}
             \cos\left(\omega_m n\Delta t + \arg C_m\right) \;[+\; \tfrac{C_{M/2}}{M}(-1)^n],
    \qquad \omega_m = \frac{2\pi m}{M\Delta t},

so the components are :math:`a_m = 2|C_m|/M` (:math:`|C_m|/M` for m = 0 and the Nyquist term),
:math:`\varphi_m = \arg C_m`, with simulation time t = 0 at the first sample. Kept all, they
reproduce the record at its sample times to rounding (~1e-13); kept the ``n_keep`` largest, they
are the best ``n_keep``-term approximation in the least-squares sense (Parseval). The replay is
periodic with the record length M Δt.

The gauge stands at (x_g, y_g) and the waves travel towards θ (long-crested): each component gets
:math:`k_m` from the dispersion relation and its phase is moved to the global origin,
:math:`\varphi_m \leftarrow \varphi_m + k_m (x_g\cos\theta + y_g\sin\theta)`, so that
η(x_g, y_g, t) is the record and η at the vessel follows from the same sum.

The CSV reader lives in :mod:`boatland.sea.records` (kernels do no I/O).
"""

from __future__ import annotations

import math

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.waves.dispersion import wavenumber
from boatland.waves.realisation import Components

__all__ = ["check_uniform_time", "record_components"]


def check_uniform_time(t, rtol: float = 0.01, source: str = "wave record", lines=None) -> float:
    """Check that ``t`` is increasing with a uniform step; return the mean step Δt [s].

    Every step must be within ``rtol`` of the median step (a step above 1.5 median steps is reported
    as a gap). Errors name the sample's line (``lines[i]``, or the sample index) and the valid range.
    The returned Δt = (t_last − t_first)/(M − 1) is the least-sensitive estimate for rounded times.
    """
    t = np.asarray(t, dtype=float)
    where = (lambda i: f"line {lines[i]}") if lines is not None else (lambda i: f"sample {i}")
    d = np.diff(t)
    bad = np.flatnonzero(d <= 0)
    if bad.size:
        i = int(bad[0]) + 1
        raise BoatlandInputError(f"{source}: {where(i)}: time {t[i]:g} s does not increase (previous "
                                 f"{t[i - 1]:g} s); times must be strictly increasing")
    dt = float(np.median(d))
    rel = d / dt - 1.0
    gap = np.flatnonzero(rel > 0.5)
    if gap.size:
        i = int(gap[0]) + 1
        missing = int(round(d[i - 1] / dt)) - 1
        raise BoatlandInputError(f"{source}: {where(i)}: gap of {d[i - 1]:g} s between t = {t[i - 1]:g} s and "
                                 f"{t[i]:g} s (about {max(missing, 1)} missing sample(s) at Δt = {dt:g} s); "
                                 "a record must be gap-free")
    off = np.flatnonzero(np.abs(rel) > rtol)
    if off.size:
        i = int(off[0]) + 1
        raise BoatlandInputError(f"{source}: {where(i)}: time step {d[i - 1]:g} s differs from the record's "
                                 f"Δt = {dt:g} s by {100 * abs(rel[i - 1]):.3g} %; the step must be uniform "
                                 f"within {100 * rtol:g} %")
    return float((t[-1] - t[0]) / (t.size - 1))


def record_components(eta, dt: float, x_g: float = 0.0, y_g: float = 0.0, theta: float = 0.0,
                      n_keep: int | None = None, remove_mean: bool = True, h: float = math.inf,
                      g: float = 9.81) -> Components:
    r"""Components of a uniformly sampled record (module docstring), referred to the global origin.

    Parameters
    ----------
    eta : ndarray, shape (M,)
        Elevation samples [m] at t = n Δt.
    dt : float
        Sample step Δt [s].
    x_g, y_g : float
        Gauge position in the global frame [m].
    theta : float
        Direction of travel of the recorded waves [rad], global frame.
    n_keep : int or None
        Keep the ``n_keep`` largest-amplitude components (all when None), in decreasing amplitude.
    remove_mean : bool
        Drop the mean (ω = 0 term; it is a water level, not a wave).
    h, g : float
        Water depth [m] and gravity [m/s²].
    """
    x = np.asarray(eta, dtype=float)
    M = x.size
    C = np.fft.rfft(x)
    a = 2.0 * np.abs(C) / M
    a[0] *= 0.5
    if M % 2 == 0:
        a[-1] *= 0.5
    phi = np.angle(C)
    omega = 2.0 * math.pi * np.arange(C.size) / (M * dt)
    keep = np.arange(1 if remove_mean else 0, C.size)
    order = keep[np.argsort(-a[keep], kind="stable")]
    if n_keep is not None:
        order = order[: int(n_keep)]
    omega, a, phi = omega[order], a[order], phi[order]
    k = wavenumber(omega, h, g)
    phi = phi + k * (x_g * math.cos(theta) + y_g * math.sin(theta))
    return Components(omega, k, a, np.full(omega.size, math.fmod(theta, 2 * math.pi) % (2 * math.pi)), phi)
