"""A hanging sleeper in a cell: the quantities a track engineer reads (issue 19, section 3).

`hanging_cell` builds the cell: N sound sleepers on one linear law, sleeper
`at` hanging `gap` above the same ballast (`railtrack.GapFoundation`).
`sleeper_extremes` reads per sleeper the largest rail-seat load and
foundation force, the lowest displacement and the share of the period in
contact; `moment_extremes` the rail's bending moment above a sleeper and at
the mid-spans beside it.  Both read a `railtrack.CellSolution` or the ring's
`railtrack.TimeDomainSolution` alike, so that the two methods are compared
on the same quantities.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..model.cell import SleeperCell
from ..model.foundations import LinearFoundation
from ..model.gap import GapFoundation
from ..model.passage import Passage
from ..solvers.cell_solution import CellSolution
from ..solvers.wheel_solution import WheelSolution

__all__ = ["hanging_cell", "neighbour_rise", "SleeperExtremes", "sleeper_extremes",
           "moment_extremes"]

SAMPLES = 2048
"""Instants per period at which a harmonic-balance solution is read."""


def hanging_cell(passage: Passage, law: LinearFoundation, gap: float, *, sleepers: int = 30,
                 at: int | None = None, gravity: float = 0.0,
                 hanging_mass: float | None = None) -> SleeperCell:
    """N sleepers of the passage on `law`, sleeper `at` (default N // 2) hanging `gap` [m] above it.

    ``gap = 0`` gives the sound cell (every sleeper on `law`).  `hanging_mass`
    [kg], if given, is the hanging sleeper's mass: on a track whose sleeper
    mass includes the ballast that moves with it, the sleeper over a void
    keeps only its own.

    Examples
    --------
    >>> cell = hanging_cell(Passage.paper(), LinearFoundation(20e6, 2e5), 1e-3, sleepers=4)
    >>> type(cell.foundations[2]).__name__, cell.foundations[2].gap
    ('GapFoundation', 0.001)
    """
    at = sleepers // 2 if at is None else at
    cell = SleeperCell.identical(passage, law, sleepers, gravity=gravity)
    if gap == 0:
        return cell
    void = GapFoundation(gap, law.stiffness, law.damping)
    if hanging_mass is None:
        return cell.with_sleeper(at, foundation=void)
    return cell.with_sleeper(at, foundation=void, sleeper_mass=hanging_mass)


def neighbour_rise(sound, hanging, at: int) -> tuple[float, float]:
    """How much more the more loaded neighbour of sleeper `at` takes than a sound sleeper.

    Parameters
    ----------
    sound, hanging : CellSolution or WheelSolution
        The same track and train on the sound cell and on the cell with
        sleeper `at` hanging (`hanging_cell`).
    at : int
        The hanging sleeper.

    Returns
    -------
    (float, float)
        The largest of the two neighbours' peak foundation forces, and of
        their deepest displacements, over the sound track's sleeper `at`,
        minus 1 [-] (0.25: a quarter more).

    Examples
    --------
    >>> import railtrack as rt
    >>> p, law = Passage.paper(), LinearFoundation(20e6, 2e5)
    >>> solved = [rt.solve(p.track, p.train, hanging_cell(p, law, gap, sleepers=30), 200)
    ...           for gap in (0.0, 1e-3)]
    >>> force, depth = neighbour_rise(*solved, at=15)
    >>> round(force, 2), round(depth, 2)
    (0.24, 0.2)
    """
    before, after = sleeper_extremes(sound), sleeper_extremes(hanging)
    side = [at - 1, at + 1]
    force = after.peak_foundation_force[side] / before.peak_foundation_force[at]
    depth = after.lowest_displacement[side] / before.lowest_displacement[at]
    return float(force.max() - 1.0), float(depth.max() - 1.0)


class SleeperExtremes(NamedTuple):
    """Per sleeper, over one period: arrays of shape (N,)."""

    peak_seat_load: np.ndarray       # [N], largest rail-seat load (compression)
    peak_foundation_force: np.ndarray  # [N], largest force on the foundation (compression)
    lowest_displacement: np.ndarray  # [m], w positive upward
    contact_fraction: np.ndarray     # [-], share of the period with foundation force > 0


def _histories(solution):
    """(seat load, foundation force, displacement), each (N, instants), from either method."""
    if isinstance(solution, (CellSolution, WheelSolution)):
        t = solution.one_period(SAMPLES)[0]
        return (solution.rail_seat_load(t), solution.foundation_force(t),
                solution.sleeper_displacement(t))
    return (solution.rail_seat_loads.T, solution.foundation_forces.T,
            solution.sleeper_displacements.T)


def sleeper_extremes(solution) -> SleeperExtremes:
    """Extremes of every sleeper of a `CellSolution`, a `WheelSolution` or the ring's sleepers."""
    seat, force, displacement = _histories(solution)
    return SleeperExtremes(seat.max(axis=1), force.max(axis=1), displacement.min(axis=1),
                           np.mean(force > 0.0, axis=1))


def moment_extremes(solution, at: int) -> dict[str, tuple[float, float]]:
    """(largest sagging, largest hogging) rail moment [N m] above sleeper `at` and mid-spans.

    Keys ``"mid-span before"``, ``"above"``, ``"mid-span after"`` (x = (at - 1/2) L,
    at L, (at + 1/2) L).  For a `CellSolution` the moment is read at
    `SAMPLES` instants and at the instants each wheel is there (the sagging
    peak is a cusp under the wheel); the ring's at its time steps.
    """
    if isinstance(solution, CellSolution):
        passage = solution.passage
        span = passage.sleeper_spacing
        x = (at + np.array([-0.5, 0.0, 0.5])) * span
        under = (x[:, None] + np.asarray(passage.axle_positions)) / float(passage.speed)
        t = np.concatenate([np.broadcast_to(solution.one_period(SAMPLES)[0], (3, SAMPLES)),
                            np.mod(under, solution.period)], axis=1)
        moment = solution.rail_bending_moment(t, x[:, None])
    else:
        moment = np.stack([solution.bending_moments_midspan[:, at - 1],
                           solution.bending_moments_above_sleepers[:, at],
                           solution.bending_moments_midspan[:, at]])
    names = ("mid-span before", "above", "mid-span after")
    return {name: (float(row.max()), float(row.min())) for name, row in zip(names, moment)}
