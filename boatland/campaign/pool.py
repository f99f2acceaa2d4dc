"""A pool of workers that lives across rounds of tasks: local processes, this process, or a Dask cluster.

An adaptive campaign (:mod:`boatland.campaign.isee`) decides its next tasks from the results of the
last ones, so it submits in rounds; starting worker processes (and loading the compiled kernels and
the campaign's databases into them) once per round would cost more than the tasks. :class:`Pool` keeps
them for the whole campaign: local workers are forked once (they die with the campaign, as those of
:func:`boatland.campaign.runner.run_campaign`), a Dask client connects once.

Results never depend on the pool: each task's inputs come only from its arguments, and the caller
orders results by their task, not by completion.
"""

from __future__ import annotations

import os

from boatland.campaign.runner import _check_scheduler_address, _worker_init
from boatland.errors import BoatlandInputError

__all__ = ["Pool"]


class Pool:
    """Workers for rounds of tasks.

    Parameters
    ----------
    executor : {"local", "dask"}
    workers : int, optional
        Local worker processes (default: all cores; 1 runs the tasks in this process).
    scheduler : str, optional
        Dask scheduler address (``tcp://host:port``) for ``executor="dask"``.
    connect_timeout : float
        Seconds to wait for the Dask scheduler.
    """

    def __init__(self, executor: str = "local", workers: int | None = None, scheduler: str | None = None,
                 connect_timeout: float = 10.0):
        if executor not in ("local", "dask"):
            raise BoatlandInputError(f"executor must be 'local' or 'dask', got {executor!r}")
        self.executor = executor
        self.n = 1 if executor == "dask" else (workers or os.cpu_count() or 1)
        self._pool = None
        self._client = None
        if executor == "dask":
            _check_scheduler_address(scheduler)
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
        """Run ``fn(*args)`` for every ``args`` of ``arglists``; yield the results as they finish (any
        order). An exception of the consumer cancels what is queued and stops local workers."""
        arglists = list(arglists)
        if not arglists:
            return
        if self.executor == "dask":
            from distributed import as_completed

            futures = self._client.map(fn, *zip(*arglists), pure=False)
            try:
                for fut in as_completed(futures, loop=self._client.loop):
                    yield fut.result()
            except BaseException:
                self._client.cancel(futures)
                raise
            return
        if self.n == 1:
            for args in arglists:
                yield fn(*args)
            return
        from concurrent.futures import as_completed

        pool = self._local()
        futures = [pool.submit(fn, *args) for args in arglists]
        try:
            for fut in as_completed(futures):
                yield fut.result()
        except BaseException:
            for fut in futures:
                fut.cancel()
            self.close(kill=True)
            raise

    def _local(self):
        if self._pool is None:
            import multiprocessing
            from concurrent.futures import ProcessPoolExecutor

            # fork where there is one: the workers inherit what the campaign prepared (compiled kernels,
            # databases, linear models) instead of making it again
            method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
            self._pool = ProcessPoolExecutor(max_workers=self.n, mp_context=multiprocessing.get_context(method),
                                             initializer=_worker_init, initargs=(os.getpid(),))
        return self._pool

    def close(self, kill: bool = False) -> None:
        """Stop the workers (``kill``: now, dropping queued tasks) or disconnect from Dask."""
        if self._pool is not None:
            procs = list(getattr(self._pool, "_processes", {}).values())
            self._pool.shutdown(wait=not kill, cancel_futures=kill)
            if kill:
                for p in procs:
                    p.kill()
                for p in procs:
                    p.join(5.0)
            self._pool = None
        if self._client is not None:
            self._client.close()
            self._client = None

    def __enter__(self) -> "Pool":
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        self.close(kill=exc_type is not None)
