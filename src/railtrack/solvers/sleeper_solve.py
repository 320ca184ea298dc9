"""`railtrack.solve` for one sleeper on a rigid ground: checks, the rounds of m, the result.

`solve_one_sleeper` is the body of `railtrack.solve` once the ground, the
wheels and the cell of sleepers have been sent their own ways: it checks
the arguments, builds the first system (`railtrack.solvers.auto_harmonics`),
runs the method (`railtrack.solvers.methods`), falls back along the speed
where Newton fails from its linear guess (`railtrack.solvers.speed_path`),
grows m while "auto" misses its accuracy, and packs the outcome into a
`Solution` with the warnings of `railtrack.solve`.  It is one frame below
`railtrack.solve`, and its warnings' stacklevels count that frame, so that
they name the caller's line.
"""

from __future__ import annotations

import dataclasses
import warnings

from ..equations.harmonic_balance import two_sided
from ..model.foundations import as_foundation
from ..model.passage import Passage
from .auto_harmonics import (
    AUTO_ROUNDS,
    WARN_TRUNCATION,
    auto_stopped,
    first_system,
    next_system,
    truncation_warning,
)
from .conditioning import check_conditioning
from .diagnosis import convergence_error
from .guards import (
    check_laws_at_rest,
    hold_to_accuracy,
    look_at_stability,
    require_scalar_fields,
)
from .methods import checked_harmonics_arguments, run_method
from .solution import ConvergenceWarning, Solution
from .speed_path import not_converged_advice, speed_path
from .truncation import estimate_of

__all__ = ["solve_one_sleeper", "DEFAULT_TOL"]

DEFAULT_TOL = 1e-10
"""The relative residual of eq. (17) below which a solve has converged, when tol is None."""


def solve_one_sleeper(track, train, foundation, harmonics, method, *, methods, accuracy, tol,
                      max_iterations, split, samples, initial, strict, check_foundation,
                      fallback, stability) -> Solution:
    """`railtrack.solve` for one sleeper: arguments as there; returns a `Solution`.

    `methods` is `railtrack.solvers.solve.METHODS`, passed in by `solve`.
    """
    fallback = True if fallback is None else fallback
    if method not in methods:
        raise ValueError(f"method must be one of {sorted(methods)}; got {method!r}")
    passage = Passage(track, train)
    require_scalar_fields(track, train)
    check_conditioning(passage)
    automatic, accuracy, tol, max_iterations = checked_harmonics_arguments(
        harmonics, method, accuracy, tol, DEFAULT_TOL, max_iterations, initial, samples, split)
    foundation = as_foundation(foundation)
    check_laws_at_rest([foundation], [float(passage.pad_stiffness)],
                       [float(passage.pad_damping)], check_foundation)

    m, target, spectrum, system, initial = first_system(
        passage, foundation, harmonics, automatic, method, accuracy, samples, initial)

    iterations, path = 0, None
    for _round in range(AUTO_ROUNDS + 1):
        outcome, used_split, note = run_method(methods, method, system, tol, max_iterations,
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
        warnings.warn(truncation_warning(passage, foundation, m, estimate), stacklevel=3)
    solution = Solution(
        passage=passage, foundation=foundation, harmonics=system.harmonics,
        coefficients=two_sided(outcome.coefficients), method=method,
        converged=outcome.converged, iterations=iterations,
        residual_history=outcome.residual_history, message=message, split=used_split,
        samples=system.samples, truncation_error=estimate)
    if strict and not solution.converged:
        raise convergence_error(method, outcome, solution, message)
    solution, short = hold_to_accuracy(solution, automatic, accuracy, strict, stacklevel=4,
                                       of="the peak sleeper displacement",
                                       stopped=auto_stopped(m))
    judged = look_at_stability(solution, stability, stacklevel=5)
    if judged is not None:
        solution = dataclasses.replace(solution, stability=judged)
    budget_spent = max_iterations is not None and outcome.iterations >= max_iterations
    if not solution.converged and not budget_spent and not short:
        # an explicit max_iterations that runs out is the caller's budget (the
        # paper's k = 100 fixed-point steps): converged=False says so, quietly
        warnings.warn(ConvergenceWarning(not_converged_advice(
            method, message, passage, system.harmonics, stalled="line search" in outcome.message
            or path is not None)), stacklevel=3)
    return solution
