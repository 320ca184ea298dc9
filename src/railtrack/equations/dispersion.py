"""Free waves of the smeared track, and the speeds at which a train's harmonics meet them.

Smear the sleepers: the rail (rho S, EI) rests on a pad k1/L, a mass M/L and
a foundation k2/L per metre, undamped.  A free wave exp(i(kappa x - omega t))
of wavenumber kappa has x = omega^2 solving

    (EI kappa^4 - rho S x)(k1 + k2 - M x) + (k1/L)(k2 - M x) = 0,

two branches; on the lower one the sleeper moves with the rail.  A train of
identical wagons H long loads the rail with the wavenumbers kappa_n = 2 pi n / H
only (harmonic n of the period T = H/v), each travelling at the train speed,
so harmonic n resonates where v equals the phase speed omega/kappa of the
free wave of wavelength H/n.  The continuous support ignores the sleepers'
discreteness; chapter 10 of the book compares it with eq. (23).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["smeared_phase_speed", "harmonic_resonance_speeds"]


def smeared_phase_speed(track, foundation, wavenumbers: ArrayLike) -> np.ndarray:
    """Phase speed omega/kappa of the lower branch of the smeared track's free waves [m/s].

    Parameters
    ----------
    track : railtrack.Track
    foundation : a law with ``linearization()``
        Its stiffness at rest is k2 [N/m]; damping is ignored.
    wavenumbers : array_like
        kappa > 0 [rad/m].

    Returns
    -------
    ndarray
        Shaped like `wavenumbers` [m/s].

    Examples
    --------
    >>> import railtrack as rt
    >>> c = smeared_phase_speed(rt.Track.paper(), rt.LinearFoundation.paper(), [1.0, 2.0])
    >>> [round(float(x)) for x in c]
    [418, 369]
    """
    kappa = np.asarray(wavenumbers, dtype=float)
    if np.any(kappa <= 0) or not np.all(np.isfinite(kappa)):
        raise ValueError("wavenumbers must be positive and finite [rad/m]")
    k1, k2 = float(track.pad_stiffness), float(foundation.linearization()[0])
    rho, ei = float(track.rail_linear_mass), float(track.rail_bending_stiffness)
    mass, spacing = float(track.sleeper_mass), float(track.sleeper_spacing)
    bending, springs = ei * kappa**4, k1 + k2
    qa = rho * mass
    qb = bending * mass + rho * springs + k1 * mass / spacing
    qc = bending * springs + k1 * k2 / spacing
    # The smaller root of qa x^2 - qb x + qc = 0, written to avoid cancellation.
    lower = 2.0 * qc / (qb + np.sqrt(qb**2 - 4.0 * qa * qc))
    return np.sqrt(lower) / kappa


def harmonic_resonance_speeds(track, foundation, train, harmonics: ArrayLike) -> np.ndarray:
    """Train speeds at which harmonic n of the wagon load meets a free wave [m/s].

    Harmonic n has wavelength H/n and moves with the train, so it resonates
    where v = smeared_phase_speed(2 pi n / H).

    Examples
    --------
    >>> import railtrack as rt
    >>> track, law = rt.Track.paper(), rt.LinearFoundation.paper()
    >>> v = harmonic_resonance_speeds(track, law, rt.Train.paper(), [2, 3])
    >>> [round(float(x)) for x in v]
    [560, 406]
    """
    n = np.asarray(harmonics, dtype=float)
    return smeared_phase_speed(track, foundation, 2.0 * np.pi * n / float(train.wagon_length))
