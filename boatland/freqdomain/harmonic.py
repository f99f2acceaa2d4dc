r"""Complex amplitude of a steady regular-wave response in a time series: the bridge from a time-domain
run to the frequency domain's RAOs (exp(+iωt), :mod:`boatland.conventions`)."""

from __future__ import annotations

import numpy as np

__all__ = ["first_harmonic"]


def first_harmonic(t, y, omega: float, periods: float = 10.0) -> complex:
    r"""Complex amplitude :math:`\hat c` of the first harmonic of ``y`` over its last ``periods`` periods.

    Least-squares fit of

    .. math:: y(t) \approx c_0 + c_1 t + \mathrm{Re}\{\hat c\, e^{i\omega t}\}

    The constant absorbs a static part (a preload), the trend a slow drift left by the start-up
    (e.g. surge, which has no restoring). Phase as in :mod:`boatland.conventions`: ``arg ĉ`` is the
    lead over :math:`\cos\omega t`.

    Parameters
    ----------
    t : array_like, shape (n,)
        Time [s].
    y : array_like, shape (n,)
        The signal.
    omega : float
        Its frequency [rad/s].
    periods : float
        Length of the fitted window at the end of the record, in periods of ``omega``.

    Returns
    -------
    complex
        :math:`\hat c` (same unit as ``y``).
    """
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    keep = t >= t[-1] - periods * 2.0 * np.pi / omega
    if np.count_nonzero(keep) < 4 or t[-1] - t[0] < periods * 2.0 * np.pi / omega * (1 - 1e-9):
        raise ValueError(f"the record ({t[-1] - t[0]:.4g} s) is shorter than {periods:g} periods of "
                         f"ω = {omega:.4g} rad/s")
    tt = t[keep]
    G = np.column_stack([np.ones_like(tt), tt, np.cos(omega * tt), np.sin(omega * tt)])
    c, *_ = np.linalg.lstsq(G, y[keep], rcond=None)
    return complex(c[2], -c[3])  # Re{(c2 − i c3) e^{iωt}} = c2 cos ωt + c3 sin ωt
