r"""Statistics of a campaign case: incident probability within the access, mean time to the first
incident, limiting Hs.

- P(incident within the access) from k incidents in n trials, with the Clopper–Pearson ("exact")
  interval (Clopper & Pearson 1934, *Biometrika* 26(4)):
  :math:`[B(\alpha/2; k, n-k+1),\ B(1-\alpha/2; k+1, n-k)]`, B the beta quantile.
- Time to first incident: exponential (memoryless, seed 002 §3.3.2 eq. 3.54). With every trial ending
  in an incident at :math:`t_i`, the :math:`(1-\alpha)` interval of the mean time is seed 002 eq. 3.55
  (Ross 2009): :math:`2n\bar t/\chi^2_{1-\alpha/2,\,2n} < \theta < 2n\bar t/\chi^2_{\alpha/2,\,2n}`
  (χ²_p the p-quantile). Trials that end without an incident are *censored* at the access duration:
  the estimate is then :math:`\hat\theta = T/r` with T the total time at risk and r the incidents,
  and the interval the time-censored one, :math:`2T/\chi^2_{1-\alpha/2,\,2r+2} < \theta <
  2T/\chi^2_{\alpha/2,\,2r}` (Epstein 1954, *Ann. Math. Stat.* 25(3); Meeker & Escobar 1998 §7.6),
  which reduces to eq. 3.55's upper bound and is conservative below; with r = 0 only the lower bound exists.
- Limiting Hs at a target probability: linear interpolation of P along the Hs axis at the first
  crossing of the target (NaN when P never reaches it; the smallest Hs when P starts above it).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import stats

__all__ = ["clopper_pearson", "exponential_mean_interval", "limiting_hs"]


def clopper_pearson(k: int, n: int, confidence: float = 0.95) -> tuple[float, float, float]:
    """(k/n, lower, upper) of the Clopper–Pearson interval of a binomial proportion."""
    if n <= 0:
        return math.nan, math.nan, math.nan
    a = 1.0 - confidence
    lo = 0.0 if k == 0 else float(stats.beta.ppf(a / 2, k, n - k + 1))
    hi = 1.0 if k == n else float(stats.beta.ppf(1 - a / 2, k + 1, n - k))
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
    if r == t.size:  # every trial ended in an incident: seed 002 eq. 3.55
        return T / r, 2 * T / stats.chi2.ppf(1 - a / 2, 2 * r), 2 * T / stats.chi2.ppf(a / 2, 2 * r)
    lower = 2 * T / stats.chi2.ppf(1 - a / 2, 2 * r + 2)
    if r == 0:
        return math.inf, float(lower), math.inf
    return T / r, float(lower), float(2 * T / stats.chi2.ppf(a / 2, 2 * r))


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
