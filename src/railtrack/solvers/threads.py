"""One BLAS thread inside the library's hot loops of small dense solves (issue 28).

A stack of thousands of 30 x 30 solves gains nothing from a second BLAS
thread (each LAPACK call is microseconds long), and when the BLAS threads
outnumber the free cores they wait on each other: on a busy 2-core machine
one study ran ten times slower with OpenBLAS's default threads than with
one, and a cell of 30 sleepers, the dipped weld with wheels and a cell of 100
took 1.3 s, 4.2 s and 2.3 s on the default two threads against 0.33 s, 1.0 s
and 1.0 s on one (issue 28).  `blas_threads` limits BLAS (OpenBLAS, MKL,
BLIS) to `limit` threads inside a ``with`` block and restores the caller's
setting after it, so a user's default setup is not the slow one; work that
scales (many draws) is spread over processes or threads by an executor
instead (`railtrack.solvers.chunk_map`).  The public entry points
(`railtrack.solve`, `railtrack.floquet`, `railtrack.check_branch`,
`railtrack.continuation`, the ring and the speed ramp) run their bodies
under it; a ``with`` in the body, not a decorator, so that their warnings
still name the caller's line (a wrapper would add a frame to every
``stacklevel``).

threadpoolctl's ``threadpool_limits`` scans the loaded libraries at every
call (about 1 ms, as long as the paper's whole solve); one controller, made
at first use, switches them in about 10 microseconds.
"""

from __future__ import annotations

from threadpoolctl import ThreadpoolController

__all__ = ["blas_threads"]

_CONTROLLER: list[ThreadpoolController] = []


def _controller() -> ThreadpoolController:
    # made once numpy and scipy have loaded their BLAS, i.e. at the first solve
    if not _CONTROLLER:
        _CONTROLLER.append(ThreadpoolController())
    return _CONTROLLER[0]


def blas_threads(limit: int = 1):
    """A context manager: BLAS runs on at most `limit` threads inside it.

    Examples
    --------
    >>> import numpy as np
    >>> with blas_threads():
    ...     x = np.linalg.solve(np.eye(3), np.ones(3))
    >>> x.tolist()
    [1.0, 1.0, 1.0]
    """
    return _controller().limit(limits=int(limit), user_api="blas")

