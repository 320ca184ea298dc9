"""The stability of every member of a sweep, judged as `railtrack.solve` judges one solution.

``sweep(..., stability="quick")`` (the default, as for `railtrack.solve`)
gives each converged member of a nonlinear law the quick look of
`railtrack.solvers.stability_hint`: it finds the members that are unstable,
and marks the others "unknown" (it looks at one Bloch phase only, so it
never proves stability).  ``stability="full"`` (or True) judges each by its
Floquet multipliers from Hill's method (`railtrack.floquet` with its
defaults: the disturbances that repeat every wagon, which a ring one wagon
long carries), at the sweep's m.  A linear law is stable.  A member that
did not converge has no periodic solution to judge: its verdict is unknown
(None), not unstable, and its multiplier NaN.  Hill's method needs a whole
number of sleepers per wagon, H / L an integer, which ``"full"`` checks for
every member before anything is solved; the quick look skips such members.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..equations.hill import bloch_phases
from ..model.passage import Passage
from ..solvers.batch import member
from ..solvers.stability_hint import (STABILITY_MODES, UnstableSolutionWarning,
                                      stability_look, unstable_message)

__all__ = ["require_whole_sleepers", "member_stability", "stability_mode"]


def require_whole_sleepers(passage: Passage, size: int, values: dict) -> None:
    """Refuse stability="full" where a member's H / L is not an integer (Hill's method needs it).

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


def stability_mode(stability) -> str:
    """``sweep``'s stability argument as a mode of `railtrack.solve`: True is "full", False "off"."""
    if isinstance(stability, (bool, np.bool_)):
        return "full" if stability else "off"
    if isinstance(stability, str) and stability in STABILITY_MODES:
        return stability
    raise TypeError(f"stability must be one of {STABILITY_MODES} (or True for 'full', False for "
                    f"'off'); got {stability!r}")


def member_stability(result, values: dict, mode: str = "full",
                     stacklevel: int = 4) -> tuple[np.ndarray, np.ndarray]:
    """Verdicts and dominant Floquet multipliers of a `Sweep`'s members; one warning if unstable.

    Each member is judged as `railtrack.solve` judges its solution
    (`railtrack.solvers.stability_hint.stability_look`, the same code).

    Parameters
    ----------
    result : Sweep
    values : dict of str to array_like
        The swept values, to name a member in an error or the warning.
    mode : {"quick", "full"}
        As `railtrack.solve`'s ``stability``.

    Returns
    -------
    stable : ndarray of object, shape (B,)
        True (verdict "stable"), False ("unstable") or None ("unknown": the
        member did not converge, or its look could have missed a multiplier
        outside the unit circle; a quick look never proves stability).
    dominant : ndarray of complex, shape (B,)
        The dominant multiplier mu per period H / v (`railtrack.Floquet.dominant`)
        [-] where the verdict is "stable" or "unstable" from a Floquet search,
        NaN elsewhere.

    Warns
    -----
    UnstableSolutionWarning
        Once, naming how many members are unstable and the first of them.
    """
    size = len(result)
    stable = np.full(size, None, dtype=object)
    dominant = np.full(size, np.nan + 0j, dtype=complex)
    unstable = []
    for i in np.flatnonzero(result.converged):
        solution = result.solution(int(i))
        try:
            verdict, found = stability_look(solution, mode)
        except (ValueError, np.linalg.LinAlgError) as error:
            raise type(error)(f"member {i} ({_named(values, i)}) of the sweep: its Floquet "
                              f"multipliers failed: {error}") from error
        stable[i] = {"stable": True, "unstable": False}.get(verdict)
        if found is not None and verdict != "unknown":
            dominant[i] = found.dominant
        if verdict == "unstable":
            unstable.append((int(i), solution, found))
    if unstable:
        i, solution, found = unstable[0]
        warnings.warn(UnstableSolutionWarning(
            f"{len(unstable)} of {size} members of the sweep are unstable (Sweep.stable is False "
            f"there); the first, member {i} ({_named(values, i)}): "
            + unstable_message(solution, found) + ".  rt.continuation and rt.check_branch find "
            "and judge the other solutions at those values"), stacklevel=stacklevel)
    return stable, dominant


def _named(values: dict, i: int) -> str:
    return ", ".join(f"{k} = {float(np.ravel(v)[i])!r}" for k, v in values.items())
