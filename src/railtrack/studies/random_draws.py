"""The draws of a random-support Monte Carlo (`railtrack.studies.random_support`).

`lognormal_factors` draws each sleeper's stiffness factor X_j (mean 1),
`scaled_law` and `draw_cell` put them on the laws and the cell, and
`draw_chunk` solves draws one by one (`railtrack.solve` for a cell), each
read for its peaks by `draw_peaks`.  Draws on linear laws are solved in a
batch instead (`railtrack.studies.random_support_batch`).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..model.cell import SleeperCell
from ..model.foundations import as_foundation
from ..solvers.cell_auto import solve_track_cell
from ..solvers.stability_hint import cell_verdict
from .random_support_batch import POINTS_PER_SPAN, TIMES

__all__ = ["lognormal_factors", "scaled_law", "draw_cell", "draw_chunk", "draw_peaks"]


def lognormal_factors(variation: float, shape, rng: np.random.Generator) -> np.ndarray:
    """Lognormal factors of mean 1 and coefficient of variation `variation` [-]."""
    if not 0.0 <= variation < 10.0:
        raise ValueError(f"variation (coefficient of variation) must be in [0, 10); "
                         f"got {variation!r}")
    sigma = np.sqrt(np.log1p(variation**2))
    return rng.lognormal(-0.5 * sigma**2, sigma, size=shape)


def scaled_law(law, factor: float):
    """`law` with every field whose name contains "stiffness" multiplied by `factor`.

    Examples
    --------
    >>> from railtrack.model.foundations import CubicFoundation
    >>> scaled_law(CubicFoundation(20e6, 2e13, 0.8, 2e5), 0.5).stiffness
    10000000.0
    """
    law = as_foundation(law)
    if not dataclasses.is_dataclass(law):
        raise TypeError(f"random_support scales a law's stiffness fields; a "
                        f"{type(law).__name__} has none (use a package law)")
    changes = {f.name: getattr(law, f.name) * factor for f in dataclasses.fields(law)
               if "stiffness" in f.name}
    if not changes:
        raise TypeError(f"{type(law).__name__} has no field named *stiffness* to scale")
    return dataclasses.replace(law, **changes)


def draw_cell(base: SleeperCell, row: np.ndarray) -> SleeperCell:
    """The cell of one draw: sleeper j on its law's stiffness times X_j."""
    return dataclasses.replace(
        base, foundations=tuple(scaled_law(law, x) for law, x in zip(base.foundations, row)))


def draw_chunk(track, train, cells, harmonics, stability: str):
    """Draws solved one by one (`railtrack.solve` for a cell): their peaks, flags and verdicts."""
    size = len(cells)
    seat, moment = np.full(size, np.nan), np.full(size, np.nan)
    converged, used = np.zeros(size, bool), np.zeros(size, int)
    verdicts = np.full(size, "unknown", dtype="<U8")
    for k, cell in enumerate(cells):
        solution = solve_track_cell(track, train, cell, harmonics, stability="off")
        converged[k], used[k] = solution.converged, solution.harmonics
        verdicts[k] = cell_verdict(solution, stability)[0]
        if solution.converged:
            seat[k], moment[k] = draw_peaks(solution)
    return seat, moment, converged, used, verdicts


def draw_peaks(solution) -> tuple[float, float]:
    """The largest rail-seat load [N] and sagging moment under a wheel [N m] of a draw's solution."""
    passage = solution.passage
    times = solution.one_period(TIMES)[0]
    seat = float(solution.rail_seat_load(times).max())
    span = passage.sleeper_spacing
    x = np.arange(solution.sleepers * POINTS_PER_SPAN) * span / POINTS_PER_SPAN
    wheels = np.asarray(passage.axle_positions, dtype=float)
    under = (x[:, None] + wheels[None, :]) / float(passage.speed)    # wheel j above x
    moment = solution.rail_bending_moment(np.mod(under, solution.period), x[:, None])
    return seat, float(moment.max())
