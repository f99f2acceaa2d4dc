"""Shared timer for the benchmark scripts."""

from __future__ import annotations

import time


def best_of(fn, n=5):
    """Shortest wall time [s] of ``n`` calls of ``fn`` (after one warm-up call: numba compile or
    cache load) and the last result."""
    fn()
    times, out = [], None
    for _ in range(n):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out
