r"""Response amplitude operators of the free vessel and of the vessel hinged at its fender point.

Free vessel (seed 000 eq. 3.29–3.31):

.. math::
    Z(\omega)\,\hat x = X(\omega, \beta), \qquad
    Z(\omega) = -\omega^2\left(M + A(\omega)\right) + i\omega\left(B(\omega) + B_{add}\right) + C .

Vessel hinged at body points :math:`r_c` (seed 002 §3.2.1, eq. 3.1–3.12, after Wu 2014): the
translation of each point is zero, the rotations are free. With the 3 × 6 map of the motions to the
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

which is eq. 3.10–3.12 of seed 002 written without eliminating the translations (eq. 3.9): the same
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
follows the vessel's x axis (seed 002 §3.4, eq. 3.62–3.63) and the static contact forces turn their
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
uses (:func:`boatland.model.seastate.excitation_table`,
:func:`boatland.waves.excitation.interpolate_excitation`). Frequencies above the database's band are
refused.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.model.hydrodb import HydroDB, skew
from boatland.model.seastate import excitation_table
from boatland.model.wave_directions import direction_problem
from boatland.waves.excitation import interpolate_excitation

__all__ = ["HingedResponse", "excitation_force", "free_rao", "hinged_rao", "impedance", "point_map",
           "preload_stiffness", "radiation_coefficients"]


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
    shows port–starboard symmetric counts as the full circle: :mod:`boatland.model.wave_directions`)."""
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
    (:func:`boatland.model.seastate.excitation_table`): periodic in β when the database goes round the
    circle, or is a half circle of a hull it shows port–starboard symmetric (completed by
    :math:`X_j(360° - \beta) = s_j X_j(\beta)`). ``beta_deg`` None = the database's directions.

    Raises
    ------
    BoatlandInputError
        A direction outside those the database covers (an asymmetric or partial table, a single
        direction): :func:`boatland.model.wave_directions.direction_problem`.
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
    r"""RAO of the freely floating vessel (seed 000 eq. 3.31).

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


def point_map(point) -> np.ndarray:
    r"""3 × 6 map :math:`G = [I \;\; -S(r)]` of the motions to the (small) translation of body point ``r``:
    :math:`G x = x_{1:3} + x_{4:6} \times r` (seed 002 eq. 3.7–3.8). :math:`G^\top f` is the
    generalised force of a force f at r."""
    G = np.zeros((3, 6))
    G[:, :3] = np.eye(3)
    G[:, 3:] = -skew(point)
    return G


def _tangents(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(t_v, t_h) of a plane with unit normal n: t_h = e_z × n / |…|, t_v = n × t_h (vertical when n
    is horizontal) — the axes of :mod:`boatland.contact.fender`."""
    th = np.cross([0.0, 0.0, 1.0], n)
    if np.linalg.norm(th) < 1e-9:
        raise ValueError(f"normal {n} is vertical: the contact plane of a strut is vertical (horizontal normal)")
    th /= np.linalg.norm(th)
    return np.cross(n, th), th


def preload_stiffness(thrust: float, thrust_position, forces, points) -> np.ndarray:
    r"""Linearised generalised force of the static loads as the vessel rotates: :math:`\delta F = K_g x`.

    The time domain applies the thrust T along the vessel's own x axis at body point :math:`r_T`
    (a follower force, seed 002 §3.4) and the contact forces along fixed (local-frame) directions at
    the rotating fender points :math:`R(\theta) r_c`. To first order in the rotations θ, the static
    values :math:`T` and :math:`J^0_c` then add

    .. math::
        K_g = \begin{bmatrix} 0 & -T\,S(e_x) \\ 0 & -S(r_T \times T e_x) + \sum_c S(J^0_c)\,S(r_c) \end{bmatrix}

    (forces :math:`T\,\theta \times e_x` — seed 002 eq. 3.62–3.63 — and moments
    :math:`\theta \times (r_T \times T e_x) + \sum_c (\theta \times r_c) \times J^0_c`). In the
    frequency domain it enters as the stiffness :math:`-K_g`.

    Parameters
    ----------
    thrust : float
        Push T [N] along the body x axis.
    thrust_position : array_like, shape (3,)
        Its body point r_T [m].
    forces : array_like, shape (Np, 3)
        Static contact forces on the vessel J⁰_c, local axes [N].
    points : array_like, shape (Np, 3)
        Contact points r_c, body frame [m].

    Returns
    -------
    K_g : ndarray, shape (6, 6)
        [N/m, N/rad, N m/rad]; acts on the rotations only (columns 4–6).
    """
    ex = np.array([1.0, 0.0, 0.0])
    Kg = np.zeros((6, 6))
    Kg[:3, 3:] = -thrust * skew(ex)
    Kg[3:, 3:] = -skew(np.cross(np.asarray(thrust_position, dtype=float), thrust * ex))
    for f, r in zip(np.atleast_2d(forces), np.atleast_2d(points)):
        Kg[3:, 3:] += skew(f) @ skew(r)
    return Kg


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
        Contact-plane normals (landing → vessel) when given.
    x : ndarray of complex, shape (Nw, Nβ, 6)
        Motions [m/m, rad/m].
    J : ndarray of complex, shape (Nw, Nβ, Np, 3)
        Reaction force on the vessel at each point, body (= local at rest) axes x, y, z [N/m].
    x_static : ndarray, shape (6,)
        Static displacement under the thrust [m, rad] (zero without thrust).
    J_static : ndarray, shape (Np, 3)
        Static reaction on the vessel at each point, local axes [N] (zero without thrust).
    """

    omega: np.ndarray
    beta_deg: np.ndarray
    points: np.ndarray
    normals: np.ndarray | None
    x: np.ndarray
    J: np.ndarray
    x_static: np.ndarray
    J_static: np.ndarray

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
        axes = np.stack([np.stack([n, *_tangents(n)]) for n in self.normals])  # (Np, 3, 3): rows n, t_v, t_h
        if static:
            return np.einsum("pak,pk->pa", axes, self.J_static)
        return np.einsum("pak,wbpk->wbpa", axes, self.J)


def _per_point(value, n_points: int, name: str) -> np.ndarray:
    a = np.asarray(value, dtype=float)
    a = np.broadcast_to(a, (n_points,)) if a.ndim == 0 else a.reshape(-1)
    if a.shape != (n_points,) or np.any(a < 0) or not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be one finite value ≥ 0 or one per point ({n_points}), got {value!r}")
    return np.array(a)


def _solve_saddle(Z: np.ndarray, Cmat: np.ndarray, F: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    r"""Solve :math:`[Z\; -C^\top;\ C\; 0]\,[x; \lambda] = [F; 0]` for one frequency, several right-hand
    sides F (6, Nb). Minimum-norm (SVD) so that redundant constraints share their reaction; the blocks
    are balanced first (Z ~ 1e5–1e8, C ~ 1–10). Returns x (6, Nb), λ (m, Nb) and the relative residual."""
    m = Cmat.shape[0]
    s = float(np.max(np.abs(Z)))
    K = np.zeros((6 + m, 6 + m), dtype=complex)
    K[:6, :6] = Z
    K[:6, 6:] = -s * Cmat.T
    K[6:, :6] = s * Cmat
    rhs = np.zeros((6 + m, F.shape[1]), dtype=complex)
    rhs[:6] = F
    sol = np.linalg.lstsq(K, rhs, rcond=None)[0]
    res = np.linalg.norm(K @ sol - rhs) / max(np.linalg.norm(rhs), 1e-300)
    return sol[:6], s * sol[6:], float(res)


def _reactions(lam, x, Tt, gn, N, kc):
    """Reactions J (..., Np, 3) from the multipliers λ (..., m) and the motions x (..., 6): the pinned
    directions T_c λ_c, and with a spring normal (``kc`` = per point k + iωd, else None) its force
    −(k + iωd) n nᵀ G x."""
    n_p = len(Tt)
    J = np.empty(x.shape[:-1] + (n_p, 3), dtype=complex)
    row = 0
    for c in range(n_p):
        r = Tt[c].shape[0]
        J[..., c, :] = lam[..., row:row + r] @ Tt[c]
        if kc is not None:
            J[..., c, :] -= (kc[c] * (x @ gn[c]))[..., None] * N[c]
        row += r
    return J


def _static_preload(C, Cmat, Tt, gn, N, k, P, thrust, rT):
    r"""Static equilibrium on the hinge(s) under the follower thrust: (x⁰, J⁰, K_g(J⁰)).

    :math:`(C + \sum_c k_c G_c^\top n_c n_c^\top G_c - K_g(J^0))\,x^0 = T[e_x;\ r_T\times e_x] + \sum_c G_c^\top J^0_c`
    with the pins :math:`\mathcal T x^0 = 0`: the preload's own stiffness tilts the thrust and turns
    the contact moments by the static rotation. A fixed point in J⁰ (K_g is O(T/C₅₅) of the
    restoring: a few iterations). ``k`` (Np,) the normal springs, None for rigid hinges.
    """
    F_T = thrust * np.concatenate([[1.0, 0.0, 0.0], np.cross(rT, [1.0, 0.0, 0.0])])
    Z0 = C if k is None else C + sum(k[c] * np.outer(gn[c], gn[c]) for c in range(len(Tt)))
    J0 = np.zeros((len(Tt), 3))
    Kg = np.zeros((6, 6))
    for _ in range(50):
        xs, ls, res = _solve_saddle((Z0 - Kg).astype(complex), Cmat, F_T[:, None].astype(complex))
        if res > 1e-8:
            raise ValueError(f"the hinge cannot hold the thrust statically (relative residual {res:.2g}): a force "
                             "or moment about a direction with neither restoring nor a pin — e.g. a yaw moment "
                             "about a single fender point, or a normal without a spring")
        x0 = xs[:, 0].real
        J_new = _reactions(ls[:, 0].real, x0, Tt, gn, N, k).real
        done = np.max(np.abs(J_new - J0)) <= 1e-12 * np.max(np.abs(J_new))
        J0 = J_new
        Kg = preload_stiffness(thrust, rT, J0, P)
        if done:
            return x0, J0, Kg
    raise ValueError("the static equilibrium under the thrust did not converge: the preload's geometric stiffness "
                     "is comparable with the restoring (thrust far too large for this hinge)")


def hinged_rao(db: HydroDB, omega, points, *, beta_deg=None, normal=None, stiffness=None, damping=None,
               thrust: float = 0.0, thrust_position=(0.0, 0.0, 0.0), additional_damping=None) -> HingedResponse:
    r"""Motions and hinge reactions of the vessel pinned at its fender point(s) (seed 002 §3.2.1).

    Solves (module docstring; seed 002 eq. 3.1–3.12)

    .. math::
        \begin{bmatrix} Z - K_g + \sum_c (k_c + i\omega d_c) G_c^\top n_c n_c^\top G_c & -\mathcal T^\top \\
                        \mathcal T & 0 \end{bmatrix}
        \begin{bmatrix} \hat x \\ \hat\lambda \end{bmatrix} =
        \begin{bmatrix} X \\ 0 \end{bmatrix}

    with :math:`Z = -\omega^2 (M + A) + i\omega (B + B_{add}) + C`, :math:`G_c = [I\;\; -S(r_c)]` and
    :math:`\mathcal T` the pinned directions of each point: all three for a rigid hinge (seed 002),
    the two tangential ones :math:`(t_v, t_h)` of the contact plane when the normal carries a
    spring–damper :math:`(k_c, d_c)`. The reaction on the vessel is
    :math:`\hat J_c = T_c\hat\lambda_c - (k_c + i\omega d_c)\, n_c n_c^\top G_c \hat x`.

    With a ``thrust`` T, the static hinge problem gives the preload :math:`x^0, J^0` — the same
    system at ω = 0 with :math:`Z = C - K_g(J^0)` (solved as a fixed point) and the follower thrust
    :math:`T[e_x;\ r_T \times e_x]` as load: the static vertical force of seed 002 eq. 3.56–3.61, here
    for any hinge, plus the tilt of the thrust by the static pitch that §3.4 neglects — and the
    dynamic system is linearised about it with :math:`K_g` = :func:`preload_stiffness` (the follower
    force :math:`T\theta\times e_x` of seed 002 eq. 3.62–3.63 and the turning of the static forces'
    moments). Otherwise the levers are those of the unrotated vessel: the static rotation, O(T/C₅₅),
    moves the fender point by θ⁰ × r (1.4 cm for ctv24's bow point under 80 kN), which is neglected.

    Parameters
    ----------
    db : HydroDB
        The vessel (with ``M``).
    omega : float or array_like, shape (Nw,)
        Wave frequencies [rad/s].
    points : array_like, shape (3,) or (Np, 3)
        Hinge (fender contact) points, body frame [m].
    beta_deg : float or array_like, optional
        Wave directions relative to the vessel [deg]; default the database's.
    normal : array_like, shape (3,) or (Np, 3), optional
        Contact-plane normals, from the landing towards the vessel (normalised here; must not be
        vertical). Needed for a spring–damper normal and for :meth:`HingedResponse.contact_components`.
    stiffness, damping : float or array_like, shape (Np,), optional
        Normal spring k_n [N/m] and damper d_n [N s/m] per point (one value for all). When either is
        given (the other defaults to 0) the points are pinned only tangentially; when both are None
        the points are pinned in all three directions (rigid hinge).
    thrust : float
        Bollard push T [N] along the vessel's x axis (0: no preload, the linear system of seed 002 §3.2.1).
    thrust_position : array_like, shape (3,)
        Body point of the thrust [m].
    additional_damping : array_like, shape (6, 6) or (6,), optional
        Extra linear damping of the vessel.

    Returns
    -------
    HingedResponse
        ``x`` (Nw, Nβ, 6) and ``J`` (Nw, Nβ, Np, 3) per unit wave amplitude, phase = lead over the
        crest at the reference point; ``x_static``, ``J_static`` the preload.

    Raises
    ------
    ValueError
        Bad arguments, or a thrust the hinge cannot hold statically (e.g. a yaw moment about a single
        fender point, or a normal with no spring).
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
    if spring and N is None:
        raise ValueError("a spring–damper normal (stiffness, damping) needs the contact normal(s): give normal=")
    k = _per_point(0.0 if stiffness is None else stiffness, n_p, "stiffness")
    d = _per_point(0.0 if damping is None else damping, n_p, "damping")

    w = _omega(db, omega)
    Z = impedance(db, w, additional_damping)        # (Nw, 6, 6)
    X = excitation_force(db, w, beta_deg)           # (Nw, Nβ, 6)
    G = np.stack([point_map(p) for p in P])         # (Np, 3, 6)
    # pinned directions of each point: the rows of T_c^T (3 for a rigid hinge, the 2 tangents with a spring normal)
    Tt = [np.stack(_tangents(N[c])) if spring else np.eye(3) for c in range(n_p)]
    Cmat = np.concatenate([Tt[c] @ G[c] for c in range(n_p)])  # (m, 6)
    gn = [N[c] @ G[c] if spring else np.zeros(6) for c in range(n_p)]  # n_c^T G_c: normal displacement

    x0, J0, Kg = np.zeros(6), np.zeros((n_p, 3)), np.zeros((6, 6))
    if thrust != 0.0:
        x0, J0, Kg = _static_preload(db.C, Cmat, Tt, gn, N, k if spring else None, P, float(thrust),
                                     np.asarray(thrust_position, dtype=float).reshape(3))
    Zs = Z - Kg
    if spring:
        for c in range(n_p):
            Zs = Zs + (k[c] + 1j * w * d[c])[:, None, None] * np.outer(gn[c], gn[c])[None]
    nb = X.shape[1]
    x = np.empty((w.size, nb, 6), dtype=complex)
    lam = np.empty((w.size, nb, Cmat.shape[0]), dtype=complex)
    for iw in range(w.size):
        xi, li, _ = _solve_saddle(Zs[iw], Cmat, X[iw].T)
        x[iw], lam[iw] = xi.T, li.T
    J = _reactions(lam, x, Tt, gn, N, [(k[c] + 1j * w * d[c])[:, None] for c in range(n_p)] if spring else None)
    return HingedResponse(omega=w, beta_deg=_beta(db, beta_deg), points=P, normals=N, x=x, J=J,
                          x_static=x0, J_static=J0)
