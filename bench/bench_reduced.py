"""Can one low-order MIMO state space replace the per-pair radiation fits? (issue 28, item 1)

Run: ``python bench/bench_reduced.py``. For each built-in vessel (ctv24, T_K 40 s; ctv27, 120 s) the
per-pair fits (target R² 0.99999 per DOF pair, :data:`boatland.vessel.radiation.TARGET_R2`) are joined
into one MIMO system per symmetry group — (surge, heave, pitch) and (sway, roll, yaw), which do not
couple — and reduced by square-root balanced truncation (Moore 1981, IEEE Trans. AC 26(1); Tombs &
Postlethwaite 1987, Int. J. Control 46(4)), inputs and outputs scaled by √max|K_ii| so that every DOF
weighs alike. Balanced truncation keeps the system stable; its H∞ error is at most twice the sum of the
discarded Hankel singular values, and no model of order r errs less than the (r+1)-th (Glover 1984,
Int. J. Control 39(6)).

Printed per group and order r: the Hankel lower bound on any order-r model's H∞ error (relative to
‖K̂‖∞), and the truncated model's worst per-pair R² against the IRF K(t) beside the gate the per-pair
fit meets (min(0.99999, the pair's own R²)). The gate is the one the project chose for the memory
(R² = 0.999 left the catamaran's heave and pitch decays 3.7 % and 5.0 % off; see
``boatland/vessel/radiation.py``).
"""

from __future__ import annotations

import platform
import time

import numpy as np
import scipy
import scipy.linalg as sl

from boatland.hydro.builtin import load_builtin
from boatland.irf.impulse import IRFSettings
from boatland.vessel.radiation import TARGET_R2, default_dt, radiation_memory

GROUPS = ((0, 2, 4), (1, 3, 5))
VESSELS = (("ctv24", 40.0), ("ctv27", 120.0))


def group_system(ss, group):
    """The per-pair fits of the pairs whose output is in ``group`` as one MIMO (A, B, C)."""
    blocks = [(i, j, f) for (i, j), f in sorted(ss.pairs.items()) if f.order > 0 and i in group]
    n = sum(f.order for *_, f in blocks)
    A = np.zeros((n, n)); B = np.zeros((n, 6)); C = np.zeros((6, n))
    k = 0
    for i, j, f in blocks:
        o = f.order
        A[k:k + o, k:k + o], B[k:k + o, j], C[i, k:k + o] = f.A, f.B, f.C
        k += o
    g = list(group)
    return A, B[:, g], C[g, :]


def balanced_truncation(A, B, C, r):
    """Square-root balanced truncation to order r; also the Hankel singular values."""
    P = sl.solve_continuous_lyapunov(A, -B @ B.T)
    Q = sl.solve_continuous_lyapunov(A.T, -C.T @ C)
    wp, Vp = np.linalg.eigh(0.5 * (P + P.T))
    wq, Vq = np.linalg.eigh(0.5 * (Q + Q.T))
    Lp, Lq = Vp * np.sqrt(np.clip(wp, 0, None)), Vq * np.sqrt(np.clip(wq, 0, None))
    U, s, Vt = np.linalg.svd(Lq.T @ Lp)
    S = np.diag(s[:r] ** -0.5)
    T, Ti = Lp @ Vt[:r].T @ S, S @ U[:, :r].T @ Lq.T
    return Ti @ A @ T, Ti @ B, C @ T, s


def impulse(A, B, C, t):
    lam, V = np.linalg.eig(A)
    Bm, Cm = np.linalg.solve(V, B.astype(complex)), C @ V
    return np.real(np.einsum("in,tn,nj->ijt", Cm, np.exp(np.outer(t, lam)), Bm))


def hinf(A, B, C, omega):
    n = A.shape[0]
    return max(np.linalg.norm(C @ np.linalg.solve(1j * w * np.eye(n) - A, B), 2) for w in omega)


def r2(K, Kf):
    return 1.0 - np.sum((Kf - K) ** 2) / np.sum((K - K.mean()) ** 2)


def main():
    print(f"# {time.strftime('%Y-%m-%d')}, {platform.machine()}, Python {platform.python_version()}, numpy "
          f"{np.__version__}, scipy {scipy.__version__}\n")
    print("| vessel | group | per-pair states | order r | Hankel bound: any order-r model's H∞ error ≥ "
          "| truncated: worst pair R² | its gate | meets the gate |")
    print("|---|---|---|---|---|---|---|---|")
    for name, t_max in VESSELS:
        db = load_builtin(name)
        mem = radiation_memory(db, IRFSettings(t_max=t_max, dt=default_dt(db.omega[-1])))
        ss, irf = mem.state_space, mem.irf
        for group in GROUPS:
            A, B, C = group_system(ss, group)
            g = list(group)
            d = np.array([1.0 / np.sqrt(np.max(np.abs(irf.K[i, i]))) for i in g])
            Bs, Cs = B * d[None, :], C * d[:, None]
            norm = hinf(A, Bs, Cs, np.linspace(0.005, db.omega[-1], 1500))
            K_pp = impulse(A, B, C, irf.t)
            for r in (30, 45, 60, 75, 90):
                if r >= A.shape[0]:
                    continue
                Ar, Br, Cr, hsv = balanced_truncation(A, Bs, Cs, r)
                K_r = impulse(Ar, Br / d[None, :], Cr / d[:, None], irf.t)
                worst, gate = 1.0, 1.0
                for a, i in enumerate(g):
                    for b, j in enumerate(g):
                        if irf.significant[i, j]:
                            want = min(TARGET_R2, r2(irf.K[i, j], K_pp[a, b]))
                            got = r2(irf.K[i, j], K_r[a, b])
                            if got - want < worst - gate:
                                worst, gate = got, want
                names = "".join("xyzrpw"[i] for i in g)
                print(f"| {name} | {names} | {A.shape[0]} | {r} | {100 * hsv[r] / norm:.2f} % | {worst:.6f} "
                      f"| {gate:.6f} | {'yes' if worst >= gate else 'no'} |")


if __name__ == "__main__":
    main()
