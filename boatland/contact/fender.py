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

Per RK4 stage the kinematics of every contact are computed once (:func:`contact_states`) into buffers
of :func:`contact_workspace`, allocated once per run. The kernels here only index caller-owned arrays
and are compiled without numba's reference counting and inlined into the integrator (``_nrt=False,
forceinline=True``; see :mod:`boatland.integrate.cummins`).
"""

from __future__ import annotations

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.core.extending import intrinsic

from boatland.rigid import add_point_force, rotation_matrix

__all__ = ["stribeck", "contact_kinematics", "tangential_position", "contact_workspace", "contact_states",
           "contact_forces", "decide_modes", "OPEN", "STICK", "SLIP"]

OPEN, STICK, SLIP = 0, 1, 2


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
    """μ(v) = μ_k + (μ_s − μ_k) exp(−(|v|/v_ref)^δ) + k_v |v|  (seed 001 eq. 2.78); μ(0) = μ_s."""
    s = abs(v)
    return mu_k + (mu_s - mu_k) * np.exp(-((s / v_ref) ** delta)) + k_v * s


@njit(cache=True, _nrt=False, forceinline=True)
def point_kinematics(R, x, v, p, s, n, th, out_r, out_u, out_cen):
    """Kinematics of one contact with the body rotation ``R`` = R(x₄, x₅, x₆) (3, 3) given; returns (δ, δ̇).
    Fills lever r = R p (3), tangential velocity (u_v, u_h) and tangential centripetal acceleration (2)."""
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
def contact_kinematics(x, v, p, s, n, th, out_r, out_u, out_cen):
    """Kinematics of one contact; returns (δ, δ̇). Fills lever r = R p (3), tangential velocity
    (u_v, u_h) and tangential centripetal acceleration (2)."""
    return point_kinematics(rotation_matrix(x[3], x[4], x[5]), x, v, p, s, n, th, out_r, out_u, out_cen)


@njit(cache=True, _nrt=False, forceinline=True)
def point_tangential_position(R, x, p, th):
    """(vertical, horizontal-along-plane) coordinates of the fender point P = x + R p, R given."""
    Px = x[0] + R[0, 0] * p[0] + R[0, 1] * p[1] + R[0, 2] * p[2]
    Py = x[1] + R[1, 0] * p[0] + R[1, 1] * p[1] + R[1, 2] * p[2]
    Pz = x[2] + R[2, 0] * p[0] + R[2, 1] * p[1] + R[2, 2] * p[2]
    return Pz, Px * th[0] + Py * th[1] + Pz * th[2]


@njit(cache=True)
def tangential_position(x, p, th):
    """(vertical, horizontal-along-plane) coordinates of the fender point P = x + R p."""
    return point_tangential_position(rotation_matrix(x[3], x[4], x[5]), x, p, th)


@njit(cache=True)
def contact_workspace(nc, sideways):
    """Buffers of :func:`contact_states`, :func:`contact_forces` and :func:`decide_modes` for ``nc``
    contacts, allocated once per run (the hot loop allocates nothing).

    Returns
    -------
    kin : tuple
        Kinematics of every contact at one state: lever r (Nc, 3), tangential velocity u (Nc, 2),
        tangential centripetal acceleration (Nc, 2), (δ, δ̇) (Nc, 2), tangential position (Nc, 2).
    solve : tuple
        The augmented solve for up to m = Nc·(2 if sideways else 1) stick constraints: G (6, m), target
        (m,), first column of each contact (Nc,) int, (M + A∞)⁻¹G (6, m), W (m, m), right-hand side and
        solution (m,), eigenvectors of W (m, m).
    F_try : (6,)
        Scratch copy of the other forces for each trial solve of :func:`decide_modes`.
    """
    m = nc * (2 if sideways else 1)
    kin = (np.zeros((nc, 3)), np.zeros((nc, 2)), np.zeros((nc, 2)), np.zeros((nc, 2)), np.zeros((nc, 2)))
    solve = (np.zeros((6, m)), np.zeros(m), np.zeros(nc, dtype=np.int64), np.zeros((6, m)), np.zeros((m, m)),
             np.zeros(m), np.zeros(m), np.zeros((m, m)))
    return kin, solve, np.zeros(6)


@njit(cache=True, _nrt=False, forceinline=True)
def contact_states(R, x, v, P, S, N, TH, kin):
    """Kinematics of every contact at the state (x, v) with rotation ``R`` = R(x₄, x₅, x₆), into ``kin``
    (see :func:`contact_workspace`): computed once per RK4 stage, shared by the stick–slip decision
    and the contact forces."""
    r, u, cen, dd, tpos = kin
    for c in range(P.shape[0]):
        dd[c, 0], dd[c, 1] = point_kinematics(R, x, v, P[c], S[c], N[c], TH[c], r[c], u[c], cen[c])
        tpos[c, 0], tpos[c, 1] = point_tangential_position(R, x, P[c], TH[c])


#: Damping ρ of the stick solve's least squares, relative to the largest diagonal entry of W (see
#: :func:`_damped_solve`): directions the stuck contacts restrain only through a lever shorter than
#: about √ρ ≈ 3 % of the vessel's radius of gyration are left to the fender's compliance.
STICK_DAMPING = 1e-3


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
    single columns and Gᵀacc (the order of the OpenBLAS x86-64 kernels used before) — so results do
    not depend on the BLAS build.
    """
    for k in range(m):
        for d in range(6):
            MG[d, k] = _dot_pairs(Mt_inv[d], G[:, k]) if m == 1 else _dot_fma(Mt_inv[d], G[:, k])
    for a in range(m):
        for b in range(m):
            W[a, b] = _dot_fma(G[:, a], MG[:, b])
        rhs[a] = target[a] - _dot_pairs(G[:, a], acc)


@njit(cache=True, _nrt=False, forceinline=True)
def contact_forces(dt, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored, Mt_inv, kin, solve,
                   F, acc, f_t, f_n):
    r"""Add the contact forces to ``F`` and solve the accelerations ``acc`` at one RK4 stage.

    Parameters
    ----------
    dt : float
        Time step [s] (the stick condition drives the tangential velocity to zero within it).
    N, TH : (Nc, 3)
        Plane normals and horizontal tangents (local frame).
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
    kin, solve : tuple
        Kinematics of the stage state from :func:`contact_states`; solve buffers (see
        :func:`contact_workspace`).
    F : (6,)
        All other forces; contact forces are added in place.
    acc : (6,)
        Output accelerations.
    f_t : (Nc, 2)
        Output tangential friction (or stick) force per contact.
    f_n : (Nc,)
        Output normal force.
    """
    r, u, cen, dd, tpos = kin
    G, target, idx, MG, W, rhs, f, V = solve
    nc = CF.shape[0]
    m_per = 2 if sideways else 1
    m = 0
    for c in range(nc):
        f_t[c, 0] = 0.0
        f_t[c, 1] = 0.0
        delta, ddelta = dd[c, 0], dd[c, 1]
        rx, ry, rz = r[c, 0], r[c, 1], r[c, 2]
        fn = 0.0
        if delta > 0.0:
            fn = CF[c] * delta + DF[c] * ddelta
            if fn < 0.0:
                fn = 0.0
        f_n[c] = fn
        if fn > 0.0:
            add_point_force(rx, ry, rz, N[c, 0], N[c, 1], N[c, 2], fn, F)
        if fn <= 0.0 or mode[c] == OPEN:
            continue
        if mode[c] == SLIP:
            mu = stribeck(np.sqrt(u[c, 0] * u[c, 0] + u[c, 1] * u[c, 1]),
                          MU[c, 0], MU[c, 1], MU[c, 2], MU[c, 3], MU[c, 4])
            fv, fh = mu * fn * fdir[c, 0], mu * fn * fdir[c, 1]
            f_t[c, 0], f_t[c, 1] = fv, fh
            add_point_force(rx, ry, rz, 0.0, 0.0, 1.0, fv, F)
            if sideways:
                add_point_force(rx, ry, rz, TH[c, 0], TH[c, 1], TH[c, 2], fh, F)
            continue
        # stuck: one or two constraint columns
        idx[c] = m
        for k in range(m_per):
            if k == 0:
                t0, t1, t2 = 0.0, 0.0, 1.0
            else:
                t0, t1, t2 = TH[c, 0], TH[c, 1], TH[c, 2]
            G[0, m], G[1, m], G[2, m] = t0, t1, t2
            G[3, m] = ry * t2 - rz * t1
            G[4, m] = rz * t0 - rx * t2
            G[5, m] = rx * t1 - ry * t0
            e = 0.0
            if anchored[c]:
                e = tpos[c, k] - anchor[c, k]
            target[m] = -u[c, k] / dt - e / (dt * dt) - cen[c, k]
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
    # agree (anchors set at different steps, centripetal terms): the solve enforces their mean, where
    # a regularised (W + εI) solve turned their disagreement into opposing forces of order
    # disagreement / ε (model2_j04: 1e10 N needed against 80 N of normal force).
    _damped_solve(W, rhs, m, V, f, STICK_DAMPING)
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


@njit(cache=True, _nrt=False, forceinline=True)
def decide_modes(dt, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored, Mt_inv, kin, solve, F_try,
                 F, acc, f_t, f_n, needed, available, v_tol):
    """Stick or slip for each contact at the start of a step (see the module docstring).

    ``kin`` holds the kinematics at the step start (:func:`contact_states`) and ``F`` the other forces
    there (it is not modified; ``F_try`` is scratch). Sets ``mode`` and ``fdir``; ``needed`` and
    ``available`` receive the stick force that would hold each contact and μ(|u|) f_n. ``acc``, ``f_t``
    and ``f_n`` receive the last trial solve (as :func:`contact_forces`).

    Returns
    -------
    final : bool
        True when that last solve used the decided modes, i.e. ``acc``, ``f_t``, ``f_n`` are
        :func:`contact_forces` at the step start and need not be solved again.
    """
    r, u, cen, dd, tpos = kin
    nc = CF.shape[0]
    for c in range(nc):
        delta, ddelta = dd[c, 0], dd[c, 1]
        fn = CF[c] * delta + DF[c] * ddelta if delta > 0.0 else 0.0
        needed[c] = 0.0
        available[c] = 0.0
        if fn <= 0.0:
            mode[c] = OPEN
            anchored[c] = False
        else:
            if mode[c] == OPEN:
                anchored[c] = False
            mode[c] = STICK  # try to stick every contact in touch
            speed = np.sqrt(u[c, 0] * u[c, 0] + (u[c, 1] * u[c, 1] if sideways else 0.0))
            available[c] = stribeck(speed, MU[c, 0], MU[c, 1], MU[c, 2], MU[c, 3], MU[c, 4]) * fn
    for _ in range(nc):
        for d in range(6):
            F_try[d] = F[d]
        contact_forces(dt, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored, Mt_inv, kin, solve,
                       F_try, acc, f_t, f_n)
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
            return True
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
            uh = u[c, 1] if sideways else 0.0
            speed = np.sqrt(u[c, 0] * u[c, 0] + uh * uh)
            if speed > v_tol and dv * u[c, 0] + dh * uh > 0.0:
                dv, dh = -u[c, 0] / speed, -uh / speed
            mode[c] = SLIP
            anchored[c] = False
            fdir[c, 0], fdir[c, 1] = dv, dh
    return False
