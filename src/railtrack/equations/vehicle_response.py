"""The vehicle seen from its wheelsets, and its steady ride over a rigid, irregular track.

Held at its wheelsets, the linear vehicle of `vehicle_matrices` answers a
harmonic motion z_w e^{i omega t} of the four wheelsets with the forces

    P = D(omega) z_w,   D = D_ww - D_wr D_rr^-1 D_rw,   D = K + i omega C - omega^2 M,

(r: the body and bogies, w: the wheelsets): the dynamic stiffness the
wheel solver will need in place of today's wheel on a primary spring to a
fixed body (`railtrack.Wheel`), which it becomes for an infinitely heavy
body and bogies.

On a rigid track the wheelsets follow the rail-top profile r(x): wheelset j,
at s_j from the body's centre, is at x = v t + s_j, so z_wj(t) = r(v t + s_j).
For a profile repeating every `period` the ride repeats every period / v:
each harmonic Omega_n = 2 pi n / period of r drives omega_n = Omega_n v,
and the contact forces are the static loads plus sum_n D(omega_n) z_w,n.
Per unit harmonic e^{i Omega x} of the rail (x at the body's centre) the
force on wheelset j is H_j(Omega) = sum_k D_jk(Omega v) e^{i Omega s_k}; over a
random rail of one-sided spectrum S its variance is the integral of
|H_j|^2 S dOmega (`spectral_wheel_load_std`).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import quad_vec

from ..model.vehicle import Vehicle
from .vehicle_matrices import WHEELSETS, static_wheelset_loads, vehicle_matrices

__all__ = ["wheelset_dynamic_stiffness", "wheel_load_transfer", "rigid_track_ride",
           "spectral_wheel_load_std", "band_std"]


def wheelset_dynamic_stiffness(vehicle: Vehicle, omega) -> np.ndarray:
    """D(omega) [N/m], complex, shape ``omega.shape + (4, 4)``: wheelset forces per motion.

    Examples
    --------
    >>> D = wheelset_dynamic_stiffness(Vehicle.manchester(), 0.0)
    >>> bool(np.allclose(D @ np.ones(4), 0.0, atol=1e-6))     # the whole vehicle lifted
    True
    """
    mass, damping, stiffness = vehicle_matrices(vehicle)
    omega = np.asarray(omega, dtype=float)
    w = omega[..., None, None]
    dynamic = stiffness + 1j * w * damping - w ** 2 * mass
    rest = slice(0, 6)
    coupling = np.linalg.solve(dynamic[..., rest, rest], dynamic[..., rest, WHEELSETS])
    return dynamic[..., WHEELSETS, WHEELSETS] - dynamic[..., WHEELSETS, rest] @ coupling


def wheel_load_transfer(vehicle: Vehicle, speed: float, wavenumbers) -> np.ndarray:
    """H(Omega) [N/m], complex, shape ``wavenumbers.shape + (4,)``, on a rigid track.

    The force on each wheelset (leading first) per unit harmonic
    e^{i Omega x} of the rail-top profile, x at the body's centre, at speed v.

    Examples
    --------
    >>> H = wheel_load_transfer(Vehicle.manchester(), 30.0, 2 * np.pi / np.array([25.0, 1.5]))
    >>> (np.abs(H) / 1e6).round(1).tolist()           # MN/m; at 1.5 m ~ the wheelsets' mass
    [[1.6, 1.6, 0.3, 0.4], [25.2, 26.1, 25.2, 26.1]]
    """
    wavenumbers = np.asarray(wavenumbers, dtype=float)
    shifts = np.exp(1j * wavenumbers[..., None] * vehicle.wheelset_positions)
    stiffness = wheelset_dynamic_stiffness(vehicle, wavenumbers * float(speed))
    return np.einsum("...ij,...j->...i", stiffness, shifts)


def spectral_wheel_load_std(vehicle: Vehicle, spectrum, speed: float,
                            wavelengths: tuple) -> np.ndarray:
    """The standard deviation [N] of each wheelset's force over a random rigid rail.

    sigma_j^2 = integral of |H_j(Omega)|^2 S(Omega) dOmega over the band
    2 pi / lambda_max .. 2 pi / lambda_min (adaptive quadrature), S one-sided
    [m^2/(rad/m)] (`railtrack.model.irregularity`).

    Examples
    --------
    >>> from railtrack.model.irregularity import FRASpectrum
    >>> sigma = spectral_wheel_load_std(Vehicle.manchester(), FRASpectrum(4), 45.0, (1.5, 25.0))
    >>> (sigma / 1e3).round(1).tolist()                            # kN, on 109 kN
    [19.7, 22.4, 19.7, 22.4]
    """
    return band_std(lambda omega: wheel_load_transfer(vehicle, speed, omega), spectrum,
                    wavelengths)


def band_std(transfer, spectrum, wavelengths: tuple, period: float | None = None) -> np.ndarray:
    """sqrt of the integral of |transfer(Omega)|^2 S(Omega) dOmega over the band [N].

    ``period=None``: adaptive quadrature over 2 pi / lambda_max .. 2 pi / lambda_min.
    A `period` [m]: the sum over its harmonics Omega_j = 2 pi j / period in the
    band, times dOmega = 2 pi / period, the variance of a `RandomProfile` of that
    period exactly (the midpoint rule of the integral).
    """
    shortest, longest = (float(w) for w in wavelengths)
    if not 0.0 < shortest < longest:
        raise ValueError(f"wavelengths must satisfy 0 < lambda_min < lambda_max [m]; "
                         f"got {wavelengths!r}")

    def density(omega):
        return np.abs(transfer(omega)) ** 2 * np.asarray(spectrum(omega))[..., None]

    if period is not None:
        period = float(period)
        j = np.arange(int(np.ceil(period / longest - 1e-9)),
                      int(np.floor(period / shortest + 1e-9)) + 1)
        omega = 2 * np.pi * j[j >= 1] / period
        step = 2 * np.pi / period
        return np.sqrt(step * np.sum(density(omega), axis=0))
    variance, _ = quad_vec(density, 2 * np.pi / longest, 2 * np.pi / shortest,
                           epsrel=1e-10, limit=400)
    return np.sqrt(variance)


def rigid_track_ride(vehicle: Vehicle, profile, speed: float, period: float,
                     samples: int = 1024, gravity: float = 9.81):
    """The steady ride over a rigid track with rail-top `profile`: times and contact forces.

    Parameters
    ----------
    vehicle : Vehicle
    profile : callable
        r(x) [m], repeating every `period`.
    speed : float
        v > 0 [m/s].
    period : float
        > 0 [m], the profile's period (e.g. ``profile.period``).
    samples : int
        Points per period, for the profile's harmonics (exact for a profile
        with no harmonic above samples / 2, e.g. a `RandomProfile`).
    gravity : float
        [m/s^2], for the static loads.

    Returns
    -------
    times : ndarray, shape (samples,)
        t [s] over one period of the ride, period / v.
    forces : ndarray, shape (4, samples)
        The track's force on each wheelset [N], leading first, upward.

    Examples
    --------
    >>> t, P = rigid_track_ride(Vehicle.manchester(), lambda x: 0 * x, 30.0, 18.0, 64)
    >>> (P.mean(axis=1) / 1e3).round(3).tolist()              # a smooth rail: the static loads
    [109.092, 109.092, 109.092, 109.092]
    """
    speed, period = float(speed), float(period)
    if not (np.isfinite(speed) and speed > 0 and np.isfinite(period) and period > 0):
        raise ValueError(f"speed and period must be finite and > 0; got {speed}, {period}")
    if int(samples) != samples or samples < 4:
        raise ValueError(f"samples must be an integer >= 4; got {samples!r}")
    samples = int(samples)
    x = np.arange(samples) * period / samples
    wavenumbers = 2 * np.pi * np.arange(samples // 2 + 1) / period
    spectrum = np.fft.rfft(np.asarray(profile(x), dtype=float)) / samples
    # wheelset j meets the rail at v t + s_j: its input is the profile shifted by s_j
    forces = (wheel_load_transfer(vehicle, speed, wavenumbers) * spectrum[:, None]).T
    forces[:, 0] = 0.0                          # a level shift lifts the whole vehicle
    dynamic = np.fft.irfft(forces * samples, n=samples, axis=1)
    times = x / speed
    return times, static_wheelset_loads(vehicle, gravity)[:, None] + dynamic
