"""The verdict of `railtrack.studies.stability.check_stability`, and the growth it reads.

`StabilityCheck` is what the ring did when started on a periodic solution:
stayed, grew, left for another periodic state, settled on none, or
diverged.  The growth per period is read off the record as the exponential
of a least-squares slope of its logarithm: of the distance from the solution
while it is small (the linear regime), and of the change from one period to
the next over the last half of the run, which shows a slow departure first
(`SLOW_GROWTH`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["VERDICTS", "SLOW_GROWTH", "StabilityCheck", "factor_per_period", "distance_growth",
           "period_change_growth"]

VERDICTS = ("stays", "grows", "leaves", "not periodic", "diverges")

SLOW_GROWTH = 1.01
"""Growth per period of the period-to-period change beyond which a run is unstable [-].

On the lightly damped cubic branch of chapter 10 the stable points checked
give 0.60-0.99 over 30 periods, the two unstable ones next to the torus
bifurcation 1.08 and 1.13, where the distance to the solution had only
grown from 6.0e-4 to 6.8e-4 and 1.4e-3 of the peak after 20 periods.
"""


@dataclass(frozen=True, eq=False)
class StabilityCheck:
    """What the ring did when started on a periodic solution (`check_stability`).

    Attributes
    ----------
    stable : bool
        True for the verdict "stays".
    verdict : {"stays", "grows", "leaves", "not periodic", "diverges"}
        Stayed within `tol` of the solution for the periods watched; stayed
        within `tol` but its period-to-period change grows (`change_growth`
        > `SLOW_GROWTH`: unstable, too slowly to leave within `max_periods`);
        left it for another periodic state; left it and settled on no
        periodic state within `max_periods`; grew without bound.
    distance : ndarray, shape (periods run,)
        max |w_TD - w_HB| of sleeper 0 over each period, over the peak |w_HB| [-].
    growth : float
        Geometric mean growth of `distance` per period while it was below
        0.1 (the linear regime) [-]: < 1 stable, > 1 unstable; NaN if unknown.
    change_growth : float
        The same for the change of sleeper 0 from one period to the next,
        over the last half of the periods run [-].  The distance holds the
        ring's constant offset from the harmonic-balance solution; the
        change does not, so a slow departure shows in it first.
    reached_min, reached_max : float
        Least and greatest sleeper displacement (all sleepers) over the last
        period of the state it went to [m]; NaN if it stayed or diverged.
    period_change : float
        Last period-to-period change of sleeper 0 over its peak [-].
    interharmonic_fraction : float
        `Spectrum.interharmonic_fraction` of sleeper 0 over the last half of
        the run (whole wagon periods) [-].
    periods : int
        Periods integrated.
    wagons : int
        Wagons on the ring.
    message : str
        The verdict in words, with the numbers.
    record : ndarray, shape (periods, steps)
        Sleeper 0 over every period [m].
    """

    stable: bool
    verdict: str
    distance: np.ndarray
    growth: float
    change_growth: float
    reached_min: float
    reached_max: float
    period_change: float
    interharmonic_fraction: float
    periods: int
    wagons: int
    message: str
    record: np.ndarray


def factor_per_period(periods: np.ndarray, values: np.ndarray, fewest: int) -> float:
    """exp of the least-squares slope of log(values) against the period index (NaN if too few)."""
    if values.size < fewest:
        return float("nan")
    return float(np.exp(np.polyfit(periods, np.log(values), 1)[0]))


def distance_growth(distance: np.ndarray) -> float:
    """Mean factor per period of the distance while linear (below 0.1 of the peak)."""
    linear = distance[: int(np.argmax(distance > 0.1))] if np.any(distance > 0.1) else distance
    return factor_per_period(np.arange(linear.size), linear, fewest=3)


def period_change_growth(record: np.ndarray, peak: float) -> float:
    """Factor per period of the period-to-period change over the last half of `record`."""
    change = np.max(np.abs(np.diff(record, axis=0)), axis=1) / peak
    index = np.arange(change.size)[change.size // 2:]
    index = index[change[index] > 1e-12]          # below that: round-off, not a trend
    return factor_per_period(index, change[index], fewest=4)
