r"""The vessel on its landing as the frequency-domain screening sees it: :class:`LandingSetup`, made from a
scenario through the same :class:`~boatland.landing.contacts.FenderOnLanding` as the time domain's contacts
(:meth:`LandingSetup.from_scenario`), or given directly (points, normals, the fender's laws, the push).
"""

from __future__ import annotations

import dataclasses
import math
import weakref
from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.freqdomain.rao import hinged_rao
from boatland.landing.law import SteadyLoad, normal_follows
from boatland.landing.setup import Setup
from boatland.sea.drift import mean_drift
from boatland.sea.states import SeaState
from boatland.sea.pile import Pile, pile_scattered_excitation
from boatland.vessel.database import HydroDB
from boatland.waves.excitation import direction_brackets, periodic_directions

__all__ = ["GUST_F_MAX", "GUST_OMEGA_MIN", "GUST_POINTS", "LandingSetup"]

#: The gusts' grid (:meth:`LandingSetup.gust_response`): lowest frequency [rad/s], number of points, highest
#: gust frequency [Hz] (as the time domain's synthesis, :data:`boatland.loads.wind.F_MAX`).
GUST_OMEGA_MIN = 1e-3
GUST_POINTS = 1500
GUST_F_MAX = 2.0

#: The databases with the pile's scattered wave added, per database and layout (computing X_s over a
#: database's whole (ω, β) grid takes about a second; the screening of one landing asks for it often).
_NEAR_PILE: "weakref.WeakKeyDictionary[HydroDB, dict]" = weakref.WeakKeyDictionary()


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
    pile : Pile or None
        The monopile whose scattered wave the vessel feels (:class:`boatland.sea.pile.Pile`), as the time
        domain applies it (``landing.diffraction``); None: the open sea.
    position : (float, float)
        The vessel's mean reference-point position, global [m] (where it lies beside the pile).
    fender_width : float
        Length of the fender line at each contact [m] (0: a point fender).
    tube_radius : ndarray, shape (Np,)
        Radii of the tubes [m] (how a point fender's normal turns: :func:`boatland.landing.law.normal_follows`).
    thrust_direction : ndarray, shape (3,)
        Unit body direction of the push (default along x).
    steady : SteadyLoad or None
        Steady loads besides the push — current, mean wind, mean wave drift — with their linearisation
        (:meth:`boatland.landing.environment.Environment.steady_load`); None: none.
    environment : Environment or None
        The scenario's loads beside the waves (:class:`boatland.landing.environment.Environment`), for the
        statistical linearisation of the hull's drag (:meth:`with_drag_linearised`); None: none.
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
    pile: Pile | None = None
    position: tuple = (0.0, 0.0)
    fender_width: float = 0.0
    tube_radius: np.ndarray | float = np.inf
    thrust_direction: np.ndarray = dataclasses.field(default_factory=lambda: np.array([1.0, 0.0, 0.0]))
    steady: SteadyLoad | None = None
    environment: object = None

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
        object.__setattr__(self, "thrust_direction", np.asarray(self.thrust_direction, dtype=float).reshape(3))
        object.__setattr__(self, "additional_damping", np.asarray(self.additional_damping, dtype=float))

    @property
    def n_points(self) -> int:
        return self.points.shape[0]

    @property
    def mean_normal(self) -> np.ndarray:
        """Unit vector along the sum of the normals, :math:`\\bar n`."""
        n = self.normals.sum(axis=0)
        return n / np.linalg.norm(n)

    def response(self, db: HydroDB, omega, beta_deg, method: str = "improved", loads=None):
        """The landed vessel's response (:func:`boatland.freqdomain.rao.hinged_rao`) as the screening takes it:
        ``"improved"`` — the time domain's contacts (normal and shear laws, the rigid stick when k_t = ∞),
        follower thrust, steady loads, the pile's scattered wave when the setup has one; ``"wu"`` — a rigid
        hinge in the open sea. ``loads`` (K, 6): force patterns solved beside the waves."""
        if method == "wu":
            return hinged_rao(db, omega, self.points, beta_deg=beta_deg, normal=self.normals,
                              additional_damping=self.additional_damping)
        follows = normal_follows(self.fender_width, np.broadcast_to(self.tube_radius, (self.n_points,)),
                                 self.thrust / self.n_points / self.stiffness)
        return hinged_rao(self.near_pile(db, beta_deg), omega, self.points, beta_deg=beta_deg, normal=self.normals,
                          stiffness=self.stiffness, damping=self.damping, shear_stiffness=self.shear_stiffness,
                          shear_damping=self.shear_damping, sideways=self.sideways,
                          thrust=self.thrust, thrust_position=self.thrust_position,
                          thrust_direction=self.thrust_direction, steady=self.steady, loads=loads,
                          additional_damping=self.additional_damping,
                          normal_follows=follows["follows"], tube_radius=follows.get("radius", np.inf))

    def gust_response(self, db: HydroDB):
        """The landed response to the steady loads' gust pattern on the gusts' own grid: (ω, trapezoid
        weights, x (Nw, 6), J (Nw, Np, 3)) per unit gust force (:class:`boatland.landing.law.SteadyLoad`).

        The grid is log-spaced from :data:`GUST_OMEGA_MIN` (periods of ~100 min; the NPD spectrum's variance below
        is < 1 % at 10 m/s) with :data:`GUST_POINTS` points up to the gusts' highest frequency (or the database's
        band): 0.46 % apart, fine enough for the landed vessel's slow sway–yaw mode (ctv27: ~0.08 rad/s, lightly
        damped), whose resonance carries most of the gusts' effect on the fender."""
        w = np.geomspace(GUST_OMEGA_MIN, min(float(db.omega[-1]), 2 * math.pi * GUST_F_MAX), GUST_POINTS)
        r = self.response(db, w, np.array([0.0]), loads=self.steady.gust_pattern[None])
        wt = np.zeros_like(w)
        dw = np.diff(w)
        wt[:-1] += dw / 2
        wt[1:] += dw / 2
        return w, wt, r.x_loads[:, 0], r.J_loads[:, 0]

    @property
    def drag_linearisable(self) -> bool:
        """The hull's drag damping depends on the motions' size (:meth:`with_drag_linearised` applies)."""
        env = self.environment
        return env is not None and env.linearisable and self.steady is not None

    def strip_sigma(self, omega, weights, x) -> np.ndarray:
        """Standard deviations (n, 2) of the drag strips' longitudinal and transverse velocities for motions
        ``x`` (Nw, ..., 6) per unit of a process with spectral ``weights`` (Nw, ...) = S(ω) dω."""
        G = self.environment.strip_maps()
        x = np.asarray(x).reshape(x.shape[0], -1, 6)                           # (Nw, K, 6)
        v = 1j * np.asarray(omega)[:, None, None] * x
        wts = np.asarray(weights, dtype=float).reshape(x.shape[0], -1)          # (Nw, K)
        return np.sqrt(np.einsum("wk,wkij->ij", wts, np.abs(np.einsum("ijd,wkd->wkij", G, v)) ** 2))

    def with_drag_linearised(self, db: HydroDB, wave_sigma=None, iterations: int = 20,
                             rtol: float = 1e-3) -> "LandingSetup":
        r"""The setup with the hull's drag damping linearised statistically: the damping :math:`B^s` of the
        cross-flow drag (:meth:`boatland.landing.environment.Environment.drag_damping`: Gaussian equivalent
        linearisation, :math:`B = 2k\,E|w|`) at the strips' velocity standard deviations σ — the gusts' part
        (iterated with the response, as σ depends on B, to a relative change below ``rtol``) and the waves'
        ``wave_sigma`` (n, 2), added in quadrature (independent processes); the drag's mean load grows with the
        same σ (:meth:`boatland.landing.environment.Environment.drag_mean_shift`) and enters the steady force.
        Without a cross-flow drag, the setup as it is; without gusts, only the waves' σ."""
        if not self.drag_linearisable:
            return self
        env, st = self.environment, self.steady
        B_det = env.current_damping()
        B_0 = env.drag_damping(np.zeros(env.strip_maps().shape[:2]))
        sw = None if wave_sigma is None else np.asarray(wave_sigma, dtype=float)

        def damped(sig_g):
            sig = sig_g if sw is None else np.sqrt(sig_g ** 2 + sw ** 2)
            return self.replace(steady=dataclasses.replace(st, damping=B_det + env.drag_damping(sig) - B_0,
                                                           force=st.force + env.drag_mean_shift(sig)))

        sig_g = np.zeros(env.strip_maps().shape[:2])
        setup = damped(sig_g)
        if st.gust_pattern is None:
            return setup
        for _ in range(iterations):
            w, wt, x, _ = setup.gust_response(db)
            new = setup.strip_sigma(w, st.gust_spectrum(w) * wt, x)
            done = np.all(np.abs(new - sig_g) <= rtol * max(float(new.max()), 1e-12))
            sig_g = new
            setup = damped(sig_g)
            if done:
                break
        # λ, the linear share of the swing's damping: for one lightly damped mode σ² ∝ 1/c, so the ratio of its
        # variance with the linearised drag to that with the drag's linear part only (its derivative at the
        # mean current; the waves' share counted as linear, they set it whatever the swing does)
        lin = self.replace(steady=dataclasses.replace(st, damping=B_det + (0.0 if sw is None else
                                                                             env.drag_damping(sw) - B_0)))
        w, wt, x, _ = lin.gust_response(db)
        s_lin = float(np.sum(lin.strip_sigma(w, st.gust_spectrum(w) * wt, x) ** 2))
        w, wt, x, _ = setup.gust_response(db)
        s_all = float(np.sum(setup.strip_sigma(w, st.gust_spectrum(w) * wt, x) ** 2))
        share = min(1.0, s_all / s_lin) if s_lin > 0 else 1.0
        return setup.replace(steady=dataclasses.replace(setup.steady, linear_share=share))

    def with_drift(self, db: HydroDB, parts, water_depth: float | None = None) -> "LandingSetup":
        """The setup with the mean wave drift of the sea ``parts`` (spectral parts, global directions) added to its
        steady loads, when the scenario applies drift (``sea.drift``); the setup itself otherwise.

        The expected mean :math:`\\sum_i a_i^2 D(\\omega_i, \\theta_i - \\psi)` of the parts' components (their
        amplitudes are the spectrum's: deterministic), :func:`boatland.sea.drift.mean_drift`. It depends on the sea
        (∝ H_s², on the direction), so a table over T_p and directions (:func:`~boatland.freqdomain.screening.
        screening_grid`) leaves it out; it is tens of newtons at ctv27's landing limits (README)."""
        env = self.environment
        if env is None or env.drift == "none" or getattr(db, "drift", None) is None:
            return self
        sea = SeaState(parts=tuple(parts), water_depth=math.inf if water_depth is None else float(water_depth),
                       g=float(db.g))
        F = mean_drift(db, sea.realise(0, 1800.0), self.heading_deg)
        st = self.steady if self.steady is not None else SteadyLoad(force=np.zeros(6), stiffness=np.zeros((6, 6)),
                                                                     damping=np.zeros((6, 6)))
        return self.replace(steady=dataclasses.replace(st, force=st.force + F))

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
        radius, position, depth = self.pile.radius, self.pile.offset(*self.position), self.pile.water_depth
        cols = None
        if beta_deg is not None and periodic_directions(db.wave_dir_deg):
            j, j1, _, _ = direction_brackets(np.atleast_1d(np.asarray(beta_deg, dtype=float)), db.wave_dir_deg, True)
            cols = tuple(int(c) for c in np.unique(np.concatenate([j, j1])))
            if len(cols) == db.n_dir:
                cols = None
        layout = (float(radius), float(position[0]), float(position[1]), float(depth), float(self.heading_deg))
        per_db = _NEAR_PILE.setdefault(db, {})
        for (made, made_cols), near in per_db.items():   # a table made for more columns serves fewer
            if made == layout and (made_cols is None or (cols is not None and set(cols) <= set(made_cols))):
                return near
        key = (layout, cols)
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
    def from_scenario(cls, scenario, db: HydroDB, *, roll_limit_deg: float | None = None,
                      setup: Setup | None = None) -> "LandingSetup":
        """The landing of a validated scenario, as its time domain runs it (the same
        :class:`~boatland.landing.contacts.FenderOnLanding`): its fender points, the tubes' normals in the
        vessel's axes, μ_s, thrust, the fender's normal and shear laws (the shear damping from its ratio of
        critical for this vessel), additional linear damping, heading, and the monopile's scattered wave
        when the trial applies it. Roll limit: ``roll_limit_deg``, else the largest of
        ``incidents.roll_limit_deg``, else 10°. ``setup``: ``Setup.of(scenario, db)`` when at hand.

        Raises
        ------
        BoatlandInputError
            The scenario has no landing, fender or thrust (keys named).
        """
        src = scenario.source
        for key in ("landing", "fender", "thrust"):
            if getattr(scenario, key) is None:
                raise BoatlandInputError(f"{src}: [{key}] is missing: screening needs a landing, a fender and a thrust")
        f = scenario.fender
        P = np.asarray(f.points, dtype=float)
        if len(scenario.landing.struts) != P.shape[0]:
            raise BoatlandInputError(f"{src}: fender.points: {P.shape[0]} points for {len(scenario.landing.struts)} "
                                     "struts")
        setup = Setup.of(scenario, db, setup)
        lim = roll_limit_deg
        if lim is None:
            lim = max(scenario.incidents.roll_limit_deg) if scenario.incidents.roll_limit_deg else 10.0
        fol = setup.fender
        landing = cls(points=P, normals=fol.normals_3d, mu=f.mu_s, thrust=scenario.thrust.force,
                      thrust_position=scenario.thrust.position, stiffness=f.stiffness, damping=f.damping,
                      shear_stiffness=f.shear_stiffness, shear_damping=fol.shear_damping, sideways=f.sideways,
                      additional_damping=setup.additional_damping()[0], heading_deg=scenario.vessel.heading_deg,
                      roll_limit_deg=lim, pile=setup.pile, position=setup.start_pose[:2], fender_width=f.width,
                      tube_radius=np.array([st.diameter / 2 for st in scenario.landing.struts]),
                      thrust_direction=setup.environment.push_direction,
                      steady=setup.environment.steady_load(),
                      environment=setup.environment)
        landing.check_on_hull(db, src)
        return landing.with_drag_linearised(db)
