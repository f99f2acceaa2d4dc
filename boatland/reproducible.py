"""Results that do not depend on the machine's core count: the numerical libraries pinned to one thread.

OpenBLAS (and MKL, BLIS) split large dot products, matrix–vector products, matrix products and LAPACK's
blocked factorisations over as many threads as there are cores, and the partial sums are added in a
different order with 1, 2 or 64 threads: the IRFs K(t) (a matrix product) and the state-space fit
(SVD, eigenvalues, least squares) then differ in their last bits (2e-8 relative was seen), and a
stick–slip trial amplifies such differences into different slip events. Dask workers run with one
BLAS thread, a local process with one per core, so the same campaign gave different stores.

:func:`single_threaded` pins the BLAS/LAPACK and OpenMP thread pools of the process to one thread
while a computation whose round-off reaches results runs (threadpoolctl does it for every library
it finds loaded); the previous limits are restored afterwards. It nests, and costs about a
millisecond per entry. Bits still depend on the CPU's instruction set where a library dispatches on it
(OpenBLAS kernels, numpy's SIMD transcendental functions): identical machines give identical bits.
"""

from __future__ import annotations

import contextlib
import functools
import threading
from typing import Iterator

__all__ = ["single_threaded", "pinned"]

_depth = threading.local()


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
    from threadpoolctl import threadpool_limits

    _depth.n = 1
    try:
        with threadpool_limits(limits=1):
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
