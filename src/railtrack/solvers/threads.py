"""One BLAS thread inside the library's hot loops of small dense solves (issue 28).

A stack of thousands of 30 x 30 solves gains nothing from a second BLAS
thread (each LAPACK call is microseconds long), and when the BLAS threads
outnumber the free cores they wait on each other: on a busy 2-core machine
one study ran ten times slower with OpenBLAS's default threads than with
one.  `blas_threads` limits BLAS (OpenBLAS, MKL, BLIS) to `limit` threads
inside a ``with`` block and restores the caller's setting after it, so a
user's default setup is not the slow one; work that scales (many draws)
is spread over processes or threads by an executor instead
(`railtrack.solvers.chunk_map`).
"""

from __future__ import annotations

from threadpoolctl import threadpool_limits

__all__ = ["blas_threads"]


def blas_threads(limit: int = 1) -> threadpool_limits:
    """A context manager: BLAS runs on at most `limit` threads inside it.

    Examples
    --------
    >>> import numpy as np
    >>> with blas_threads():
    ...     x = np.linalg.solve(np.eye(3), np.ones(3))
    >>> x.tolist()
    [1.0, 1.0, 1.0]
    """
    return threadpool_limits(limits=int(limit), user_api="blas")
