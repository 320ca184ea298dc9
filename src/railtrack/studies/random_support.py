"""Random support: a Monte Carlo over cells whose sleepers' ballast stiffness scatters (issue 19).

Each draw is a cell of N sleepers on the same law, each sleeper's stiffness
multiplied by its own factor X_j, drawn independently from a lognormal
distribution of mean 1 and coefficient of variation ``variation``
(``ln X ~ Normal(-s^2/2, s^2)``, ``s^2 = ln(1 + variation^2)``).  Every
stiffness field of the law is scaled (`scaled_law`), dampings are kept.
The cell repeats every N sleepers: a draw stands for a long track whose
pattern repeats, not for an endless random one, and N should be large
enough that the extremes no longer change with it.  The draws come from
``numpy.random.default_rng(seed)``, so a seed gives the same cells on
every machine.

For each draw the result keeps the largest rail-seat load over the
sleepers and the period, and the rail's largest sagging moment along the
cell: the moment under each wheel, at 8 points a span (the sagging peak
of a span is under a wheel, `railtrack.equations.moment`).

Harmonic balance finds unstable periodic states as readily as stable ones,
and a train does not stay on an unstable one (its peaks can be far from
what the track carries).  Each draw is judged by the Floquet multipliers of
its cell (`railtrack.solvers.stability_hint.cell_verdict`): "unstable",
"stable" or "unknown", counted in `RandomSupport.summary`; any unstable draw
raises one `UnstableSolutionWarning`.

**Speed.**  On linear laws every draw is the same rail, train, sleepers and
pads at the same m, so the cell's operators are built once per m and all
draws are solved as one batch (`railtrack.studies.random_support_batch`):
m is what "auto" picks for the cell of the mean factor, every draw gets
its own residual and truncation estimate, and only the draws that miss the
accuracy are solved again at a larger m; a draw the batch leaves short of
the accuracy at its last level is solved alone by `railtrack.solve`, whose
verdict it takes (``converged=False`` where "auto" falls short there too).
Other laws are solved draw by draw (`railtrack.solve` for a cell).  The draws can be spread over any
``concurrent.futures`` executor (a Dask client too) with the same results,
and a progress bar (``tqdm``) is shown for large studies.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from ..model.cell import SleeperCell, cell_size
from ..model.foundations import LinearFoundation
from ..model.passage import Passage
from ..model.validation import require_non_negative
from ..solvers.arguments import require_count
from ..solvers.auto_harmonics import DEFAULT_ACCURACY, WARN_TRUNCATION
from ..solvers.chunk_map import chunk_bounds, map_chunks, show_progress
from ..solvers.solution import TruncationWarning
from ..solvers.stability_hint import UnstableSolutionWarning
from .random_draws import draw_cell, draw_chunk, lognormal_factors, scaled_law
from .random_support_batch import linear_draws
from ..solvers.export import Exports
from ..solvers.result_repr import ShortRepr
from .study_repr import random_support_rows

__all__ = ["RandomSupport", "random_support", "scaled_law", "lognormal_factors"]

PROGRESS_DRAWS = 500
"""With ``progress=None`` the bar is shown from this many draws (tens of seconds)."""


@dataclass(frozen=True, repr=False)
class RandomSupport(ShortRepr, Exports):
    """Draws of a random-support Monte Carlo.

    Attributes
    ----------
    variation : float
        Coefficient of variation of the stiffness factors [-].
    factors : ndarray, shape (draws, N)
        Each draw's stiffness factor per sleeper [-].
    peak_seat_load : ndarray, shape (draws,)
        Largest rail-seat load over the cell's sleepers and the period [N].
    peak_moment : ndarray, shape (draws,)
        Largest sagging rail moment along the cell [N m].
    converged : ndarray of bool, shape (draws,)
    harmonics : ndarray of int, shape (draws,)
    stability : ndarray of str, shape (draws,)
        Each draw's state: "stable", "unstable" or "unknown" (module docstring).
    """

    variation: float
    factors: np.ndarray
    peak_seat_load: np.ndarray
    peak_moment: np.ndarray
    converged: np.ndarray
    harmonics: np.ndarray
    stability: np.ndarray = field(default_factory=lambda: np.empty(0, dtype="<U8"))
    inputs: dict | None = field(default=None, repr=False, compare=False)
    """The study's track, train, foundation, sleepers, draws, seed, harmonics and stability."""

    def stability_counts(self) -> dict[str, int]:
        """How many draws are "stable", "unstable" and "unknown"."""
        return {key: int(np.sum(self.stability == key))
                for key in ("stable", "unstable", "unknown")}

    def summary(self) -> str:
        """One line: draws, converged, and the count of stable, unstable and unknown states."""
        counts = self.stability_counts()
        return (f"{self.converged.size} draws (variation {self.variation:g}): "
                f"{int(self.converged.sum())} converged; {counts['stable']} stable, "
                f"{counts['unstable']} unstable, {counts['unknown']} unknown")

    def quantiles(self, q=(0.5, 0.95, 0.99)) -> dict[str, np.ndarray]:
        """Quantiles of the peak seat load [N] and moment [N m] over the converged draws.

        A ValueError if no draw converged.
        """
        ok = self.converged
        if not ok.any():
            raise ValueError(f"none of the {ok.size} draws converged, so there is no quantile "
                             "to give; see .converged and .harmonics, and try more harmonics")
        return {"peak_seat_load": np.quantile(self.peak_seat_load[ok], q),
                "peak_moment": np.quantile(self.peak_moment[ok], q)}

    _rows = random_support_rows         # __repr__, _repr_html_ (ShortRepr)
    _table_row = None                   # to_dataframe: a row per draw, converged's dimension

    def to_xarray(self):
        """Every draw as an `xarray.Dataset` (CF units; `railtrack.studies.study_export`)."""
        from .study_export import random_support_dataset
        return random_support_dataset(self)


def random_support(track, train, foundation, *, sleepers: int = 30, variation: float = 0.3,
                   draws: int = 100, seed: int = 0, harmonics="auto",
                   stability: str = "quick", progress=None, executor=None) -> RandomSupport:
    """Monte Carlo over cells of `sleepers` sleepers with lognormal ballast stiffness.

    Parameters
    ----------
    track, train : Track, Train
        Scalar fields; every sleeper has the track's mass and pad.
    foundation : law
        A package law (a dataclass with a ``*stiffness*`` field), scaled per sleeper.
    sleepers : int
        N, the cell's size.
    variation : float
        Coefficient of variation of each sleeper's stiffness factor [-].
    draws : int
        Number of cells drawn, >= 1.
    seed : int
        For ``numpy.random.default_rng``, >= 0.
    harmonics : int or "auto"
        As `railtrack.solve`.  On a linear law "auto" starts every draw at the
        m of the cell of the mean factor and steps up only the draws whose own
        truncation estimate misses the accuracy (module docstring); a draw may
        so keep a larger m than it would alone, never a worse accuracy.
    stability : {"quick", "full", "off"}
        How each draw is judged (`railtrack.solvers.stability_hint.cell_verdict`):
        "quick" looks at Bloch phase 0 per cell (every disturbance that repeats
        every wagon when N is a multiple of H / L; skipped, "unknown", for a
        cell of differing sleepers whose Hill matrix has more than
        `railtrack.solvers.stability_hint.QUICK_CELL_SIZE` rows, e.g. 30 sleepers at m > 6), "full" at every
        phase (tens of solves' cost), "off" marks every draw "unknown".
    progress : bool or None
        A ``tqdm`` progress bar (on stderr, or a notebook widget): None shows it
        from `PROGRESS_DRAWS` draws on, True or False force it.
    executor : concurrent.futures.Executor, optional
        Runs the chunks of draws (a ``ProcessPoolExecutor``, a Dask ``Client``);
        default: this process.  The results do not depend on it.

    Returns
    -------
    RandomSupport

    Examples
    --------
    >>> import railtrack as rt
    >>> sample = random_support(rt.Track.paper(), rt.Train.paper(),
    ...                         rt.LinearFoundation(20e6, 2e5), sleepers=10, draws=3)
    >>> sample.peak_seat_load.shape, bool(sample.converged.all())
    ((3,), True)
    """
    draws, seed = require_count("draws", draws, 1), require_count("seed", seed, 0)
    sleepers = cell_size(sleepers)
    require_non_negative("variation", variation)     # True is no coefficient of variation
    if not (isinstance(harmonics, str) and harmonics == "auto"):
        require_count("harmonics", harmonics, 1)
    shown = show_progress(progress, draws >= PROGRESS_DRAWS)
    passage = Passage(track, train)
    rng = np.random.default_rng(seed)
    factors = lognormal_factors(variation, (draws, sleepers), rng)
    base = SleeperCell.identical(passage, foundation, sleepers)
    law = base.foundations[0]
    if isinstance(law, LinearFoundation):
        found = linear_draws(passage, base, law, factors, harmonics, accuracy=DEFAULT_ACCURACY,
                             executor=executor, progress=shown)
        # cell_verdict's rule for a cell on linear laws: stable once converged
        verdicts = np.where(found["converged"], "stable", "unknown").astype("<U8")
        short = _warn_truncation(found, harmonics)
        values = (found["seat"], found["moment"], found["converged"], found["harmonics"])
        values += (verdicts,)
        # a draw the batch did not converge, or where "auto" fell short of its accuracy,
        # is solved alone: `railtrack.solve` decides (a failure, converged=False, if short)
        for k in np.flatnonzero(~found["converged"] | short):
            row = draw_chunk(track, train, [draw_cell(base, factors[k])], harmonics,
                              stability)
            for array, value in zip(values, row):
                array[k] = value[0]
    else:
        bounds = chunk_bounds(draws, 1 if executor is None else 10)
        parts = map_chunks(draw_chunk, [(track, train, [draw_cell(base, row) for row in
                                                          factors[a:b]], harmonics, stability)
                                         for a, b in bounds],
                           [b - a for a, b in bounds], executor=executor, progress=shown,
                           description="random_support")
        values = tuple(np.concatenate([part[i] for part in parts]) for i in range(5))
    seat, moment, converged, used, verdicts = values
    result = RandomSupport(float(variation), factors, seat, moment, converged, used,
                           verdicts.astype("<U8"), inputs=dict(
                               track=track, train=train, foundation=foundation,
                               sleepers=sleepers, draws=draws, seed=seed,
                               harmonics=harmonics, stability=stability))
    if np.any(verdicts == "unstable"):
        warnings.warn(UnstableSolutionWarning(
            f"{int(np.sum(verdicts == 'unstable'))} of {draws} draws are unstable periodic "
            "states (RandomSupport.stability): a train does not stay on them, and their peaks "
            f"need not be what the track carries. {result.summary()}"), stacklevel=2)
    return result


def _warn_truncation(found: dict, harmonics) -> np.ndarray:
    """The converged draws that "auto" left short of its accuracy (to be solved alone).

    An explicit m: none, and one `TruncationWarning` for the converged draws
    whose estimate exceeds 1 %.
    """
    over = found["converged"] & (found["error"] > (
        DEFAULT_ACCURACY if isinstance(harmonics, str) else WARN_TRUNCATION))
    if isinstance(harmonics, str):
        return over
    if over.any():
        worst = int(np.nanargmax(np.where(over, found["error"], np.nan)))
        warnings.warn(TruncationWarning(
            f"{int(over.sum())} of {over.size} draws have an estimated truncation error above "
            f"{WARN_TRUNCATION:.1%} of their largest sleeper peak (worst "
            f"{found['error'][worst]:.1%} at harmonics={found['harmonics'][worst]}); pass a "
            "larger harmonics"), stacklevel=3)
    return np.zeros_like(over)
