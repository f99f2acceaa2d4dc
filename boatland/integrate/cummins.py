r"""Fixed-step RK4 of the Cummins equation with radiation memory by convolution or state space.

.. math::
    (M + A_\infty)\ddot x + \mu(t) + B_v \dot x + B_q |\dot x|\dot x + C x
        = F_{exc}(t) + F_T(t, x) + F_c(t, x, \dot x), \qquad
    \mu(t) = \int_0^t K(t-\tau)\,\dot x(\tau)\,d\tau

(Cummins 1962; seed 000 eq. 3.40 and §4.2 for RK4 with the trapezoid convolution).

Stage consistency of the memory (seed 000 §4.2; DESIGN.md §1): at the RK4 stage time
:math:`t_n + c\,\Delta t` (c = 0, ½, 1) the integral is split into a history part over
:math:`[0, t_n]` — trapezoid over the stored step velocities, fixed during the step — and the current
interval :math:`[t_n, t_n + c\Delta t]`, trapezoid with the stage velocity:

.. math::
    \mu_c = \underbrace{\sum_{m=0}^{n} w_m \Delta t\, K((n-m+c)\Delta t)\,\dot x_m}_{H_c\ \text{(fixed in the step)}}
          + \frac{c\Delta t}{2}\left[K(c\Delta t)\dot x_n + K(0)\,\dot x_{stage}\right]

with :math:`w_0 = w_n = ½`. K is therefore sampled every Δt/2. The history at c = 0 of step n+1 is
the c = 1 history of step n plus the last interval with the accepted velocity, so two history sums
are computed per step, over the significant DOF pairs only.

State space: the fitted systems :math:`\dot z = A_r z + B_r \dot x_j`, :math:`\mu_{ij} = C_r z` are
appended to the RK4 state, so they are consistent at every stage by construction.

All arrays are SI, DOF order surge..yaw, body motions small (linear hydrodynamics) while positions
of force points follow the exact rotation :math:`R(\phi,\theta,\psi)` (z-y-x Euler angles).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from boatland.contact.fender import STICK, contact_forces, decide_modes, tangential_position
from boatland.rigid import rotation_matrix

__all__ = ["run_cummins", "STATUS_OK", "STATUS_NAN", "STATUS_RUNAWAY", "STATUS_MESSAGES"]

STATUS_OK = 0
STATUS_NAN = 1
STATUS_RUNAWAY = 2
STATUS_MESSAGES = {
    STATUS_OK: "completed",
    STATUS_NAN: "the state became NaN or infinite",
    STATUS_RUNAWAY: "runaway motion (a displacement or rotation beyond the limit)",
}


@njit(cache=True)
def _thrust(x, T, r_p, out):
    """Generalised force of a push T along the body x axis applied at body point r_p (exact rotation)."""
    R = rotation_matrix(x[3], x[4], x[5])
    f0, f1, f2 = T * R[0, 0], T * R[1, 0], T * R[2, 0]
    rx = R[0, 0] * r_p[0] + R[0, 1] * r_p[1] + R[0, 2] * r_p[2]
    ry = R[1, 0] * r_p[0] + R[1, 1] * r_p[1] + R[1, 2] * r_p[2]
    rz = R[2, 0] * r_p[0] + R[2, 1] * r_p[1] + R[2, 2] * r_p[2]
    out[0] += f0
    out[1] += f1
    out[2] += f2
    out[3] += ry * f2 - rz * f1
    out[4] += rz * f0 - rx * f2
    out[5] += rx * f1 - ry * f0


@njit(cache=True)
def _history(vbuf, head, count, Kh, pairs_i, pairs_j, dt, H0, Hh, H1):
    """H_c = Σ_m w_m Δt K((n−m+c)Δt) v_m for c = 0, ½, 1 in one pass over the stored velocities.

    ``vbuf`` (2 nb, 6) is a mirrored ring buffer (each velocity stored at ``head`` and ``head + nb``),
    so the last ``count`` velocities are contiguous: lag ℓ sits at ``head + nb − ℓ``. ``Kh`` (npairs,
    nK2) holds K at the half steps k Δt / 2.
    """
    for d in range(6):
        H0[d] = 0.0
        Hh[d] = 0.0
        H1[d] = 0.0
    if count < 2:  # [0, t_n] is empty at the first step
        return
    nb = vbuf.shape[0] // 2
    nK2 = Kh.shape[1]
    top = head + nb
    for p in range(pairs_i.shape[0]):
        i, j = pairs_i[p], pairs_j[p]
        n_lag = min(count, (nK2 - 1) // 2)  # lags whose K(lag + 1) sample exists
        s0 = 0.0
        sh = 0.0
        s1 = 0.0
        for lag in range(n_lag):
            vv = vbuf[top - lag, j]
            k = 2 * lag
            s0 += Kh[p, k] * vv
            sh += Kh[p, k + 1] * vv
            s1 += Kh[p, k + 2] * vv
        # trapezoid: half weight at both ends of [0, t_n]
        v_new = vbuf[top, j]
        s0 -= 0.5 * Kh[p, 0] * v_new
        sh -= 0.5 * Kh[p, 1] * v_new
        s1 -= 0.5 * Kh[p, 2] * v_new
        if n_lag == count:
            v_old = vbuf[top - count + 1, j]
            k = 2 * (count - 1)
            s0 -= 0.5 * Kh[p, k] * v_old
            sh -= 0.5 * Kh[p, k + 1] * v_old
            s1 -= 0.5 * Kh[p, k + 2] * v_old
        H0[i] += s0 * dt
        Hh[i] += sh * dt
        H1[i] += s1 * dt


@njit(cache=True)
def _forces(t_idx, x, v, z, mu_hist, c2, v_n, dt, C, Bv, Bq, F_ext, thrust, r_p,
            Kh, pairs_i, pairs_j, conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, dz, F):
    """All forces but the contacts, into ``F``; the state-space derivative into ``dz``."""
    for d in range(6):
        F[d] = F_ext[t_idx, d] - Bv[d] * v[d] - Bq[d] * abs(v[d]) * v[d]
        for e in range(6):
            F[d] -= C[d, e] * x[e]
    if thrust[t_idx] != 0.0:
        _thrust(x, thrust[t_idx], r_p, F)
    if conv:
        cdt = 0.5 * c2 * dt
        for p in range(pairs_i.shape[0]):
            i, j = pairs_i[p], pairs_j[p]
            cur = 0.5 * cdt * (Kh[p, c2] * v_n[j] + Kh[p, 0] * v[j]) if c2 > 0 else 0.0
            F[i] -= cur
        for d in range(6):
            F[d] -= mu_hist[d]
    else:
        # block-diagonal modal realisation: each state couples to itself and at most one partner
        n_s = z.shape[0]
        for s in range(n_s):
            acc_z = ss_A[s, 0] * z[s] + ss_B[s] * v[ss_in[s]]
            q = ss_pair[s]
            if q >= 0:
                acc_z += ss_A[s, 1] * z[q]
            dz[s] = acc_z
            F[ss_out[s]] -= ss_C[s] * z[s]


@njit(cache=True)
def _stage(t_idx, x, v, z, mu_hist, c2, v_n, dt, Mt_inv, C, Bv, Bq, F_ext, thrust, r_p,
           Kh, pairs_i, pairs_j, conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, ct, cs, dz, acc, F, f_t, f_n):
    """Accelerations ``acc`` and state-space derivative ``dz`` at one RK4 stage (contacts included)."""
    _forces(t_idx, x, v, z, mu_hist, c2, v_n, dt, C, Bv, Bq, F_ext, thrust, r_p,
            Kh, pairs_i, pairs_j, conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, dz, F)
    P, S, N, TH, CF, DF, MU, sideways = ct
    mode, fdir, anchor, anchored = cs
    if P.shape[0] == 0:
        for d in range(6):
            a = 0.0
            for e in range(6):
                a += Mt_inv[d, e] * F[e]
            acc[d] = a
    else:
        contact_forces(x, v, dt, P, S, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored,
                       Mt_inv, F, acc, f_t, f_n)


@njit(cache=True)
def _trial_state(x, v, z, v_stage, kv, kz, h, kx, xs, vs, zs):
    """RK4 stage update: kx = the stage velocity, then (xs, vs, zs) = (x, v, z) + h (kx, kv, kz).
    ``v_stage`` may be ``vs`` itself (it is read before being overwritten)."""
    for d in range(6):
        kx[d] = v_stage[d]
    for d in range(6):
        xs[d] = x[d] + h * kx[d]
        vs[d] = v[d] + h * kv[d]
    for q in range(z.shape[0]):
        zs[q] = z[q] + h * kz[q]


@njit(cache=True)
def run_cummins(dt, n_steps, Mt_inv, C, Bv, Bq, F_ext, thrust, r_p, x0, v0,
                conv, Kh, pairs_i, pairs_j, n_hist, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair,
                ct, v_tol, limit_trans, limit_rot, out_x, out_v, out_mode, out_fn, out_ft, out_need,
                out_avail, out_tpos):
    """Integrate the Cummins equation with classic RK4; returns ``(status, last_step)``.

    Parameters
    ----------
    dt : float
        Time step [s].
    n_steps : int
        Number of steps; outputs have ``n_steps + 1`` rows.
    Mt_inv : (6, 6)
        (M + A∞)⁻¹.
    C : (6, 6)
        Restoring matrix.
    Bv, Bq : (6,)
        Additional linear and quadratic damping.
    F_ext : (2 n_steps + 1, 6)
        External force without memory (wave excitation), at half steps t = k Δt / 2.
    thrust : (2 n_steps + 1,)
        Push along the body x axis [N] at half steps (ramp included); ``r_p`` (3,) its body point.
    x0, v0 : (6,)
        Initial displacement and velocity.
    conv : bool
        True: convolution memory with ``Kh`` (npairs, nK2) = K(k Δt/2) of the pairs
        (``pairs_i``, ``pairs_j``) over ``n_hist`` past steps. False: state space in modal
        (block-diagonal) form: ``ss_A`` (ns, 2) the diagonal entry and the entry coupling each state
        to its 2×2-block partner ``ss_pair`` (ns,) (−1 for a real pole), ``ss_B`` (ns,), ``ss_C``
        (ns,), input DOF ``ss_in`` (ns,), output DOF ``ss_out`` (ns,).
    ct : tuple
        Contacts ``(P, S, N, TH, CF, DF, MU, sideways)`` as in
        :func:`boatland.contact.fender.contact_forces` (Nc = 0 for none).
    v_tol : float
        Speed below which a contact's sliding direction is not defined [m/s].
    limit_trans, limit_rot : float
        Runaway limits [m], [rad].
    out_x, out_v : (n_steps + 1, 6)
        Trajectory.
    out_mode, out_fn, out_need, out_avail : (n_steps + 1, Nc)
        Per step start: contact mode (0 open, 1 stick, 2 slip), normal force, stick force needed,
        friction available μ(|u|) f_n.
    out_ft, out_tpos : (n_steps + 1, Nc, 2)
        Tangential (vertical, horizontal) friction force and fender-point position.

    Returns
    -------
    status : int
        :data:`STATUS_OK`, :data:`STATUS_NAN` or :data:`STATUS_RUNAWAY` (see :data:`STATUS_MESSAGES`).
    last : int
        Last step written.
    """
    P, S, N, TH, CF, DF, MU, sideways = ct
    nc = P.shape[0]
    mode = np.zeros(nc, dtype=np.int64)
    fdir = np.zeros((nc, 2))
    anchor = np.zeros((nc, 2))
    anchored = np.zeros(nc, dtype=np.bool_)
    cs = (mode, fdir, anchor, anchored)
    f_t = np.zeros((nc, 2))
    f_n = np.zeros(nc)
    need = np.zeros(nc)
    avail = np.zeros(nc)
    n_s = ss_B.shape[0]
    x = x0.copy()
    v = v0.copy()
    z = np.zeros(n_s)
    nb = max(n_hist + 1, 1)
    vbuf = np.zeros((2 * nb, 6))  # mirrored ring buffer (see _history)
    head = 0
    count = 1
    vbuf[0, :] = v
    vbuf[nb, :] = v
    H0 = np.zeros(6)
    Hh = np.zeros(6)
    H1 = np.zeros(6)
    F = np.zeros(6)
    k1x, k2x, k3x, k4x = np.empty(6), np.empty(6), np.empty(6), np.empty(6)
    k1v, k2v, k3v, k4v = np.empty(6), np.empty(6), np.empty(6), np.empty(6)
    k1z, k2z, k3z, k4z = np.empty(n_s), np.empty(n_s), np.empty(n_s), np.empty(n_s)
    xs, vs, zs = np.empty(6), np.empty(6), np.empty(n_s)
    dz0 = np.empty(n_s)
    for n in range(n_steps + 1):
        if conv:
            # H0 is the whole integral at t_n (the current interval of stage 1 is empty)
            _history(vbuf, head, count, Kh, pairs_i, pairs_j, dt, H0, Hh, H1)
        if nc > 0:
            _forces(2 * n, x, v, z, H0, 0, v, dt, C, Bv, Bq, F_ext, thrust, r_p, Kh, pairs_i, pairs_j,
                    conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, dz0, F)
            decide_modes(x, v, dt, P, S, N, TH, CF, DF, MU, sideways, mode, fdir, anchor, anchored,
                         Mt_inv, F, need, avail, v_tol)
        # stage 1 (c = 0) — also the step-start record
        _stage(2 * n, x, v, z, H0, 0, v, dt, Mt_inv, C, Bv, Bq, F_ext, thrust, r_p, Kh, pairs_i, pairs_j,
               conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, ct, cs, k1z, k1v, F, f_t, f_n)
        out_x[n, :] = x
        out_v[n, :] = v
        for c in range(nc):
            out_mode[n, c] = mode[c]
            out_fn[n, c] = f_n[c]
            out_ft[n, c, 0] = f_t[c, 0]
            out_ft[n, c, 1] = f_t[c, 1]
            out_need[n, c] = need[c]
            out_avail[n, c] = avail[c]
            out_tpos[n, c, 0], out_tpos[n, c, 1] = tangential_position(x, P[c], TH[c])
        if n == n_steps:
            break
        _trial_state(x, v, z, v, k1v, k1z, 0.5 * dt, k1x, xs, vs, zs)
        # stage 2 (c = ½)
        _stage(2 * n + 1, xs, vs, zs, Hh, 1, v, dt, Mt_inv, C, Bv, Bq, F_ext, thrust, r_p, Kh, pairs_i, pairs_j,
               conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, ct, cs, k2z, k2v, F, f_t, f_n)
        _trial_state(x, v, z, vs, k2v, k2z, 0.5 * dt, k2x, xs, vs, zs)
        # stage 3 (c = ½)
        _stage(2 * n + 1, xs, vs, zs, Hh, 1, v, dt, Mt_inv, C, Bv, Bq, F_ext, thrust, r_p, Kh, pairs_i, pairs_j,
               conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, ct, cs, k3z, k3v, F, f_t, f_n)
        _trial_state(x, v, z, vs, k3v, k3z, dt, k3x, xs, vs, zs)
        # stage 4 (c = 1)
        _stage(2 * n + 2, xs, vs, zs, H1, 2, v, dt, Mt_inv, C, Bv, Bq, F_ext, thrust, r_p, Kh, pairs_i, pairs_j,
               conv, ss_A, ss_B, ss_C, ss_in, ss_out, ss_pair, ct, cs, k4z, k4v, F, f_t, f_n)
        for d in range(6):
            k4x[d] = vs[d]
        bad = False
        for d in range(6):
            x[d] += dt / 6.0 * (k1x[d] + 2 * k2x[d] + 2 * k3x[d] + k4x[d])
            v[d] += dt / 6.0 * (k1v[d] + 2 * k2v[d] + 2 * k3v[d] + k4v[d])
            if not (np.isfinite(x[d]) and np.isfinite(v[d])):
                bad = True
        for q in range(n_s):
            z[q] += dt / 6.0 * (k1z[q] + 2 * k2z[q] + 2 * k3z[q] + k4z[q])
        if bad:
            out_x[n + 1, :] = x
            out_v[n + 1, :] = v
            return STATUS_NAN, n + 1
        for d in range(3):
            if abs(x[d]) > limit_trans or abs(x[d + 3]) > limit_rot:
                out_x[n + 1, :] = x
                out_v[n + 1, :] = v
                return STATUS_RUNAWAY, n + 1
        # a contact that stuck during this step is anchored where it came to rest
        for c in range(nc):
            if mode[c] == STICK and not anchored[c]:
                anchor[c, 0], anchor[c, 1] = tangential_position(x, P[c], TH[c])
                anchored[c] = True
            elif mode[c] != STICK:
                anchored[c] = False
        head = (head + 1) % nb
        vbuf[head, :] = v
        vbuf[head + nb, :] = v
        if count < nb:
            count += 1
    return STATUS_OK, n_steps
