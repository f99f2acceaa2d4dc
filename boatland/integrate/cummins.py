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

State space: the fitted modal systems :math:`\dot z = A_r z + B_r \dot x_j`, :math:`\mu_{ij} = C_r z`
are integrated exactly over each step for a velocity linear between the step's ends (first-order hold,
the "triangle-hold equivalent" of Franklin, Powell & Workman 1998, *Digital Control of Dynamic
Systems*, §6.3.2; the integrals by Van Loan's block exponential, Van Loan 1978, IEEE Trans. AC 23(3)):

.. math::
    z(t_n + h) = \Phi(h) z_n + \Gamma_0(h)\,\dot x_n + \Gamma_1(h)\,\dot x(t_n + h), \qquad
    \mu_c = \underbrace{C\,\Phi(c\Delta t)\, z_n}_{H_c\ \text{(fixed in the step)}}
          + C\Gamma_0(c\Delta t)\,\dot x_n + C\Gamma_1(c\Delta t)\,\dot x_{stage}

— the same split as the convolution's (a history fixed in the step, the current interval linear in the
stage velocity), exact for the fitted K: no stability limit on Δt from fast poles, and the memory costs
two passes over its states per step (the three history sums, then :math:`z_{n+1}` from the step's end
velocity) instead of a derivative at each of the four stages.

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
from boatland.rigid import add_point_force, rotation_into
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


@njit(cache=True, _nrt=False, forceinline=True, fastmath={"reassoc"})
def _ss_history(z, ss_P, rows, H):
    r"""State-space history sums :math:`H_c = C\,\Phi(c\Delta t)\,z_n` for c = 0, ½, 1 (rows of ``H`` (3, 6)).

    ``ss_P`` (3, N) holds each state's output coefficient at the three stage times, the states of each
    output DOF contiguous (``rows``: first state and count). The sums may be reassociated (``reassoc``,
    this function only) so that they run in SIMD lanes: the order is fixed by the compiled code, the
    same on every run, worker and core count of this machine.
    """
    for i in range(6):
        s = np.uint64(rows[i, 0])
        end = s + np.uint64(rows[i, 1])
        h0 = 0.0
        h1 = 0.0
        h2 = 0.0
        while s < end:
            zs = z[s]
            h0 += ss_P[0, s] * zs
            h1 += ss_P[1, s] * zs
            h2 += ss_P[2, s] * zs
            s += _U1
        H[0, i] = h0
        H[1, i] = h1
        H[2, i] = h2


@njit(cache=True, _nrt=False, forceinline=True)
def _ss_advance(z, z_next, ss_E, ss_seg, v_n, v):
    r"""The states at the step's end: :math:`z_{n+1} = \Phi(\Delta t) z_n + \Gamma_0 \dot x_{j,n} +
    \Gamma_1 \dot x_{j,n+1}` into ``z_next``, state by state in the modal layout of
    :func:`boatland.trial.motion.modal_layout` (``ss_E`` rows: Φ's diagonal, its coefficient of the state
    above and of the state below — a complex pair's partner —, Γ₀, Γ₁). Each run of ``ss_seg`` shares its
    input DOF; every loop is contiguous with unsigned indices, so it vectorises.
    """
    for g in range(ss_seg.shape[0]):
        j = ss_seg[g, 2]
        a = v_n[j]
        b = v[j]
        s = np.uint64(ss_seg[g, 0])
        end = np.uint64(ss_seg[g, 1])
        while s < end:
            z_next[s] = (((ss_E[0, s] * z[s] + ss_E[1, s] * z[s + _U1]) + ss_E[2, s] * z[s - _U1])
                         + ss_E[3, s] * a) + ss_E[4, s] * b
            s += _U1


@njit(cache=True, _nrt=False, forceinline=True)
def _forces(t_idx, c2, x, v, v_n, R, H, C, Bv, Bq, F_ext, T, push, flow, memory, F):
    """All forces but the contacts, into ``F``.

    The stage is ``c2`` half steps into the step (0, 1, 2: c = 0, ½, 1), at half-step index ``t_idx``;
    ``v_n`` is the velocity at the step start, ``H`` (3, 6) the memory's history sums of the step. The
    memory of the current interval is linear in the stage velocity: :math:`G_0 \\dot x_{j,n} + G_1 \\dot
    x_j` per pair (``memory`` = (pairs_i, pairs_j, G (npairs, 3, 2)); the convolution's trapezoid or the
    state space's exact hold, see the module). ``T`` is the push [N] at this stage, ``push`` = (r_p, e_T)
    its body point and direction; ``flow`` = (on, U, table, par, ramp, strips) the current's drag on the
    hull's strips (:func:`boatland.loads.drag.add_drag`) when ``on``, its speed × ramp at the half steps.
    """
    pairs_i, pairs_j, G = memory
    for d in range(6):
        F[d] = F_ext[t_idx, d] - Bv[d] * v[d] - Bq[d] * abs(v[d]) * v[d]
        for e in range(6):
            F[d] -= C[d, e] * x[e]
    if T != 0.0:
        _thrust(R, T, push[0], push[1], F)
    if flow[0]:
        add_drag(R, v, flow[1], flow[4][t_idx], flow[2], flow[3], flow[5], F)
    if c2 > 0:
        for p in range(pairs_i.shape[0]):
            i, j = pairs_i[p], pairs_j[p]
            F[i] -= G[p, c2, 0] * v_n[j] + G[p, c2, 1] * v[j]
    for d in range(6):
        F[d] -= H[c2, d]


@njit(cache=True, _nrt=False, forceinline=True)
def _stage(n, st, x, v, v_n, R, dt, H, Mt_inv, C, Bv, Bq, F_ext, T, push, flow, memory, ct, cs, ws, v_tol, kv,
           scratch, records):
    """Stage ``st`` (0–3) of step ``n`` at the stage state (x, v): accelerations into row ``st`` of ``kv``
    (4, 6), contacts included.

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
    _forces(t_idx, c2, x, v, v_n, R, H, C, Bv, Bq, F_ext, T, push, flow, memory, F)
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
def _trial_state(st, h, x, v, kx, kv, xs, vs):
    """State (xs, vs) of RK4 stage ``st``: the step start (x, v) for st = 0, else (x, v) + h (kx, kv)[st − 1]
    after kx[st − 1] = the previous stage's velocity ``vs``."""
    if st == 0:
        for d in range(6):
            xs[d] = x[d]
            vs[d] = v[d]
        return
    k = st - 1
    for d in range(6):
        kx[k, d] = vs[d]
    for d in range(6):
        xs[d] = x[d] + h * kx[k, d]
        vs[d] = v[d] + h * kv[k, d]


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
                conv, Kh, pairs_i, pairs_j, G, n_hist, ss_E, ss_P, ss_seg, ss_rows,
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
        (block-diagonal) form discretised exactly over the step, laid out by
        :func:`boatland.trial.motion.modal_layout`: ``ss_E`` (5, N) each state's Φ(Δt) coefficient of
        itself, of the state above and of the state below, its Γ₀ and Γ₁; ``ss_P`` (3, N) its output
        coefficient C Φ(cΔt) at c = 0, ½, 1; ``ss_seg`` (n_seg, 3) runs [start, end) sharing an input DOF,
        ``ss_rows`` (6, 2) first state and number of states per output DOF (N = states + 2 zero guards).
    G : (npairs, 3, 2)
        The memory of the current interval at the stage c2 half steps into the step:
        ``G[p, c2, 0] v_n[j] + G[p, c2, 1] v_stage[j]`` on output ``i`` of pair p (zero at c2 = 0).
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
    memory = (pairs_i, pairs_j, G)
    x = x0.copy()
    v = v0.copy()
    v_n = v0.copy()  # the velocity at the step start, kept for the state space's advance
    z = np.zeros(ss_E.shape[1])  # state-space memory at the step start (zero guards at both ends)
    z_next = np.zeros(ss_E.shape[1])
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
    kx, kv = np.zeros((4, 6)), np.zeros((4, 6))  # stage derivatives
    R = np.zeros((3, 3))  # body rotation at the stage state
    xs, vs = np.zeros(6), np.zeros(6)  # stage state
    for n in range(n_steps + 1):
        progress[0] = n
        if conv:
            _history(vbuf, head, count, Kh, pairs_i, pairs_j, dt, H)
        else:
            _ss_history(z, ss_P, ss_rows, H)
        if controlled:
            held, T_held = skipper_thrust(n, thrust, skipper, sk_buf, sk_state)
        for st in range(4):
            _trial_state(st, _A_NEXT[st - 1] * dt, x, v, kx, kv, xs, vs)
            rotation_into(xs[3], xs[4], xs[5], R)  # once per stage: thrust direction, contact points
            T = T_held if held else thrust[2 * n + _C2[st]]
            # stage 1 decides the contact modes of the step and is the step-start record
            _stage(n, st, xs, vs, v, R, dt, H, Mt_inv, C, Bv, Bq, F_ext, T, push, flow, memory, ct, cs, ws, v_tol,
                   kv, scratch, records)
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
            v_n[d] = v[d]
            x[d] += dt / 6.0 * (kx[0, d] + 2 * kx[1, d] + 2 * kx[2, d] + kx[3, d])
            v[d] += dt / 6.0 * (kv[0, d] + 2 * kv[1, d] + 2 * kv[2, d] + kv[3, d])
            if not (np.isfinite(x[d]) and np.isfinite(v[d])):
                bad = True
        if not conv:
            _ss_advance(z, z_next, ss_E, ss_seg, v_n, v)
            z, z_next = z_next, z
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
