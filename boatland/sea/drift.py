r"""Second-order wave drift of a sea on the vessel: the mean, and the slowly varying part by Newman's
approximation, from the database's mean drift coefficients.

With :math:`D_j(\omega, \beta)` the mean drift force (or moment) j per unit wave amplitude squared
(:attr:`boatland.vessel.database.HydroDB.drift`) and the sea's components :math:`a_i, \omega_i, \theta_i,
\varphi_i` (phases at the vessel's reference point), ``sea.drift`` gives

- ``"mean"``: :math:`\bar F_j = \sum_i a_i^2 D_j(\omega_i, \theta_i - \psi)` — the time average of the
  difference-frequency force over a long record (Faltinsen 1990, *Sea Loads on Ships and Offshore
  Structures*, §5.4, eq. 5.40);
- ``"newman"``: :math:`F_j(t) = 2\,s_j(t)\,\sigma_j(t)`, :math:`s_j = \sum_i a_i\sqrt{|D_{ji}|}\cos\phi_i(t)`,
  :math:`\sigma_j = \sum_i a_i\,\mathrm{sgn}(D_{ji})\sqrt{|D_{ji}|}\cos\phi_i(t)` — Newman's (1974)
  approximation of the off-diagonal quadratic transfer function by the diagonal,
  :math:`T_{ik} \approx \tfrac12(T_{ii} + T_{kk})` in its usual signed form (Faltinsen 1990 eq. 5.43 for
  :math:`D \ge 0`; the product keeps the mean :math:`\sum a_i^2 D_i` exact where D changes sign). Its time
  average is the mean above, plus the slowly varying (difference-frequency) force and a sum-frequency part at
  twice the wave frequencies, which Newman's form also carries (a landed vessel on stiff contacts responds to
  both quasi-statically).

The force is taken at the vessel's mean position and heading (its motions do not change it), ramps in with
the square of the waves' ramp, and is zero for components above the database's band (short waves' drift —
reflection from the hull — is then missed: extend the database's band when the sea has energy there).
Interpolation in frequency and direction is that of the first-order excitation (with D = 0 at ω = 0: long
waves pass without reflection).
"""

from __future__ import annotations

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.vessel.directions import full_circle_drift
from boatland.waves.excitation import excitation_coefficients
from boatland.waves.realisation import Components
from boatland.waves.synthesis import harmonic_series

__all__ = ["DRIFT_MODES", "drift_at", "drift_series", "mean_drift"]

DRIFT_MODES = ("none", "mean", "newman")


def _table(db) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(omega, beta_deg, D) of the database's drift, completed to the circle as X is, with ω = 0 prepended."""
    table = full_circle_drift(db)
    if table is None:
        raise BoatlandInputError(f"the database {db.name!r} has no mean drift coefficients (sea.drift needs them): "
                                 "import a BEM output that has them (WAMIT .8/.9, AQWA, ...) or add them to a "
                                 "Capytaine-built database (boatland.hydro.drift)")
    beta, D = table
    Dc = np.asarray(D, dtype=complex)
    omega = np.asarray(db.omega, dtype=float)
    if omega[0] > 0:
        omega = np.concatenate([[0.0], omega])
        Dc = np.concatenate([np.zeros(Dc.shape[:2] + (1,), dtype=complex), Dc], axis=2)
    return omega, np.asarray(beta, dtype=float), Dc


def drift_at(db, components: Components, heading_deg: float) -> np.ndarray:
    """D_j(ω_i, θ_i − ψ) (6, N) at the sea's components (real; 0 above the band)."""
    omega, beta, D = _table(db)
    unit = components._replace(a=np.ones_like(components.a), phi=np.zeros_like(components.phi))
    c, _, _ = excitation_coefficients(unit, omega, beta, D, 0.0, 0.0, np.radians(heading_deg))
    return c.real


def mean_drift(db, components: Components, heading_deg: float) -> np.ndarray:
    r"""The mean drift :math:`\sum_i a_i^2 D(\omega_i, \theta_i - \psi)` (6,) [N, N m] of the components."""
    return drift_at(db, components, heading_deg) @ (components.a ** 2)


def drift_series(mode: str, db, components: Components, *, dt: float, n_steps: int, x0: float, y0: float,
                 heading_deg: float, ramp=None) -> np.ndarray:
    """The drift force (2 n_steps + 1, 6) at the half steps (module docstring); ``ramp`` (2 n_steps + 1,): the
    waves' ramp factor, applied squared."""
    m = 2 * n_steps + 1
    if mode == "none":
        return np.zeros((m, 6))
    if mode not in DRIFT_MODES:
        raise ValueError(f"drift mode {mode!r}: use one of {', '.join(DRIFT_MODES)}")
    D = drift_at(db, components, heading_deg)
    if mode == "mean":
        F = np.tile(D @ (components.a ** 2), (m, 1))
    else:
        # phasors of the components at the reference point: a_i e^{i(φ_i − k_i·x0)}
        k = components.k
        ph = components.a * np.exp(1j * (components.phi - k * (x0 * np.cos(components.theta)
                                                              + y0 * np.sin(components.theta))))
        root = np.sqrt(np.abs(D))
        s = harmonic_series(components.omega, root * ph[None, :], 0.0, dt / 2, m)
        sigma = harmonic_series(components.omega, np.sign(D) * root * ph[None, :], 0.0, dt / 2, m)
        F = 2.0 * s * sigma
    if ramp is not None:
        F *= (np.asarray(ramp, dtype=float) ** 2)[:, None]
    return F
