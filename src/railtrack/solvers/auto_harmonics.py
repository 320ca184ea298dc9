"""How `railtrack.solve` chooses m: the first system, the next m, the warning when m is short.

``harmonics="auto"`` starts at the m that `railtrack.solvers.truncation`
predicts from eq. (23) (through m / 4 first when that is above
`WARM_START_ABOVE`), and while the solution's estimated truncation error
misses the accuracy, grows m to what the solution's own spectrum needs
(`next_system`), at most `AUTO_ROUNDS` times; where it stops short of the
accuracy the result is a failure (`railtrack.solvers.guards.hold_to_accuracy`,
told why by `auto_stopped`).  An explicit m is kept, and warns when its
estimate exceeds `WARN_TRUNCATION` (`truncation_warning`).
"""

from __future__ import annotations

import math

from ..equations.harmonic_balance import require_jacobian_samples
from ..model.passage import Passage
from .arguments import checked_initial
from .solution import TruncationWarning
from .truncation import (
    MAX_AUTO_HARMONICS,
    TAIL_FACTOR,
    auto_samples,
    grown_harmonics,
    padded,
    predict_harmonics,
    track_spectrum,
)

__all__ = ["DEFAULT_ACCURACY", "WARN_TRUNCATION", "AUTO_ROUNDS", "WARM_START_ABOVE",
           "first_system", "next_system", "truncation_warning", "auto_stopped"]

DEFAULT_ACCURACY = 1e-3
"""Relative truncation error (max norm of w over the period / peak) that harmonics="auto" meets."""
WARN_TRUNCATION = 1e-2
"""An explicit m whose estimated truncation error exceeds this warns (`TruncationWarning`)."""
AUTO_ROUNDS = 4
WARM_START_ABOVE = 60
"""harmonics="auto" reaches a predicted m above this through a solve at m / 4 first:
Newton on a kinked law with long lifted stretches needs far fewer steps from there."""


def first_system(passage: Passage, foundation, harmonics, automatic: bool, method: str,
                 accuracy: float, samples, initial, ground=None):
    """The system of the first solve, as (m, target m, spectrum, system, initial).

    For "auto" the predicted m (or a quarter of it, see `WARM_START_ABOVE`);
    otherwise the explicit m, with `samples` and `initial` checked against it.
    One evaluation of eq. (3), the spectrum, serves the solve and its
    truncation estimate.
    """
    if automatic:
        target, spectrum = predict_harmonics(passage, foundation, accuracy / 2, ground)
        coarse = method == "analytic" or target <= WARM_START_ABOVE
        m = target if coarse else max(15, target // 4)
        system = spectrum.system(passage, foundation, m, auto_samples(m))
        return m, target, spectrum, system, initial
    m = int(harmonics)
    if samples is not None:
        require_jacobian_samples(samples, m)
    spectrum = track_spectrum(passage, TAIL_FACTOR * m, ground)
    system = spectrum.system(passage, foundation, m, samples)
    return m, m, spectrum, system, None if initial is None else checked_initial(initial, m)


def next_system(passage: Passage, foundation, method: str, m: int, target: int, estimate: float,
                accuracy: float, coefficients, tail, spectrum, ground=None):
    """The next round of "auto": None when m is done, else (m, spectrum, system, initial).

    m is done once it has reached the target and meets the accuracy (or is
    `MAX_AUTO_HARMONICS`).  Below the target the next m is the target;
    otherwise the solution and its estimated tail are the best spectrum
    known, and the next m is chosen from it, as the prediction did from
    eq. (23), by at least 10 %.
    """
    if m >= target and (estimate <= accuracy or m >= MAX_AUTO_HARMONICS):
        return None
    if m < target:
        grown = target
    else:
        grown = min(MAX_AUTO_HARMONICS, max(
            math.ceil(1.1 * m), grown_harmonics(coefficients, tail, 0.8 * accuracy)))
    if spectrum.upto < TAIL_FACTOR * grown:
        spectrum = track_spectrum(passage, TAIL_FACTOR * grown, ground)
    initial = padded(coefficients, tail, grown) if method != "analytic" else None
    system = spectrum.system(passage, foundation, grown, auto_samples(grown))
    return grown, spectrum, system, initial


def truncation_warning(passage: Passage, foundation, m: int, estimate: float) -> TruncationWarning:
    """The warning for a converged solution at an explicit m whose estimate exceeds 1 %.

    (harmonics="auto" that misses its accuracy is a failure instead:
    `railtrack.solvers.guards.hold_to_accuracy`, told why by `auto_stopped`.)
    """
    chosen = predict_harmonics(passage, foundation, DEFAULT_ACCURACY / 2)[0]
    return TruncationWarning(
        f"harmonics={m}: the estimated truncation error is {estimate:.1%} of the peak "
        f"sleeper displacement; harmonics='auto' picks m = {chosen} (pass a larger "
        "harmonics or use 'auto')")


def auto_stopped(m: int) -> str:
    """Why harmonics="auto" for one sleeper went no further than m."""
    if m >= MAX_AUTO_HARMONICS:
        return f"the largest m that 'auto' takes is {MAX_AUTO_HARMONICS}"
    return f"'auto' stopped after {AUTO_ROUNDS + 1} solves"
