"""How a solve says it fell short: `ConvergenceError`, `ConvergenceWarning`, `TruncationWarning`.

Kept apart from `railtrack.solvers.solution` (which imports them again, so
``from railtrack.solvers.solution import ConvergenceWarning`` still works)
to keep that module short.
"""

from __future__ import annotations

from typing import Any

__all__ = ["ConvergenceError", "ConvergenceWarning", "TruncationWarning"]


class ConvergenceError(RuntimeError):
    """Raised by ``solve(..., strict=True)`` when the iteration did not converge.

    Or when ``harmonics="auto"`` fell short of its accuracy (the equations
    solved at an m whose estimated truncation error misses it): then
    ``slow_harmonics`` is empty and the solution's ``truncation_error`` says by how much.

    Attributes
    ----------
    solution : Solution
        The unconverged result.
    slow_harmonics : list of int
        Harmonics whose residual shrank by less than 10 % per step, or grew.
    """

    def __init__(self, message: str, solution: Any, slow_harmonics: list[int]):
        super().__init__(message)
        self.solution = solution
        self.slow_harmonics = slow_harmonics


class ConvergenceWarning(UserWarning):
    """A solve returned ``converged=False``: its answer is not the one asked for.

    Either the iteration did not solve eq. (17), or ``harmonics="auto"``
    solved it at an m whose estimated truncation error misses `accuracy`
    (the message names m and the estimate; no `TruncationWarning` besides).

    Issued by `railtrack.solve` (and the studies built on it) unless
    ``strict=True``, which raises `ConvergenceError` instead.  The message
    says why the iteration stopped and what to try; where Newton stalls as
    it does near a fold of the response curve, it names `railtrack.continuation`.
    Silence it with ``warnings.simplefilter("ignore", rt.ConvergenceWarning)``.
    """


class TruncationWarning(UserWarning):
    """An explicit number of harmonics m leaves an estimated truncation error above 1 %.

    The message names m, the estimate and the fix (``harmonics="auto"`` or a
    larger m).  See `railtrack.solvers.truncation`.
    """
