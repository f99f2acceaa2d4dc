"""Shared timer for the benchmark scripts."""

from __future__ import annotations

import platform
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


def cpu_name() -> str:
    """The CPU model (for the figures' machine line)."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()
