"""What every path of `railtrack.solve` decides alike (issue 27).

`railtrack.solve` has three paths: one sleeper (`railtrack.solvers.sleeper_solve`),
a `SleeperCell` (`railtrack.solvers.cell_auto.solve_track_cell`) and wheels
(`railtrack.solvers.wheel_auto.solve_track_wheels`).  Each calls this module
for what must not differ between them:

* the foundation laws at rest (`check_laws_at_rest`): a law with negative
  stiffness or damping at rest is refused unless ``check_foundation=False``;
* tol and accuracy (`checked_tol`, `checked_accuracy`): real, finite,
  0 < x < 1, and tol at most `LARGEST_TOL`;
* the arguments a path does not use (`refuse_unused`): refused with the
  reason, never ignored;
* the truncation warning's threshold (`truncation_limit`);
* harmonics="auto" held to its accuracy (`hold_to_accuracy`): a level whose
  estimated truncation error misses the accuracy (or has none) is a failure,
  ``converged=False``, not a converged answer with a warning;
* the quick stability look after a converged solve (`look_at_stability`);
* how many failed levels harmonics="auto" steps past (`FAILED_LEVELS`);
* a converged result no track survives (`warn_if_displaced`): a displacement
  above `LARGEST_DISPLACEMENT`, which says the inputs are probably off.
"""

from __future__ import annotations

import dataclasses
import reprlib
import warnings

import numpy as np

from ..model.plausibility_check import warn_implausible
from .arguments import require_fraction
from .auto_harmonics import DEFAULT_ACCURACY, WARN_TRUNCATION
from .convergence import ConvergenceError, ConvergenceWarning
from .foundation_at_rest import check_foundation_at_rest
from .stability_hint import STABILITY_MODES, judge_stability

__all__ = ["LARGEST_TOL", "FAILED_LEVELS", "checked_tol", "checked_accuracy",
           "check_laws_at_rest", "refuse_unused", "require_scalar_fields", "truncation_limit",
           "hold_to_accuracy",
           "checked_stability", "look_at_stability", "LARGEST_DISPLACEMENT", "warn_if_displaced"]

LARGEST_TOL = 1e-2
"""The loosest tol any path accepts [-].

tol bounds a residual relative to the load (||R|| / ||F|| for the sleepers,
the contact residual over the largest wheel load Q).  Above 1 % the starting
point itself can pass: with wheels, tol = 0.5 accepted the constant-force
start after 0 steps, a mean contact force 14.6 kN (19 % of Q) off the static
load and a loss of contact that does not happen.  Asking for less than 1 %
of the load is asking for no solution at all."""


FAILED_LEVELS = 3
"""harmonics="auto" (cells and wheels) steps up in m past a level that fails to converge, and
gives up after this many failures in a row."""


def checked_tol(tol, default: float) -> float:
    """tol as a float: `default` for None, else real with 0 < tol <= `LARGEST_TOL`.

    Raises
    ------
    ValueError
        Naming tol, its value and the range.
    """
    if tol is None:
        return default
    tol = require_fraction("tol", tol)
    if tol > LARGEST_TOL:
        raise ValueError(f"tol must be <= {LARGEST_TOL:g} (a residual of {LARGEST_TOL:.0%} of "
                         f"the load); got {tol!r}: a looser tol accepts the starting point "
                         "as a solution")
    return tol


def checked_accuracy(accuracy, automatic: bool, stacklevel: int = 3) -> float:
    """accuracy as a float, real with 0 < accuracy < 1 (default `DEFAULT_ACCURACY`).

    An accuracy given with an explicit m warns: only harmonics="auto" uses it.
    """
    if accuracy is not None and not automatic:
        warnings.warn("accuracy is used by harmonics='auto' only; ignored for an explicit m",
                      stacklevel=stacklevel)
    return DEFAULT_ACCURACY if accuracy is None else require_fraction("accuracy", accuracy)


def check_laws_at_rest(laws, pad_stiffness, pad_damping, check_foundation: bool) -> None:
    """`check_foundation_at_rest` for every law (one per sleeper) unless not check_foundation."""
    if not check_foundation:
        return
    seen = set()
    for law, k1, eta1 in zip(laws, pad_stiffness, pad_damping):
        key = (id(law), float(k1), float(eta1))
        if key not in seen:
            seen.add(key)
            check_foundation_at_rest(law, float(k1), float(eta1))


def require_scalar_fields(track, train) -> None:
    """Refuse a track or a train with an array field: `railtrack.solve` solves one case."""
    batched = [f for part in (track, train) for f, v in vars(part).items()
               if not isinstance(v, tuple) and np.ndim(v) > 0]
    if batched:
        raise ValueError(f"solve takes a track and a train with scalar fields; {batched} are "
                         "arrays (for a batch of linear tracks use railtrack.sweep_speeds)")


def refuse_unused(path: str, **given) -> None:
    """Refuse the arguments `path` does not use, each given as ``name=(value, why)``.

    An argument left at None is not given.  Ignoring one without a word lets a
    caller believe it acted (issue 27: the wheel path took method="bogus").

    Raises
    ------
    ValueError
        Naming every such argument, its value and why `path` does not use it.
    """
    used = [f"{name}={_short(value)} ({why})" for name, (value, why) in given.items()
            if value is not None]
    if used:
        raise ValueError(f"{path} does not use " + "; ".join(used) + ": drop "
                         + ("it" if len(used) == 1 else "them"))


def _short(value) -> str:
    """A repr short enough for a message (an array of 601 zeros is not read)."""
    if isinstance(value, np.ndarray):
        return f"<array of shape {value.shape}>"
    return reprlib.repr(value)


def truncation_limit(automatic: bool, accuracy: float) -> float:
    """The estimated truncation error above which a converged solve warns.

    "auto" promised `accuracy`; an explicit m warns above `WARN_TRUNCATION` (1 %).
    """
    return accuracy if automatic else WARN_TRUNCATION


def hold_to_accuracy(result, automatic: bool, accuracy: float, strict: bool, *, of: str,
                     stopped: str, stacklevel: int = 4):
    """A result of harmonics="auto" that misses its accuracy, as a failure: (result, short).

    "auto" promised an answer within `accuracy`.  Where the last level
    converged but its ``truncation_error`` exceeds `accuracy`, or is NaN
    (no estimate could be made where "auto" stopped), the equations are
    solved at that m, but the answer is not the one asked for: the result
    comes back with ``converged=False`` and a message that says so, `stopped`
    (why "auto" went no further) and how to proceed, with every field
    (coefficients, truncation_error, harmonics) kept for a look.  Like any
    failure it raises `ConvergenceError` with ``strict`` and warns
    `ConvergenceWarning` otherwise (the one warning: no `TruncationWarning`
    besides).  An explicit m, a failed iteration or a level that meets the
    accuracy come back unchanged, with ``short`` False.  `of` names what the
    estimate is relative to ("Q", "the peak sleeper displacement").
    """
    error = float(result.truncation_error)
    if not (automatic and result.converged) or error <= accuracy:
        return result, False
    estimate = (f"the estimated truncation error, {_share(error)} of {of}, exceeds"
                if np.isfinite(error) else "no truncation error could be estimated to meet")
    text = (f"harmonics='auto' fell short: the equations are solved at m = {result.harmonics}, "
            f"but {estimate} accuracy = {_share(accuracy)} ({stopped}). To proceed, pass an explicit "
            "larger harmonics=m, loosen accuracy, or use the time-domain ring "
            "(railtrack.simulate_time_domain)")
    result = dataclasses.replace(result, converged=False, message=f"{result.message}; {text}")
    if strict:
        raise ConvergenceError(text, result, [])
    warnings.warn(ConvergenceWarning(text), stacklevel=stacklevel)
    return result, True


def _share(x: float) -> str:
    """A fraction as a percentage, or in powers of ten below 0.1 %."""
    return f"{x:.1%}" if x >= 1e-3 else f"{x:.1e}"


def checked_stability(stability) -> str:
    """stability, one of "quick", "full", "off" (checked before the solve, not after)."""
    if not isinstance(stability, str) or stability not in STABILITY_MODES:
        raise ValueError(f"stability must be one of {STABILITY_MODES}; got {stability!r}")
    return stability


def look_at_stability(result, stability: str, stacklevel: int = 4):
    """The quick (or full) stability look of `judge_stability` after a converged solve.

    Returns what `judge_stability` returns (a `Floquet` for "full", else None):
    one sleeper by `railtrack.floquet`, a cell by Hill's matrix of the cell.
    """
    if not result.converged:
        return None
    warn_if_displaced(result)
    return judge_stability(result, stability, stacklevel=stacklevel)


LARGEST_DISPLACEMENT = 0.1
"""|w| [m] of a sleeper or of the rail above one past which a converged result warns.

No track survives it.  Measured deflections stay below about 10 mm even on the
soft ground of Ledsgard near the critical speed (Madshus & Kaynia 2000), a
hanging sleeper's gap is a few mm, and a wheel's flange is about 30 mm high:
a rail 0.1 m down has derailed the train.  0.1 m is ten times the worst
deflection measured, so a result beyond it is the inputs' doing (a foundation
stiffness typed in MN/m: 20 N/m "converges" to -162 m)."""


def warn_if_displaced(result, samples: int = 64) -> None:
    """Warn `PlausibilityWarning` if a converged result moves a sleeper or the rail > 0.1 m.

    Sleepers and the rail above sleeper 0 are sampled at `samples` times over
    one period (the peaks of a smooth periodic response, to well under the
    factor this threshold leaves).
    """
    if not result.converged:
        return
    t = np.linspace(0.0, float(result.period), samples, endpoint=False)
    sleepers = float(np.max(np.abs(result.sleeper_displacement(t))))
    rail = float(np.max(np.abs(result.rail_displacement(t))))
    if max(sleepers, rail) > LARGEST_DISPLACEMENT:
        warn_implausible(
            f"the solution moves the sleepers by up to {sleepers:.3g} m and the rail by up "
            f"to {rail:.3g} m: no track survives a displacement above "
            f"{LARGEST_DISPLACEMENT:g} m, so the inputs are probably off (a unit slip? "
            f"check them against railtrack.plausible_ranges())")
