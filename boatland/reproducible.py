"""Results that do not depend on the machine's core count: the numerical libraries pinned to one thread.

OpenBLAS (and MKL, BLIS) split large dot products, matrix–vector products, matrix products and LAPACK's
blocked factorisations over as many threads as there are cores, and the partial sums are added in a
different order with 1, 2 or 64 threads: the IRFs K(t) (a matrix product) and the state-space fit
(SVD, eigenvalues, least squares) then differ in their last bits (2e-8 relative was seen), and a
stick–slip trial amplifies such differences into different slip events. Dask workers run with one
BLAS thread, a local process with one per core, so the same campaign gave different stores.

:func:`single_threaded` pins the BLAS/LAPACK and OpenMP thread pools of the process to one thread
while a computation whose round-off reaches results runs (threadpoolctl does it for every library
it finds loaded); the previous limits are restored afterwards. It nests. Finding the libraries (a scan
of every shared object loaded, 1–5 ms) is done once and again only when modules have been imported
since — a new BLAS or OpenMP runtime comes with an import — so an entry costs tens of µs (a
campaign worker enters once per trial). Bits still depend on the CPU's instruction set where a library
dispatches on it (OpenBLAS kernels, numpy's SIMD transcendental functions): identical machines give
identical bits.
"""

from __future__ import annotations

import contextlib
import functools
import sys
import threading
from typing import Iterator

__all__ = ["single_threaded", "pinned"]

_depth = threading.local()
_found: list = [None, -1]   # [threadpoolctl.ThreadpoolController, len(sys.modules) when it scanned]
_found_lock = threading.Lock()


def _controller():
    """The thread pools of the loaded libraries, scanned again whenever modules were imported since."""
    with _found_lock:
        if _found[0] is None or _found[1] != len(sys.modules):
            from threadpoolctl import ThreadpoolController

            _found[0] = ThreadpoolController()
            _found[1] = len(sys.modules)            # counted after the imports above
        return _found[0]


@contextlib.contextmanager
def single_threaded() -> Iterator[None]:
    """Run the block with BLAS, LAPACK and OpenMP limited to one thread (nested uses are free)."""
    if getattr(_depth, "n", 0):
        _depth.n += 1
        try:
            yield
        finally:
            _depth.n -= 1
        return
    _depth.n = 1
    try:
        with _controller().limit(limits=1):
            yield
    finally:
        _depth.n = 0


def pinned(func):
    """Decorator: ``func`` runs inside :func:`single_threaded`."""
    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        with single_threaded():
            return func(*args, **kwargs)
    return wrapper
