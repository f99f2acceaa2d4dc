r"""State-space approximation of the radiation memory: O(1) cost per time step instead of a convolution.

For each significant DOF pair (i, j) a continuous-time SISO system

.. math::
    \dot z = A_r z + B_r \dot x_j, \qquad \mu_{ij} = C_r z \;\approx\; \int_0^t K_{ij}(t-\tau)\dot x_j(\tau)\,d\tau,

whose impulse response :math:`C_r e^{A_r t} B_r` matches :math:`K_{ij}(t)`.

Method (time-domain identification, as in Taghipour, Perez & Moan 2008, *Marine Structures* 21,
"Hybrid frequency–time domain models for dynamic response analysis of marine structures", §3):

1. poles by the matrix-pencil method (Hua & Sarkar 1990, IEEE Trans. ASSP 38(5)) on the sampled K(t);
2. stability enforced: a pole with Re p ≥ 0 is reflected to −|Re p| (every pole in the open left
   half-plane);
3. residues by linear least squares with the poles fixed (the best fit those stable poles allow),
   constrained to :math:`\hat K(s=0) = \int_0^\infty \hat K\,dt = 0`, i.e. zero damping at ω = 0
   — the structural zero at s = 0 of the radiation transfer function (Perez & Fossen 2008,
   *Modeling, Identification and Control* 29(1), §3) that keeps the fit passive at low frequency;
4. the order rises from 2 until the fit reaches the target R² and, for a diagonal pair, is passive
   (or the maximum order is reached);
5. passivity checked: the fitted damping :math:`\hat B(\omega) = \mathrm{Re}\,\hat K(i\omega)` must be
   ≥ 0 over the band (diagonal pairs) within a tolerance; violations are reported, not hidden.

Real modal realisation: a real pole p gives the block ``A=[p], B=[1], C=[r]``; a complex pair
σ ± iω with residue a ± ib gives ``A=[[σ, ω], [−ω, σ]], B=[1, 0]ᵀ, C=[2a, 2b]``, whose impulse
response is :math:`2e^{σt}(a\cos ωt − b\sin ωt)`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from boatland.irf.impulse import IRF, pair_name

__all__ = ["PairFit", "StateSpace", "fit_pair", "fit_state_space", "impulse_response", "frequency_response"]


@dataclass(frozen=True, eq=False)
class PairFit:
    """A fitted SISO system for one DOF pair: ``A`` (n, n), ``B`` (n,), ``C`` (n,), R² of the fit."""

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    r2: float

    @property
    def order(self) -> int:
        return int(self.A.shape[0])

    @property
    def stable(self) -> bool:
        return bool(self.order == 0 or np.max(np.linalg.eigvals(self.A).real) < 0)


@dataclass(frozen=True, eq=False)
class StateSpace:
    """State-space radiation model of a vessel: one :class:`PairFit` per significant pair.

    Attributes
    ----------
    pairs : dict[(int, int), PairFit]
    target_r2 : float
    max_order : int
    passivity : ndarray (6, 6)
        min over the band of the fitted damping divided by max|B_ij| (diagonal pairs; NaN elsewhere):
        ≥ −tolerance means passive.
    notes : tuple of str
    """

    pairs: dict
    target_r2: float
    max_order: int
    passivity: np.ndarray
    notes: tuple[str, ...] = ()

    @property
    def orders(self) -> np.ndarray:
        o = np.zeros((6, 6), dtype=int)
        for (i, j), f in self.pairs.items():
            o[i, j] = f.order
        return o

    @property
    def r2(self) -> np.ndarray:
        r = np.full((6, 6), np.nan)
        for (i, j), f in self.pairs.items():
            r[i, j] = f.r2
        return r

    @property
    def n_states(self) -> int:
        return int(sum(f.order for f in self.pairs.values()))


def impulse_response(fit: PairFit, t: np.ndarray) -> np.ndarray:
    """:math:`C e^{A t} B` at times ``t`` (through the eigen-decomposition; A is block-diagonal)."""
    if fit.order == 0:
        return np.zeros_like(t)
    lam, V = np.linalg.eig(fit.A)
    w = np.linalg.solve(V, fit.B.astype(complex))
    c = fit.C @ V
    return np.real(np.exp(np.outer(t, lam)) @ (c * w))


def frequency_response(fit: PairFit, omega: np.ndarray) -> np.ndarray:
    """:math:`\\hat K(i\\omega) = C (i\\omega I - A)^{-1} B`; Re = fitted B(ω), Im/ω = A(ω) − A∞."""
    if fit.order == 0:
        return np.zeros(len(omega), complex)
    lam, V = np.linalg.eig(fit.A)
    w = np.linalg.solve(V, fit.B.astype(complex))
    c = fit.C @ V
    return (c * w) @ (1.0 / (1j * np.asarray(omega)[None, :] - lam[:, None]))


def _hankel_right_vectors(y: np.ndarray) -> np.ndarray:
    """Right singular vectors of the (N−L)×(L+1) Hankel matrix of ``y`` (L = N/3), computed once per pair."""
    L = y.size // 3
    H = np.lib.stride_tricks.sliding_window_view(y, L + 1)
    return np.linalg.svd(H, full_matrices=False)[2]


def _pencil_poles(Vh: np.ndarray, dt: float, n: int) -> np.ndarray:
    """Matrix-pencil poles of order n from the Hankel right singular vectors."""
    V = Vh[:n].T  # (L+1, n)
    z = np.linalg.eigvals(np.linalg.pinv(V[:-1]) @ V[1:])
    keep = ~((np.abs(z.imag) < 1e-12 * np.abs(z)) & (z.real <= 0)) & (np.abs(z) > 0)  # no Nyquist / zero poles
    z = z[keep]
    p = np.log(z.astype(complex)) / dt
    # one member per conjugate pair, real poles as they are
    real = p[np.abs(p.imag) < 1e-9 * np.maximum(np.abs(p), 1e-300)].real
    cplx = p[p.imag > 1e-9 * np.abs(p)]
    real = -np.abs(real)                               # stability: reflect into the left half-plane
    cplx = -np.abs(cplx.real) + 1j * cplx.imag
    return np.concatenate([real.astype(complex), cplx])


def _basis(t, poles):
    cols, kinds = [], []
    for p in poles:
        e = np.exp(p.real * t)
        if p.imag == 0:
            cols.append(e); kinds.append(("r", p))
        else:
            cols.append(e * np.cos(p.imag * t)); cols.append(-e * np.sin(p.imag * t)); kinds.append(("c", p))
    return np.column_stack(cols) if cols else np.zeros((t.size, 0)), kinds


def _dc_gain_row(poles):
    """Row g with g @ coef = ∫_0^∞ (basis @ coef) dt (the DC gain K̂(0))."""
    g = []
    for p in poles:
        if p.imag == 0:
            g.append(-1.0 / p.real)
        else:
            s, w = p.real, p.imag
            d = s * s + w * w
            g.extend([-s / d, -w / d])
    return np.array(g)


def _constrained_lstsq(Phi, y, g):
    """min ||Phi c − y|| subject to g·c = 0 (null-space of the constraint)."""
    # orthonormal basis of {c : g·c = 0}
    _, _, Vh = np.linalg.svd(g[None, :])
    N = Vh[1:].T
    z, *_ = np.linalg.lstsq(Phi @ N, y, rcond=None)
    return N @ z


def _realise(poles, coef):
    blocks_A, blocks_B, blocks_C = [], [], []
    k = 0
    for p in poles:
        if p.imag == 0:
            blocks_A.append(np.array([[p.real]])); blocks_B.append([1.0]); blocks_C.append([coef[k]]); k += 1
        else:
            s, w = p.real, p.imag
            a2, b2 = coef[k], coef[k + 1]  # 2a, 2b
            blocks_A.append(np.array([[s, w], [-w, s]])); blocks_B.append([1.0, 0.0]); blocks_C.append([a2, b2])
            k += 2
    n = sum(b.shape[0] for b in blocks_A)
    A = np.zeros((n, n))
    i = 0
    for b in blocks_A:
        m = b.shape[0]
        A[i:i + m, i:i + m] = b
        i += m
    return A, np.concatenate(blocks_B), np.concatenate(blocks_C)


def fit_pair(t: np.ndarray, K: np.ndarray, target_r2: float = 0.999, max_order: int = 12,
             max_samples: int = 400, omega: np.ndarray | None = None, B_ref: np.ndarray | None = None,
             passivity_tol: float = 0.01) -> PairFit:
    """Fit a stable state-space system to one sampled IRF ``K(t)`` (uniform ``t``).

    The order rises from 2 until R² = 1 − Σ(K − K̂)² / Σ(K − mean K)² reaches ``target_r2`` and — when
    ``omega`` and the damping ``B_ref`` on it are given (diagonal pairs) — the fitted damping stays
    ≥ −passivity_tol · max|B_ref| over ``omega``. Otherwise the best-R² fit up to ``max_order`` is
    returned (its R² and passivity tell).
    """
    t = np.asarray(t, dtype=float)
    K = np.asarray(K, dtype=float)
    if not np.any(K != 0):
        return PairFit(np.zeros((0, 0)), np.zeros(0), np.zeros(0), 1.0)
    step = max(1, t.size // max_samples)
    ts, Ks = t[::step], K[::step]
    dt = ts[1] - ts[0]
    ss_tot = np.sum((K - K.mean()) ** 2)
    Vh = _hankel_right_vectors(Ks)
    best = None
    for n in range(2, max_order + 1):
        poles = _pencil_poles(Vh, dt, n)
        if poles.size == 0:
            continue
        Phi, _ = _basis(t, poles)
        if Phi.shape[1] > max_order:
            continue
        if Phi.shape[1] < 2:
            continue
        coef = _constrained_lstsq(Phi, K, _dc_gain_row(poles))
        r2 = 1.0 - np.sum((Phi @ coef - K) ** 2) / ss_tot
        A, B, C = _realise(poles, coef)
        fit = PairFit(A, B, C, float(r2))
        if best is None or fit.r2 > best.r2 + 1e-12:
            best = fit
        passive = True
        if omega is not None and B_ref is not None:
            scale = np.max(np.abs(B_ref))
            passive = scale == 0 or np.min(frequency_response(fit, omega).real) >= -passivity_tol * scale
        if r2 >= target_r2 and passive:
            return fit
    return best


def fit_state_space(irf: IRF, omega_band: np.ndarray, B_band: np.ndarray, *, target_r2: float = 0.999,
                    max_order: int = 12, passivity_tol: float = 0.01) -> StateSpace:
    """Fit every significant DOF pair of ``irf``; check stability and passivity.

    Parameters
    ----------
    irf : IRF
    omega_band : ndarray (Nf,)
        Frequencies for the passivity check [rad/s] (the BEM band).
    B_band : ndarray (6, 6, Nf)
        Radiation damping on that band (scale for the passivity margin).
    target_r2, max_order : float, int
    passivity_tol : float
        Fitted diagonal damping may dip to −tol · max B_ii before it is reported as not passive.
    """
    pairs = {}
    notes = []
    passivity = np.full((6, 6), np.nan)
    for i in range(6):
        for j in range(6):
            if not irf.significant[i, j]:
                continue
            diag = i == j
            fit = fit_pair(irf.t, irf.K[i, j], target_r2, max_order, omega=omega_band if diag else None,
                           B_ref=B_band[i, i] if diag else None, passivity_tol=passivity_tol)
            pairs[(i, j)] = fit
            if fit.r2 < target_r2:
                notes.append(f"{pair_name(i, j)}: R² = {fit.r2:.6f} < {target_r2:g} at the maximum order {max_order}")
            if not fit.stable:  # cannot happen by construction; guard the invariant
                raise AssertionError(f"unstable fit for {pair_name(i, j)}")
            if i == j:
                b_fit = frequency_response(fit, omega_band).real
                scale = np.max(np.abs(B_band[i, i]))
                passivity[i, i] = float(np.min(b_fit) / scale) if scale > 0 else 0.0
                if passivity[i, i] < -passivity_tol:
                    k = int(np.argmin(b_fit))
                    notes.append(f"{pair_name(i, i)}: fitted damping not passive, min {b_fit[k]:.3g} at ω = "
                                 f"{omega_band[k]:.3g} rad/s ({100 * passivity[i, i]:.2g} % of max B)")
    return StateSpace(pairs=pairs, target_r2=target_r2, max_order=max_order, passivity=passivity,
                      notes=tuple(notes))
