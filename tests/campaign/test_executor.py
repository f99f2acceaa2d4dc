"""The one executor of Monte Carlo and rare-event campaigns (boatland.campaign.executor): results whatever
runs them, shared values shipped once per call, a consumer that stops takes the workers with it. Real
worker processes (forked) and, marked slow, a real Dask scheduler and workers on loopback."""

import operator
import time

import pytest

from boatland.campaign.executor import Executor, Shared, check_scheduler_address
from boatland.errors import BoatlandInputError


@pytest.mark.parametrize("workers", [1, 2])
def test_every_task_runs_once_with_its_shared_value(workers):
    with Executor("local", workers) as ex:
        args = [(Shared(k % 3, 100 * (k % 3)), k) for k in range(12)]
        assert sorted(ex.map(operator.add, args)) == sorted(100 * (k % 3) + k for k in range(12))
        assert sorted(ex.map(len, [(Shared("v", [1, 2, 3]),), (Shared("v", [1, 2, 3]),)])) == [3, 3]
        assert list(ex.map(len, [])) == []


def _started(ex):
    """Results of 20 sleeping tasks on two workers, the first one taken, and the worker processes."""
    rows = ex.map(time.sleep, [(0.3,)] * 20)
    next(rows)                                       # the pool is up and working
    procs = list(ex._pool._processes.values())
    assert len(procs) == 2 and all(p.is_alive() for p in procs)
    return rows, procs


def _gone(pid: int) -> bool:
    """The process is gone or a zombie (killed, not yet reaped by the pool's thread)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(")")[-1].split()[0] in ("Z", "X")
    except FileNotFoundError:
        return True


def _stopped(procs, t0):
    """Every worker gone within 2.5 s (the 20 tasks queued would take 3 s)."""
    pids = [p.pid for p in procs]
    while time.perf_counter() - t0 < 2.5:
        if all(_gone(pid) for pid in pids):
            return True
        time.sleep(0.02)
    return False


def test_a_consumer_that_stops_stops_the_workers():
    """An error while results are being taken (the store's disk is full): leaving the executor's block kills
    the workers and drops what is queued; so does closing the results (what the campaign runner does)."""
    t0 = time.perf_counter()
    with pytest.raises(RuntimeError, match="disk full"):
        with Executor("local", 2) as ex:
            rows, procs = _started(ex)
            for _ in rows:
                raise RuntimeError("disk full")
    assert _stopped(procs, t0)
    ex = Executor("local", 2)
    rows, procs = _started(ex)
    t0 = time.perf_counter()
    rows.close()
    assert _stopped(procs, t0) and ex._pool is None
    ex.close()


def test_bad_executors_and_addresses_are_one_clear_error():
    with pytest.raises(BoatlandInputError, match="executor must be 'local' or 'dask'"):
        Executor("threads")
    for bad in (None, "", "127.0.0.1:8786", "http://127.0.0.1:8786", "tcp://127.0.0.1"):
        with pytest.raises(BoatlandInputError):
            check_scheduler_address(bad)
    check_scheduler_address("tcp://127.0.0.1:8786")


@pytest.mark.slow
def test_a_dask_cluster_gives_the_same_results_and_a_key_is_one_calls(dask_cluster):
    """Shared values are scattered once per key and call: a later call's value under the same key is its
    own (not the first call's), and a list is one value, not its elements."""
    with Executor("dask", scheduler=dask_cluster) as ex:
        assert sorted(ex.map(len, [(Shared("k", [1, 2, 3]),)] * 4)) == [3] * 4
        assert sorted(ex.map(len, [(Shared("k", [1, 2]),)] * 4)) == [2] * 4
        assert sorted(ex.map(operator.add, [(Shared("a", 10), k) for k in range(6)])) == list(range(10, 16))
