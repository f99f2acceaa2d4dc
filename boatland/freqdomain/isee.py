r"""Importance sampling of elementary events (ISEE; Au & Beck 2001) for a union of half-spaces in the
space of independent standard-normal variables.

Problem. u ~ N(0, I_d); elementary events :math:`E_e = \{u : b_e^\top u > a_e\}`, e = 1 … n (a response
of a linear system driven by Gaussian noise exceeding its capacity at one time); failure is their union
:math:`F = \bigcup_e E_e` ("first passage within the duration"). Each :math:`P(E_e) = \Phi(-\beta_e)`,
:math:`\beta_e = a_e/|b_e|`, is known in closed form; P(F) is not.

Importance density (Au & Beck 2001, eq. 13–17): a mixture of the conditional densities of the
elementary events, weighted by their probabilities,

.. math::
    q(u) = \sum_e \frac{P(E_e)}{\bar P}\,\frac{\varphi(u)\,1_{E_e}(u)}{P(E_e)} = \frac{\varphi(u)\,N(u)}{\bar P},
    \qquad \bar P = \sum_e P(E_e), \qquad N(u) = \sum_e 1_{E_e}(u),

so the importance weight is :math:`\varphi(u)/q(u) = \bar P/N(u)` on F (and q = 0 outside F). For any
event :math:`G \subseteq F` (e.g. an incident only a nonlinear simulation can decide, run on the same u),

.. math:: \hat P(G) = \frac{1}{n}\sum_{s=1}^{n} \frac{\bar P}{N(u_s)}\,1_G(u_s), \qquad u_s \sim q,

is unbiased; for G = F the weights lie in :math:`[\bar P/n_{events}, \bar P]` and its coefficient of
variation hardly grows as P(F) shrinks (Au & Beck 2001 §4–5). A single event gives :math:`\Phi(-\beta)`
with zero variance.

Drawing from q (eq. 18–19): choose e with probability :math:`P(E_e)/\bar P`; then
:math:`u = z + (s - \hat b_e^\top z)\,\hat b_e` with z ~ N(0, I) and s ~ N(0, 1) conditioned on s > β_e,
:math:`s = -\Phi^{-1}\big(U\,\Phi(-\beta_e)\big)` (in logarithms, so β of 40 and more stay exact).

Randomness: one ``numpy.random.Generator`` per sample, drawn in the order U (event), z (d normals),
U (tail): a sample depends only on its generator, never on which worker draws it.

Reference: Au, S. K. & Beck, J. L. (2001), *First excursion probabilities for linear systems by very
efficient importance sampling*, Probabilistic Engineering Mechanics 16(3), 193–207.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.special import log_ndtr, ndtri_exp

__all__ = ["HalfSpaces", "IseeEstimate", "conditional_normal", "draw", "estimate", "select_event"]


def select_event(log_p: np.ndarray, U: float) -> tuple[int, float]:
    r"""Index e of the flattened ``log_p`` (log P(E_e); −inf for none) chosen with probability
    :math:`P(E_e)/\bar P` by the uniform number ``U`` in [0, 1), and :math:`\log\bar P`.

    The cumulative sum runs in a fixed order (numpy's pairwise-free ``cumsum``), so the choice is the
    same on every machine for the same ``U``."""
    lp = np.ravel(log_p)
    top = float(np.max(lp))
    if not np.isfinite(top):
        raise ValueError("no elementary event has a positive probability")
    w = np.exp(lp - top)
    c = np.cumsum(w)
    e = int(np.searchsorted(c, U * c[-1], side="right"))
    return min(e, lp.size - 1), top + math.log(c[-1])


def conditional_normal(z: np.ndarray, b: np.ndarray, a: float, U: float) -> np.ndarray:
    r"""u ~ N(0, I) conditioned on :math:`b^\top u > a`, from z ~ N(0, I) and U uniform in (0, 1]:
    :math:`u = z + (s - \hat b^\top z)\hat b`, :math:`s = -\Phi^{-1}(U\,\Phi(-a/|b|))`."""
    nb = float(np.sqrt(b @ b))
    bh = b / nb
    s = -float(ndtri_exp(math.log(U) + float(log_ndtr(-a / nb))))
    return z + (s - float(bh @ z)) * bh


class HalfSpaces:
    r"""An explicit union of half-spaces :math:`\{u: B_e u > a_e\}` (small problems and tests).

    Parameters
    ----------
    B : array_like, shape (n, d)
        Rows b_e.
    a : array_like, shape (n,)
        Capacities a_e (> 0).
    """

    def __init__(self, B, a):
        self.B = np.atleast_2d(np.asarray(B, dtype=float))
        self.a = np.asarray(a, dtype=float).reshape(-1)
        if self.a.size != self.B.shape[0] or np.any(self.a <= 0):
            raise ValueError("a must hold one capacity > 0 per row of B")
        self.dim = self.B.shape[1]

    def log_probabilities(self) -> np.ndarray:
        return log_ndtr(-self.a / np.linalg.norm(self.B, axis=1))

    def select(self, U: float) -> tuple[int, float]:
        return select_event(self.log_probabilities(), U)

    def row(self, e: int) -> tuple[np.ndarray, float]:
        return self.B[e], float(self.a[e])

    def count(self, u: np.ndarray, chosen: int | None = None) -> int:
        """N(u); the event ``chosen`` counts even where rounding puts u on its boundary."""
        hit = self.B @ u > self.a
        if chosen is not None:
            hit[chosen] = True
        return int(np.sum(hit))


def draw(problem, rng: np.random.Generator):
    r"""One sample of the ISEE density of ``problem`` (anything with ``dim``, ``select(U)`` — the event
    chosen with probability :math:`P(E_e)/\bar P` by a uniform U, and :math:`\log\bar P` — and
    ``row(e)`` — its :math:`(b_e, a_e)`).

    Returns
    -------
    u : ndarray, shape (d,)
    e : int
        The elementary event it was drawn from (count it in N(u) even if rounding puts u on its boundary).
    log_pbar : float
        :math:`\log\bar P`.
    """
    e, log_pbar = problem.select(rng.random())
    z = rng.standard_normal(problem.dim)
    b, a = problem.row(e)
    return conditional_normal(z, b, a, 1.0 - rng.random()), e, log_pbar


@dataclass(frozen=True)
class IseeEstimate:
    r"""An ISEE estimate of a probability.

    Attributes
    ----------
    p : float
        :math:`\hat P = \bar P\,\overline{1_G/N}`.
    cov : float
        Its coefficient of variation, :math:`\mathrm{sd}(1_G/N)/(\overline{1_G/N}\sqrt n)` (inf with no hit).
    lo, hi : float
        Its ``confidence`` interval, normal approximation :math:`\hat P(1 \mp z\,\delta)` (lower clipped at 0).
    n : int
        Samples.
    hits : int
        Samples in G.
    """

    p: float
    cov: float
    lo: float
    hi: float
    n: int
    hits: int


def estimate(values, log_pbar: float, confidence: float = 0.95) -> IseeEstimate:
    r"""The ISEE estimate from the per-sample values :math:`1_G(u_s)/N(u_s)` (shape (n,)) and
    :math:`\log\bar P`."""
    v = np.asarray(values, dtype=float)
    n = v.size
    if n == 0:
        return IseeEstimate(math.nan, math.nan, math.nan, math.nan, 0, 0)
    mean = float(np.mean(v))
    hits = int(np.count_nonzero(v))
    pbar = math.exp(log_pbar)
    if mean <= 0.0:
        return IseeEstimate(0.0, math.inf, 0.0, math.nan, n, 0)
    sd = float(np.std(v, ddof=1)) if n > 1 else math.inf
    cov = sd / (mean * math.sqrt(n))
    from scipy.special import ndtri               # the normal quantile (scipy.stats.norm.ppf), without scipy.stats

    zq = float(ndtri(0.5 + confidence / 2))
    p = pbar * mean
    return IseeEstimate(p, cov, max(0.0, p * (1 - zq * cov)), p * (1 + zq * cov), n, hits)
