"""Rail-top profiles that repeat: a random one drawn from a spectrum, a measured one.

Both are profiles in the sense of `railtrack.model.profile` (a callable r(x)
[m], positive upward, vectorised, with ``slope(x)`` and ``period``).  For a
steady state the period must be a whole number of wagon lengths (the
harmonic-balance solvers of today accept a period that divides the wagon
length H: one wagon).

`RandomProfile` sums cosines at the harmonics of its period,

    r(x) = sum_j a_j cos(Omega_j x + phi_j),   Omega_j = j dOmega,   dOmega = 2 pi / period,

over the j with lambda_min <= 2 pi / Omega_j <= lambda_max, with
a_j = sqrt(2 S(Omega_j) dOmega) and phases phi_j uniform on [0, 2 pi) from
``numpy.random.default_rng(seed)``.  Its mean square over one period is
exactly sum_j S(Omega_j) dOmega: the midpoint rule for the integral of the
one-sided S over the cells [Omega_j - dOmega/2, Omega_j + dOmega/2], whose
error falls as dOmega^2 (a longer period, more wagons, converges).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import CubicSpline

from .validation import require_positive

__all__ = ["RandomProfile", "MeasuredProfile"]

_CHUNK = 4096
"""Positions evaluated at once: bounds the (positions x harmonics) work array."""


@dataclass(frozen=True)
class RandomProfile:
    """One realisation of a one-sided spectrum S(Omega), periodic over `period`.

    Parameters
    ----------
    spectrum : callable
        S(Omega) [m^2/(rad/m)] of Omega [rad/m], one-sided
        (e.g. `railtrack.model.irregularity.FRASpectrum`).
    wavelengths : (float, float)
        (lambda_min, lambda_max) [m], the band kept (0 < lambda_min < lambda_max).
    period : float
        > 0 [m], the length after which the profile repeats: for a steady
        state a whole number of wagon lengths.
    seed : int
        >= 0, for ``numpy.random.default_rng``: the same seed, the same rail.

    Examples
    --------
    >>> from railtrack.model.irregularity import FRASpectrum
    >>> rail = RandomProfile(FRASpectrum(4), (1.5, 25.0), 18.0, seed=1)
    >>> rail.harmonics.tolist()                      # 18 m / j between 1.5 and 25 m
    [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]
    >>> bool(abs(rail(3.0) - rail(21.0)) < 1e-15)
    True
    """

    spectrum: object
    wavelengths: tuple
    period: float
    seed: int
    harmonics: np.ndarray = field(init=False, repr=False, compare=False)
    amplitudes: np.ndarray = field(init=False, repr=False, compare=False)
    phases: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not callable(self.spectrum):
            raise TypeError(f"spectrum must be a callable S(Omega) [m^2/(rad/m)], e.g. "
                            f"FRASpectrum(4); got {self.spectrum!r}")
        try:
            shortest, longest = (float(w) for w in self.wavelengths)
        except (TypeError, ValueError) as error:
            raise TypeError(f"wavelengths must be (lambda_min, lambda_max) in m; "
                            f"got {self.wavelengths!r}") from error
        if not (np.isfinite(longest) and 0.0 < shortest < longest):
            raise ValueError(f"wavelengths must satisfy 0 < lambda_min < lambda_max [m]; "
                             f"got {self.wavelengths!r}")
        require_positive("period", self.period, "m")
        if isinstance(self.seed, bool) or not isinstance(self.seed, (int, np.integer)) \
                or self.seed < 0:
            raise TypeError(f"seed must be an integer >= 0; got {self.seed!r}")
        period = float(self.period)
        j = np.arange(int(np.ceil(period / longest - 1e-9)),
                      int(np.floor(period / shortest + 1e-9)) + 1)
        j = j[j >= 1]
        if j.size == 0:
            raise ValueError(f"no harmonic of the period ({period} m) has a wavelength "
                             f"period/j in [{shortest}, {longest}] m: lengthen the period")
        step = 2 * np.pi / period
        density = np.asarray(self.spectrum(j * step), dtype=float)
        if density.shape != j.shape or not np.all(np.isfinite(density) & (density >= 0)):
            raise ValueError("the spectrum must return finite values >= 0, one per wavenumber")
        phases = np.random.default_rng(int(self.seed)).uniform(0.0, 2 * np.pi, j.size)
        object.__setattr__(self, "wavelengths", (shortest, longest))
        object.__setattr__(self, "period", period)
        object.__setattr__(self, "harmonics", j)
        object.__setattr__(self, "amplitudes", np.sqrt(2.0 * density * step))
        object.__setattr__(self, "phases", phases)

    @property
    def wavenumbers(self) -> np.ndarray:
        """Omega_j = 2 pi j / period [rad/m]."""
        return 2 * np.pi * self.harmonics / self.period

    @property
    def variance(self) -> float:
        """The mean square over one period, sum_j a_j^2 / 2 [m^2]."""
        return float(0.5 * np.sum(self.amplitudes ** 2))

    def _sum(self, x, derivative: bool) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        flat, out = x.ravel(), np.empty(x.size)
        omega = self.wavenumbers
        weights = -self.amplitudes * omega if derivative else self.amplitudes
        for start in range(0, flat.size, _CHUNK):
            arguments = np.multiply.outer(flat[start:start + _CHUNK], omega) + self.phases
            out[start:start + _CHUNK] = (np.sin(arguments) if derivative
                                         else np.cos(arguments)) @ weights
        return out.reshape(x.shape)

    def __call__(self, x) -> np.ndarray:
        return self._sum(x, derivative=False)

    def slope(self, x) -> np.ndarray:
        """dr/dx [-]."""
        return self._sum(x, derivative=True)


@dataclass(frozen=True)
class MeasuredProfile:
    """Heights measured at a constant spacing, repeated periodically.

    Between the samples the profile is the periodic cubic spline through
    them (``scipy.interpolate.CubicSpline``, ``bc_type="periodic"``): r, its
    slope and curvature are continuous, also across the seam where the
    record repeats, and a sample's influence decays within a few spacings
    (no ringing over the whole record, as a Fourier interpolation would give
    at a step).  The period is ``len(heights) * spacing``; a record whose
    ends do not meet (a trend) makes a kink at the seam: detrend it first.

    Parameters
    ----------
    heights : array_like
        r_i [m] at x_i = i * spacing, i = 0 .. n-1 (n >= 3, finite).
    spacing : float
        > 0 [m].

    Examples
    --------
    >>> rail = MeasuredProfile([0.0, -1e-3, 0.0, 1e-3], 0.5)
    >>> rail.period
    2.0
    >>> (rail(np.array([0.5, 2.5])) * 1e3).round(6).tolist()
    [-1.0, -1.0]
    """

    heights: tuple
    spacing: float
    period: float = field(init=False)
    _spline: CubicSpline = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        heights = np.asarray(self.heights, dtype=float)
        if heights.ndim != 1 or heights.size < 3 or not np.all(np.isfinite(heights)):
            raise ValueError(f"heights must be a 1-D array of at least 3 finite values [m]; "
                             f"got shape {heights.shape}")
        require_positive("spacing", self.spacing, "m")
        spacing = float(self.spacing)
        x = np.arange(heights.size + 1) * spacing
        spline = CubicSpline(x, np.append(heights, heights[0]), bc_type="periodic")
        object.__setattr__(self, "heights", tuple(heights.tolist()))
        object.__setattr__(self, "spacing", spacing)
        object.__setattr__(self, "period", heights.size * spacing)
        object.__setattr__(self, "_spline", spline)

    def __call__(self, x) -> np.ndarray:
        return self._spline(np.mod(np.asarray(x, dtype=float), self.period))

    def slope(self, x) -> np.ndarray:
        """dr/dx [-]."""
        return self._spline(np.mod(np.asarray(x, dtype=float), self.period), 1)
