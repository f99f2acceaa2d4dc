r"""The fender on the landing's tubes in the vessel's axes: one adapter behind the kernel's contacts
(:class:`boatland.contact.fender.Contacts`) and the frequency domain's contact law
(:class:`boatland.landing.law.ContactLaw`).

:func:`fender_on_landing` turns a scenario's fender and tubes into the local frame once (origin at the
reference point's start position, axes along the vessel at rest): the tubes' axes and normals, their
radii (a flat plate where the fender is a lumped spring compressed past the tubes' axes), the rubber's
shear damping from its ratio of critical on this vessel, and the contact dynamics
(:class:`ContactPeriod`) that bound the time step. :meth:`FenderOnLanding.kernel_contacts` and
:meth:`FenderOnLanding.contact_law` give the two views of that one description.

References: Ferreira González, D. (2023), *Development of a Numerical Approach for the Simulation of
Boatlanding Maneuvers*, Dr.-Ing. dissertation, TU Hamburg (§3.4: the contact plane; Table 5.4); Grøtting,
H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc thesis, NTNU
(§3.2.2: the compliant rubber, 5 % of critical damping).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.contact.fender import Contacts, contact_set
from boatland.errors import BoatlandInputError
from boatland.landing.law import ContactLaw, normal_follows
from boatland.scenario.parts import rotation_2d
from boatland.vessel.database import HydroDB

__all__ = ["ContactPeriod", "FenderOnLanding", "STEPS_PER_CONTACT_PERIOD", "STEPS_PER_SHEAR_PERIOD",
           "contact_directions", "contact_period", "fender_on_landing", "lumped_fender", "mass_matrix"]

#: dt must resolve the fastest normal contact mode with this many steps (impacts, loss of contact) ...
STEPS_PER_CONTACT_PERIOD = 20
#: ... and the stuck rubber's fastest (linear) shear mode with this many.
STEPS_PER_SHEAR_PERIOD = 8


@dataclass(frozen=True)
class ContactPeriod:
    r"""The fender's contact dynamics on the vessel.

    Attributes
    ----------
    period : float
        :math:`T_c = 2\pi / \max|\lambda|` [s] of the normal contact: λ the eigenvalues of
        :math:`(M + A_\infty)\ddot x + D\dot x + K x = 0` with :math:`K = c_f \sum_i g_i g_i^\top`,
        :math:`D = d_f \sum_i g_i g_i^\top`, :math:`g_i = (n_i, r_i \times n_i)` the generalized
        direction of contact i (normal n_i in the body frame, point r_i): all contacts closed.
    shear_period : float
        The same with the rubber's shear springs and dampers added in the tangential directions
        :math:`t_v = e_z` (and :math:`t_h = e_z \times n_i` with sideways friction) — the stuck fender's
        fastest mode [s]; ``inf`` for a rigid stick.
    m_eff : tuple of float
        Effective mass of the vessel at each contact point along its normal,
        :math:`m_{eff} = 1 / (g^\top (M + A_\infty)^{-1} g)` [kg].
    m_eff_vertical : tuple of float
        The same vertically (:math:`g = (e_z, r_i \times e_z)`) [kg]: it sets the critical shear damping.
    undamped : tuple of float
        :math:`T_f = 2\pi\sqrt{m_{eff}/c_f}` of each contact alone [s].
    shear_damping : tuple of float
        c_t of each contact [N s/m] (the file's, or ζ·2√(k_t m_eff,vertical)); 0 for a rigid stick.
    """

    period: float
    shear_period: float
    m_eff: tuple[float, ...]
    m_eff_vertical: tuple[float, ...]
    undamped: tuple[float, ...]
    shear_damping: tuple[float, ...]

    @property
    def dt_limit(self) -> float:
        """Largest time step the contact allows [s]: T_c / 20 for the normal contact (impacts) and
        T_shear / 8 for the stuck rubber's linear mode (RK4 at ωΔt = 2π/8: period 0.3 % short,
        amplitude kept to 0.1 % per period)."""
        return min(self.period / STEPS_PER_CONTACT_PERIOD, self.shear_period / STEPS_PER_SHEAR_PERIOD)


def mass_matrix(db: HydroDB) -> np.ndarray:
    """:math:`M + A_\\infty` of ``db`` (A at the top of the band without A∞).

    Raises
    ------
    BoatlandInputError
        The database has no mass matrix.
    """
    if db.M is None:
        raise BoatlandInputError(f"database {db.name!r} has no mass matrix M: a time-domain run needs it")
    A_inf = db.A_inf if db.A_inf is not None else db.A[:, :, -1]
    return np.asarray(db.M, float) + np.asarray(A_inf, float)


def _fastest_period(Minv: np.ndarray, K: np.ndarray, D: np.ndarray) -> float:
    A = np.block([[np.zeros((6, 6)), np.eye(6)], [-Minv @ K, -Minv @ D]])
    lam = float(np.max(np.abs(np.linalg.eigvals(A))))
    return 2 * math.pi / lam if lam > 0 else math.inf


def contact_directions(scenario) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    r"""Per contact at rest, body frame: (normal g_n, vertical g_v, horizontal g_h) generalized directions
    :math:`g = (d, r \times d)` of the fender point r along n (landing → vessel), e_z and e_z × n."""
    f, land = scenario.fender, scenario.landing
    Rt = rotation_2d(scenario.vessel.heading_deg).T  # global → body
    out = []
    for r, strut in zip(f.points_array, land.struts):
        n = np.array([*(Rt @ strut.normal), 0.0])
        tv = np.array([0.0, 0.0, 1.0])
        th = np.cross(tv, n)
        out.append(tuple(np.concatenate([d, np.cross(r, d)]) for d in (n, tv, th)))
    return out


def contact_period(scenario, db: HydroDB) -> ContactPeriod:
    """The contact dynamics of ``scenario``'s fender on the vessel of ``db`` (:class:`ContactPeriod`)."""
    f = scenario.fender
    Minv = np.linalg.inv(mass_matrix(db))
    dirs = contact_directions(scenario)
    Gn = np.array([g[0] for g in dirs])
    K = f.stiffness * Gn.T @ Gn
    D = f.damping * Gn.T @ Gn
    period = _fastest_period(Minv, K, D)
    m_eff = tuple(float(1.0 / (g @ Minv @ g)) for g in Gn)
    m_vert = tuple(float(1.0 / (g[1] @ Minv @ g[1])) for g in dirs)
    if f.rigid:
        c_t = (0.0,) * len(dirs)
        shear_period = math.inf
    else:
        if f.shear_damping is not None:
            c_t = (f.shear_damping,) * len(dirs)
        else:
            c_t = tuple(2 * f.shear_damping_ratio * math.sqrt(f.shear_stiffness * m) for m in m_vert)
        Kt, Dt = K.copy(), D.copy()
        for (_, gv, gh), c in zip(dirs, c_t):
            for g in ((gv, gh) if f.sideways else (gv,)):
                Kt += f.shear_stiffness * np.outer(g, g)
                Dt += c * np.outer(g, g)
        shear_period = _fastest_period(Minv, Kt, Dt)
    undamped = tuple(2 * math.pi * math.sqrt(m / f.stiffness) for m in m_eff)
    return ContactPeriod(period=period, shear_period=shear_period, m_eff=m_eff, m_eff_vertical=m_vert,
                         undamped=undamped, shear_damping=tuple(float(c) for c in c_t))


def lumped_fender(scenario) -> bool:
    """True when the fender's static compression under the thrust, F_b / (N c_f), reaches a tube's radius:
    its spring is a lumped compliance (the tank model's c_f = 0.5 kN/m: 0.12 m under 62 N on 17 mm tubes)
    and the fender pushes on a flat plate at the tubes' front, along the landing's normal — the contact
    plane of Ferreira González (2023) — instead of meeting round tubes (:mod:`boatland.contact.fender`)."""
    f, land, thr = scenario.fender, scenario.landing, scenario.thrust
    if f is None or land is None or thr is None:
        return False
    return thr.force / len(f.points) / f.stiffness >= min(st.diameter for st in land.struts) / 2


@dataclass(frozen=True, eq=False)
class FenderOnLanding:
    """A scenario's fender on its landing's tubes, in the vessel's axes at rest (:func:`fender_on_landing`).

    Attributes
    ----------
    fender : boatland.scenario.parts.Fender
        The fender as the file gives it (points, normal and shear laws, friction).
    struts : tuple of boatland.scenario.parts.Strut
        The landing's tubes (``struts[i]`` meets ``fender.points[i]``).
    normals : ndarray, shape (Np, 2)
        Unit horizontal normals of the tubes at rest (landing → vessel), local frame.
    axes : ndarray, shape (Np, 2)
        Tube axes (x, y), local frame [m] — for a lumped fender the flat plates' points at the tubes' front.
    radius : ndarray, shape (Np,)
        Tube radii [m] (``inf``: a flat plate, :func:`lumped_fender`).
    period : ContactPeriod or None
        The contact dynamics on this vessel (None when the database has no mass matrix).
    """

    fender: object
    struts: tuple
    normals: np.ndarray
    axes: np.ndarray
    radius: np.ndarray
    lumped: bool
    compression: float
    period: ContactPeriod | None

    @property
    def n_points(self) -> int:
        return len(self.struts)

    @property
    def shear_damping(self) -> np.ndarray | float:
        """c_t per contact [N s/m] (:attr:`ContactPeriod.shear_damping`); 0.0 for the rigid stick."""
        if self.fender.rigid:
            return 0.0
        if self.period is None:
            raise BoatlandInputError("the fender's shear damping needs the vessel's mass matrix")
        return np.asarray(self.period.shear_damping)

    @property
    def normals_3d(self) -> np.ndarray:
        """(Np, 3) the :attr:`normals` with z = 0."""
        return np.column_stack([self.normals, np.zeros(self.n_points)])

    def kernel_contacts(self) -> Contacts:
        """The kernel's :class:`~boatland.contact.fender.Contacts`: fender lines along the body y axis on the
        tubes, the normal and shear laws, the friction law."""
        f, struts = self.fender, self.struts
        c_t = tuple(self.shear_damping) if not f.rigid else 0.0
        return contact_set(f.points_array, self.axes, self.radius, self.normals, direction=(0.0, 1.0, 0.0),
                           half_width=f.width / 2, bottom=[st.bottom for st in struts],
                           top=[st.top for st in struts], stiffness=f.stiffness, damping=f.damping,
                           shear_stiffness=f.shear_stiffness, shear_damping=c_t, mu_s=f.mu_s,
                           mu_k=f.mu_k, k_v=f.k_v, v_ref=f.v_ref, delta=f.delta, sideways=f.sideways)

    def follows(self) -> dict:
        """How the contact normals turn (:func:`boatland.landing.law.normal_follows`)."""
        return normal_follows(self.fender.width, [s.diameter / 2 for s in self.struts], self.compression)

    def contact_law(self) -> ContactLaw:
        """The linear restraint of each contact (:class:`~boatland.landing.law.ContactLaw`): the points, the
        tubes' normals, the normal spring–damper, the rubber's shear spring and damper or the rigid stick."""
        f = self.fender
        return ContactLaw(f.points_array, self.normals_3d, f.stiffness, f.damping, f.shear_stiffness,
                          self.shear_damping, sideways=f.sideways, **self.follows())


def fender_on_landing(scenario, db: HydroDB, start_pose=None) -> FenderOnLanding | None:
    """The scenario's fender on its landing in the vessel's axes (:class:`FenderOnLanding`); None without a
    landing or a fender. ``start_pose``: ``scenario.start_pose()`` when already at hand."""
    if scenario.fender is None or scenario.landing is None:
        return None
    x0, y0, psi = scenario.start_pose() if start_pose is None else start_pose
    c, s = np.cos(psi), np.sin(psi)
    to_local = np.array([[c, s], [-s, c]])                      # global → local rotation (by −ψ)
    struts = scenario.landing.struts
    axes = (np.array([st.position for st in struts], dtype=float) - [x0, y0]) @ to_local.T
    normals = scenario.landing.normals @ to_local.T
    radius = np.array([st.diameter / 2 for st in struts])
    lumped = lumped_fender(scenario)
    if lumped:   # compressed past the tubes' axes: a plate at their front (the thesis's plane)
        axes, radius = axes + radius[:, None] * normals, np.full(len(struts), np.inf)
    f = scenario.fender
    compression = scenario.thrust.force / len(f.points) / f.stiffness if scenario.thrust is not None else 0.0
    period = contact_period(scenario, db) if db.M is not None else None
    return FenderOnLanding(fender=f, struts=tuple(struts), normals=normals, axes=axes, radius=radius, lumped=lumped,
                           compression=compression, period=period)
