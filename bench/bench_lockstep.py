"""Trials in lock-step: what a batch layout gives the radiation memory on this CPU (issue 28, item 2).

Run: ``python bench/bench_lockstep.py``. The state-space memory is the part of a step that a batch of
trials could share instruction by instruction (the same coefficients for every trial of a case; the
contacts branch per trial). This times the kernel's own memory step — the history sums
(:func:`boatland.integrate.cummins._ss_history`) and the advance (:func:`boatland.integrate.cummins._ss_advance`),
one trial, vectorised over the states — against the same arithmetic for a batch of B trials laid out
trials-innermost (``z[state, trial]``: every coefficient loaded once and applied to B lanes, the layout a
GPU kernel would use), per trial and step, on the arrays of the ctv24 and ctv27 default scenarios' memories.
One core, best of ``ROUNDS`` round-robin rounds of ``STEPS`` steps.
"""

from __future__ import annotations

import platform
import time

import numba
import numpy as np
from numba import njit

from boatland.hydro.builtin import load_builtin
from boatland.integrate.cummins import _ss_advance, _ss_history
from boatland.irf.impulse import IRFSettings
from boatland.trial.motion import compile_motion
from boatland.vessel.radiation import default_dt, radiation_memory

STEPS = 20_000
ROUNDS = 7
BATCHES = (4, 8, 16, 32)
_U1 = np.uint64(1)


@njit(cache=True)
def one_trial(ss_E, ss_P, seg, rows, n_steps):
    """The kernel's memory step for one trial, ``n_steps`` times (velocities varied so nothing is hoisted)."""
    N = ss_E.shape[1]
    z, z_next = np.zeros(N), np.zeros(N)
    H = np.zeros((3, 6))
    v_n, v = np.full(6, 0.1), np.full(6, 0.2)
    acc = 0.0
    for n in range(n_steps):
        _ss_history(z, ss_P, rows, H)
        acc += H[1, 2]
        v[n % 6] += 1e-3
        _ss_advance(z, z_next, ss_E, seg, v_n, v)
        z, z_next = z_next, z
    return acc


@njit(cache=True)
def lock_step(ss_E, ss_P, seg, rows, n_steps, nb):
    """The same arithmetic for ``nb`` trials together, trials innermost."""
    N = ss_E.shape[1]
    z, z_next = np.zeros((N, nb)), np.zeros((N, nb))
    H = np.zeros((3, 6, nb))
    v_n, v = np.full((6, nb), 0.1), np.full((6, nb), 0.2)
    acc = 0.0
    for n in range(n_steps):
        for i in range(6):
            for c in range(3):
                for k in range(nb):
                    H[c, i, k] = 0.0
            for s in range(rows[i, 0], rows[i, 0] + rows[i, 1]):
                p0, p1, p2 = ss_P[0, s], ss_P[1, s], ss_P[2, s]
                for k in range(nb):
                    zs = z[s, k]
                    H[0, i, k] += p0 * zs
                    H[1, i, k] += p1 * zs
                    H[2, i, k] += p2 * zs
        acc += H[1, 2, 0]
        for k in range(nb):
            v[n % 6, k] += 1e-3
        for g in range(seg.shape[0]):
            j = seg[g, 2]
            for s in range(seg[g, 0], seg[g, 1]):
                e0, e1, e2, g0, g1 = ss_E[0, s], ss_E[1, s], ss_E[2, s], ss_E[3, s], ss_E[4, s]
                for k in range(nb):
                    z_next[s, k] = (((e0 * z[s, k] + e1 * z[s + 1, k]) + e2 * z[s - 1, k]) + g0 * v_n[j, k]) \
                        + g1 * v[j, k]
        z, z_next = z_next, z
    return acc


def main():
    numba.set_num_threads(1)
    print(f"# {time.strftime('%Y-%m-%d')}, {platform.machine()}, Python {platform.python_version()}, numba "
          f"{numba.__version__}, one core, best of {ROUNDS} × {STEPS:,} steps\n")
    cases = {}
    for name, t_max in (("ctv24", 40.0), ("ctv27", 120.0)):
        db = load_builtin(name)
        mem = radiation_memory(db, IRFSettings(t_max=t_max, dt=default_dt(db.omega[-1])))
        arr = compile_motion(db, mem, 0.05, method="state_space")
        cases[name] = (arr.n_states, (arr.ss_E, arr.ss_P, arr.ss_seg, arr.ss_rows))
    runs = {}
    for name, (_, a) in cases.items():
        runs[name, 1] = lambda a=a: one_trial(*a, STEPS)
        for nb in BATCHES:
            runs[name, nb] = lambda a=a, nb=nb: lock_step(*a, STEPS, nb)
    best = {k: float("inf") for k in runs}
    for f in runs.values():
        f()  # compile or load from the cache
    for _ in range(ROUNDS):
        for k, f in runs.items():
            t0 = time.perf_counter()
            f()
            best[k] = min(best[k], time.perf_counter() - t0)
    print("| vessel | memory states | layout | ns per trial and step | relative to one trial |")
    print("|---|---|---|---|---|")
    for (name, nb), t in best.items():
        per = t / STEPS / nb * 1e9
        one = best[name, 1] / STEPS * 1e9
        layout = "one trial (the kernel's)" if nb == 1 else f"lock-step, {nb} trials"
        print(f"| {name} | {cases[name][0]} | {layout} | {per:.0f} | {per / one:.2f} |")


if __name__ == "__main__":
    main()
