r"""Statistics of the screening's responses (slip margins and roll, :mod:`boatland.freqdomain.screening`) in a
wave spectrum: spectral moments, which responses are events of their own, the incident probability per
wave cycle and per access, and the limiting Hs at an accepted risk.

In a spectrum :math:`S(\omega)` (long-crested, direction β) the spectral moments of a response with
transfer function H are :math:`m_k = \int_0^\infty \omega^k |H(\omega,\beta)|^2 S(\omega)\,d\omega`
(Grøtting 2015 eq. 3.29–3.32, 3.35). All are proportional to :math:`H_s^2` for a fixed spectral shape —
the limiting Hs solves a 1-D monotone equation.

Statistics (``statistics``):

``"rayleigh"`` (Grøtting 2015): per wave cycle (one per Tp) the peak of each margin exceeds its capacity with
  probability :math:`e^{-a_m^2/2\sigma_m^2}` (eq. 3.36; the thesis's sign typo corrected), the roll
  amplitude its limit with :math:`e^{-\theta_{max}^2/2\sigma_\phi^2}` (eq. 3.37); incident per cycle
  :math:`P_{inc} = 1 - \prod(1 - P_i)` (eq. 3.40 / 3.80); acceptable per cycle
  :math:`P_{facc}T_p/t_{acc}` (eq. 3.38).
``"rice"``: Rice's up-crossing rate of each capacity :math:`\nu_m = \nu_{0,m}\,e^{-a_m^2/2m_{0,m}}`,
  :math:`\nu_0 = \sqrt{m_2/m_0}/2\pi` (roll: both signs, 2ν), Poisson arrivals: per access
  :math:`P = 1 - \exp(-t_{acc}\sum\nu)`, accepted when ≤ :math:`P_{facc}`.
``"vanmarcke"``: as Rice with Vanmarcke's (1975) clumping correction of each rate,
  :math:`\nu^{*} = \nu\,\min\!\left(1, \frac{1 - \exp(-\sqrt{2\pi}\,\delta^{1.2} r)}{1 - e^{-r^2/2}}\right)`
  (roll, a double barrier: :math:`\sqrt{\pi/2}` and 2ν), :math:`r = a/\sigma`, bandwidth
  :math:`\delta = \sqrt{1 - m_1^2/(m_0 m_2)}`.

The accepted risk (:data:`ACCEPT_PRESETS`) is a probability of an incident per access of
:data:`ACCESS_DURATION`, Grøtting (2015) Table 2.1.

References: Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*,
MSc thesis, NTNU; Rice, S. O. (1945), *Bell Syst. Tech. J.* 24, 46–156; Vanmarcke, E. H. (1975), *J. Appl.
Mech.* 42(1), 215–220.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numba
import numpy as np

from boatland.errors import BoatlandInputError
from boatland.sea.spectra import SpectrumPart

__all__ = ["ACCEPT_PRESETS", "DEFAULT_STATISTICS", "ACCEPT_SOURCES", "access_text", "one_in", "probability_text", "risk_in_words", "ACCESS_DURATION", "HS_MAX", "LimitTable", "MODES", "SAME_EVENT", "STATISTICS",
           "accept_probability", "correlation_matrix", "distinct_events", "hermite_level", "incident_probability", "limiting_hs", "rayleigh_exceedance",
           "response_correlation", "response_names", "rice_rate", "slow_amplitude_weights", "slow_fast_rate", "SlowSwing",
           "spectral_moments", "unit_spectra", "vanmarcke_rate"]


#: Slip modes, in the order of the margin arrays (then roll as the 5th response).
MODES = ("down", "up", "left", "right")


def response_names(n_responses: int) -> tuple[str, ...]:
    """Names of the screening's responses: each contact's four slip modes (``"down 0"`` …), then roll."""
    return tuple(f"{m} {c}" for c in range((n_responses - 1) // 4) for m in MODES) + ("roll",)


#: Accepted probability of a failure (incident) during one access operation, Grøtting (2015) Table 2.1
#: (his best estimate, and the conservative and non-conservative ends of his range).
ACCEPT_PRESETS = {"best": 0.00119, "conservative": 0.00002, "non-conservative": 0.02681}
#: How each preset is named in words (:func:`risk_in_words`).
ACCEPT_SOURCES = {"best": "Grøtting 2015 best estimate", "conservative": "Grøtting 2015 conservative",
                  "non-conservative": "Grøtting 2015 non-conservative"}


#: Duration of one access operation t_acc [s] (Grøtting 2015 §3.2.1: 30 min throughout).
ACCESS_DURATION = 1800.0


def one_in(p: float) -> str:
    """A probability as odds a planner reads: 0.00119 → "1 in 840", 0.005 → "1 in 200", 0.5 → "1 in 2"
    (two significant figures; "1 in 1" from 0.67 up would say nothing, so from there "1 in 1.5" …,
    and at 1 "every one")."""
    p = float(p)
    if not math.isfinite(p) or p < 0:
        return "–"
    if p == 0:
        return "none"
    if p >= 1:
        return "every one"
    n = 1.0 / p
    digits = 2 - int(math.floor(math.log10(n))) - 1
    r = round(n, digits)
    text = f"{r:,.0f}" if r >= 10 else f"{r:.2g}"
    return f"1 in {text}"


def probability_text(p: float) -> str:
    """A probability to three significant figures, small ones as ``1.19e-3`` (no padded exponent)."""
    p = float(p)
    if not math.isfinite(p) or p == 0 or p >= 0.01:
        return f"{p:.3g}"
    mantissa, exponent = f"{p:.2e}".split("e")
    return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"


def access_text(access: float = ACCESS_DURATION) -> str:
    """"30-min access" (an access of ``access`` seconds)."""
    return f"{access / 60:g}-min access" if access % 60 == 0 else f"{access:g}-s access"


def risk_in_words(accept, access: float = ACCESS_DURATION) -> str:
    """The accepted risk as a planner reads it: ``"1 access in 840 (1.19e-3 per 30-min access, Grøtting 2015
    best estimate)"`` — for a preset name or a number (a number equal to a preset is named as it, for a
    30-min access: Grøtting's figures are per 30-min access)."""
    p = accept_probability(accept)
    source = next((ACCEPT_SOURCES[k] for k, v in ACCEPT_PRESETS.items() if v == p), None) \
        if access == ACCESS_DURATION else None                 # Grøtting's figures are per 30-min access
    odds = one_in(p).replace("1 in", "1 access in")
    return f"{odds} ({probability_text(p)} per {access_text(access)}" + (f", {source})" if source else ", as given)")


STATISTICS = ("rayleigh", "rice", "vanmarcke")

#: The screening's default statistic: Rice's up-crossings. Chosen on evidence (``boatland validate --case
#: screening-vs-monte-carlo``, ctv24 at Tp 7 s, 24 × 30-min trials per point, measured 2026-12-03 on the rebuilt
#: databases): at the six points where P(first slip per access) is 0.3–0.8, five of six time-domain probabilities
#: lie above Rayleigh's (Rayleigh's one peak per Tp undercounts the cycles of a response whose mean period is
#: shorter than Tp — a one-sided, unconservative bias; on the databases before, 6 of 6, one outside its
#: interval); Rice lies inside all six, three above and three below. In the tail (the default ctv27 at the accepted 1.19e-3, ``boatland campaign
#: scenarios/campaigns/ctv_limits.toml``, measured 2026-12-03) Rice agrees with the time domain's limiting Hs
#: within 2 % (0.3743 / 0.2522 / 0.1553 m against 0.3739 / 0.2514 / 0.1583 m head / 135° / beam: inside the
#: campaign's 95 % intervals, beam on 1.9 % below it, on the safe side).
DEFAULT_STATISTICS = "rice"


HS_MAX = 30.0  # [m] limiting Hs reported as inf above this


def accept_probability(accept) -> float:
    """An accepted probability per access: a number in (0, 1) or a preset name of :data:`ACCEPT_PRESETS`.

    Raises
    ------
    BoatlandInputError
        Outside (0, 1) or an unknown name.
    """
    if isinstance(accept, str):
        key = accept.strip().lower()
        if key in ACCEPT_PRESETS:
            return ACCEPT_PRESETS[key]
        try:
            accept = float(key)
        except ValueError:
            raise BoatlandInputError(f"accepted probability {accept!r}: give a number in (0, 1) or one of "
                                     f"{', '.join(ACCEPT_PRESETS)} (Grøtting 2015 Table 2.1)") from None
    p = float(accept)
    if not 0.0 < p < 1.0:
        raise BoatlandInputError(f"accepted probability {p:g} is outside (0, 1): it is a probability of failure "
                                 f"per access, e.g. {ACCEPT_PRESETS['best']} (Grøtting 2015 Table 2.1 best estimate)")
    return p


# --------------------------------------------------------------------------------------- statistics
def _part(sea) -> SpectrumPart:
    return SpectrumPart(Hs=1.0, Tp=10.0) if sea is None else sea


def unit_spectra(omega, Tp, *, sea: SpectrumPart | None = None, water_depth: float = math.inf,
                 g: float = 9.81) -> tuple[np.ndarray, np.ndarray]:
    """The spectra (NT, Nw) of ``sea``'s shape (default JONSWAP γ 3.3) at Hs = 1 m and each peak period ``Tp``
    on the frequencies ``omega``, and the frequencies' trapezoid weights (Nw,)."""
    part = _part(sea)
    T = np.atleast_1d(np.asarray(Tp, dtype=float))
    if np.any(~np.isfinite(T)) or np.any(T <= 0):
        raise BoatlandInputError(f"peak periods must be > 0 s, got {T}")
    w = np.asarray(omega, dtype=float)
    S = np.stack([dataclasses.replace(part, Hs=1.0, Tp=float(t)).spectrum(w, water_depth, g) for t in T])
    wt = np.zeros_like(w)
    dw = np.diff(w)
    wt[:-1] += dw / 2
    wt[1:] += dw / 2
    return S, wt


def spectral_moments(transfer, Tp, *, sea: SpectrumPart | None = None,
                     water_depth: float = math.inf, g: float = 9.81) -> tuple[np.ndarray, np.ndarray]:
    r"""Spectral moments :math:`m_k = \int \omega^k |H|^2 S\,d\omega`, k = 0, 1, 2, for Hs = 1 m.

    Parameters
    ----------
    transfer : SlipTransfer
        The responses' transfer functions (:func:`boatland.freqdomain.screening.slip_transfer`).
    Tp : array_like, shape (NT,)
        Peak periods [s].
    sea : SpectrumPart, optional
        Shape of the spectrum (kind, γ, σ_a, σ_b); its Hs, Tp and direction are ignored. Default
        JONSWAP γ = 3.3.
    water_depth, g : float
        For a TMA spectrum.

    Returns
    -------
    m : ndarray, shape (NT, Nβ, R, 3)
        m₀, m₁, m₂ of the 4 margins [N²·s⁻ᵏ] and roll [rad²·s⁻ᵏ] per m² of Hs².
    captured : ndarray, shape (NT,)
        Share of the wave variance m₀ inside the frequency grid (the rest is left out).
    """
    w = transfer.omega
    S, wt = unit_spectra(w, Tp, sea=sea, water_depth=water_depth, g=g)
    H2 = np.abs(transfer.H) ** 2                            # (Nw, Nβ, R)
    powers = w[:, None] ** np.arange(3)[None, :]            # (Nw, 3)
    m = np.einsum("tw,w,wbr,wk->tbrk", S, wt, H2, powers, optimize=True)
    captured = (S @ wt) / (1.0 / 16.0)
    return m, captured


#: Responses whose correlation reaches this are one event (:func:`distinct_events`).
SAME_EVENT = 0.99


def response_correlation(transfer, Tp, *, sea: SpectrumPart | None = None,
                         water_depth: float = math.inf, g: float = 9.81) -> np.ndarray:
    r"""Correlation coefficients of the responses (margins, roll) in each sea:
    :math:`\rho_{ij} = \int \mathrm{Re}(H_i \bar H_j) S\,d\omega / (\sigma_i\sigma_j)`.

    Returns
    -------
    ndarray, shape (NT, Nβ, R, R)
    """
    S, wt = unit_spectra(transfer.omega, Tp, sea=sea, water_depth=water_depth, g=g)
    H = transfer.H                                           # (Nw, Nβ, R)
    cov = np.einsum("tw,w,wbi,wbj->tbij", S, wt, H, H.conj(), optimize=True).real
    return correlation_matrix(cov)


def correlation_matrix(cov: np.ndarray) -> np.ndarray:
    """Correlation coefficients ρ_ij = C_ij / (σ_i σ_j) of covariance matrices (..., R, R); 0 where a σ is 0."""
    sd = np.sqrt(np.clip(np.einsum("...ii->...i", cov), 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = cov / (sd[..., :, None] * sd[..., None, :])
    return np.nan_to_num(rho)


def distinct_events(m0: np.ndarray, capacity: np.ndarray, correlation: np.ndarray,
                    same: float = SAME_EVENT, background: "SlowSwing | None" = None) -> np.ndarray:
    r"""Which responses are events of their own: a response correlated at ρ ≥ ``same`` with one that is
    at least as likely (smaller reliability index β = a/σ) exceeds its capacity only when that one does
    — the same event — and is left out of the union. Two symmetric contacts in head seas have identical
    margins (ρ = 1): counted twice, as independent events, they would double the incident rate. β is
    proportional to 1/Hs for every response, so the choice does not depend on Hs. Roll (the last
    response) is always kept. With a ``background`` (the gusts' slow swing, which does not grow with Hs) two
    responses are one event only when both their wave parts and their swings are that correlated: the swing
    turns the vessel about its bow one way, then the other, unloading each tube in turn, so symmetric tubes
    the waves load alike slip at different moments (ctv27 in head seas with a 10 kn beam wind: the time
    domain's first-slip rate is twice one tube's). Counting both when the waves dominate is on the safe side.

    Parameters
    ----------
    m0 : ndarray, shape (..., R)
        Variances of the responses (any Hs).
    capacity : ndarray, shape (R,)
    correlation : ndarray, shape (..., R, R)

    Returns
    -------
    ndarray of bool, shape (..., R)
    """
    if background is not None and background.correlation is not None:
        correlation = np.minimum(correlation, background.correlation)
    with np.errstate(divide="ignore", invalid="ignore"):
        beta = np.where(m0 > 0, capacity / np.sqrt(m0), np.inf)
    keep = np.ones(m0.shape, bool)
    flat_beta = beta.reshape(-1, beta.shape[-1])
    flat_keep = keep.reshape(-1, beta.shape[-1])
    flat_rho = correlation.reshape(-1, *correlation.shape[-2:])
    for cell in range(flat_beta.shape[0]):
        order = np.argsort(flat_beta[cell, :-1], kind="stable")
        kept: list[int] = []
        for i in order:
            if any(flat_rho[cell, i, j] >= same for j in kept):
                flat_keep[cell, i] = False
            else:
                kept.append(int(i))
    return keep


def rayleigh_exceedance(a, sigma) -> np.ndarray:
    r"""Probability that the peak of one cycle of a zero-mean narrow-band Gaussian process with standard
    deviation σ exceeds a (Grøtting 2015 eq. 3.36–3.37): :math:`P = e^{-a^2/2\sigma^2}`, 1 for a ≤ 0."""
    a = np.asarray(a, dtype=float)
    sigma = np.asarray(sigma, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        p = np.exp(-0.5 * (a / sigma) ** 2)
    return np.where(a <= 0, 1.0, np.where(sigma > 0, p, 0.0))


def rice_rate(a, m0, m2) -> np.ndarray:
    r"""Rice's mean rate of up-crossings of level a [1/s]: :math:`\nu_a = \frac{1}{2\pi}\sqrt{m_2/m_0}\,
    e^{-a^2/2m_0}` (Rice 1945), the zero up-crossing rate :math:`\nu_0` times the Rayleigh factor."""
    a, m0, m2 = (np.asarray(v, dtype=float) for v in (a, m0, m2))
    with np.errstate(divide="ignore", invalid="ignore"):
        nu0 = np.sqrt(m2 / m0) / (2 * math.pi)
        nu = nu0 * np.exp(-0.5 * a * a / m0)
    return np.where(m0 > 0, np.where(a <= 0, nu0, nu), 0.0)


def hermite_level(r, skew, exkurt) -> np.ndarray:
    r"""The level of a standard Gaussian crossed as often as a non-Gaussian process with skewness ``skew``
    and excess kurtosis ``exkurt`` crosses ``r`` standard deviations above its mean (upper tail).

    Winterstein's Hermite model (Winterstein, S. R. (1988), *Nonlinear vibration models for extremes and
    fatigue*, J. Eng. Mech. 114(10), 1772–1790): the process is a monotone transform of a standard Gaussian U,

    .. math:: \frac{X - \bar X}{\sigma} = \kappa\left[U + h_3(U^2 - 1) + h_4(U^3 - 3U)\right], \quad
              h_4 = \frac{\sqrt{1 + 1.5\,\gamma_4} - 1}{18}, \quad h_3 = \frac{\gamma_3}{6(1 + 6h_4)}, \quad
              \kappa = (1 + 2h_3^2 + 6h_4^2)^{-1/2}

    (γ₃ the skewness, γ₄ ≥ 0 the excess kurtosis; a γ₄ < 0 is taken as 0, the model's softening branch not
    being needed for the quadratic responses it serves), so the crossings of r by X are those of u = g⁻¹(r) by
    U, Rice's rate :math:`\nu_0 e^{-u^2/2}`. Solved by Newton's method on the model's monotone branch
    (:math:`u > -(1 + 6h_4)/(2h_3)` … the turning points); where the branch ends below r (a skewness beyond the
    model), the turning point. With γ₃ = γ₄ = 0, u = r exactly.
    """
    r, g3, g4 = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (r, skew, exkurt)))
    g4 = np.maximum(g4, 0.0)
    h4 = (np.sqrt(1.0 + 1.5 * g4) - 1.0) / 18.0
    h3 = g3 / (6.0 * (1.0 + 6.0 * h4))
    kap = 1.0 / np.sqrt(1.0 + 2.0 * h3 * h3 + 6.0 * h4 * h4)
    x = r / kap
    u = np.array(r, dtype=float, copy=True)
    for _ in range(40):
        f = u + h3 * (u * u - 1.0) + h4 * (u ** 3 - 3.0 * u) - x
        d = 1.0 + 2.0 * h3 * u + 3.0 * h4 * (u * u - 1.0)
        u = np.where(d > 1e-3, u - f / np.where(d > 1e-3, d, 1.0), u)
    return np.where((g3 == 0.0) & (g4 == 0.0), r, u)


@dataclass(frozen=True, eq=False)
class SlowSwing:
    r"""The part of every response that does not grow with the waves: the landed vessel's slow swing in the
    wind's gusts (:func:`boatland.freqdomain.screening.gust_moments`).

    Attributes
    ----------
    moments : ndarray, shape (R, 3) or (..., R, 3)
        Its spectral moments m₀, m₁, m₂ per response (Gaussian equivalent linearisation of the hull's drag);
        with leading axes, one swing per cell of a table (each sea state in its own wind:
        :mod:`boatland.site.wind`) — :func:`limiting_hs` takes those.
    linear_share : float or ndarray, shape (...)
        λ: the share of the swing's equivalent damping that is linear (radiation, fender, the drag's
        derivative at the mean current); the rest is the hull's quadratic drag, which makes its large swings
        rarer than a Gaussian's (:func:`slow_amplitude_weights`). 1: all linear (Rayleigh amplitudes).
    correlation : ndarray, shape (R, R) or (..., R, R), optional
        The swing's correlation between the responses (1 between two it does not move at all): a yaw swing
        unloads one tube while it loads the other, so margins the waves make identical differ in the gusts
        (:func:`distinct_events`).
    """

    moments: np.ndarray
    linear_share: float | np.ndarray = 1.0
    correlation: np.ndarray | None = None


#: κ of the swing amplitudes' law under quadratic damping (:func:`slow_amplitude_weights`): (8/9π)/√(8/π).
_KAPPA_QUADRATIC = (8.0 / (9.0 * math.pi)) / math.sqrt(8.0 / math.pi)


def slow_amplitude_weights(edges, linear_share: float) -> np.ndarray:
    r"""Probabilities of the slow swing's cycle amplitude u = A/σ_G in the bins ``edges`` (σ_G: the
    Gaussian-linearised standard deviation), by stochastic averaging of a lightly damped mode with linear
    and quadratic damping under broad-band forcing (Roberts, J. B. & Spanos, P. D. (1986), *Stochastic
    averaging: an approximate method of solving random vibration problems*, Int. J. Non-Linear Mech. 21(2)
    111–134; the energy-equivalent damping of :math:`k|\dot x|\dot x` at amplitude A is :math:`8k\omega A/3\pi`):

    .. math:: p(u) \propto u\,\exp\!\left(-\lambda\frac{u^2}{2} - \kappa(1-\lambda)\,u^3\right), \qquad
              \kappa = \frac{8/9\pi}{\sqrt{8/\pi}} = 0.177

    with λ the linear share of the Gaussian equivalent damping (λ = 1: Rayleigh). Measured on ctv27 in a
    10 m/s beam wind (time domain, 12 × 30 min): the swing's excess kurtosis −0.36, this law's −0.35 at the
    screening's λ = 0.09 (a Gaussian's 0), so that the swing's large crests — the slips — are rarer than
    Rayleigh amplitudes say."""
    lam = float(linear_share)
    u = np.linspace(edges[0], edges[-1], 8 * (len(edges) - 1) + 1)
    pdf = u * np.exp(-lam * u * u / 2 - _KAPPA_QUADRATIC * (1 - lam) * u ** 3)
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (pdf[1:] + pdf[:-1]) * np.diff(u))])
    cdf /= cdf[-1]
    return np.diff(np.interp(edges, u, cdf))


#: Quadrature of :func:`slow_fast_rate`: Rayleigh amplitudes of the slow cycles (points up to SLOW_A_MAX σ) and
#: phases within a cycle.
SLOW_A_POINTS, SLOW_A_MAX, SLOW_PHASES = 160, 10.0, 32


def slow_fast_rate(a, m0f, m2f, m0s, m2s, duration: float, sides=1.0, linear_share: float = 1.0) -> np.ndarray:
    r"""Equivalent first-passage rate [1/s] of a response made of a slow narrow-band part (the landed vessel's
    swing in gusts: spectral moments m0s, m2s) and a fast one (the waves': m0f, m2f), independent Gaussians.

    Rice's rate of the sum counts up-crossings as independent; but the waves cross the level mostly while
    the slow swing is near its crest, in clumps, so Poisson arrivals of crossings overstate the probability of
    a first passage (for ctv27 in a 10 m/s beam wind, ×4 against the time domain at P ≈ 0.35). Here the slow
    part is a sequence of independent cycles of period :math:`T_s = 2\pi\sqrt{m_{0s}/m_{2s}}` with Rayleigh
    amplitudes A and the waves' crossings are Poisson given it, at the rate of the level a − x(t):

    .. math::
        P(\text{no passage in } T) = \left(E_A\!\left[\exp\Big(-\int_0^{T_s}
            \nu_f\big(a - A\cos\tfrac{2\pi t}{T_s}\big)\,dt\Big)\right]\right)^{T/T_s},
        \qquad \nu_f(b) = \tfrac{1}{2\pi}\sqrt{m_{2f}/m_{0f}}\;e^{-b^2/2m_{0f}}

    times, for each cycle, the probability :math:`\Phi((a - A)/\sqrt{m_{0f}})` that the swing's crest plus the
    waves there stays below a (two-sided, ``sides`` = 2: also the level −a); returned as :math:`-\ln P/T`. The
    amplitudes A follow :func:`slow_amplitude_weights` (``linear_share`` λ; Rayleigh for λ = 1). It tends to Rice's rate of the
    waves alone as the slow part vanishes, and to Rice's rate of the slow swing alone (its crests' Rayleigh
    exceedance once per cycle) as the waves vanish. The conditional-Poisson treatment of a slowly varying
    offset under wave-frequency crossings is that of combined low- and wave-frequency extremes of moored
    vessels (e.g. Naess, A. & Moan, T. (2013), *Stochastic Dynamics of Marine Structures*, Cambridge, ch. 9).
    """
    a, m0f, m2f, m0s, m2s = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (a, m0f, m2f, m0s, m2s)))
    sides = np.broadcast_to(np.asarray(sides, dtype=float), a.shape)
    edges, u, wA, tail, n_amp, c = _swing_tables(np.array([float(linear_share)]))
    flat = [np.ascontiguousarray(v, dtype=float).ravel() for v in (a, m0f, m2f, m0s, m2s, sides)]
    out = np.empty(a.size)
    _swing_rates(*flat, float(duration), wA[0], n_amp[0], tail[0], float(linear_share) == 1.0, edges, u, c, out)
    return out.reshape(a.shape)


def _swing_tables(shares: np.ndarray):
    """The quadrature of :func:`slow_fast_rate` for each linear share λ of ``shares`` (K,): the amplitude bins'
    ``edges`` and middles ``u`` (in σ_s, up to :data:`SLOW_A_MAX`), their probabilities ``wA`` (K, nA)
    (:func:`slow_amplitude_weights`) and tails P(u > edge) (K, nA + 1), how many bins count ``n_amp`` (K,) —
    those whose weight is below 1e-25 of the largest change no rate by more than 1e-20 relative — and the
    distinct |cos| ``c`` of the :data:`SLOW_PHASES` phases of a cycle (they come in ± pairs, each twice)."""
    edges = np.linspace(0.0, SLOW_A_MAX, SLOW_A_POINTS + 1)                   # A/σ_s
    u = 0.5 * (edges[1:] + edges[:-1])
    wA = np.stack([slow_amplitude_weights(edges, float(s)) for s in shares])
    tail = np.concatenate([np.cumsum(wA[:, ::-1], axis=1)[:, ::-1], np.zeros((shares.size, 1))], axis=1)
    n_amp = np.array([int(np.flatnonzero(w >= 1e-25 * w.max())[-1]) + 1 for w in wA], dtype=np.int64)
    c = np.cos(2 * math.pi * (np.arange(SLOW_PHASES // 4) + 0.5) / SLOW_PHASES)
    return edges, u, wA, tail, n_amp, c


def swing_limits(m: np.ndarray, capacity, p_acc: float, duration: float, keep, background: SlowSwing):
    r"""Limiting Hs of every cell under the Rice statistics with a slow swing (:func:`slow_fast_rate`), each cell
    solved on its own by a compiled kernel: the same rate as :func:`incident_probability` evaluates, and the root
    of :math:`t_{acc}\sum_i 
u_i(H_s) = -\ln(1 - P_{facc})` in :math:`\ln H_s` on [1 mm, :data:`HS_MAX`] by the
    Illinois variant of regula falsi (Dowell, M. & Jarratt, P. (1971), *BIT* 11, 168–174) to a relative
    precision of 1e-11 — about ten evaluations of the rates, against the sixty of a bisection over all cells
    at once, and without its (cells × responses × amplitudes × phases) arrays, which made a year of sea states
    in a gusty wind take gigabytes and minutes. Capacities, keep masks and the swing (moments, λ) may differ
    per cell (each sea state in its own wind).

    Parameters
    ----------
    m : ndarray, shape (..., R, 3)
        The waves' spectral moments per unit Hs².
    capacity : ndarray, shape (R,) or (..., R)
    p_acc, duration : float
        Accepted probability per access and the access [s].
    keep : ndarray of bool, shape (..., R), or None
    background : SlowSwing
        Moments (R, 3) or (..., R, 3); λ a float or (...).

    Returns
    -------
    Hs : ndarray, shape (...)
        inf where even :data:`HS_MAX` is accepted, 0 where 1 mm is not.
    governing : ndarray of int, shape (...)
        The response with the largest rate at the limit (at 1 m where the limit is 0 or inf).
    """
    lead, R = m.shape[:-2], m.shape[-2]
    n = int(np.prod(lead))
    mm = np.ascontiguousarray(m.reshape(n, R, 3), dtype=float)
    cap = np.ascontiguousarray(np.broadcast_to(capacity, lead + (R,)).reshape(n, R), dtype=float)
    on = np.ones((n, R)) if keep is None else np.ascontiguousarray(np.broadcast_to(keep, lead + (R,)).reshape(n, R),
                                                                    dtype=float)
    bg = np.broadcast_to(np.asarray(background.moments, dtype=float), lead + (R, 3)).reshape(n, R, 3)
    lam = np.broadcast_to(np.asarray(background.linear_share, dtype=float), lead).reshape(n)
    shares, which = np.unique(lam, return_inverse=True)
    edges, u, wA, tail, n_amp, c = _swing_tables(shares)
    sides = np.ones(R)
    sides[-1] = 2.0                                                   # roll (last): both signs
    target = -math.log1p(-p_acc) / duration
    Hs = np.empty(n)
    gov = np.empty(n, dtype=np.int64)
    _swing_limits(mm, cap, on, np.ascontiguousarray(bg[..., 0]), np.ascontiguousarray(bg[..., 2]),
                  np.ascontiguousarray(which.reshape(n), dtype=np.int64), wA, n_amp, tail, shares == 1.0, edges, u,
                  c, sides, float(duration), target, 1e-3, HS_MAX, Hs, gov)
    return Hs.reshape(lead), gov.reshape(lead)


@numba.njit(cache=True)
def _ndtr(z):
    return 0.5 * math.erfc(-z / math.sqrt(2.0))


@numba.njit(cache=True)
def _swing_rate(a, m0f, m2f, m0s, m2s, duration, sides, wA, n_amp, tail, rayleigh, edges, u, c):
    """One response's rate of :func:`slow_fast_rate` (scalars; ``wA``/``tail`` its λ's amplitude weights, of
    which the first ``n_amp`` count; ``c`` the distinct phase cosines ≥ 0 — the phases of :func:`slow_fast_rate`
    are symmetric in sign and about the half cycle, so each |cos| stands for four of them, two per sign)."""
    if m0s <= 0.0:                                                   # no swing: Rice
        if m0f <= 0.0:
            return 0.0
        nu0 = math.sqrt(m2f / m0f) / (2 * math.pi)
        return sides * (nu0 if a <= 0.0 else nu0 * math.exp(-0.5 * a * a / m0f))
    Ts = 2 * math.pi * math.sqrt(m0s / m2s) if m2s > 0.0 else duration
    sig_s = math.sqrt(m0s)
    if m0f > 0.0:
        nu0f = math.sqrt(m2f / m0f) / (2 * math.pi)
        half = 0.5 / m0f
        sf1 = math.sqrt(m0f)
        q = 0.0                       # and 1 − q summed as such (p): small rates keep their digits
        p = 0.0
        for i in range(n_amp):
            x = sig_s * u[i]
            acc = 0.0
            for j in range(c.size):
                b1 = a - x * c[j]
                b2 = a + x * c[j]
                acc += (math.exp(-half * b1 * b1) if b1 > 0.0 else 1.0) + (math.exp(-half * b2 * b2) if b2 > 0.0
                                                                           else 1.0)
            I = nu0f * sides * acc / (2 * c.size) * Ts
            z = (a - x) / sf1
            crest = _ndtr(z)                                         # Φ(z): the crest below the level …
            over = _ndtr(-z)                                         # … and 1 − Φ(z), each to its own digits
            if sides > 1.0:
                over *= 1.0 + crest                                  # 1 − Φ² = (1 − Φ)(1 + Φ)
                crest *= crest
            q += wA[i] * math.exp(-I) * crest                        # e^{−I} Φ
            p += wA[i] * (-math.expm1(-I) + math.exp(-I) * over)     # 1 − e^{−I} Φ
        if q < 0.5:                   # a likely passage: q itself is the accurate one
            return -math.log(max(q, 1e-300)) / Ts
    else:                                                            # the swing alone: its crests
        r = max(a, 0.0) / sig_s
        if rayleigh:
            p = math.exp(-0.5 * r * r) * sides
        elif r >= edges[-1]:
            p = 0.0
        else:
            k = min(int(r / (edges[1] - edges[0])), edges.size - 2)
            f = (r - edges[k]) / (edges[k + 1] - edges[k])
            p = (tail[k] + f * (tail[k + 1] - tail[k])) * sides
    if p >= 1.0:
        return -math.log(1e-300) / Ts
    return -math.log1p(-p) / Ts


@numba.njit(cache=True)
def _swing_rates(a, m0f, m2f, m0s, m2s, sides, duration, wA, n_amp, tail, rayleigh, edges, u, c, out):
    """:func:`_swing_rate` of each element (one λ)."""
    for i in range(a.size):
        out[i] = _swing_rate(a[i], m0f[i], m2f[i], m0s[i], m2s[i], duration, sides[i], wA, n_amp, tail, rayleigh,
                             edges, u, c)


@numba.njit(cache=True)
def _swing_total(h2, m, cap, on, m0s, m2s, sides, wA, n_amp, tail, rayleigh, edges, u, c, duration):
    total = 0.0
    for r in range(cap.size):
        if on[r] != 0.0:
            total += on[r] * _swing_rate(cap[r], m[r, 0] * h2, m[r, 2] * h2, m0s[r], m2s[r], duration, sides[r],
                                         wA, n_amp, tail, rayleigh, edges, u, c)
    return total


@numba.njit(cache=True)
def _swing_limits(m, cap, on, m0s, m2s, which, wA, n_amp, tail, rayleigh, edges, u, c, sides, duration, target,
                  h_lo, h_hi, Hs, gov):
    """Per cell: the root of ln(Σν) = ln(target) in s = 1/Hs² (:func:`swing_limits`): bracketed from Hs = 1 m in
    steps of ×16 in s (a limit is seldom far from a metre), then regula falsi (Illinois) — Rice's ln ν is linear
    in s, so it converges in a few steps — to 1e-11 of s (the rates' own round-off is ~1e-12); then the
    governing response."""
    lt = math.log(target)
    s_min, s_max = 1.0 / (h_hi * h_hi), 1.0 / (h_lo * h_lo)
    for k in range(m.shape[0]):
        kk = which[k]
        w, na, tl, ray = wA[kk], n_amp[kk], tail[kk], rayleigh[kk]
        mk, ck, ok, ak, bk = m[k], cap[k], on[k], m0s[k], m2s[k]
        s = 1.0
        f = _swing_total(1.0 / s, mk, ck, ok, ak, bk, sides, w, na, tl, ray, edges, u, c, duration)
        up = f > target                          # not accepted at 1 m: the limit is below (larger s)
        s_a = s_b = s
        f_a = f_b = f
        result = -1.0
        while True:
            if up:
                if s_b >= s_max:
                    result = 0.0                     # not even at 1 mm
                    break
                s_a, f_a = s_b, f_b
                s_b = min(s_b * 16.0, s_max)
                f_b = _swing_total(1.0 / s_b, mk, ck, ok, ak, bk, sides, w, na, tl, ray, edges, u, c, duration)
                if f_b <= target:
                    break
            else:
                if s_a <= s_min:
                    result = math.inf                # accepted up to HS_MAX
                    break
                s_b, f_b = s_a, f_a
                s_a = max(s_a / 16.0, s_min)
                f_a = _swing_total(1.0 / s_a, mk, ck, ok, ak, bk, sides, w, na, tl, ray, edges, u, c, duration)
                if f_a > target:
                    break
        if result < 0.0:                             # f_a > target ≥ f_b on [s_a, s_b]
            # responses whose rate at the bracket's largest Hs is below 1e-14 of the target change no root: out
            ok = ok.copy()
            for r in range(ck.size):
                if ok[r] != 0.0 and ok[r] * _swing_rate(ck[r], mk[r, 0] / s_a, mk[r, 2] / s_a, ak[r], bk[r], duration,
                                                        sides[r], w, na, tl, ray, edges, u, c) < 1e-14 * target:
                    ok[r] = 0.0
            g_a = math.log(f_a) - lt
            g_b = math.log(f_b) - lt if f_b > 0.0 else -math.inf
            side = 0
            for _ in range(200):
                if s_b - s_a <= 1e-11 * s_a:
                    break
                if math.isfinite(g_b):
                    s = (s_a * g_b - s_b * g_a) / (g_b - g_a)
                    if not (s_a < s < s_b):
                        s = 0.5 * (s_a + s_b)
                else:
                    s = math.sqrt(s_a * s_b)         # no rate at all there: shrink geometrically
                f = _swing_total(1.0 / s, mk, ck, ok, ak, bk, sides, w, na, tl, ray, edges, u, c, duration)
                g = math.log(f) - lt if f > 0.0 else -math.inf
                if g > 0.0:
                    s_a, g_a = s, g
                    if side == 1 and math.isfinite(g_b):
                        g_b *= 0.5
                    side = 1
                else:
                    s_b, g_b = s, g
                    if side == -1:
                        g_a *= 0.5
                    side = -1
            result = 1.0 / math.sqrt(s_b)            # the accepted end
        Hs[k] = result
        ok = on[k]
        h2 = result * result if (math.isfinite(result) and result > 0.0) else 1.0
        best, arg = -1.0, 0
        for r in range(ck.size):
            v = ok[r] * _swing_rate(ck[r], mk[r, 0] * h2, mk[r, 2] * h2, ak[r], bk[r], duration, sides[r], w, na, tl,
                                    ray, edges, u, c)
            if v > best:
                best, arg = v, r
        gov[k] = arg


def vanmarcke_rate(a, m0, m1, m2, two_sided: bool = False) -> np.ndarray:
    r"""Rice's rate with Vanmarcke's (1975) clumping correction: the rate of independent first passages [1/s].

    .. math:: \nu^* = \nu_a\,\min\!\left(1,\ \frac{1 - \exp(-c\,\delta^{1.2}\,r)}{1 - e^{-r^2/2}}\right),
              \quad r = a/\sqrt{m_0},\quad \delta = \sqrt{1 - m_1^2/(m_0 m_2)}

    with :math:`c = \sqrt{2\pi}` for a single barrier (X > a) and :math:`c = \sqrt{\pi/2}` for the
    double barrier (|X| > a, ``two_sided``; :math:`\nu_a` is then twice Rice's rate): in both cases
    :math:`c\,\delta\,r\,\nu_a` is the rate of envelope up-crossings, :math:`\sqrt{2\pi}\,\delta\,r\,
    \nu_0 e^{-r^2/2}`, to which the rate tends for a narrow band.

    Vanmarcke, E. H. (1975), *J. Appl. Mech.* 42(1), 215–220 (δ^1.2: his empirical equivalent bandwidth).
    A narrow band (δ → 0) makes crossings come in clumps (one per envelope excursion), so fewer
    independent first passages than up-crossings.
    """
    a, m0, m1, m2 = (np.asarray(v, dtype=float) for v in (a, m0, m1, m2))
    nu = rice_rate(a, m0, m2) * (2.0 if two_sided else 1.0)
    c = math.sqrt(math.pi / 2) if two_sided else math.sqrt(2 * math.pi)
    with np.errstate(divide="ignore", invalid="ignore"):
        delta = np.sqrt(np.clip(1.0 - m1 * m1 / (m0 * m2), 0.0, 1.0))
        r = a / np.sqrt(m0)
        f = -np.expm1(-c * delta ** 1.2 * r) / -np.expm1(-0.5 * r * r)
    return nu * np.where((r > 0) & np.isfinite(f), np.minimum(1.0, f), 1.0)


def incident_probability(Hs, m: np.ndarray, capacity: np.ndarray, Tp, *, statistics: str = DEFAULT_STATISTICS,
                         access_duration: float = ACCESS_DURATION, keep=None,
                         background=None, tails=None) -> tuple[np.ndarray, np.ndarray]:
    r"""Probability of an incident (any slip mode or roll) per wave cycle and per access.

    ``"rayleigh"`` — Grøtting 2015 eq. 3.80 per cycle of Tp, :math:`P_{cyc} = 1-\prod_i(1-e^{-a_i^2/2\sigma_i^2})`;
    per access :math:`1-(1-P_{cyc})^{t_{acc}/T_p}`. ``"rice"`` / ``"vanmarcke"`` — per access
    :math:`1-\exp(-t_{acc}\sum_i\nu_i)` (roll counted at ±θ_max); per cycle the same with
    :math:`t_{acc} = T_p`.

    Parameters
    ----------
    Hs : array_like
        Significant wave heights [m], broadcast against ``m[..., 0, 0]`` (shape (NT, Nβ)).
    m : ndarray, shape (NT, Nβ, R, 3)
        Spectral moments for Hs = 1 m (:func:`spectral_moments`).
    capacity : ndarray, shape (R,)
        Levels a_i (:attr:`boatland.freqdomain.screening.SlipTransfer.capacity`).
    Tp : array_like, shape (NT,)
    statistics : {"rayleigh", "rice", "vanmarcke"}
    access_duration : float
        t_acc [s].
    keep : ndarray of bool, shape (NT, Nβ, R), optional
        The responses that are events of their own (:func:`distinct_events`); default all.
    background : SlowSwing, optional
        The part that does not scale with Hs (the landed vessel's swing in the wind's gusts,
        :attr:`boatland.freqdomain.screening.SlipTransfer.background`): for ``"rice"`` a slow swing under the
        waves (:func:`slow_fast_rate`), for the other statistics its moments added to ``m`` Hs².
    tails : ndarray, shape (NT, Nβ, R, 2), optional
        Skewness and excess kurtosis of each response at Hs = 1 m (the hull drag's second-order part,
        :class:`boatland.freqdomain.quadratic_drag.QuadraticDrag`; second order, so they grow as Hs and Hs²):
        each capacity a is replaced by the level a Gaussian response reaches as often,
        :math:`\sigma\,u(a/\sigma)` with σ the waves' part (:func:`hermite_level`) — exact for Rice's rate,
        the same mapping for the others. Roll (last) keeps its own: its two barriers' changes cancel to first
        order.

    Returns
    -------
    p_cycle, p_access : ndarray, shape (NT, Nβ)
        Incident probability per cycle and per access.
    per_mode : ndarray, shape (NT, Nβ, R)
        Per-cycle exceedance probability (Rayleigh) or first-passage rate [1/s] (Rice, Vanmarcke) of each
        response of :data:`MODES` and roll.
    """
    if statistics not in STATISTICS:
        raise BoatlandInputError(f"statistics {statistics!r}: use one of {', '.join(STATISTICS)}")
    Hs = np.asarray(Hs, dtype=float)[..., None]
    T = np.asarray(Tp, dtype=float)[:, None]
    bg = np.zeros(3) if background is None else np.asarray(background.moments, dtype=float)
    m0 = m[..., 0] * Hs ** 2
    if tails is not None:
        t = np.asarray(tails, dtype=float)
        sd = np.sqrt(m0)
        cap = np.broadcast_to(capacity, m0.shape)
        with np.errstate(divide="ignore", invalid="ignore"):
            eq = sd * hermite_level(cap / np.where(sd > 0, sd, 1.0), t[..., 0] * Hs, t[..., 1] * Hs ** 2)
        use = (sd > 0) & (cap > 0)
        use[..., -1] = False
        capacity = np.where(use, eq, cap)
    if background is not None:
        m0 = m0 + bg[..., 0]
    on = 1.0 if keep is None else np.asarray(keep, dtype=float)
    if statistics == "rayleigh":
        p = rayleigh_exceedance(capacity, np.sqrt(m0)) * on
        p_cycle = 1.0 - np.prod(1.0 - p, axis=-1)
        with np.errstate(divide="ignore"):
            p_access = -np.expm1(access_duration / T * np.log1p(-np.minimum(p_cycle, 1.0)))
        return p_cycle, p_access, p
    m1, m2 = m[..., 1] * Hs ** 2, m[..., 2] * Hs ** 2
    if background is not None:
        m1, m2 = m1 + bg[..., 1], m2 + bg[..., 2]
    if statistics == "rice":
        sides = np.ones(capacity.shape[-1])
        sides[-1] = 2.0                                                   # roll (last): both signs
        if background is None:
            nu = rice_rate(capacity, m0, m2) * sides
        else:                   # the gusts' slow swing and the waves: crossings in clumps (slow_fast_rate)
            nu = slow_fast_rate(capacity, m[..., 0] * Hs ** 2, m[..., 2] * Hs ** 2, bg[..., 0], bg[..., 2],
                                access_duration, sides, background.linear_share)
    else:
        nu = np.concatenate([vanmarcke_rate(capacity[..., :-1], m0[..., :-1], m1[..., :-1], m2[..., :-1]),
                             vanmarcke_rate(capacity[..., -1:], m0[..., -1:], m1[..., -1:], m2[..., -1:],
                                            two_sided=True)],
                            axis=-1)
    nu = nu * on
    total = nu.sum(axis=-1)
    return -np.expm1(-total * T), -np.expm1(-total * access_duration), nu


@dataclass(frozen=True, eq=False)
class LimitTable:
    """Limiting Hs per (Tp, relative direction) for an accepted probability per access.

    Attributes
    ----------
    Tp : ndarray, shape (NT,)
    beta_deg : ndarray, shape (Nβ,)
    Hs : ndarray, shape (NT, Nβ)
        Limiting significant wave height [m] (inf above :data:`HS_MAX`, 0 if the fender slips statically).
    governing : ndarray of str, shape (NT, Nβ)
        The response that dominates at the limit (a slip mode of :data:`MODES` and its contact, e.g.
        ``"down 1"``, or ``"roll"``).
    accept : float
    statistics, method : str
    captured : ndarray, shape (NT,)
        Share of the wave variance inside the frequency grid.
    """

    Tp: np.ndarray
    beta_deg: np.ndarray
    Hs: np.ndarray
    governing: np.ndarray
    accept: float
    statistics: str
    method: str
    captured: np.ndarray

    def text(self) -> str:
        """The table as aligned text: rows Tp, columns relative direction."""
        head = "Tp [s] \\ β [deg] " + "".join(f"{b:>8g}" for b in self.beta_deg)
        rows = [head]
        for i, t in enumerate(self.Tp):
            rows.append(f"{t:>16.2f} " + "".join(f"{h:>8.2f}" if np.isfinite(h) else f"{'>' + str(int(HS_MAX)):>8}"
                                                  for h in self.Hs[i]))
        return "\n".join(rows)


def limiting_hs(m: np.ndarray, capacity: np.ndarray, Tp, beta_deg, *, accept=ACCEPT_PRESETS["best"],
                statistics: str = DEFAULT_STATISTICS, access_duration: float = ACCESS_DURATION, method: str = "improved",
                captured=None, names=None, keep=None, background=None, tails=None) -> LimitTable:
    r"""Limiting Hs per (Tp, β): the largest Hs whose incident probability is accepted.

    ``"rayleigh"``: :math:`P_{inc}(H_s) \le P_{facc}\,T_p/t_{acc}` (Grøtting 2015 eq. 3.38–3.40, 3.80);
    ``"rice"``/``"vanmarcke"``: :math:`1 - \exp(-t_{acc}\sum\nu_i(H_s)) \le P_{facc}`. Both sides are
    monotone in Hs (every σ ∝ Hs), so a vectorised bisection in log Hs over all cells at once
    (60 halvings of [1 mm, 30 m]: relative precision 1e-16).

    Parameters
    ----------
    m : ndarray, shape (NT, Nβ, R, 3)
        Spectral moments for Hs = 1 m.
    capacity : ndarray, shape (R,)
    Tp, beta_deg : array_like
    accept : float or str
        Accepted probability of an incident per access, in (0, 1), or a preset name.
    background : SlowSwing, optional
        The part independent of Hs (gusts: :func:`incident_probability`); the probability still grows with Hs,
        so the bisection holds.
    tails : ndarray, shape (NT, Nβ, R, 2), optional
        The responses' skewness and excess kurtosis at Hs = 1 m (:func:`incident_probability`).

    Returns
    -------
    LimitTable
    """
    p_acc = accept_probability(accept)
    T = np.asarray(Tp, dtype=float)
    names = np.array(response_names(np.shape(capacity)[-1]) if names is None else names)
    if statistics == "rice" and background is not None and tails is None:
        Hs, gov = swing_limits(m, capacity, p_acc, access_duration, keep, background)
        cap = np.ones(T.size) if captured is None else np.asarray(captured)
        return LimitTable(Tp=T, beta_deg=np.asarray(beta_deg, dtype=float), Hs=Hs, governing=names[gov],
                          accept=p_acc, statistics=statistics, method=method, captured=cap)
    if statistics == "rice" and background is not None and np.ndim(background.linear_share):
        raise ValueError("a swing per cell with tails: not supported (give tails=None)")
    if statistics == "rayleigh":
        target = np.broadcast_to((p_acc * T / access_duration)[:, None], m.shape[:2])
    else:
        target = np.full(m.shape[:2], p_acc)

    def excess(h):
        pc, pa, _ = incident_probability(h, m, capacity, T, statistics=statistics, access_duration=access_duration,
                                         keep=keep, background=background, tails=tails)
        return (pc if statistics == "rayleigh" else pa) - target

    lo = np.full(m.shape[:2], math.log(1e-3))
    hi = np.full(m.shape[:2], math.log(HS_MAX))
    never = excess(np.exp(hi)) <= 0
    always = excess(np.exp(lo)) > 0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        bad = excess(np.exp(mid)) > 0
        hi = np.where(bad, mid, hi)
        lo = np.where(bad, lo, mid)
    Hs = np.where(never, np.inf, np.where(always, 0.0, np.exp(lo)))
    _, _, per = incident_probability(np.where(np.isfinite(Hs) & (Hs > 0), Hs, 1.0), m, capacity, T,
                                     statistics=statistics, access_duration=access_duration, keep=keep,
                                     background=background, tails=tails)
    governing = names[np.argmax(per, axis=-1)]
    cap = np.ones(T.size) if captured is None else np.asarray(captured)
    return LimitTable(Tp=T, beta_deg=np.asarray(beta_deg, dtype=float), Hs=Hs, governing=governing,
                      accept=p_acc, statistics=statistics, method=method, captured=cap)
