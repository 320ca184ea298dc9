"""`solve`: one entry point for the three methods of the package.

* ``"newton"``: Newton's method on eq. (17) (`railtrack.solvers.newton`);
* ``"fixed-point"``: the paper's iteration, eq. (21) (`railtrack.solvers.fixed_point`);
* ``"analytic"``: eq. (23), for a `LinearFoundation` only (`railtrack.equations.linear`).

`solve` sends a ground, wheels or a cell of sleepers their own ways
(`railtrack.solvers.ground_solve`, `railtrack.solvers.wheel_auto`,
`railtrack.solvers.cell_auto`); one sleeper's solve
(`railtrack.solvers.sleeper_solve`) checks the arguments, looks the method
up in `METHODS`, runs it and packs the outcome into a `Solution`; how it
chooses m is `railtrack.solvers.auto_harmonics`.  Not converging is a result
(``converged=False``), not an exception, unless ``strict=True``.
"""

from __future__ import annotations

import numpy as np

from .auto_harmonics import (
    AUTO_ROUNDS as AUTO_ROUNDS,
    DEFAULT_ACCURACY,
    WARM_START_ABOVE as WARM_START_ABOVE,
    WARN_TRUNCATION,
)
from .guards import checked_stability
from ..model.cell import SleeperCell
from ..equations.harmonic_balance import HarmonicSystem, residual, residual_norm
from ..equations.linear import analytic_coefficients
from .fixed_point import SolverOutcome, iterate_fixed_point
from .newton import iterate_newton
from .cell_auto import solve_track_cell
from .ground_solve import solve_on_ground
from .sleeper_solve import DEFAULT_TOL as DEFAULT_TOL, solve_one_sleeper
from .wheel_auto import solve_track_wheels
from .solution import Solution
from ..model.track import Track
from ..model.train import Train
from .threads import blas_threads

__all__ = ["solve", "METHODS", "DEFAULT_ACCURACY", "WARN_TRUNCATION"]


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
        (`railtrack.solvers.foundation_at_rest.check_foundation_at_rest`).  A
        softening law whose stiffness at rest is positive passes; to solve a
        law that is deliberately unstable at rest, pass False, and check the
        answer with `railtrack.simulate_time_domain`.
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
        return solve_one_sleeper(track, train, foundation, harmonics, method, methods=METHODS,
                                 accuracy=accuracy, tol=tol, max_iterations=max_iterations,
                                 split=split, samples=samples, initial=initial, strict=strict,
                                 check_foundation=check_foundation, fallback=fallback,
                                 stability=stability)
