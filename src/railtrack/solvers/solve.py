"""`solve`: one entry point for the three methods of the package.

* ``"newton"``: Newton's method on eq. (17) (`railtrack.solvers.newton`);
* ``"fixed-point"``: the paper's iteration, eq. (21) (`railtrack.solvers.fixed_point`);
* ``"analytic"``: eq. (23), for a `LinearFoundation` only (`railtrack.equations.linear`).

`solve` checks its arguments, looks the method up in `METHODS`, runs it and
packs the outcome into a `Solution`; how it chooses m is
`railtrack.solvers.auto_harmonics`.  Not converging is a result
(``converged=False``), not an exception, unless ``strict=True``.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np

from .arguments import require_count
from .auto_harmonics import (
    AUTO_ROUNDS,
    DEFAULT_ACCURACY,
    WARM_START_ABOVE as WARM_START_ABOVE,
    WARN_TRUNCATION as WARN_TRUNCATION,
    auto_stopped,
    first_system,
    next_system,
    truncation_warning,
)
from .diagnosis import convergence_error
from .guards import (
    check_laws_at_rest,
    checked_accuracy,
    checked_stability,
    checked_tol,
    hold_to_accuracy,
    look_at_stability,
    require_scalar_fields,
)
from ..model.cell import SleeperCell
from ..model.foundations import as_foundation
from ..equations.harmonic_balance import HarmonicSystem, residual, residual_norm, two_sided
from ..equations.linear import analytic_coefficients
from .fixed_point import SolverOutcome, iterate_fixed_point
from .methods import check_method_arguments, run_method
from .newton import iterate_newton
from .cell_auto import solve_track_cell
from .ground_solve import solve_on_ground
from .wheel_auto import solve_track_wheels
from .conditioning import check_conditioning
from .solution import ConvergenceWarning, Solution
from .speed_path import not_converged_advice, speed_path
from ..model.passage import Passage
from ..model.track import Track
from ..model.train import Train
from .threads import blas_threads
from .truncation import estimate_of

__all__ = ["solve", "METHODS", "DEFAULT_ACCURACY", "WARN_TRUNCATION"]

DEFAULT_TOL = 1e-10


ANALYTIC_ROUND_OFF = 1e-8
"""Eq. (23) counts as solved when its residual in eq. (17) is finite and below this."""


def _newton(system: HarmonicSystem, tol, max_iterations, split, initial) -> SolverOutcome:
    return iterate_newton(system, 100 if max_iterations is None else max_iterations, tol, initial)


def _fixed_point(system: HarmonicSystem, tol, max_iterations, split, initial) -> SolverOutcome:
    return iterate_fixed_point(
        system, split, 100 if max_iterations is None else max_iterations, tol, initial
    )


def _analytic(system: HarmonicSystem, tol, max_iterations, split, initial) -> SolverOutcome:
    full = analytic_coefficients(system.passage, system.foundation, system.harmonics)
    c = full[system.harmonics :]
    current = residual(system, c)
    norm = residual_norm(system, current)
    solved = bool(np.isfinite(norm) and norm <= ANALYTIC_ROUND_OFF)
    message = f"eq. (23); relative residual {norm:.1e}" + (
        "" if solved else f" is not below the round-off level {ANALYTIC_ROUND_OFF:.0e}"
    )
    return SolverOutcome(c, solved, 0, np.array([norm]), message, np.abs(current)[None, :])


METHODS = {"newton": _newton, "fixed-point": _fixed_point, "analytic": _analytic}
"""Method name -> function(system, tol, max_iterations, split, initial) -> SolverOutcome."""


def solve(
    track: Track,
    train: Train,
    foundation,
    harmonics: int | str = "auto",
    method: str = "newton",
    *,
    accuracy: float | None = None,
    tol: float | None = None,
    max_iterations: int | None = None,
    split: int | str | None = None,
    samples: int | None = None,
    initial: np.ndarray | None = None,
    strict: bool = False,
    check_foundation: bool = True,
    fallback: bool | None = None,
    stability: str = "quick",
    wheel=None,
    profile=None,
    ground=None,
) -> Solution:
    """Periodic response of a sleeper on a (nonlinear) foundation, eqs. (12)–(23).

    Parameters
    ----------
    track : Track
        Rail, pads and sleepers, e.g. ``Track.paper()``; scalar fields only.
    train : Train
        Wagon length, axles and speed, e.g. ``Train.paper()``; scalar speed.
    foundation : foundation object, callable or SleeperCell
        `LinearFoundation`, `BilinearFoundation`, `CubicFoundation`, or any
        callable ``f(w, v)`` returning the foundation force [N] as an array
        shaped like w.  A `SleeperCell` (sleepers that differ, repeating
        every N) is solved by `railtrack.solvers.cell_auto` and returns a
        `CellSolution`; its sleepers' masses and pads replace the track's.
    harmonics : int or "auto"
        m, the number of harmonics kept (eq. 19).  "auto" (default) picks
        the smallest m whose estimated truncation error is below `accuracy`
        (`railtrack.solvers.truncation`); the paper uses m = 15.  Two rules:
        "auto" promises `accuracy`, and where it stops short (m at its cap,
        or its rounds spent) the result has ``converged=False``, its fields
        kept, and a message saying m and the estimate (a `ConvergenceWarning`,
        or `ConvergenceError` with ``strict``).  With an explicit m,
        ``converged`` refers to the equations at that m, and an estimated
        error above 1 % warns with a `TruncationWarning`.
    method : {"newton", "fixed-point", "analytic"}
    accuracy : float, optional
        For ``harmonics="auto"``: the largest estimated truncation error of
        the sleeper displacement, max norm over the period relative to its
        peak, 0 < accuracy < 1 (default 1e-3).
    tol : float, optional
        Converged when the relative residual ``||R|| / ||F||`` of eq. (17)
        is <= tol, 0 < tol <= 1e-2 (default 1e-10; a looser tol would pass
        the starting point, `railtrack.solvers.guards.LARGEST_TOL`).  Not used
        by "analytic", which is exact up to round-off.
    max_iterations : int, optional
        Newton steps (default 100) or fixed-point iterations k (default 100,
        the paper's choice); 0 evaluates the starting point only.
    split : int or "auto", optional
        N0 of eq. (21), fixed point only.  Default (None): m, all harmonics
        in the first branch of eq. (21).  "auto": the N0 with the smallest
        largest contraction factor (`railtrack.solvers.fixed_point.automatic_split`).
    samples : int, optional
        AFT samples per period, > 4m (default
        `railtrack.equations.harmonic_balance.default_samples`); needs an explicit m.
    initial : ndarray, shape (m+1,), optional
        Starting c_0..c_m for the iterative methods (finite, c_0 real); needs
        an explicit m.
    strict : bool
        Raise `ConvergenceError` instead of returning an unconverged solution,
        which otherwise warns with a `ConvergenceWarning` (except when it
        used all of an explicit `max_iterations`: a budget the caller set).
    check_foundation : bool
        Refuse a law with negative stiffness or damping at rest
        (`railtrack.model.foundations.check_foundation_at_rest`).  A softening law
        whose stiffness at rest is positive passes; to solve a law that is
        deliberately unstable at rest, pass False, and check the answer with
        `railtrack.simulate_time_domain`.
    fallback : bool, optional
        One sleeper only (default True; a `SleeperCell` or wheels refuse it).
        Where Newton fails from its linear guess (no `initial` given), follow
        the branch of solutions in speed up from half the speed
        (`railtrack.solvers.speed_path`) and land on this speed; the message
        says so.  Where several solutions exist this finds one of them:
        `railtrack.continuation` lists them all.  False: give up at once.
    wheel : Wheel or Vehicle, optional
        Put a wheel of this unsprung mass on a Hertz spring under every axle
        (`railtrack.Wheel`), or a whole `railtrack.Vehicle` above the wheels:
        one wheel per wheelset on the modelled rail, the four of a wagon
        coupled through bogies and body (the train must be
        ``vehicle.train(H, v)``; the same residual with the wheels' receptance
        generalised, so every check of the wheel path applies: one entry point,
        as a `Wheel` is a vehicle with an infinitely heavy body on an
        infinitely soft primary).  Returns a `WheelSolution`
        (`railtrack.solvers.wheel_auto`): contact forces, wheel and sleeper
        histories.  Newton only; `accuracy`, `tol`, `max_iterations`,
        `samples`, `check_foundation` and `strict` apply, `initial`, `split` and
        `fallback` are refused; the quick stability look is not done for
        wheels, and "full" is refused (`railtrack.simulate_time_domain` with
        ``wheel=`` is the check).  With a profile, ``harmonics="auto"`` reads
        m off the contact force's spectrum (`railtrack.solvers.wheel_rounds`).
    profile : callable, optional
        The rail-top profile r(x) [m] under the wheels (default: smooth;
        `railtrack.CosineDip` for a dipped weld); it must repeat with the
        cell of sleepers.  A `period` of n > 1 wagon lengths makes the steady
        state n wagons long: the result's passage is ``train.tiled(n)``.
    ground : GroundCompliance, optional
        The law between each sleeper and this ground, which couples them all
        (`railtrack.model.ground_protocol`); a `GroundSolution`
        (`railtrack.solvers.ground_solve`).
    stability : {"quick", "full", "off"}
        After a converged solve of a nonlinear law, look at its Floquet
        multipliers (`railtrack.solvers.stability_hint`): "quick" warns
        (`UnstableSolutionWarning`) when the disturbances that repeat every
        sleeper show it unstable, at about twice the cost of the solve, and
        proves nothing when they do not; "full" runs `railtrack.floquet` and
        keeps its result as ``Solution.stability``.

    Returns
    -------
    Solution
        With ``converged`` and ``truncation_error``.  A diverging iteration,
        or "auto" short of `accuracy`, is ``converged=False``, the message says which.

    Raises
    ------
    ValueError
        Unknown method, bad harmonics, accuracy, samples, tol, split or
        initial, a law that is unstable at rest, or one that returns
        non-finite forces at the start.
    TypeError
        A track that is not a `Track`, or a foundation that is not a law.
    ConvergenceError
        Only with ``strict=True``.

    Examples
    --------
    >>> from railtrack import Track, Train, CubicFoundation, solve
    >>> solution = solve(Track.paper(), Train.paper(), CubicFoundation.paper(epsilon=0.8))
    >>> solution.converged, solution.truncation_error < 1e-3
    (True, True)
    >>> w = solution.sleeper_displacement([0.0, 0.1])    # metres, w < 0 is down
    """
    with blas_threads(1):
        stability = checked_stability(stability)
        if ground is not None:
            return solve_on_ground(
                track, train, foundation, ground, harmonics, method, methods=METHODS,
                accuracy=accuracy, tol=tol, max_iterations=max_iterations, split=split,
                samples=samples, initial=initial, strict=strict, check_foundation=check_foundation,
                fallback=fallback, stability=stability, wheel=wheel, profile=profile,
                cell=isinstance(foundation, SleeperCell))
        if wheel is not None:
            return solve_track_wheels(track, train, foundation, wheel, profile, harmonics, method,
                                      accuracy=accuracy, tol=tol, max_iterations=max_iterations,
                                      split=split, samples=samples, initial=initial, strict=strict,
                                      check_foundation=check_foundation, fallback=fallback,
                                      stability=stability)
        if profile is not None:
            raise ValueError("a profile is felt through wheels: pass wheel=railtrack.Wheel(...)")
        if isinstance(foundation, SleeperCell):
            return solve_track_cell(track, train, foundation, harmonics, method, accuracy=accuracy,
                                    tol=tol, max_iterations=max_iterations, samples=samples,
                                    initial=initial, strict=strict, stability=stability,
                                    check_foundation=check_foundation, split=split,
                                    fallback=fallback)
        fallback = True if fallback is None else fallback
        if method not in METHODS:
            raise ValueError(f"method must be one of {sorted(METHODS)}; got {method!r}")
        passage = Passage(track, train)
        require_scalar_fields(track, train)
        check_conditioning(passage)
        automatic = isinstance(harmonics, str) and harmonics == "auto"
        if not automatic:
            require_count("harmonics", harmonics, 1)
        check_method_arguments(method, automatic, tol, max_iterations, initial, samples, split)
        accuracy = checked_accuracy(accuracy, automatic)
        tol = checked_tol(tol, DEFAULT_TOL)
        if max_iterations is not None:
            max_iterations = require_count("max_iterations", max_iterations, 0)
        foundation = as_foundation(foundation)
        check_laws_at_rest([foundation], [float(passage.pad_stiffness)],
                           [float(passage.pad_damping)], check_foundation)

        m, target, spectrum, system, initial = first_system(
            passage, foundation, harmonics, automatic, method, accuracy, samples, initial)

        iterations, path = 0, None
        for _round in range(AUTO_ROUNDS + 1):
            outcome, used_split, note = run_method(METHODS, method, system, tol, max_iterations,
                                                   split, initial)
            iterations += outcome.iterations
            if (fallback and method == "newton" and not outcome.converged and initial is None
                    and max_iterations is None and path is None):
                path = speed_path(system, tol, 100)
                if path.outcome is not None:
                    outcome = path.outcome._replace(message=f"{path.outcome.message}; "
                                                    f"{path.describe(float(passage.speed))}")
                    iterations += outcome.iterations
            estimate, tail = estimate_of(system, outcome.coefficients, spectrum)
            if not automatic or not outcome.converged or tail is None:
                break
            grown = next_system(passage, foundation, method, m, target, estimate, accuracy,
                                outcome.coefficients, tail, spectrum)
            if grown is None or _round == AUTO_ROUNDS:   # the last round's m is the one solved
                break
            m, spectrum, system, initial = grown
            target = m

        message = outcome.message + (f"; {note}" if note and not outcome.converged else "")
        if path is not None and path.outcome is None:
            message += f"; {path.describe(float(passage.speed))}"
        if automatic:
            message += (f"; harmonics='auto' chose m = {m} ({iterations} steps in all, "
                        f"estimated truncation error {estimate:.1e})")
        if not automatic and outcome.converged and estimate > WARN_TRUNCATION:
            warnings.warn(truncation_warning(passage, foundation, m, estimate), stacklevel=2)
        solution = Solution(
            passage=passage, foundation=foundation, harmonics=system.harmonics,
            coefficients=two_sided(outcome.coefficients), method=method,
            converged=outcome.converged, iterations=iterations,
            residual_history=outcome.residual_history, message=message, split=used_split,
            samples=system.samples, truncation_error=estimate)
        if strict and not solution.converged:
            raise convergence_error(method, outcome, solution, message)
        solution, short = hold_to_accuracy(solution, automatic, accuracy, strict, stacklevel=3,
                                           of="the peak sleeper displacement",
                                           stopped=auto_stopped(m))
        judged = look_at_stability(solution, stability, stacklevel=4)
        if judged is not None:
            solution = dataclasses.replace(solution, stability=judged)
        budget_spent = max_iterations is not None and outcome.iterations >= max_iterations
        if not solution.converged and not budget_spent and not short:
            # an explicit max_iterations that runs out is the caller's budget (the
            # paper's k = 100 fixed-point steps): converged=False says so, quietly
            warnings.warn(ConvergenceWarning(not_converged_advice(
                method, message, passage, system.harmonics, stalled="line search" in outcome.message
                or path is not None)), stacklevel=2)
        return solution
