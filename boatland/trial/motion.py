"""Compile a vessel's database and radiation memory into the arrays of the RK4 Cummins kernel."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from boatland.contact.fender import Contacts, no_contacts
from boatland.integrate.cummins import STATUS_MESSAGES, run_cummins
from boatland.vessel.database import HydroDB
from boatland.vessel.radiation import RadiationMemory

__all__ = ["MotionArrays", "compile_motion", "modal_layout"]


@dataclass(frozen=True, eq=False)
class MotionArrays:
    """Everything :func:`boatland.integrate.run_cummins` needs about the vessel (no time series)."""

    Mt_inv: np.ndarray
    C: np.ndarray
    conv: bool
    Kh: np.ndarray
    pairs_i: np.ndarray
    pairs_j: np.ndarray
    G: np.ndarray
    n_hist: int
    ss_E: np.ndarray
    ss_P: np.ndarray
    ss_seg: np.ndarray
    ss_rows: np.ndarray

    def __post_init__(self):
        n = self.pairs_i.shape[0]
        if self.pairs_j.shape != (n,) or self.G.shape != (n, 3, 2) or (self.conv and self.Kh.shape[0] != n):
            raise ValueError(f"pairs_i, pairs_j, G (and Kh for the convolution) must describe the same {n} pairs")

    @property
    def n_states(self) -> int:
        """Number of state-space memory states (the guards of :func:`modal_layout` not counted)."""
        return self.ss_E.shape[1] - 2

    @classmethod
    def without_memory(cls, Mt, C) -> "MotionArrays":
        """A system with no radiation memory (K ≡ 0): (M + A∞) x'' + C x = F — for analytic checks."""
        e = np.zeros(0, dtype=np.int64)
        return cls(np.linalg.inv(np.asarray(Mt, dtype=float)), np.asarray(C, dtype=float).copy(), True,
                   np.zeros((0, 1)), e, e, np.zeros((0, 3, 2)), 0, *_no_state_space())

    @staticmethod
    def allocate_outputs(n_steps: int, nc: int) -> dict:
        """Zeroed output arrays of :meth:`run` for ``n_steps`` steps and ``nc`` contacts."""
        return {
            "x": np.zeros((n_steps + 1, 6)), "v": np.zeros((n_steps + 1, 6)),
            "mode": np.zeros((n_steps + 1, nc), dtype=np.int64), "fn": np.zeros((n_steps + 1, nc)),
            "ft": np.zeros((n_steps + 1, nc, 2)), "needed": np.zeros((n_steps + 1, nc)),
            "available": np.zeros((n_steps + 1, nc)), "tpos": np.zeros((n_steps + 1, nc, 2)),
            "slide": np.zeros((n_steps + 1, nc, 2)), "work": np.zeros((n_steps + 1, nc)),
            "thrust": np.zeros(n_steps + 1),
        }

    def run(self, dt: float, n_steps: int, *, F_ext=None, thrust=None, r_p=(0.0, 0.0, 0.0),
            push_direction=(1.0, 0.0, 0.0), skipper=None, current=None, current_ramp=None, x0=None, v0=None,
            Bv=None, Bq=None, contacts=None, v_tol: float = 1e-6, limit_trans: float = 1e3,
            limit_rot: float = 1.0, progress=None, out=None, gate=None):
        """Integrate; returns a dict of arrays (t, x, v, thrust and, with contacts, mode, fn, ft, needed,
        available, tpos, slide, work) plus ``status`` and ``message``.

        ``F_ext`` (2 n_steps + 1, 6) and ``thrust`` (2 n_steps + 1,) are sampled at half steps; the push
        acts at body point ``r_p`` along the body direction ``push_direction`` (unit); ``skipper``: the
        controller's parameters (:meth:`boatland.loads.skipper.Skipper.kernel`; None: a constant push);
        ``current``: (U (3,) the current's local-frame velocity, :class:`boatland.loads.drag.DragLoad`)
        for the drag on the moving hull (None: no current), its speed times ``current_ramp`` (2 n_steps + 1,)
        at the half steps (default 1);
        ``contacts`` is a :class:`boatland.contact.fender.Contacts` in the local frame (None: none). ``progress``, an int64 array of shape
        (1,), receives the number of steps completed while the kernel runs (it releases the GIL, so
        another thread can poll it for a progress bar). ``out``: preallocated output arrays from
        :meth:`allocate_outputs` (rows below the progress count are final while the kernel runs — a
        logger in another thread may read them); by default they are allocated here. ``gate``, an int64
        array of shape (1,): the kernel starts step n only when ``gate[0] ≥ n`` (a logger keeps it a block
        ahead of what it has written, see :func:`boatland.integrate.run_cummins`); default: never waits.
        """
        m = 2 * n_steps + 1
        F_ext = np.zeros((m, 6)) if F_ext is None else np.ascontiguousarray(F_ext, dtype=float)
        thrust = np.zeros(m) if thrust is None else np.ascontiguousarray(thrust, dtype=float)
        if F_ext.shape != (m, 6) or thrust.shape != (m,):
            raise ValueError(f"F_ext must be ({m}, 6) and thrust ({m},) for {n_steps} steps (half steps)")
        vec = lambda a: np.zeros(6) if a is None else np.asarray(a, dtype=float).reshape(6)  # noqa: E731
        if contacts is None:
            contacts = no_contacts()
        elif not isinstance(contacts, Contacts):
            raise ValueError("contacts must be a boatland.contact.fender.Contacts (see contact_set)")
        one_int64 = lambda a: isinstance(a, np.ndarray) and a.dtype == np.int64 and a.shape == (1,)  # noqa: E731
        if progress is None:
            progress = np.zeros(1, dtype=np.int64)
        elif not one_int64(progress):
            raise ValueError("progress must be a numpy int64 array of shape (1,)")
        if gate is None:
            gate = np.array([n_steps], dtype=np.int64)
        elif not one_int64(gate):
            raise ValueError("gate must be a numpy int64 array of shape (1,)")
        nc = contacts[0].shape[0]
        if out is None:
            out = self.allocate_outputs(n_steps, nc)
        elif out["x"].shape != (n_steps + 1, 6) or out["mode"].shape != (n_steps + 1, nc):
            raise ValueError(f"out arrays must be allocate_outputs({n_steps}, {nc})")
        e_T = np.asarray(push_direction, dtype=float).reshape(3)
        if abs(np.linalg.norm(e_T) - 1.0) > 1e-12:
            raise ValueError(f"push_direction must be a unit vector, got {e_T}")
        sk = np.zeros(9) if skipper is None else np.ascontiguousarray(skipper, dtype=float).reshape(9)
        if current is None:
            flow = (False, np.zeros(3), np.zeros((4, 2)), np.zeros(8), np.ones(1), np.zeros((0, 3)))
        else:
            U, load = current
            tab, par = load.kernel()
            ramp = np.ones(m) if current_ramp is None else np.ascontiguousarray(current_ramp, dtype=float)
            if ramp.shape != (m,):
                raise ValueError(f"current_ramp must be ({m},) for {n_steps} steps (half steps)")
            flow = (True, np.asarray(U, dtype=float).reshape(3), tab, par, ramp, load.strips)
        status, last = run_cummins(
            float(dt), int(n_steps), self.Mt_inv, self.C, vec(Bv), vec(Bq), F_ext, thrust,
            np.asarray(r_p, dtype=float), e_T, sk, flow, vec(x0), vec(v0), self.conv, self.Kh, self.pairs_i,
            self.pairs_j, self.G, self.n_hist, self.ss_E, self.ss_P, self.ss_seg, self.ss_rows, contacts,
            float(v_tol), float(limit_trans), float(limit_rot), out["x"], out["v"], out["mode"], out["fn"],
            out["ft"], out["needed"], out["available"], out["tpos"], out["slide"], out["work"], out["thrust"],
            progress, gate)
        out = {k: a[:last + 1] for k, a in out.items()}
        out["t"] = np.arange(last + 1) * dt
        out["status"], out["message"] = int(status), STATUS_MESSAGES[int(status)]
        return out


def _resample_irf(memory: RadiationMemory, pairs, h: float, t_max: float) -> np.ndarray:
    """K of the given pairs at t = k h, k = 0 … t_max/h (linear interpolation of the stored IRF)."""
    irf = memory.irf
    t = np.arange(int(round(t_max / h)) + 1) * h
    return np.array([np.interp(t, irf.t, irf.K[i, j], right=0.0) for i, j in pairs]).reshape(len(pairs), t.size)


def _trapezoid_interval(Kh: np.ndarray, dt: float) -> np.ndarray:
    """G of the convolution: its current interval [t_n, t_n + cΔt] by the trapezoid,
    (cΔt / 2) [K(cΔt) v_n + K(0) v_stage] at c = 0, ½, 1 (see :mod:`boatland.integrate.cummins`)."""
    G = np.zeros((Kh.shape[0], 3, 2))
    for c2 in (1, 2):
        half = 0.5 * (0.5 * c2 * dt)
        G[:, c2, 0] = half * Kh[:, c2]
        G[:, c2, 1] = half * Kh[:, 0]
    return G


def hold_discretisation(a: np.ndarray, b: np.ndarray, h: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""Exact step of :math:`\dot z = a z + b u` over ``h`` for u linear between its values at the ends.

    .. math::
        z(h) = \Phi z(0) + \Gamma_0 u(0) + \Gamma_1 u(h), \quad \Phi = e^{ah}, \quad
        \Gamma_0 = \int_0^h e^{a\sigma} b\,d\sigma - \Gamma_1, \quad
        \Gamma_1 = \frac{1}{h}\int_0^h e^{a\sigma} b\,(h - \sigma)\,d\sigma

    (first-order hold, Franklin, Powell & Workman 1998, *Digital Control of Dynamic Systems* §6.3.2),
    the integrals read off one exponential of the augmented matrix
    :math:`\begin{bmatrix} a & b & 0\\ 0 & 0 & 1\\ 0 & 0 & 0\end{bmatrix} h` (Van Loan 1978, IEEE Trans.
    Automatic Control 23(3), "Computing integrals involving the matrix exponential").

    Parameters
    ----------
    a : (k, k)
        A modal block (k = 1 or 2).
    b : (k,)
    h : float

    Returns
    -------
    Phi : (k, k); Gamma0, Gamma1 : (k,)
    """
    from scipy.linalg import expm

    k = a.shape[0]
    M = np.zeros((k + 2, k + 2))
    M[:k, :k], M[:k, k], M[k, k + 1] = a * h, b * h, h
    E = expm(M)
    g1 = E[:k, k + 1] / h
    return E[:k, :k], E[:k, k] - g1, g1


def _modal_blocks(A: np.ndarray):
    """The diagonal blocks of a modal realisation: lists of state indices (one real pole or a complex pair)."""
    n = A.shape[0]
    blocks, s_ = [], 0
    while s_ < n:
        if s_ + 1 < n and (A[s_, s_ + 1] != 0.0 or A[s_ + 1, s_] != 0.0):
            blocks.append([s_, s_ + 1]); s_ += 2
        else:
            blocks.append([s_]); s_ += 1
    for q in blocks:  # nothing outside the blocks
        rest = np.delete(A[q], q, axis=1)
        if np.any(rest != 0.0):
            raise ValueError("state-space blocks larger than 2×2: not a modal realisation")
    return blocks


def compile_motion(db: HydroDB, memory: RadiationMemory, dt: float, *, method: str = "convolution",
                   memory_length: float | None = None) -> MotionArrays:
    """Kernel arrays for ``db`` with radiation ``memory`` at time step ``dt``.

    Parameters
    ----------
    db : HydroDB
        Needs ``M`` (mass matrix) — a database without it cannot be integrated.
    memory : RadiationMemory
        IRFs (and the state-space fit for ``method="state_space"``).
    dt : float
        Integration step [s]; K is resampled every Δt/2 for the stage-consistent convolution, the state
        space discretised exactly over Δt/2 and Δt (:func:`hold_discretisation`).
    method : {"convolution", "state_space"}
    memory_length : float, optional
        T_K [s] of the convolution; default the IRF's own length.
    """
    if db.M is None:
        raise ValueError("the database has no mass matrix: give mass, centre of gravity and inertia")
    Mt = db.M + memory.irf.A_inf
    Mt = 0.5 * (Mt + Mt.T)  # A∞ is symmetric in theory; BEM round-off leaves ~1e-5 relative asymmetry
    pairs = [(i, j) for i in range(6) for j in range(6) if memory.irf.significant[i, j]]
    T_K = float(memory.irf.t[-1]) if memory_length is None else float(memory_length)
    pi = np.array([p[0] for p in pairs], dtype=np.int64)
    pj = np.array([p[1] for p in pairs], dtype=np.int64)
    if method == "convolution":
        Kh = _resample_irf(memory, pairs, dt / 2, T_K)
        return MotionArrays(np.linalg.inv(Mt), db.C.copy(), True, Kh, pi, pj, _trapezoid_interval(Kh, dt),
                            int(round(T_K / dt)), *_no_state_space())
    if method != "state_space":
        raise ValueError(f"method must be 'convolution' or 'state_space', got {method!r}")
    ss = memory.state_space
    if ss is None:
        raise ValueError("no state-space fit in this radiation memory")
    # every block of every pair's modal system, discretised exactly at Δt/2 and Δt (hold_discretisation)
    E, P, s_in, s_out, partner = [], [], [], [], []
    G = np.zeros((len(pairs), 3, 2))
    for p, (i, j) in enumerate(pairs):
        f = ss.pairs.get((i, j))
        if f is None or f.order == 0:
            continue
        for q in _modal_blocks(f.A):
            a_, b_, c_ = f.A[np.ix_(q, q)], f.B[q], f.C[q]
            Phi_h, g0_h, g1_h = hold_discretisation(a_, b_, dt / 2)
            Phi, g0, g1 = hold_discretisation(a_, b_, dt)
            G[p, 1] += (c_ @ g0_h, c_ @ g1_h)
            G[p, 2] += (c_ @ g0, c_ @ g1)
            c_h, c_1 = c_ @ Phi_h, c_ @ Phi              # output coefficients at c = ½ and 1
            first = len(E)
            for r in range(len(q)):
                pair_ = len(q) == 2                      # a complex pair: the states first and first + 1
                E.append((Phi[r, r], Phi[r, 1 - r] if pair_ else 0.0, g0[r], g1[r]))
                P.append((c_[r], c_h[r], c_1[r]))
                s_in.append(j); s_out.append(i)
                partner.append(first + 1 - r if pair_ else -1)
    n = len(E)
    ss_E, ss_P, ss_seg, rows = modal_layout(np.array(E).reshape(n, 4), np.array(P).reshape(n, 3),
                                           np.array(s_in, dtype=np.int64), np.array(s_out, dtype=np.int64),
                                           np.array(partner, dtype=np.int64))
    return MotionArrays(np.linalg.inv(Mt), db.C.copy(), False, np.zeros((0, 1)), pi, pj, G, 0,
                        ss_E, ss_P, ss_seg, rows)


def modal_layout(E, P, s_in, s_out, pair):
    r"""The kernel's layout of a discretised modal state-space memory (:func:`boatland.integrate.cummins._ss_advance`,
    :func:`boatland.integrate.cummins._ss_history`).

    The states of the discretised systems :math:`z_s \leftarrow \phi_s z_s + \phi'_s z_{q(s)} + \gamma_{0,s}
    \dot x_{j(s),n} + \gamma_{1,s} \dot x_{j(s),n+1}`, :math:`H_{c,i} = \sum_{s: i(s) = i} p_{c,s} z_s`
    (``pair`` q(s) = −1: a real pole) keep their order, grouped by output DOF, between one zero guard
    state at each end (length N = n + 2). A complex pair's partner must be its neighbour, so the kernel
    reads it as the state above or below (``ss_E`` rows 1, 2; the other row 0) in contiguous,
    vectorisable loops without an index array. A zero coefficient adds an exact zero and the guards stay
    zero.

    Parameters
    ----------
    E : (n, 4)
        Per state: φ (its own coefficient), φ' (its partner's), γ₀, γ₁.
    P : (n, 3)
        Per state: its output coefficient at c = 0, ½, 1.
    s_in, s_out, pair : (n,) int64

    Returns
    -------
    ss_E : (5, N)
        Coefficient of the state itself, of the state above, of the state below, γ₀, γ₁ (rows contiguous).
    ss_P : (3, N)
        Output coefficients at c = 0, ½, 1.
    ss_seg : (n_seg, 3) int64
        Runs ``[start, end)`` of states sharing an input and an output DOF (third column: the input),
        covering every state once.
    rows : (6, 2) int64
        First state and number of states of each output DOF.
    """
    n = E.shape[0]
    if np.any(np.diff(s_out) < 0):
        raise ValueError("state-space states must be grouped by output DOF (blocks sorted by pair)")
    N = n + 2
    ss_E, ss_P = np.zeros((5, N)), np.zeros((3, N))
    ss_E[0, 1:-1], ss_E[3, 1:-1], ss_E[4, 1:-1] = E[:, 0], E[:, 2], E[:, 3]
    ss_P[:, 1:-1] = P.T
    for s_ in range(n):
        q = pair[s_]
        if q < 0:
            continue
        if s_out[q] != s_out[s_] or abs(q - s_) != 1:
            raise ValueError("a complex pole's partner state must be its neighbour in the same pair's block")
        ss_E[1 if q > s_ else 2, 1 + s_] = E[s_, 1]
    counts = np.bincount(s_out, minlength=6)
    rows = np.stack([1 + np.concatenate([[0], np.cumsum(counts)[:-1]]), counts], axis=1).astype(np.int64)
    seg = []
    s_ = 0
    while s_ < n:
        e = s_ + 1
        while e < n and s_in[e] == s_in[s_] and s_out[e] == s_out[s_]:
            e += 1
        seg.append((1 + s_, 1 + e, s_in[s_]))
        s_ = e
    return ss_E, ss_P, np.array(seg, dtype=np.int64).reshape(-1, 3), rows


def _no_state_space():
    """:func:`modal_layout` of no states: the state-space fields of a kernel without that memory."""
    e = np.zeros(0, dtype=np.int64)
    return modal_layout(np.zeros((0, 4)), np.zeros((0, 3)), e, e, e)
