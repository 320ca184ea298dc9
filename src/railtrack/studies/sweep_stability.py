"""The Floquet verdict of every converged member of a sweep (``sweep(..., stability=True)``).

Each converged member is judged by its Floquet multipliers from Hill's
method (`railtrack.floquet` with its defaults: the disturbances that repeat
every wagon, which a ring one wagon long carries), at the sweep's m.  A
member that did not converge has no periodic solution to judge: it is
marked not stable and its multiplier NaN.  Hill's method needs a whole
number of sleepers per wagon, H / L an integer, which is checked for every
member before anything is solved.
"""

from __future__ import annotations

import numpy as np

from ..equations.hill import bloch_phases
from ..model.passage import Passage
from ..solvers.batch import member
from ..solvers.floquet import floquet

__all__ = ["require_whole_sleepers", "member_stability"]


def require_whole_sleepers(passage: Passage, size: int, values: dict) -> None:
    """Refuse stability=True where a member's H / L is not an integer (Hill's method needs it).

    Raises
    ------
    ValueError
        Naming the first such member, its swept values and its H / L.
    """
    ratio = np.broadcast_to(np.asarray(passage.wagon_length / passage.sleeper_spacing, dtype=float),
                            (size, 1))[:, 0]
    count = np.round(ratio)
    bad = np.flatnonzero((count < 1) | ~(np.abs(ratio - count) <= 1e-9 * np.maximum(1.0, ratio)))
    if len(bad):
        i = int(bad[0])
        named = ", ".join(f"{k} = {float(np.ravel(v)[i])!r}" for k, v in values.items())
        others = f" (and {len(bad) - 1} other member(s))" if len(bad) > 1 else ""
        try:
            bloch_phases(Passage(member(passage.track, i), member(passage.train, i)))
        except ValueError as error:
            raise ValueError(f"stability=True: member {i} ({named}) of the sweep{others}: "
                             f"{error}; sweep with stability=False, or with a wagon length "
                             "that is a whole number of sleeper spacings") from None


def member_stability(result, values: dict) -> tuple[np.ndarray, np.ndarray]:
    """Stable flags and dominant Floquet multipliers of a `Sweep`'s members.

    Parameters
    ----------
    result : Sweep
    values : dict of str to array_like
        The swept values, to name a member in an error.

    Returns
    -------
    stable : ndarray of bool, shape (B,)
        True where the member converged and every resolved multiplier has
        |mu| < 1; False where it is unstable or did not converge.
    dominant : ndarray of complex, shape (B,)
        The dominant multiplier mu per period H / v (`railtrack.Floquet.dominant`)
        [-], NaN where the member did not converge.
    """
    size = len(result)
    stable = np.zeros(size, dtype=bool)
    dominant = np.full(size, np.nan + 0j, dtype=complex)
    for i in np.flatnonzero(result.converged):
        try:
            verdict = floquet(result.solution(int(i)))
        except (ValueError, np.linalg.LinAlgError) as error:
            named = ", ".join(f"{k} = {float(np.ravel(v)[i])!r}" for k, v in values.items())
            raise type(error)(f"member {i} ({named}) of the sweep: its Floquet multipliers "
                              f"failed: {error}") from error
        stable[i], dominant[i] = verdict.stable, verdict.dominant
    return stable, dominant
