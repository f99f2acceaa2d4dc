r"""Bow fender against the tubes of a boat landing: spring–damper normal force, a rubber fender that
shears while it sticks, Stribeck friction when it slides, and the rigid stick of Ferreira González
(2023) as the limit of an infinitely stiff rubber.

References: Ferreira González, D. (2023), *Development of a Numerical Approach for the Simulation of
Boatlanding Maneuvers*, Dr.-Ing. dissertation, TU Hamburg — §2.5 (friction, Stribeck, the stick
condition as an extra unknown), §3.4 (the fender contact model, two contacts); Grøtting, H. (2015),
*Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc thesis, NTNU — §3.2.2
(fender modelling: shear stiffness 3000 kN/m after Wu 2014, friction in all directions along the
sliding plane); Cundall, P. A. & Strack, O. D. L. (1979), *Géotechnique* 29(1), 47–65 (tangential
spring capped by Coulomb friction); Simo, J. C. & Hughes, T. J. R. (1998), *Computational Inelasticity*,
Springer, §1.2 and §2.3 (the return map of a rate-independent slider).

Geometry (local frame: origin at the vessel reference point's mean position, axes along the vessel
at rest, z up). A **tube** of the landing is a vertical cylinder: axis through :math:`a_c`, radius
:math:`\rho_c`, from :math:`z_{bot}` to :math:`z_{top}` (an infinite radius is a flat plate through
:math:`a_c` with normal :math:`n^0_c`). The **fender** of contact c is a horizontal line of half
width :math:`w_c` through the body point :math:`p_c` along the body direction :math:`d_c` (a point when
:math:`w_c = 0`). With the exact rotation R of the vessel, the contact point is the point of the
fender line closest to the tube axis,

.. math:: s^* = \mathrm{clip}\!\left(-\frac{(x + Rp_c - a_c)_{xy}\cdot(Rd_c)_{xy}}{|(Rd_c)_{xy}|^2},
          -w_c, w_c\right), \qquad Q = x + R(p_c + s^* d_c),

where the tube meets the fender's face (the axis projects onto the line, :math:`|s| \le w_c`) the
normal is the face's, :math:`n = -m` with :math:`m = (R(d_c \times e_z))_{xy}` normalised (from the tube
towards the vessel), and the penetration is :math:`\delta = \rho_c - (a_c - Q)\cdot m`; where it meets
the end of the line the normal follows the tube surface to that end, :math:`n = (Q - a_c)_{xy}/|(Q -
a_c)_{xy}|`, :math:`\delta = \rho_c - |(Q - a_c)_{xy}|` (continuous with the face at :math:`|s| = w_c`).
The geometry assumes the fender is compressed less than a tube radius; a lumped spring that compresses
further (the tank model's c_f = 0.5 kN/m: 0.12 m under 62 N on a 17 mm tube) is given a flat plate at
the tubes' front instead by :func:`boatland.landing.contacts.fender_on_landing` — with a tube axis behind the
face, the face normal would turn the normal force about it, a yaw lever with no physical counterpart. The
tangents are :math:`t_v = e_z` and :math:`t_h = e_z \times n`. The contact is **off the landing** when Q is above
or below the tube, or when the tube has passed the end of the fender line by a tube radius (no
contact is possible there): the trial ends with that incident.

Forces on the vessel at Q (velocity of the fender material there :math:`V = \dot x_{1:3} + \omega\times r`,
:math:`r = Q - x_{1:3}`, :math:`\omega \approx \dot x_{4:6}` as in linear seakeeping):

- normal (Ferreira González 2023, eq. 3.21; never pulling): :math:`f_n = \max(0,\, c_f\delta + d_f\dot\delta)`
  along n, :math:`\dot\delta = -V\cdot n`;
- Stribeck coefficient (eq. 2.78): :math:`\mu(v) = \mu_k + (\mu_s-\mu_k)e^{-(v/v_{ref})^\delta} + k_v v`,
  v the tangential sliding speed in the directions friction acts in (vertical, and horizontal when
  ``sideways``) — the same speed for the stick/slip decision and for μ;
- tangential, **compliant fender** (shear stiffness :math:`k_t`, damping :math:`c_t`): the rubber's
  patch is anchored on the tube (anchor A, the fender material point :math:`p_A` it holds) and its
  shear deflection :math:`e = ((x + Rp_A) - A)\cdot(t_v, t_h)` carries

  .. math:: f^{tr} = -k_t\,e - c_t\,u, \qquad f = f^{tr}\,\min\!\left(1, \frac{\mu f_n}{|f^{tr}|}\right),

  the trial force capped by friction (Cundall & Strack 1979): μ = μ_s while the contact sticks,
  μ(|u|) while it slides. The anchor slides only through the **return map** at the end of a sliding
  step (Simo & Hughes 1998): when :math:`|f^{tr}| > \mu f_n` the deflection is projected back onto
  the friction limit, :math:`k_t e' = -\mu f_n \hat f^{tr} - c_t u`, and the anchor moves by
  :math:`\Delta A = e - e' = -(|f^{tr}| - \mu f_n)\,\hat f^{tr}/k_t` — exactly against the friction
  force :math:`\mu f_n \hat f^{tr}`. Friction therefore opposes the sliding of the rubber over the
  tube in both tangential directions at once, and its work :math:`f\cdot\Delta A = -\mu f_n(|f^{tr}| -
  \mu f_n)/k_t` is never positive, at any Δt. The shear force is explicit in the state, so RK4 integrates
  it to fourth order while the contact sticks: the stuck fender is exactly the spring-supported
  vessel of the frequency domain (:mod:`boatland.freqdomain.rao`).
- tangential, **rigid stick** (:math:`k_t = \infty`, the model of Ferreira González 2023): the needed
  stick forces are extra unknowns of the equation of motion (eq. 2.84–2.86, 3.22–3.24),

  .. math::
      (M + A_\infty)\,a - \sum_{c\in S} G_c f_c = F, \qquad G_c^\top a = \dot u'_c \quad (c \in S),

  :math:`G_c = [t;\ r_c\times t]`, :math:`\dot u'_c = -u_c/\Delta t - e_c/\Delta t^2 - (\omega\times(\omega
  \times r_c))_t`: the tangential velocity is driven to zero within the step (eq. 3.23) and a contact
  already stuck is pulled back to its anchor so that it cannot drift. Solved by the Schur complement
  on :math:`(M+A_\infty)^{-1}` by damped least squares: redundant constraints (two tubes restraining
  the same sideways motion) share their force equally. A sliding rigid contact carries
  :math:`\mu(|u|)f_n` against its sliding velocity u at every RK4 stage (the power :math:`f\cdot u\le 0`
  at every stage, so the RK4-weighted work of a step is never positive); below ``v_tol`` the
  direction of the force that would have stopped it, less any component along u.

Modes (decided once per step at its start, kept for the four RK4 stages): 0 open, 1 stick, 2 slip,
3 off the landing. Compliant: a stuck contact slips when :math:`|f^{tr}| > \mu_s f_n`; a sliding one
slides on while the rubber is loaded further (:math:`f^{tr}\cdot u < 0`, the fender still moving
against its friction) or its force exceeds :math:`\mu_s f_n`, else it sticks again where its anchor
is. Rigid: every contact in touch is first tried stuck; the one whose needed force exceeds the
available :math:`\mu(|u|)f_n` by most is released, the rest solved again, until every stuck contact
holds (for two contacts the three-case logic of Ferreira González 2023 §3.4).

Per RK4 stage the kinematics of every contact are computed once (:func:`contact_states`) into buffers
of :func:`contact_workspace`, allocated once per run. The kernels here only index caller-owned arrays
and are compiled without numba's reference counting and inlined into the integrator (``_nrt=False,
forceinline=True``; see :mod:`boatland.integrate.cummins`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.core.extending import intrinsic

from boatland.rigid import add_point_force, angular_velocity, euler_moment

__all__ = ["Contacts", "contact_set", "no_contacts", "stribeck", "contact_workspace", "contact_states",
           "contact_forces", "decide_modes", "contact_state_arrays", "accumulate_sliding", "OPEN", "STICK", "SLIP", "OFF",
           "MODE_NAMES"]

OPEN, STICK, SLIP, OFF = 0, 1, 2, 3
#: What the mode codes mean (records, events, logs).
MODE_NAMES = ("open", "stick", "slip", "off the landing")


class Contacts(NamedTuple):
    """The fender contacts of a trial as the kernel takes them (local frame, SI).

    Attributes
    ----------
    P : (Nc, 3)
        Centre of each contact's fender line, body frame [m].
    D : (Nc, 3)
        Unit direction of the fender line, body frame (horizontal at rest, e.g. (0, 1, 0)).
    HW : (Nc,)
        Half width of the fender line [m]; 0 for a point.
    AX : (Nc, 3)
        A point of the tube axis at z = 0, local frame [m].
    RT : (Nc,)
        Tube radius [m]; ``inf`` for a flat plate through ``AX`` with normal ``N0``.
    ZB, ZT : (Nc,)
        Bottom and top of the tube, local z [m] (±inf: unbounded).
    N0 : (Nc, 3)
        Horizontal unit normal of the landing at rest (from the landing towards the vessel): the plate's
        normal, and the reference of the horizontal position ``tpos`` (along :math:`e_z \\times N_0`).
    CF, DF : (Nc,)
        Normal spring c_f [N/m] and damper d_f [N s/m].
    KT, CT : (Nc,)
        Shear stiffness k_t [N/m] (``inf``: the rigid stick) and shear damping c_t [N s/m] of the rubber.
    MU : (Nc, 5)
        μ_s, μ_k, k_v [s/m], v_ref [m/s], δ of the Stribeck law.
    sideways : bool
        Friction (and shear) also horizontally along the tube surface, not only vertically.
    """

    P: np.ndarray
    D: np.ndarray
    HW: np.ndarray
    AX: np.ndarray
    RT: np.ndarray
    ZB: np.ndarray
    ZT: np.ndarray
    N0: np.ndarray
    CF: np.ndarray
    DF: np.ndarray
    KT: np.ndarray
    CT: np.ndarray
    MU: np.ndarray
    sideways: bool

    @property
    def n(self) -> int:
        return self.P.shape[0]


def contact_set(points, axes, radius, normal, *, direction=(0.0, 1.0, 0.0), half_width=0.0,
                bottom=-math.inf, top=math.inf, stiffness, damping, shear_stiffness=math.inf,
                shear_damping=0.0, mu_s=0.0, mu_k=0.0, k_v=0.0, v_ref=0.2, delta=1.5,
                sideways: bool = True) -> Contacts:
    """Build a :class:`Contacts` from per-contact values (scalars are repeated for every contact).

    Parameters
    ----------
    points : array_like, shape (Nc, 3)
        Fender line centres, body frame [m].
    axes : array_like, shape (Nc, 2) or (Nc, 3)
        Tube axis positions (x, y), local frame [m].
    radius : float or array_like
        Tube radii [m] (``inf``: flat plate).
    normal : array_like, shape (Nc, 2) or (Nc, 3)
        Landing normals at rest (towards the vessel), horizontal.
    direction : array_like, shape (3,) or (Nc, 3)
        Fender line direction, body frame.
    half_width, bottom, top, stiffness, damping, shear_stiffness, shear_damping, mu_s, mu_k, k_v, v_ref, delta
        Per contact or one value for all (see :class:`Contacts`).
    sideways : bool
    """
    P = np.ascontiguousarray(np.atleast_2d(np.asarray(points, dtype=float)))
    nc = P.shape[0]

    def vec3(a):
        a = np.atleast_2d(np.asarray(a, dtype=float))
        if a.shape[1] == 2:
            a = np.column_stack([a, np.zeros(a.shape[0])])
        return np.array(np.broadcast_to(a, (nc, 3)), dtype=float)

    def per(a):
        return np.array(np.broadcast_to(np.asarray(a, dtype=float), (nc,)), dtype=float)

    D = vec3(direction)
    D = D / np.maximum(np.linalg.norm(D, axis=1), 1e-300)[:, None]
    N0 = vec3(normal)
    N0[:, 2] = 0.0
    N0 = N0 / np.linalg.norm(N0, axis=1)[:, None]
    AX = vec3(axes)
    AX[:, 2] = 0.0
    MU = np.ascontiguousarray(np.column_stack([per(mu_s), per(mu_k), per(k_v), per(v_ref), per(delta)]))
    return Contacts(P, np.ascontiguousarray(D), per(half_width), np.ascontiguousarray(AX), per(radius), per(bottom),
                    per(top), np.ascontiguousarray(N0), per(stiffness), per(damping), per(shear_stiffness),
                    per(shear_damping), MU, bool(sideways))


def no_contacts() -> Contacts:
    """An empty contact set (free floating)."""
    e3, e = np.zeros((0, 3)), np.zeros(0)
    return Contacts(e3, e3, e, e3, e, e, e, e3, e, e, e, e, np.zeros((0, 5)), True)


@intrinsic
def _fma(typingctx, a, b, c):
    """a·b + c with a single rounding (LLVM ``llvm.fma.f64``; a hardware FMA on x86-64 since Haswell)."""
    sig = types.float64(types.float64, types.float64, types.float64)

    def codegen(context, builder, signature, args):
        d = ir.DoubleType()
        fn = builder.module.declare_intrinsic("llvm.fma", [d], ir.FunctionType(d, [d, d, d]))
        return builder.call(fn, args)

    return sig, codegen


@njit(cache=True, _nrt=False, forceinline=True)
def stribeck(v, mu_s, mu_k, k_v, v_ref, delta):
    """μ(v) = μ_k + (μ_s − μ_k) exp(−(|v|/v_ref)^δ) + k_v |v|  (Ferreira González 2023, eq. 2.78); μ(0) = μ_s."""
    s = abs(v)
    return mu_k + (mu_s - mu_k) * np.exp(-((s / v_ref) ** delta)) + k_v * s


@njit(cache=True, _nrt=False, forceinline=True)
def _speed(u0, u1, sideways):
    """Tangential sliding speed in the directions friction acts in."""
    return math.sqrt(u0 * u0 + u1 * u1) if sideways else abs(u0)


@njit(cache=True)
def contact_workspace(nc, sideways):
    """Buffers of :func:`contact_states`, :func:`contact_forces` and :func:`decide_modes` for ``nc``
    contacts, allocated once per run (the hot loop allocates nothing).

    Returns
    -------
    kin : tuple
        Kinematics of every contact at one state: lever r (Nc, 3) of the contact point Q, normal n
        (Nc, 3), horizontal tangent t_h (Nc, 3), tangential velocity u (Nc, 2), tangential centripetal
        acceleration (Nc, 2), (δ, δ̇) (Nc, 2), ``tpos`` (Nc, 2), shear deflection e from the anchor
        (Nc, 2), the contact point p_c + s* d_c in the body frame (Nc, 3), off the landing (Nc,) bool.
    solve : tuple
        The augmented solve for up to m = Nc·(2 if sideways else 1) rigid stick constraints: G (6, m),
        target (m,), first column of each contact (Nc,) int, (M + A∞)⁻¹G (6, m), W (m, m),
        right-hand side and solution (m,), Cholesky factor (m, m).
    F_try : (6,)
        Scratch copy of the other forces for each trial solve of :func:`decide_modes`.
    """
    m = nc * (2 if sideways else 1)
    kin = (np.zeros((nc, 3)), np.zeros((nc, 3)), np.zeros((nc, 3)), np.zeros((nc, 2)), np.zeros((nc, 2)),
           np.zeros((nc, 2)), np.zeros((nc, 2)), np.zeros((nc, 2)), np.zeros((nc, 3)), np.zeros(nc, dtype=np.bool_))
    solve = (np.zeros((6, m)), np.zeros(m), np.zeros(nc, dtype=np.int64), np.zeros((6, m)), np.zeros((m, m)),
             np.zeros(m), np.zeros(m), np.zeros((m, m)))
    return kin, solve, np.zeros(6)


@njit(cache=True)
def contact_state_arrays(nc):
    """The per-contact state carried from step to step: mode (Nc,), slip direction of a rigid contact
    (Nc, 2), anchor on the tube A (Nc, 3, local), fender material point it holds p_A (Nc, 3, body),
    anchored (Nc,), landed (Nc,: has stuck at least once), and the sliding and friction work of the
    step so far: slide (Nc, 2) [m], work (Nc,) [J]."""
    return (np.zeros(nc, dtype=np.int64), np.zeros((nc, 2)), np.zeros((nc, 3)), np.zeros((nc, 3)),
            np.zeros(nc, dtype=np.bool_), np.zeros(nc, dtype=np.bool_), np.zeros((nc, 2)), np.zeros(nc))


@njit(cache=True, _nrt=False, forceinline=True)
def _contact_point(R, x, C, c):
    """Closest point of contact c's fender line to its tube: returns (s*, unclamped s, Q (3 floats))."""
    p, d = C.P[c], C.D[c]
    # fender line centre and direction, local frame
    cx = x[0] + R[0, 0] * p[0] + R[0, 1] * p[1] + R[0, 2] * p[2]
    cy = x[1] + R[1, 0] * p[0] + R[1, 1] * p[1] + R[1, 2] * p[2]
    cz = x[2] + R[2, 0] * p[0] + R[2, 1] * p[1] + R[2, 2] * p[2]
    dx = R[0, 0] * d[0] + R[0, 1] * d[1] + R[0, 2] * d[2]
    dy = R[1, 0] * d[0] + R[1, 1] * d[1] + R[1, 2] * d[2]
    dz = R[2, 0] * d[0] + R[2, 1] * d[1] + R[2, 2] * d[2]
    hw = C.HW[c]
    su = 0.0
    d2 = dx * dx + dy * dy
    if d2 > 0.0 and math.isfinite(C.RT[c]):
        su = -((cx - C.AX[c, 0]) * dx + (cy - C.AX[c, 1]) * dy) / d2
    s = min(max(su, -hw), hw)
    return s, su, cx + s * dx, cy + s * dy, cz + s * dz, cx, cy


@njit(cache=True, _nrt=False, forceinline=True)
def _point_kinematics(R, x, v, C, c, cs, kin, omega):
    """Kinematics of contact c at the state (x, v) with rotation ``R`` into row c of ``kin``; ``omega``: the
    body's angular velocity and its axes' turning (:func:`boatland.rigid.angular_velocity`)."""
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    s, su, qx, qy, qz, cx, cy = _contact_point(R, x, C, c)
    ax, ay = C.AX[c, 0], C.AX[c, 1]
    rho = C.RT[c]
    if math.isfinite(rho):
        # the fender face's outward normal m = R (d × e_z), horizontal part
        d = C.D[c]
        bx, by = d[1], -d[0]
        mx = R[0, 0] * bx + R[0, 1] * by
        my = R[1, 0] * bx + R[1, 1] * by
        mm = math.sqrt(mx * mx + my * my)
        mx, my = mx / mm, my / mm
        front = (ax - qx) * mx + (ay - qy) * my        # the tube axis ahead of the fender face at Q
        if abs(su) <= C.HW[c] or front <= 0.0:
            nx, ny = -mx, -my                          # the tube meets the fender's face
            delta = rho - front
        else:                                          # ... or the end of the fender line
            hx, hy = qx - ax, qy - ay
            dist = math.sqrt(hx * hx + hy * hy)
            nx, ny = hx / dist, hy / dist
            delta = rho - dist
        past_end = abs(su) - C.HW[c] >= rho
    else:  # flat plate through AX with normal N0
        nx, ny = C.N0[c, 0], C.N0[c, 1]
        delta = (ax - qx) * nx + (ay - qy) * ny
        past_end = False
    off[c] = past_end or qz < C.ZB[c] or qz > C.ZT[c]
    rx, ry, rz = qx - x[0], qy - x[1], qz - x[2]
    wx, wy, wz, bx_, by_, bz_ = omega
    Vx = v[0] + wy * rz - wz * ry
    Vy = v[1] + wz * rx - wx * rz
    Vz = v[2] + wx * ry - wy * rx
    kx, ky, kz = wy * rz - wz * ry, wz * rx - wx * rz, wx * ry - wy * rx
    # the point's acceleration beyond the angles' own: ω × (ω × r) and the Euler axes' turning × r
    ax_ = wy * kz - wz * ky + by_ * rz - bz_ * ry
    ay_ = wz * kx - wx * kz + bz_ * rx - bx_ * rz
    az_ = wx * ky - wy * kx + bx_ * ry - by_ * rx
    tx, ty = -ny, nx                   # t_h = e_z × n
    r[c, 0], r[c, 1], r[c, 2] = rx, ry, rz
    nrm[c, 0], nrm[c, 1], nrm[c, 2] = nx, ny, 0.0
    th[c, 0], th[c, 1], th[c, 2] = tx, ty, 0.0
    u[c, 0] = Vz
    u[c, 1] = Vx * tx + Vy * ty
    cen[c, 0] = az_
    cen[c, 1] = ax_ * tx + ay_ * ty
    dd[c, 0] = delta
    dd[c, 1] = -(Vx * nx + Vy * ny)
    # the fender's position in the landing's frame: contact height, the fender centre along e_z × N0
    tpos[c, 0] = qz
    tpos[c, 1] = cx * (-C.N0[c, 1]) + cy * C.N0[c, 0]
    p = C.P[c]
    d = C.D[c]
    cp[c, 0], cp[c, 1], cp[c, 2] = p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]
    if anchored[c]:
        a = anchP[c]
        mx = x[0] + R[0, 0] * a[0] + R[0, 1] * a[1] + R[0, 2] * a[2] - anchA[c, 0]
        my = x[1] + R[1, 0] * a[0] + R[1, 1] * a[1] + R[1, 2] * a[2] - anchA[c, 1]
        mz = x[2] + R[2, 0] * a[0] + R[2, 1] * a[1] + R[2, 2] * a[2] - anchA[c, 2]
        e[c, 0] = mz
        e[c, 1] = mx * tx + my * ty
    else:
        e[c, 0] = 0.0
        e[c, 1] = 0.0


@njit(cache=True, _nrt=False, forceinline=True)
def contact_states(R, x, v, C, cs, kin):
    """Kinematics of every contact at the state (x, v) with rotation ``R`` = R(x₄, x₅, x₆), into ``kin``
    (see :func:`contact_workspace`): computed once per RK4 stage, shared by the stick–slip decision
    and the contact forces. ``cs`` is the contact state (:func:`contact_state_arrays`: the anchors)."""
    omega = angular_velocity(R, v)  # the same for every contact
    for c in range(C.P.shape[0]):
        _point_kinematics(R, x, v, C, c, cs, kin, omega)


@njit(cache=True, _nrt=False, forceinline=True)
def _anchor_here(R, x, c, kin, cs, e0, e1):
    """Anchor contact c at its current contact point with shear deflection (e0, e1): p_A = the fender
    point in contact, A = its position less the deflection along (t_v, t_h)."""
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    for k in range(3):
        anchP[c, k] = cp[c, k]
    px = x[0] + R[0, 0] * cp[c, 0] + R[0, 1] * cp[c, 1] + R[0, 2] * cp[c, 2]
    py = x[1] + R[1, 0] * cp[c, 0] + R[1, 1] * cp[c, 1] + R[1, 2] * cp[c, 2]
    pz = x[2] + R[2, 0] * cp[c, 0] + R[2, 1] * cp[c, 1] + R[2, 2] * cp[c, 2]
    anchA[c, 0] = px - e1 * th[c, 0]
    anchA[c, 1] = py - e1 * th[c, 1]
    anchA[c, 2] = pz - e0
    anchored[c] = True
    e[c, 0] = e0
    e[c, 1] = e1


@njit(cache=True, _nrt=False, forceinline=True)
def _normal_force(C, c, kin):
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    if off[c] or dd[c, 0] <= 0.0:
        return 0.0
    fn = C.CF[c] * dd[c, 0] + C.DF[c] * dd[c, 1]
    return fn if fn > 0.0 else 0.0


@njit(cache=True, _nrt=False, forceinline=True)
def _shear_trial(C, c, kin):
    """Trial shear force (vertical, horizontal) of a compliant contact with its anchor held: −k_t e − c_t u."""
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    fv = -C.KT[c] * e[c, 0] - C.CT[c] * u[c, 0]
    fh = (-C.KT[c] * e[c, 1] - C.CT[c] * u[c, 1]) if C.sideways else 0.0
    return fv, fh


@njit(cache=True, _nrt=False, forceinline=True)
def _add_tangential(R, r, th, c, fv, fh, sideways, F):
    add_point_force(R, r[c, 0], r[c, 1], r[c, 2], 0.0, 0.0, 1.0, fv, F)
    if sideways:
        add_point_force(R, r[c, 0], r[c, 1], r[c, 2], th[c, 0], th[c, 1], th[c, 2], fh, F)


@njit(cache=True, _nrt=False, forceinline=True)
def _damped_solve(W, b, m, V, y, rho):
    r"""Damped least-squares solution of W y = b for a small symmetric positive semi-definite W (its
    leading m × m block):

    .. math:: y = (W^2 + \mu^2 I)^{-1} W b = \sum_k \frac{\lambda_k}{\lambda_k^2 + \mu^2}\, v_k v_k^\top b,
              \qquad \mu = \rho \max_k W_{kk}

    (damped least squares at kinematic singularities: Nakamura & Hanafusa 1986, *J. Dyn. Syst. Meas.
    Control* 108(3); Wampler 1986, *IEEE Trans. SMC* 16(1)), by Cholesky of the positive-definite
    :math:`W^2 + \mu^2 I` in ``V`` (no allocation, no LAPACK: 1–8 unknowns). Exactly redundant
    constraints (λ = 0: two struts sharing a plane both stuck sideways) get the minimum-norm solution —
    the statically indeterminate force shared equally — whatever their right-hand sides. Nearly
    redundant ones (the same two contacts once the vessel has yawed a little: their sideways
    constraints then differ only through a lever of spacing × yaw) would make a rigid stick lock the
    yaw through that lever with forces of order 1/lever; the damping bounds the gain at 1/(2μ) and
    leaves well-conditioned directions (λ ≫ μ) exact to (μ/λ)². ``W`` is left symmetrised.
    """
    mu = 0.0
    for k in range(m):
        mu = max(mu, W[k, k])
        for q in range(k):  # symmetric by construction; average out round-off
            w = 0.5 * (W[k, q] + W[q, k])
            W[k, q] = w
            W[q, k] = w
    mu *= rho
    for i in range(m):
        s = 0.0
        for k in range(m):
            s += W[i, k] * b[k]
        y[i] = s                                   # W b
        for j in range(i + 1):
            s = 0.0
            for k in range(m):
                s += W[i, k] * W[k, j]
            V[i, j] = s + (mu * mu if i == j else 0.0)
    # in-place Cholesky of the lower triangle of V, then forward and back substitution on y
    for j in range(m):
        d = V[j, j]
        for k in range(j):
            d -= V[j, k] * V[j, k]
        d = np.sqrt(d)
        V[j, j] = d
        for i in range(j + 1, m):
            s = V[i, j]
            for k in range(j):
                s -= V[i, k] * V[j, k]
            V[i, j] = s / d
    for i in range(m):
        s = y[i]
        for k in range(i):
            s -= V[i, k] * y[k]
        y[i] = s / V[i, i]
    for i in range(m - 1, -1, -1):
        s = y[i]
        for k in range(i + 1, m):
            s -= V[k, i] * y[k]
        y[i] = s / V[i, i]


#: Damping ρ of the stick solve's least squares, relative to the largest diagonal entry of W (see
#: :func:`_damped_solve`): directions the stuck contacts restrain only through a lever shorter than
#: about √ρ ≈ 3 % of the vessel's radius of gyration are left to the fender's compliance.
STICK_DAMPING = 1e-3


@njit(cache=True, _nrt=False, forceinline=True)
def _dot_fma(a, b):
    """Σ a_e b_e over 6 terms, fused multiply–adds in index order."""
    s = 0.0
    for e in range(6):
        s = _fma(a[e], b[e], s)
    return s


@njit(cache=True, _nrt=False, forceinline=True)
def _dot_pairs(a, b):
    """Σ a_e b_e over 6 terms as ((a₀b₀ + a₂b₂) + (a₁b₁ + a₃b₃)) + (a₄b₄ + a₅b₅ with one rounding)."""
    head = (a[0] * b[0] + a[2] * b[2]) + (a[1] * b[1] + a[3] * b[3])
    return head + _fma(a[4], b[4], a[5] * b[5])


@njit(cache=True, _nrt=False, forceinline=True)
def _schur(Mt_inv, G, m, acc, target, MG, W, rhs):
    """MG = (M + A∞)⁻¹ G, W = Gᵀ MG and rhs = target − Gᵀ acc over the first m columns of G.

    Written out (1–8 columns: a BLAS call costs more than its arithmetic here) in one fixed summation
    order — fused multiply–adds in index order, and the pairwise 6-term sum of :func:`_dot_pairs` for
    single columns and Gᵀacc — so results do not depend on the BLAS build or its thread count.
    """
    for k in range(m):
        for d in range(6):
            MG[d, k] = _dot_pairs(Mt_inv[d], G[:, k]) if m == 1 else _dot_fma(Mt_inv[d], G[:, k])
    for a in range(m):
        for b in range(m):
            W[a, b] = _dot_fma(G[:, a], MG[:, b])
        rhs[a] = target[a] - _dot_pairs(G[:, a], acc)


@njit(cache=True, _nrt=False, forceinline=True)
def _rigid_slip_direction(c, u, fdir, sideways, v_tol):
    """Unit direction (vertical, horizontal) of the friction on a sliding rigid contact: against its
    sliding velocity, or below ``v_tol`` the decided direction ``fdir`` less any component along u."""
    u0 = u[c, 0]
    u1 = u[c, 1] if sideways else 0.0
    sp = math.sqrt(u0 * u0 + u1 * u1)
    if sp > v_tol:
        return -u0 / sp, -u1 / sp
    dv, dh = fdir[c, 0], fdir[c, 1]
    p = dv * u0 + dh * u1
    if p > 0.0:                        # would push along the (tiny) velocity: keep only the normal part
        dv -= p * u0 / (sp * sp)
        dh -= p * u1 / (sp * sp)
        mag = math.sqrt(dv * dv + dh * dh)
        if mag > 0.0:
            dv, dh = dv / mag, dh / mag
    return dv, dh


@njit(cache=True, _nrt=False, forceinline=True)
def contact_forces(dt, C, cs, R, Mt_inv, kin, solve, F, acc, f_t, f_n, v_tol):
    r"""Add the contact forces to ``F`` and solve the accelerations ``acc`` at one RK4 stage.

    Parameters
    ----------
    dt : float
        Time step [s] (the rigid stick condition drives the tangential velocity to zero within it).
    C : Contacts
        The contacts.
    cs : tuple
        Contact state (:func:`contact_state_arrays`): the modes decided for this step, slip directions
        and anchors.
    R : (3, 3)
        The body rotation at the stage: the contact forces' moments act about its Euler axes
        (:func:`boatland.rigid.add_point_force`).
    Mt_inv : (6, 6)
        (M + A∞)⁻¹.
    kin, solve : tuple
        Kinematics of the stage state from :func:`contact_states`; solve buffers (see
        :func:`contact_workspace`).
    F : (6,)
        All other forces; contact forces are added in place.
    acc : (6,)
        Output accelerations.
    f_t : (Nc, 2)
        Output tangential friction (or stick) force per contact, along (t_v, t_h).
    f_n : (Nc,)
        Output normal force.
    v_tol : float
        Speed [m/s] below which a rigid contact's sliding direction is taken from its decided direction.
    """
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    G, target, idx, MG, W, rhs, f, V = solve
    nc = C.P.shape[0]
    sideways = C.sideways
    m_per = 2 if sideways else 1
    m = 0
    for c in range(nc):
        f_t[c, 0] = 0.0
        f_t[c, 1] = 0.0
        fn = _normal_force(C, c, kin)
        f_n[c] = fn
        if fn > 0.0:
            add_point_force(R, r[c, 0], r[c, 1], r[c, 2], nrm[c, 0], nrm[c, 1], nrm[c, 2], fn, F)
        if fn <= 0.0 or mode[c] == OPEN or mode[c] == OFF:
            continue
        mu = C.MU[c]
        if math.isfinite(C.KT[c]):
            # compliant: the sheared rubber, capped by friction (μ_s while stuck, Stribeck while sliding)
            fv, fh = _shear_trial(C, c, kin)
            if mode[c] == SLIP:
                cap = stribeck(_speed(u[c, 0], u[c, 1], sideways), mu[0], mu[1], mu[2], mu[3], mu[4]) * fn
            else:
                cap = mu[0] * fn
            mag = math.sqrt(fv * fv + fh * fh)
            if mag > cap:
                fv, fh = fv * cap / mag, fh * cap / mag
            f_t[c, 0], f_t[c, 1] = fv, fh
            _add_tangential(R, r, th, c, fv, fh, sideways, F)
            continue
        if mode[c] == SLIP:
            sp = _speed(u[c, 0], u[c, 1], sideways)
            cap = stribeck(sp, mu[0], mu[1], mu[2], mu[3], mu[4]) * fn
            dv, dh = _rigid_slip_direction(c, u, fdir, sideways, v_tol)
            fv, fh = cap * dv, cap * dh
            f_t[c, 0], f_t[c, 1] = fv, fh
            _add_tangential(R, r, th, c, fv, fh, sideways, F)
            continue
        # rigid and stuck: one or two constraint columns
        idx[c] = m
        rx, ry, rz = r[c, 0], r[c, 1], r[c, 2]
        for k in range(m_per):
            if k == 0:
                t0, t1, t2 = 0.0, 0.0, 1.0
            else:
                t0, t1, t2 = th[c, 0], th[c, 1], th[c, 2]
            G[0, m], G[1, m], G[2, m] = t0, t1, t2
            G[3, m], G[4, m], G[5, m] = euler_moment(R, ry * t2 - rz * t1, rz * t0 - rx * t2, rx * t1 - ry * t0)
            target[m] = -u[c, k] / dt - e[c, k] / (dt * dt) - cen[c, k]
            m += 1
    for d in range(6):
        a = 0.0
        for e_ in range(6):
            a += Mt_inv[d, e_] * F[e_]
        acc[d] = a
    if m == 0:
        return
    _schur(Mt_inv, G, m, acc, target, MG, W, rhs)
    # Damped least squares: two contacts on parallel struts give the same horizontal constraint twice
    # (a rigid fender cannot slide sideways at one tube only), so W is singular and the split of that
    # force between the tubes is statically indeterminate — shared equally. The two copies need not
    # agree (anchors set at different steps, centripetal terms): the solve enforces their mean.
    _damped_solve(W, rhs, m, V, f, STICK_DAMPING)
    for d in range(6):
        s = 0.0
        for k in range(m):
            s += MG[d, k] * f[k]
        acc[d] += s
    for c in range(nc):
        if mode[c] == STICK and f_n[c] > 0.0 and not math.isfinite(C.KT[c]):
            f_t[c, 0] = f[idx[c]]
            if sideways:
                f_t[c, 1] = f[idx[c] + 1]


@njit(cache=True, _nrt=False, forceinline=True)
def accumulate_sliding(C, cs, kin, f_t, w):
    """Add one RK4 stage of every sliding rigid contact to the step's slide [m] and friction work [J]
    in ``cs``: weight ``w`` = b_stage Δt, so that the step's sums are the RK4 quadratures of ∫u dt and
    ∫f·u dt (every stage's power f·u ≤ 0 and the weights are positive: the work is never positive)."""
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    for c in range(C.P.shape[0]):
        if mode[c] != SLIP or math.isfinite(C.KT[c]):
            continue
        uh = u[c, 1] if C.sideways else 0.0
        work[c] += w * (f_t[c, 0] * u[c, 0] + f_t[c, 1] * uh)
        slide[c, 0] += w * u[c, 0]
        slide[c, 1] += w * uh


@njit(cache=True, _nrt=False, forceinline=True)
def _return_map(R, x, C, c, kin, cs, fn):
    """End of a compliant contact's sliding step (evaluated at the next step start, the same state):
    project the rubber's trial force onto the friction limit μ(|u|) f_n and move the anchor by the
    slide; the slide [m] and the friction work [J] of the step go into ``cs``. Re-anchors at the
    current contact point (the deflection is kept)."""
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    mu = C.MU[c]
    fv, fh = _shear_trial(C, c, kin)
    cap = stribeck(_speed(u[c, 0], u[c, 1], C.sideways), mu[0], mu[1], mu[2], mu[3], mu[4]) * fn
    mag = math.sqrt(fv * fv + fh * fh)
    e0, e1 = e[c, 0], e[c, 1]
    if mag > cap and mag > 0.0:
        gv, gh = fv * cap / mag, fh * cap / mag                  # the friction force, on the limit
        uh = u[c, 1] if C.sideways else 0.0
        n0 = -(gv + C.CT[c] * u[c, 0]) / C.KT[c]
        n1 = -(gh + C.CT[c] * uh) / C.KT[c] if C.sideways else 0.0
        s0, s1 = e0 - n0, (e1 - n1) if C.sideways else 0.0      # = −(|f_tr| − cap) f̂_tr / k_t
        slide[c, 0] += s0
        slide[c, 1] += s1
        work[c] += gv * s0 + gh * s1                              # = −cap (|f_tr| − cap) / k_t ≤ 0
        e0, e1 = n0, n1
    _anchor_here(R, x, c, kin, cs, e0, e1 if C.sideways else 0.0)


@njit(cache=True, _nrt=False, forceinline=True)
def decide_modes(dt, C, cs, R, x, Mt_inv, kin, solve, F_try, F, acc, f_t, f_n, needed, available, v_tol):
    """Stick or slip for each contact at the start of a step (see the module docstring).

    ``kin`` holds the kinematics at the step start (:func:`contact_states`), ``R`` and ``x`` that
    state, and ``F`` the other forces there (it is not modified; ``F_try`` is scratch). Closes the
    previous step of each contact first (anchoring a contact that has just stuck or landed, the return
    map of a compliant contact that slid), then sets ``mode`` and the slip directions in ``cs``;
    ``needed`` and ``available`` receive the force that would hold each contact stuck (the rubber's
    trial force, or the rigid stick force) and the friction available, μ_s f_n or μ(|u|) f_n. ``acc``,
    ``f_t`` and ``f_n`` receive the last trial solve (as :func:`contact_forces`).

    Returns
    -------
    final : bool
        True when that last solve used the decided modes, i.e. ``acc``, ``f_t``, ``f_n`` are
        :func:`contact_forces` at the step start and need not be solved again.
    """
    r, nrm, th, u, cen, dd, tpos, e, cp, off = kin
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    nc = C.P.shape[0]
    sideways = C.sideways
    any_rigid = False
    for c in range(nc):
        fn = _normal_force(C, c, kin)
        was = mode[c]
        needed[c] = 0.0
        available[c] = 0.0
        mu = C.MU[c]
        if off[c] or fn <= 0.0:
            mode[c] = OFF if off[c] else OPEN
            anchored[c] = False
            continue
        landed[c] = True
        compliant = math.isfinite(C.KT[c])
        if compliant:
            if was == SLIP and anchored[c]:
                _return_map(R, x, C, c, kin, cs, fn)
            elif not anchored[c] or was == OPEN or was == OFF:
                _anchor_here(R, x, c, kin, cs, 0.0, 0.0)    # landing: the rubber unstrained
            fv, fh = _shear_trial(C, c, kin)
            mag = math.sqrt(fv * fv + fh * fh)
            needed[c] = mag
            static = mu[0] * fn
            loading = fv * u[c, 0] + fh * (u[c, 1] if sideways else 0.0) < -v_tol * mag
            if mag > static or (was == SLIP and loading):
                mode[c] = SLIP
                available[c] = stribeck(_speed(u[c, 0], u[c, 1], sideways), mu[0], mu[1], mu[2], mu[3], mu[4]) * fn
            else:
                if was == SLIP:                          # sticks again where the anchor is
                    _anchor_here(R, x, c, kin, cs, e[c, 0], e[c, 1])
                mode[c] = STICK
                available[c] = static
            continue
        any_rigid = True
        if was == STICK and not anchored[c]:
            _anchor_here(R, x, c, kin, cs, 0.0, 0.0)        # it came to rest during the last step
        elif was != STICK:
            anchored[c] = False
            e[c, 0] = 0.0
            e[c, 1] = 0.0
        mode[c] = STICK  # try to stick every rigid contact in touch
        available[c] = stribeck(_speed(u[c, 0], u[c, 1], sideways), mu[0], mu[1], mu[2], mu[3], mu[4]) * fn
    if not any_rigid:
        return False
    for _ in range(nc):
        for d in range(6):
            F_try[d] = F[d]
        contact_forces(dt, C, cs, R, Mt_inv, kin, solve, F_try, acc, f_t, f_n, v_tol)
        worst, excess, scale = -1, 0.0, 0.0
        for c in range(nc):
            if mode[c] != STICK or math.isfinite(C.KT[c]):
                continue
            mag = np.sqrt(f_t[c, 0] ** 2 + f_t[c, 1] ** 2)
            needed[c] = mag
            scale = max(scale, mag)
            if mag - available[c] > excess:
                worst, excess = c, mag - available[c]
        if worst < 0:
            return True
        # release the contact that exceeds most — and any that exceed as much (symmetric contacts must
        # not be split by their order in the list)
        tie = 1e-9 * scale
        for c in range(nc):
            if mode[c] != STICK or math.isfinite(C.KT[c]):
                continue
            mag = np.sqrt(f_t[c, 0] ** 2 + f_t[c, 1] ** 2)
            if mag - available[c] < excess - tie:
                continue
            mode[c] = SLIP
            anchored[c] = False
            fdir[c, 0], fdir[c, 1] = f_t[c, 0] / mag, f_t[c, 1] / mag
    return False
