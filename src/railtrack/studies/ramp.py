"""The jump phenomenon: the time-domain ring carried through a sequence of speeds.

Where the harmonic-balance branch of a nonlinear foundation folds, two
stable periodic states coexist at one speed, and which one the track is on
depends on where it came from.  `speed_ramp` runs the ring
(`railtrack.simulate_time_domain`) at each speed of a sequence until its
response repeats, starting each from the steady state of the one before:
rising, then falling speeds jump from one branch to the other at different
speeds (hysteresis).

Why the end state of one speed is a valid start for the next: at the end of
a period the wheels are back at their t = 0 places on the ring, whatever the
speed.  The displacements are kept.  The velocities are scaled by
v_new / v_old: in a state that travels with the train, w(x, t) ~ W(x - v t),
so u' = -v W' scales with v; what the discrete sleepers add to that
(w(x + L, t) = w(x, t - L / v) only at whole spans) is a small transient that
the run then damps out.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ..timedomain.spectrum import record_spectrum
from ..solvers.solution import ConvergenceWarning
from ..timedomain.fem import sleepers_on_ring
from ..timedomain.runcost import LONG_RUN_SECONDS, TYPICAL_PERIODS, estimate_run_cost
from ..timedomain.simulation import simulate_time_domain
from ..model.passage import Passage
from ..solvers.progress import progress_bar, show_progress
from ..model.track import Track
from ..model.train import Train
from ..solvers.threads import blas_threads

__all__ = ["SpeedRamp", "speed_ramp"]


@dataclass(frozen=True, eq=False)
class SpeedRamp:
    """Steady states of the ring along a sequence of speeds (`speed_ramp`).

    Attributes
    ----------
    speeds : ndarray, shape (S,)
        The speeds, in the order run [m/s].
    minimum, maximum : ndarray, shape (S,)
        Least and greatest displacement of any sleeper over the last period [m].
    converged : ndarray of bool, shape (S,)
        Whether the response repeated within `tol` at that speed.
    periods : ndarray of int, shape (S,)
        Periods integrated at that speed.
    interharmonic_fraction : ndarray, shape (S,)
        `railtrack.studies.stability.Spectrum.interharmonic_fraction` of sleeper 0
        over the last half of the periods run at that speed [-]: near 0 for a
        periodic response or a dying transient; lines between the multiples
        of v / H (a quasi-periodic response) make it large.
    final_state : (ndarray, ndarray)
        The ring's state after the last speed, to continue the ramp.
    """

    speeds: np.ndarray
    minimum: np.ndarray
    maximum: np.ndarray
    converged: np.ndarray
    periods: np.ndarray
    interharmonic_fraction: np.ndarray
    final_state: tuple[np.ndarray, np.ndarray]


def _interharmonic(result) -> float:
    """Interharmonic fraction of sleeper 0 over the last half of a run (0 for < 4 periods)."""
    history = result.sleeper_history
    if history.shape[0] < 4:
        return 0.0
    # the fraction compares lines, so the period's value (here 1) does not matter
    return record_spectrum(history[history.shape[0] // 2:].ravel(), 1.0,
                           history.shape[1]).interharmonic_fraction


def speed_ramp(track: Track, train: Train, foundation, speeds, elements_per_span: int = 8,
               steps_per_period: int = 2400, *, tol: float = 1e-6, max_periods: int = 100,
               start="static", warn_step_error: float | None = None,
               progress: bool | None = None) -> SpeedRamp:
    """Steady response of the ring at each speed, each run started from the previous one.

    Parameters
    ----------
    track, train : Track, Train
        The train's speed is replaced by each of `speeds`; H / L an integer.
    foundation : foundation object or callable
    speeds : sequence of float
        Speeds in the order to run them, e.g. rising then falling [m/s].
    elements_per_span, steps_per_period, tol, max_periods, warn_step_error
        As in `simulate_time_domain`, for every speed.
    start : {"static", "rest"}, Solution or (u, v)
        Start of the first speed.  Each later speed starts from the previous
        one's end state, its velocities scaled by the ratio of the speeds
        (see the module docstring).
    progress : bool or None
        A ``tqdm`` bar counting the speeds (`railtrack.solvers.progress`):
        None shows it when the ring's estimated time for a typical run
        (`railtrack.timedomain.runcost`) times the number of speeds passes
        a minute, True or False force it.

    Returns
    -------
    SpeedRamp

    Examples
    --------
    >>> from railtrack import LinearFoundation
    >>> ramp = speed_ramp(Track.paper(), Train.paper(), LinearFoundation.paper(), [40.0, 45.0], 2, 480)
    >>> ramp.converged.tolist(), round(1e3 * float(ramp.minimum[1]), 2)
    ([True, True], -1.13)
    """
    with blas_threads(1):
        speeds = np.asarray(speeds, dtype=float).ravel()
        if speeds.size == 0 or not np.all(np.isfinite(speeds) & (speeds > 0)):
            raise ValueError(f"speeds must be a non-empty sequence of finite speeds > 0; got {speeds!r}")
        try:
            cost = estimate_run_cost(sleepers_on_ring(Passage(track, train)), elements_per_span,
                                     steps_per_period).seconds(min(TYPICAL_PERIODS, max_periods))
        except (TypeError, ValueError):
            cost = 0.0  # the first run refuses the arguments with its own message
        shown = show_progress(progress, speeds.size * cost > LONG_RUN_SECONDS)
        with progress_bar(shown, speeds.size, "speed_ramp", "speeds") as bar:
            results = _ramp(track, train, foundation, speeds, start, bar,
                            dict(elements_per_span=elements_per_span,
                                 steps_per_period=steps_per_period, tol=tol,
                                 max_periods=max_periods, warn_step_error=warn_step_error))
        return SpeedRamp(
            speeds=speeds,
            minimum=np.array([float(r.sleeper_displacements.min()) for r in results]),
            maximum=np.array([float(r.sleeper_displacements.max()) for r in results]),
            converged=np.array([r.converged for r in results]),
            periods=np.array([r.periods for r in results]),
            interharmonic_fraction=np.array([_interharmonic(r) for r in results]),
            final_state=results[-1].final_state,
        )


def _ramp(track, train, foundation, speeds, state, bar, run) -> list:
    """The ring at each speed from the previous one's end state; `bar` counts the speeds."""
    results, previous = [], None
    for count, speed in enumerate(speeds, 1):
        if previous is not None:
            u, v = state
            state = (u, v * (speed / previous))
        with warnings.catch_warnings():
            # SpeedRamp.converged reports each speed; a warning per speed would repeat it
            warnings.simplefilter("ignore", ConvergenceWarning)
            result = simulate_time_domain(track, train.replace(speed=float(speed)), foundation,
                                          start=state, progress=False, **run)
        results.append(result)
        state, previous = result.final_state, speed
        bar.to(count, f"{speed:g} m/s")
    return results
