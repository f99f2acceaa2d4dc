r"""Statistics of a campaign case: incident probability within the access, mean time to the first
incident, limiting Hs.

- P(incident within the access) from k incidents in n trials, with the Clopper–Pearson ("exact")
  interval (Clopper & Pearson 1934, *Biometrika* 26(4)):
  :math:`[B(\alpha/2; k, n-k+1),\ B(1-\alpha/2; k+1, n-k)]`, B the beta quantile.
- Time to first incident: exponential (memoryless, Grøtting 2015 §3.3.2 eq. 3.54). With every trial ending
  in an incident at :math:`t_i`, the :math:`(1-\alpha)` interval of the mean time is Grøtting 2015 eq. 3.55
  (Ross 2009): :math:`2n\bar t/\chi^2_{1-\alpha/2,\,2n} < \theta < 2n\bar t/\chi^2_{\alpha/2,\,2n}`
  (χ²_p the p-quantile). Trials that end without an incident are *censored* at the access duration:
  the estimate is then :math:`\hat\theta = T/r` with T the total time at risk and r the incidents,
  and the interval the time-censored one, :math:`2T/\chi^2_{1-\alpha/2,\,2r+2} < \theta <
  2T/\chi^2_{\alpha/2,\,2r}` (Epstein 1954, *Ann. Math. Stat.* 25(3); Meeker & Escobar 1998 §7.6),
  which reduces to eq. 3.55's upper bound and is conservative below; with r = 0 only the lower bound exists.
- Limiting Hs at a target probability: linear interpolation of P along the Hs axis at the first
  crossing of the target (NaN when P never reaches it; the smallest Hs when P starts above it);
  :func:`limiting_hs_interval` adds its interval — where the Clopper–Pearson bounds of P cross the
  target — and says when a value is the end of the sweep rather than a crossing (:class:`Crossing`).
- Seeds per case for an interval of P no wider than asked: :func:`seeds_for_width`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special

__all__ = ["clopper_pearson", "exponential_mean_interval", "limiting_hs", "Crossing", "crossing", "LimitingHs",
           "limiting_hs_interval", "seeds_for_width"]


def beta_ppf(q, a, b):
    """Quantile q of the beta distribution B(a, b): the regularised incomplete beta function's inverse,
    ``scipy.special.betaincinv`` — what ``scipy.stats.beta.ppf`` computes (the same values: tests), without
    importing ``scipy.stats`` (≈ 1.2 s, once per campaign process)."""
    return special.betaincinv(a, b, q)


def chi2_ppf(q, df):
    """Quantile q of the χ² distribution with ``df`` degrees of freedom, 2 P⁻¹(df/2, q) with P the
    regularised lower incomplete gamma function — what ``scipy.stats.chi2.ppf`` computes (the same values:
    tests)."""
    return 2.0 * special.gammaincinv(df / 2, q)


def clopper_pearson(k: int, n: int, confidence: float = 0.95) -> tuple[float, float, float]:
    """(k/n, lower, upper) of the Clopper–Pearson interval of a binomial proportion."""
    if n <= 0:
        return math.nan, math.nan, math.nan
    a = 1.0 - confidence
    lo = 0.0 if k == 0 else float(beta_ppf(a / 2, k, n - k + 1))
    hi = 1.0 if k == n else float(beta_ppf(1 - a / 2, k + 1, n - k))
    return k / n, lo, hi


def exponential_mean_interval(times, exposure, confidence: float = 0.95) -> tuple[float, float, float]:
    """(estimate, lower, upper) of the mean time to the first incident.

    Parameters
    ----------
    times : array_like
        Time to the first incident of each trial [s]; NaN or inf for a trial without one (censored at
        ``exposure``).
    exposure : float or array_like
        Time at risk of a trial without an incident [s] (the access duration), or one per trial.
    """
    t = np.asarray(times, dtype=float)
    hit = np.isfinite(t)
    r = int(hit.sum())
    if t.size == 0:
        return math.nan, math.nan, math.nan
    T = float(np.sum(np.where(hit, t, exposure)))
    a = 1.0 - confidence
    if r == t.size:  # every trial ended in an incident: Grøtting 2015 eq. 3.55
        return T / r, 2 * T / chi2_ppf(1 - a / 2, 2 * r), 2 * T / chi2_ppf(a / 2, 2 * r)
    lower = 2 * T / chi2_ppf(1 - a / 2, 2 * r + 2)
    if r == 0:
        return math.inf, float(lower), math.inf
    return T / r, float(lower), float(2 * T / chi2_ppf(a / 2, 2 * r))


def limiting_hs(hs, p, target: float) -> float:
    """Hs at which the probability ``p`` (along increasing ``hs``) first reaches ``target``."""
    hs = np.asarray(hs, dtype=float)
    p = np.asarray(p, dtype=float)
    order = np.argsort(hs)
    hs, p = hs[order], p[order]
    if p.size == 0 or not np.any(p >= target):
        return math.nan
    k = int(np.argmax(p >= target))
    if k == 0:
        return float(hs[0])
    h0, h1, p0, p1 = hs[k - 1], hs[k], p[k - 1], p[k]
    return float(h0 + (target - p0) * (h1 - h0) / (p1 - p0))


@dataclass(frozen=True)
class Crossing:
    """Where a probability along increasing Hs first reaches a target.

    ``where``: ``"inside"`` (``value`` interpolated between two swept heights), ``"below"`` (already at
    or above the target at the lowest swept Hs: ``value`` is that Hs, an upper bound of the crossing, not
    a crossing) or ``"above"`` (never reaches it: ``value`` is the highest swept Hs, a lower bound).
    """

    value: float
    where: str

    def text(self, unit: str = " m") -> str:
        if self.where == "below":
            return f"< {self.value:g}{unit}"
        if self.where == "above":
            return f"> {self.value:g}{unit}"
        return f"{self.value:.3g}{unit}"

    def as_dict(self) -> dict:
        return {"value": self.value, "where": self.where, "text": self.text()}


def crossing(hs, p, target: float) -> Crossing:
    """:func:`limiting_hs` with where it lies: inside the sweep, below its lowest Hs or above its highest."""
    hs = np.asarray(hs, dtype=float)
    p = np.asarray(p, dtype=float)
    order = np.argsort(hs)
    hs, p = hs[order], p[order]
    if not np.any(p >= target):
        return Crossing(float(hs[-1]), "above")
    if p[0] >= target:
        return Crossing(float(hs[0]), "below")
    return Crossing(limiting_hs(hs, p, target), "inside")


@dataclass(frozen=True)
class LimitingHs:
    """The limiting Hs at a target probability and its interval: ``estimate`` from P, ``lower`` from the
    upper Clopper–Pearson bound of P (it reaches the target first), ``upper`` from the lower bound."""

    estimate: Crossing
    lower: Crossing
    upper: Crossing

    def text(self) -> str:
        e = self.estimate
        if e.where != "inside":
            return e.text() + (" (below the sweep)" if e.where == "below" else " (above the sweep)")
        return f"{e.text()} [{self.lower.text(unit='')}, {self.upper.text(unit='')}]"

    def as_dict(self) -> dict:
        return {"estimate": self.estimate.as_dict(), "lower": self.lower.as_dict(), "upper": self.upper.as_dict(),
                "text": self.text()}


def limiting_hs_interval(hs, p, p_lo, p_hi, target: float) -> LimitingHs:
    """Limiting Hs at ``target`` with its interval from the pointwise Clopper–Pearson bounds along Hs
    (``p_lo``, ``p_hi``): the bounds of P cross the target at the bounds of the limiting Hs."""
    return LimitingHs(crossing(hs, p, target), crossing(hs, p_hi, target), crossing(hs, p_lo, target))


def seeds_for_width(p: float, width: float, confidence: float = 0.95, n_max: int = 100_000) -> int | None:
    """Fewest trials per case whose Clopper–Pearson interval at a probability ``p`` is at most ``width``
    wide (k = round(p n) incidents); None when even ``n_max`` is not enough."""
    if not (0.0 < width < 1.0) or not (0.0 <= p <= 1.0):
        raise ValueError("width must lie in (0, 1) and p in [0, 1]")
    a = 1.0 - confidence
    n = np.unique(np.round(np.geomspace(1, n_max, 4000)).astype(int))
    k = np.round(p * n)
    lo = np.where(k == 0, 0.0, beta_ppf(a / 2, np.maximum(k, 1), n - k + 1))
    hi = np.where(k == n, 1.0, beta_ppf(1 - a / 2, k + 1, np.maximum(n - k, 1)))
    ok = np.nonzero(hi - lo <= width)[0]
    if not ok.size:
        return None
    # the first n on the coarse grid that is narrow enough: refine between its neighbour and it
    j = ok[0]
    start = int(n[j - 1]) + 1 if j > 0 else 1
    for m in range(start, int(n[j]) + 1):
        km = round(p * m)
        w = clopper_pearson(km, m, confidence)
        if w[2] - w[1] <= width:
            return m
    return int(n[j])
