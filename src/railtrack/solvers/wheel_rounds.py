"""harmonics="auto" with wheels: the rounds of m, and what each one did (issues 20, 27).

"auto" solves at m, then about 1.5 m, .. until two successive converged
contact-force histories differ by at most ``accuracy`` times the largest
static wheel load, and returns the finer one with that difference as
``truncation_error``.  A level that does not converge does not end the
search (issue 27: a 5 mm dip at 45 m/s fails at m = 60 and converges above):
m grows past it, from the last converged level's contact forces where there
is one, at most `FAILED_LEVELS` failures in a row.  The message lists every
m tried and what happened there.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..equations.wheel_harmonic_balance import profile_harmonics
from .guards import FAILED_LEVELS
from .wheel_newton import solve_wheels
from .wheel_solution import WheelSolution

__all__ = ["auto_wheels", "wrap", "MAX_HARMONICS"]

MAX_HARMONICS = 1200
"""The largest m "auto" takes with wheels."""

RAIL_FIELD_NOTE = (
    "with wheels the rail between the sleepers also carries the wheels' varying forces, which "
    "this field leaves out: ask the WheelSolution (its rail_displacement and "
    "rail_bending_moment add them); the rail above the sleepers, the sleepers, their "
    "rail-seat loads and foundation forces are complete here")


def wrap(passage, wheel, profile, raw) -> WheelSolution:
    """A `WheelSolution` from `railtrack.solvers.wheel_newton.solve_wheels`' result."""
    rail_top = profile_harmonics(passage, profile, raw.grid, raw.sleepers.samples)
    sleepers = replace(raw.sleepers, rail_field_note=RAIL_FIELD_NOTE)
    return WheelSolution(passage, wheel, profile, raw.sleepers.harmonics, raw.grid,
                         raw.contact_harmonics, raw.compression_harmonics, raw.lift, rail_top,
                         sleepers, raw.converged, raw.residual, raw.iterations, raw.message)


def auto_wheels(passage, cell, wheel, profile, groups: int, accuracy: float, tol: float,
                max_iterations: int, first: int | None = None) -> WheelSolution:
    """The wheels' response at the first m whose refinement changes P by <= accuracy Q.

    Parameters
    ----------
    groups : int
        G = H / (N L): m is kept a multiple of it.
    first : int, optional
        The first m (default max(4 G, 60)).
    """
    m = max(4 * groups, 60) if first is None else int(first)
    t = np.linspace(0.0, float(passage.period), 4096, endpoint=False)
    scale = float(np.max(passage.axle_loads))
    previous, start, change, failed, tried = None, None, float("nan"), 0, []
    steps = 0
    while True:
        raw = solve_wheels(passage, cell, wheel, profile, m, tol=tol,
                           max_iterations=max_iterations, start=start)
        result = wrap(passage, wheel, profile, raw)
        steps += result.iterations
        if result.converged:
            failed = 0
            force = result.contact_force(t)
            if previous is None:
                change = float("nan")
                tried.append(f"m = {m}: converged")
            else:
                change = float(np.max(np.abs(force - previous[1]))) / scale
                tried.append(f"m = {m}: converged, P changed by {change:.1e} Q from "
                             f"m = {previous[0]}")
            if previous is not None and change <= accuracy:
                break
            previous, start = (m, force), (raw.contact_harmonics, raw.lift)
        else:
            failed += 1
            tried.append(f"m = {m}: did not converge ({raw.message.split(';')[0]})")
            previous = None            # nothing converged next to it to compare with
            if failed >= FAILED_LEVELS:
                break
        if m >= MAX_HARMONICS:
            break
        m = min(int(np.ceil(1.5 * m / groups)) * groups, MAX_HARMONICS)
    # the last level is the answer: converged with its change, or the failure that ended
    # the search, never an earlier level passed off as meeting the accuracy
    history = "; ".join(tried)
    return replace(result, iterations=steps, truncation_error=change if result.converged
                   else float("nan"), message=f"{result.message}; harmonics='auto' tried {history}")
