"""Which periodic solution the track reaches: stability judged by the time domain.

Harmonic balance finds periodic solutions, stable or not, and a nonlinear
foundation may have several at one speed.  `check_stability` starts the
finite-element ring (`railtrack.simulate_time_domain`) on a solution's state
at t = 0 and watches, period by period, how far the sleeper's response
drifts from it.  The ring's own discretization keeps it ~1e-6 of the peak
from any harmonic-balance solution, and the solution's truncation error adds
its share: that residue is the disturbance.  On a stable solution it dies
out; on an unstable one it grows, by a factor per period that the distance
history shows, until the track settles on another periodic state, on none,
or grows without bound.

What a ring of one wagon can and cannot reveal
----------------------------------------------
The ring of length H is periodic in space, so it carries only disturbances
that repeat every wagon: the Bloch wavenumber 0 of the periodic track, any
temporal form (growth at any frequency, in phase or not with the wheels).  A
solution that is stable on that ring may still be unstable to disturbances
of spatial period 2H, 3H, ... (period doubling, subharmonics) or to
wavetrains longer than the ring, which a ring of n wagons
(``wagons=n``: the train tiled into one super-wagon of length n H,
`tiled_train`) carries for every wavenumber that fits n times; the solution,
periodic over H, is periodic over n H as well and seeds that ring.  No
finite ring tests every wavenumber of the endless track: "stays" means
stable to the disturbances that fit the ring.

The result, `StabilityCheck`, and the growth rates read off the record are
in `railtrack.studies.stability_verdict`.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..timedomain.fem import ring_mesh
from ..timedomain.ring_state import ring_state_from_solution
from ..timedomain.spectrum import Spectrum, record_spectrum
from ..solvers.solution import ConvergenceWarning
from ..timedomain.simulation import simulate_time_domain
from ..model.passage import Passage
from ..model.track import require_non_negative, require_positive
from ..solvers.arguments import require_count
from ..model.train import Train
from .stability_verdict import (SLOW_GROWTH, StabilityCheck, distance_growth as _growth,
                                period_change_growth as _change_growth)

__all__ = ["Spectrum", "record_spectrum", "tiled_train", "StabilityCheck", "check_stability"]


def tiled_train(train: Train, wagons: int) -> Train:
    """`wagons` wagons of `train` as one super-wagon of length n H (the axle list tiled).

    Examples
    --------
    >>> tiled_train(Train.paper(), 2).axle_positions
    (0.0, 3.0, 18.0, 21.0)
    """
    if isinstance(wagons, bool) or not isinstance(wagons, (int, np.integer)) or wagons < 1:
        raise ValueError(f"wagons must be an integer >= 1; got {wagons!r}")
    length = float(train.wagon_length)
    positions = (length * np.arange(wagons)[:, None] + np.asarray(train.axle_positions)).ravel()
    return Train(wagons * length, positions, np.tile(train.axle_loads, wagons), train.speed)


def check_stability(solution, periods: int = 20, tol: float = 1e-2, elements_per_span: int = 8,
                    steps_per_period: int | None = None, *, wagons: int = 1,
                    max_periods: int = 200, settle_tol: float = 1e-6,
                    quasi_periodic: float = 1e-3,
                    warn_step_error: float | None = None, kick: float = 0.0,
                    seed: int = 0) -> StabilityCheck:
    """Does the track stay on a periodic solution?  The ring started on it tells.

    The ring (`simulate_time_domain`, ``start=solution``) is integrated for
    `periods` periods; the solution "stays" if sleeper 0 remains within
    ``tol`` times its peak of the solution in every one of them.  Otherwise
    the run goes on, up to `max_periods` in all, until the response repeats
    (period-to-period change <= `settle_tol`): "leaves" for that periodic
    state, or "not periodic" if it never repeats (the message says whether
    the spectrum of the record has lines between the multiples of v / H,
    `interharmonic_fraction` > `quasi_periodic`: a quasi-periodic or chaotic
    response, or none: a transient still dying out).  A response that grows
    without bound "diverges".  Only disturbances that fit the ring are
    tested: periodic over the ring's n H (see the module docstring;
    ``wagons=n`` for a ring of n wagons).

    Parameters
    ----------
    solution : railtrack.Solution
        A converged periodic solution; its track's H / L must be an integer.
    periods : int
        Periods watched for the verdict "stays" (>= 2).
    tol : float
        Distance from the solution, over its peak, that still counts as
        staying [-].  It must exceed the ring's discretization error and the
        solution's `truncation_error`.
    elements_per_span, steps_per_period : int
        The ring's mesh; steps default to 80 per sleeper on the ring.
    wagons : int
        Wagons on the ring (`tiled_train`).
    max_periods : int
        Periods integrated at most in all.
    settle_tol : float
        Period-to-period change at which a departed response counts as periodic [-].
    quasi_periodic : float
        Interharmonic fraction above which "not periodic" is called quasi-periodic [-].
    warn_step_error : float or None
        Passed to `simulate_time_domain`.
    kick : float
        A disturbance added to the start: each sleeper's displacement moved
        by `kick` times the solution's peak times a standard normal draw
        (NumPy's generator seeded with `seed`) [-].  Without it the ring
        starts on the solution up to its own discretization residue, which
        repeats every wagon: on a ring of several wagons a disturbance of
        another wavelength then starts from round-off and may not show
        within the watch.
    seed : int
        Seed of the kick's draws.

    Returns
    -------
    StabilityCheck

    Examples
    --------
    >>> from railtrack import Track, Train, LinearFoundation, solve
    >>> s = solve(Track.paper(), Train.paper(), LinearFoundation.paper(), harmonics=60)
    >>> check = check_stability(s, periods=3, elements_per_span=2, steps_per_period=600)
    >>> check.verdict, bool(check.distance.max() < 1e-3)
    ('stays', True)
    """
    periods = require_count("periods", periods, 2)
    max_periods = require_count("max_periods", max_periods, periods)
    seed = require_count("seed", seed, 0)
    for name, value in (("tol", tol), ("settle_tol", settle_tol), ("quasi_periodic", quasi_periodic)):
        require_positive(name, value)    # a TypeError for a string, before any comparison
    require_non_negative("kick", kick)
    if not kick < tol:
        raise ValueError(f"kick must be a finite number in [0, tol = {tol:g}); got {kick!r}")
    if hasattr(solution, "cell") or hasattr(solution, "wheel"):
        kind = "SleeperCell" if hasattr(solution, "cell") else "wheel"
        raise TypeError(f"check_stability starts the ring on one sleeper's solution; a {kind} "
                        "solution is judged by rt.floquet(solution) (Hill's matrix; cells only) "
                        "or rt.ring_multipliers(solution) (cells), and a wheel solution by "
                        "rt.simulate_time_domain(..., wheel=...)")
    if not getattr(solution, "converged", False):
        # An unconverged iterate is no periodic solution: the ring would leave
        # it whatever its stability, and the verdict would say "leaves".
        raise ValueError(
            "check_stability needs a converged solution; this one is not converged "
            f"({getattr(solution, 'message', 'no message')}).  Solve again with more "
            "iterations, another method or a nearby start (rt.continuation)")
    truncation = float(getattr(solution, "truncation_error", float("nan")))
    if truncation > 0.5 * tol:
        # The ring keeps every harmonic: it leaves a truncated solution for the
        # periodic state nearby by about the truncation error, stable or not.
        raise ValueError(
            f"the solution's truncation error {truncation:.2g} exceeds half the check's "
            f"tolerance, tol / 2 = {0.5 * tol:g}: the ring would leave it for the periodic state "
            "it approximates.  Solve with more harmonics (harmonics='auto'), or judge it by "
            "rt.floquet, which does not depend on the ring")
    train = tiled_train(solution.train, wagons)
    sleepers = round(float(train.wagon_length) / float(solution.track.sleeper_spacing))
    steps = 80 * sleepers if steps_per_period is None else steps_per_period
    run = dict(elements_per_span=elements_per_span, steps_per_period=steps, tol=settle_tol,
               warn_step_error=warn_step_error)
    records: list[np.ndarray] = []
    try:
        start = solution
        if kick:
            mesh = ring_mesh(Passage(solution.track, train), elements_per_span)
            u, v = ring_state_from_solution(mesh, solution)
            peak = float(np.max(np.abs(solution.one_period()[1])))
            draws = np.random.default_rng(seed).standard_normal(mesh.n_sleepers)
            u[mesh.sleeper_dofs] += kick * peak * draws
            start = (u, v)
        first = simulate_time_domain(solution.track, train, solution.foundation, start=start,
                                     min_periods=periods, max_periods=periods, **run)
        records.append(first.sleeper_history)
        last = first
        reference = solution.sleeper_displacement(first.times)
        peak = float(np.max(np.abs(reference)))
        distance = np.max(np.abs(first.sleeper_history - reference), axis=1) / peak
        # Still within tol but growing: an instability that has not shown yet.
        if (distance.max() > tol or _change_growth(first.sleeper_history, peak) > SLOW_GROWTH) \
                and max_periods > periods:
            with warnings.catch_warnings():
                # a ring that does not repeat is what this check reads and reports itself
                warnings.simplefilter("ignore", ConvergenceWarning)
                last = simulate_time_domain(solution.track, train, solution.foundation,
                                            start=first.final_state,
                                            max_periods=max_periods - periods, **run)
            records.append(last.sleeper_history)
    except RuntimeError as error:
        done = int(sum(r.shape[0] for r in records))
        return StabilityCheck(False, "diverges", np.array([]), float("nan"), float("nan"),
                              float("nan"), float("nan"), float("nan"), float("nan"), done, wagons,
                              f"the ring started on the solution diverged: {error}",
                              np.concatenate(records) if records else np.empty((0, steps)))
    record = np.concatenate(records)
    distance = np.max(np.abs(record - reference), axis=1) / peak
    change = float(last.period_change[-1]) if last.period_change.size else float("nan")
    # The last half of the run, but at least two ring periods (periods=2 leaves one in the half).
    tail = record[min(record.shape[0] // 2, max(record.shape[0] - 2, 0)):]
    spectrum = record_spectrum(tail.ravel(), float(solution.period),
                               steps // wagons)
    growth, change_growth = _growth(distance), _change_growth(record, peak)
    low, high = (float(f(last.sleeper_displacements)) for f in (np.min, np.max))
    if distance.max() <= tol and change_growth > SLOW_GROWTH:
        verdict, low, high = "grows", float("nan"), float("nan")
        message = (f"grows: within {distance.max():.2g} of its peak of the solution over "
                   f"{record.shape[0]} periods (tol {tol:g}), but its change from one period to "
                   f"the next grows {change_growth:.3g}-fold per period: unstable, leaving too "
                   "slowly to leave tol within max_periods")
    elif distance.max() <= tol:
        verdict, low, high = "stays", float("nan"), float("nan")
        message = (f"stays: within {distance.max():.2g} of its peak of the solution "
                   f"over {record.shape[0]} periods on a ring of {wagons} wagon(s) (tol {tol:g}); "
                   f"distance growth {growth:.3g}, change growth {change_growth:.3g} per period")
    elif last.converged:
        verdict = "leaves"
        message = (f"leaves: the distance grew {growth:.3g}-fold per period and the ring "
                   f"settled after {record.shape[0]} periods on another periodic state, "
                   "sleepers between "
                   f"{1e3 * low:.4g} and {1e3 * high:.4g} mm (the solution: "
                   f"{1e3 * reference.min():.4g} to {1e3 * reference.max():.4g} mm)")
    else:
        verdict = "not periodic"
        kind = ("quasi-periodic: its spectrum has lines between the multiples of v/H "
                f"(interharmonic fraction {spectrum.interharmonic_fraction:.2g})"
                if spectrum.interharmonic_fraction > quasi_periodic else
                "its spectrum has almost no lines between the multiples of v/H "
                f"({spectrum.interharmonic_fraction:.2g}): a transient still dying out?")
        message = (f"not periodic: left the solution and after {record.shape[0]} periods still "
                   f"changes by {change:.2g} of its peak per period; {kind}")
    return StabilityCheck(verdict == "stays", verdict, distance, growth, change_growth, low, high,
                          change, spectrum.interharmonic_fraction, int(record.shape[0]), wagons,
                          message, record)
