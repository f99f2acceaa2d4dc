r"""Response amplitude operators of the free vessel and of the vessel hinged at its fender point.

Free vessel (San Nicolás Méndez 2024 eq. 3.29–3.31):

.. math::
    Z(\omega)\,\hat x = X(\omega, \beta), \qquad
    Z(\omega) = -\omega^2\left(M + A(\omega)\right) + i\omega\left(B(\omega) + B_{add}\right) + C .

Vessel on its landing — "hinged" at body points :math:`r_c` (Grøtting 2015 §3.2.1, eq. 3.1–3.12, after Wu
2014: the translation of each point is zero, the rotations are free), or held there by the fender's
springs (the compliant rubber of :mod:`boatland.contact.fender`; the general linear restraint is
:class:`boatland.landing.law.ContactLaw`). With the 3 × 6 map of the motions to the
translation of a point,

.. math:: G_c\,\hat x = \hat x_{1:3} + \hat\theta \times r_c = [\,I \;\; -S(r_c)\,]\,\hat x,
          \qquad S(r)\,v = r \times v,

the reaction :math:`\hat J_c` (force *on the vessel* from the landing, at :math:`r_c`) has the
generalised force :math:`G_c^\top \hat J_c = [\hat J_c;\; r_c \times \hat J_c]` (eq. 3.3, 3.6), and
motions and reactions solve the augmented (saddle-point) system

.. math::
    \begin{bmatrix} Z & -G^\top \\ G & 0 \end{bmatrix}
    \begin{bmatrix} \hat x \\ \hat J \end{bmatrix} =
    \begin{bmatrix} X \\ 0 \end{bmatrix},

which is eq. 3.10–3.12 of Grøtting 2015 written without eliminating the translations (eq. 3.9): the same
solution, and it takes several points and the generalisation below without new algebra.

Generalisation: a spring–damper normal. A point may be pinned only in the two tangential directions
of a contact plane with unit normal :math:`n_c` (from the landing towards the vessel), i.e.
:math:`t_v` (vertical for a vertical strut) and :math:`t_h = e_z \times n_c` — the axes of the
time-domain fender (:mod:`boatland.contact.fender`) — while the normal carries the fender's linear
spring–damper, :math:`\hat J_{n,c} = -(k_{n,c} + i\omega d_{n,c})\, n_c^\top G_c \hat x`. With
:math:`T_c = [t_v\; t_h]` (3 × 2) the system becomes

.. math::
    \begin{bmatrix} Z + \sum_c (k_{n,c} + i\omega d_{n,c}) G_c^\top n_c n_c^\top G_c & -\mathcal T^\top \\
                    \mathcal T & 0 \end{bmatrix}
    \begin{bmatrix} \hat x \\ \hat\lambda \end{bmatrix} =
    \begin{bmatrix} X \\ 0 \end{bmatrix}, \qquad \mathcal T = [\,T_c^\top G_c\,]_c ,

and :math:`\hat J_c = T_c \hat\lambda_c + \hat J_{n,c}\, n_c`. As :math:`k_n \to \infty` it tends to
the rigid hinge. This is the frequency-domain image of the stuck fender of the time domain (linear
spring–damper normal, tangential stick).

Preload. Under a thrust the time domain oscillates about a preloaded equilibrium in which the thrust
follows the vessel's x axis (Grøtting 2015 §3.4, eq. 3.62–3.63) and the static contact forces turn their
moments with the vessel. Given the thrust, :func:`hinged_rao` finds that equilibrium and adds its
stiffness (:math:`Z \to Z - K_g`, :func:`preload_stiffness`). For ctv24 under 80 kN, leaving it out
puts the vertical reaction up to 3 % and 1.7° off the time domain; with it they agree within 0.05 %
(tests/validation/test_hinge_reaction.py).

Redundant constraints (two points on parallel struts both pinned sideways) make the split of that
reaction statically indeterminate; it is solved in the minimum-norm sense (shared equally), as the
time-domain stick solve does.

All quantities per unit wave amplitude, exp(+iωt), phase = lead over the incident crest at the
reference point; DOF order surge … yaw; body frame = local frame at rest (:mod:`boatland.conventions`).

Interpolation in ω (shared by both RAOs): A and B linearly (held at the first tabulated value below
the band); X linearly in ω and in β on its real and imaginary parts (periodically when the database
goes round the circle or is a checked symmetric half circle; other directions are refused), with
the exact long-wave limit X(0, β) = C[:, 2] below the band — the same interpolation the time-domain excitation
uses (:func:`boatland.sea.states.excitation_table`,
:func:`boatland.waves.excitation.interpolate_excitation`). Frequencies above the database's band are
refused.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.vessel.database import HydroDB
from boatland.landing.law import ContactLaw, point_map, preload_stiffness, solve_saddle_stack, static_preload, tangents
from boatland.sea.states import excitation_table
from boatland.vessel.directions import direction_problem
from boatland.waves.excitation import interpolate_excitation

__all__ = ["HingedResponse", "excitation_force", "free_rao", "hinged_rao", "impedance", "point_map",
           "preload_stiffness", "radiation_coefficients", "static_preload"]


def _omega(db: HydroDB, omega) -> np.ndarray:
    w = np.atleast_1d(np.asarray(omega, dtype=float))
    if w.ndim != 1 or not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ValueError("omega must be finite frequencies > 0 [rad/s] (a scalar or a 1-D array)")
    if np.any(w > db.omega[-1] * (1 + 1e-12)):
        raise ValueError(f"omega up to {w.max():.4g} rad/s is above the band of database {db.name!r} "
                         f"({db.omega[0]:.4g}–{db.omega[-1]:.4g} rad/s): its A, B and X are unknown there")
    return w


def _beta(db: HydroDB, beta_deg) -> np.ndarray:
    """The directions asked for, checked against those the database covers (a half circle of a hull it
    shows port–starboard symmetric counts as the full circle: :mod:`boatland.vessel.directions`)."""
    if beta_deg is None:
        return np.asarray(db.wave_dir_deg, dtype=float).copy()
    b = np.atleast_1d(np.asarray(beta_deg, dtype=float))
    if b.ndim != 1 or not np.all(np.isfinite(b)):
        raise ValueError("beta_deg must be finite directions [deg] (a scalar or a 1-D array)")
    problem = direction_problem(db, b)
    if problem:
        raise BoatlandInputError(f"beta_deg: {problem}")
    return b


def radiation_coefficients(db: HydroDB, omega) -> tuple[np.ndarray, np.ndarray]:
    """Added mass and damping at ``omega``, linear in ω (held at ``db.omega[0]`` below the band).

    Parameters
    ----------
    db : HydroDB
    omega : float or array_like, shape (Nw,)
        Frequencies [rad/s], > 0 and within the database's band at the top.

    Returns
    -------
    A, B : ndarray, shape (Nw, 6, 6)
    """
    w = _omega(db, omega)
    i = np.clip(np.searchsorted(db.omega, w, side="right") - 1, 0, db.n_freq - 2)
    f = np.clip((w - db.omega[i]) / (db.omega[i + 1] - db.omega[i]), 0.0, 1.0)[:, None, None]
    lerp = lambda T: (1 - f) * np.moveaxis(T[:, :, i], 2, 0) + f * np.moveaxis(T[:, :, i + 1], 2, 0)  # noqa: E731
    return lerp(db.A), lerp(db.B)


def excitation_force(db: HydroDB, omega, beta_deg=None) -> np.ndarray:
    r"""Excitation X(ω, β) per unit wave amplitude, shape (Nw, Nβ, 6) complex [N/m, N m/m].

    Bilinear in (ω, β) on real and imaginary parts, towards the long-wave limit
    :math:`X(0,\beta) = C_{:,2}` below the band — exactly what the time-domain excitation uses
    (:func:`boatland.sea.states.excitation_table`): periodic in β when the database goes round the
    circle, or is a half circle of a hull it shows port–starboard symmetric (completed by
    :math:`X_j(360° - \beta) = s_j X_j(\beta)`). ``beta_deg`` None = the database's directions.

    Raises
    ------
    BoatlandInputError
        A direction outside those the database covers (an asymmetric or partial table, a single
        direction): :func:`boatland.vessel.directions.direction_problem`.
    """
    w = _omega(db, omega)
    b = _beta(db, beta_deg)
    om, bt, X = excitation_table(db)
    wc = np.repeat(w, b.size)
    bc = np.tile(b, w.size)
    Xc, _, _ = interpolate_excitation(wc, bc, om, bt, X)
    return Xc.T.reshape(w.size, b.size, 6)


def impedance(db: HydroDB, omega, additional_damping=None) -> np.ndarray:
    r"""Mechanical impedance :math:`Z = -\omega^2 (M + A(\omega)) + i\omega (B(\omega) + B_{add}) + C`.

    Parameters
    ----------
    db : HydroDB
        Needs the mass matrix ``M``.
    omega : float or array_like, shape (Nw,)
    additional_damping : array_like, shape (6, 6) or (6,), optional
        Extra linear damping B_add (a 6-vector is its diagonal) [N s/m, N m s/rad].

    Returns
    -------
    Z : ndarray of complex, shape (Nw, 6, 6)
    """
    if db.M is None:
        raise ValueError(f"database {db.name!r} has no mass matrix: give mass, centre of gravity and inertia")
    w = _omega(db, omega)
    A, B = radiation_coefficients(db, w)
    if additional_damping is not None:
        Bv = np.asarray(additional_damping, dtype=float)
        Bv = np.diag(Bv) if Bv.shape == (6,) else Bv
        if Bv.shape != (6, 6):
            raise ValueError(f"additional_damping must be (6, 6) or (6,), got {Bv.shape}")
        B = B + Bv
    ww = w[:, None, None]
    return -ww ** 2 * (db.M + A) + 1j * ww * B + db.C


def free_rao(db: HydroDB, omega, beta_deg=None, *, additional_damping=None) -> np.ndarray:
    r"""RAO of the freely floating vessel (San Nicolás Méndez 2024 eq. 3.31).

    .. math:: \hat x(\omega, \beta) = \left[-\omega^2 (M + A(\omega)) + i\omega (B(\omega) + B_{add})
              + C\right]^{-1} X(\omega, \beta)

    Parameters
    ----------
    db : HydroDB
        The vessel (with its mass matrix ``M``).
    omega : float or array_like, shape (Nw,)
        Wave frequencies [rad/s] (> 0, not above the database's band).
    beta_deg : float or array_like, shape (Nβ,), optional
        Wave directions relative to the vessel [deg] (direction of travel; 180° head seas); default
        the database's directions. Directions between tabulated ones are interpolated.
    additional_damping : array_like, shape (6, 6) or (6,), optional
        Extra linear (e.g. viscous roll) damping.

    Returns
    -------
    ndarray of complex, shape (Nw, Nβ, 6)
        Motion per unit wave amplitude [m/m, rad/m], phase = lead over the crest at the reference point.
    """
    Z = impedance(db, omega, additional_damping)
    X = excitation_force(db, omega, beta_deg)
    return np.linalg.solve(Z, np.swapaxes(X, 1, 2)).swapaxes(1, 2)


@dataclass(frozen=True, eq=False)
class HingedResponse:
    r"""Motions and hinge reactions of the hinged vessel per unit wave amplitude (exp(+iωt)), and the
    static preload it was linearised about.

    Attributes
    ----------
    omega : ndarray, shape (Nw,)
        Frequencies [rad/s].
    beta_deg : ndarray, shape (Nβ,)
        Wave directions relative to the vessel [deg].
    points : ndarray, shape (Np, 3)
        Hinge points, body frame [m].
    normals : ndarray, shape (Np, 3) or None
        Contact normals (landing → vessel) when given.
    law : ContactLaw
        What each point restrains (springs, pins).
    x : ndarray of complex, shape (Nw, Nβ, 6)
        Motions [m/m, rad/m].
    J : ndarray of complex, shape (Nw, Nβ, Np, 3)
        Reaction force on the vessel at each point, body (= local at rest) axes x, y, z [N/m].
    x_static : ndarray, shape (6,)
        Static displacement under the thrust [m, rad] (zero without thrust).
    J_static : ndarray, shape (Np, 3)
        Static reaction on the vessel at each point, local axes [N] (zero without thrust).
    x_loads, J_loads : ndarray of complex, shape (Nw, K, 6) and (Nw, K, Np, 3), or None
        The same per unit amplitude of each of the ``loads`` patterns (a gust's force), when asked.
    """

    omega: np.ndarray
    beta_deg: np.ndarray
    points: np.ndarray
    normals: np.ndarray | None
    law: ContactLaw
    x: np.ndarray
    J: np.ndarray
    x_static: np.ndarray
    J_static: np.ndarray
    x_loads: np.ndarray | None = None
    J_loads: np.ndarray | None = None

    def point_motion(self) -> np.ndarray:
        """Translation of each hinge point, shape (Nw, Nβ, Np, 3) [m/m] (zero where pinned)."""
        G = np.stack([point_map(p) for p in self.points])  # (Np, 3, 6)
        return np.einsum("pkd,wbd->wbpk", G, self.x)

    def contact_components(self, static: bool = False) -> np.ndarray:
        r"""Reactions in the contact axes (normal, vertical, horizontal) = :math:`(n, t_v, t_h)`.

        The same axes and signs as the time-domain contact output: ``fn`` along n, ``ft[..., 0]`` along
        :math:`t_v = e_z` and ``ft[..., 1]`` along :math:`t_h = e_z \times n`
        (:mod:`boatland.contact.fender`).

        Returns
        -------
        ndarray
            Complex (Nw, Nβ, Np, 3) [N/m]; with ``static=True`` the static preload, real (Np, 3) [N].
        """
        if self.normals is None:
            raise ValueError("no contact normals were given to hinged_rao")
        axes = np.stack([np.stack([n, *tangents(n)]) for n in self.normals])  # (Np, 3, 3): rows n, t_v, t_h
        if static:
            return np.einsum("pak,pk->pa", axes, self.J_static)
        return np.einsum("pak,wbpk->wbpa", axes, self.J)


def _per_point(value, n_points: int, name: str) -> np.ndarray:
    a = np.asarray(value, dtype=float)
    a = np.broadcast_to(a, (n_points,)) if a.ndim == 0 else a.reshape(-1)
    if a.shape != (n_points,) or np.any(a < 0) or np.any(np.isnan(a)):
        raise ValueError(f"{name} must be one value ≥ 0 or one per point ({n_points}), got {value!r}")
    return np.array(a)


def hinged_rao(db: HydroDB, omega, points, *, beta_deg=None, normal=None, stiffness=None, damping=None,
               shear_stiffness=None, shear_damping=None, sideways: bool = True, thrust: float = 0.0,
               thrust_position=(0.0, 0.0, 0.0), additional_damping=None, normal_follows: str = "fixed",
               tube_radius=np.inf, thrust_direction=(1.0, 0.0, 0.0), steady=None, loads=None) -> HingedResponse:
    r"""Motions and contact forces of the vessel on its landing (Grøtting 2015 §3.2.1 after Wu 2014).

    Solves (:mod:`boatland.landing.law`; Grøtting 2015 eq. 3.1–3.12)

    .. math::
        \begin{bmatrix} Z - K_g + \sum (k + i\omega c)\, G_c^\top d\,d^\top G_c & -\mathcal T^\top \\
                        \mathcal T & 0 \end{bmatrix}
        \begin{bmatrix} \hat x \\ \hat\lambda \end{bmatrix} =
        \begin{bmatrix} X \\ 0 \end{bmatrix}

    with :math:`Z = -\omega^2 (M + A) + i\omega (B + B_{add}) + C`, :math:`G_c = [I\;\; -S(r_c)]`, the
    springs (k, c) along the directions d each contact restrains and :math:`\mathcal T` its pinned
    directions:

    - no ``stiffness``, ``damping``, ``shear_stiffness``: a rigid hinge, every point pinned in all three
      directions (Wu 2014, Grøtting 2015);
    - ``stiffness``/``damping``: the normal carries the fender's spring–damper; the tangential
      directions :math:`t_v = e_z, t_h = e_z\times n` are pinned (the rigid stick of Ferreira González
      2023), or — with a finite ``shear_stiffness`` — carry the rubber's shear spring and
      ``shear_damping`` (the compliant fender: no pin at all, roll is not locked); ``sideways=False``
      leaves :math:`t_h` free.

    The reaction on the vessel is :math:`\hat J_c = \sum_{pins} \hat\lambda\,d - \sum_{springs}
    (k + i\omega c)\,d\,d^\top G_c \hat x`.

    With a ``thrust`` T, the static problem gives the preload :math:`x^0, J^0`
    (:func:`boatland.landing.law.static_preload`: the same system at ω = 0 with the follower thrust
    :math:`T[e_x;\ r_T \times e_x]` as load) and the dynamic system is linearised about it with
    :math:`K_g` = :func:`preload_stiffness` (the follower force :math:`T\theta\times e_x` of Grøtting
    2015 eq. 3.62–3.63 and the turning of the static forces' moments). The static rotation, O(T/C₅₅),
    moves the fender point by θ⁰ × r (1.4 cm for ctv24's bow point under 80 kN), which is neglected.

    Parameters
    ----------
    db : HydroDB
        The vessel (with ``M``).
    omega : float or array_like, shape (Nw,)
        Wave frequencies [rad/s].
    points : array_like, shape (3,) or (Np, 3)
        Contact points, body frame [m].
    beta_deg : float or array_like, optional
        Wave directions relative to the vessel [deg]; default the database's.
    normal : array_like, shape (3,) or (Np, 3), optional
        Contact normals, from the landing towards the vessel (normalised here; horizontal). Needed for
        springs and for :meth:`HingedResponse.contact_components`.
    stiffness, damping : float or array_like, shape (Np,), optional
        Normal spring k_n [N/m] and damper d_n [N s/m] per point (one value for all).
    shear_stiffness, shear_damping : float or array_like, shape (Np,), optional
        The rubber's shear spring k_t [N/m] (``inf`` or None: pinned) and damper c_t [N s/m].
    sideways : bool
        The horizontal tangent is restrained too (friction along the tube).
    thrust : float
        Bollard push T [N] along the vessel's x axis (0: no preload).
    thrust_position : array_like, shape (3,)
        Body point of the thrust [m].
    thrust_direction : array_like, shape (3,)
        Unit body direction of the thrust (default along x).
    steady : SteadyLoad, optional
        Steady loads besides the thrust (current, mean wind, mean drift:
        :class:`boatland.landing.law.SteadyLoad`): their force enters the preload, their linearisation the
        dynamics (:math:`Z \to Z + K^s + i\omega B^s`).
    loads : array_like, shape (K, 6), optional
        Generalised force patterns solved beside the waves (e.g. a gust's; ``x_loads``, ``J_loads``).
    additional_damping : array_like, shape (6, 6) or (6,), optional
        Extra linear damping of the vessel.
    normal_follows : {"fixed", "fender", "tube"}
        How the contact normals turn with the motions (:meth:`boatland.landing.law.ContactLaw.geometric_stiffness`:
        the face of a line fender turns with the yaw, a point on a round tube follows its surface).
    tube_radius : float or array_like
        Tube radius [m] for ``normal_follows="tube"``.

    Returns
    -------
    HingedResponse
        ``x`` (Nw, Nβ, 6) and ``J`` (Nw, Nβ, Np, 3) per unit wave amplitude, phase = lead over the
        crest at the reference point; ``x_static``, ``J_static`` the preload.

    Raises
    ------
    ValueError
        Bad arguments, or a thrust the landing cannot hold statically (e.g. a yaw moment about a
        single fender point, or a normal with no spring).
    """
    P = np.atleast_2d(np.asarray(points, dtype=float))
    if P.ndim != 2 or P.shape[1] != 3 or not np.all(np.isfinite(P)):
        raise ValueError(f"points must be (3,) or (Np, 3) body coordinates [m], got shape {np.shape(points)}")
    n_p = P.shape[0]
    N = None
    if normal is not None:
        N = np.array(np.broadcast_to(np.asarray(normal, dtype=float), (n_p, 3)) if np.ndim(normal) == 1
                     else np.asarray(normal, dtype=float))
        if N.shape != (n_p, 3):
            raise ValueError(f"normal must be (3,) or ({n_p}, 3), got shape {np.shape(normal)}")
        lens = np.linalg.norm(N, axis=1)
        if np.any(lens == 0) or not np.all(np.isfinite(lens)):
            raise ValueError("normals must be finite non-zero vectors")
        N = N / lens[:, None]
    spring = stiffness is not None or damping is not None
    if (spring or shear_stiffness is not None) and N is None:
        raise ValueError("springs (stiffness, damping, shear_stiffness) need the contact normal(s): give normal=")
    inf = np.inf
    if spring:
        law = ContactLaw(P, N, _per_point(0.0 if stiffness is None else stiffness, n_p, "stiffness"),
                         _per_point(0.0 if damping is None else damping, n_p, "damping"),
                         _per_point(inf if shear_stiffness is None else shear_stiffness, n_p, "shear_stiffness"),
                         _per_point(0.0 if shear_damping is None else shear_damping, n_p, "shear_damping"),
                         sideways=sideways, follows=normal_follows, radius=tube_radius)
    elif shear_stiffness is not None:
        raise ValueError("a shear spring needs the normal's spring too (stiffness=)")
    else:  # Wu's rigid hinge: every direction pinned
        law = ContactLaw(P, np.array([1.0, 0.0, 0.0]) if N is None else N, inf, 0.0, inf, 0.0, sideways=True)

    w = _omega(db, omega)
    Z = impedance(db, w, additional_damping)        # (Nw, 6, 6)
    X = excitation_force(db, w, beta_deg)           # (Nw, Nβ, 6)
    K, D, pins, _ = law.assemble()
    x0, J0, Kg = np.zeros(6), np.zeros((n_p, 3)), np.zeros((6, 6))
    if thrust != 0.0 or steady is not None:
        x0, J0, Kg = static_preload(db.C, law, float(thrust), thrust_position, thrust_direction, steady)
    Zs = Z - Kg + K[None] + 1j * w[:, None, None] * D[None]
    if steady is not None:
        Zs = Zs + steady.stiffness[None] + 1j * w[:, None, None] * steady.damping[None]
    nb = X.shape[1]
    L = np.zeros((0, 6)) if loads is None else np.atleast_2d(np.asarray(loads, dtype=float))
    nl = L.shape[0]
    rhs = np.swapaxes(X, 1, 2)                                                   # (Nw, 6, Nβ)
    if nl:
        rhs = np.concatenate([rhs, np.broadcast_to(L.T.astype(complex), (w.size, 6, nl))], axis=2)
    xs, ls = solve_saddle_stack(Zs, pins, rhs)
    x, lam = np.swapaxes(xs, 1, 2), np.swapaxes(ls, 1, 2)
    J = law.reactions(x, lam, w[:, None])
    extra = {} if loads is None else {"x_loads": x[:, nb:], "J_loads": J[:, nb:]}
    return HingedResponse(omega=w, beta_deg=_beta(db, beta_deg), points=P, normals=N, law=law, x=x[:, :nb],
                          J=J[:, :nb], x_static=x0, J_static=J0, **extra)
