r"""The vessel on its landing, linearised: what each fender contact restrains, the static preload under
the thrust, its geometric stiffness, and the landed natural modes.

This is the linear image of the time-domain contact of :mod:`boatland.contact.fender` with every
contact stuck (Grøtting 2015 §3.2.1 and §3.4 after Wu 2014, for a rigid hinge; here for the compliant
fender too). Contact c at body point :math:`r_c`, with the 3 × 6 map of the motions to the point's
translation :math:`G_c = [I\;\; -S(r_c)]` (:math:`S(r)v = r\times v`), restrains the directions
:math:`d \in \{n_c, t_v, t_h\}` (normal from the landing towards the vessel, :math:`t_v = e_z`,
:math:`t_h = e_z \times n_c`) each in one of three ways:

- a spring–damper :math:`(k, c)`: the force :math:`-(k + i\omega c)\,d\,d^\top G_c\hat x` on the vessel —
  the normal fender :math:`(c_f, d_f)` and the compliant rubber's shear :math:`(k_t, c_t)`;
- a pin (:math:`k = \infty`): the row :math:`d^\top G_c\hat x = 0` with its reaction as an unknown —
  the rigid stick of Ferreira González (2023), and Wu's rigid hinge;
- nothing (:math:`k = c = 0`): a direction without friction (``sideways = false``).

Motions and pin reactions then solve the saddle-point system (Grøtting 2015 eq. 3.1–3.12 written
without eliminating the translations)

.. math::
    \begin{bmatrix} Z - K_g + \sum (k + i\omega c) G^\top d d^\top G & -\mathcal T^\top \\ \mathcal T & 0
    \end{bmatrix} \begin{bmatrix} \hat x \\ \hat\lambda \end{bmatrix} = \begin{bmatrix} F \\ 0 \end{bmatrix},

with :math:`K_g` the stiffness of the preload (:func:`preload_stiffness`). Redundant pins (two points
on parallel struts both pinned sideways) share their reaction equally (minimum-norm solve), as the
time-domain stick solve does.

References: Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind
Turbines*, MSc thesis, NTNU; Ferreira González, D. (2023), *Development of a Numerical Approach for
the Simulation of Boatlanding Maneuvers*, Dr.-Ing. dissertation, TU Hamburg.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.vessel.database import HydroDB, skew

__all__ = ["ContactLaw", "LandedModes", "NoStaticEquilibrium", "SteadyLoad", "landed_modes", "normal_follows",
           "point_map", "preload_stiffness", "solve_saddle", "solve_saddle_stack", "static_preload", "tangents"]

_EX = np.array([1.0, 0.0, 0.0])


@dataclass(frozen=True, eq=False)
class SteadyLoad:
    r"""Steady loads on the landed vessel besides the push, linearised: :math:`F^s + \delta F`,
    :math:`\delta F = -K^s x - B^s\dot x` (current, mean wind and mean drift:
    :class:`boatland.landing.environment.Environment`).

    Attributes
    ----------
    force : ndarray, shape (6,)
        The load at the start pose [N, N m] (local frame): its time average.
    stiffness, damping : ndarray, shape (6, 6)
        :math:`K^s = -\partial F/\partial x`, :math:`B^s = -\partial F/\partial \dot x`.
    gust_pattern : ndarray, shape (6,), or None
        A slowly varying part :math:`f_g\,g(t)` besides the mean (the wind's gusts): its pattern f_g ...
    gust_spectrum : callable or None
        ... and the one-sided spectrum :math:`S_g(\omega)` [per rad/s] of the zero-mean Gaussian g(t).
    linear_share : float
        The share of the slow swing's equivalent damping that is linear (1 unless the hull's quadratic drag is
        linearised statistically: :meth:`boatland.freqdomain.landing.LandingSetup.with_drag_linearised`).
    """

    force: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    gust_pattern: np.ndarray | None = None
    gust_spectrum: object = None
    linear_share: float = 1.0


def point_map(point) -> np.ndarray:
    r"""3 × 6 map :math:`G = [I \;\; -S(r)]` of the motions to the (small) translation of body point ``r``:
    :math:`G x = x_{1:3} + x_{4:6} \times r` (Grøtting 2015 eq. 3.7–3.8). :math:`G^\top f` is the
    generalised force of a force f at r."""
    G = np.zeros((3, 6))
    G[:, :3] = np.eye(3)
    G[:, 3:] = -skew(point)
    return G


def tangents(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(t_v, t_h) of a contact with unit normal n: t_h = e_z × n / |…|, t_v = n × t_h (vertical when n
    is horizontal) — the axes of :mod:`boatland.contact.fender`."""
    th = np.cross([0.0, 0.0, 1.0], n)
    if np.linalg.norm(th) < 1e-9:
        raise ValueError(f"normal {n} is vertical: the contact of a tube is horizontal")
    th /= np.linalg.norm(th)
    return np.cross(n, th), th


def preload_stiffness(thrust: float, thrust_position, forces, points, direction=_EX) -> np.ndarray:
    r"""Linearised generalised force of the static loads as the vessel rotates: :math:`\delta F = K_g x`.

    The time domain applies the thrust T along the vessel's own x axis at body point :math:`r_T`
    (a follower force, Grøtting 2015 §3.4) and the contact forces along fixed (local-frame) directions
    at the rotating fender points :math:`R(\theta) r_c`. To first order in the rotations θ, the static
    values :math:`T` and :math:`J^0_c` then add

    .. math::
        K_g = \begin{bmatrix} 0 & -T\,S(e_x) \\ 0 & -S(r_T \times T e_x) + \sum_c S(J^0_c)\,S(r_c) \end{bmatrix}

    (forces :math:`T\,\theta \times e_x` — Grøtting 2015 eq. 3.62–3.63 — and moments
    :math:`\theta \times (r_T \times T e_x) + \sum_c (\theta \times r_c) \times J^0_c`), and the turn of
    the Euler axes the time domain takes the loads' moments about (:func:`boatland.rigid.euler_moment`): with
    :math:`M^0` their static moment, :math:`\delta Q_\phi = \psi M^0_y - \theta M^0_z`,
    :math:`\delta Q_\theta = -\psi M^0_x`. In the
    frequency domain it enters as the stiffness :math:`-K_g`. A push along another body direction
    :math:`e_T` (``direction``) replaces :math:`e_x`.

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
    ex = np.asarray(direction, dtype=float).reshape(3)
    Kg = np.zeros((6, 6))
    Kg[:3, 3:] = -thrust * skew(ex)
    M0 = np.cross(np.asarray(thrust_position, dtype=float), thrust * ex)
    Kg[3:, 3:] = -skew(M0)
    for f, r in zip(np.atleast_2d(forces), np.atleast_2d(points)):
        Kg[3:, 3:] += skew(f) @ skew(r)
        M0 = M0 + np.cross(r, f)
    Kg[3, 4] -= M0[2]                      # the Euler axes turning under the static moment
    Kg[3, 5] += M0[1]
    Kg[4, 5] -= M0[0]
    return Kg


def solve_saddle(Z: np.ndarray, Cmat: np.ndarray, F: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    r"""Solve :math:`[Z\; -C^\top;\ C\; 0]\,[x; \lambda] = [F; 0]` for one frequency, several right-hand
    sides F (6, Nb). Minimum-norm (SVD) so that redundant constraints share their reaction; the blocks
    are balanced first (Z ~ 1e5–1e8, C ~ 1–10). Without constraints (C with no rows) it is Z x = F
    (least squares: a direction without any restraint gets no static displacement). Returns x (6, Nb),
    λ (m, Nb) and the relative residual."""
    m = Cmat.shape[0]
    s = float(np.max(np.abs(Z))) or 1.0
    K = np.zeros((6 + m, 6 + m), dtype=complex)
    K[:6, :6] = Z
    K[:6, 6:] = -s * Cmat.T
    K[6:, :6] = s * Cmat
    rhs = np.zeros((6 + m, F.shape[1]), dtype=complex)
    rhs[:6] = F
    sol = np.linalg.lstsq(K, rhs, rcond=None)[0]
    res = np.linalg.norm(K @ sol - rhs) / max(np.linalg.norm(rhs), 1e-300)
    return sol[:6], s * sol[6:], float(res)


def solve_saddle_stack(Z: np.ndarray, Cmat: np.ndarray, F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    r""":func:`solve_saddle` for a stack of frequencies at once: Z (Nw, 6, 6), F (Nw, 6, Nb) → x (Nw, 6, Nb),
    λ (Nw, m, Nb).

    The constraints :math:`C x = 0` do not change with frequency, so they are eliminated once (the null-space
    method, e.g. Nocedal & Wright 2006, *Numerical Optimization*, §16.2): with :math:`N` an orthonormal basis of
    C's null space, :math:`x = N y`, :math:`(N^H Z N)\,y = N^H F` (one LU solve per frequency, all in one
    call), and the reactions are the least-norm :math:`\lambda = (C^	op)^+ (Z x - F)` — the same solution as the
    minimum-norm saddle solve whenever :math:`N^H Z N` is regular (residuals ~1e-14 of the load; the least
    squares' ~1e-12). A stack where it is exactly singular (LU fails) or the solution is not finite is solved
    frequency by frequency by :func:`solve_saddle`; a nearly singular one is not detected (with a vessel's mass at
    ω > 0, as the screening and the gusts' grid have it, it does not arise)."""
    m = Cmat.shape[0]
    try:
        if m:
            u, sv, vh = np.linalg.svd(Cmat)
            rank = int(np.sum(sv > sv[0] * max(Cmat.shape) * np.finfo(float).eps))
            Nb = vh[rank:].conj().T                                       # (6, 6 − rank)
            y = np.linalg.solve(Nb.conj().T @ Z @ Nb, Nb.conj().T @ F)
            x = Nb @ y
            lam = np.linalg.pinv(Cmat.T) @ (Z @ x - F)
        else:
            x = np.linalg.solve(Z, F)
            lam = np.zeros((Z.shape[0], 0, F.shape[-1]), dtype=complex)
        if np.all(np.isfinite(x)) and np.all(np.isfinite(lam)):
            return x, lam
    except np.linalg.LinAlgError:
        pass
    out = [solve_saddle(Z[i], Cmat, F[i]) for i in range(Z.shape[0])]
    return np.stack([o[0] for o in out]), np.stack([o[1] for o in out]).reshape(Z.shape[0], m, F.shape[-1])


@dataclass(frozen=True, eq=False)
class ContactLaw:
    r"""The linear restraint of each contact, body frame at rest.

    Attributes
    ----------
    points : ndarray, shape (Np, 3)
        Contact points r_c [m].
    normals : ndarray, shape (Np, 3)
        Unit horizontal normals, landing → vessel.
    k_n, c_n : ndarray, shape (Np,)
        Normal spring [N/m] and damper [N s/m]; ``k_n = inf`` pins the normal.
    k_t, c_t : ndarray, shape (Np,)
        Shear spring and damper along t_v (and t_h when ``sideways``); ``k_t = inf`` pins them.
    sideways : bool
        The horizontal tangent t_h is restrained (friction along the tube), not only t_v.
    follows : str
        How the contact normal turns as the vessel moves (:meth:`geometric_stiffness`): ``"fixed"`` (a
        plate, or the linear hinge of Wu 2014), ``"fender"`` (a tube against the face of a fender line:
        the normal is the face's and turns with the vessel's yaw), ``"tube"`` (a point fender on a round
        tube: the normal follows the tube surface as the point moves sideways).
    radius : ndarray, shape (Np,)
        For ``"tube"``: the tube's radius [m] (less the static compression N⁰/k_n it is the distance from
        the axis to the contact point).
    """

    points: np.ndarray
    normals: np.ndarray
    k_n: np.ndarray
    c_n: np.ndarray
    k_t: np.ndarray
    c_t: np.ndarray
    sideways: bool = True
    follows: str = "fixed"
    radius: np.ndarray | float = np.inf

    def __post_init__(self):
        P = np.atleast_2d(np.asarray(self.points, dtype=float))
        n_p = P.shape[0]
        N = np.array(np.broadcast_to(np.asarray(self.normals, dtype=float), (n_p, 3)))
        lens = np.linalg.norm(N, axis=1)
        if P.shape[1] != 3 or not np.all(np.isfinite(P)) or np.any(lens == 0) or not np.all(np.isfinite(lens)):
            raise ValueError("points and normals must be finite (Np, 3) arrays with non-zero normals")
        object.__setattr__(self, "points", P)
        object.__setattr__(self, "normals", N / lens[:, None])
        for name in ("k_n", "c_n", "k_t", "c_t", "radius"):
            a = np.array(np.broadcast_to(np.asarray(getattr(self, name), dtype=float), (n_p,)))
            if np.any(a < 0) or np.any(np.isnan(a)):
                raise ValueError(f"{name} must be ≥ 0 (inf: pinned), got {a}")
            object.__setattr__(self, name, a)
        if self.follows not in ("fixed", "fender", "tube"):
            raise ValueError(f"follows must be 'fixed', 'fender' or 'tube', got {self.follows!r}")
        out = []                        # the restrained directions, made once (the statics ask for them often)
        for c in range(self.n_points):
            tv, th = tangents(self.normals[c])
            dirs = [(self.normals[c], self.k_n[c], self.c_n[c]), (tv, self.k_t[c], self.c_t[c])]
            if self.sideways:
                dirs.append((th, self.k_t[c], self.c_t[c]))
            out.append([(d, k, cc) for d, k, cc in dirs if k > 0 or cc > 0])
        object.__setattr__(self, "_directions", out)

    @property
    def n_points(self) -> int:
        return self.points.shape[0]

    def directions(self):
        """Per contact: the list of (unit direction d (3,), k, c) it restrains, normal first."""
        return self._directions

    def assemble(self, omega=None):
        r"""The restraint in matrix form.

        Returns
        -------
        K, D : ndarray, shape (6, 6)
            :math:`\sum k\,G^\top d d^\top G` and :math:`\sum c\,G^\top d d^\top G` over the finite springs.
        pins : ndarray, shape (m, 6)
            Rows :math:`d^\top G_c` of the pinned directions.
        owners : list of (contact, direction)
            Which contact and direction each pin row is.
        """
        K, D = np.zeros((6, 6)), np.zeros((6, 6))
        rows, owners = [], []
        for c, dirs in enumerate(self.directions()):
            G = point_map(self.points[c])
            for d, k, cc in dirs:
                g = d @ G
                if math.isinf(k):
                    rows.append(g)
                    owners.append((c, d))
                else:
                    K += k * np.outer(g, g)
                    D += cc * np.outer(g, g)
        return K, D, (np.array(rows) if rows else np.zeros((0, 6))), owners

    def geometric_stiffness(self, forces) -> np.ndarray:
        r"""Stiffness of the static normal forces :math:`N^0_c = n_c^\top J^0_c` as the normals turn:
        :math:`\delta F = K x` (enters the dynamics as :math:`-K`, as :func:`preload_stiffness`).

        - ``"fender"``: the normal is the fender face's, :math:`n(\theta) = n_c + \theta_z\,e_z\times n_c`
          (the horizontal part of the rotated face normal; roll and pitch turn it only to second order),
          so :math:`\delta J_c = N^0_c\,\theta_z\,(e_z \times n_c)` at :math:`r_c` — a follower force like the
          thrust, which it balances in yaw;
        - ``"tube"``: a point on a round tube of radius ρ (axis to contact): moving sideways by s along
          :math:`t_h` turns the normal by s/ρ, :math:`\delta J_c = (N^0_c/\rho)\,t_h t_h^\top G_c x` — a
          negative lateral stiffness −N/ρ (pushing on a convex surface);
        - ``"fixed"``: none.

        Parameters
        ----------
        forces : array_like, shape (Np, 3)
            Static contact forces on the vessel J⁰_c [N].
        """
        K = np.zeros((6, 6))
        if self.follows == "fixed":
            return K
        for c in range(self.n_points):
            n = self.normals[c]
            N0 = float(n @ np.asarray(forces[c], dtype=float))
            if self.follows == "fender":
                d = np.cross([0.0, 0.0, 1.0], n)
                K[:, 5] += N0 * np.concatenate([d, np.cross(self.points[c], d)])
            else:
                rho = self.radius[c] - (N0 / self.k_n[c] if np.isfinite(self.k_n[c]) and self.k_n[c] > 0 else 0.0)
                if np.isfinite(rho) and rho > 0:
                    g = tangents(n)[1] @ point_map(self.points[c])
                    K += N0 / rho * np.outer(g, g)
        return K

    def reactions(self, x: np.ndarray, lam: np.ndarray, omega) -> np.ndarray:
        r"""Force on the vessel at each contact, (..., Np, 3): the pins' :math:`\lambda d` and the springs'
        :math:`-(k + i\omega c)\,d\,d^\top G x`, for motions ``x`` (..., 6) and pin reactions ``lam``
        (..., m) at frequency ``omega`` (broadcast against the leading axes; 0 for statics)."""
        w = np.asarray(omega, dtype=float)
        J = np.zeros(x.shape[:-1] + (self.n_points, 3), dtype=complex)
        row = 0
        for c, dirs in enumerate(self.directions()):
            G = point_map(self.points[c])
            for d, k, cc in dirs:
                if math.isinf(k):
                    J[..., c, :] += lam[..., row:row + 1] * d
                    row += 1
                else:
                    kc = k + 1j * w * cc
                    J[..., c, :] -= (kc * (x @ (d @ G)))[..., None] * d
        return J


class NoStaticEquilibrium(ValueError):
    """The landing cannot hold the push (and the steady loads) statically: :func:`static_preload` found no
    equilibrium (a ValueError, as before it had a class of its own)."""


def static_preload(C: np.ndarray, law: ContactLaw, thrust: float, thrust_position, direction=_EX,
                   steady: SteadyLoad | None = None):
    r"""Static equilibrium on the landing under the follower thrust: (x⁰, J⁰, K_g(J⁰)).

    :math:`(C + K_{springs} - K_g(J^0) + K^s)\,x^0 = T[e_T;\ r_T\times e_T] + F^s + \mathcal T^\top\lambda^0`
    with the pins :math:`\mathcal T x^0 = 0`: the preload's own stiffness tilts the thrust and turns the
    contact moments by the static rotation. A fixed point in J⁰ (K_g is O(T/C₅₅) of the restoring: a
    few iterations). For a rigid hinge pinned in all directions this is the static vertical force of
    Grøtting (2015) eq. 3.56–3.61, plus the tilt of the thrust by the static pitch that §3.4 neglects.
    ``direction``: the push's body direction e_T (default e_x); ``steady``: the steady loads besides the
    push (:class:`SteadyLoad`: current, mean wind and drift), their force F^s and stiffness K^s.

    Raises
    ------
    NoStaticEquilibrium
        The landing cannot hold the thrust statically, or the iteration does not converge.
    """
    rT = np.asarray(thrust_position, dtype=float).reshape(3)
    eT = np.asarray(direction, dtype=float).reshape(3)
    F_T = thrust * np.concatenate([eT, np.cross(rT, eT)])
    K, _, pins, _ = law.assemble()
    if steady is not None:
        F_T = F_T + steady.force
        K = K + steady.stiffness
    J0 = np.zeros((law.n_points, 3))
    Kg = np.zeros((6, 6))
    last = np.inf
    for _ in range(50):
        xs, ls, res = solve_saddle((C + K - Kg).astype(complex), pins, F_T[:, None].astype(complex))
        if res > 1e-8:
            raise NoStaticEquilibrium(
                f"the landing cannot hold the thrust statically (relative residual {res:.2g}): a force "
                "or moment about a direction with neither restoring nor a restraint — e.g. a yaw moment "
                "about a single fender point, or a normal without a spring")
        x0 = xs[:, 0].real
        J_new = law.reactions(x0, ls[:, 0].real, 0.0).real
        change = np.max(np.abs(J_new - J0)) / max(np.max(np.abs(J_new)), 1e-300)
        # converged: at round-off, or no longer falling once below 1e-8 (stiff springs: the floor of the
        # solve's round-off is ~1e-11 of the force at k_t = 3e8 N/m)
        done = change <= 1e-12 or (change < 1e-8 and change > 0.5 * last)
        last = change
        J0 = J_new
        Kg = preload_stiffness(thrust, rT, J0, law.points, eT) + law.geometric_stiffness(J0)
        if done:
            return x0, J0, Kg
    raise NoStaticEquilibrium("the static equilibrium under the thrust did not converge: the preload's geometric "
                              "stiffness is comparable with the restoring (thrust far too large for this landing)")


@dataclass(frozen=True, eq=False)
class LandedModes:
    """Undamped natural modes of the landed vessel (lowest first).

    Attributes
    ----------
    omega : ndarray, shape (k,)
        Natural frequencies [rad/s] (modes with no restoring at all are left out).
    shapes : ndarray, shape (k, 6)
        Mode shapes (rows; unit norm in the mass metric M + A(ω)).
    dominant : list of str
        The DOF with the largest kinetic share of each mode.
    """

    omega: np.ndarray
    shapes: np.ndarray
    dominant: list[str]

    @property
    def periods(self) -> np.ndarray:
        return 2 * np.pi / self.omega


def landed_modes(db: HydroDB, law: ContactLaw | None, thrust: float = 0.0, thrust_position=(0.0, 0.0, 0.0),
                 direction=_EX, steady: SteadyLoad | None = None) -> LandedModes:
    r"""Natural modes of the vessel on its landing (or free, ``law`` None), undamped, with the added
    mass at each mode's own frequency:

    .. math:: \left(C + K_{springs} - K_g\right)\phi = \omega^2\,(M + A(\omega))\,\phi
              \quad\text{on}\ \{\phi : \mathcal T\phi = 0\}

    (pinned directions removed by a null-space basis of :math:`\mathcal T`; A(ω) by fixed-point
    iteration per mode, linear in ω as the RAOs take it). Rigid-body modes without any restoring
    (ω² ≤ 0) are left out. The stiffness is symmetrised (K_g is not quite symmetric: a follower force).
    """
    if db.M is None:
        raise ValueError(f"database {db.name!r} has no mass matrix")
    Kc, pins = np.zeros((6, 6)), np.zeros((0, 6))
    Kg = np.zeros((6, 6))
    if law is not None:
        Kc, _, pins, _ = law.assemble()
        if thrust:
            _, _, Kg = static_preload(db.C, law, thrust, thrust_position, direction, steady)
    Keff = db.C + Kc - Kg + (steady.stiffness if steady is not None else 0.0)
    Keff = 0.5 * (Keff + Keff.T)
    if pins.shape[0]:
        _, sv, Vt = np.linalg.svd(pins)
        rank = int(np.sum(sv > 1e-9 * sv.max()))
        Nb = Vt[rank:].T                                 # (6, 6 − rank) basis of the allowed motions
    else:
        Nb = np.eye(6)

    def added_mass(w):
        if w is None:
            return db.A_inf if db.A_inf is not None else db.A[:, :, -1]
        i = np.clip(np.searchsorted(db.omega, w) - 1, 0, db.n_freq - 2)
        f = np.clip((w - db.omega[i]) / (db.omega[i + 1] - db.omega[i]), 0.0, 1.0)
        return (1 - f) * db.A[:, :, i] + f * db.A[:, :, i + 1]

    def solve(w):
        Mt = db.M + added_mass(w)
        Mt = 0.5 * (Mt + Mt.T)
        lam, V = _generalised_eigh(Nb.T @ Keff @ Nb, Nb.T @ Mt @ Nb)
        return lam, Nb @ V, Mt

    lam0, _, _ = solve(float(db.omega[0]))
    omegas, shapes = [], []
    for k in range(lam0.size):
        if lam0[k] <= 1e-9 * max(abs(lam0).max(), 1e-300):
            continue
        w = math.sqrt(lam0[k])
        try:
            for _ in range(50):
                lam, V, _ = solve(w)
                w_new = math.sqrt(max(lam[k], 0.0))
                if abs(w_new - w) <= 1e-10 * w:
                    break
                w = w_new
            lam, V, Mt = solve(w)
        except np.linalg.LinAlgError:
            # M + A(ω) is not positive definite at some ω of the iteration (a resonance of the waves
            # trapped between the hulls makes A(ω) swing): take this mode with A∞ (a fast mode).
            lam, V, Mt = solve(None)
            w = math.sqrt(max(lam[k], 0.0))
        phi = V[:, k]
        phi = phi / math.sqrt(phi @ Mt @ phi)
        omegas.append(w)
        shapes.append(phi)
    order = np.argsort(omegas)
    names = ("surge", "sway", "heave", "roll", "pitch", "yaw")
    shapes_a = np.array(shapes)[order] if shapes else np.zeros((0, 6))
    dominant = [names[int(np.argmax(np.abs(s) * np.sqrt(np.diag(db.M))))] for s in shapes_a]
    return LandedModes(omega=np.array(omegas)[order], shapes=shapes_a, dominant=dominant)


def _generalised_eigh(K: np.ndarray, M: np.ndarray):
    """Eigenvalues (ascending) and M-orthonormal vectors of K v = λ M v, K symmetric, M SPD."""
    L = np.linalg.cholesky(M)
    Li = np.linalg.inv(L)
    lam, Y = np.linalg.eigh(Li @ K @ Li.T)
    return lam, Li.T @ Y


def normal_follows(width: float, radii, compression: float = 0.0) -> dict:
    """How the contact normals of a fender of this ``width`` on tubes of these ``radii`` turn
    (:attr:`ContactLaw.follows`), as :mod:`boatland.contact.fender` has them: a line fender meets the
    tubes with its face, a point fender follows the round tubes — unless the static ``compression``
    [m] reaches past the tube's axis, where the normal is the landing's (fixed)."""
    radii = np.asarray(radii, dtype=float)
    if compression >= radii.min():
        return {"follows": "fixed"}
    return {"follows": "fender"} if width > 0 else {"follows": "tube", "radius": radii}
