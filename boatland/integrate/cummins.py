r"""Fixed-step RK4 of the Cummins equation with radiation memory by convolution or state space.

.. math::
    (M + A_\infty)\ddot x + \mu(t) + B_v \dot x + B_q |\dot x|\dot x + C x
        = F_{exc}(t) + F_T(t, x) + F_c(t, x, \dot x), \qquad
    \mu(t) = \int_0^t K(t-\tau)\,\dot x(\tau)\,d\tau

(Cummins 1962; San Nicolás Méndez 2024 eq. 3.40 and §4.2 for RK4 with the trapezoid convolution).

Stage consistency of the memory (San Nicolás Méndez 2024 §4.2; DESIGN.md §1): at the RK4 stage time
:math:`t_n + c\,\Delta t` (c = 0, ½, 1) the integral is split into a history part over
:math:`[0, t_n]` — trapezoid over the stored step velocities, fixed during the step — and the current
interval :math:`[t_n, t_n + c\Delta t]`, trapezoid with the stage velocity:

.. math::
    \mu_c = \underbrace{\sum_{m=0}^{n} w_m \Delta t\, K((n-m+c)\Delta t)\,\dot x_m}_{H_c\ \text{(fixed in the step)}}
          + \frac{c\Delta t}{2}\left[K(c\Delta t)\dot x_n + K(0)\,\dot x_{stage}\right]

with :math:`w_0 = w_n = ½`. K is therefore sampled every Δt/2. The three history sums (c = 0, ½, 1) are
computed in one pass per step over the stored velocities, for the significant DOF pairs only.

State space: the fitted systems :math:`\dot z = A_r z + B_r \dot x_j`, :math:`\mu_{ij} = C_r z` are
appended to the RK4 state, so they are consistent at every stage by construction.

All arrays are SI, DOF order surge..yaw, body motions small (linear hydrodynamics) while positions
of force points follow the exact rotation :math:`R(\phi,\theta,\psi)` (z-y-x Euler angles); the point
loads (contacts, push, hull drag) enter as the generalised forces of those angles — their moments about the
Euler axes, the virtual work of the coordinates — and the angles' rates make the angular velocity through the
same axes (:func:`boatland.rigid.euler_moment`, :func:`boatland.rigid.angular_velocity`).

Speed: :func:`run_cummins` allocates every buffer before the first step; the helpers it calls per
stage only index those arrays, so they are compiled without numba's reference counting
(``_nrt=False``, as numba does for its own string helpers) and inlined (``forceinline``). Otherwise
each call increfs and decrefs every array argument with an atomic operation — ~630 of them per step,
three quarters of the time of a step without memory and contacts (bench/README.md). A helper that allocates cannot be
compiled that way (numba refuses it).
"""

from __future__ import annotations

import time

import numpy as np
from numba import njit, objmode

from boatland.contact.fender import (OFF, accumulate_sliding, contact_forces, contact_state_arrays, contact_states,
                                     contact_workspace, decide_modes)
from boatland.loads.drag import add_drag
from boatland.loads.skipper import skipper_measure, skipper_state, skipper_thrust
from boatland.rigid import add_point_force, rotation_matrix
from boatland.rk4 import A_NEXT, B, C_HALF_STEPS

__all__ = ["run_cummins", "STATUS_OK", "STATUS_NAN", "STATUS_RUNAWAY", "STATUS_SLID_OFF", "STATUS_MESSAGES"]

STATUS_OK = 0
STATUS_NAN = 1
STATUS_RUNAWAY = 2
STATUS_SLID_OFF = 3
STATUS_MESSAGES = {
    STATUS_OK: "completed",
    STATUS_NAN: "the state became NaN or infinite",
    STATUS_RUNAWAY: "runaway motion (a displacement or rotation beyond the limit)",
    STATUS_SLID_OFF: "the fender slid off the landing",
}
#: Statuses that end a trial with an outcome rather than a failure of the integration.
OUTCOME_STATUSES = (STATUS_OK, STATUS_SLID_OFF)


#: RK4 stages (:mod:`boatland.rk4`): time of each stage in half steps into the step (c = 0, ½, ½, 1 → 0, 1, 1,
#: 2; also the row of the history sums), the step fraction from the step start to each stage after the first
#: (indexed by stage − 1; stage 0 is the step start) and the weights.
_C2 = C_HALF_STEPS
_A_NEXT = A_NEXT
_B = B


@njit(cache=True, _nrt=False, forceinline=True)
def _thrust(R, T, r_p, e_T, out):
    """Generalised force of a push T along the body direction ``e_T`` (unit, (3,)) applied at body point
    r_p, with the body rotation ``R`` (exact rotation)."""
    rx = R[0, 0] * r_p[0] + R[0, 1] * r_p[1] + R[0, 2] * r_p[2]
    ry = R[1, 0] * r_p[0] + R[1, 1] * r_p[1] + R[1, 2] * r_p[2]
    rz = R[2, 0] * r_p[0] + R[2, 1] * r_p[1] + R[2, 2] * r_p[2]
    d0 = R[0, 0] * e_T[0] + R[0, 1] * e_T[1] + R[0, 2] * e_T[2]
    d1 = R[1, 0] * e_T[0] + R[1, 1] * e_T[1] + R[1, 2] * e_T[2]
    d2 = R[2, 0] * e_T[0] + R[2, 1] * e_T[1] + R[2, 2] * e_T[2]
    add_point_force(R, rx, ry, rz, d0, d1, d2, T, out)


@njit(cache=True, _nrt=False, forceinline=True)
def _history(vbuf, head, count, Kh, pairs_i, pairs_j, dt, H):
    """H_c = Σ_m w_m Δt K((n−m+c)Δt) v_m for c = 0, ½, 1 (rows of ``H`` (3, 6)) in one pass over the
    stored velocities.

    ``vbuf`` (2 nb, 6) is a mirrored ring buffer (each velocity stored at ``head`` and ``head + nb``),
    so the last ``count`` velocities are contiguous: lag ℓ sits at ``head + nb − ℓ``. ``Kh`` (npairs,
    nK2) holds K at the half steps k Δt / 2, each pair contiguous in time. The three sums of a pair
    run together over the lags in order: three independent chains at the scalar floating-point rate.
    (Pairs as the inner, vectorisable loop measured slower for 10 pairs; reordering the sums would
    change the round-off.)
    """
    for c in range(3):
        for d in range(6):
            H[c, d] = 0.0
    if count < 2:  # [0, t_n] is empty at the first step
        return
    nb = vbuf.shape[0] // 2
    nK2 = Kh.shape[1]
    top = head + nb
    n_lag = min(count, (nK2 - 1) // 2)  # lags whose K(lag + 1) sample exists
    for p in range(pairs_i.shape[0]):
        i, j = pairs_i[p], pairs_j[p]
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
        H[0, i] += s0 * dt
        H[1, i] += sh * dt
        H[2, i] += s1 * dt


#: One, as an unsigned index: state-space indices are unsigned so that numba emits no negative-index
#: wraparound for them (a select per access that blocks vectorisation).
_U1 = np.uint64(1)


@njit(cache=True, _nrt=False, forceinline=True)
def _state_space(v, z, ss_A, ss_B, ss_C, ss_seg, rows, st, kz, F):
    r"""Modal state-space memory: derivative into row ``st`` of ``kz`` and the output subtracted from ``F``.

    .. math::
        \dot z_s = (a_s z_s + b_s \dot x_{j(s)}) + a^{\uparrow}_s z_{s+1} + a^{\downarrow}_s z_{s-1},
        \qquad F_i \mathrel{-}= c_s z_s \ \text{for the states } s \text{ of output DOF } i \text{ in order}

    in the layout of :func:`boatland.trial.motion.modal_layout`: a complex pair's partner is the state
    above or below (the other coefficient zero), each run of ``ss_seg`` shares its input DOF, and the
    six output sums (``rows``: first state and count per output DOF) run side by side. Every loop is
    contiguous with unsigned indices, so the derivative vectorises.
    """
    for g in range(ss_seg.shape[0]):
        vj = v[ss_seg[g, 2]]
        s = np.uint64(ss_seg[g, 0])
        end = np.uint64(ss_seg[g, 1])
        while s < end:
            kz[st, s] = ((ss_A[0, s] * z[s] + ss_B[s] * vj) + ss_A[1, s] * z[s + _U1]) + ss_A[2, s] * z[s - _U1]
            s += _U1
    o0, o1, o2 = np.uint64(rows[0, 0]), np.uint64(rows[1, 0]), np.uint64(rows[2, 0])
    o3, o4, o5 = np.uint64(rows[3, 0]), np.uint64(rows[4, 0]), np.uint64(rows[5, 0])
    n0, n1, n2 = np.uint64(rows[0, 1]), np.uint64(rows[1, 1]), np.uint64(rows[2, 1])
    n3, n4, n5 = np.uint64(rows[3, 1]), np.uint64(rows[4, 1]), np.uint64(rows[5, 1])
    longest = max(n0, n1, n2, n3, n4, n5)
    # six sums written out, not a loop over an array: each stays in a register and the six dependent
    # chains run side by side (an f[6] array would pass every subtraction through memory)
    f0, f1, f2, f3, f4, f5 = F[0], F[1], F[2], F[3], F[4], F[5]
    r = np.uint64(0)
    while r < longest:
        if r < n0:
            f0 -= ss_C[o0 + r] * z[o0 + r]
        if r < n1:
            f1 -= ss_C[o1 + r] * z[o1 + r]
        if r < n2:
            f2 -= ss_C[o2 + r] * z[o2 + r]
        if r < n3:
            f3 -= ss_C[o3 + r] * z[o3 + r]
        if r < n4:
            f4 -= ss_C[o4 + r] * z[o4 + r]
        if r < n5:
            f5 -= ss_C[o5 + r] * z[o5 + r]
        r += _U1
    F[0], F[1], F[2], F[3], F[4], F[5] = f0, f1, f2, f3, f4, f5


@njit(cache=True, _nrt=False, forceinline=True)
def _forces(t_idx, c2, x, v, z, v_n, R, dt, H, C, Bv, Bq, F_ext, T, push, flow, conv, memory, st, kz, F):
    """All forces but the contacts, into ``F``; the state-space derivative into row ``st`` of ``kz``.

    The stage is ``c2`` half steps into the step (0, 1, 2: c = 0, ½, 1), at half-step index ``t_idx``;
    ``v_n`` is the velocity at the step start, ``H`` (3, 6) the history sums of the step. ``T`` is the
    push [N] at this stage, ``push`` = (r_p, e_T) its body point and direction; ``flow`` = (on, U, table,
    par, ramp, strips) the current's drag on the hull's strips (:func:`boatland.loads.drag.add_drag`) when
    ``on``, its speed × ramp at the half steps.
    """
    Kh, pairs_i, pairs_j, ss_A, ss_B, ss_C, ss_seg, ss_rows = memory
    for d in range(6):
        F[d] = F_ext[t_idx, d] - Bv[d] * v[d] - Bq[d] * abs(v[d]) * v[d]
        for e in range(6):
            F[d] -= C[d, e] * x[e]
    if T != 0.0:
        _thrust(R, T, push[0], push[1], F)
    if flow[0]:
        add_drag(R, v, flow[1], flow[4][t_idx], flow[2], flow[3], flow[5], F)
    if conv:
        cdt = 0.5 * c2 * dt
        for p in range(pairs_i.shape[0]):
            i, j = pairs_i[p], pairs_j[p]
            cur = 0.5 * cdt * (Kh[p, c2] * v_n[j] + Kh[p, 0] * v[j]) if c2 > 0 else 0.0
            F[i] -= cur
        for d in range(6):
            F[d] -= H[c2, d]
    else:
        _state_space(v, z, ss_A, ss_B, ss_C, ss_seg, ss_rows, st, kz, F)


@njit(cache=True, _nrt=False, forceinline=True)
def _stage(n, st, x, v, z, v_n, R, dt, H, Mt_inv, C, Bv, Bq, F_ext, T, push, flow, conv, memory, ct, cs, ws,
           v_tol, kv, kz, scratch, records):
    """Stage ``st`` (0–3) of step ``n`` at the stage state (x, v, z): accelerations into row ``st`` of
    ``kv`` (4, 6) and the state-space derivative into row ``st`` of ``kz`` (4, ns), contacts included.

    ``v_n`` is the velocity at the step start, ``R`` the body rotation at the stage state (thrust
    direction, contact points), ``T`` the push at the stage, ``ct`` the contacts (:class:`boatland.contact.fender.Contacts`) and
    ``cs`` their state. The first stage closes the previous step of every contact and decides the
    stick–slip modes of this one at the step start (:func:`boatland.contact.fender.decide_modes`),
    reusing its last solve when final. ``scratch`` = (acc, F) (6,) each, ``records`` = (f_t, f_n,
    needed, available) per contact.
    """
    c2 = _C2[st]
    t_idx = 2 * n + c2
    kin, solve, F_try = ws
    f_t, f_n, needed, available = records
    acc, F = scratch
    _forces(t_idx, c2, x, v, z, v_n, R, dt, H, C, Bv, Bq, F_ext, T, push, flow, conv, memory, st, kz, F)
    if ct.P.shape[0] == 0:
        for d in range(6):
            a = 0.0
            for e in range(6):
                a += Mt_inv[d, e] * F[e]
            acc[d] = a
    else:
        contact_states(R, x, v, ct, cs, kin)
        if not (st == 0 and decide_modes(dt, ct, cs, R, x, Mt_inv, kin, solve, F_try, F, acc, f_t, f_n, needed,
                                         available, v_tol)):
            contact_forces(dt, ct, cs, R, Mt_inv, kin, solve, F, acc, f_t, f_n, v_tol)
    for d in range(6):
        kv[st, d] = acc[d]


@njit(cache=True, _nrt=False, forceinline=True)
def _trial_state(st, h, x, v, z, kx, kv, kz, xs, vs, zs):
    """State (xs, vs, zs) of RK4 stage ``st``: the step start (x, v, z) for st = 0, else
    (x, v, z) + h (kx, kv, kz)[st − 1] after kx[st − 1] = the previous stage's velocity ``vs``."""
    if st == 0:
        for d in range(6):
            xs[d] = x[d]
            vs[d] = v[d]
        for q in range(z.shape[0]):
            zs[q] = z[q]
        return
    k = st - 1
    for d in range(6):
        kx[k, d] = vs[d]
    for d in range(6):
        xs[d] = x[d] + h * kx[k, d]
        vs[d] = v[d] + h * kv[k, d]
    for q in range(z.shape[0]):
        zs[q] = z[q] + h * kz[k, q]


@njit(cache=True, _nrt=False, forceinline=True)
def _record(n, x, v, cs, records, tpos, out_x, out_v, out_mode, out_fn, out_ft, out_need, out_avail, out_tpos,
            out_slide, out_work):
    """Row ``n`` of the outputs: the state and the contacts at the step start, and each contact's slide
    [m] and friction work [J] over the step that ended there (then reset for the next step)."""
    f_t, f_n, needed, available = records
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    for d in range(6):
        out_x[n, d] = x[d]
        out_v[n, d] = v[d]
    for c in range(mode.shape[0]):
        out_mode[n, c] = mode[c]
        out_fn[n, c] = f_n[c]
        out_ft[n, c, 0] = f_t[c, 0]
        out_ft[n, c, 1] = f_t[c, 1]
        out_need[n, c] = needed[c]
        out_avail[n, c] = available[c]
        out_tpos[n, c, 0] = tpos[c, 0]
        out_tpos[n, c, 1] = tpos[c, 1]
        out_slide[n, c, 0] = slide[c, 0]
        out_slide[n, c, 1] = slide[c, 1]
        out_work[n, c] = work[c]
        slide[c, 0] = 0.0
        slide[c, 1] = 0.0
        work[c] = 0.0


@njit(cache=True, _nrt=False, forceinline=True)
def _slid_off(cs):
    """True when a contact that had touched the landing is off it (past a tube's end or the fender's)."""
    mode, fdir, anchA, anchP, anchored, landed, slide, work = cs
    for c in range(mode.shape[0]):
        if mode[c] == OFF and landed[c]:
            return True
    return False


#: Sleep [s] between looks at the gate while the kernel waits for its sinks (see :func:`run_cummins`).
GATE_SLEEP = 1e-4


@njit(cache=True, nogil=True)
def _wait_for_gate(gate, n):
    """Wait (sleeping, with the GIL released between looks) until ``gate[0] ≥ n``."""
    while n > gate[0]:
        with objmode():
            time.sleep(GATE_SLEEP)


@njit(cache=True, nogil=True)
def run_cummins(dt, n_steps, Mt_inv, C, Bv, Bq, F_ext, thrust, r_p, e_T, skipper, flow, x0, v0,
                conv, Kh, pairs_i, pairs_j, n_hist, ss_A, ss_B, ss_C, ss_seg, ss_rows,
                ct, v_tol, limit_trans, limit_rot, out_x, out_v, out_mode, out_fn, out_ft, out_need,
                out_avail, out_tpos, out_slide, out_work, out_thrust, progress, gate):
    """Integrate the Cummins equation with classic RK4; returns ``(status, last_step)``.

    Runs without the GIL (``nogil``): another thread may poll ``progress`` meanwhile. All buffers are
    allocated once before the first step.

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
        Push [N] at half steps (ramp included) along the body direction ``e_T`` (3,, unit) at the body
        point ``r_p`` (3,) — the nominal push when a controller acts.
    skipper : (9,)
        The push controller's parameters (:meth:`boatland.loads.skipper.Skipper.kernel`; all zero: none):
        from its first step on, the push of each step is :func:`boatland.loads.skipper.skipper_thrust`,
        held over the step.
    flow : tuple
        (on, U (3,), table (4, n), par (8,), ramp (2 n_steps + 1,), strips (n, 3)): the current's drag on
        the moving hull's strips at every stage (:func:`boatland.loads.drag.add_drag`), its velocity U times
        the ramp at the half steps; ``on`` False: none.
    x0, v0 : (6,)
        Initial displacement and velocity.
    conv : bool
        True: convolution memory with ``Kh`` (npairs, nK2) = K(k Δt/2) of the pairs
        (``pairs_i``, ``pairs_j``) over ``n_hist`` past steps. False: state space in modal
        (block-diagonal) form, laid out by :func:`boatland.trial.motion.modal_layout`: ``ss_A`` (3, N)
        each state's coefficient of itself, of the state above and of the state below, ``ss_B`` (N,),
        ``ss_C`` (N,), ``ss_seg`` (n_seg, 3) runs [start, end) sharing an input DOF, ``ss_rows`` (6, 2)
        first state and number of states per output DOF (N = states + 2 zero guards).
    ct : Contacts
        The fender contacts in the local frame (:class:`boatland.contact.fender.Contacts`; Nc = 0 for none).
    v_tol : float
        Speed below which a rigid contact's sliding direction is not defined [m/s].
    limit_trans, limit_rot : float
        Runaway limits [m], [rad].
    out_x, out_v : (n_steps + 1, 6)
        Trajectory.
    out_mode, out_fn, out_need, out_avail : (n_steps + 1, Nc)
        Per step start: contact mode (0 open, 1 stick, 2 slip, 3 off the landing), normal force, force
        that would hold the contact stuck, friction available (μ_s f_n, or μ(|u|) f_n while sliding).
    out_ft, out_tpos : (n_steps + 1, Nc, 2)
        Tangential (vertical, horizontal) friction force and the fender's position on the landing.
    out_slide : (n_steps + 1, Nc, 2)
        Sliding of the fender over the tube during the step that ended at each row [m]; ``out_work``
        (n_steps + 1, Nc) the friction work of that step [J] (never positive).
    out_thrust : (n_steps + 1,)
        The push at each step start [N] (the controller's when one acts).
    progress : (1,) int64
        Progress counter: rows below it are final (set as each step's record is written), ``last`` on
        return.
    gate : (1,) int64
        Having written row n, the kernel integrates on to t_{n+1} only once ``gate[0] ≥ n + 1`` (it
        sleeps meanwhile): whoever consumes the rows (a run log) keeps it at most a block ahead of what
        is safely written, so that a killed run loses at most that block. ``n_steps`` or more: never waits.

    Returns
    -------
    status : int
        :data:`STATUS_OK`, :data:`STATUS_NAN`, :data:`STATUS_RUNAWAY` or :data:`STATUS_SLID_OFF`
        (see :data:`STATUS_MESSAGES`).
    last : int
        Last step written.
    """
    nc = ct.P.shape[0]
    cs = contact_state_arrays(nc)
    ws = contact_workspace(nc, ct.sideways)
    tpos = ws[0][6]  # positions of the contacts on the landing at the stage state (contact_states)
    records = (np.zeros((nc, 2)), np.zeros(nc), np.zeros(nc), np.zeros(nc))  # f_t, f_n, needed, available
    n_s = ss_B.shape[0]
    memory = (Kh, pairs_i, pairs_j, ss_A, ss_B, ss_C, ss_seg, ss_rows)
    x = x0.copy()
    v = v0.copy()
    z = np.zeros(n_s)
    nb = max(n_hist + 1, 1)
    vbuf = np.zeros((2 * nb, 6))  # mirrored ring buffer of the velocities (see _history)
    head = 0
    count = 1
    for d in range(6):
        vbuf[0, d] = v[d]
        vbuf[nb, d] = v[d]
    H = np.zeros((3, 6))  # history sums at c = 0, ½, 1 (H[0] is the whole integral at t_n)
    push = (r_p, e_T)
    controlled = skipper[0] != 0.0
    sk_buf, sk_state = skipper_state(skipper)
    held = False
    T_held = 0.0
    scratch = (np.zeros(6), np.zeros(6))  # acc, F of one stage
    kx, kv, kz = np.zeros((4, 6)), np.zeros((4, 6)), np.zeros((4, n_s))  # stage derivatives
    xs, vs, zs = np.zeros(6), np.zeros(6), np.zeros(n_s)  # stage state
    for n in range(n_steps + 1):
        progress[0] = n
        if conv:
            _history(vbuf, head, count, Kh, pairs_i, pairs_j, dt, H)
        if controlled:
            held, T_held = skipper_thrust(n, thrust, skipper, sk_buf, sk_state)
        for st in range(4):
            _trial_state(st, _A_NEXT[st - 1] * dt, x, v, z, kx, kv, kz, xs, vs, zs)
            R = rotation_matrix(xs[3], xs[4], xs[5])  # once per stage: thrust direction, contact points
            T = T_held if held else thrust[2 * n + _C2[st]]
            # stage 1 decides the contact modes of the step and is the step-start record
            _stage(n, st, xs, vs, zs, v, R, dt, H, Mt_inv, C, Bv, Bq, F_ext, T, push, flow, conv, memory, ct, cs,
                   ws, v_tol, kv, kz, scratch, records)
            if st == 0:
                _record(n, x, v, cs, records, tpos, out_x, out_v, out_mode, out_fn, out_ft, out_need,
                        out_avail, out_tpos, out_slide, out_work)
                out_thrust[n] = T
                if controlled:
                    skipper_measure(n, records[1], sk_buf, sk_state)
                if _slid_off(cs):
                    progress[0] = n
                    return STATUS_SLID_OFF, n
                if n == n_steps:
                    break
                progress[0] = n + 1                   # row n is final
                if n + 1 > gate[0]:                   # integrate beyond t_n only once the sinks allow it
                    _wait_for_gate(gate, n + 1)
            if nc:
                accumulate_sliding(ct, cs, ws[0], records[0], _B[st] * dt)
        if n == n_steps:
            break
        for d in range(6):
            kx[3, d] = vs[d]
        bad = False
        for d in range(6):
            x[d] += dt / 6.0 * (kx[0, d] + 2 * kx[1, d] + 2 * kx[2, d] + kx[3, d])
            v[d] += dt / 6.0 * (kv[0, d] + 2 * kv[1, d] + 2 * kv[2, d] + kv[3, d])
            if not (np.isfinite(x[d]) and np.isfinite(v[d])):
                bad = True
        for q in range(n_s):
            z[q] += dt / 6.0 * (kz[0, q] + 2 * kz[1, q] + 2 * kz[2, q] + kz[3, q])
        if bad:
            out_x[n + 1, :] = x
            out_v[n + 1, :] = v
            progress[0] = n + 1
            return STATUS_NAN, n + 1
        for d in range(3):
            if abs(x[d]) > limit_trans or abs(x[d + 3]) > limit_rot:
                out_x[n + 1, :] = x
                out_v[n + 1, :] = v
                progress[0] = n + 1
                return STATUS_RUNAWAY, n + 1
        head = (head + 1) % nb
        for d in range(6):
            vbuf[head, d] = v[d]
            vbuf[head + nb, d] = v[d]
        if count < nb:
            count += 1
    return STATUS_OK, n_steps
