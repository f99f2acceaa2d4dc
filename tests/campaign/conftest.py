"""Shared fixtures of the campaign tests: a real Dask scheduler and workers on loopback."""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

DASK = str(Path(sys.executable).with_name("dask")) if Path(sys.executable).with_name("dask").exists() else "dask"


def free_port() -> int:
    """A TCP port on 127.0.0.1 that nothing listens on now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture
def dask_cluster():
    """A real ``dask scheduler`` and two single-threaded ``dask worker`` processes on 127.0.0.1; yields the
    scheduler's address and stops them all afterwards."""
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    loopback = ["--host", "127.0.0.1", "--dashboard-address", "127.0.0.1:0"]   # every listener (nanny,
    # worker, their HTTP servers, which --no-dashboard does not stop) on 127.0.0.1, none on 0.0.0.0
    # each in a session of its own: a nanny and the worker process it forks are stopped together
    start = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    procs = [subprocess.Popen([DASK, "scheduler", "--port", str(port), *loopback], **start)]
    try:
        time.sleep(2.0)
        for _ in range(2):
            procs.append(subprocess.Popen([DASK, "worker", address, "--nworkers", "1", "--nthreads", "1",
                                           *loopback, "--memory-limit", "0"], **start))
        yield address
    finally:
        for p in procs[::-1]:
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:   # a nanny that hangs in its graceful close (its scheduler gone)
                pass
            with contextlib.suppress(ProcessLookupError):
                os.killpg(p.pid, signal.SIGKILL)    # the group: nothing of the cluster is left behind
            p.wait(timeout=15)


@pytest.fixture
def unused_port() -> int:
    """A free TCP port on 127.0.0.1 (nothing listens there)."""
    return free_port()


def kill_repeatedly(campaign, store, kills: int, seed: int, total: int, *, wait: float = 120.0,
                    jitter: float = 0.05) -> list[int]:
    """Start ``boatland campaign CAMPAIGN -o STORE --workers 1`` ``kills`` times, each time SIGKILLing it
    at a random moment of its progress: once a seeded random number of its new trials — between its
    first and half of the ``total`` − done still to run — has reached the disk, plus a random [0,
    ``jitter``] s (``wait``: the longest start-up to wait for). Counted in trials rather than seconds, a
    kill lands mid-campaign however fast the machine runs it. Returns the trials on disk (store +
    journal) after each kill."""
    import signal

    import h5py
    import numpy as np

    store = Path(store)
    journal = store.with_name(store.name + ".journal")

    def on_disk():
        n = sum(1 for _ in open(journal)) if journal.exists() else 0
        if store.exists():
            with h5py.File(store, "r") as f:
                n += len(f["trials"])
        return n

    rng = np.random.default_rng(seed)
    partial = []
    for _ in range(kills):
        before = on_disk()
        target = before + int(rng.integers(1, max(1, (total - before) // 2) + 1))
        p = subprocess.Popen([sys.executable, "-m", "boatland", "campaign", str(campaign), "-o", str(store),
                              "--workers", "1"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + wait
        while on_disk() < target and p.poll() is None and time.monotonic() < deadline:
            time.sleep(0.01)                       # start-up varies; then the trials arrive
        time.sleep(float(rng.uniform(0.0, jitter)))  # then kill at a random moment
        p.send_signal(signal.SIGKILL)
        p.wait()
        partial.append(on_disk())
    return partial


@pytest.fixture
def sigkill_campaign():
    """:func:`kill_repeatedly`: a campaign CLI killed with SIGKILL at random moments, several times."""
    return kill_repeatedly
