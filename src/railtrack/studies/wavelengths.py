"""How a train of wagons loads the track's wavelengths (smeared track).

A train of identical wagons H long loads the rail with the wavenumbers
kappa_n = 2 pi n / H only, harmonic n travelling at the train speed v, so at
frequency omega_n = v kappa_n (eq. 11); its weight is the wagon's axle
factor sum_j Q_j exp(-i omega_n d_j / v) / H (eq. 10, the factor of eq. 16).
Smear the sleepers -- a pad (k1 + i omega eta1)/L, a mass M/L and a
foundation (k2 + i omega eta2)/L per metre under the rail -- and each
harmonic has a closed-form steady amplitude: no discreteness, the same
damping.  Comparing its peak speed with that of eq. (23) separates what the
discrete support does from what the wagon's axle pattern does.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..equations.load import axle_factor
from ..model.passage import Passage

__all__ = ["smeared_sleeper_extremes", "axle_pattern_weight"]


def smeared_sleeper_extremes(
    track,
    train,
    foundation,
    speeds: ArrayLike,
    harmonics: int = 60,
    samples: int = 2048,
) -> tuple[np.ndarray, np.ndarray]:
    """Sleeper extremes over a period, smeared damped track [m].

    Harmonic n of the rail's displacement is

        W_n = -P_n / (H (EI kappa_n^4 - rho S omega_n^2 + K(omega_n) / L)),
        K = k1* (k2* - M omega^2) / (k1* + k2* - M omega^2),

    with P_n the axle factor at omega_n, k1* = k1 + i omega eta1 and
    k2* = k2 + i omega eta2; the sleeper moves k1* / (k1* + k2* - M omega^2)
    times the rail.  This is the continuous counterpart of
    `railtrack.sweep_extremes` (same track, train, foundation and speeds).

    Parameters
    ----------
    track : Track
    train : Train
        Its own speed is ignored.
    foundation : a law with ``linearization()``
        (k2 [N/m], eta2 [N s/m]).
    speeds : array_like, shape (S,)
        Train speeds [m/s], > 0.
    harmonics : int
        m, the highest harmonic kept.
    samples : int
        Points per period, > 2m.

    Returns
    -------
    lowest, highest : ndarray, shape (S,)
        min and max of the sleeper's w over the period [m] (w < 0 is down).
    """
    v = np.asarray(speeds, dtype=float).reshape(-1, 1)
    if np.any(v <= 0) or not np.all(np.isfinite(v)):
        raise ValueError(
            f"speeds must be positive and finite [m/s], got {speeds!r}"
        )
    if samples <= 2 * harmonics:
        raise ValueError(
            f"samples must exceed 2 * harmonics = {2 * harmonics}, "
            f"got {samples}"
        )
    k2, eta2 = foundation.linearization()
    length = float(train.wagon_length)
    kappa = 2.0 * np.pi * np.arange(harmonics + 1) / length
    omega = v * kappa
    k1 = track.pad_stiffness + 1j * omega * track.pad_damping
    k2 = k2 + 1j * omega * eta2
    sleeper = k1 + k2 - track.sleeper_mass * omega**2
    bed = (
        k1
        * (k2 - track.sleeper_mass * omega**2)
        / sleeper
        / track.sleeper_spacing
    )
    beam = (
        track.rail_bending_stiffness * kappa**4
        - track.rail_linear_mass * omega**2
    )
    load = (
        axle_factor(Passage(track, train.replace(speed=v)), omega) / length
    )
    sleeper_w = -load / (beam + bed) * k1 / sleeper
    spectrum = np.zeros((v.shape[0], samples // 2 + 1), dtype=complex)
    # c_n of the two-sided series sum_{-m}^{m} c_n exp(i omega_n t),
    # as in eq. (12)
    spectrum[:, : harmonics + 1] = sleeper_w * samples
    w = np.fft.irfft(spectrum, samples, axis=-1)
    return w.min(axis=-1), w.max(axis=-1)


def axle_pattern_weight(train, wavelengths: ArrayLike) -> np.ndarray:
    """The share of the wagon's load a wavelength receives, 0 to 1.

    |sum_j Q_j exp(-2 pi i d_j / lambda)| / sum_j Q_j.

    The wagon's axle factor (eq. 10) at the harmonic whose wavelength on
    the rail is lambda, whatever the speed; 1 for a single axle.  For the
    paper's wagon (axles D = 3 m apart) it is |cos(pi D / lambda)|.

    Parameters
    ----------
    train : Train
    wavelengths : array_like
        lambda > 0 [m].
    """
    lam = np.asarray(wavelengths, dtype=float)
    if np.any(lam <= 0) or not np.all(np.isfinite(lam)):
        raise ValueError(
            "wavelengths must be positive and finite [m], "
            f"got {wavelengths!r}"
        )
    d = np.asarray(train.axle_positions, dtype=float)
    q = np.asarray(train.axle_loads, dtype=float)
    phases = np.exp(-2j * np.pi * d / lam[..., None])
    return np.abs(phases @ q) / q.sum()
