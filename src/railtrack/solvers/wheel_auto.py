"""`railtrack.solve` with wheels: the cell, the checks, and ``harmonics="auto"`` (issue 20).

A steady state exists when every wheel meets the same track every wagon
length H: the rail-top profile must repeat with the cell of sleepers (N L),
and the cell must divide H.  A foundation law (identical sleepers) takes
the smallest such cell: N = 1 for the smooth rail (the wheels feel the
sleepers pass, harmonics p = H/L, 2H/L, ..), N = period / L for a profile
with a `period` (a dipped weld once a wagon: N = H/L, every harmonic).

"auto" is `railtrack.solvers.wheel_rounds` (m read off the contact force's
spectrum, `railtrack.solvers.wheel_tail`); an explicit m is estimated by
`railtrack.solvers.wheel_truncation`.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..model.cell import SleeperCell
from ..model.passage import Passage
from ..model.profile import smooth_rail
from ..model.vehicle import Vehicle
from ..model.wheel import Wheel
from .arguments import require_count
from .diagnosis import report
from .guards import (
    check_laws_at_rest,
    checked_accuracy,
    checked_stability,
    checked_tol,
    hold_to_accuracy,
    refuse_unused,
    truncation_limit,
    warn_if_displaced,
)
from .wheel_newton import solve_wheels
from . import wheel_rounds
from .wheel_rounds import auto_wheels, wrap
from .wheel_solution import WheelSolution
from .wheel_truncation import wheel_truncation

__all__ = ["solve_track_wheels", "wheel_cell", "wagons_in_period"]

DEFAULT_WHEEL_TOL = 1e-9
"""The contact residual over the largest wheel load Q at which a wheel solve stops [-]."""
DEFAULT_STEPS = 40
"""Newton steps of a wheel solve, unless max_iterations says otherwise."""


def wagons_in_period(profile, train) -> int:
    """n, when the profile's `period` is n > 1 wagon lengths; else 1.

    The steady state then repeats every n wagons only: the solve runs on
    ``train.tiled(n)``, one wagon n H long with the n wagons' wheels.

    Examples
    --------
    >>> import railtrack as rt
    >>> wagons_in_period(rt.CosineDip(1e-3, 1.0, 36.0), rt.Train.paper())   # H = 18 m
    2
    """
    period = getattr(profile, "period", None)
    if period is None:
        return 1
    ratio = float(period) / float(train.wagon_length)
    whole = int(round(ratio))
    return whole if whole > 1 and abs(ratio - whole) <= 1e-9 * ratio else 1


def _fitting_periods(profile, span: float, wagon: float) -> str:
    """For a wheel flat: the circumferences near its own that fit (whole spacings dividing H)."""
    if getattr(profile, "circumference", None) is None:
        return ""
    fits = [k * span for k in range(1, int(round(wagon / span)) + 1)
            if abs(wagon / (k * span) - round(wagon / (k * span))) <= 1e-9]
    near = sorted(fits, key=lambda c: abs(c - float(profile.circumference)))[:2]
    return (f"; a wheel flat's circumference must be both, on L = {span:g} m and H = "
            f"{wagon:g} m: the nearest are {' and '.join(f'{c:g} m' for c in sorted(near))} "
            f"(chapter 17: P1 barely depends on it)")


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
            raise ValueError(f"the profile's period ({float(period):g} m) must be a whole "
                             f"number of sleeper spacings (L = {span:g} m) for a steady state"
                             + _fitting_periods(profile, span, wagon))
        cell = SleeperCell.identical(passage, support, sleepers)
    length = cell.sleepers * span
    if abs(wagon / length - round(wagon / length)) > 1e-9:
        raise ValueError(f"the wagon length H = {wagon:g} m must be a whole number of cells "
                         f"(N L = {length:g} m) for a steady state with wheels"
                         + _fitting_periods(profile, span, wagon))
    x = np.linspace(0.0, wagon, 2048, endpoint=False)
    if not callable(profile):
        raise TypeError(f"profile must be a callable r(x) [m], e.g. railtrack.CosineDip(...); "
                        f"got {type(profile).__name__} {profile!r}")
    here, there = np.asarray(profile(x), float), np.asarray(profile(x + length), float)
    if here.shape != x.shape or there.shape != x.shape:
        raise ValueError(f"the profile r(x) must return an array shaped like x (one height "
                         f"[m] per position); for x of shape {x.shape} it returned shape "
                         f"{here.shape}: use numpy operations, e.g. np.zeros_like(x)")
    if not np.all(np.isfinite(here)):
        raise ValueError("the profile r(x) is not finite along the wagon length")
    size = max(float(np.max(np.abs(here))), 1e-12)
    if np.max(np.abs(there - here)) > 1e-9 * size:
        raise ValueError(f"the profile must repeat every N L = {length} m (the cell), so that "
                         "every wagon meets the same rail; give the profile a `period` that "
                         "divides H, or pass a SleeperCell of that length")
    return cell


def solve_track_wheels(track, train, support, wheel, profile=smooth_rail, harmonics="auto",
                       method: str = "newton", *, accuracy=None, tol=None,
                       max_iterations=None, split=None, samples=None, initial=None,
                       strict: bool = False, check_foundation: bool = True, fallback=None,
                       stability: str = "quick") -> WheelSolution:
    """`railtrack.solve` with ``wheel=``: see `railtrack.solve` and the module docstring.

    Checked by `railtrack.solvers.guards` as the other paths are: the laws at
    rest, tol and accuracy, the arguments this path does not use (method
    other than "newton", initial, split, fallback: refused).  An explicit m
    gets the truncation estimate of `railtrack.solvers.wheel_truncation` and
    a `TruncationWarning` above 1 % (``converged`` refers to the equations at
    that m).  harmonics="auto" promises `accuracy` (of Q): where it stops
    short of it, at its cap or with no estimate, the result has
    ``converged=False`` (`railtrack.solvers.guards.hold_to_accuracy`).  The quick stability look is not done
    for wheels (their Floquet multipliers are not computed), and
    ``stability="full"`` is refused: run `railtrack.simulate_time_domain`
    with ``wheel=`` from this state instead.

    A `railtrack.Vehicle` goes where a `Wheel` goes: its wheels are coupled
    through the suspension (`railtrack.equations.wheel_receptance`); the
    train must be its own (`Vehicle.check_train`: axles and static loads).

    A profile whose `period` is n > 1 wagon lengths (a random rail realised
    over several wagons) makes the steady state n wagons long: the solve runs
    on ``train.tiled(n)`` (`wagons_in_period`), and the solution's passage,
    period and wheels (4n for a four-axle wagon, wagon by wagon) are those of
    the n wagons.
    """
    if not isinstance(wheel, (Wheel, Vehicle)):
        raise TypeError(f"wheel must be a railtrack.Wheel, e.g. Wheel({wheel!r}) for an unsprung "
                        f"mass of {wheel!r} kg, or a railtrack.Vehicle; got "
                        f"{type(wheel).__name__} {wheel!r}")
    if isinstance(wheel, Vehicle):
        wheel.check_train(train)
    if method != "newton":
        raise ValueError(f"with wheels, solve uses method='newton' only; got {method!r}")
    refuse_unused("the wheel path", initial=(initial, "it starts from the static contact"),
                  split=(split, "a fixed-point setting"),
                  fallback=(fallback, "no speed path with wheels"))
    if checked_stability(stability) == "full":
        raise ValueError("stability='full' is not available with wheels (their Floquet "
                         "multipliers are not computed): start railtrack.simulate_time_domain("
                         "..., wheel=...) from this state and watch whether it stays")
    if isinstance(wheel, Wheel) and (wheel.primary_stiffness or wheel.primary_damping):
        raise ValueError("the harmonic balance takes an infinitely soft primary suspension "
                         "(the wheel carries its static load Q whatever it does); a primary "
                         "suspension under a moving body: pass wheel=railtrack.Vehicle(...); "
                         "to a fixed body: the time-domain ring, "
                         "railtrack.simulate_time_domain(..., wheel=...)")
    profile = smooth_rail if profile is None else profile
    passage = Passage(track, train.tiled(wagons_in_period(profile, train)))
    cell = wheel_cell(passage, support, profile)
    check_laws_at_rest(cell.foundations, cell.pad_stiffness, cell.pad_damping, check_foundation)
    tol = checked_tol(tol, DEFAULT_WHEEL_TOL)
    iterations = DEFAULT_STEPS if max_iterations is None else require_count(
        "max_iterations", max_iterations, 0)
    groups = int(round(float(passage.wagon_length) / (cell.sleepers * passage.sleeper_spacing)))
    automatic = isinstance(harmonics, str) and harmonics == "auto"
    accuracy = checked_accuracy(accuracy, automatic, stacklevel=4)
    if isinstance(harmonics, str) and not automatic:
        raise ValueError(f'harmonics must be an integer >= 1 or "auto"; got {harmonics!r}')
    if automatic:
        if samples is not None:
            raise ValueError("samples needs an explicit harmonics=m; 'auto' chooses m itself")
        result = auto_wheels(passage, cell, wheel, profile, groups, accuracy, tol, iterations)
        text = ""
    else:
        if isinstance(harmonics, bool) or not isinstance(harmonics, (int, np.integer)) \
                or harmonics < groups:
            raise ValueError(f"harmonics must be an integer >= H/(N L) = {groups} (the first "
                             f"harmonic the wheels feel); got {harmonics!r}")
        if samples is not None:
            samples = require_count("samples", samples, 4 * int(harmonics) + 1)
        result = wrap(passage, wheel, profile, solve_wheels(
            passage, cell, wheel, profile, int(harmonics), samples=samples, tol=tol,
            max_iterations=iterations))
        if result.converged:
            result = replace(result, truncation_error=wheel_truncation(result))
        text = (f"harmonics={result.harmonics}: the estimated truncation error of the contact "
                f"force is {result.truncation_error:.1%} of Q; pass a larger harmonics")
    budget_spent = max_iterations is not None and result.iterations >= iterations
    stopped = (f"'auto' goes up to m = {wheel_rounds.MAX_HARMONICS} with wheels; the message "
               "lists every m it tried")
    result, short = hold_to_accuracy(result, automatic, accuracy, strict, of="Q",
                                     stopped=stopped)
    warn_if_displaced(result)
    return result if short else report(result, strict, truncation_limit(automatic, accuracy),
                                       text, quiet=budget_spent)
