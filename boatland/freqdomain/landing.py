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
from boatland.landing.setup import Setup
from boatland.sea.pile import Pile, pile_scattered_excitation
from boatland.vessel.database import HydroDB
from boatland.waves.excitation import direction_brackets, periodic_directions

__all__ = ["LandingSetup"]

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
        radius, position, depth = self.pile.radius, self.pile.offset(*self.position), self.pile.water_depth
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
                      tube_radius=np.array([st.diameter / 2 for st in scenario.landing.struts]))
        landing.check_on_hull(db, src)
        return landing
