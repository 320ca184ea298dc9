"""Statistics of the dynamic wheel load: a Monte Carlo over random rails (issue 32).

Realisation i is the `RandomProfile` of the spectrum with seed
``seed + i`` (i = 0 .. N-1), repeating every `wagons` wagon lengths, and
the vehicle's steady ride over it on the track, `railtrack.solve` with
``wheel=vehicle`` and ``profile=`` that rail: Hertz contact, the vehicle
above, the track's law below, every check of `railtrack.solve` applied.
Each solve starts from its own linear guess: the wheel path of
`railtrack.solve` refuses ``initial``, so nothing is warm-started.

The wheel load is the contact force P_k(t) of `WheelSolution.contact_force`
on the modelled rail (half a wheelset's), sampled at `samples` instants
evenly over the period.  Wheel k of every wagon of the period counts as
wheel k.  Pooled over time and over the realisations that converged,
per wheel: the mean, the standard deviation sigma, and the central
intervals holding 68.3 / 95.5 / 99.7 % of the samples (the empirical
quantiles at (1 -+ p) / 2), beside Q -+ 1, 2, 3 sigma (Q the static
load), which bound the same fractions if P is normal (Eisenmann's reading,
`railtrack.equations.eisenmann`).  Realisations that did not converge are
counted in ``converged`` and left out of the pooled values, never dropped
unseen; so are the solves that ``harmonics="auto"`` leaves short of its
accuracy (stopped at its cap, as where the wheels leave the rail: a
failure of `railtrack.solve`, ``converged=False``), their estimate kept in
``truncation``.  An explicit m whose estimate exceeds the accuracy is kept
in the pool and warned about once.

The ride over the smooth rail (one more solve) is kept too: on a sleepered
track the wheel load varies as the wheels pass the sleepers even without
an irregularity.  For a nearly linear contact the two add in variance,
sigma^2 = sigma_smooth^2 + sigma_rail^2 (their harmonics differ: see
docs/wheel_load_statistics.md), and sigma_rail is what the spectral
integral `railtrack.equations.track_wheel_load.track_wheel_load_std`
gives.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field

import numpy as np

from ..model.plausibility_check import warn_implausible
from ..model.random_profile import RandomProfile
from ..model.vehicle import Vehicle
from ..solvers.arguments import require_count
from ..solvers.auto_harmonics import DEFAULT_ACCURACY
from ..solvers.convergence import ConvergenceWarning, TruncationWarning
from ..solvers.progress import progress_bar, show_progress
from ..solvers.solve import solve

__all__ = ["WheelLoadStatistics", "wheel_load_statistics", "LEVELS", "PROGRESS_REALISATIONS",
           "SERVICE_SPEED"]

LEVELS = (0.683, 0.955, 0.997)
"""The fractions of the wheel load inside Q -+ t sigma, t = 1, 2, 3, if it is normal."""

PROGRESS_REALISATIONS = 50
"""With ``progress=None`` the bar is shown from this many realisations (~20 s)."""

SERVICE_SPEED = 350.0 / 3.6
"""97.2 m/s (350 km/h), the fastest trains in passenger service, as commonly quoted.

A faster speed warns `PlausibilityWarning` before any solve: 160 typed
for 160 km/h is 160 m/s, near the 159.7 m/s world record [tgvrecord2007].
On the README's example (ballasted track, FRA class 4) at 160 m/s the
wheels leave the rail and the first realisation fails after 72-196 s (on a
shared 2-core machine; 0.3 s at 45 m/s).  A first realisation that fails
is warned about at once (`ConvergenceWarning`), before the others run.
"""


@dataclass(frozen=True, repr=False)
class WheelLoadStatistics:
    """The wheel loads of a Monte Carlo over random rails (module docstring).

    Attributes
    ----------
    static_load : float
        Q [N], each wheel's static load on the modelled rail.
    seeds : ndarray of int, shape (N,)
        The `RandomProfile` seed of each realisation.
    std : ndarray, shape (N, 4)
        Each realisation's standard deviation of P_k over time [N].
    peak : ndarray, shape (N, 4)
        Each realisation's largest P_k over time [N].
    converged : ndarray of bool, shape (N,)
    harmonics : ndarray of int, shape (N,)
        m of each solve.
    truncation : ndarray, shape (N,)
        Each solve's estimated truncation error of the contact force, over Q
        [-] (`WheelSolution.truncation_error`; NaN if not estimated).
    mean : ndarray, shape (4,)
        P_k pooled over time and the converged realisations [N].
    pooled_std : ndarray, shape (4,)
        sigma_k, pooled likewise [N].
    lower, upper : ndarray, shape (3, 4)
        The empirical quantiles (1 - p) / 2 and (1 + p) / 2 of P_k, pooled, for
        p in `LEVELS`: the central interval holding the fraction p [N].
    smooth_std : ndarray, shape (4,)
        sigma_k over time on the smooth rail: the sleepers passing [N].
    """

    static_load: float
    seeds: np.ndarray
    std: np.ndarray
    peak: np.ndarray
    converged: np.ndarray
    harmonics: np.ndarray
    truncation: np.ndarray
    mean: np.ndarray
    pooled_std: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    smooth_std: np.ndarray
    inputs: dict | None = field(default=None, compare=False)

    @property
    def failed(self) -> int:
        """How many realisations did not converge (left out of the pooled values)."""
        return int(np.sum(~self.converged))

    @property
    def normal_bounds(self) -> np.ndarray:
        """Q + t sigma_k for t = 1, 2, 3 [N], shape (3, 4): beside `upper`."""
        return self.static_load + np.outer([1.0, 2.0, 3.0], self.pooled_std)

    @property
    def rail_std(self) -> np.ndarray:
        """sqrt(sigma_k^2 - sigma_smooth,k^2) [N]: the part the rail's irregularity adds."""
        return np.sqrt(np.maximum(self.pooled_std ** 2 - self.smooth_std ** 2, 0.0))

    def summary(self) -> str:
        """Realisations, failures, and sigma / Q and the 99.7 % bound per wheel, 2 digits."""
        ratio = " ".join(f"{s:.2f}" for s in self.pooled_std / self.static_load)
        top = " ".join(f"{u:.2f}" for u in self.upper[-1] / self.static_load)
        return (f"{self.converged.size} realisations, {self.failed} not converged; "
                f"sigma/Q per wheel {ratio}; 99.85 % quantile / Q {top}")

    def __repr__(self) -> str:
        return f"WheelLoadStatistics({self.summary()})"


def wheel_load_statistics(track, foundation, vehicle: Vehicle, spectrum, speed: float, *,
                          wagon_length: float, wavelengths=(1.5, 25.0), wagons: int = 1,
                          realisations: int = 20, seed: int = 0, harmonics="auto",
                          samples: int = 2048, progress=None) -> WheelLoadStatistics:
    """A Monte Carlo of the wheel load over `realisations` random rails (module docstring).

    Parameters
    ----------
    track, foundation
        As `railtrack.solve`.
    vehicle : Vehicle
    spectrum : callable
        S(Omega) [m^2/(rad/m)], one-sided (`railtrack.model.irregularity`).
    speed : float
        v [m/s].
    wagon_length : float
        H [m], a whole number of sleeper spacings.
    wavelengths : (float, float)
        (lambda_min, lambda_max) [m], the band of the rail.
    wagons : int
        The rail repeats every `wagons` H (>= 1): a longer period resolves the
        spectrum more finely (`RandomProfile`), at more cost per solve.
    realisations : int
        N >= 2 (a standard deviation over realisations needs two).
    seed : int
        The first seed, >= 0; realisation i uses ``seed + i``.
    harmonics : int or "auto"
        As `railtrack.solve`.
    samples : int
        Instants per period at which P_k is sampled, >= 64.
    progress : bool or None
        A ``tqdm`` bar: None shows it from `PROGRESS_REALISATIONS` on.

    Returns
    -------
    WheelLoadStatistics

    Examples
    --------
    >>> import railtrack as rt
    >>> from railtrack.model.irregularity import FRASpectrum
    >>> car = rt.Vehicle.manchester()
    >>> found = wheel_load_statistics(rt.Track.paper(), rt.LinearFoundation.paper(), car,
    ...     FRASpectrum(6), 45.0, wagon_length=26.4, realisations=2)
    >>> found.failed, bool(abs(found.mean[0] / found.static_load - 1) < 1e-6)
    (0, True)
    """
    if isinstance(speed, (int, float, np.floating, np.integer)) and speed > SERVICE_SPEED:
        warn_implausible(f"speed = {speed:g} m/s ({3.6 * speed:.0f} km/h), above the fastest "
                         f"trains in service ({3.6 * SERVICE_SPEED:.0f} km/h): km/h? "
                         f"({speed:g} km/h = {speed / 3.6:.3g} m/s); over a rough rail the "
                         "wheels may leave it, and each failed realisation takes a minute or more")
    if not isinstance(vehicle, Vehicle):
        raise TypeError(f"vehicle must be a railtrack.Vehicle; got {type(vehicle).__name__}")
    count = require_count("realisations", realisations, 2)
    first = require_count("seed", seed, 0)
    wagons = require_count("wagons", wagons, 1)
    samples = require_count("samples", samples, 64)
    shown = show_progress(progress, count >= PROGRESS_REALISATIONS)
    train = vehicle.train(wagon_length, speed)
    period = wagons * float(train.wagon_length)
    load = vehicle.static_wheel_load()
    seeds = np.arange(first, first + count)
    std, peak = np.zeros((count, 4)), np.zeros((count, 4))
    converged, used = np.zeros(count, dtype=bool), np.zeros(count, dtype=int)
    truncation = np.full(count, np.nan)
    pooled = []

    def ride(profile, tiles):
        found = solve(track, train, foundation, harmonics, wheel=vehicle, profile=profile)
        times = np.arange(samples) * found.period / samples
        forces = found.contact_force(times).reshape(tiles, 4, samples)
        return found, np.moveaxis(forces, 0, 1).reshape(4, tiles * samples)

    smooth, forces = ride(None, 1)
    if not smooth.converged:
        raise RuntimeError(f"the ride over the smooth rail did not converge: {smooth.message}")
    smooth_std = forces.std(axis=1)
    with progress_bar(shown, count, "random rails", "rails") as bar:
        for i, value in enumerate(seeds):
            rail = RandomProfile(spectrum, wavelengths, period, int(value))
            start = time.perf_counter()
            with warnings.catch_warnings():
                # every failure or truncation is counted and warned about once below
                warnings.simplefilter("ignore", ConvergenceWarning)
                warnings.simplefilter("ignore", TruncationWarning)
                found, forces = ride(rail, wagons)
            if i == 0 and not found.converged and count > 1:     # say so before the rest
                _first_failed(found, forces, time.perf_counter() - start, count,
                              float(train.speed))
            converged[i], used[i] = found.converged, found.harmonics
            truncation[i] = found.truncation_error
            std[i], peak[i] = forces.std(axis=1), forces.max(axis=1)
            if found.converged:
                pooled.append(forces)
            bar.to(i + 1, f"{int(np.sum(~converged[:i + 1]))} not converged")
    if not pooled:
        raise RuntimeError(f"none of the {count} realisations converged: no statistics")
    if not converged.all():
        warnings.warn(f"{int(np.sum(~converged))} of {count} realisations did not converge "
                      f"(or harmonics='auto' fell short of its accuracy); they are left out "
                      f"of the pooled values (see .converged, .truncation and .harmonics)",
                      ConvergenceWarning, stacklevel=2)
    coarse = int(np.sum(converged & (truncation > DEFAULT_ACCURACY)))
    if coarse:
        warnings.warn(f"{coarse} of {count} realisations kept a truncation error above "
                      f"{DEFAULT_ACCURACY:.1%} of Q (largest {np.nanmax(truncation):.1%}; see "
                      f".truncation and .harmonics)", TruncationWarning, stacklevel=2)
    every = np.concatenate(pooled, axis=1)
    levels = np.asarray(LEVELS)
    lower = np.quantile(every, (1 - levels) / 2, axis=1)
    upper = np.quantile(every, (1 + levels) / 2, axis=1)
    inputs = dict(track=track, foundation=foundation, vehicle=vehicle, spectrum=spectrum,
                  speed=float(speed), wagon_length=float(train.wagon_length),
                  wavelengths=tuple(wavelengths), wagons=wagons, samples=samples)
    return WheelLoadStatistics(load, seeds, std, peak, converged, used, truncation,
                               every.mean(axis=1), every.std(axis=1), lower, upper,
                               smooth_std, inputs)


def _first_failed(found, forces, seconds, count, speed) -> None:
    """Warn, before the other realisations, that the first did not converge and how long it took."""
    lost = " (a contact force reached 0: the wheels leave the rail)" if forces.min() <= 0 else ""
    warnings.warn(f"the first realisation did not converge{lost} after {seconds:.0f} s, at "
                  f"{speed:g} m/s = {3.6 * speed:.0f} km/h; the other {count - 1} may fail "
                  f"as slowly ({found.message.split(';')[0]})", ConvergenceWarning, stacklevel=3)
