r"""Wu (2014) slip screening in the frequency domain (Grøtting 2015 §3.2.1, §3.4): slip margins, their
statistics in a wave spectrum, the incident probability, limiting Hs per (Tp, direction).

The vessel is held on its landing (:func:`boatland.freqdomain.rao.hinged_rao`). **Each contact c is
checked on its own**: with its force on the vessel :math:`J_c = J^0_c + \mathrm{Re}\{\hat J_c e^{i\omega t}\}`
(static preload plus waves), its normal :math:`n_c` (landing → vessel) and, for each slip mode m, the
direction :math:`d_{m,c}` of the force the landing must supply,

=========  ======================  =====================================================
mode       :math:`d_{m,c}`          the fender slips ... when the needed force along d
=========  ======================  =====================================================
down       :math:`+e_z`             ... upwards exceeds friction (waves push the bow down)
up         :math:`-e_z`             ... downwards exceeds friction
left       :math:`-s_c`             ... to starboard exceeds friction (slip to port)
right      :math:`+s_c`             ... to port exceeds friction (slip to starboard)
=========  ======================  =====================================================

with :math:`s_c = n_c \times e_z` (port for a bow-on landing), the contact holds while

.. math:: d_{m,c}^\top J_c(t) < \mu\,n_c^\top J_c(t)
   \quad\Longleftrightarrow\quad
   \zeta_{m,c}(t) = (d_{m,c} - \mu n_c)^\top \tilde J_c(t) < a_{m,c} = \mu\, n_c^\top J^0_c - d_{m,c}^\top J^0_c ,

Grøtting 2015 eq. 3.13–3.24 and eq. 3.64–3.75 of the improved variant. Friction is isotropic (a circle,
:math:`|J_t| < \mu N`): where the static load has a tangential part across a mode — a current or wind
pressing the tubes sideways across the vertical modes, the push's own vertical share (ctv27: 9.7 kN per
tube) across the side modes — its direction is tilted onto the circle's tangent at that load
(:func:`slip_directions`); without one it is the table's. Grøtting's margins are for the summed force of
a single hinge; summed over two contacts the opposite vertical forces of a roll or yaw couple would
cancel, so here every contact has its own four margins. The margins are zero-mean Gaussian with
transfer functions :math:`H_{m,c} = (d_{m,c} - \mu n_c)^\top \hat J_c` (eq. 3.25–3.28, 3.76–3.79).

Two hinge models (``method``):

``"wu"`` — Grøtting 2015 §3.2.1: rigid hinge at the points, the thrust along the *global* x axis, so
  it only sets the static normal :math:`N^0_c = F_b / N_p` (no dynamics of its own).
``"improved"`` (default) — §3.4: the thrust follows the vessel's x axis; :func:`hinged_rao` solves the
  static preload (the :math:`F_{zc}` of eq. 3.56–3.61 for any landing) and linearises about it, which
  contains the follower forces :math:`F_b\theta_5, F_b\theta_6` of eq. 3.62–3.63; each contact is the
  time domain's: the normal spring–damper and the rubber's shear spring–damper (or the rigid stick),
  and the pile's scattered wave when the time domain applies it. The stuck contact forces of the time
  domain equal these (tests/validation/test_hinge_reaction.py).

In a spectrum :math:`S(\omega)` (long-crested, direction β) the spectral moments of a response with
transfer function H are :math:`m_k = \int_0^\infty \omega^k |H(\omega,\beta)|^2 S(\omega)\,d\omega`
(σ² = m₀, eq. 3.29–3.32, 3.35; a sum of wave systems adds their integrals, eq. 3.41–3.45). All are
proportional to :math:`H_s^2` for a fixed spectral shape — the limiting Hs solves a 1-D monotone
equation.

The statistics of the margins — Rayleigh peaks, Rice or Vanmarcke up-crossing rates — and the
limiting Hs are :mod:`boatland.freqdomain.statistics`; the landing as the screening sees it is
:class:`boatland.freqdomain.landing.LandingSetup`.

Conventions: β relative to the vessel, direction of travel (180° head seas); exp(+iωt); SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.quadratic_drag import QuadraticDrag
from boatland.freqdomain.statistics import (SlowSwing, ACCEPT_PRESETS, ACCESS_DURATION, DEFAULT_STATISTICS, HS_MAX, STATISTICS, LimitTable,
                                            accept_probability, correlation_matrix, distinct_events,
                                            incident_probability, limiting_hs, response_correlation, response_names,
                                            spectral_moments, unit_spectra)
from boatland.scenario.schema import SHEAR_DAMPING_RATIO_DEFAULT, SHEAR_STIFFNESS_DEFAULT
from boatland.sea.spectra import SpectrumPart
from boatland.vessel.database import HydroDB
from boatland.waves.spectra import spreading_cos2s

__all__ = ["METHODS", "SHEAR_FACTORS", "SeaResponse", "ShearSweep", "SlipTransfer", "default_omega", "gust_moments", "landed_response",
           "margin_rows", "screening_grid", "sea_response", "shear_sweep", "slip_directions", "slip_transfer", "slow_swing"]

METHODS = ("improved", "wu")


# --------------------------------------------------------------------------------------- transfer functions
@dataclass(frozen=True, eq=False)
class SlipTransfer:
    r"""Slip-margin and roll transfer functions of the landed vessel, per unit wave amplitude.

    Attributes
    ----------
    omega : ndarray, shape (Nw,)
    beta_deg : ndarray, shape (Nβ,)
        Relative wave directions [deg].
    H : ndarray of complex, shape (Nw, Nβ, 4 Np + 1)
        Margins ζ_{m,c} of :data:`MODES` for each contact (contact-major: contact 0's four, then
        contact 1's, …) [N/m], then roll [rad/m].
    capacity : ndarray, shape (4 Np + 1,)
        Levels a_{m,c} = μ n_cᵀJ⁰_c − d_{m,c}ᵀJ⁰_c of the margins [N], then θ_max [rad].
    names : tuple of str
        What each response is: ``"down 0"`` … ``"right 1"``, ``"roll"``.
    J_static : ndarray, shape (Np, 3)
        Static contact force on the vessel at each contact [N]; ``N_static`` (Np,) its normal part.
    method : str
    setup : LandingSetup
    background : SlowSwing or None
        The margins' and roll's part that does not grow with the waves: the swing in the wind's gusts
        (:func:`gust_moments`); None without.
    motions : ndarray of complex, shape (Nw, Nβ, 6), or None
        The landed vessel's motions per unit wave amplitude (for the hull drag's linearisation).
    directions : ndarray, shape (Np, 4, 3), or None
        Each contact's rows :math:`d_{m,c} - \mu n_c` that make its margins of its force.
    """

    omega: np.ndarray
    beta_deg: np.ndarray
    H: np.ndarray
    capacity: np.ndarray
    names: tuple[str, ...]
    J_static: np.ndarray
    N_static: np.ndarray
    method: str
    setup: LandingSetup
    background: SlowSwing | None = None
    motions: np.ndarray | None = None
    directions: np.ndarray | None = None

    def drag_tails(self, db: HydroDB, weights, sigma=None, *, together: bool = False) -> np.ndarray | None:
        r"""Skewness and excess kurtosis (K, Nβ, R, 2) of the responses from the hull drag's second-order part
        (:class:`boatland.freqdomain.quadratic_drag.QuadraticDrag`) in K seas of variance weights ``weights``
        (K, Nβ, Nw) = S(ω) dω per relative direction, each direction a sea of its own — or, ``together``, the
        directions one short-crested sea (K, 1, R, 2); ``sigma`` the strips' velocity σ the drag is linearised
        at. None without a current's cross-flow drag, or for the "wu" hinge."""
        if self.method == "wu" or self.directions is None:
            return None
        qd = QuadraticDrag.of(db, self.setup, self.omega, self.directions, sigma=sigma)
        if qd is None:
            return None
        W = np.asarray(weights, dtype=float)
        if together:
            return np.stack([qd.tails(Wk, self.H, self.motions)[None] for Wk in W])
        return np.stack([np.stack([qd.tails(Wk[b:b + 1], self.H[:, b:b + 1], self.motions[:, b:b + 1])
                                   for b in range(self.beta_deg.size)]) for Wk in W])


def slip_directions(n: np.ndarray, J0: np.ndarray | None = None, mu: float = 0.0) -> np.ndarray:
    r"""The four modes' directions :math:`d_{m,c}` (module docstring) of a contact with normal ``n``, tilted
    onto the friction circle by the static tangential load across each mode.

    The time domain's friction is isotropic: the contact holds while :math:`|J_t| < \mu\,n^\top J`, a circle
    in the tangent plane, not the square of four independent margins. Where the static load :math:`J^0`
    has a tangential part :math:`F_p = p_m^\top J^0` across mode m (p_m the other tangent; a current or
    wind on the beam loads the tubes sideways), the mode's slip happens where the circle is reached at
    that side load: the margin is linearised at that point of the circle, the tangent line
    :math:`d_{m,c} = \cos\theta\,e_m + \sin\theta\,p_m`, :math:`\sin\theta = F_p / (\mu N^0)` (the first-order
    reliability method's tangent at the design point, Madsen, Krenk & Lind 1986, *Methods of Structural
    Safety*, §5; here the design point's side load is the static one). Without a load across the mode
    :math:`d_{m,c} = e_m`, as in Grøtting 2015 eq. 3.13–3.24. For ctv27 with a 1 m/s beam current
    (Tp 7 s, bow-quartering seas, H_s 0.39 m) the tilt moves the screening's P per 30 min from 0.372 to 0.428,
    where the exact outcrossing rate of the Gaussian forces through the friction cone gives 0.42; without
    current or wind nothing that governs moves (ctv27's side modes lose 2.6 % of their capacity to the push's
    vertical share; they govern nowhere).
    """
    s = np.cross(n, [0.0, 0.0, 1.0])
    s /= np.linalg.norm(s)
    ez = np.array([0.0, 0.0, 1.0])
    base = np.stack([ez, -ez, -s, s])  # down, up, left (to port), right (to starboard)
    if J0 is None:
        return base
    cap = mu * float(n @ J0)
    across = np.stack([s, s, ez, ez])  # the other tangent of each mode
    out = base.copy()
    for m in range(4):
        f_p = float(across[m] @ J0)
        if f_p != 0.0 and cap > 0.0:
            sin = max(-1.0, min(1.0, f_p / cap))
            out[m] = math.sqrt(1.0 - sin * sin) * base[m] + sin * across[m]
    return out


def default_omega(db: HydroDB, n: int = 600) -> np.ndarray:
    """Frequency grid of the screening: ``n`` points, 0.05 rad/s (or the band's start) … the band's top."""
    return np.linspace(max(0.05, float(db.omega[0])), float(db.omega[-1]), n)


def landed_response(db: HydroDB, setup: LandingSetup, omega, beta_deg, method: str = "improved", loads=None):
    """The landed vessel's response as the screening takes it (:meth:`LandingSetup.response`)."""
    return setup.response(db, omega, beta_deg, method, loads)


def slip_transfer(db: HydroDB, setup: LandingSetup, *, omega=None, beta_deg=None, method: str = "improved",
                  mu: float | None = None, thrust: float | None = None) -> SlipTransfer:
    r"""Transfer functions of every contact's four slip margins and of roll (Grøtting 2015 eq. 3.25–3.28,
    3.34, 3.76–3.79, per contact).

    .. math:: H_{m,c}(\omega,\beta) = (d_{m,c} - \mu n_c)^\top \hat J_c(\omega,\beta), \qquad
              a_{m,c} = \mu\,n_c^\top J^0_c - d_{m,c}^\top J^0_c

    Parameters
    ----------
    db : HydroDB
        The vessel (with ``M``).
    setup : LandingSetup
    omega : array_like, optional
        Frequencies [rad/s]; default :func:`default_omega`.
    beta_deg : array_like, optional
        Relative wave directions [deg]; default 0, 45, …, 315.
    method : {"improved", "wu"}
        Hinge model (module docstring).
    mu, thrust : float, optional
        Override the setup's μ and F_b.

    Returns
    -------
    SlipTransfer
    """
    if method not in METHODS:
        raise BoatlandInputError(f"method {method!r}: use one of {', '.join(METHODS)}")
    if mu is not None or thrust is not None:
        setup = setup.replace(mu=setup.mu if mu is None else mu, thrust=setup.thrust if thrust is None else thrust)
    w = default_omega(db) if omega is None else np.asarray(omega, dtype=float)
    b = np.arange(0.0, 360.0, 45.0) if beta_deg is None else np.atleast_1d(np.asarray(beta_deg, dtype=float))
    r = landed_response(db, setup, w, b, method)
    n_p = setup.n_points
    J0 = (-setup.thrust / n_p * np.tile([1.0, 0.0, 0.0], (n_p, 1))) if method == "wu" else r.J_static
    rows, cap = margin_rows(setup, J0, tilt=method != "wu")
    H = np.concatenate([r.J[:, :, c] @ rows[c].T for c in range(n_p)] + [r.x[..., 3:4]], axis=-1)
    background = slow_swing(db, setup, J0) if method != "wu" else None
    return SlipTransfer(omega=w, beta_deg=b, H=H, capacity=cap, names=response_names(cap.size), J_static=J0,
                        N_static=np.einsum("pk,pk->p", setup.normals, J0), method=method, setup=setup,
                        background=background, motions=r.x, directions=rows)


def margin_rows(setup: LandingSetup, J0: np.ndarray, tilt: bool = True) -> tuple[np.ndarray, np.ndarray]:
    r"""Each contact's rows :math:`d_{m,c} - \mu n_c` (Np, 4, 3) that make its four margins of its force, and the
    capacities (4 Np + 1,): :math:`a_{m,c} = \mu\,n_c^\top J^0_c - d_{m,c}^\top J^0_c`, then θ_max [rad] (module
    docstring); ``tilt``: the directions tilted onto the friction circle by the static load
    (:func:`slip_directions`), else Grøtting's table (the "wu" hinge)."""
    rows, cap = [], []
    for c in range(setup.n_points):
        n = setup.normals[c]
        Dc = slip_directions(n, J0[c], setup.mu) if tilt else slip_directions(n)
        rows.append(Dc - setup.mu * n)
        cap.append(setup.mu * float(n @ J0[c]) - Dc @ J0[c])
    return np.stack(rows), np.concatenate(cap + [[math.radians(setup.roll_limit_deg)]])


def slow_swing(db: HydroDB, setup: LandingSetup, J0: np.ndarray) -> SlowSwing | None:
    """The margins' and roll's swing in the wind's gusts (:func:`gust_moments`, with its correlation and the
    setup's linear share of damping); None without gusts."""
    if setup.steady is None or setup.steady.gust_pattern is None:
        return None
    mom, cor = gust_moments(db, setup, J0, correlation=True)
    return SlowSwing(mom, setup.steady.linear_share, cor)


def gust_moments(db: HydroDB, setup: LandingSetup, J0: np.ndarray, correlation: bool = False):
    r"""Spectral moments (R, 3) of every margin and of roll answering the gusts,
    :math:`m_k = \int \omega^k |H_g(\omega)|^2 S_g(\omega)\,d\omega`, with :math:`H_g` the margins per unit
    gust force g (:class:`boatland.landing.law.SteadyLoad`: pattern f_g, spectrum S_g) from the landed response
    to f_g on the gusts' own grid (:meth:`LandingSetup.gust_response`, trapezoid); ``J0`` (Np, 3) the static
    contact forces, which tilt the margins' directions as the waves' (:func:`slip_directions`). With
    ``correlation``, also the swing's correlation (R, R) between the responses (1 between two it does not
    move: :attr:`boatland.freqdomain.statistics.SlowSwing.correlation`)."""
    w, wt, x, J = setup.gust_response(db)
    Hg = []
    for c in range(setup.n_points):
        n = setup.normals[c]
        Hg.append(J[:, c] @ (slip_directions(n, J0[c], setup.mu) - setup.mu * n).T)   # (Nw, 4)
    Hg = np.concatenate(Hg + [x[:, 3:4]], axis=-1)
    S = setup.steady.gust_spectrum(w)
    m = np.einsum("w,w,wr,wk->rk", S, wt, np.abs(Hg) ** 2, w[:, None] ** np.arange(3)[None, :])
    if not correlation:
        return m
    rho = correlation_matrix(np.einsum("w,w,wi,wj->ij", S, wt, Hg, Hg.conj()).real)
    still = m[:, 0] <= 1e-12 * max(float(m[:, 0].max()), 1e-300)
    rho[np.ix_(still, still)] = 1.0
    return m, rho


def screening_grid(db: HydroDB, setup: LandingSetup, Tp, beta_deg=None, *, accept=ACCEPT_PRESETS["best"],
                   statistics: str = DEFAULT_STATISTICS, method: str = "improved", sea: SpectrumPart | None = None,
                   water_depth: float | None = None, access_duration: float = ACCESS_DURATION, omega=None,
                   mu: float | None = None, thrust: float | None = None) -> LimitTable:
    r"""Limiting-Hs table of a vessel on its landing (Wu 2014; Grøtting 2015 §3.2.1, §3.4, Figures 4.1–4.18).

    :func:`slip_transfer` → :func:`spectral_moments` → :func:`limiting_hs`.

    Parameters
    ----------
    db : HydroDB
    setup : LandingSetup
    Tp : array_like, shape (NT,)
        Peak periods [s].
    beta_deg : array_like, shape (Nβ,), optional
        Relative wave directions [deg] (default 0, 45, …, 315).
    accept : float or str
        Accepted probability per access (or a Grøtting 2015 Table 2.1 preset name).
    statistics : {"rayleigh", "rice", "vanmarcke"}
    method : {"improved", "wu"}
    sea : SpectrumPart, optional
        Spectral shape (default JONSWAP γ 3.3).
    water_depth : float, optional
        For TMA (default the database's).
    access_duration : float
        t_acc [s] (default 1800 s).
    omega : array_like, optional
        Frequency grid (default :func:`default_omega`).
    mu, thrust : float, optional
        Override the setup's μ and F_b.

    Returns
    -------
    LimitTable
    """
    if statistics not in STATISTICS:
        raise BoatlandInputError(f"statistics {statistics!r}: use one of {', '.join(STATISTICS)}")
    accept_probability(accept)
    tr = slip_transfer(db, setup, omega=omega, beta_deg=beta_deg, method=method, mu=mu, thrust=thrust)
    h = db.water_depth if water_depth is None else water_depth
    m, captured = spectral_moments(tr, Tp, sea=sea, water_depth=h, g=db.g)
    keep = distinct_events(m[..., 0], tr.capacity, response_correlation(tr, Tp, sea=sea, water_depth=h, g=db.g),
                           background=tr.background)
    S, wt = unit_spectra(tr.omega, Tp, sea=sea, water_depth=h, g=db.g)
    tails = tr.drag_tails(db, np.broadcast_to((S * wt)[:, None, :], (S.shape[0], tr.beta_deg.size, wt.size)))
    return limiting_hs(m, tr.capacity, Tp, tr.beta_deg, accept=accept, statistics=statistics,
                       access_duration=access_duration, method=method, captured=captured, names=tr.names,
                       keep=keep, background=tr.background, tails=tails)


# --------------------------------------------------------------------------------------- one given sea
@dataclass(frozen=True, eq=False)
class SeaResponse:
    r"""Slip margins and roll in one given sea (a sum of wave systems; Grøtting 2015 eq. 3.41–3.45).

    Attributes
    ----------
    sigma : ndarray, shape (R,)
        Standard deviations of every contact's margins of :data:`MODES` [N] and of roll [rad].
    m : ndarray, shape (R, 3)
        Spectral moments m₀, m₁, m₂.
    capacity : ndarray, shape (R,)
    names : tuple of str
        The responses (:attr:`SlipTransfer.names`).
    p_cycle, p_access : float
        Incident probability per cycle (of ``cycle_period``) and per access.
    cycle_period : float
        Tp of the most energetic part [s].
    statistics, method : str
    per_mode : ndarray, shape (R,)
        Each response's per-cycle exceedance probability (Rayleigh) or first-passage rate [1/s] (Rice,
        Vanmarcke); 0 for a response that is not an event of its own.
    access_duration : float
        [s].
    tails : ndarray, shape (R, 2), or None
        Skewness and excess kurtosis of each response from the hull drag's second-order part in a current
        (:class:`boatland.freqdomain.quadratic_drag.QuadraticDrag`; they enter ``per_mode``); None without one.
    """

    sigma: np.ndarray
    m: np.ndarray
    capacity: np.ndarray
    names: tuple
    p_cycle: float
    p_access: float
    cycle_period: float
    statistics: str
    method: str
    per_mode: np.ndarray | None = None
    access_duration: float = ACCESS_DURATION
    tails: np.ndarray | None = None

    def p_slip(self) -> float:
        """Probability of a slip onset (any contact, any mode) per access, roll left out."""
        return self._access(self.per_mode[:-1])

    def p_roll_above(self, limit_deg: float) -> float:
        """Probability of roll beyond ±``limit_deg`` per access, the same statistics (Grøtting 2015 eq. 3.37)."""
        m = self.m[-1:][None, None]
        _, p, _ = incident_probability(1.0, m, np.array([math.radians(limit_deg)]), [self.cycle_period],
                                       statistics=self.statistics, access_duration=self.access_duration)
        return float(p[0, 0])

    def _access(self, per_mode) -> float:
        if self.statistics == "rayleigh":
            pc = 1.0 - float(np.prod(1.0 - per_mode))
            return float(-np.expm1(self.access_duration / self.cycle_period * np.log1p(-min(pc, 1.0))))
        return float(-np.expm1(-float(np.sum(per_mode)) * self.access_duration))


#: Passes of the hull drag's linearisation with the waves' velocities in :func:`sea_response` (the second
#: changes the probabilities of the validation cases by < 1 % of the first's change).
DRAG_PASSES = 2


def sea_response(db: HydroDB, setup: LandingSetup, parts, *, water_depth: float | None = None,
                 statistics: str = DEFAULT_STATISTICS, method: str = "improved", access_duration: float = ACCESS_DURATION,
                 omega=None, spreading_step_deg: float = 5.0) -> SeaResponse:
    r"""Incident probability of the landing in one sea made of spectral parts (swell + wind sea …).

    .. math:: m_k = \sum_p \int_0^\infty \omega^k \int D_p(\theta)\,|H(\omega, \theta - \psi)|^2\,d\theta\;
              S_p(\omega)\,d\omega

    (Grøtting 2015 eq. 3.41–3.45; a long-crested part has :math:`D_p = \delta(\theta - \bar\theta_p)`, a
    short-crested one its cos-2s spreading on a ``spreading_step_deg`` grid over the whole circle, as the
    time domain draws it).

    Parameters
    ----------
    db : HydroDB
    setup : LandingSetup
        Its ``heading_deg`` ψ turns the parts' global directions into relative ones.
    parts : sequence of SpectrumPart
        The wave systems with their Hs, Tp, global direction (towards) and spreading.
    water_depth : float, optional
        For TMA parts (default the database's).
    statistics, method, access_duration, omega
        As :func:`screening_grid`.

    Returns
    -------
    SeaResponse
    """
    parts = list(parts)
    if not parts:
        raise BoatlandInputError("sea_response needs at least one spectral part")
    dirs, weights, owner = [], [], []
    for i, p in enumerate(parts):
        if p.spreading is None:
            d, wgt = np.array([p.direction_deg]), np.array([1.0])
        else:
            d = p.direction_deg + np.arange(-180.0, 180.0, spreading_step_deg)   # the whole circle, as the TD
            wgt = spreading_cos2s(np.radians(d), math.radians(p.direction_deg), p.spreading)
            wgt = wgt / wgt.sum()
        dirs.append(d)
        weights.append(wgt)
        owner.append(np.full(d.size, i))
    beta = (np.concatenate(dirs) - setup.heading_deg) % 360.0
    h = db.water_depth if water_depth is None else water_depth
    if method != "wu":
        setup = setup.with_drift(db, parts, h)      # the sea's own mean wave drift, when the scenario applies it
    tr = slip_transfer(db, setup, omega=omega, beta_deg=beta, method=method)
    w = tr.omega
    S = np.stack([p.spectrum(w, h, db.g) for p in parts])[np.concatenate(owner)]     # (Nβ, Nw)
    S = S * np.concatenate(weights)[:, None]
    wt = np.zeros_like(w)
    dw = np.diff(w)
    wt[:-1] += dw / 2
    wt[1:] += dw / 2
    if method != "wu" and setup.drag_linearisable:
        # the hull's drag sees the waves' velocities too: linearise it with them (twice: they change a little)
        for _ in range(DRAG_PASSES):
            sig = setup.strip_sigma(w, (S * wt[None, :]).T, tr.motions)
            tr = slip_transfer(db, setup.with_drag_linearised(db, wave_sigma=sig), omega=omega, beta_deg=beta,
                               method=method)
    tails = None
    if method != "wu" and setup.drag_linearisable:
        # the drag's square: the margins' skewness (boatland.freqdomain.quadratic_drag)
        tails = tr.drag_tails(db, (S * wt[None, :])[None], sigma=sig, together=True)
    m = np.einsum("bw,w,wbr,wk->rk", S, wt, np.abs(tr.H) ** 2, w[:, None] ** np.arange(3)[None, :])
    cov = np.einsum("bw,w,wbi,wbj->ij", S, wt, tr.H, tr.H.conj()).real
    keep = distinct_events(m[None, None, :, 0], tr.capacity, correlation_matrix(cov)[None, None],
                           background=tr.background)
    Tc = parts[int(np.argmax([p.Hs for p in parts]))].Tp
    pc, pa, per_mode = incident_probability(1.0, m[None, None], tr.capacity, [Tc], statistics=statistics,
                                            access_duration=access_duration, keep=keep, background=tr.background,
                                            tails=tails)
    if tr.background is not None:
        m = m + tr.background.moments   # the gusts: independent of the waves, their variances add
    return SeaResponse(sigma=np.sqrt(m[:, 0]), m=m, capacity=tr.capacity, names=tr.names, p_cycle=float(pc[0, 0]),
                       p_access=float(pa[0, 0]), cycle_period=float(Tc), statistics=statistics, method=method,
                       per_mode=np.asarray(per_mode[0, 0], dtype=float), access_duration=float(access_duration),
                       tails=None if tails is None else tails[0, 0])


#: Shear stiffnesses of :func:`shear_sweep` as multiples of the scenario's (and the rigid stick, ``inf``).
SHEAR_FACTORS = (0.1, 0.3, 1.0, 3.0, 10.0, 100.0, math.inf)


@dataclass(frozen=True, eq=False)
class ShearSweep:
    """Limiting Hs against the fender's shear stiffness: ``Hs`` (Nk, Nβ) at one Tp for the stiffnesses
    ``k_t`` (Nk,) [N/m] (``inf``: the rigid stick) and relative directions ``beta_deg``; ``governing``
    the response at each limit; ``table`` the first :class:`LimitTable` (for its accept, statistics)."""

    Tp: float
    k_t: np.ndarray
    beta_deg: np.ndarray
    Hs: np.ndarray
    governing: np.ndarray
    table: LimitTable

    def text(self) -> str:
        head = "k_t [N/m] \\ β [deg] " + "".join(f"{b:>8g}" for b in self.beta_deg)
        rows = [head]
        for k, h in zip(self.k_t, self.Hs):
            label = "rigid" if not np.isfinite(k) else f"{k:.3g}"
            rows.append(f"{label:>19} " + "".join(f"{x:>8.3f}" if np.isfinite(x) else f"{'>' + str(int(HS_MAX)):>8}"
                                                  for x in h))
        return "\n".join(rows)


def shear_sweep(db: HydroDB, setup: LandingSetup, Tp: float, beta_deg, *, k_t=None, **kw) -> ShearSweep:
    r"""The limiting Hs of :func:`screening_grid` at one peak period for a range of shear stiffnesses of
    the fender (the oblique-sea answer depends on it: the rubber's compliance sets how much of the roll
    moment two contacts take as a couple of opposite vertical forces). The shear damping keeps its ratio of
    critical, :math:`c_t \propto \sqrt{k_t}`.

    Parameters
    ----------
    k_t : array_like, optional
        Stiffnesses [N/m] (``inf``: rigid); default :data:`SHEAR_FACTORS` × the setup's (× 3 MN/m with 5 % of
        critical damping when the setup is rigid: Grøtting 2015 §3.2.2).
    **kw
        Passed to :func:`screening_grid` (accept, statistics, sea, ...).
    """
    if math.isfinite(setup.shear_stiffness):
        base = setup.shear_stiffness
        ratio = setup.shear_damping / math.sqrt(base)             # c_t/√k_t = 2ζ√m_eff: ζ kept
    else:                                                          # from a rigid stick: Grøtting's defaults
        base = SHEAR_STIFFNESS_DEFAULT
        Mt = db.M + (db.A_inf if db.A_inf is not None else db.A[:, :, -1])
        g = [np.concatenate([[0.0, 0.0, 1.0], np.cross(p, [0.0, 0.0, 1.0])]) for p in setup.points]
        ratio = np.array([2 * SHEAR_DAMPING_RATIO_DEFAULT / math.sqrt(gi @ np.linalg.solve(Mt, gi)) for gi in g])
    ks = np.asarray([f * base for f in SHEAR_FACTORS] if k_t is None else k_t, dtype=float)
    tables = []
    for k in ks:
        s = setup.replace(shear_stiffness=float(k), shear_damping=ratio * math.sqrt(k) if np.isfinite(k) else 0.0)
        tables.append(screening_grid(db, s, [Tp], beta_deg, **kw))
    return ShearSweep(Tp=float(Tp), k_t=ks, beta_deg=tables[0].beta_deg, Hs=np.array([t.Hs[0] for t in tables]),
                      governing=np.array([t.governing[0] for t in tables]), table=tables[0])
