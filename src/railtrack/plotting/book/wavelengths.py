"""How a train of wagons loads the track's wavelengths (chapter 10).

The peak speed of the discrete track, eq. (23), beside that of the smeared
track with the same damping (`railtrack.studies.wavelengths`), for several
trains; and the harmonics of a wagon with their resonance speeds and the
share of the load each receives.
"""

from __future__ import annotations

import numpy as np

from ...equations.dispersion import harmonic_resonance_speeds
from ...equations.linear import sweep_extremes
from ...studies.wavelengths import (
    axle_pattern_weight,
    smeared_sleeper_extremes,
)
from .speed import peak_speed

__all__ = ["peaks_by_train", "harmonic_table"]


def peaks_by_train(track, foundation, trains: dict, speeds) -> dict:
    """Peak speeds of the discrete and the smeared track, per train [m/s].

    Parameters
    ----------
    track : Track
    foundation : LinearFoundation
    trains : dict of str -> Train
    speeds : array_like, shape (S,)
        Increasing train speeds [m/s]; the peaks are refined between them
        (`peak_speed`).

    Returns
    -------
    dict of str -> (float, float)
        Train name -> (peak speed of eq. (23), peak speed of the smeared
        track) [m/s].
    """
    out = {}
    for name, train in trains.items():
        discrete = sweep_extremes(track, train, foundation, speeds)[0]
        smeared = smeared_sleeper_extremes(
            track, train, foundation, speeds
        )[0]
        out[name] = (
            peak_speed(speeds, discrete)[0],
            peak_speed(speeds, smeared)[0],
        )
    return out


def harmonic_table(track, foundation, train, harmonics) -> list[list[str]]:
    """Rows n, wavelength H/n [m], resonance speed [m/s], share of the load.

    The resonance speed is where harmonic n meets a free wave of the
    undamped smeared track (`harmonic_resonance_speeds`); the share is
    `axle_pattern_weight` at the wavelength H/n.
    """
    n = np.asarray(harmonics)
    wavelength = float(train.wagon_length) / n
    speed = harmonic_resonance_speeds(track, foundation, train, n)
    share = axle_pattern_weight(train, wavelength)
    return [
        [f"{k}", f"{lam:.2f}", f"{v:.1f}", f"{s:.2f}"]
        for k, lam, v, s in zip(n, wavelength, speed, share)
    ]
