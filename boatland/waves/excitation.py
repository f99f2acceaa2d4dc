r"""First-order wave excitation force series F_exc(t) on the integrator's time grid.

Linear superposition through the excitation transfer function X(ω, β) of the hydrodynamic database
(per unit amplitude, exp(+iωt), referred to the incident elevation at the vessel's reference point;
:mod:`boatland.conventions`), in the body frame of a vessel whose reference point is at (x_0, y_0)
with heading ψ (global frame):

.. math::
    F_j(t) = r(t) \sum_i a_i\, \mathrm{Re}\left\{X_j(\omega_i, \theta_i - \psi)\,
             e^{i(\omega_i t - k_i (x_0\cos\theta_i + y_0\sin\theta_i) + \varphi_i)}\right\},

the same phase convention as :math:`\eta = \sum a_i\cos(\omega_i t - k_i\cdot x + \varphi_i)`
(:mod:`boatland.waves.synthesis`): a component's force leads its crest at the reference point by
arg X. The position phase :math:`k_i(x_0\cos\theta_i + y_0\sin\theta_i)` is exact (it is not
interpolated).

Interpolation of X (once per component, not per time step)
    Linear in ω and linear in β, on the **real and imaginary parts**. Real/imaginary interpolation
    is exact for a transfer function that is linear between BEM frequencies, passes correctly
    through the zeros of |X| (cancellation frequencies, where the phase jumps by π and
    magnitude/phase interpolation would invent a spurious peak) and needs no phase unwrapping. Its
    cost is a small magnitude loss where the phase turns fast between samples: |X|(Δarg X)²/8 at
    mid-interval (0.3 % for 0.15 rad per step). Steps in ω and β should keep Δarg X small — the
    database's job: for short waves on a long hull X(β) oscillates with k(L/2)Δcos β, so a 15°
    direction grid is coarse above ω ≈ 1.5 rad/s for a 24 m vessel.
Directions
    The table is used periodically in β (360° wrap) only when its directions go round the circle
    (:func:`periodic_directions`: the wrap-around gap 360° − (β_last − β_first) is no larger than the
    largest step). Otherwise it is known on [β_first, β_last] only — a single direction only at
    itself — and a component outside gets **NaN**, never a value interpolated across the part of
    the circle the table does not cover. A half-circle table of a port–starboard symmetric hull
    is completed to the circle before it gets here
    (:func:`boatland.vessel.directions.full_circle_excitation`), and the sea (:mod:`boatland.sea.states`) refuses
    directions outside any other table with a message first
    (:func:`boatland.vessel.directions.direction_problem`).
Outside the frequency band
    Above ω_max of the table the excitation is **zero** (and counted: ``n_above``; :mod:`boatland.sea.states`
    warns with the variance share). Below the first tabulated frequency X is held at its value
    there (counted: ``n_below``); :func:`boatland.sea.states.excitation_table` prepends the exact long-wave limit
    X(0, β) = ``C[:, 2]`` (the heave column of the restoring matrix: a wave much longer than the
    vessel is a slow rise of the water level, in phase with the crest), so that with a database the
    low end is interpolated between ω = 0 and ω_min instead.
Start-up ramp
    :math:`r(t) = \tfrac12\left(1 - \cos(\pi t/T_{ramp})\right)` for 0 ≤ t < T_ramp, 1 after
    (continuous value and slope; T_ramp = 0: no ramp).
Time grid
    :math:`t_n = t_0 + n\,h`; for RK4 with step Δt use h = Δt/2 and 2N+1 points, so the stage
    times t, t + Δt/2, t + Δt are all samples. Summed by :func:`boatland.waves.synthesis.harmonic_series`:
    the direct sum for short series, a non-uniform FFT for long ones (cost linear-logarithmic in the
    duration; equal to the direct sum to ~1e-13 of the amplitudes), serial either way.
"""

from __future__ import annotations

import math

import numpy as np

from boatland.waves.synthesis import component_phasors, harmonic_series

__all__ = ["DIRECTION_ATOL_DEG", "PERIODIC_STEP_RTOL", "direction_brackets", "interpolate_excitation",
           "excitation_coefficients",
           "excitation_series", "periodic_directions", "ramp"]

#: Two directions closer than this [deg] are the same direction (a component "at" a tabulated one).
DIRECTION_ATOL_DEG = 1e-9
#: A table of directions goes round the circle when its wrap-around gap exceeds its largest step by no
#: more than this fraction of the step (directions printed with two decimals, or stored in float32).
PERIODIC_STEP_RTOL = 1e-3


def periodic_directions(beta_deg) -> bool:
    r"""Whether a table of directions covers the circle periodically.

    True when the wrap-around gap is no larger than the largest step between tabulated directions,

    .. math:: 360° - (\beta_{N-1} - \beta_0) \le (1 + \epsilon)\max_k (\beta_{k+1} - \beta_k)

    with ε = :data:`PERIODIC_STEP_RTOL`,
    so that interpolating across the wrap (from β_last to β_first + 360°) is no coarser than inside
    the table. One direction is never periodic.

    Parameters
    ----------
    beta_deg : array_like, shape (Nb,)
        Tabulated directions [deg], strictly increasing.
    """
    b = np.asarray(beta_deg, dtype=float).reshape(-1)
    if b.size < 2:
        return False
    return bool(360.0 - (b[-1] - b[0]) <= (1.0 + PERIODIC_STEP_RTOL) * float(np.max(np.diff(b))))


def direction_brackets(beta_c_deg, beta_deg, periodic: bool | None = None):
    r"""Where directions fall in a table of directions: the columns ``j``, ``j1`` and the weight ``wb`` of
    :func:`interpolate_excitation`'s linear interpolation in β, :math:`(1 - w_b) X_j + w_b X_{j_1}`.

    Parameters
    ----------
    beta_c_deg : ndarray, shape (N,)
        Directions [deg] (any turn).
    beta_deg : ndarray, shape (Nb,)
        Table directions [deg], increasing within one turn.
    periodic : bool, optional
        As :func:`interpolate_excitation`.

    Returns
    -------
    j, j1 : ndarray of int, shape (N,)
        The two columns each direction reads (j1 = j when the table has one direction).
    wb : ndarray, shape (N,)
        Weight of column j1.
    outside : ndarray of bool, shape (N,)
        Directions a non-periodic table does not cover.
    """
    bc = np.asarray(beta_c_deg, dtype=float)
    beta = np.asarray(beta_deg, dtype=float)
    nb = beta.size
    if periodic is None:
        periodic = periodic_directions(beta)
    outside = np.zeros(bc.size, dtype=bool)
    if nb == 1:
        j = j1 = np.zeros(bc.size, dtype=int)
        wb = np.zeros(bc.size)
        if not periodic:
            outside = np.abs(np.mod(bc - beta[0] + 180.0, 360.0) - 180.0) > DIRECTION_ATOL_DEG
    elif periodic:
        # periodic bracket [ext[j], ext[j+1]] with ext = beta ∪ {beta[0] + 360}
        ext = np.append(beta, beta[0] + 360.0)
        b = beta[0] + np.mod(bc - beta[0], 360.0)
        j = np.clip(np.searchsorted(ext, b, side="right") - 1, 0, nb - 1)
        wb = np.clip((b - ext[j]) / (ext[j + 1] - ext[j]), 0.0, 1.0)
        j1 = (j + 1) % nb
    else:
        # the turn that starts just below beta[0]; known on [beta[0], beta[-1]] only
        b = beta[0] - DIRECTION_ATOL_DEG + np.mod(bc - beta[0] + DIRECTION_ATOL_DEG, 360.0)
        outside = b > beta[-1] + DIRECTION_ATOL_DEG
        j = np.clip(np.searchsorted(beta, b, side="right") - 1, 0, nb - 2)
        wb = np.clip((b - beta[j]) / (beta[j + 1] - beta[j]), 0.0, 1.0)
        j1 = j + 1
    return j, j1, wb, outside


def interpolate_excitation(omega_c, beta_c_deg, omega, beta_deg, X, periodic: bool | None = None):
    r"""X(ω_c, β_c) for each component: bilinear in (ω, β) on real and imaginary parts.

    Parameters
    ----------
    omega_c : ndarray, shape (N,)
        Component frequencies [rad/s].
    beta_c_deg : ndarray, shape (N,)
        Relative directions θ_i − ψ [deg] (any turn).
    omega : ndarray, shape (Nf,)
        Table frequencies [rad/s], increasing (may start at 0).
    beta_deg : ndarray, shape (Nb,)
        Table directions [deg], increasing within one turn.
    X : ndarray of complex, shape (m, Nb, Nf)
        Transfer function (m outputs, usually the 6 DOF).
    periodic : bool, optional
        Use the table periodically in β (360° wrap). Default: :func:`periodic_directions` of
        ``beta_deg``. When False the table covers [β_0, β_last] only (a single direction: itself, within
        :data:`DIRECTION_ATOL_DEG`) and components outside get NaN in every output. ``True`` with a
        single direction uses it for every β.

    Returns
    -------
    Xc : ndarray of complex, shape (m, N)
        NaN for components outside a non-periodic table's directions.
    n_below, n_above : int
        Components below ``omega[0]`` (X held) and above ``omega[-1]`` (X = 0).
    """
    wc = np.asarray(omega_c, dtype=float)
    om = np.asarray(omega, dtype=float)
    beta = np.asarray(beta_deg, dtype=float)
    bc = np.asarray(beta_c_deg, dtype=float)
    X = np.asarray(X, dtype=complex)
    nf = om.size
    if periodic is None:
        periodic = periodic_directions(beta)
    # ω: index i and weight f on [omega[i], omega[i+1]]
    if nf == 1:
        i = np.zeros(wc.size, dtype=int)
        f = np.zeros(wc.size)
    else:
        i = np.clip(np.searchsorted(om, wc, side="right") - 1, 0, nf - 2)
        f = np.clip((wc - om[i]) / (om[i + 1] - om[i]), 0.0, 1.0)
    below = wc < om[0]
    above = wc > om[-1]
    j, j1, wb, outside = direction_brackets(bc, beta, periodic)
    i1 = np.minimum(i + 1, nf - 1)
    lo = (1.0 - f) * X[:, j, i] + f * X[:, j, i1]
    hi = (1.0 - f) * X[:, j1, i] + f * X[:, j1, i1]
    Xc = (1.0 - wb) * lo + wb * hi
    Xc[:, above] = 0.0
    Xc[:, outside] = np.nan
    return Xc, int(np.count_nonzero(below)), int(np.count_nonzero(above))


def excitation_coefficients(components, omega, beta_deg, X, x0: float = 0.0, y0: float = 0.0,
                            psi: float = 0.0, X_extra=None):
    r"""Complex force amplitudes of each component.

    .. math:: c_{ji} = a_i \left(X_j(\omega_i, \theta_i - \psi) + X^{extra}_{ji}\right)
              e^{i(\varphi_i - k_i(x_0\cos\theta_i + y_0\sin\theta_i))}


    Returns ``(c (m, N) complex, n_below, n_above)``; arguments as :func:`excitation_series`.
    """
    cp = components
    Xc, n_below, n_above = interpolate_excitation(cp.omega, np.degrees(cp.theta - psi), omega, beta_deg, X)
    ph = component_phasors(cp, x0, y0)
    c = Xc * ph
    if X_extra is not None:
        c = c + np.where((cp.omega > omega[-1])[None, :], 0.0, X_extra) * ph
    return c, n_below, n_above


def ramp(t, T_ramp: float) -> np.ndarray:
    r"""Start-up ramp r(t) = ½(1 − cos(π t / T_ramp)) on [0, T_ramp), 0 before, 1 after.

    ``T_ramp = 0`` means no ramp (1 everywhere).
    """
    t = np.asarray(t, dtype=float)
    if T_ramp <= 0:
        return np.ones_like(t)
    x = np.clip(t / T_ramp, 0.0, 1.0)
    return 0.5 * (1.0 - np.cos(math.pi * x))


def excitation_series(components, omega, beta_deg, X, x0: float, y0: float, psi: float, t0: float,
                      h: float, n: int, T_ramp: float = 0.0, X_extra=None):
    r"""Excitation force series F (n, m) on t_n = t0 + n h, body frame (module docstring).

    Parameters
    ----------
    components : Components
        Wave components (:mod:`boatland.waves.realisation`), phases at the global origin.
    omega : ndarray, shape (Nf,)
        Frequencies of the X table [rad/s] (increasing; may start at 0).
    beta_deg : ndarray, shape (Nb,)
        Directions of the X table [deg], increasing within one turn (relative to the vessel).
    X : ndarray of complex, shape (m, Nb, Nf)
        Excitation per unit amplitude [N/m, N m/m], exp(+iωt), referred to the reference point.
    x0, y0 : float
        Reference point of the vessel in the global frame [m].
    psi : float
        Heading ψ of the vessel's x axis in the global frame [rad].
    t0, h : float
        First time and spacing of the grid [s] (h = Δt/2 for RK4 stages).
    n : int
        Number of times (2 N_steps + 1 for RK4).
    T_ramp : float
        Duration of the half-cosine start-up ramp [s], measured from t = 0; 0 for none.
    X_extra : ndarray of complex, shape (m, N), optional
        More excitation per unit amplitude at each component, referred like X (e.g. the monopile's
        scattered wave, :func:`boatland.sea.pile.pile_scattered_components`); added to
        the interpolated X before the sum (zero above the table's band, like X).

    Returns
    -------
    F : ndarray, shape (n, m)
        Forces [N] and moments [N m].
    n_below, n_above : int
        Components below / above the table's band (see :func:`interpolate_excitation`).
    """
    c, n_below, n_above = excitation_coefficients(components, omega, beta_deg, X, x0, y0, psi, X_extra)
    F = harmonic_series(components.omega, c, t0, h, n)
    if T_ramp > 0:
        F *= ramp(t0 + h * np.arange(n), T_ramp)[:, None]
    return F, n_below, n_above
