"""`solve`: one entry point for the three methods of the package.

* ``"newton"``: Newton's method on eq. (17) (`railtrack.newton`);
* ``"fixed-point"``: the paper's iteration, eq. (21) (`railtrack.fixed_point`);
* ``"analytic"``: eq. (23), for a `LinearFoundation` only (`railtrack.linear`).

`solve` checks its arguments, looks the method up in `METHODS`, runs it and
packs the outcome into a `Solution`.  Not converging is a result
(``converged=False``), not an exception, unless ``strict=True``.
"""

from __future__ import annotations

import warnings

import numpy as np

from .fixed_point import SolverOutcome, automatic_split, iterate_fixed_point
from .foundations import as_foundation
from .harmonic_balance import HarmonicSystem, harmonic_system, residual, residual_norm, two_sided
from .linear import analytic_coefficients
from .newton import iterate_newton
from .solution import ConvergenceError, Solution
from .track import Track

__all__ = ["solve", "METHODS"]


def _newton(system: HarmonicSystem, tol, max_iterations, split, initial) -> SolverOutcome:
    return iterate_newton(system, max_iterations or 50, tol, initial)


def _fixed_point(system: HarmonicSystem, tol, max_iterations, split, initial) -> SolverOutcome:
    return iterate_fixed_point(system, split, max_iterations or 100, tol, initial)


def _analytic(system: HarmonicSystem, tol, max_iterations, split, initial) -> SolverOutcome:
    full = analytic_coefficients(system.track, system.foundation, system.harmonics)
    c = full[system.harmonics :]
    current = residual(system, c)
    norm = residual_norm(system, current)
    return SolverOutcome(
        c, True, 0, np.array([norm]), f"eq. (23); relative residual {norm:.1e}",
        np.abs(current)[None, :],
    )


METHODS = {"newton": _newton, "fixed-point": _fixed_point, "analytic": _analytic}
"""Method name -> function(system, tol, max_iterations, split, initial) -> SolverOutcome."""


def _slow_harmonics(outcome: SolverOutcome) -> tuple[list[int], list[int]]:
    """Harmonics whose residual fell by < 10 % per step over the last steps, and those that grew."""
    history = outcome.harmonic_residuals
    if len(history) < 2:
        return [], []
    steps = len(history) - 1
    with np.errstate(divide="ignore", invalid="ignore"):
        rate = (history[-1] / history[0]) ** (1.0 / steps)
    relevant = history[-1] > 1e-3 * history[-1].max()
    slow = np.flatnonzero(relevant & (rate > 0.9) & (rate <= 1.0))
    growing = np.flatnonzero(relevant & ~(rate <= 1.0))
    return slow.tolist(), growing.tolist()


def solve(
    track: Track,
    foundation,
    harmonics: int = 15,
    method: str = "newton",
    *,
    tol: float = 1e-10,
    max_iterations: int | None = None,
    split: int | str | None = None,
    samples: int | None = None,
    initial: np.ndarray | None = None,
    strict: bool = False,
) -> Solution:
    """Periodic response of a sleeper on a (nonlinear) foundation, eqs. (12)–(23).

    Parameters
    ----------
    track : Track
        Track and train, e.g. ``Track.paper()``.
    foundation : foundation object or callable
        `LinearFoundation`, `BilinearFoundation`, `CubicFoundation`, or any
        callable ``f(w, v)`` returning the foundation force [N].
    harmonics : int
        m, the number of harmonics kept (eq. 19); the paper uses 15.
    method : {"newton", "fixed-point", "analytic"}
    tol : float
        Converged when the relative residual ``||R|| / ||F||`` of eq. (17)
        is <= tol.  Ignored by "analytic".
    max_iterations : int, optional
        Newton steps (default 50) or fixed-point iterations k (default 100,
        the paper's choice).
    split : int or "auto", optional
        N0 of eq. (21), fixed point only.  Default (None): m, all harmonics
        in the first branch of eq. (21).  "auto": the N0 with the smallest
        largest contraction factor (`railtrack.fixed_point.automatic_split`).
    samples : int, optional
        AFT samples per period (default `railtrack.harmonic_balance.default_samples`).
    initial : ndarray, shape (m+1,), optional
        Starting c_0..c_m for the iterative methods.
    strict : bool
        Raise `ConvergenceError` instead of returning an unconverged solution.

    Returns
    -------
    Solution

    Raises
    ------
    ValueError
        Unknown method, bad harmonics, samples, tol or split, or a foundation
        law that returns non-finite forces.
    ConvergenceError
        Only with ``strict=True``.

    Examples
    --------
    >>> from railtrack import Track, CubicFoundation, solve
    >>> solution = solve(Track.paper(), CubicFoundation.paper(epsilon=0.8))
    >>> solution.converged
    True
    >>> w = solution.sleeper_displacement([0.0, 0.1])    # metres, w < 0 is down
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {sorted(METHODS)}; got {method!r}")
    if not np.isfinite(tol) or tol < 0:
        raise ValueError(f"tol must be a finite number >= 0; got {tol!r}")
    if max_iterations is not None and (
        isinstance(max_iterations, bool) or not isinstance(max_iterations, (int, np.integer))
        or max_iterations < 0
    ):
        raise ValueError(f"max_iterations must be an integer >= 0; got {max_iterations!r}")
    foundation = as_foundation(foundation)
    system = harmonic_system(track, foundation, harmonics, samples)
    if method != "fixed-point" and split is not None:
        warnings.warn(f"split is used by method='fixed-point' only; ignored by {method!r}")
    if split is None:
        split = system.harmonics
    elif split == "auto":
        split = automatic_split(system)
    elif isinstance(split, bool) or not isinstance(split, (int, np.integer)) or not 0 <= split <= harmonics:
        raise ValueError(f"split (N0) must be 'auto' or an integer in 0..{harmonics}; got {split!r}")
    if initial is not None and np.shape(initial) != (system.harmonics + 1,):
        raise ValueError(
            f"initial must have shape ({system.harmonics + 1},) (c_0..c_m); got {np.shape(initial)}"
        )

    outcome = METHODS[method](system, tol, max_iterations, split, initial)
    solution = Solution(
        track=track,
        foundation=foundation,
        harmonics=system.harmonics,
        coefficients=two_sided(outcome.coefficients),
        method=method,
        converged=outcome.converged,
        iterations=outcome.iterations,
        residual_history=outcome.residual_history,
        message=outcome.message,
        split=int(split) if method == "fixed-point" else None,
        samples=system.samples,
    )
    if strict and not solution.converged:
        slow, growing = _slow_harmonics(outcome)
        advice = (
            "raise max_iterations, try split='auto', or use method='newton'"
            if method == "fixed-point"
            else "raise max_iterations, give a better initial guess, or raise tol"
        )
        raise ConvergenceError(
            f"{method} did not converge: {outcome.message}. "
            f"Slow harmonics (residual falling < 10 %/step): {slow or 'none'}; "
            f"diverging harmonics: {growing or 'none'}. To fix: {advice}.",
            solution,
            slow + growing,
        )
    return solution
