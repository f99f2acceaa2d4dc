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

Grøtting 2015 eq. 3.13–3.24 and eq. 3.64–3.75 of the improved variant — there for the summed force of
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

Statistics (``statistics``):

``"rayleigh"`` (seed 002): per wave cycle (one per Tp) the peak of each margin exceeds its capacity with
  probability :math:`e^{-a_m^2/2\sigma_m^2}` (eq. 3.36; the seed's sign typo corrected), the roll
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

Conventions: β relative to the vessel, direction of travel (180° head seas); exp(+iωt); SI.
"""

from __future__ import annotations

import dataclasses
import math
import weakref
from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.freqdomain.rao import hinged_rao
from boatland.model.hydrodb import HydroDB
from boatland.model.landed import normal_follows
from boatland.model.pile_diffraction import pile_scattered_excitation
from boatland.model.scenario_schema import SHEAR_DAMPING_RATIO_DEFAULT, SHEAR_STIFFNESS_DEFAULT
from boatland.model.seastate import SpectrumPart
from boatland.waves.excitation import direction_brackets, periodic_directions
from boatland.waves.spectra import spreading_cos2s

__all__ = ["ACCEPT_PRESETS", "ACCESS_DURATION", "MODES", "SHEAR_FACTORS", "LandingSetup", "LimitTable", "SeaResponse",
           "ShearSweep", "SlipTransfer", "distinct_events", "response_correlation", "shear_sweep",
           "accept_probability", "incident_probability", "limiting_hs", "rayleigh_exceedance", "rice_rate",
           "screening_grid", "sea_response", "slip_transfer", "spectral_moments", "vanmarcke_rate"]

#: Accepted probability of a failure (incident) during one access operation, seed 002 Table 2.1.
ACCEPT_PRESETS = {"best": 0.00119, "conservative": 0.00002, "non-conservative": 0.02681}
#: Duration of one access operation t_acc [s] (seed 002 §3.2.1: 30 min throughout).
ACCESS_DURATION = 1800.0
#: Slip modes, in the order of the margin arrays (then roll as the 5th response).
MODES = ("down", "up", "left", "right")
STATISTICS = ("rayleigh", "rice", "vanmarcke")
METHODS = ("improved", "wu")
HS_MAX = 30.0  # [m] limiting Hs reported as inf above this
#: The databases with the pile's scattered wave added, per database and layout (computing X_s over a
#: database's whole (ω, β) grid takes about a second; the screening of one landing asks for it often).
_NEAR_PILE: "weakref.WeakKeyDictionary[HydroDB, dict]" = weakref.WeakKeyDictionary()


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
                                     f"{', '.join(ACCEPT_PRESETS)} (seed 002 Table 2.1)") from None
    p = float(accept)
    if not 0.0 < p < 1.0:
        raise BoatlandInputError(f"accepted probability {p:g} is outside (0, 1): it is a probability of failure "
                                 f"per access, e.g. {ACCEPT_PRESETS['best']} (seed 002 Table 2.1 best estimate)")
    return p


# --------------------------------------------------------------------------------------- the landing
@dataclass(frozen=True, kw_only=True, eq=False)
class LandingSetup:
    r"""Vessel on its landing, as the screening sees it (body frame, vessel at rest).

    Attributes
    ----------
    points : ndarray, shape (Np, 3)
        Fender contact points [m].
    normals : ndarray, shape (Np, 3)
        Unit contact normals, landing → vessel (horizontal).
    mu : float
        Static friction coefficient μ (μ_s; stuck fender).
    thrust : float
        Bollard push F_b [N] along the vessel's x axis (> 0).
    thrust_position : ndarray, shape (3,)
        Body point of the thrust [m].
    stiffness, damping : float
        Fender normal spring c_f [N/m] and damper d_f [N s/m] per contact (``"improved"`` hinge).
    shear_stiffness : float
        The rubber's shear stiffness k_t per contact [N/m]; ``inf``: the rigid stick.
    shear_damping : ndarray, shape (Np,)
        Its damping c_t per contact [N s/m].
    sideways : bool
        Friction (and shear) also along the tube, not only vertically.
    additional_damping : ndarray, shape (6, 6)
        Extra linear damping of the vessel (viscous roll …).
    heading_deg : float
        Vessel heading [deg] (global): relative direction = wave direction − heading.
    roll_limit_deg : float
        Maximum acceptable roll angle θ_max [deg] (Grøtting 2015 Table 4.1: 10°).
    pile : tuple or None
        ``(radius, (x, y), water_depth)``: the monopile whose scattered wave the vessel feels — its radius
        [m], the vessel's mean reference-point position relative to the pile axis (global) [m] and the
        depth [m] — as the time domain applies it (``landing.diffraction``); None: the open sea.
    fender_width : float
        Length of the fender line at each contact [m] (0: a point fender).
    tube_radius : ndarray, shape (Np,)
        Radii of the tubes [m] (how a point fender's normal turns: :func:`boatland.model.landed.normal_follows`).
    """

    points: np.ndarray
    normals: np.ndarray
    mu: float
    thrust: float
    thrust_position: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(3))
    stiffness: float = 1.0e6
    damping: float = 4.0e4
    shear_stiffness: float = math.inf
    shear_damping: np.ndarray | float = 0.0
    sideways: bool = True
    additional_damping: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros((6, 6)))
    heading_deg: float = 0.0
    roll_limit_deg: float = 10.0
    pile: tuple | None = None
    fender_width: float = 0.0
    tube_radius: np.ndarray | float = np.inf

    def __post_init__(self):
        P = np.atleast_2d(np.asarray(self.points, dtype=float))
        N = np.atleast_2d(np.asarray(self.normals, dtype=float))
        if P.shape[1:] != (3,) or N.shape != P.shape or not np.all(np.isfinite(P)) or not np.all(np.isfinite(N)):
            raise BoatlandInputError(f"landing: points and normals must be (Np, 3) finite arrays of equal shape, "
                                     f"got {P.shape} and {N.shape}")
        N = N / np.linalg.norm(N, axis=1)[:, None]
        for name, v, lo in (("mu", self.mu, 0.0), ("thrust", self.thrust, 0.0), ("roll_limit_deg",
                            self.roll_limit_deg, 0.0)):
            if not (math.isfinite(v) and v > lo):
                raise BoatlandInputError(f"landing: {name} = {v!r} must be a finite number > {lo:g}")
        if not self.shear_stiffness > 0:
            raise BoatlandInputError(f"landing: shear_stiffness = {self.shear_stiffness!r} must be > 0 (inf: rigid)")
        object.__setattr__(self, "points", P)
        object.__setattr__(self, "normals", N)
        c_t = np.asarray(self.shear_damping, dtype=float).ravel()
        if c_t.size not in (1, P.shape[0]):
            if not np.all(c_t == c_t[0]):
                raise BoatlandInputError(f"landing: shear_damping has {c_t.size} values for {P.shape[0]} points")
            c_t = c_t[:1]                       # one value for all (e.g. after replace(points=...))
        object.__setattr__(self, "shear_damping", np.array(np.broadcast_to(c_t, (P.shape[0],))))
        object.__setattr__(self, "thrust_position", np.asarray(self.thrust_position, dtype=float).reshape(3))
        object.__setattr__(self, "additional_damping", np.asarray(self.additional_damping, dtype=float))

    @property
    def n_points(self) -> int:
        return self.points.shape[0]

    @property
    def mean_normal(self) -> np.ndarray:
        """Unit vector along the sum of the normals, :math:`\\bar n`."""
        n = self.normals.sum(axis=0)
        return n / np.linalg.norm(n)

    def replace(self, **changes) -> "LandingSetup":
        """A copy with some attributes changed (e.g. ``mu=0.8, thrust=120e3``)."""
        return dataclasses.replace(self, **changes)

    def near_pile(self, db: HydroDB, beta_deg=None) -> HydroDB:
        """``db`` with the pile's scattered wave added to its excitation (:func:`pile_scattered_excitation`),
        as the time domain has it; ``db`` itself without a pile.

        ``beta_deg`` (relative directions [deg]): X^s is added only to the columns of a full-circle table
        that the interpolation at these directions reads (:func:`~boatland.waves.excitation.direction_brackets`)
        — the same values there, at the cost of those columns instead of all of them; the other columns
        keep the open-sea X, so use the result only at ``beta_deg``. Other tables get every column."""
        if self.pile is None:
            return db
        radius, position, depth = self.pile
        cols = None
        if beta_deg is not None and periodic_directions(db.wave_dir_deg):
            j, j1, _, _ = direction_brackets(np.atleast_1d(np.asarray(beta_deg, dtype=float)), db.wave_dir_deg, True)
            cols = tuple(int(c) for c in np.unique(np.concatenate([j, j1])))
            if len(cols) == db.n_dir:
                cols = None
        key = (float(radius), float(position[0]), float(position[1]), float(depth), float(self.heading_deg), cols)
        per_db = _NEAR_PILE.setdefault(db, {})
        if key not in per_db:
            Xs = pile_scattered_excitation(db, position, self.heading_deg, radius, depth, directions=cols)
            if cols is None:
                X = db.X + Xs
            else:
                X = np.array(db.X)
                X[:, list(cols), :] = db.X[:, list(cols), :] + Xs
            if len(per_db) >= 4:                # a few layouts and direction sets per database: bounded memory
                per_db.pop(next(iter(per_db)))
            per_db[key] = db.replace(X=X)
        return per_db[key]

    def check_on_hull(self, db: HydroDB, source: str = "landing") -> None:
        """Refuse fender points that are not at the bow of ``db``'s hull (front 20 % of its length, at most
        10 % ahead of the stem, within its beam), as the scenario checks do.

        Raises
        ------
        BoatlandInputError
            Names ``source`` and the point: ``fender.points[i]``.
        """
        if getattr(db, "mesh", None) is None:
            return
        v = db.mesh.vertices
        x0, x1 = float(v[:, 0].min()), float(v[:, 0].max())
        y0, y1 = float(v[:, 1].min()), float(v[:, 1].max())
        L = x1 - x0
        for i, (x, y, _) in enumerate(self.points):
            if not (x1 - 0.2 * L <= x <= x1 + 0.1 * L and y0 <= y <= y1):
                raise BoatlandInputError(f"{source}: fender.points[{i}] = ({x:g}, {y:g}) m is outside the bow of "
                                         f"{db.name!r} (hull x = {x0:g} … {x1:g} m, y = {y0:g} … {y1:g} m): "
                                         f"the fender must sit in the front 20 % and within the beam")

    @classmethod
    def from_scenario(cls, scenario, db: HydroDB, *, roll_limit_deg: float | None = None) -> "LandingSetup":
        """The landing of a validated scenario, as its time domain runs it: its fender points, the tubes'
        normals turned into the vessel's axes, μ_s, thrust, the fender's normal and shear laws (the
        shear damping from its ratio of critical for this vessel), additional linear damping, heading,
        and the monopile's scattered wave when the trial applies it. Roll limit: ``roll_limit_deg``,
        else the largest of ``incidents.roll_limit_deg``, else 10°.

        Raises
        ------
        BoatlandInputError
            The scenario has no landing, fender or thrust (keys named).
        """
        from boatland.model.scenario_checks import contact_period

        src = scenario.source
        for key in ("landing", "fender", "thrust"):
            if getattr(scenario, key) is None:
                raise BoatlandInputError(f"{src}: [{key}] is missing: screening needs a landing, a fender and a thrust")
        x0, y0, psi = scenario.start_pose()
        c, s = math.cos(psi), math.sin(psi)
        n_loc = scenario.landing.normals @ np.array([[c, s], [-s, c]]).T
        f = scenario.fender
        P = np.asarray(f.points, dtype=float)
        if n_loc.shape[0] != P.shape[0]:
            raise BoatlandInputError(f"{src}: fender.points: {P.shape[0]} points for {n_loc.shape[0]} struts")
        lim = roll_limit_deg
        if lim is None:
            lim = max(scenario.incidents.roll_limit_deg) if scenario.incidents.roll_limit_deg else 10.0
        pile = scenario.pile(db)
        if pile is not None:
            model = scenario.wave_model(db)
            depth = getattr(model, "water_depth", db.water_depth)
            pile = (pile[0], (x0 - pile[1][0], y0 - pile[1][1]), depth)
        c_t = 0.0 if f.rigid else np.asarray(contact_period(scenario, db).shear_damping)
        setup = cls(points=P, normals=np.column_stack([n_loc, np.zeros(len(P))]), mu=f.mu_s,
                    thrust=scenario.thrust.force, thrust_position=scenario.thrust.position,
                    stiffness=f.stiffness, damping=f.damping, shear_stiffness=f.shear_stiffness,
                    shear_damping=c_t, sideways=f.sideways,
                    additional_damping=scenario.additional_damping(db)[0], heading_deg=scenario.vessel.heading_deg,
                    roll_limit_deg=lim, pile=pile, fender_width=f.width,
                    tube_radius=np.array([st.diameter / 2 for st in scenario.landing.struts]))
        setup.check_on_hull(db, src)
        return setup


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


def response_names(n_responses: int) -> tuple[str, ...]:
    """Names of the screening's responses: each contact's four slip modes (``"down 0"`` …), then roll."""
    return tuple(f"{m} {c}" for c in range((n_responses - 1) // 4) for m in MODES) + ("roll",)


def _directions(n: np.ndarray) -> np.ndarray:
    s = np.cross(n, [0.0, 0.0, 1.0])
    s /= np.linalg.norm(s)
    ez = np.array([0.0, 0.0, 1.0])
    return np.stack([ez, -ez, -s, s])  # down, up, left (to port), right (to starboard)


def default_omega(db: HydroDB, n: int = 600) -> np.ndarray:
    """Frequency grid of the screening: ``n`` points, 0.05 rad/s (or the band's start) … the band's top."""
    return np.linspace(max(0.05, float(db.omega[0])), float(db.omega[-1]), n)


def landed_response(db: HydroDB, setup: LandingSetup, omega, beta_deg, method: str = "improved"):
    """The landed vessel's response (:func:`hinged_rao`) as the screening takes it: ``"improved"`` —
    the time domain's contacts (normal and shear laws, the rigid stick when k_t = ∞), follower thrust,
    the pile's scattered wave when the setup has one; ``"wu"`` — a rigid hinge in the open sea."""
    if method == "wu":
        return hinged_rao(db, omega, setup.points, beta_deg=beta_deg, normal=setup.normals,
                          additional_damping=setup.additional_damping)
    shear = None if not math.isfinite(setup.shear_stiffness) else setup.shear_stiffness
    return hinged_rao(setup.near_pile(db, beta_deg), omega, setup.points, beta_deg=beta_deg, normal=setup.normals,
                      stiffness=setup.stiffness, damping=setup.damping, shear_stiffness=shear,
                      shear_damping=setup.shear_damping if shear is not None else None, sideways=setup.sideways,
                      thrust=setup.thrust, thrust_position=setup.thrust_position,
                      additional_damping=setup.additional_damping,
                      **_follows(normal_follows(setup.fender_width, np.broadcast_to(setup.tube_radius, (setup.n_points,)),
                                                setup.thrust / setup.n_points / setup.stiffness)))


def _follows(spec: dict) -> dict:
    return {"normal_follows": spec["follows"], "tube_radius": spec.get("radius", np.inf)}


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
    H, cap, names = [], [], []
    for c in range(n_p):
        n = setup.normals[c]
        Dc = _directions(n)
        H.append(r.J[:, :, c] @ (Dc - setup.mu * n).T)                    # (Nw, Nβ, 4)
        cap.append(setup.mu * float(n @ J0[c]) - Dc @ J0[c])
        names += [f"{m} {c}" for m in MODES]
    H = np.concatenate(H + [r.x[..., 3:4]], axis=-1)
    cap = np.concatenate(cap + [[math.radians(setup.roll_limit_deg)]])
    return SlipTransfer(omega=w, beta_deg=b, H=H, capacity=cap, names=tuple(names + ["roll"]), J_static=J0,
                        N_static=np.einsum("pk,pk->p", setup.normals, J0), method=method, setup=setup)


# --------------------------------------------------------------------------------------- statistics
def _part(sea) -> SpectrumPart:
    return SpectrumPart(Hs=1.0, Tp=10.0) if sea is None else sea


def spectral_moments(transfer: SlipTransfer, Tp, *, sea: SpectrumPart | None = None,
                     water_depth: float = math.inf, g: float = 9.81) -> tuple[np.ndarray, np.ndarray]:
    r"""Spectral moments :math:`m_k = \int \omega^k |H|^2 S\,d\omega`, k = 0, 1, 2, for Hs = 1 m.

    Parameters
    ----------
    transfer : SlipTransfer
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
    part = _part(sea)
    T = np.atleast_1d(np.asarray(Tp, dtype=float))
    if np.any(~np.isfinite(T)) or np.any(T <= 0):
        raise BoatlandInputError(f"peak periods must be > 0 s, got {T}")
    w = transfer.omega
    S = np.stack([dataclasses.replace(part, Hs=1.0, Tp=float(t)).spectrum(w, water_depth, g) for t in T])
    wt = np.zeros_like(w)                                   # trapezoid weights
    dw = np.diff(w)
    wt[:-1] += dw / 2
    wt[1:] += dw / 2
    H2 = np.abs(transfer.H) ** 2                            # (Nw, Nβ, R)
    powers = w[:, None] ** np.arange(3)[None, :]            # (Nw, 3)
    m = np.einsum("tw,w,wbr,wk->tbrk", S, wt, H2, powers, optimize=True)
    captured = (S @ wt) / (1.0 / 16.0)
    return m, captured


#: Responses whose correlation reaches this are one event (:func:`distinct_events`).
SAME_EVENT = 0.99


def response_correlation(transfer: SlipTransfer, Tp, *, sea: SpectrumPart | None = None,
                         water_depth: float = math.inf, g: float = 9.81) -> np.ndarray:
    r"""Correlation coefficients of the responses (margins, roll) in each sea:
    :math:`
ho_{ij} = \int \mathrm{Re}(H_i ar H_j) S\,d\omega / (\sigma_i\sigma_j)`.

    Returns
    -------
    ndarray, shape (NT, Nβ, R, R)
    """
    part = _part(sea)
    T = np.atleast_1d(np.asarray(Tp, dtype=float))
    w = transfer.omega
    S = np.stack([dataclasses.replace(part, Hs=1.0, Tp=float(t)).spectrum(w, water_depth, g) for t in T])
    wt = np.zeros_like(w)
    dw = np.diff(w)
    wt[:-1] += dw / 2
    wt[1:] += dw / 2
    H = transfer.H                                           # (Nw, Nβ, R)
    cov = np.einsum("tw,w,wbi,wbj->tbij", S, wt, H, H.conj(), optimize=True).real
    return _correlation(cov)


def _correlation(cov: np.ndarray) -> np.ndarray:
    sd = np.sqrt(np.clip(np.einsum("...ii->...i", cov), 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = cov / (sd[..., :, None] * sd[..., None, :])
    return np.nan_to_num(rho)


def distinct_events(m0: np.ndarray, capacity: np.ndarray, correlation: np.ndarray,
                    same: float = SAME_EVENT) -> np.ndarray:
    r"""Which responses are events of their own: a response correlated at ρ ≥ ``same`` with one that is
    at least as likely (smaller reliability index β = a/σ) exceeds its capacity only when that one does
    — the same event — and is left out of the union. Two symmetric contacts in head seas have identical
    margins (ρ = 1): counted twice, as independent events, they would double the incident rate. β is
    proportional to 1/Hs for every response, so the choice does not depend on Hs. Roll (the last
    response) is always kept.

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
    deviation σ exceeds a (seed 002 eq. 3.36–3.37): :math:`P = e^{-a^2/2\sigma^2}`, 1 for a ≤ 0."""
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


def incident_probability(Hs, m: np.ndarray, capacity: np.ndarray, Tp, *, statistics: str = "rayleigh",
                         access_duration: float = ACCESS_DURATION, keep=None) -> tuple[np.ndarray, np.ndarray]:
    r"""Probability of an incident (any slip mode or roll) per wave cycle and per access.

    ``"rayleigh"`` — seed 002 eq. 3.80 per cycle of Tp, :math:`P_{cyc} = 1-\prod_i(1-e^{-a_i^2/2\sigma_i^2})`;
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
        Levels a_i (:attr:`SlipTransfer.capacity`).
    Tp : array_like, shape (NT,)
    statistics : {"rayleigh", "rice", "vanmarcke"}
    access_duration : float
        t_acc [s].
    keep : ndarray of bool, shape (NT, Nβ, R), optional
        The responses that are events of their own (:func:`distinct_events`); default all.

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
    m0 = m[..., 0] * Hs ** 2
    on = 1.0 if keep is None else np.asarray(keep, dtype=float)
    if statistics == "rayleigh":
        p = rayleigh_exceedance(capacity, np.sqrt(m0)) * on
        p_cycle = 1.0 - np.prod(1.0 - p, axis=-1)
        with np.errstate(divide="ignore"):
            p_access = -np.expm1(access_duration / T * np.log1p(-np.minimum(p_cycle, 1.0)))
        return p_cycle, p_access, p
    m1, m2 = m[..., 1] * Hs ** 2, m[..., 2] * Hs ** 2
    if statistics == "rice":
        sides = np.ones(capacity.shape[-1])
        sides[-1] = 2.0                                                   # roll (last): both signs
        nu = rice_rate(capacity, m0, m2) * sides
    else:
        nu = np.concatenate([vanmarcke_rate(capacity[:-1], m0[..., :-1], m1[..., :-1], m2[..., :-1]),
                             vanmarcke_rate(capacity[-1:], m0[..., -1:], m1[..., -1:], m2[..., -1:], two_sided=True)],
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
                statistics: str = "rayleigh", access_duration: float = ACCESS_DURATION, method: str = "improved",
                captured=None, names=None, keep=None) -> LimitTable:
    r"""Limiting Hs per (Tp, β): the largest Hs whose incident probability is accepted.

    ``"rayleigh"``: :math:`P_{inc}(H_s) \le P_{facc}\,T_p/t_{acc}` (seed 002 eq. 3.38–3.40, 3.80);
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

    Returns
    -------
    LimitTable
    """
    p_acc = accept_probability(accept)
    T = np.asarray(Tp, dtype=float)
    if statistics == "rayleigh":
        target = np.broadcast_to((p_acc * T / access_duration)[:, None], m.shape[:2])
    else:
        target = np.full(m.shape[:2], p_acc)

    def excess(h):
        pc, pa, _ = incident_probability(h, m, capacity, T, statistics=statistics, access_duration=access_duration,
                                         keep=keep)
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
                                     statistics=statistics, access_duration=access_duration, keep=keep)
    names = np.array(response_names(capacity.shape[-1]) if names is None else names)
    governing = names[np.argmax(per, axis=-1)]
    cap = np.ones(T.size) if captured is None else np.asarray(captured)
    return LimitTable(Tp=T, beta_deg=np.asarray(beta_deg, dtype=float), Hs=Hs, governing=governing,
                      accept=p_acc, statistics=statistics, method=method, captured=cap)


def screening_grid(db: HydroDB, setup: LandingSetup, Tp, beta_deg=None, *, accept=ACCEPT_PRESETS["best"],
                   statistics: str = "rayleigh", method: str = "improved", sea: SpectrumPart | None = None,
                   water_depth: float | None = None, access_duration: float = ACCESS_DURATION, omega=None,
                   mu: float | None = None, thrust: float | None = None) -> LimitTable:
    r"""Limiting-Hs table of a vessel on its landing (Wu 2014; seed 002 §3.2.1, §3.4, Figures 4.1–4.18).

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
        Accepted probability per access (or a seed 002 Table 2.1 preset name).
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
    keep = distinct_events(m[..., 0], tr.capacity, response_correlation(tr, Tp, sea=sea, water_depth=h, g=db.g))
    return limiting_hs(m, tr.capacity, Tp, tr.beta_deg, accept=accept, statistics=statistics,
                       access_duration=access_duration, method=method, captured=captured, names=tr.names,
                       keep=keep)


# --------------------------------------------------------------------------------------- one given sea
@dataclass(frozen=True, eq=False)
class SeaResponse:
    r"""Slip margins and roll in one given sea (a sum of wave systems; seed 002 eq. 3.41–3.45).

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


def sea_response(db: HydroDB, setup: LandingSetup, parts, *, water_depth: float | None = None,
                 statistics: str = "rayleigh", method: str = "improved", access_duration: float = ACCESS_DURATION,
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
    tr = slip_transfer(db, setup, omega=omega, beta_deg=beta, method=method)
    h = db.water_depth if water_depth is None else water_depth
    w = tr.omega
    S = np.stack([p.spectrum(w, h, db.g) for p in parts])[np.concatenate(owner)]     # (Nβ, Nw)
    S = S * np.concatenate(weights)[:, None]
    wt = np.zeros_like(w)
    dw = np.diff(w)
    wt[:-1] += dw / 2
    wt[1:] += dw / 2
    m = np.einsum("bw,w,wbr,wk->rk", S, wt, np.abs(tr.H) ** 2, w[:, None] ** np.arange(3)[None, :])
    cov = np.einsum("bw,w,wbi,wbj->ij", S, wt, tr.H, tr.H.conj()).real
    keep = distinct_events(m[None, None, :, 0], tr.capacity, _correlation(cov)[None, None])
    Tc = parts[int(np.argmax([p.Hs for p in parts]))].Tp
    pc, pa, _ = incident_probability(1.0, m[None, None], tr.capacity, [Tc], statistics=statistics,
                                     access_duration=access_duration, keep=keep)
    return SeaResponse(sigma=np.sqrt(m[:, 0]), m=m, capacity=tr.capacity, names=tr.names, p_cycle=float(pc[0, 0]),
                       p_access=float(pa[0, 0]), cycle_period=float(Tc), statistics=statistics, method=method)


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
