r"""Bow fender against vertical boat-landing struts: spring–damper normal force, Stribeck friction,
stick–slip as an augmented linear system (seed 001 §2.5 and §3.4).

Geometry (all in the *local frame*: origin at the vessel reference point's mean position, axes along
the vessel's axes at rest; the caller converts the global strut positions). Contact c has a fender
point :math:`p_c` (body frame), a contact plane through :math:`s_c` (strut surface) with horizontal
unit normal :math:`n_c` pointing from the landing towards the vessel, and tangential directions
:math:`t_v = e_z` (vertical) and :math:`t_h = e_z \times n_c` (horizontal along the plane). With the
rigid-body position :math:`P_c = x_{1:3} + R(x_{4:6})\,p_c` (exact rotation; small-angle DOFs for the
angular velocity :math:`\omega \approx \dot x_{4:6}`, as in linear seakeeping):

- penetration :math:`\delta = (s_c - P_c)\cdot n_c`, its rate :math:`\dot\delta = -\dot P_c\cdot n_c`;
- normal force (seed 001 eq. 3.21, never pulling): :math:`f_n = \max(0,\, c_f\delta + d_f\dot\delta)` for
  :math:`\delta > 0`, else 0, acting along :math:`n_c` at :math:`P_c`;
- Stribeck coefficient (eq. 2.78): :math:`\mu(v) = \mu_k + (\mu_s-\mu_k)e^{-(v/v_{ref})^\delta} + k_v v`.

Stick–slip (eq. 2.83–2.86, 3.22–3.24), generalised to N contacts and, optionally, both tangential
directions. With :math:`G_c = [t;\ r_c\times t]` (6 × m_c, one column per tangential direction),
the accelerations and the stick forces :math:`f_c` solve

.. math::
    (M + A_\infty)\,a - \sum_{c\in S} G_c f_c = F, \qquad G_c^\top a = \dot u'_c \quad (c \in S),

:math:`\dot u'_c = -u_c/\Delta t - e_c/\Delta t^2 - (\omega\times(\omega\times r_c))_t`: the tangential
velocity :math:`u_c` is driven to zero within the step (eq. 3.23) and a contact already stuck is
pulled back to its anchor (:math:`e_c`, tangential offset from where it stuck) so that it cannot drift.
It is solved by the Schur complement on :math:`(M+A_\infty)^{-1}`, in the least-squares
minimum-norm sense: redundant constraints (two struts sharing a plane constrain the same sideways
motion) make the split of that force statically indeterminate, and it is shared equally.

The mode of each contact is decided once per step, at its start, and kept for the four RK4 stages:
all contacts in touch are first assumed stuck; the contact whose needed force exceeds the available
:math:`\mu(|u_c|) f_n` by most is released to slip and the rest solved again, until every stuck
contact holds (for two contacts this is the three-case logic of seed 001 §3.4). A slipping contact
carries the available force :math:`\mu(|u_c|) f_n` in the direction of the force that would have stopped
it — never more than that force (eq. 2.83), so friction cannot reverse the sliding within a step
and never adds energy. A slipping contact whose needed force falls back within the available one
sticks again (velocity reversed or vanished).

Mode codes: 0 open, 1 stick, 2 slip.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from boatland.rigid import rotation_matrix

__all__ = ["stribeck", "contact_kinematics", "OPEN", "STICK", "SLIP"]

OPEN, STICK, SLIP = 0, 1, 2


@njit(cache=True)
def stribeck(v, mu_s, mu_k, k_v, v_ref, delta):
    """μ(v) = μ_k + (μ_s − μ_k) exp(−(|v|/v_ref)^δ) + k_v |v|  (seed 001 eq. 2.78); μ(0) = μ_s."""
    s = abs(v)
    return mu_k + (mu_s - mu_k) * np.exp(-((s / v_ref) ** delta)) + k_v * s


@njit(cache=True)
def contact_kinematics(x, v, p, s, n, th, out_r, out_u, out_cen):
    """Kinematics of one contact; returns (δ, δ̇). Fills lever r = R p (3), tangential velocity
    (u_v, u_h) and tangential centripetal acceleration (2)."""
    R = rotation_matrix(x[3], x[4], x[5])
    for k in range(3):
        out_r[k] = R[k, 0] * p[0] + R[k, 1] * p[1] + R[k, 2] * p[2]
    wx, wy, wz = v[3], v[4], v[5]
    rx, ry, rz = out_r[0], out_r[1], out_r[2]
    # velocity and centripetal acceleration of the point
    Vx = v[0] + wy * rz - wz * ry
    Vy = v[1] + wz * rx - wx * rz
    Vz = v[2] + wx * ry - wy * rx
    cx, cy, cz = wy * rz - wz * ry, wz * rx - wx * rz, wx * ry - wy * rx
    ax = wy * cz - wz * cy
    ay = wz * cx - wx * cz
    az = wx * cy - wy * cx
    Px, Py, Pz = x[0] + rx, x[1] + ry, x[2] + rz
    delta = (s[0] - Px) * n[0] + (s[1] - Py) * n[1] + (s[2] - Pz) * n[2]
    ddelta = -(Vx * n[0] + Vy * n[1] + Vz * n[2])
    out_u[0] = Vz
    out_u[1] = Vx * th[0] + Vy * th[1] + Vz * th[2]
    out_cen[0] = az
    out_cen[1] = ax * th[0] + ay * th[1] + az * th[2]
    return delta, ddelta


@njit(cache=True)
def tangential_position(x, p, th):
    """(vertical, horizontal-along-plane) coordinates of the fender point P = x + R p."""
    R = rotation_matrix(x[3], x[4], x[5])
    Px = x[0] + R[0, 0] * p[0] + R[0, 1] * p[1] + R[0, 2] * p[2]
    Py = x[1] + R[1, 0] * p[0] + R[1, 1] * p[1] + R[1, 2] * p[2]
    Pz = x[2] + R[2, 0] * p[0] + R[2, 1] * p[1] + R[2, 2] * p[2]
    return Pz, Px * th[0] + Py * th[1] + Pz * th[2]


@njit(cache=True)
def _cholesky_solve(W, b, m):
    """Solve W f = b for a small symmetric positive-definite W (m × m) in place (no LAPACK call:
    the per-stage contact systems are 1–4 unknowns, where the call overhead dominates)."""
    L = W
    for j in range(m):
        d = L[j, j]
        for k in range(j):
            d -= L[j, k] * L[j, k]
        d = np.sqrt(d)
        L[j, j] = d
        for i in range(j + 1, m):
            s = L[i, j]
            for k in range(j):
                s -= L[i, k] * L[j, k]
            L[i, j] = s / d
    y = np.empty(m)
    for i in range(m):
        s = b[i]
        for k in range(i):
            s -= L[i, k] * y[k]
        y[i] = s / L[i, i]
    for i in range(m - 1, -1, -1):
        s = y[i]
        for k in range(i + 1, m):
            s -= L[k, i] * y[k]
        y[i] = s / L[i, i]
    return y


@njit(cache=True)
def _gen_force(r, d0, d1, d2, f, out):
    """Add the generalised force of a force f·d at lever r to out (6)."""
    fx, fy, fz = f * d0, f * d1, f * d2
    out[0] += fx
    out[1] += fy
    out[2] += fz
    out[3] += r[1] * fz - r[2] * fy
    out[4] += r[2] * fx - r[0] * fz
    out[5] += r[0] * fy - r[1] * fx


@njit(cache=True)
def contact_forces(x, v, dt, P, S, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored,
                   Mt_inv, F, acc, f_t, f_n):
    r"""Add the contact forces to ``F`` and solve the accelerations ``acc`` at one RK4 stage.

    Parameters
    ----------
    P, S, N, TH : (Nc, 3)
        Fender points (body), plane points, plane normals, horizontal tangents (local frame).
    CF, DF : (Nc,)
        Fender stiffness c_f [N/m] and damping d_f [N s/m].
    MU : (Nc, 5)
        μ_s, μ_k, k_v, v_ref, δ per contact.
    sideways : bool
        Friction also horizontally along the plane.
    mode : (Nc,) int
        OPEN / STICK / SLIP for this step; ``fdir`` (Nc, 2) the unit slip-force direction in
        (vertical, horizontal) for slipping contacts; ``anchor`` (Nc, 2) and ``anchored`` (Nc,) for
        stuck ones.
    Mt_inv : (6, 6)
        (M + A∞)⁻¹.
    F : (6,)
        All other forces; contact forces are added in place.
    acc : (6,)
        Output accelerations.
    f_t : (Nc, 2)
        Output tangential friction (or stick) force per contact.
    f_n : (Nc,)
        Output normal force.
    """
    nc = P.shape[0]
    m_per = 2 if sideways else 1
    G = np.zeros((6, nc * m_per))
    target = np.zeros(nc * m_per)
    idx = np.zeros(nc, dtype=np.int64)
    r = np.empty(3)
    u = np.empty(2)
    cen = np.empty(2)
    m = 0
    for c in range(nc):
        f_t[c, 0] = 0.0
        f_t[c, 1] = 0.0
        delta, ddelta = contact_kinematics(x, v, P[c], S[c], N[c], TH[c], r, u, cen)
        fn = 0.0
        if delta > 0.0:
            fn = CF[c] * delta + DF[c] * ddelta
            if fn < 0.0:
                fn = 0.0
        f_n[c] = fn
        if fn > 0.0:
            _gen_force(r, N[c, 0], N[c, 1], N[c, 2], fn, F)
        if fn <= 0.0 or mode[c] == OPEN:
            continue
        if mode[c] == SLIP:
            mu = stribeck(np.sqrt(u[0] * u[0] + u[1] * u[1]), MU[c, 0], MU[c, 1], MU[c, 2], MU[c, 3], MU[c, 4])
            fv, fh = mu * fn * fdir[c, 0], mu * fn * fdir[c, 1]
            f_t[c, 0], f_t[c, 1] = fv, fh
            _gen_force(r, 0.0, 0.0, 1.0, fv, F)
            if sideways:
                _gen_force(r, TH[c, 0], TH[c, 1], TH[c, 2], fh, F)
            continue
        # stuck: one or two constraint columns
        idx[c] = m
        for k in range(m_per):
            if k == 0:
                t0, t1, t2 = 0.0, 0.0, 1.0
            else:
                t0, t1, t2 = TH[c, 0], TH[c, 1], TH[c, 2]
            G[0, m], G[1, m], G[2, m] = t0, t1, t2
            G[3, m] = r[1] * t2 - r[2] * t1
            G[4, m] = r[2] * t0 - r[0] * t2
            G[5, m] = r[0] * t1 - r[1] * t0
            e = 0.0
            if anchored[c]:
                pv, ph = tangential_position(x, P[c], TH[c])
                e = (pv - anchor[c, 0]) if k == 0 else (ph - anchor[c, 1])
            target[m] = -u[k] / dt - e / (dt * dt) - cen[k]
            m += 1
    for d in range(6):
        a = 0.0
        for e_ in range(6):
            a += Mt_inv[d, e_] * F[e_]
        acc[d] = a
    if m == 0:
        return
    Gm = np.ascontiguousarray(G[:, :m])
    MG = Mt_inv @ Gm
    W = np.ascontiguousarray(Gm.T) @ MG
    rhs = target[:m] - np.ascontiguousarray(Gm.T) @ acc
    # Minimum-norm solution: two contacts on parallel struts give the same horizontal constraint
    # twice (a rigid fender cannot slide sideways at one tube only), so W is singular and the split of
    # that force between the tubes is statically indeterminate — shared equally. The constraints are
    # consistent, so the Tikhonov solve (W + εI) f = rhs with ε = 1e-10 max W_kk gives the
    # pseudo-inverse solution to ~1e-6 relative in the redundant direction (and is 20× cheaper than
    # an SVD least-squares solve per stage).
    eps = 0.0
    for k in range(m):
        eps = max(eps, W[k, k])
        for q in range(k):  # symmetric by construction; average out round-off before Cholesky
            w = 0.5 * (W[k, q] + W[q, k])
            W[k, q] = w
            W[q, k] = w
    for k in range(m):
        W[k, k] += 1e-10 * eps
    f = _cholesky_solve(W, rhs, m)
    for d in range(6):
        s = 0.0
        for k in range(m):
            s += MG[d, k] * f[k]
        acc[d] += s
    for c in range(nc):
        if mode[c] == STICK and f_n[c] > 0.0:
            f_t[c, 0] = f[idx[c]]
            if sideways:
                f_t[c, 1] = f[idx[c] + 1]


@njit(cache=True)
def decide_modes(x, v, dt, P, S, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored,
                 Mt_inv, F, needed, available, v_tol):
    """Stick or slip for each contact at the start of a step (see the module docstring).

    ``F`` holds the other forces at the step start (it is not modified). Sets ``mode`` and ``fdir``;
    ``needed`` and ``available`` receive the stick force that would hold each contact and μ(|u|) f_n.
    """
    nc = P.shape[0]
    r = np.empty(3)
    u = np.empty(2)
    cen = np.empty(2)
    Fc = np.empty(6)
    acc = np.empty(6)
    f_t = np.zeros((nc, 2))
    f_n = np.zeros(nc)
    speed = np.zeros(nc)
    for c in range(nc):
        delta, ddelta = contact_kinematics(x, v, P[c], S[c], N[c], TH[c], r, u, cen)
        fn = CF[c] * delta + DF[c] * ddelta if delta > 0.0 else 0.0
        speed[c] = np.sqrt(u[0] * u[0] + (u[1] * u[1] if sideways else 0.0))
        needed[c] = 0.0
        available[c] = 0.0
        if fn <= 0.0:
            mode[c] = OPEN
            anchored[c] = False
        else:
            if mode[c] == OPEN:
                anchored[c] = False
            mode[c] = STICK  # try to stick every contact in touch
            available[c] = stribeck(speed[c], MU[c, 0], MU[c, 1], MU[c, 2], MU[c, 3], MU[c, 4]) * fn
    for _ in range(nc):
        for d in range(6):
            Fc[d] = F[d]
        contact_forces(x, v, dt, P, S, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored,
                       Mt_inv, Fc, acc, f_t, f_n)
        worst, excess, scale = -1, 0.0, 0.0
        for c in range(nc):
            if mode[c] != STICK:
                continue
            mag = np.sqrt(f_t[c, 0] ** 2 + f_t[c, 1] ** 2)
            needed[c] = mag
            scale = max(scale, mag)
            if mag - available[c] > excess:
                worst, excess = c, mag - available[c]
        if worst < 0:
            break
        # release the contact that exceeds most — and any that exceed as much (symmetric contacts must
        # not be split by their order in the list)
        tie = 1e-9 * scale
        for c in range(nc):
            if mode[c] != STICK:
                continue
            mag = np.sqrt(f_t[c, 0] ** 2 + f_t[c, 1] ** 2)
            if mag - available[c] < excess - tie:
                continue
            dv, dh = f_t[c, 0] / mag, f_t[c, 1] / mag
            # friction opposes the sliding: never a component along the velocity
            contact_kinematics(x, v, P[c], S[c], N[c], TH[c], r, u, cen)
            uh = u[1] if sideways else 0.0
            if speed[c] > v_tol and dv * u[0] + dh * uh > 0.0:
                dv, dh = -u[0] / speed[c], -uh / speed[c]
            mode[c] = SLIP
            anchored[c] = False
            fdir[c, 0], fdir[c, 1] = dv, dh
