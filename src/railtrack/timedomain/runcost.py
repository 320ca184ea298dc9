"""What a time-domain run will cost, estimated before anything is allocated.

`simulate_time_domain` keeps every sleeper's displacement over one period
(steps_per_period x H/L floats, twice: the record and the result's copy) and
the wheel loads of every step, and factors a ring of 2 H/L e + H/L degrees
of freedom whose condensed response A^-1 U is a dense n_dofs x H/L array.
Its time is steps x periods x the cost of one step, a sparse
back-substitution and a product with that dense array plus Python's
overhead.  `check_run_cost` refuses a run that would not fit in
`MEMORY_LIMIT` and warns (`LongRunWarning`) when one would take longer than
`LONG_RUN_SECONDS`.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

__all__ = [
    "LongRunWarning",
    "MEMORY_LIMIT",
    "LONG_RUN_SECONDS",
    "TYPICAL_PERIODS",
    "RunCost",
    "estimate_run_cost",
    "check_run_cost",
]

MEMORY_LIMIT = 4e9
"""Largest estimated memory of a run accepted [bytes]."""

LONG_RUN_SECONDS = 60.0
"""Estimated run time above which `LongRunWarning` is issued [s].

A minute: the default ring takes well under a second a period, so a run
estimated at a minute or more has sizes far beyond the defaults.  (It was
ten minutes, and `elements_per_span=2000`, estimated at 7 min for five
periods, ran 65 s to 294 s without a word.)
"""

TYPICAL_PERIODS = 5
"""Periods a run usually needs from the static start (3 to 5 on the paper's laws)."""

# Measured on a 2-core machine (paper's track, one period, OMP_NUM_THREADS=1):
# linear law 0.17, 0.59, 1.97, 4.5, 9.9 and 19.9 s a period at 8, 64, 250,
# 500, 1000 and 2000 elements per span, the tensionless law 0.24 s at 8:
# ~1e-4 s of overhead per step, Newton's few iterations included, plus
# 1.5e-9 to 2.3e-9 s per entry of the dense n_dofs x H/L response (the
# sparse solve grows like it).  The constants below err on the long side:
# 1.2 to 2.6 times the linear law's times.
_SECONDS_PER_STEP = 1.5e-4
_SECONDS_PER_RESPONSE_ENTRY = 2.5e-9
# Per step and sleeper: its displacement twice (the period and its copy),
# and four floats of `ring_fields.SleeperRecorder` and one of the foundation
# forces, the output of every sleeper, and for a cell the previous period's
# record (the 8 * 8 n_sleepers bytes); five
# 8-byte arrays (times, rail twice, two periods of sleeper 0) and 8
# wheel-load entries (int64 DOF and float64 value), twice for their
# temporaries.
_BYTES_PER_SLEEPER_STEP = 8 * 8
_BYTES_PER_LOAD_STEP = 2 * 8 * (8 + 8) + 5 * 8
# Per DOF: the sparse M, C, K, the Newmark matrix, its history product and
# LU factors, ~100 bytes per matrix (generous).
_BYTES_PER_DOF = 2000


class LongRunWarning(UserWarning):
    """A time-domain run is estimated to take longer than `LONG_RUN_SECONDS`."""


@dataclass(frozen=True)
class RunCost:
    """Estimated cost of a run of `simulate_time_domain`.

    Attributes
    ----------
    memory : float
        Peak memory [bytes].
    seconds_per_period : float
        Wall time of one period [s].
    n_dofs : int
        Degrees of freedom of the ring.
    """

    memory: float
    seconds_per_period: float
    n_dofs: int

    def seconds(self, periods: int) -> float:
        """Wall time of `periods` periods [s]."""
        return periods * self.seconds_per_period


def estimate_run_cost(n_sleepers: int, elements_per_span: int, steps_per_period: int) -> RunCost:
    """Memory and time of a run, from the sizes alone (nothing is allocated).

    Examples
    --------
    >>> cost = estimate_run_cost(30, 8, 2400)
    >>> f"{cost.memory / 1e6:.1f} MB, {cost.seconds_per_period:.1f} s per period"
    '6.6 MB, 0.5 s per period'
    """
    n_dofs = (2 * elements_per_span + 1) * n_sleepers
    response = float(n_dofs) * n_sleepers  # entries of A^-1 U, and of U itself
    memory = (
        float(steps_per_period) * (_BYTES_PER_SLEEPER_STEP * n_sleepers + _BYTES_PER_LOAD_STEP)
        + 2 * 8.0 * response
        + float(n_dofs) * _BYTES_PER_DOF
    )
    seconds = float(steps_per_period) * (_SECONDS_PER_STEP + _SECONDS_PER_RESPONSE_ENTRY * response)
    return RunCost(memory, seconds, n_dofs)


def _duration(seconds: float) -> str:
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


def check_run_cost(
    n_sleepers: int, elements_per_span: int, steps_per_period: int, max_periods: int,
    stacklevel: int = 3,
) -> RunCost:
    """Refuse a run that would exhaust memory; warn about one that would take long.

    The warning's `stacklevel` (default: the caller of the function that calls this).

    Raises
    ------
    ValueError
        If the estimated memory exceeds `MEMORY_LIMIT`.

    Warns
    -----
    LongRunWarning
        If `TYPICAL_PERIODS` periods (or `max_periods`, if fewer) are
        estimated to take longer than `LONG_RUN_SECONDS`.
    """
    cost = estimate_run_cost(n_sleepers, elements_per_span, steps_per_period)
    sizes = f"steps_per_period = {steps_per_period}, elements_per_span = {elements_per_span}"
    if cost.memory > MEMORY_LIMIT:
        raise ValueError(
            f"{sizes} would need about {cost.memory / 1e9:.3g} GB of memory "
            f"({cost.n_dofs} DOFs; {n_sleepers} sleepers recorded at every step), above the "
            f"{MEMORY_LIMIT / 1e9:g} GB limit (railtrack.timedomain.runcost.MEMORY_LIMIT), and about "
            f"{_duration(cost.seconds_per_period)} per period. Use fewer steps or elements: "
            "the defaults 2400 and 8 are accurate to ~1e-6 of the peak on the paper's track"
        )
    periods = min(TYPICAL_PERIODS, max_periods)
    if cost.seconds(periods) > LONG_RUN_SECONDS:
        warnings.warn(
            f"{sizes} is estimated to take {_duration(cost.seconds_per_period)} per period, "
            f"{_duration(cost.seconds(periods))} for {periods} periods (up to "
            f"{_duration(cost.seconds(max_periods))} for max_periods = {max_periods}); "
            "fewer steps or elements would be faster",
            LongRunWarning,
            stacklevel=stacklevel,
        )
    return cost
