"""Whether the periodic solution `solve` returns is one a train can stay on.

Harmonic balance converges to unstable periodic solutions as readily as to
stable ones (on the fold track of chapter 10, `solve` lands on an unstable
solution at every speed from 475 to 535 m/s).  After a converged solve of a
nonlinear law, `judge_stability` looks at the Floquet multipliers
(`railtrack.solvers.floquet`):

* ``"quick"`` (the default of `solve`): the strip of one Bloch phase only,
  the disturbances that repeat every sleeper, about twice the cost of the
  solve; skipped above m = 100 harmonics, where it would cost far more.  It warns when it finds a multiplier outside the unit circle; when
  it finds none it proves nothing, since the other 29 phases of a 30-sleeper
  wagon are not looked at: its verdict is then "unknown", never "stable".
* ``"full"``: `rt.floquet` with its defaults (every disturbance that repeats
  every wagon), about twenty times the cost of the solve; the result is
  kept on the solution (`Solution.stability`).
* ``"off"``: nothing.

A linear law is not looked at: with positive damping every disturbance of
the linear track dies out.

A `CellSolution` is judged the same way with Hill's matrix of the cell
(`railtrack.solvers.cell_floquet`): "quick" looks at Bloch phase 0 per cell
alone (for a cell as long as the wagon, N = H / L, that is every disturbance
that repeats every wagon), skipped where `quick_skipped`; "full" keeps the
result on the solution (`CellSolution.stability`).
"""

from __future__ import annotations

import warnings

from ..model.foundations import LinearFoundation
from ..equations.cell_hill import cell_bloch_phases
from .cell_floquet import travelling_wave, uniform_cell
from .floquet import Floquet, floquet
from .solution import Solution

__all__ = ["UnstableSolutionWarning", "STABILITY_MODES", "judge_stability", "stability_look",
           "unstable_message", "quick_skipped", "cell_verdict"]

STABILITY_MODES = ("quick", "full", "off")
QUICK_FLOOR = 0.9
"""The quick look's smallest multiplier searched for [-]."""
QUICK_POINTS = 16
"""Its contour points (it wants only the multipliers near and outside the unit circle)."""
QUICK_HARMONICS = 100
"""Above this m the quick look (its cost grows as m^3, the solve's as m^2) is skipped."""
QUICK_CELL_SIZE = 400
"""Above N (2m+1) rows of the cell's Hill matrix (differing sleepers) the quick look is skipped."""
KINDS = {"real +": "a real positive one", "real -": "a real negative one",
         "complex": "a complex pair"}


class UnstableSolutionWarning(UserWarning):
    """The periodic solution found is unstable: a train does not stay on it."""


def stability_look(solution: Solution, mode: str) -> tuple[str, Floquet | None]:
    """The verdict of `judge_stability`'s look, without a warning: (verdict, `Floquet` or None).

    "stable" for a linear law (nothing grows on it), "unknown" where nothing
    is looked at (``mode="off"``, an unconverged solution, a quick look
    skipped) or the look cannot tell (`railtrack.Floquet.verdict`).
    """
    if mode not in STABILITY_MODES:
        raise ValueError(f"stability must be one of {STABILITY_MODES}; got {mode!r}")
    if mode == "off" or not solution.converged:
        return "unknown", None
    if hasattr(solution, "cell"):
        return cell_verdict(solution, mode)
    if isinstance(solution.foundation, LinearFoundation):
        return "stable", None
    sleepers = float(solution.passage.wagon_length / solution.passage.sleeper_spacing)
    if mode == "quick" and abs(sleepers - round(sleepers)) > 1e-9 * sleepers:
        return "unknown", None   # Hill's phases need H/L whole; "full" says so with an error
    if mode == "quick" and solution.harmonics > QUICK_HARMONICS:
        return "unknown", None   # the look would cost far more than the solve
    # The quick look searches only near and outside the unit circle, where a verdict
    # of "unstable" would lie: at low speed the box down to |mu| = 0.01 holds dozens
    # of well-damped exponents whose refinement would cost ten solves.
    result = floquet(solution) if mode == "full" else floquet(
        solution, shifts=False, min_multiplier=QUICK_FLOOR, points=QUICK_POINTS)
    return result.verdict, result


def unstable_message(solution: Solution, result: Floquet) -> str:
    """The warning's words for an unstable `solution` with multipliers `result`."""
    return (f"the periodic solution found at v = {float(solution.passage.speed):g} m/s is "
            f"unstable: a disturbance of it grows {abs(result.dominant):.3f}-fold per period "
            f"({KINDS[result.kind]} of Floquet multipliers), so a train does not stay on it")


def judge_stability(solution: Solution, mode: str, stacklevel: int = 3) -> Floquet | None:
    """Warn if `solution` is unstable; the full `Floquet` result for ``mode="full"``.

    Parameters
    ----------
    solution : Solution or CellSolution
    mode : {"quick", "full", "off"}
    stacklevel : int
        Passed to `warnings.warn`, so that the warning points at the caller of `solve`.

    Returns
    -------
    Floquet or None
        The multipliers for ``mode="full"`` on a converged nonlinear solve, else None.
    """
    verdict, result = stability_look(solution, mode)
    if verdict == "unstable":
        warnings.warn(UnstableSolutionWarning(
            unstable_message(solution, result) + ".  Other solutions may exist at "
            "this speed: rt.continuation finds them and rt.check_branch judges each; "
            "solve(..., stability='off') skips this check"), stacklevel=stacklevel)
    return result if mode == "full" else None


def quick_skipped(solution) -> bool:
    """True where the quick look of a `CellSolution` is skipped: H/L not whole, or too costly.

    A cell of identical sleepers is looked at as one sleeper (above m =
    `QUICK_HARMONICS` skipped, as for `solve`); a cell of differing sleepers
    has Hill matrices of N (2m+1) rows, and above `QUICK_CELL_SIZE` rows the
    look would cost several solves.
    """
    sleepers = float(solution.passage.wagon_length / solution.passage.sleeper_spacing)
    if abs(sleepers - round(sleepers)) > 1e-9 * sleepers:
        return True
    if uniform_cell(solution.cell) and travelling_wave(solution):
        return solution.harmonics > QUICK_HARMONICS
    return solution.sleepers * (2 * solution.harmonics + 1) > QUICK_CELL_SIZE


def cell_verdict(solution, mode: str = "quick") -> tuple[str, Floquet | None]:
    """"stable", "unstable" or "unknown" for a `CellSolution`, without a warning.

    "stable" for a cell on linear laws, or when the look covered every
    disturbance that repeats every wagon ("full", or "quick" on a cell whose
    length is a multiple of the wagon's H, one Bloch phase per cell then
    being all of them) and `railtrack.Floquet.verdict` says so; "unknown"
    where nothing is looked at (unconverged, "off", look skipped) or the
    look cannot tell.  Also the `Floquet` looked at.
    """
    if mode not in STABILITY_MODES:
        raise ValueError(f"stability must be one of {STABILITY_MODES}; got {mode!r}")
    if not solution.converged:
        return "unknown", None
    if all(isinstance(law, LinearFoundation) for law in solution.cell.foundations):
        return "stable", None
    if mode == "off" or (mode == "quick" and quick_skipped(solution)):
        return "unknown", None
    if mode == "full":
        result = floquet(solution)
    else:
        # one phase per cell is all of them when the cell holds whole wagons
        complete = cell_bloch_phases(solution.passage, solution.sleepers).size == 1
        result = floquet(solution, shifts=complete, min_multiplier=QUICK_FLOOR,
                         points=QUICK_POINTS)
    return result.verdict, result
