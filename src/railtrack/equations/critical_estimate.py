"""The quick estimate of the critical speed where the track's and the ground's dispersion meet.

Mezher et al. (2016) estimate a track's critical speed without solving the
coupled problem: the track's own dispersion curve, here a beam (EI [N m^2],
m [kg/m]) on its ballast or pad springs k_p [N/m^2] over a rigid base,

    m omega^2 = EI k^4 + k_p        (a free beam when there is no pad, k_p = 0),

is drawn with the ground's fundamental Rayleigh mode c_1(omega)
(`railtrack.equations.ground_waves.fundamental_phase_speed`); where they
cross, the phase speed omega / k is the estimate.  The coupled answer is
`railtrack.equations.beam_on_ground.critical_speed_on_ground`.  (The work is
cited by authors and year only: its bibliographic fields were not at hand to
verify, so it is not in book/references.bib.)
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from ..model.ground import Ground
from ..model.validation import require_positive
from .ground_waves import fundamental_phase_speed

__all__ = ["track_phase_speed", "mezher_critical_speed"]


def track_phase_speed(bending_stiffness: float, mass: float, frequency,
                      pad_stiffness: float = math.inf) -> np.ndarray:
    """omega / k [m/s] of the free track (beam on pad springs, rigid base) at f [Hz].

    NaN below the cut-off sqrt(k_p / m) / 2 pi, where the track carries no wave.

    Examples
    --------
    >>> round(float(track_phase_speed(1e7, 500.0, 10.0)), 3)   # (EI/m)^(1/4) sqrt(omega)
    94.264
    """
    require_positive("bending_stiffness", bending_stiffness, "N m^2")
    require_positive("mass", mass, "kg/m")
    pad = 0.0 if pad_stiffness == math.inf else pad_stiffness
    omega = 2 * np.pi * np.asarray(frequency, dtype=float)
    with np.errstate(invalid="ignore"):
        k = ((mass * omega**2 - pad) / bending_stiffness) ** 0.25
    return np.where(mass * omega**2 > pad, omega / np.where(k > 0, k, 1.0), np.nan)


def mezher_critical_speed(ground: Ground, bending_stiffness: float, mass: float,
                          pad_stiffness: float = math.inf, frequencies=None) -> tuple[float, float]:
    """(speed [m/s], frequency [Hz]) where the free track's and the ground's curves first cross.

    Parameters
    ----------
    ground : Ground
    bending_stiffness, mass, pad_stiffness
        As in `track_phase_speed`.
    frequencies : array_like, optional
        The frequencies [Hz] scanned for the crossing (the lowest one is
        refined by Brent's method); default 80 from 0.2 to 200 Hz.

    Raises
    ------
    ValueError
        If the curves do not cross in the scanned band.

    Examples
    --------
    On a half-space the ground's curve is flat at c_R = 92.74 m/s:

    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0)
    >>> round(mezher_critical_speed(ground, 1e7, 500.0)[0], 2)
    92.74
    """
    f = np.geomspace(0.2, 200.0, 80) if frequencies is None else np.asarray(frequencies, float)
    args = (bending_stiffness, mass, f, pad_stiffness)
    gap = track_phase_speed(*args) - fundamental_phase_speed(ground, f)
    change = np.flatnonzero(np.isfinite(gap[:-1]) & (np.sign(gap[:-1]) * np.sign(gap[1:]) <= 0))
    if change.size == 0:
        raise ValueError("the free track's dispersion curve does not cross the ground's "
                         f"fundamental mode between {f[0]} and {f[-1]} Hz")
    i = int(change[0])

    def difference(x: float) -> float:
        return float(track_phase_speed(bending_stiffness, mass, x, pad_stiffness)
                     - fundamental_phase_speed(ground, np.array([x]))[0])
    crossing = brentq(difference, f[i], f[i + 1], xtol=1e-9 * f[i])
    return float(track_phase_speed(bending_stiffness, mass, crossing, pad_stiffness)), crossing
