"""The ISEE estimator of Au & Beck (2001) on problems with a closed-form answer: one elementary event
(exactly Φ(−β), zero variance), two orthogonal events (their union), and a union of many correlated
half-spaces against plain Monte Carlo; the conditional draw and the event choice.

Au, S. K. & Beck, J. L. (2001), First excursion probabilities for linear systems by very efficient
importance sampling, Probabilistic Engineering Mechanics 16(3), 193–207.
"""

import math

import numpy as np
import pytest
from scipy.stats import kstest, norm

from boatland.freqdomain.isee import HalfSpaces, conditional_normal, draw, estimate, select_event


def run(problem, n, seed=1):
    vals, lpb = [], None
    for s in range(n):
        rng = np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(s,)))
        u, e, lpb = draw(problem, rng)
        vals.append(1.0 / problem.count(u, e))
    return estimate(vals, lpb)


@pytest.mark.parametrize("beta", [1.0, 4.0, 9.0, 30.0])
def test_one_elementary_event_gives_phi_minus_beta_exactly(beta):
    b = np.array([3.0, -4.0, 0.0, 12.0])                       # |b| = 13
    est = run(HalfSpaces([b], [13.0 * beta]), 50)
    assert est.p == pytest.approx(norm.sf(beta), rel=1e-13)    # every weight is P̄ = Φ(−β)
    assert est.cov == 0.0 and est.hits == 50


def test_two_orthogonal_events_give_their_union():
    """E1 = {u1 > 2}, E2 = {u2 > 2.5}: P(E1 ∪ E2) = 1 − (1 − p1)(1 − p2)."""
    p1, p2 = norm.sf(2.0), norm.sf(2.5)
    exact = 1 - (1 - p1) * (1 - p2)
    prob = HalfSpaces([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [2.0, 2.5])
    est = run(prob, 4000)
    # the estimator's own distribution is known too: N = 2 with probability 2 p1 p2 / (p1 + p2) under q
    sd = (p1 + p2) * math.sqrt(2 * p1 * p2 / (p1 + p2) * (1 - 2 * p1 * p2 / (p1 + p2))) / 2 / math.sqrt(4000)
    assert abs(est.p - exact) < 4 * sd
    # the sample CoV estimates that sd from ~40 samples with N = 2: its own relative error is ≈ 1/(2√40) = 8 %
    assert est.cov == pytest.approx(sd / exact, rel=0.3)
    assert est.lo < exact < est.hi


@pytest.mark.slow
def test_many_correlated_half_spaces_match_plain_monte_carlo():
    """A discretised first passage: b_k = (cos ω t_k, sin ω t_k) of two frequencies — ISEE with 400 samples
    against 2·10⁶ plain samples (both unbiased)."""
    t = np.arange(200) * 0.1
    B = np.column_stack([np.cos(t), np.sin(t), 0.6 * np.cos(1.7 * t), 0.6 * np.sin(1.7 * t)])
    a = np.full(t.size, 3.2)
    est = run(HalfSpaces(B, a), 400, seed=3)
    rng = np.random.default_rng(9)
    hits = 0
    n = 2_000_000
    for _ in range(20):
        u = rng.standard_normal((n // 20, 4))
        hits += int(np.count_nonzero((u @ B.T > a).any(axis=1)))
    p_mc = hits / n
    sd_mc = math.sqrt(p_mc * (1 - p_mc) / n)
    assert abs(est.p - p_mc) < 4 * math.hypot(est.cov * est.p, sd_mc)
    assert est.cov < 0.05                          # the point of ISEE: a few % from a few hundred samples
    single = float(np.max(norm.sf(a / np.linalg.norm(B, axis=1))))
    assert single < est.p < float(np.sum(norm.sf(a / np.linalg.norm(B, axis=1))))


def test_conditional_draw_is_the_truncated_normal():
    b = np.array([1.0, 2.0, -2.0])
    a = 7.5                                        # β = 2.5
    rng = np.random.default_rng(4)
    s = []
    for _ in range(3000):
        u = conditional_normal(rng.standard_normal(3), b, a, 1.0 - rng.random())
        assert b @ u > a * (1 - 1e-12)
        s.append(b @ u / 3.0)
    s = np.array(s)
    cdf = lambda x: 1 - norm.sf(x) / norm.sf(2.5)  # noqa: E731
    assert kstest(s, cdf).pvalue > 0.01


def test_event_choice_follows_the_probabilities_and_is_deterministic():
    lp = np.log(np.array([0.1, 0.0, 0.3, 0.6]) + 1e-300)
    counts = np.zeros(4)
    for U in (np.arange(10000) + 0.5) / 10000:
        e, lpb = select_event(lp, U)
        counts[e] += 1
    np.testing.assert_allclose(counts / 10000, [0.1, 0.0, 0.3, 0.6], atol=2e-4)
    assert lpb == pytest.approx(0.0, abs=1e-12)
    prob = HalfSpaces(np.eye(3), [2.0, 2.0, 3.0])
    a = draw(prob, np.random.default_rng(np.random.SeedSequence(5, spawn_key=(7,))))
    b = draw(prob, np.random.default_rng(np.random.SeedSequence(5, spawn_key=(7,))))
    assert a[1] == b[1] and a[0].tobytes() == b[0].tobytes()
