"""harmonics="auto" with wheels: the rounds of m, and what each one did (issues 20, 27, 28).

With a rail-top profile, "auto" reads m off the contact force's spectrum
(`railtrack.solvers.wheel_tail`): a first solve at twice the wheel's bounce
harmonic, a fit of the force's tail on the profile's, one solve (warm) at
the m whose estimated tail is within the accuracy, and the estimate there,
refitted and checked against the measured change of P, as
``truncation_error`` (on the 0.5 mm dip of issue 28: m = 282 then 549,
instead of 60, 90, .., 687).  Where the fit cannot be trusted (a flat rail,
whose force is the sleepers' passing; see `wheel_tail`) m grows by 1.5
until two successive converged contact-force histories differ by at most
``accuracy`` times the largest static wheel load, the finer one returned
with that difference as ``truncation_error``.  A level that does not
converge does not end the search (issue 27: a 5 mm dip at 45 m/s fails at
m = 60 and converges above): m grows past it, from the last converged
level's contact forces where there is one, at most `FAILED_LEVELS`
failures in a row.  The message lists every m tried and what happened there.
Every level after the first starts from the last converged one: its contact
forces, lifts and sleepers' harmonics (the sleepers' inner solve from rest took
5 Newton steps at every level of the hanging sleeper's search, 2-3 from there).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..equations.wheel_harmonic_balance import profile_harmonics
from .guards import FAILED_LEVELS
from .wheel_newton import solve_wheels
from .wheel_solution import WheelSolution
from .wheel_tail import AIM, TailFit, harmonics_for, profile_tail, tail_estimate, transfer

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
    """The wheels' response at an m whose contact force is estimated within accuracy Q.

    With a profile whose tail `railtrack.solvers.wheel_tail` can fit, the
    first m is twice the wheel's bounce harmonic; each converged level fits
    T_P and solves next (warm) at the m whose estimated tail is `AIM` x
    accuracy, until the estimate at the level itself (T_P the largest fitted,
    or the one the measured change of P asks for) is <= accuracy.  Otherwise
    (or once the fit fails at a level) m grows by 1.5 until two successive
    contact forces differ by <= accuracy Q.  The message lists every m and why.

    Parameters
    ----------
    groups : int
        G = H / (N L): m is kept a multiple of it.
    first : int, optional
        The first m (default: the fit's, else max(4 G, 60)).
    """
    tail = profile_tail(passage, wheel, profile, groups, MAX_HARMONICS)
    fitted = not isinstance(tail, str)
    m = int(first) if first is not None else tail.first if fitted else max(4 * groups, 60)
    t = np.linspace(0.0, float(passage.period), 4096, endpoint=False)
    tried = [] if fitted else [f"m grows by 1.5 ({tail})"]
    scale = float(np.max(passage.axle_loads))
    previous, start, failed, steps, fitting = None, None, 0, 0, TailFit(0.0, 0.0)
    change = estimate = float("nan")
    while True:
        raw = solve_wheels(passage, cell, wheel, profile, m, tol=tol,
                           max_iterations=max_iterations, start=start)
        result = wrap(passage, wheel, profile, raw)
        steps += result.iterations
        grown = min(int(np.ceil(1.5 * m / groups)) * groups, MAX_HARMONICS)
        if not result.converged:
            failed += 1
            tried.append(f"m = {m}: did not converge ({raw.message.split(';')[0]})")
            previous = None            # nothing converged next to it to compare with
            if failed >= FAILED_LEVELS or m >= MAX_HARMONICS:
                break
            m = grown
            continue
        failed = 0
        force = result.contact_force(t)
        change = float("nan") if previous is None else \
            float(np.max(np.abs(force - previous[1]))) / scale
        entry = f"m = {m}: converged" + ("" if previous is None else
                                         f", P changed by {change:.1e} Q from m = {previous[0]}")
        if fitted:
            fit = transfer(tail, raw.grid, raw.contact_harmonics)
            if isinstance(fit, str):
                fitted, estimate = False, float("nan")
                entry += f"; m grows by 1.5 from here ({fit})"
            else:
                fitting = fitting | fit
                if previous is not None:
                    # the one check: the change of P the last fit predicted against the
                    # measured one, which scales the fit up where it fell short
                    predicted = tail_estimate(tail, previous[2], previous[0]) - tail_estimate(
                        tail, previous[2], m)
                    ratio = change / max(predicted, 1e-300)
                    fitting = fitting | TailFit(ratio * previous[2].stiffness,
                                                ratio * previous[2].passing)
                    entry += f" (the fit predicted {predicted:.1e} Q)"
                estimate = tail_estimate(tail, fitting, m)
                entry += (f"; P_p ~ {fitting.stiffness:.2e} N/m x r_p (the profile's harmonics, "
                          f"falling as p^{tail.decay:.1f}) and the sleepers' passing "
                          f"<= {fitting.passing:.1e} N / p^3: estimated tail {estimate:.1e} Q")
        tried.append(entry)
        if fitted and estimate <= accuracy:
            break
        if not fitted and previous is not None and change <= accuracy:
            break
        if m >= MAX_HARMONICS:
            break
        previous, start = (m, force, fitting), (raw.contact_harmonics, raw.lift,
                                                  raw.coefficients[:, m:])
        if fitted:
            m = min(max(grown, harmonics_for(tail, fitting, AIM * accuracy, MAX_HARMONICS)),
                    MAX_HARMONICS)
        else:
            m = grown
    # the last level is the answer: converged with its estimate, or the failure that ended
    # the search, never an earlier level passed off as meeting the accuracy
    error = (estimate if fitted else change) if result.converged else float("nan")
    history = "; ".join(tried)
    return replace(result, iterations=steps, truncation_error=error,
                   message=f"{result.message}; harmonics='auto' tried {history}")
