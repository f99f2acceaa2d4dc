r"""The landed vessel's slip margins as linear functions of the sea's standard-normal coefficients.

Before its first slip the vessel on its landing is a linear system (every contact stuck on its
compliant rubber, :func:`boatland.freqdomain.screening.landed_response`, which equals the time domain's
stuck forces within about 1 %: tests/validation/test_hinge_reaction.py). On the grid of a
:class:`~boatland.sea.gaussian.GaussianSea` (component i: ω_i, σ_i, direction θ_i, wave number k_i)
every contact force component and the roll are, at the integrator's steps :math:`t_k = k\Delta t`,

.. math::
    y_j(t_k) = y^0_j + \mathrm{Re}\sum_i C_{ji}\,(u_{2i} - i\,u_{2i+1})\,e^{i\omega_i t_k}, \qquad
    C_{ji} = \hat y_j(\omega_i, \theta_i - \psi)\,\sigma_i\,e^{-ik_i(x_0\cos\theta_i + y_0\sin\theta_i)},

with :math:`\hat y_j` the transfer function per unit wave amplitude at the reference point (its start
position :math:`(x_0, y_0)`, heading ψ) and :math:`y^0_j` the static preload under the thrust. The
responses j are, per contact c, the normal force :math:`f_n` and the tangential force
:math:`f_t = (f_v, f_h)` along :math:`t_v = e_z` and :math:`t_h = e_z\times n_c` — the axes and signs of
the time-domain contact (:mod:`boatland.contact.fender`) — and then roll. This is the steady state: the
events are taken only in a **window** of steps after the time domain's start-up (thrust, wave ramp) has
settled (:mod:`boatland.campaign.isee` adds a settling time before the access).

Slip. The time domain slips contact c when the rubber's tangential force leaves the friction circle,
:math:`|f_t| > \mu_s f_n`. For unit directions :math:`d_j = (\cos\phi_j, \sin\phi_j)` in the contact
plane, :math:`|f_t| > \mu f_n \iff \exists d: d\cdot f_t > \mu f_n`: the union over *all* directions is
the circle. With M directions :math:`\phi_j = 2\pi j/M` each margin

.. math:: g_{j,c}(t) = d_j\cdot f_t - \mu' f_n = \zeta_{j,c}(t) - a_{j,c}, \qquad
          a_{j,c} = \mu' f^0_n - d_j\cdot f^0_t ,

is a half-space in u. Their union is the outside of a regular M-gon. With μ' = μ (M = 4: the square of
the screening's down/up/left/right margins, :mod:`boatland.freqdomain.screening`) the M-gon circumscribes
the circle and the union misses slips towards the diagonals; with :math:`\mu' = \mu\cos(\pi/M)` it is
inscribed, and the union **contains** the circle's event exactly (every :math:`f_t` lies within π/M of
some d_j, so :math:`d_j\cdot f_t - \mu' f_n \ge \cos(\pi/M)\,(|f_t| - \mu f_n)`; for :math:`f_n < 0` every
margin with :math:`d_j\cdot f_t \ge 0` is exceeded). Without sideways friction the directions are up and
down and μ' = μ. Roll: :math:`\pm\phi > \theta_{max}`.

Sampling domain D of the ISEE estimator (:mod:`boatland.freqdomain.isee`): the union over the window's
steps of :math:`\{\zeta_r > a_r - \kappa s_r\}`, r the inscribed M-gon's margins and roll ±, s_r the
margin's standard deviation — the guard κ (in standard deviations) keeps the time domain's slips inside D
although its stuck forces differ slightly from the linear ones. Measured on ctv24 over 30 trials per
sea (|g_TD − g_lin|/s_r where g_lin > −2.5 s_r, before the first slip): beam seas Tp 4–7 s at most
0.17 from 20 s after the waves reach full height on and 0.10–0.15 later (0.9 at the end of the wave
ramp: the ramp sets the lightly damped landed roll modes, T ≈ 2.5–2.7 s, ringing), head seas below
0.01. The default κ = 0.3 is twice the largest; the window begins 30 s after the ramp.

Indicators of one sample (:meth:`LandedMargins.indicators`): N(u) (elementary events of D exceeded),
the linear first slip on the circle at μ (exact, per step), on the screening's square at μ, contact
loss (:math:`f_n < 0`), roll beyond θ_max.

Memory. The matrix mapping u (2N) to every margin at every step (30 min at Δt = 0.05 s with
N ≈ 1 200 and 34 margins: 36 000 × 34 rows of 2 400, 24 GB) is never formed: the series of one u
are one inverse FFT of length n_fft per response (:func:`boatland.sea.gaussian.grid_series`;
O(n_fft log n_fft) each, 7 series), a row is formed when the sampler draws from its event
(:meth:`LandedMargins.row`, O(N)), and rows for checks are streamed in blocks of steps
(:meth:`LandedMargins.rows`).

References: Au & Beck (2001), *First excursion probabilities for linear systems by very efficient
importance sampling*, Probabilistic Engineering Mechanics 16(3) 193–207; Grøtting (2015), *Small Water
Plane Area Solutions for Access of Offshore Wind Turbines*, MSc thesis, NTNU (§3.2.1, §3.4: the
margins); Ferreira González (2023), *Development of a Numerical Approach for the Simulation of
Boatlanding Maneuvers*, TU Hamburg (the contact); Rice (1945), *Mathematical analysis of random noise*,
Bell System Technical Journal 24(1) 46–156 (the upper bound).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np
from scipy.special import log_ndtr

from boatland.errors import BoatlandInputError
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import landed_response
from boatland.sea.gaussian import GaussianSea, grid_series
from boatland.vessel.database import HydroDB

__all__ = ["DIRECTIONS_DEFAULT", "KAPPA_DEFAULT", "Indicators", "LandedMargins", "landed_margins"]

#: Slip directions per contact in the contact plane (the inscribed M-gon of the module docstring). The
#: sampling domain's excess over the circle's event falls with M (the share of ISEE samples that slip, at
#: p ≈ 1e-3 per 30 min on ctv24: M = 8: 1–4 %, 16: 11–12 %, 32: 18–20 %, then the guard κ dominates), so 32
#: halves the samples of 16 for the same CoV (bench/README.md, "ISEE").
DIRECTIONS_DEFAULT = 32
#: Guard κ of the sampling domain, in standard deviations of each margin (module docstring).
KAPPA_DEFAULT = 0.3


@dataclass(frozen=True)
class Indicators:
    """What one sample's linear series show (:meth:`LandedMargins.indicators`).

    Attributes
    ----------
    n_exceeded : int
        N(u): elementary events of the sampling domain D exceeded (margin × step).
    first_slip : bool
        Linear first slip, circle: :math:`|f_t| > \\mu f_n` at some step (any contact).
    square : bool
        The screening's four margins at μ exceeded at some step (down/up/left/right).
    contact_loss : bool
        :math:`f_n < 0` at some step.
    roll : bool
        :math:`|\\phi| > \\theta_{max}` at some step.
    t_first_slip : float
        Time [s] of the first circle exceedance (NaN: none).
    """

    n_exceeded: int
    first_slip: bool
    square: bool
    contact_loss: bool
    roll: bool
    t_first_slip: float

    @property
    def first_incident(self) -> bool:
        return self.first_slip or self.contact_loss or self.roll


@dataclass(frozen=True, eq=False)
class LandedMargins:
    r"""Contact forces and roll of the landed vessel as linear functions of u, and the ISEE problem of
    the sampling domain D (module docstring). Build with :func:`landed_margins`.

    Attributes
    ----------
    C : ndarray of complex, shape (3 Np + 1, N)
        Coefficients of f_n, f_v, f_h of each contact (contact-major), then roll [N, rad] per unit u.
    static : ndarray, shape (3 Np + 1,)
        Static preload of the same responses.
    m, omega : ndarray, shape (N,)
        Grid index and frequency of each component (ω_i = (m_i + ½)Δω); ``n_fft``, ``dt`` the grid.
    steps : ndarray of int, shape (n_t,)
        The integrator steps k of the elementary events (the window).
    mu, roll_limit : float
        μ_s and θ_max [rad].
    phi : ndarray, shape (M,)
        Slip directions in the contact plane (from t_v towards t_h) [rad].
    kappa : float
        Guard κ.
    E : ndarray of complex, shape (R, N)
        Coefficients of the R margins ζ_r (each contact's M directions at μ cos(π/M), contact-major, then
        roll + and −); ``a`` (R,) their capacities, ``s`` (R,) their standard deviations.
    names : tuple of str
        ``"c0 d3"`` … ``"roll+"``, ``"roll-"``.
    """

    C: np.ndarray
    static: np.ndarray
    m: np.ndarray
    omega: np.ndarray
    n_fft: int
    dt: float
    steps: np.ndarray
    mu: float
    roll_limit: float
    phi: np.ndarray
    sideways: bool
    kappa: float
    E: np.ndarray
    a: np.ndarray
    s: np.ndarray
    names: tuple

    @property
    def n_points(self) -> int:
        return (self.C.shape[0] - 1) // 3

    def scaled(self, f: float) -> "LandedMargins":
        """The same landing in the same sea shape with every wave amplitude times ``f`` (Hs f Hs): the
        dynamic coefficients scale, the preload does not."""
        import dataclasses

        return dataclasses.replace(self, C=self.C * f, E=self.E * f, s=self.s * f)

    @property
    def dim(self) -> int:
        """Number of coefficients u, 2N."""
        return 2 * self.C.shape[1]

    @property
    def n_steps(self) -> int:
        return int(self.steps.size)

    @property
    def duration(self) -> float:
        """(n_t − 1) Δt [s]: the window."""
        return (self.n_steps - 1) * self.dt

    @property
    def mu_cover(self) -> float:
        """μ cos(π/M): the M-gon inscribed in the friction circle (μ without sideways friction)."""
        return self.mu * (math.cos(math.pi / self.phi.size) if self.sideways else 1.0)

    @property
    def beta(self) -> np.ndarray:
        """Reliability index of each margin of D at every step, :math:`a_r/s_r - \\kappa` (R,)."""
        with np.errstate(divide="ignore"):
            return np.where(self.s > 0, self.a / self.s, np.inf) - self.kappa

    @property
    def static_slip(self) -> bool:
        """The preload alone slips or rolls past the limit (μ, θ_max): every access fails."""
        y0 = self.static
        npt = self.n_points
        ft = np.hypot(y0[1:3 * npt:3], y0[2:3 * npt:3]) if self.sideways else np.abs(y0[1:3 * npt:3])
        return bool(np.any(ft >= self.mu * y0[0:3 * npt:3]) or abs(y0[-1]) >= self.roll_limit)

    # ------------------------------------------------------------------ elementary events
    def log_probabilities(self) -> np.ndarray:
        r""":math:`\log P(E_{r,k}) = \log\Phi(-\beta_r)`, the same at every step: shape (R,) (multiplicity
        n_t each)."""
        return log_ndtr(-self.beta)

    def select(self, U: float) -> tuple[int, float]:
        r"""The flattened event e = r n_t + k chosen with probability :math:`P(E_{r,k})/\bar P` by one uniform
        number U in [0, 1) — margin r by the cumulative sum of :math:`\Phi(-\beta_r)`, the step uniformly
        within it — and :math:`\log\bar P = \log(n_t\sum_r\Phi(-\beta_r))`."""
        lp = self.log_probabilities()
        top = float(np.max(lp))
        if not np.isfinite(top):
            raise ValueError("no margin of the sampling domain can be exceeded")
        w = np.exp(lp - top)
        c = np.cumsum(w)
        x = U * c[-1]
        r = min(int(np.searchsorted(c, x, side="right")), lp.size - 1)
        frac = (x - (c[r - 1] if r else 0.0)) / w[r]
        k = min(int(frac * self.n_steps), self.n_steps - 1)
        return r * self.n_steps + k, top + math.log(c[-1]) + math.log(self.n_steps)

    def row(self, e: int) -> tuple[np.ndarray, float]:
        r"""Row :math:`b_{r,k}` (2N,) of the flattened event e = r n_t + k and its capacity in D,
        :math:`a_r - \kappa s_r` (the event is :math:`b^\top u > a_r - \kappa s_r`)."""
        r, k = divmod(int(e), self.n_steps)
        h = self.E[r] * np.exp(1j * self.omega * (self.steps[k] * self.dt))
        b = np.empty(self.dim)
        b[0::2] = h.real
        b[1::2] = h.imag
        return b, float(self.a[r] - self.kappa * self.s[r])

    def rows(self, r: int, k0: int, k1: int) -> np.ndarray:
        """Rows of margin r at window steps k0 … k1−1 (indices into :attr:`steps`), shape (k1−k0, 2N): the
        matrix streamed in blocks (for checks; the sampler never needs it)."""
        t = self.steps[k0:k1] * self.dt
        h = self.E[r][None, :] * np.exp(1j * np.outer(t, self.omega))
        out = np.empty((k1 - k0, self.dim))
        out[:, 0::2] = h.real
        out[:, 1::2] = h.imag
        return out

    # ------------------------------------------------------------------ one sample
    def series(self, u: np.ndarray) -> np.ndarray:
        r"""f_n, f_v, f_h per contact and roll at :attr:`steps` for coefficients ``u``, static included,
        shape (3 Np + 1, n_t): one inverse FFT per response."""
        A = np.asarray(u, dtype=float)
        A = A[0::2] - 1j * A[1::2]
        c = np.zeros((self.C.shape[0], self.n_fft), dtype=complex)
        for j in range(self.C.shape[0]):
            np.add.at(c[j], self.m, self.C[j] * A)
        n = int(self.steps[-1]) + 1
        return grid_series(c, self.n_fft, n)[:, self.steps] + self.static[:, None]

    def margins(self, y: np.ndarray) -> np.ndarray:
        """D's margins (R, n_t) of the series ``y`` (:meth:`series`): :math:`\\zeta_r - a_r + \\kappa s_r`,
        > 0 where an elementary event is exceeded."""
        npt = self.n_points
        fn, fv, fh = y[0:3 * npt:3], y[1:3 * npt:3], y[2:3 * npt:3]
        cphi, sphi = np.cos(self.phi), np.sin(self.phi)
        g = (cphi[None, :, None] * fv[:, None, :] + sphi[None, :, None] * fh[:, None, :]
             - self.mu_cover * fn[:, None, :]).reshape(-1, y.shape[1])
        g = np.concatenate([g, (y[-1] - self.roll_limit)[None], (-y[-1] - self.roll_limit)[None]])
        return g + (self.kappa * self.s)[:, None]

    def count(self, u: np.ndarray, chosen: int | None = None) -> int:
        """N(u): elementary events of D exceeded (:meth:`indicators`)."""
        return self.indicators(u, chosen).n_exceeded

    def indicators(self, u: np.ndarray, chosen: int | None = None) -> Indicators:
        """Everything the linear model says about one sample (:class:`Indicators`). ``chosen``: the
        flattened event the sample was drawn from — counted even where rounding puts u on its boundary."""
        y = self.series(u)
        npt = self.n_points
        n_hit = _count_exceeded(y, npt, np.cos(self.phi), np.sin(self.phi), self.mu_cover, self.roll_limit,
                                self.kappa * self.s, -1 if chosen is None else int(chosen))
        fn, fv, fh = y[0:3 * npt:3], y[1:3 * npt:3], y[2:3 * npt:3]
        ft = np.hypot(fv, fh) if self.sideways else np.abs(fv)
        any_circle = (ft > self.mu * fn).any(axis=0)
        sq = np.maximum(np.abs(fv), np.abs(fh) if self.sideways else 0.0) > self.mu * fn
        first = int(np.argmax(any_circle)) if any_circle.any() else -1
        return Indicators(n_exceeded=n_hit, first_slip=bool(any_circle.any()),
                          square=bool(sq.any()), contact_loss=bool(np.any(fn < 0)),
                          roll=bool(np.any(np.abs(y[-1]) > self.roll_limit)),
                          t_first_slip=float(self.steps[first] * self.dt) if first >= 0 else math.nan)

    # ------------------------------------------------------------------ bounds
    def spectral_moments(self, coef: np.ndarray) -> np.ndarray:
        """m₀, m₁, m₂ (…, 3) of responses with coefficients ``coef`` (…, N)."""
        p = np.abs(coef) ** 2
        return np.stack([p.sum(-1), (p * self.omega).sum(-1), (p * self.omega ** 2).sum(-1)], axis=-1)

    def largest_event_probability(self) -> float:
        r"""Lower bound of the linear first incident (circle slip or roll beyond θ_max): the largest
        single elementary probability :math:`\max_r\Phi(-a_r/s_r)` of the M directions at μ (each a
        subset of the circle's event) and of roll beyond ±θ_max."""
        E, a = margin_events(self.C, self.static, self.phi, self.mu, self.roll_limit)
        s = np.sqrt(self.spectral_moments(E)[:, 0])
        return float(np.exp(np.max(log_ndtr(-a / s))))

    def rice_bound(self) -> float:
        r"""Upper bound of the linear first incident (circle slip or roll beyond θ_max) in the window:

        .. math:: P \le \sum_r\Big[\Phi(-\beta_r) + \nu_r T\Big], \qquad
                  \nu_r = \frac{1}{2\pi}\sqrt{m_{2,r}/m_{0,r}}\,e^{-\beta_r^2/2}

        — Rice's (1945) mean number of up-crossings of each margin over the window T plus the chance
        that it starts above (every first passage in continuous time is one or the other, and the
        window's steps are instants of it), for the inscribed M-gon at :math:`\mu\cos(\pi/M)` (whose union
        contains the circle's event) and roll ±θ_max, without the guard.
        """
        E, a = margin_events(self.C, self.static, self.phi, self.mu_cover, self.roll_limit)
        mom = self.spectral_moments(E)
        beta = a / np.sqrt(mom[:, 0])
        nu = np.sqrt(mom[:, 2] / mom[:, 0]) / (2 * math.pi) * np.exp(-0.5 * beta ** 2)
        return float(np.sum(np.exp(log_ndtr(-beta)) + nu * self.duration))


@numba.njit(cache=True)
def _count_exceeded(y, npt, cphi, sphi, mu_d, roll_lim, guard, chosen):
    """N(u) of :meth:`LandedMargins.indicators`: the margins of :meth:`LandedMargins.margins` > 0 counted
    without forming them (the same operations in the same order, so the same count), the ``chosen``
    flattened event (−1: none) counted whatever its rounding."""
    n_t = y.shape[1]
    M = cphi.shape[0]
    count = 0
    for c in range(npt):
        for d in range(M):
            r = c * M + d
            for k in range(n_t):
                g = (cphi[d] * y[3 * c + 1, k] + sphi[d] * y[3 * c + 2, k] - mu_d * y[3 * c, k]) + guard[r]
                if g > 0 or r * n_t + k == chosen:
                    count += 1
    base = npt * M
    for k in range(n_t):
        roll = y[y.shape[0] - 1, k]
        if ((roll - roll_lim) + guard[base] > 0) or base * n_t + k == chosen:
            count += 1
        if ((-roll - roll_lim) + guard[base + 1] > 0) or (base + 1) * n_t + k == chosen:
            count += 1
    return count


def margin_events(C, static, phi, mu_d, roll_lim):
    """(coefficients (R, N), capacities (R,)) of the directions ``phi`` at μ_d and roll ±``roll_lim``."""
    npt = (C.shape[0] - 1) // 3
    cphi, sphi = np.cos(phi), np.sin(phi)
    E, a = [], []
    for c in range(npt):
        E.append(cphi[:, None] * C[3 * c + 1][None] + sphi[:, None] * C[3 * c + 2][None] - mu_d * C[3 * c][None])
        a.append(mu_d * static[3 * c] - cphi * static[3 * c + 1] - sphi * static[3 * c + 2])
    E.append(np.stack([C[-1], -C[-1]]))
    a.append(np.array([roll_lim - static[-1], roll_lim + static[-1]]))
    return np.concatenate(E), np.concatenate(a)


def landed_margins(db: HydroDB, setup: LandingSetup, sea: GaussianSea, *, x0: float, y0: float, first_step: int,
                   last_step: int | None = None, kappa: float = KAPPA_DEFAULT,
                   directions: int = DIRECTIONS_DEFAULT) -> LandedMargins:
    r"""The landed vessel's responses on the grid of ``sea`` as linear functions of its u, and the ISEE
    problem of the steps ``first_step`` … ``last_step`` (module docstring).

    Parameters
    ----------
    db : HydroDB
    setup : LandingSetup
        The landing as the time domain runs it (:meth:`LandingSetup.from_scenario`): contacts, μ_s, thrust,
        heading ψ, roll limit, the pile's scattered wave.
    sea : GaussianSea
        The grid (its u is not used).
    x0, y0 : float
        Global start position of the reference point [m] (the excitation's phase reference).
    first_step, last_step : int
        The window of the elementary events (default last: the sea's last step), in the full sea.
    kappa : float
        Guard κ ≥ 0 of the sampling domain [standard deviations].
    directions : int
        M slip directions per contact (≥ 3; without sideways friction: up and down).

    Raises
    ------
    BoatlandInputError
        Bad ``directions``, ``kappa`` or window.
    """
    if not isinstance(directions, (int, np.integer)) or isinstance(directions, bool) or directions < 3:
        raise BoatlandInputError(f"directions = {directions!r}: give an integer ≥ 3 (slip directions per contact)")
    if not (math.isfinite(kappa) and 0.0 <= kappa <= 3.0):
        raise BoatlandInputError(f"kappa = {kappa!r}: give a guard of 0 … 3 standard deviations")
    last = sea.n_steps if last_step is None else int(last_step)
    if not 0 <= int(first_step) <= last <= sea.n_steps:
        raise BoatlandInputError(f"window of steps {first_step} … {last} is not within the sea's 0 … {sea.n_steps}")
    npt = setup.n_points
    C = np.zeros((3 * npt + 1, sea.size), dtype=complex)
    static = None
    for p in np.unique(sea.part):
        idx = np.flatnonzero(sea.part == p)
        w = sea.omega[idx]
        inband = w <= db.omega[-1]                     # above the band the time domain has no excitation
        theta = float(sea.theta[idx[0]])
        beta = (math.degrees(theta) - setup.heading_deg) % 360.0
        r = landed_response(db, setup, w[inband], [beta])
        cc = r.contact_components()[:, 0]              # (Nw, Np, 3): f_n, f_v, f_h
        phase = sea.sigma[idx][inband] * np.exp(-1j * sea.k[idx][inband] * (x0 * math.cos(theta) + y0 * math.sin(theta)))
        sel = idx[inband]
        C[0:3 * npt, sel] = (cc.reshape(cc.shape[0], 3 * npt) * phase[:, None]).T
        C[-1, sel] = r.x[:, 0, 3] * phase
        if static is None:
            static = np.concatenate([r.contact_components(static=True).reshape(-1), [r.x_static[3]]])
    phi = np.arange(directions) * 2 * math.pi / directions if setup.sideways else np.array([0.0, math.pi])
    roll_limit = math.radians(setup.roll_limit_deg)
    mu_c = setup.mu * (math.cos(math.pi / phi.size) if setup.sideways else 1.0)
    E, a = margin_events(C, static, phi, mu_c, roll_limit)
    names = tuple(f"c{c} d{j}" for c in range(npt) for j in range(phi.size)) + ("roll+", "roll-")
    return LandedMargins(C=C, static=static, m=np.asarray(sea.m), omega=np.asarray(sea.omega), n_fft=sea.n_fft,
                         dt=sea.dt, steps=np.arange(int(first_step), last + 1), mu=setup.mu, roll_limit=roll_limit,
                         phi=phi, sideways=setup.sideways, kappa=float(kappa), E=E, a=a,
                         s=np.sqrt(np.sum(np.abs(E) ** 2, axis=1)), names=names)
