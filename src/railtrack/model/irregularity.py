"""Spectral densities of the rail's vertical profile: the FRA classes and the German spectra.

Convention (the library's, throughout): S(Omega) is ONE-SIDED, a function of
the angular wavenumber Omega = 2 pi / lambda [rad/m] for Omega > 0, in
m^2/(rad/m), such that the profile's variance in a band is

    sigma^2 = integral of S(Omega) dOmega over the band      [m^2].

Sources differ, and a factor slips in easily:

* the FRA coefficients A_v are tabulated in cm^2 rad/m (1 cm^2 = 1e-4 m^2);
  here they are converted to m^2 rad/m;
* a spectrum in cycles/m, S_n(n) with n = Omega / (2 pi), carries the same
  variance per band: S_n(n) = 2 pi S(2 pi n), not S(n);
* a two-sided density, over -inf < Omega < inf, is S/2.

The coefficients below agree between independent transcriptions that we
could read (none is the primary source, which we could not read):

* FRA classes 1-6 (k = 0.25, Omega_c = 0.8245 rad/m, A_v in cm^2 rad/m
  1.2107, 1.0181, 0.6816, 0.5376, 0.2095, 0.0339): D. Cantero, TTB-2D
  (GitHub DanielCanteroNTNU/TTB-2D, file A04_Options.m, block "FRA version
  2", citing A. R. B. Berawi's doctoral thesis, FEUP), and a Python script
  found by content search (repository not identified; the same six values,
  Omega_c and k = 0.25 in its "USA spectra" branch).
* German high-speed spectra (Omega_c = 0.8246, Omega_r = 0.0206 rad/m,
  A_v = 4.032e-7 m^2 rad/m for low and 10.80e-7 for high disturbance): that
  Python script (both values, "very good" and "good" track), TTB-2D
  (4.032e-7, citing Guo, Xia, De Roeck & Liu, Computers & Structures
  112-113 (2012) 205-216), and a Chinese script labelling 4.032e-7 "low
  disturbance" and 1.08e-6 "high".  One further script found swaps the two
  (and is a factor 10 off): beware.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["FRASpectrum", "GermanSpectrum", "FRA_AV", "FRA_OMEGA_C", "FRA_K",
           "GERMAN_AV", "GERMAN_OMEGA_C", "GERMAN_OMEGA_R"]

FRA_AV = {1: 1.2107e-4, 2: 1.0181e-4, 3: 0.6816e-4, 4: 0.5376e-4, 5: 0.2095e-4, 6: 0.0339e-4}
"""A_v [m^2 rad/m] of the FRA track classes (tabulated in cm^2 rad/m: x 1e-4)."""
FRA_OMEGA_C = 0.8245
"""Omega_c [rad/m] of the FRA vertical-profile spectrum, the same for every class."""
FRA_K = 0.25
"""The FRA spectrum's factor k [-]."""

GERMAN_AV = {"low": 4.032e-7, "high": 10.80e-7}
"""A_v [m^2 rad/m] of the German high-speed spectra, by level of disturbance."""
GERMAN_OMEGA_C = 0.8246
"""Omega_c [rad/m] of the German spectra."""
GERMAN_OMEGA_R = 0.0206
"""Omega_r [rad/m] of the German spectra."""


def _band(low, high) -> tuple[float, float]:
    low, high = float(low), float(high)
    if not (np.isfinite(low) and np.isfinite(high) and 0.0 < low < high):
        raise ValueError(f"the wavenumber band must satisfy 0 < low < high [rad/m]; "
                         f"got low = {low}, high = {high}")
    return low, high


@dataclass(frozen=True)
class FRASpectrum:
    """The FRA vertical-profile spectrum of a US track class (1 roughest, 6 smoothest).

        S(Omega) = k A_v Omega_c^2 / (Omega^2 (Omega^2 + Omega_c^2))     [m^2/(rad/m)],

    one-sided, Omega [rad/m] (module docstring for the convention and sources).

    Parameters
    ----------
    track_class : int
        1-6.

    Examples
    --------
    >>> s = FRASpectrum(4)
    >>> round(float(s(2 * np.pi / 10.0)) * 1e6, 3)       # at 10 m wavelength, mm^2/(rad/m)
    21.537
    >>> round(s.band_variance(2 * np.pi / 25, 2 * np.pi / 1.5) ** 0.5 * 1e3, 2)  # mm
    5.71
    """

    track_class: int

    def __post_init__(self) -> None:
        if isinstance(self.track_class, bool) or self.track_class not in FRA_AV:
            raise ValueError(f"track_class must be one of the FRA classes 1-6; "
                             f"got {self.track_class!r}")

    @property
    def roughness(self) -> float:
        """A_v [m^2 rad/m]."""
        return FRA_AV[self.track_class]

    def __call__(self, omega) -> np.ndarray:
        omega = np.asarray(omega, dtype=float)
        c2 = FRA_OMEGA_C ** 2
        return FRA_K * self.roughness * c2 / (omega ** 2 * (omega ** 2 + c2))

    def band_variance(self, low: float, high: float) -> float:
        """The integral of S over [low, high] [rad/m], in closed form [m^2].

        By partial fractions S = k A_v (1/Omega^2 - 1/(Omega^2 + Omega_c^2)), so

            int_a^b S = k A_v [(1/a - 1/b) - (atan(b/Omega_c) - atan(a/Omega_c)) / Omega_c].
        """
        a, b = _band(low, high)
        c = FRA_OMEGA_C
        return float(FRA_K * self.roughness * ((1 / a - 1 / b)
                                               - (np.arctan(b / c) - np.arctan(a / c)) / c))


@dataclass(frozen=True)
class GermanSpectrum:
    """The German high-speed vertical-profile spectrum, low or high disturbance.

        S(Omega) = A_v Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2))   [m^2/(rad/m)],

    one-sided, Omega [rad/m] (module docstring for the convention and sources).

    Parameters
    ----------
    disturbance : {"low", "high"}

    Examples
    --------
    >>> s = GermanSpectrum("low")
    >>> round(s.band_variance(2 * np.pi / 25, 2 * np.pi / 1.5) ** 0.5 * 1e3, 2)  # mm
    0.99
    """

    disturbance: str

    def __post_init__(self) -> None:
        if self.disturbance not in GERMAN_AV:
            raise ValueError(f"disturbance must be 'low' or 'high'; got {self.disturbance!r}")

    @property
    def roughness(self) -> float:
        """A_v [m^2 rad/m]."""
        return GERMAN_AV[self.disturbance]

    def __call__(self, omega) -> np.ndarray:
        omega = np.asarray(omega, dtype=float)
        c2, r2 = GERMAN_OMEGA_C ** 2, GERMAN_OMEGA_R ** 2
        return self.roughness * c2 / ((omega ** 2 + r2) * (omega ** 2 + c2))

    def band_variance(self, low: float, high: float) -> float:
        """The integral of S over [low, high] [rad/m], in closed form [m^2] (partial fractions)."""
        a, b = _band(low, high)
        c, r = GERMAN_OMEGA_C, GERMAN_OMEGA_R
        scale = self.roughness * c ** 2 / (c ** 2 - r ** 2)
        return float(scale * ((np.arctan(b / r) - np.arctan(a / r)) / r
                              - (np.arctan(b / c) - np.arctan(a / c)) / c))
