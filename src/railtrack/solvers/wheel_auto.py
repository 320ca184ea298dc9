"""`railtrack.solve` with wheels: the cell, the checks, and ``harmonics="auto"`` (issue 20).

A steady state exists when every wheel meets the same track every wagon
length H: the rail-top profile must repeat with the cell of sleepers (N L),
and the cell must divide H.  A foundation law (identical sleepers) takes
the smallest such cell: N = 1 for the smooth rail (the wheels feel the
sleepers pass, harmonics p = H/L, 2H/L, ..), N = period / L for a profile
with a `period` (a dipped weld once a wagon: N = H/L, every harmonic).

"auto" solves at m, then 1.5 m, .. until two successive contact-force
histories differ by at most ``accuracy`` times the largest static wheel
load, and returns the finer one with that difference as
``truncation_error``.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..equations.wheel_harmonic_balance import profile_harmonics
from ..model.cell import SleeperCell
from ..model.passage import Passage
from ..model.profile import smooth_rail
from .auto_harmonics import DEFAULT_ACCURACY
from .diagnosis import report
from .wheel_newton import solve_wheels
from .wheel_solution import WheelSolution

__all__ = ["solve_track_wheels", "wheel_cell"]

MAX_HARMONICS = 1200


def wheel_cell(passage: Passage, support, profile) -> SleeperCell:
    """The cell a law and a profile need, or ``support`` itself if it is a `SleeperCell`.

    Raises
    ------
    ValueError
        A profile that does not repeat with the cell, or a cell that H does
        not hold a whole number of times.

    Examples
    --------
    >>> import railtrack as rt
    >>> passage = rt.Passage(rt.Track.paper(), rt.Train.paper())
    >>> law = rt.LinearFoundation(20e6, 0.2e6)
    >>> wheel_cell(passage, law, smooth_rail).sleepers                 # sleeper passing
    1
    >>> wheel_cell(passage, law, rt.CosineDip(0.5e-3, 1.0, 18.0)).sleepers   # a weld a wagon
    30
    """
    span, wagon = float(passage.sleeper_spacing), float(passage.wagon_length)
    if isinstance(support, SleeperCell):
        cell = support
    else:
        period = getattr(profile, "period", None)
        sleepers = 1 if period is None else int(round(float(period) / span))
        if period is not None and (sleepers < 1 or abs(sleepers * span - period) > 1e-9 * wagon):
            raise ValueError(f"the profile's period ({period} m) must be a whole number of "
                             f"sleeper spacings (L = {span} m) for a steady state")
        cell = SleeperCell.identical(passage, support, sleepers)
    length = cell.sleepers * span
    if abs(wagon / length - round(wagon / length)) > 1e-9:
        raise ValueError(f"the wagon length H = {wagon} m must be a whole number of cells "
                         f"(N L = {length} m) for a steady state with wheels")
    x = np.linspace(0.0, wagon, 2048, endpoint=False)
    here, there = np.asarray(profile(x), float), np.asarray(profile(x + length), float)
    if not np.all(np.isfinite(here)):
        raise ValueError("the profile r(x) is not finite along the wagon length")
    size = max(float(np.max(np.abs(here))), 1e-12)
    if np.max(np.abs(there - here)) > 1e-9 * size:
        raise ValueError(f"the profile must repeat every N L = {length} m (the cell), so that "
                         "every wagon meets the same rail; give the profile a `period` that "
                         "divides H, or pass a SleeperCell of that length")
    return cell


def solve_track_wheels(track, train, support, wheel, profile=smooth_rail,
                       harmonics="auto", *, accuracy: float | None = None,
                       tol: float = 1e-9, strict: bool = False) -> WheelSolution:
    """`railtrack.solve` with ``wheel=``: see `railtrack.solve` and the module docstring."""
    if wheel.primary_stiffness or wheel.primary_damping:
        raise ValueError("the harmonic balance takes an infinitely soft primary suspension "
                         "(the wheel carries its static load Q whatever it does); a primary "
                         "suspension is modelled by the time-domain ring, "
                         "railtrack.simulate_time_domain(..., wheel=...)")
    passage = Passage(track, train)
    profile = smooth_rail if profile is None else profile
    cell = wheel_cell(passage, support, profile)
    groups = int(round(float(passage.wagon_length) / (cell.sleepers * passage.sleeper_spacing)))
    scale = float(np.max(passage.axle_loads))
    if isinstance(harmonics, str):
        if harmonics != "auto":
            raise ValueError(f'harmonics must be an integer >= 1 or "auto"; got {harmonics!r}')
        accuracy = DEFAULT_ACCURACY if accuracy is None else float(accuracy)
        result = _auto(passage, cell, wheel, profile, groups, accuracy, tol, scale)
        limit = accuracy
    else:
        if isinstance(harmonics, bool) or int(harmonics) != harmonics or harmonics < groups:
            raise ValueError(f"harmonics must be an integer >= H/(N L) = {groups} (the first "
                             f"harmonic the wheels feel); got {harmonics!r}")
        result = _wrap(passage, wheel, profile, solve_wheels(passage, cell, wheel, profile,
                                                             int(harmonics), tol=tol))
        limit = np.inf
    return report(result, strict, limit,
                  f"harmonics={result.harmonics}: the contact force changed by "
                  f"{result.truncation_error:.1%} of Q at the last refinement")


RAIL_FIELD_NOTE = (
    "with wheels the rail between the sleepers also carries the wheels' varying forces, which "
    "this field leaves out: ask the WheelSolution (its rail_displacement and "
    "rail_bending_moment add them); the rail above the sleepers, the sleepers, their "
    "rail-seat loads and foundation forces are complete here")


def _wrap(passage, wheel, profile, raw) -> WheelSolution:
    rail_top = profile_harmonics(passage, profile, raw.grid, raw.sleepers.samples)
    sleepers = replace(raw.sleepers, rail_field_note=RAIL_FIELD_NOTE)
    return WheelSolution(passage, wheel, profile, raw.sleepers.harmonics, raw.grid,
                         raw.contact_harmonics, raw.compression_harmonics, raw.lift, rail_top,
                         sleepers, raw.converged, raw.residual, raw.iterations, raw.message)


def _auto(passage, cell, wheel, profile, groups, accuracy, tol, scale) -> WheelSolution:
    m = max(4 * groups, 60)
    t = np.linspace(0.0, float(passage.period), 4096, endpoint=False)
    previous, change = None, float("nan")
    while True:
        result = _wrap(passage, wheel, profile, solve_wheels(passage, cell, wheel, profile, m,
                                                             tol=tol))
        if not result.converged:
            return replace(result, truncation_error=change)
        force = result.contact_force(t)
        if previous is not None:
            change = float(np.max(np.abs(force - previous))) / scale
            if change <= accuracy:
                return replace(result, truncation_error=change)
        if m >= MAX_HARMONICS:
            return replace(result, truncation_error=change)
        previous, m = force, min(int(np.ceil(1.5 * m / groups)) * groups, MAX_HARMONICS)
