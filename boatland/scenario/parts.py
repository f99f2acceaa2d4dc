r"""The parts of a :class:`~boatland.scenario.scenario.Scenario`: small frozen records, SI units inside.

Each part holds validated values (the loader in :mod:`boatland.scenario.scenario` checks them with key
paths) and offers the few derived quantities the services need: strut normals and contact planes,
the Stribeck friction law, the wave model adapted to a database, the start pose.

Geometry (DESIGN.md §2): global frame z up, origin on the mean free surface at the monopile axis;
body frame x forward, y to port, z up, origin at the database's reference point. A strut is a
vertical cylinder at ``position`` (global x, y); its contact plane is vertical, with unit normal
:math:`n = (\cos\theta_n, \sin\theta_n, 0)` pointing from the landing towards the vessel, and touches
the strut surface at :math:`q = s + (d/2)\,n`. A fender point :math:`r` (body) is at
:math:`p + R(\psi) r` at the start pose; its gap to the plane is :math:`(p + R(\psi) r - q)\cdot n`
(negative = penetration).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from boatland.loads.skipper import Skipper
from boatland.vessel.database import HydroDB
from boatland.sea.states import MeasuredRecord, RegularWave, SeaState

__all__ = ["Fender", "Incidents", "InitialState", "Landing", "Output", "Radiation", "Sea", "Simulation", "Strut",
           "Thrust", "VesselSetup", "derive_position", "rotation_2d", "unit"]


def _cos_sin(angle_deg: float) -> tuple[float, float]:
    """cos, sin of an angle in degrees, exact (0, ±1) at multiples of 90° (no 6e-17 residues)."""
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    return (0.0 if abs(c) < 1e-15 else c), (0.0 if abs(s) < 1e-15 else s)


def unit(angle_deg: float) -> np.ndarray:
    """Horizontal unit vector (cos θ, sin θ) of a direction in degrees."""
    return np.array(_cos_sin(angle_deg))


def rotation_2d(heading_deg: float) -> np.ndarray:
    """2×2 rotation from the body to the global frame for a heading ψ [deg] (yaw about z)."""
    c, s = _cos_sin(heading_deg)
    return np.array([[c, -s], [s, c]])


@dataclass(frozen=True, kw_only=True)
class Simulation:
    """Time stepping.

    Attributes
    ----------
    duration : float
        Simulated time [s].
    dt : float or None
        RK4 step [s] as given; None = the default rule (:func:`boatland.landing.setup.time_step`).
    seed : int
        Seed of the random wave phases.
    start_ramp : float
        Half-cosine start-up ramp of the waves [s] (the sea's default, 2 Tp, when not given).
    """

    duration: float
    dt: float | None
    seed: int
    start_ramp: float


@dataclass(frozen=True, kw_only=True)
class VesselSetup:
    """The vessel: which database, where it starts, what damping is added.

    Attributes
    ----------
    database : str
        As written: a built-in name or a path.
    database_path : Path or None
        The resolved file for a path (relative to the scenario file); None for a built-in name.
    heading_deg, position : float, (float, float)
        Start pose: global direction of the x axis [deg] and global position of the reference
        point [m] (derived when not given: see ``heading_derived``, ``position_derived``).
    linear_damping, quadratic_damping : tuple of 6 float
        Additional damping per DOF (diagonal) [N s/m, N m s/rad] and [N s²/m², N m s²/rad²].
    roll_critical_fraction : float
        Extra roll damping ζ as a fraction of critical (:func:`boatland.landing.setup.additional_damping`).
    """

    database: str
    database_path: Path | None
    heading_deg: float
    position: tuple[float, float]
    heading_derived: bool
    position_derived: bool
    linear_damping: tuple[float, ...]
    quadratic_damping: tuple[float, ...]
    roll_critical_fraction: float

    @property
    def is_builtin(self) -> bool:
        return self.database_path is None

    @property
    def database_key(self) -> str:
        """The database as one string — its resolved file, or the built-in name: scenarios with the same key
        share one loaded database (a campaign loads each once)."""
        return str(self.database_path or self.database)


@dataclass(frozen=True, kw_only=True)
class Radiation:
    """Radiation memory: ``method`` ("convolution" | "state_space"), ``memory`` T_K [s], IRF ``tail``/``taper``."""

    method: str
    memory: float
    tail: str
    taper: str


@dataclass(frozen=True)
class Strut:
    """A vertical strut (tube) of the boat landing: axis ``position`` (global) [m], ``diameter`` [m],
    the horizontal direction ``normal_deg`` from the landing towards the vessel at this tube (where the
    fender meets it at rest), and its ends ``bottom`` and ``top`` (global z [m]; ±inf: unbounded)."""

    position: tuple[float, float]
    diameter: float
    normal_deg: float
    bottom: float = -math.inf
    top: float = math.inf

    @property
    def normal(self) -> np.ndarray:
        """Unit normal (2,) of the contact plane, global."""
        return unit(self.normal_deg)

    @property
    def plane_point(self) -> np.ndarray:
        """Where the contact plane touches the strut surface: s + (d/2) n (2,), global [m]."""
        return np.asarray(self.position) + 0.5 * self.diameter * self.normal


@dataclass(frozen=True, kw_only=True)
class Landing:
    """The monopile and its boat landing.

    ``bearing_deg`` is the compact form's direction from the pile axis to the landing (None when the
    struts were given explicitly).
    """

    monopile_diameter: float
    monopile_position: tuple[float, float]
    struts: tuple[Strut, ...]
    bearing_deg: float | None = None
    diffraction: bool | None = None     # None: on when the database has a hull mesh

    @property
    def normals(self) -> np.ndarray:
        """(N, 2) unit normals of the contact planes."""
        return np.array([s.normal for s in self.struts])

    @property
    def plane_points(self) -> np.ndarray:
        """(N, 2) points of the contact planes on the strut surfaces [m]."""
        return np.array([s.plane_point for s in self.struts])

    @property
    def mean_normal(self) -> np.ndarray:
        """Unit vector along the sum of the normals (the direction the landing faces)."""
        n = self.normals.sum(axis=0)
        return n / np.linalg.norm(n)

    def facing_heading_deg(self) -> float:
        """Heading [deg] with the bow pointing at the landing (against the mean normal)."""
        n = self.mean_normal
        return math.degrees(math.atan2(-n[1], -n[0])) % 360.0


@dataclass(frozen=True, kw_only=True)
class Fender:
    r"""The bow fender: contact points and the contact law (Ferreira González 2023 §2.5, §3.4).

    Normal force per contact :math:`f_n = c_f\,\Delta x + d_f\,\Delta\dot x \ge 0`; friction
    coefficient :math:`\mu(v) = \mu_k + (\mu_s - \mu_k)\,e^{-(|v|/v_{ref})^\delta} + k_v |v|`
    (Stribeck, Ferreira González 2023 eq. 2.78), :math:`\mu_s` while stuck.

    Tangentially the rubber shears while it sticks (stiffness k_t, damping c_t per contact) and slides
    once its force reaches μ f_n (:mod:`boatland.contact.fender`); ``shear_stiffness = inf`` is the
    rigid stick of Ferreira González (2023).

    Attributes
    ----------
    points : tuple of (x, y, z)
        Centre of the fender line at each contact, body frame [m]; ``points[i]`` meets ``landing.struts[i]``.
    stiffness, damping : float
        c_f [N/m] and d_f [N s/m] per contact.
    shear_stiffness : float
        k_t [N/m] per contact (``inf``: rigid stick).
    shear_damping : float or None
        c_t [N s/m] per contact as given; None: ``shear_damping_ratio`` of critical (needs the vessel).
    shear_damping_ratio : float
        ζ of the shear mode, c_t = 2ζ√(k_t m_eff) (used when ``shear_damping`` is None).
    width : float
        Length of the fender line at each contact, along the body y axis [m] (0: a point).
    mu_s, mu_k, k_v, v_ref, delta : float
        Friction law ([-], [-], [s/m], [m/s], [-]).
    sideways : bool
        Friction (and shear) also horizontally along the tube, not only vertically.
    preset : str or None
        The preset the values came from (explicit keys override it).
    """

    points: tuple[tuple[float, float, float], ...]
    stiffness: float
    damping: float
    mu_s: float
    mu_k: float
    k_v: float
    v_ref: float
    delta: float
    sideways: bool
    shear_stiffness: float = math.inf
    shear_damping: float | None = None
    shear_damping_ratio: float = 0.0
    width: float = 0.0
    preset: str | None = None

    @property
    def rigid(self) -> bool:
        """True for the rigid stick (no shear compliance)."""
        return not math.isfinite(self.shear_stiffness)

    @property
    def points_array(self) -> np.ndarray:
        """(N, 3) contact points, body frame [m]."""
        return np.array(self.points, dtype=float)

    def mu(self, v) -> np.ndarray:
        """Kinetic friction coefficient μ(v) of the Stribeck law at sliding speed ``v`` [m/s]."""
        v = np.abs(np.asarray(v, dtype=float))
        return self.mu_k + (self.mu_s - self.mu_k) * np.exp(-(v / self.v_ref) ** self.delta) + self.k_v * v


@dataclass(frozen=True, kw_only=True)
class Thrust:
    """Bollard push ``force`` [N] at ``position`` (body) [m], ramped in over ``ramp`` [s], along the body's
    horizontal direction ``direction_deg`` from the x axis towards port (or ``"trim"``: the skipper's angle
    against the steady yaw moment); ``control``: how the skipper holds it
    (:class:`boatland.loads.skipper.Skipper`: a constant push by default)."""

    force: float
    position: tuple[float, float, float]
    ramp: float
    direction_deg: float | str = "trim"
    control: Skipper = Skipper()

    @property
    def trimmed(self) -> bool:
        """The push's direction is the skipper's trim against the steady yaw moment
        (:meth:`boatland.landing.environment.Environment.of`), not a given angle."""
        return self.direction_deg == "trim"


@dataclass(frozen=True, kw_only=True, eq=False)
class Sea:
    """The waves of a scenario.

    Attributes
    ----------
    kind : str
        "jonswap", "pm", "tma" (one spectrum), "parts" (a sum), "regular" or "measured".
    waves : SeaState or RegularWave or MeasuredRecord
        The wave model (directions already global; water depth as given, else deep until
        :meth:`model` adapts it to a database).
    water_depth : float or None
        The site depth given in the file [m] (inf = deep); None = the database's.
    peak_period : float
        Shortest peak period of the sea [s] (Tp of the parts, T of a regular wave, the period of a
        record's largest component): sets the default time step Tp/100.
    shortest_period : float
        Period [s] above whose frequency only 1 % of the wave variance lies (the regular wave's T):
        the time step must resolve it (dt ≤ shortest_period / 20).
    drift : str
        The second-order wave drift applied: "none", "mean" or "newman" (:mod:`boatland.sea.drift`).
    """

    kind: str
    waves: SeaState | RegularWave | MeasuredRecord
    water_depth: float | None
    peak_period: float
    shortest_period: float
    drift: str = "none"

    def model(self, db: HydroDB | None = None) -> SeaState | RegularWave | MeasuredRecord:
        """The wave model for a run with ``db``: its water depth (unless the file gave one) and g."""
        w = self.waves
        depth = self.water_depth
        if depth is None:
            depth = db.water_depth if db is not None else w.water_depth
        g = db.g if db is not None else w.g
        if depth == w.water_depth and g == w.g:
            return w
        return dataclasses.replace(w, water_depth=float(depth), g=float(g))


@dataclass(frozen=True, kw_only=True, eq=False)
class InitialState:
    """Initial displacement and velocity relative to the start pose, SI (m, rad; m/s, rad/s), (6,) each."""

    displacement: np.ndarray
    velocity: np.ndarray

    def __post_init__(self):
        for name in ("displacement", "velocity"):
            a = np.array(getattr(self, name), dtype=float).reshape(6)
            a.setflags(write=False)
            object.__setattr__(self, name, a)


@dataclass(frozen=True)
class Incidents:
    """The ``[incidents]`` table: each key's thresholds, ascending and unique — which incident definitions
    a trial reports (:func:`boatland.trial.incidents.trial_incidents` makes them).

    Attributes
    ----------
    values : mapping of str to tuple
        ``{"slip_distance": (0.1, 0.3), "roll_limit_deg": (10.0,), "slide_within": ((0.5, 120.0),)}`` — slip
        distances [m], roll limits [deg]; a key whose entries are tables has a tuple of each table's numbers
        (``slide_within``: distance [m], window [s]).
    """

    values: Mapping[str, tuple]

    @classmethod
    def from_table(cls, table: Mapping[str, Any]) -> "Incidents":
        """From the validated table (each value a number, a list of numbers or a list of tables)."""
        out = {}
        for key, v in table.items():
            if isinstance(v, (list, tuple)) and v and isinstance(v[0], Mapping):
                out[key] = tuple(sorted({tuple(float(x) for x in item.values()) for item in v}))
            else:
                out[key] = tuple(sorted(set(np.atleast_1d(np.asarray(v, dtype=float)).tolist())))
        return cls(out)

    @property
    def slip_distance(self) -> tuple[float, ...]:
        return self.values.get("slip_distance", ())

    @property
    def roll_limit_deg(self) -> tuple[float, ...]:
        return self.values.get("roll_limit_deg", ())


@dataclass(frozen=True, kw_only=True)
class Output:
    """What a run writes: time series ``file`` (HDF5), run ``log`` (MCAP), every ``decimate``-th step."""

    file: str | None
    log: str | None
    decimate: int


def derive_position(landing: Landing, points_xy: np.ndarray, heading_deg: float) -> tuple[float, float]:
    r"""Reference-point position (x, y) that puts the fender just on the struts.

    Laterally (along :math:`t = \hat z \times \bar n`, :math:`\bar n` the mean normal) the fender
    points are centred on the struts: :math:`\sum_i (p + R r_i - s_i)\cdot t = 0`. Along
    :math:`\bar n` the vessel is moved until the nearest contact touches (smallest gap zero, the
    others open): :math:`a = \max_i [-(b\,t + R r_i - q_i)\cdot n_i / (\bar n \cdot n_i)]`.

    Parameters
    ----------
    landing : Landing
    points_xy : ndarray, shape (N, 2)
        Fender points (body x, y) [m], one per strut.
    heading_deg : float
        Heading ψ of the vessel [deg].
    """
    R = rotation_2d(heading_deg)
    nbar = landing.mean_normal
    t = np.array([-nbar[1], nbar[0]])
    rg = points_xy @ R.T
    s = np.array([st.position for st in landing.struts], dtype=float)
    b = -float(np.mean((rg - s) @ t))
    n, q = landing.normals, landing.plane_points
    a = max(-float((b * t + rg[i] - q[i]) @ n[i]) / float(nbar @ n[i]) for i in range(len(s)))
    p = a * nbar + b * t
    return float(p[0]), float(p[1])
