r"""Radiation impulse-response functions K(t), infinite-frequency added mass, and their consistency.

Cummins (1962); San Nicolás Méndez 2024 §3.4 eq. 3.37–3.42:

.. math::
    K_{ij}(t) = \frac{2}{\pi}\int_0^\infty B_{ij}(\omega)\cos\omega t\,d\omega, \qquad
    B_{ij}(\omega) = \int_0^\infty K_{ij}(t)\cos\omega t\,dt, \qquad
    A_{ij}(\omega) = A_{ij}^\infty - \frac{1}{\omega}\int_0^\infty K_{ij}(t)\sin\omega t\,dt .

Numerics, all explicit in :class:`IRFSettings` and reported in :class:`IRF`:

- quadrature exact for B piecewise linear between the BEM samples (:mod:`boatland.irf.quadrature`),
  with B(0) = 0 below the first frequency;
- the frequency tail above the band: ``"none"`` (B stops at ω_max), ``"linear"`` (straight to zero
  over ``tail_width``), ``"asymptotic"`` (B_N (ω_N/ω)^n with n fitted to the top of the band,
  clamped to [2, 8], sampled to 3 ω_N), or ``"auto"`` (the default: linear when every significant
  diagonal damping has decayed below ``band_tol`` at the top of the band, else asymptotic — with a
  note naming the DOF and what to change);
- an optional cosine time taper over the last ``taper_fraction`` of [0, T_K];
- negative damping cleaned per DOF pair: ``"clip"`` (diagonal clipped at zero, off-diagonals
  limited to |B_ij| ≤ √(B_ii B_jj), the 2×2 passivity condition) or ``"cut"`` (the band ends below the
  first negative diagonal value above the damping peak), and every change logged;
- checks: π/Δt_K ≥ the highest frequency used; the damping has decayed at the top of the band;
  K has decayed by T_K; enough frequencies; damping not all zero.
- A∞ from the BEM solver when it has it, else Ogilvie's relation
  :math:`A^\infty = A(\omega) + \frac{1}{\omega}\int_0^{T_K} K\sin\omega t\,dt` averaged (median) over
  the upper half of the band, with its spread reported.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from boatland.conventions import DOF_NAMES
from boatland.errors import BoatlandInputError
from boatland.irf.quadrature import cos_transform, sin_transform

__all__ = ["IRFSettings", "IRF", "compute_irf", "find_spikes", "describe_spikes", "significant_pairs", "pair_name", "IRFError",
           "IRFNotDecayed"]

TAILS = ("auto", "none", "linear", "asymptotic")
CLEANS = ("clip", "cut", "none")
TAPERS = ("none", "cosine")


class IRFError(BoatlandInputError):
    """The IRF cannot be computed well from this input; the message says what to change."""


class IRFNotDecayed(IRFError):
    """K has not decayed by T_K: a longer memory is needed (the message says how long to try);
    ``pair`` names the DOF pair, ``t_max`` is the T_K it was computed over."""

    def __init__(self, message: str, pair: str, t_max: float):
        super().__init__(message)
        self.pair, self.t_max = pair, t_max

    def __reduce__(self):                      # picklable (raised in a worker process, re-raised here)
        return type(self), (str(self), self.pair, self.t_max)


def pair_name(i: int, j: int) -> str:
    return DOF_NAMES[i] if i == j else f"{DOF_NAMES[i]}-{DOF_NAMES[j]}"


@dataclass(frozen=True)
class IRFSettings:
    """Choices for :func:`compute_irf` (all reported with the result).

    Parameters
    ----------
    t_max : float
        Memory length T_K [s].
    dt : float
        Time step Δt_K of K(t) [s]; must satisfy π/Δt_K ≥ the highest frequency used.
    tail : {"auto", "linear", "none", "asymptotic"}
        How B(ω) continues above the band.
    tail_width : float or None
        Width of the linear tail [rad/s]; default 20 % of ω_max.
    taper : {"none", "cosine"}
        Time window on K(t).
    taper_fraction : float
        Fraction of [0, T_K] the cosine taper spans, at the end.
    clean : {"clip", "cut", "none"}
        Treatment of negative damping.
    band_tol : float
        Largest allowed B_ii(ω_max) / max B_ii for a damping that "has decayed" (tail "asymptotic"
        accepts any, with a note).
    decay_tol : float
        Largest allowed max|K_ii(t ≥ 0.9 T_K)| / max|K_ii|.
    significance : float
        Threshold of :func:`significant_pairs`.
    length_scale : float
        ℓ [m] making rotational entries commensurable in :func:`significant_pairs` (use ∇^⅓).
    check_band : tuple of float or None
        (ω_lo, ω_hi) for the round-trip errors; default the whole band.
    """

    t_max: float = 60.0
    dt: float = 0.05
    tail: str = "auto"
    tail_width: float | None = None
    taper: str = "none"
    taper_fraction: float = 0.2
    clean: str = "clip"
    band_tol: float = 0.05
    decay_tol: float = 0.05
    significance: float = 1e-3
    length_scale: float = 1.0
    check_band: tuple[float, float] | None = None

    def __post_init__(self):
        problems = []
        if not (np.isfinite(self.t_max) and self.t_max > 0):
            problems.append(f"t_max must be > 0 s, got {self.t_max}")
        if not (np.isfinite(self.dt) and 0 < self.dt < self.t_max):
            problems.append(f"dt must be in (0, t_max), got {self.dt}")
        if self.tail not in TAILS:
            problems.append(f"tail must be one of {', '.join(TAILS)}, got {self.tail!r}")
        if self.clean not in CLEANS:
            problems.append(f"clean must be one of {', '.join(CLEANS)}, got {self.clean!r}")
        if self.taper not in TAPERS:
            problems.append(f"taper must be one of {', '.join(TAPERS)}, got {self.taper!r}")
        if not 0 < self.taper_fraction < 1:
            problems.append(f"taper_fraction must be in (0, 1), got {self.taper_fraction}")
        if self.tail_width is not None and not self.tail_width > 0:
            problems.append(f"tail_width must be > 0 rad/s, got {self.tail_width}")
        if problems:
            raise IRFError("IRF settings: " + "; ".join(problems))


@dataclass(frozen=True, eq=False)
class IRF:
    """Radiation impulse-response functions of one vessel, with how they were made and how good they are.

    Attributes
    ----------
    t : ndarray (Nt,)
        Time [s], 0 … T_K step Δt_K.
    K : ndarray (6, 6, Nt)
        Kernel [N/m, N/rad, N·m/m, N·m/rad per s²·... i.e. force per unit velocity per second].
    A_inf : ndarray (6, 6)
        Infinite-frequency added mass used with K.
    A_inf_source : str
        ``"solver"`` or ``"ogilvie"``.
    ogilvie_spread : ndarray (6, 6)
        Spread (max − min)/max|A∞| of Ogilvie's A∞ over the upper half of the band, per pair (also
        computed when the solver's A∞ is used, as a consistency figure).
    err_B, err_A : ndarray (6, 6)
        Relative L2 errors of B and A reconstructed from K over the check band (NaN for pairs that
        are not significant).
    truncation : ndarray (6, 6)
        max|K(t ≥ 0.9 T_K)| / max|K| per pair.
    significant : ndarray of bool (6, 6)
    settings : IRFSettings
    omega_max_used : float
        Highest frequency in the transform (band top plus tail) [rad/s].
    notes : tuple of str
        What was cleaned, cut, extrapolated, or looks suspicious.
    """

    t: np.ndarray
    K: np.ndarray
    A_inf: np.ndarray
    A_inf_source: str
    ogilvie_spread: np.ndarray
    err_B: np.ndarray
    err_A: np.ndarray
    truncation: np.ndarray
    significant: np.ndarray
    settings: IRFSettings = field(default_factory=IRFSettings)
    omega_max_used: float = 0.0
    notes: tuple[str, ...] = ()
    check_band: tuple[float, float] = (0.0, 0.0)


def find_spikes(b: np.ndarray, factor: float = 5.0) -> np.ndarray:
    """Indices of isolated spikes in a sampled curve: a sample far from both neighbours (irregular
    frequencies of a BEM run without a lid), relative to the local variation."""
    b = np.asarray(b, dtype=float)
    if b.size < 5:
        return np.array([], dtype=int)
    mid = b[1:-1]
    jump = np.abs(mid - 0.5 * (b[:-2] + b[2:]))
    scale = np.abs(b[2:] - b[:-2]) + 1e-3 * np.max(np.abs(b))
    return np.nonzero(jump > factor * scale)[0] + 1


def describe_spikes(name: str, omega: np.ndarray, b: np.ndarray) -> str | None:
    """One line naming the sharp peaks of a damping curve (see :func:`find_spikes`), or None."""
    spikes = find_spikes(b)
    if not spikes.size:
        return None
    return (f"sharp peaks in B[{name}] at ω ≈ " + ", ".join(f"{omega[k]:.3g}" for k in spikes[:5])
            + " rad/s: irregular frequencies if the BEM run had no lid, or waves trapped between the "
              "demihulls of a catamaran (they make K ring)")


def significant_pairs(B: np.ndarray, significance: float = 1e-3, length_scale: float = 1.0) -> np.ndarray:
    """(6, 6) bool: DOF pairs whose damping matters.

    Entries are first made commensurable: a rotational index divides by ``length_scale`` ℓ (so every
    entry is in N·s/m). A diagonal pair is significant when its peak exceeds ``significance`` times
    the largest diagonal peak (a sphere's yaw damping is round-off); an off-diagonal pair when both
    its diagonals are significant and its peak exceeds ``significance`` · √(peak_ii peak_jj).
    """
    peak = np.max(np.abs(B), axis=-1)
    rot = np.array([0, 0, 0, 1, 1, 1])
    norm = peak / float(length_scale) ** (rot[:, None] + rot[None, :])
    diag = np.diag(norm)
    diag_sig = diag > significance * diag.max()
    scale = np.sqrt(np.outer(diag, diag))
    sig = (norm > significance * scale) & np.outer(diag_sig, diag_sig)
    sig[np.diag_indices(6)] = diag_sig
    return sig


def _clean(omega, B, how, notes, sig):
    """Remove negative damping (see module docstring); notes name significant pairs changed by more
    than 0.01 % of their peak (round-off-level changes are made silently)."""
    B = B.copy()
    if how == "none":
        return omega, B
    if how == "cut":
        cut = omega.size
        for i in range(6):
            b = B[i, i]
            if not np.any(b != 0):
                continue
            k0 = int(np.argmax(b))
            neg = np.nonzero(b[k0:] < 0)[0]
            if neg.size:
                cut = min(cut, k0 + int(neg[0]))
        if cut < omega.size:
            if cut < 10:
                raise IRFError(f"negative damping from ω = {omega[cut]:.3g} rad/s leaves fewer than 10 "
                               "frequencies below it: use clean='clip' or check the BEM run")
            notes.append(f"band cut at ω = {omega[cut - 1]:.4g} rad/s (negative diagonal damping above it); "
                         f"{omega.size - cut} frequencies dropped")
            return omega[:cut], B[:, :, :cut]
        return omega, B
    # clip
    diag = np.array([B[i, i] for i in range(6)])
    for i in range(6):
        neg = diag[i] < 0
        if np.any(neg) and sig[i, i]:
            notes.append(f"clipped negative damping B[{pair_name(i, i)}] to 0 at {neg.sum()} frequencies "
                         f"({omega[neg].min():.3g}–{omega[neg].max():.3g} rad/s, min {diag[i].min():.3g})")
        B[i, i] = np.maximum(diag[i], 0.0)
    for i in range(6):
        for j in range(6):
            if i == j:
                continue
            bound = np.sqrt(B[i, i] * B[j, j])
            over = np.abs(B[i, j]) > bound * (1 + 1e-9) + 1e-300
            peak = np.max(np.abs(B[i, j]))
            if np.any(over) and peak > 0:
                change = np.max(np.abs(B[i, j][over]) - bound[over]) / peak
                if change > 1e-4 and i < j and sig[i, j]:
                    notes.append(f"limited B[{pair_name(i, j)}] to √(B_ii B_jj) at {over.sum()} frequencies "
                                 f"(largest change {100 * change:.2g} % of its peak)")
                B[i, j] = np.clip(B[i, j], -bound, bound)
    return omega, B


def _tail(omega, B, settings, notes):
    """Frequency grid and damping including the tail; B(0) = 0 prepended."""
    wN = omega[-1]
    w = np.concatenate([[0.0], omega])
    Bx = np.concatenate([np.zeros((6, 6, 1)), B], axis=-1)
    if settings.tail == "none":
        return w, Bx
    if settings.tail == "linear":
        width = settings.tail_width or 0.2 * wN
        return np.append(w, wN + width), np.concatenate([Bx, np.zeros((6, 6, 1))], axis=-1)
    # asymptotic: B_N (ω_N/ω)^n per pair, n from a log-log fit of the top 15 % of the band
    top = omega >= omega[0] + 0.85 * (wN - omega[0])
    if top.sum() < 3:
        top = slice(-3, None)
    extra = np.linspace(wN, 3 * wN, 41)[1:]
    tail = np.zeros((6, 6, extra.size))
    exps = []
    for i in range(6):
        for j in range(6):
            b = B[i, j, top]
            n = 4.0
            if np.all(b > 0) and b.size >= 3:
                slope = np.polyfit(np.log(omega[top]), np.log(b), 1)[0]
                n = float(np.clip(-slope, 2.0, 8.0))
            if i == j and B[i, i, -1] != 0:
                exps.append(f"{pair_name(i, i)} {n:.2g}")
            tail[i, j] = B[i, j, -1] * (wN / extra) ** n
    notes.append("asymptotic tail B_N (ω_N/ω)^n to 3 ω_N, n = " + ", ".join(exps))
    return np.concatenate([w, extra]), np.concatenate([Bx, tail], axis=-1)


def compute_irf(omega, A, B, A_inf=None, settings: IRFSettings | None = None) -> IRF:
    """Radiation IRFs K(t) of all 36 DOF pairs, A∞, and their round-trip consistency.

    Parameters
    ----------
    omega : ndarray (Nf,)
        BEM frequencies [rad/s], increasing, > 0.
    A, B : ndarray (6, 6, Nf)
        Added mass and radiation damping.
    A_inf : ndarray (6, 6) or None
        Infinite-frequency added mass from the solver; None → Ogilvie's relation.
    settings : IRFSettings

    Raises
    ------
    IRFError
        Too few frequencies, NaN, all-zero damping, π/Δt_K below the highest frequency, damping not
        decayed at the top of the band, or K not decayed by T_K — with what to change.
    """
    s = settings or IRFSettings()
    omega = np.asarray(omega, dtype=float)
    A = np.asarray(A, dtype=float)
    B = np.asarray(B, dtype=float)
    if omega.size < 10:
        raise IRFError(f"only {omega.size} frequencies: an IRF needs at least 10 across the damping peak "
                       "(rerun the BEM with a finer, wider band)")
    if not (np.all(np.isfinite(omega)) and np.all(np.isfinite(A)) and np.all(np.isfinite(B))):
        raise IRFError("NaN or infinite values in ω, A or B: drop those frequencies first")
    if A.shape != (6, 6, omega.size) or B.shape != (6, 6, omega.size):
        raise IRFError(f"A and B must have shape (6, 6, {omega.size}), got {A.shape} and {B.shape}")
    diag_peak = np.array([np.max(np.abs(B[i, i])) for i in range(6)])
    if not np.any(diag_peak > 0):
        raise IRFError("radiation damping is zero for every DOF: nothing radiates, the IRF would be zero "
                       "(is this the right database?)")
    notes: list[str] = []
    wb, Bc = _clean(omega, B, s.clean, notes, significant_pairs(B, s.significance, s.length_scale))

    # the damping must have decayed at the top of the band
    sig = significant_pairs(Bc, s.significance, s.length_scale)
    top = {i: abs(Bc[i, i, -1]) / np.max(np.abs(Bc[i, i])) for i in range(6) if sig[i, i]}
    if s.tail == "auto":
        tail = "asymptotic" if max(top.values()) > s.band_tol else "linear"
        s = dataclasses.replace(s, tail=tail)
        notes.append(f"tail 'auto' → '{tail}'")
    for i, ratio in top.items():
        if ratio > s.band_tol:
            msg = (f"B[{pair_name(i, i)}] at the top of the band (ω = {wb[-1]:.3g} rad/s) is still "
                   f"{100 * ratio:.0f} % of its peak: the band stops before the damping has decayed")
            if s.tail != "asymptotic":
                raise IRFError(msg + "; extend the BEM band to higher ω, or accept an extrapolation with "
                                     "tail='asymptotic'")
            notes.append(msg + " (extrapolated by the asymptotic tail; a wider BEM band avoids that)")
    notes.extend(filter(None, (describe_spikes(pair_name(i, i), wb, Bc[i, i]) for i in top)))

    w_all, B_all = _tail(wb, Bc, s, notes)
    if np.pi / s.dt < w_all[-1] * (1 - 1e-12):
        raise IRFError(f"dt = {s.dt:g} s is too coarse for frequencies up to {w_all[-1]:.3g} rad/s "
                       f"(π/dt = {np.pi / s.dt:.3g} < ω_max): use dt ≤ {np.pi / w_all[-1]:.3g} s")
    d_omega = float(np.max(np.diff(omega)))
    if np.pi / d_omega < s.t_max:
        notes.append(f"frequency step {d_omega:.3g} rad/s resolves the memory only up to π/Δω = "
                     f"{np.pi / d_omega:.3g} s < T_K = {s.t_max:g} s (K beyond that follows the linear "
                     "interpolation of B)")

    n_t = int(round(s.t_max / s.dt)) + 1
    t = np.linspace(0.0, (n_t - 1) * s.dt, n_t)
    K = (2.0 / np.pi) * cos_transform(w_all, B_all, t)
    if s.taper == "cosine":
        t0 = (1 - s.taper_fraction) * t[-1]
        win = np.where(t <= t0, 1.0, 0.5 * (1 + np.cos(np.pi * (t - t0) / (t[-1] - t0))))
        K = K * win
        notes.append(f"cosine taper on K over t ∈ [{t0:.3g}, {t[-1]:.3g}] s")

    peakK = np.max(np.abs(K), axis=-1)
    endK = np.max(np.abs(K[:, :, t >= 0.9 * t[-1]]), axis=-1)
    truncation = np.where(peakK > 0, endK / np.where(peakK > 0, peakK, 1), 0.0)
    for i in range(6):
        if sig[i, i] and truncation[i, i] > s.decay_tol:
            hint = ""
            if find_spikes(Bc[i, i]).size:
                hint = ("; B has sharp peaks that make K ring (irregular frequencies: rerun the BEM with a lid; "
                        "a catamaran's trapped waves: a longer memory)")
            raise IRFNotDecayed(f"K[{pair_name(i, i)}] has not decayed by T_K = {t[-1]:g} s "
                           f"(max|K| over the last 10 % is {100 * truncation[i, i]:.0f} % of its peak): "
                           f"increase t_max (try {2 * t[-1]:g} s){hint}", pair_name(i, i), float(t[-1]))

    # Ogilvie: A∞(ω) = A(ω) + (1/ω) ∫ K sin ωt dt, over the BEM band (uncleaned A)
    SK = sin_transform(t, K, omega)
    A_og = A + SK / omega
    upper = omega >= omega[0] + 0.5 * (omega[-1] - omega[0])
    A_og_med = np.median(A_og[:, :, upper], axis=-1)
    scale = np.maximum(np.max(np.abs(A_og[:, :, upper]), axis=-1), 1e-300)
    spread = np.ptp(A_og[:, :, upper], axis=-1) / scale
    if A_inf is None:
        A_inf_used, source = A_og_med, "ogilvie"
        notes.append("A∞ from Ogilvie's relation (median over the upper half of the band); spread "
                     + ", ".join(f"{pair_name(i, i)} {100 * spread[i, i]:.2g} %" for i in range(6) if sig[i, i]))
    else:
        A_inf_used, source = np.asarray(A_inf, dtype=float), "solver"

    lo, hi = s.check_band or (float(omega[0]), float(omega[-1]))
    band = (omega >= lo) & (omega <= hi)
    if band.sum() < 2:
        raise IRFError(f"check band {lo:g}–{hi:g} rad/s holds fewer than 2 BEM frequencies")
    wc = omega[band]
    B_rec = cos_transform(t, K, wc)
    A_rec = A_inf_used[:, :, None] - sin_transform(t, K, wc) / wc
    err_B = np.full((6, 6), np.nan)
    err_A = np.full((6, 6), np.nan)
    for i in range(6):
        for j in range(6):
            if sig[i, j]:
                err_B[i, j] = _rel_l2(B_rec[i, j], B[i, j, band])
                err_A[i, j] = _rel_l2(A_rec[i, j], A[i, j, band])
    return IRF(t=t, K=K, A_inf=A_inf_used, A_inf_source=source, ogilvie_spread=spread, err_B=err_B,
               err_A=err_A, truncation=truncation, significant=sig, settings=s,
               omega_max_used=float(w_all[-1]), notes=tuple(notes), check_band=(lo, hi))


def _rel_l2(approx, ref):
    den = np.linalg.norm(ref)
    return float(np.linalg.norm(approx - ref) / den) if den > 0 else float(np.linalg.norm(approx))
