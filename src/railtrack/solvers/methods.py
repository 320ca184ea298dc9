"""How `railtrack.solve` runs one of its methods for one sleeper: the fixed point's split.

`run_method` resolves N0 of eq. (21) for the system's m (None: m; "auto":
the smallest largest contraction factor) and runs the method.
"""

from __future__ import annotations

import warnings

from .arguments import require_count
from .fixed_point import automatic_split, contraction_factors
from .guards import checked_accuracy, checked_tol
from .newton import linear_guess

__all__ = ["run_method", "check_method_arguments", "checked_harmonics_arguments"]


def check_method_arguments(method, automatic, tol, max_iterations, initial, samples, split,
                           stacklevel: int = 3):
    """Warn about the arguments `method` does not use; refuse samples/initial with "auto".

    `stacklevel` is passed to `warnings.warn`: the default names the line
    that called the caller of this function.
    """
    if method == "analytic":
        ignored = [n for n, v in (("tol", tol), ("max_iterations", max_iterations),
                                  ("initial", initial)) if v is not None]
        if ignored:
            warnings.warn(f"{', '.join(ignored)} not used by method='analytic' (eq. 23 is exact)",
                          stacklevel=stacklevel)
    if automatic and (samples is not None or initial is not None):
        raise ValueError("samples and initial need an explicit harmonics=m; "
                         "'auto' chooses m itself")
    if method != "fixed-point" and split is not None:
        warnings.warn(f"split is used by method='fixed-point' only; ignored by {method!r}",
                      stacklevel=stacklevel)
    if split is not None and split != "auto":
        require_count("split (N0)", split, 0)


def run_method(methods, method, system, tol, max_iterations, split, initial):
    """Resolve the split for this m, run the method; (outcome, split used, note on the split)."""
    note, used = "", None
    if method == "fixed-point":
        if split is None:
            used = system.harmonics
        elif split == "auto":
            # Factors about Newton's starting guess, not the law at rest: for a
            # hardening law under a heavy load the two differ by orders.
            start = linear_guess(system) if initial is None else initial
            used = automatic_split(system, start)
            worst = float(contraction_factors(system, used, start).max())
            if worst >= 1:
                note = (f"no split N0 in 0..{system.harmonics} makes every contraction factor "
                        f"of eq. (21) < 1 (the best, N0 = {used}, has {worst:.3g})")
        elif split > system.harmonics:
            raise ValueError(f"split (N0) must be 'auto' or an integer in "
                             f"0..{system.harmonics}; got {split!r}")
        else:
            used = int(split)
    return methods[method](system, tol, max_iterations, used, initial), used, note


def checked_harmonics_arguments(harmonics, method, accuracy, tol, default_tol: float,
                                max_iterations, initial, samples, split, stacklevel: int = 4):
    """One sleeper's solve arguments checked as `railtrack.solve` checks them, on any support.

    The sleeper on springs (`railtrack.solvers.sleeper_solve`) and on a ground
    (`railtrack.solvers.ground_solve`) call this one function, so that both
    refuse and warn alike.  `stacklevel` names the user's line in the
    warnings (4: the user, `solve`, the path's solver, here).

    Returns
    -------
    (automatic, accuracy, tol, max_iterations)
        Whether m is "auto", and the checked values.
    """
    automatic = isinstance(harmonics, str) and harmonics == "auto"
    if not automatic:
        require_count("harmonics", harmonics, 1)
    check_method_arguments(method, automatic, tol, max_iterations, initial, samples, split,
                           stacklevel=stacklevel + 1)
    accuracy = checked_accuracy(accuracy, automatic, stacklevel=stacklevel + 1)
    tol = checked_tol(tol, default_tol)
    if max_iterations is not None:
        max_iterations = require_count("max_iterations", max_iterations, 0)
    return automatic, accuracy, tol, max_iterations
