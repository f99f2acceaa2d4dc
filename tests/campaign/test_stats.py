"""Campaign statistics against closed forms and against simulated data with known answers."""

import math

import numpy as np
import pytest
from scipy import stats

from boatland.campaign.stats import beta_ppf, chi2_ppf, clopper_pearson, exponential_mean_interval, limiting_hs


@pytest.mark.parametrize("k, n", [(0, 8), (3, 8), (8, 8), (17, 40)])
def test_clopper_pearson_is_the_exact_binomial_interval(k, n):
    p, lo, hi = clopper_pearson(k, n)
    ci = stats.binomtest(k, n).proportion_ci(confidence_level=0.95, method="exact")
    assert p == k / n and lo == pytest.approx(ci.low, abs=1e-12) and hi == pytest.approx(ci.high, abs=1e-12)
    if k == 0:  # closed form: 1 − (α/2)^(1/n)
        assert hi == pytest.approx(1 - 0.025 ** (1 / n), rel=1e-12)


def test_exponential_interval_is_seed002_eq_3_55_without_censoring():
    t = np.array([3906, 262, 763, 800, 6914, 5776, 450, 962.0])   # Grøtting 2015 Table 4.14, 2.25 m / 9 s / 0°
    m, lo, hi = exponential_mean_interval(t, 10000.0, confidence=0.90)
    n, tbar = t.size, t.mean()
    assert m == pytest.approx(tbar)
    assert lo == pytest.approx(2 * n * tbar / stats.chi2.ppf(0.95, 2 * n))
    assert hi == pytest.approx(2 * n * tbar / stats.chi2.ppf(0.05, 2 * n))
    # Table 4.15 prints 2 479 s, 1 487 … 4 958 s: its factors are rounded to 0.6 × and 2.0 × the mean
    # (exact: 0.6085 ×, 2.0096 ×); ours are the exact quantiles, 1 508 … 4 982 s
    assert (lo, hi) == pytest.approx((1487, 4958), rel=0.015)


def test_exponential_interval_covers_the_true_mean_with_censoring():
    """Exponential times (mean 300 s) censored at a 600 s access, 8 trials, 4000 repetitions: the
    95 % interval contains 300 s in ≥ 95 % of them (conservative below; binomial s.e. 0.35 %)."""
    rng = np.random.default_rng(7)
    covered = 0
    reps = 4000
    for _ in range(reps):
        t = rng.exponential(300.0, 8)
        t[t > 600.0] = np.inf
        _, lo, hi = exponential_mean_interval(t, 600.0)
        covered += lo <= 300.0 <= hi
    assert covered / reps >= 0.95 - 3 * math.sqrt(0.95 * 0.05 / reps)


def test_no_incident_gives_only_a_lower_bound():
    m, lo, hi = exponential_mean_interval([np.inf] * 8, 600.0)
    assert m == math.inf and hi == math.inf and lo == pytest.approx(2 * 4800 / stats.chi2.ppf(0.975, 2))


def test_limiting_hs_interpolates_the_first_crossing():
    assert limiting_hs([0.5, 1.0, 1.5, 2.0], [0.0, 0.05, 0.25, 0.9], 0.1) == pytest.approx(1.0 + 0.5 * 0.05 / 0.2)
    assert math.isnan(limiting_hs([0.5, 1.0], [0.0, 0.05], 0.1))
    assert limiting_hs([1.0, 0.5], [0.5, 0.3], 0.1) == 0.5                   # unsorted input; above at once


def test_crossing_says_when_the_sweep_does_not_cross():
    from boatland.campaign.stats import crossing

    hs = [0.25, 0.5, 0.75]
    assert crossing(hs, [0.0, 0.2, 1.0], 0.1).where == "inside"
    assert crossing(hs, [0.0, 0.2, 1.0], 0.1).value == pytest.approx(0.375)
    low = crossing(hs, [0.5, 0.75, 1.0], 0.1)          # already above the target at the lowest Hs: not a crossing
    assert (low.where, low.value, low.text()) == ("below", 0.25, "< 0.25 m")
    high = crossing(hs, [0.0, 0.0, 0.05], 0.1)
    assert (high.where, high.value, high.text()) == ("above", 0.75, "> 0.75 m")


def test_limiting_hs_interval_from_the_clopper_pearson_bounds():
    """4 seeds per case (the demo campaign): k = 0, 3, 4, 4 along Hs 0.25 … 1 m."""
    from boatland.campaign.stats import limiting_hs_interval

    hs = [0.25, 0.5, 0.75, 1.0]
    cp = [clopper_pearson(k, 4) for k in (0, 3, 4, 4)]
    p, lo, hi = (np.array(c) for c in zip(*cp))
    lim = limiting_hs_interval(hs, p, lo, hi, 0.1)
    assert lim.estimate.where == "inside" and lim.estimate.value == pytest.approx(0.25 + 0.1 / 0.75 * 0.25)
    assert lim.lower.where == "below"                    # the upper bound 0.60 > 0.1 already at 0.25 m
    assert lim.upper.where == "inside" and lim.upper.value == pytest.approx(0.25 + 0.1 / lo[1] * 0.25)
    assert lim.text() == f"{lim.estimate.value:.3g} m [< 0.25, {lim.upper.value:.3g}]"


@pytest.mark.parametrize("p, width", [(0.1, 0.2), (0.5, 0.2), (0.1, 0.1), (0.02, 0.05)])
def test_seeds_for_width_is_the_fewest_that_give_the_width(p, width):
    from boatland.campaign.stats import seeds_for_width

    n = seeds_for_width(p, width)
    _, lo, hi = clopper_pearson(round(p * n), n)
    assert hi - lo <= width
    _, lo, hi = clopper_pearson(round(p * (n - 1)), n - 1)
    assert hi - lo > width


def test_quantiles_are_scipy_stats_values_to_the_bit():
    """The campaign's quantiles come from scipy.special (no 1.2-s import of scipy.stats per campaign
    process); they are the very values scipy.stats gives, over the counts and confidences campaigns use."""
    from scipy import special

    for n in [*range(1, 41), 72, 100, 1000, 10_000]:
        k = np.arange(0, n + 1, max(1, n // 40))
        for a in (0.01, 0.05, 0.1, 0.3173):
            lo_k = np.maximum(k, 1)
            assert np.array_equal(beta_ppf(a / 2, lo_k, n - k + 1), stats.beta.ppf(a / 2, lo_k, n - k + 1))
            hi_k = np.minimum(k, n - 1)
            assert np.array_equal(beta_ppf(1 - a / 2, hi_k + 1, n - hi_k), stats.beta.ppf(1 - a / 2, hi_k + 1, n - hi_k))
    df = np.arange(2, 2002, 2)
    for q in (0.005, 0.025, 0.05, 0.95, 0.975, 0.995):
        assert np.array_equal(chi2_ppf(q, df), stats.chi2.ppf(q, df))
    q = np.linspace(0.5, 0.999, 500)
    assert np.array_equal(special.ndtri(q), stats.norm.ppf(q))        # the ISEE's z
