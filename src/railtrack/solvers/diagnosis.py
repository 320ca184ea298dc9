"""What `railtrack.solve` says when an iteration fails: which harmonics, and what to do.

`diagnose` sorts the harmonics of a failed solve into slow ones (the
residual falls by less than 10 % a step) and diverging ones (only when the
iteration as a whole diverges), and names those that carry the largest
residual; `convergence_error` turns that into the `ConvergenceError` of
``strict=True``.  `report` raises or warns for the cell and wheel solvers,
whose failures carry their own message.
"""

from __future__ import annotations

import warnings

import numpy as np

from .fixed_point import SolverOutcome
from .solution import ConvergenceError, ConvergenceWarning, Solution, TruncationWarning

__all__ = ["diagnose", "convergence_error", "report"]


def diagnose(outcome: SolverOutcome) -> tuple[list[int], list[int], list[int]]:
    """Slow harmonics, diverging harmonics, and those carrying most of the final residual.

    A harmonic is called diverging only when the iteration as a whole
    diverges (its residual ends 10 times above its smallest); otherwise a
    harmonic whose residual fell by < 10 % per step, or rose, is slow.
    """
    history = outcome.harmonic_residuals
    last = history[-1]
    finite = np.where(np.isfinite(last), last, np.inf)
    largest = np.argsort(-finite)[:3]
    dominant = [int(n) for n in largest if finite[n] > 0]
    if len(history) < 2:
        return [], [], dominant
    steps = len(history) - 1
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        rate = (history[-1] / history[0]) ** (1.0 / steps)
    relevant = ~np.isfinite(last) | (last > 1e-3 * np.nanmax(np.where(np.isfinite(last), last, 0)))
    totals = outcome.residual_history
    whole_diverges = not np.isfinite(totals[-1]) or totals[-1] > 10 * np.nanmin(totals)
    rising = relevant & ~(rate <= 1.0)
    if whole_diverges:
        return [], np.flatnonzero(rising).tolist(), dominant
    slow = np.flatnonzero(relevant & ((rate > 0.9) | rising))
    return slow.tolist(), [], dominant


def convergence_error(method: str, outcome: SolverOutcome, solution: Solution, message: str):
    slow, growing, dominant = diagnose(outcome)
    if growing:
        advice = ("use method='newton', or split='auto'" if method == "fixed-point"
                  else "give a better initial guess")
    elif method == "fixed-point":
        advice = "raise max_iterations, try split='auto', or use method='newton'"
    else:
        advice = "raise max_iterations, give a better initial guess, or loosen tol"
    parts = [f"{method} did not converge: {message}."]
    if growing:
        parts.append(f"Diverging harmonics: {_listed(growing)}.")
    if slow:
        parts.append(f"Slow harmonics (residual falling < 10 %/step): {_listed(slow)}.")
    parts.append(f"Largest residuals at harmonics n = {dominant}.")
    parts.append(f"To fix: {advice}.")
    return ConvergenceError(" ".join(parts), solution, growing + slow or dominant)


def _listed(harmonics: list[int], shown: int = 12) -> str:
    if len(harmonics) <= shown:
        return str(harmonics)
    return f"{str(harmonics[:shown])[:-1]}, ... ({len(harmonics)} in all)]"


def report(result, strict: bool, limit: float, truncation: str, quiet: bool = False):
    """Return `result` after telling its caller what went wrong, as the caller asked.

    A result that did not converge raises `ConvergenceError` with ``strict``
    and warns `ConvergenceWarning` otherwise; a converged one whose
    ``truncation_error`` exceeds `limit` warns `TruncationWarning` with the
    text `truncation`.  ``quiet``: an unconverged result that spent the caller's
    explicit max_iterations does not warn (as `railtrack.solve` for one
    sleeper: a budget the caller set).  The warnings point at the user's call
    to `railtrack.solve`.
    """
    if not result.converged:
        if strict:
            raise ConvergenceError(result.message, result, [])
        if not quiet:
            warnings.warn(result.message, ConvergenceWarning, stacklevel=4)
    elif result.truncation_error > limit:
        warnings.warn(truncation, TruncationWarning, stacklevel=4)
    return result
