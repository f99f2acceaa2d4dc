"""Progress counter of the RK4 kernel: updated every step, readable from another thread while the kernel
runs without the GIL (for the CLI's progress bar)."""

import dataclasses
import threading

import numpy as np
import pytest

from boatland.trial.motion import MotionArrays

M, K_SPRING = 2.0e5, 8.0e5


def slow_oscillator(n_pairs=36, n_hist=4000):
    """A heave oscillator with a long artificial radiation memory on all 36 DOF pairs, so that one step
    costs tens of microseconds and a run lasts long enough to be watched (K is tiny: the motion is the
    undamped oscillator's to ~1e-9)."""
    C = np.zeros((6, 6)); C[2, 2] = K_SPRING
    base = MotionArrays.without_memory(np.eye(6) * M, C)
    pairs = np.array([(i, j) for i in range(6) for j in range(6)][:n_pairs], dtype=np.int64)
    Kh = np.full((n_pairs, 2 * n_hist + 1), 1e-6)
    return dataclasses.replace(base, Kh=Kh, pairs_i=pairs[:, 0].copy(), pairs_j=pairs[:, 1].copy(),
                               G=np.zeros((n_pairs, 3, 2)), n_hist=n_hist)  # G: the current interval left out


def test_counter_reaches_the_step_count():
    progress = np.zeros(1, dtype=np.int64)
    r = slow_oscillator(n_pairs=1, n_hist=10).run(0.05, 200, x0=[0, 0, 1.0, 0, 0, 0], progress=progress)
    assert r["status"] == 0 and progress[0] == 200


def test_counter_stops_where_a_runaway_stops():
    C = np.zeros((6, 6)); C[2, 2] = -K_SPRING  # negative restoring: exponential growth
    progress = np.zeros(1, dtype=np.int64)
    r = MotionArrays.without_memory(np.eye(6) * M, C).run(0.05, 4000, x0=[0, 0, 1.0, 0, 0, 0],
                                                          limit_trans=50.0, progress=progress)
    assert r["status"] == 2 and progress[0] == len(r["t"]) - 1 < 4000


@pytest.mark.parametrize("bad", [np.zeros(1), np.zeros(2, dtype=np.int64), [0]])
def test_counter_must_be_one_int64(bad):
    with pytest.raises(ValueError, match="progress must be"):
        MotionArrays.without_memory(np.eye(6) * M, np.eye(6)).run(0.05, 10, progress=bad)


def test_counter_advances_while_the_kernel_runs_in_a_thread():
    """The kernel runs in a worker thread; the main thread polls the counter until the worker ends. It
    sees the counter between 0 and n (possible only because the kernel releases the GIL), never going
    back, and n at the end. No timing assumptions beyond the run lasting a while (~0.3 s here)."""
    arr = slow_oscillator()
    n = 3000
    arr.run(0.05, 5, x0=[0, 0, 1.0, 0, 0, 0])  # compile or load from the cache before watching
    progress = np.zeros(1, dtype=np.int64)
    box = {}
    worker = threading.Thread(target=lambda: box.update(arr.run(0.05, n, x0=[0, 0, 1.0, 0, 0, 0],
                                                                progress=progress)))
    seen = []
    worker.start()
    while worker.is_alive():
        seen.append(int(progress[0]))
    worker.join()
    seen.append(int(progress[0]))
    assert box["status"] == 0 and seen[-1] == n
    assert seen == sorted(seen)
    assert any(0 < s < n for s in seen), "the counter was never seen mid-run: does the kernel hold the GIL?"
