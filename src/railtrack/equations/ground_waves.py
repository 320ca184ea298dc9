"""The ground's free waves: the Rayleigh wave and the layered ground's fundamental mode.

A free wave exp(i (k x - omega t)) of the undamped ground is a real k at which
the assembled stiffness of `railtrack.equations.ground_stiffness` is singular:
det K(k, omega) = 0 (the modal problem of Kausel & Roesset 1981).  With
the scaling w -> i w of every node, K is real for real k and omega while the
half-space's waves are evanescent (c = omega / k below its shear-wave speed),
so det K changes sign at each mode; it also changes sign at the poles of a
layer clamped on both faces, which the search tells apart by |det K| growing
there instead of vanishing.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from ..model.ground import Ground
from ..model.validation import require_finite, require_positive
from .ground_stiffness import global_stiffness

__all__ = ["rayleigh_speed", "rayleigh_determinant", "fundamental_phase_speed"]


def rayleigh_speed(shear_wave_speed: float, poisson_ratio: float) -> float:
    """The Rayleigh-wave speed c_R [m/s] of a homogeneous elastic half-space.

    The root in (0, c_s) of Rayleigh's equation
    (2 - c^2/c_s^2)^2 = 4 sqrt(1 - c^2/c_s^2) sqrt(1 - c^2/c_p^2).

    Parameters
    ----------
    shear_wave_speed : float
        c_s > 0 [m/s].
    poisson_ratio : float
        0 < nu < 0.5.

    Examples
    --------
    >>> round(rayleigh_speed(1.0, 0.25), 6)          # sqrt(2 - 2 / sqrt(3))
    0.919402
    """
    require_positive("shear_wave_speed", shear_wave_speed, "m/s")
    require_finite("poisson_ratio", poisson_ratio)
    if not 0.0 < poisson_ratio < 0.5:
        raise ValueError(f"poisson_ratio must lie strictly between 0 and 0.5; got {poisson_ratio}")
    ratio = (1.0 - 2.0 * poisson_ratio) / (2.0 * (1.0 - poisson_ratio))     # c_s^2 / c_p^2

    def rayleigh(eta: float) -> float:
        e2 = eta * eta
        return (2.0 - e2) ** 2 - 4.0 * math.sqrt(1.0 - e2) * math.sqrt(1.0 - ratio * e2)

    # f(0.5) < 0 < f(1) for every 0 < nu < 0.5, and the root is the only one there
    return shear_wave_speed * brentq(rayleigh, 0.5, 1.0, xtol=1e-15, rtol=1e-15)


def _undamped(ground: Ground) -> Ground:
    return ground.with_damping(0.0)


def rayleigh_determinant(ground: Ground, speed, omega: float) -> np.ndarray:
    """det K at k = omega / c of the undamped ground, scaled to be real and O(1) [-].

    Parameters
    ----------
    ground : Ground
        Its damping is ignored.
    speed : array_like
        Phase speed c > 0 [m/s], below the half-space's shear-wave speed.
    omega : float
        Circular frequency > 0 [rad/s].

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.25, 1800.0)     # c_R = 91.9 m/s
    >>> bool(rayleigh_determinant(ground, 90.0, 100.0) * rayleigh_determinant(ground, 95.0, 100.0) < 0)
    True
    """
    elastic = _undamped(ground)
    k = omega / np.asarray(speed, dtype=float)
    stiffness = global_stiffness(elastic, k, omega)
    n = stiffness.shape[-1] // 2
    scale = np.tile([1.0, 1j], n)                   # w -> i w makes K real
    real = np.conj(scale)[:, None] * stiffness * scale[None, :]
    mu = max(layer.shear_modulus for layer in elastic.strata)
    return np.linalg.det(real.real / (mu * k[..., None, None]))


def fundamental_phase_speed(ground: Ground, frequency, points: int = 400) -> np.ndarray:
    """The phase speed [m/s] of the ground's fundamental (slowest) Rayleigh mode.

    For each frequency the undamped `rayleigh_determinant` is scanned on
    `points` speeds from half the slowest shear-wave speed up to the
    half-space's; the first sign change where |det| falls (a root, not a
    layer's pole) is refined by Brent's method.

    Parameters
    ----------
    ground : Ground
    frequency : array_like
        f > 0 [Hz].
    points : int
        Speeds scanned per frequency (the bracket's resolution).

    Returns
    -------
    ndarray [m/s], the shape of `frequency`.

    Raises
    ------
    ValueError
        If no mode lies below the half-space's shear-wave speed at some
        frequency (a profile whose fundamental mode leaks into the half-space).

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.25, 1800.0)
    >>> round(float(fundamental_phase_speed(ground, 10.0)[0]), 4)
    91.9402
    """
    require_positive("frequency", frequency, "Hz")
    frequencies = np.atleast_1d(np.asarray(frequency, dtype=float))
    c_top = ground.halfspace.shear_wave_speed * (1.0 - 1e-9)
    grid = np.linspace(0.5 * ground.slowest_shear_wave_speed, c_top, points)
    speeds = np.empty(frequencies.shape)
    for index, f in np.ndenumerate(frequencies):
        omega = 2.0 * math.pi * f
        values = rayleigh_determinant(ground, grid, omega)

        def det(c: float) -> float:
            return float(rayleigh_determinant(ground, np.array([c]), omega)[0])

        speeds[index] = np.nan
        for i in np.flatnonzero(np.sign(values[:-1]) * np.sign(values[1:]) < 0):
            root = brentq(det, grid[i], grid[i + 1], xtol=1e-12 * grid[i], rtol=1e-14)
            if abs(det(root)) <= min(abs(values[i]), abs(values[i + 1])):
                speeds[index] = root
                break
        if np.isnan(speeds[index]):
            raise ValueError(f"no Rayleigh mode below the half-space's shear-wave speed "
                             f"{ground.halfspace.shear_wave_speed} m/s at frequency {f} Hz")
    return speeds.reshape(np.shape(frequency)) if np.ndim(frequency) else speeds
