"""Where a campaign's tasks run: this process, local worker processes, or a Dask cluster — one executor
for Monte Carlo trials (:mod:`boatland.campaign.runner`) and rare-event samples (:mod:`boatland.campaign.isee`).

:class:`Executor` keeps its workers for its whole life, so an adaptive campaign that submits in rounds
(the rare-event sampler decides its next samples from the last ones) starts them once: local workers
are forked once (with what the campaign prepared in this process: compiled kernels, databases, linear
models) and a Dask client connects once. :meth:`Executor.map` submits lazily and yields results as
they finish — also while later tasks are still being submitted, so a campaign can prepare a case's
shared data (:class:`Shared`: shipped with the task locally, scattered once to a Dask cluster) when its
first task is sent.

Local workers die with the campaign: each sets ``PR_SET_PDEATHSIG`` (Linux) and watches its parent's
pid, so neither SIGKILL nor SIGTERM of the campaign leaves workers running; a consumer that stops (an
error, e.g. a full disk, or Ctrl-C) cancels what is queued and stops the workers at once.

Results never depend on the executor: each task's inputs come only from its arguments, and callers store
results by their task, not by completion order.
"""

from __future__ import annotations

import os
import queue
import signal
import sys
import threading
import time
from typing import Any, NamedTuple

from boatland.errors import BoatlandInputError

__all__ = ["EXECUTORS", "Executor", "Shared", "check_scheduler_address"]

#: Where tasks can run.
EXECUTORS = ("local", "dask")


class Shared(NamedTuple):
    """An argument many tasks share (e.g. a case's kernel arrays and pile tables): passed as it is to local
    workers, scattered once per ``key`` and :meth:`Executor.map` call to a Dask cluster. ``value`` None is
    passed as None."""

    key: Any
    value: Any


#: How often a task lost with a Dask worker (killed, disconnected) is sent again before the campaign stops.
LOST_RETRIES = 3
#: Seconds a scatter of a shared value may take before it is tried again (a worker lost mid-transfer).
SCATTER_TIMEOUT = 60.0
_RESENT = object()


def _lost_with_worker(exc: BaseException) -> bool:
    """Whether a Dask task failed with the cluster (its worker killed or gone, its input data lost with it),
    not in its own code (a trial's own errors are rows, never exceptions)."""
    import concurrent.futures

    names = {"KilledWorker", "FutureCancelledError", "CancelledError", "CommClosedError", "StreamClosedError",
             "TimeoutError"}
    return isinstance(exc, (concurrent.futures.CancelledError, ConnectionError)) or type(exc).__name__ in names


def check_scheduler_address(scheduler: str | None) -> None:
    """A Dask scheduler address must be ``tcp://host:port`` (or tls/ws/wss/ucx).

    Raises
    ------
    BoatlandInputError
        No address, or not one (the message shows the form expected).
    """
    from urllib.parse import urlparse

    if not scheduler:
        raise BoatlandInputError("the Dask executor needs a scheduler address (--scheduler tcp://host:port)")
    try:
        u = urlparse(scheduler)
        port = u.port
    except ValueError:
        port = None
        u = None
    if u is None or u.scheme not in ("tcp", "tls", "ws", "wss", "ucx") or not u.hostname or port is None \
            or u.path not in ("", "/") or u.query or u.fragment:
        raise BoatlandInputError(f"--scheduler {scheduler}: not a scheduler address; expected "
                                 "tcp://HOST:PORT (e.g. tcp://127.0.0.1:8786)")


def _worker_init(parent: int) -> None:
    """In each local worker: die with the campaign process, however it ends (SIGKILL included)."""
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(1, int(signal.SIGKILL), 0, 0, 0)          # PR_SET_PDEATHSIG
        except (OSError, AttributeError):
            pass
    if os.getppid() != parent:        # the parent died before the line above
        os._exit(1)
    threading.Thread(target=_watch_parent, args=(parent,), name="boatland-watch-parent", daemon=True).start()


def _watch_parent(parent: int, every: float = 1.0) -> None:
    """Fallback where PR_SET_PDEATHSIG does not exist: leave when the parent process is gone."""
    while True:
        time.sleep(every)
        if os.getppid() != parent:
            os._exit(1)


def process_pool(workers: int):
    """A pool of ``workers`` local processes that die with this one (forked where the platform can: no
    re-import per worker, no ``if __name__ == "__main__"`` guard needed in a user's script, and the
    workers inherit the compiled kernels' cache state)."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    return ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context(method),
                               initializer=_worker_init, initargs=(os.getpid(),))


def kill_pool(pool) -> None:
    """Stop a :func:`process_pool` now: queued tasks dropped, its processes killed and reaped."""
    procs = list(getattr(pool, "_processes", {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        p.kill()
    for p in procs:
        p.join(5.0)


class Executor:
    """Workers for a campaign's tasks (a context manager: leaving it stops them).

    Parameters
    ----------
    executor : {"local", "dask"}
    workers : int, optional
        Local worker processes (default: all cores; 1 runs the tasks in this process).
    scheduler : str, optional
        Dask scheduler address (``tcp://host:port``) for ``executor="dask"``.
    connect_timeout : float
        Seconds to wait for the Dask scheduler.

    Raises
    ------
    BoatlandInputError
        An unknown executor, a bad scheduler address, no ``distributed``, or no scheduler answering.
    """

    def __init__(self, executor: str = "local", workers: int | None = None, scheduler: str | None = None,
                 connect_timeout: float = 10.0):
        if executor not in EXECUTORS:
            raise BoatlandInputError(f"executor must be 'local' or 'dask', got {executor!r}")
        self.executor = executor
        self.n = 1 if executor == "dask" else (workers or os.cpu_count() or 1)
        self._pool = None
        self._client = None
        self._scattered: dict = {}
        if executor == "dask":
            check_scheduler_address(scheduler)
            try:
                from distributed import Client
            except ImportError:
                raise BoatlandInputError("the Dask executor needs dask.distributed: pip install "
                                         "'dask[distributed]'") from None
            try:
                self._client = Client(scheduler, timeout=connect_timeout, set_as_default=False)
            except (OSError, TimeoutError, ValueError) as exc:
                raise BoatlandInputError(f"--scheduler {scheduler}: no Dask scheduler answered within "
                                         f"{connect_timeout:g} s ({type(exc).__name__}); is it running?") from None

    def map(self, fn, arglists):
        """Run ``fn(*args)`` for every ``args`` of ``arglists`` (an iterable, consumed as the tasks are
        submitted; :class:`Shared` arguments are shipped or scattered once per key) and yield the results
        as they finish, in any order. A consumer that stops cancels what is queued and stops local workers."""
        if self.n == 1 and self.executor == "local":
            for args in arglists:
                yield fn(*(a.value if isinstance(a, Shared) else a for a in args))
            return
        submit = self._dask_submit if self.executor == "dask" else self._local_submit
        self._scattered = {}                       # shared values are this call's (a key may mean another later)
        futures: list = []
        finished: queue.SimpleQueue = queue.SimpleQueue()
        task: dict = {}                            # future → (its arguments, times lost)

        def send(args, lost=0):
            fut = submit(fn, args)
            futures.append(fut)
            task[fut] = (args, lost)
            fut.add_done_callback(finished.put)

        def result(fut):
            """The task's result; a task lost with its Dask worker is sent again (its shared values
            scattered anew), at most LOST_RETRIES times — then the campaign stops in one line."""
            args, lost = task.pop(fut)
            try:
                return fut.result()
            except Exception as exc:  # noqa: BLE001 - only the cluster's own failures are retried
                if self.executor != "dask" or not _lost_with_worker(exc):
                    raise
                if lost >= LOST_RETRIES:
                    raise BoatlandInputError(f"the Dask cluster lost a task {lost + 1} times ({type(exc).__name__}: "
                                             f"{exc}); the finished results are kept — run the same command "
                                             "again to resume") from None
                self._scattered = {}
                send(args, lost + 1)
                return _RESENT

        pending = 0

        def collect(wait: bool):
            """The results finished so far (``wait``: all still pending), resent tasks not counted."""
            nonlocal pending
            while pending and (wait or not finished.empty()):
                out = result(finished.get())
                if out is not _RESENT:
                    pending -= 1
                    yield out

        try:
            for args in arglists:
                send(args)
                pending += 1
                yield from collect(wait=False)    # rows that finished while later tasks were being submitted
            yield from collect(wait=True)
        except BaseException:          # the consumer stopped (an error, Ctrl-C): cancel, stop the workers now
            self._cancel(futures)
            raise

    def _local_submit(self, fn, args):
        if self._pool is None:
            self._pool = process_pool(self.n)
        return self._pool.submit(fn, *(a.value if isinstance(a, Shared) else a for a in args))

    def _dask_submit(self, fn, args):
        def ship(a):
            if not isinstance(a, Shared):
                return a
            if a.key not in self._scattered:      # each shared value scattered once (a list too: as one); lost
                # with its worker, the tasks needing it fail and are sent again with it scattered anew (map)
                self._scattered[a.key] = None if a.value is None else self._scatter(a.value)
            return self._scattered[a.key]

        return self._client.submit(fn, *(ship(a) for a in args), pure=False)

    def _scatter(self, value):
        """``value`` to a Dask worker (a worker lost meanwhile — its connection closing, no answer within
        :data:`SCATTER_TIMEOUT` s — is tried again after a pause, :data:`LOST_RETRIES` times)."""
        for attempt in range(LOST_RETRIES + 1):
            try:
                return self._client.scatter([value], hash=False, timeout=SCATTER_TIMEOUT)[0]
            except Exception as exc:  # noqa: BLE001 - only the cluster's own failures are retried
                if not _lost_with_worker(exc) or attempt == LOST_RETRIES:
                    raise
                time.sleep(1.0)

    def _cancel(self, futures) -> None:
        if self._client is not None:
            self._client.cancel(futures)
        else:
            for fut in futures:
                fut.cancel()
            self.close(kill=True)

    def close(self, kill: bool = False) -> None:
        """Stop the workers (``kill``: now, dropping queued tasks) or disconnect from Dask."""
        if self._pool is not None:
            if kill:
                kill_pool(self._pool)
            else:
                self._pool.shutdown(wait=True)
            self._pool = None
        if self._client is not None:
            self._client.close()
            self._client = None

    def __enter__(self) -> "Executor":
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        self.close(kill=exc_type is not None)
