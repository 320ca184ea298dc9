"""A beam on the ground: the track's dispersion and the critical speed (issue 31).

An Euler-Bernoulli beam (bending stiffness EI [N m^2], mass m [kg/m]) lies on
a strip of width b on the ground, optionally through a pad or ballast spring
k_p [N/m^2] per unit length in series.  With the ground's time dependence
exp(i (k x - omega t)) the beam's dynamic stiffness per unit length is

    D(k, omega) = EI k^4 - m omega^2 + K(k, omega),   1/K = 1/k_p + 1/K_eq(k, omega),

K_eq the strip's equivalent stiffness (Dieterman & Metrikine 1996,
`railtrack.equations.ground_strip`).  A load P moving at v is, in its own frame
xi = x - v t, the superposition of P exp(i k (x - v t)): omega = k v.

The track's dispersion on the ground is the set of real (k, omega) where the
undamped D vanishes.  It is real only where no ground wave radiates: where
omega / k is below the phase speed c_1(omega) of the ground's fundamental
Rayleigh mode (then every radial wavenumber sqrt(k^2 + k_y^2) >= k lies
beyond the mode's pole).  There the undamped K_eq is real; it is computed with
the ground's damping ignored, by `railtrack.equations.ground_trapped` (no
damping at all is needed: nothing radiates, no pole lies on the path of
integration).  The critical speed is the least phase speed omega / k on this
curve, where the line omega = k v touches it (group = phase velocity): the
lowest v at which D(k, k v) has a real double root (Dieterman & Metrikine 1996).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ..model.ground import Ground
from ..model.validation import require_positive
from .ground_strip import strip_stiffness
from .ground_trapped import trapped_strip_stiffness
from .ground_waves import fundamental_phase_speed, rayleigh_speed

__all__ = ["beam_on_ground_stiffness", "beam_on_ground_dispersion", "CriticalSpeed",
           "critical_speed_on_ground"]


def beam_on_ground_stiffness(ground: Ground, bending_stiffness: float, mass: float, width: float,
                             k, omega, pad_stiffness: float = math.inf,
                             average: bool = False) -> np.ndarray:
    """D(k, omega) = EI k^4 - m omega^2 + K(k, omega) [N/m^2], the beam on the ground.

    Parameters
    ----------
    ground : Ground
    bending_stiffness, mass : float
        EI [N m^2] and m [kg/m] of the beam.
    width : float
        b [m], the strip under the beam.
    k, omega : array_like
        Wavenumber [rad/m] and frequency [rad/s] (exp(i (k x - omega t))), broadcast.
    pad_stiffness : float
        k_p [N/m^2] in series between beam and ground; inf for none.
    average : bool
        As in `strip_stiffness`.

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0, 0.02)
    >>> d = beam_on_ground_stiffness(ground, 1e7, 500.0, 3.0, 1.0, 0.0)
    >>> round(float(d.real / 1e7), 2)                 # EI k^4 + K_eq(1, 0)
    9.69
    """
    require_positive("bending_stiffness", bending_stiffness, "N m^2")
    require_positive("mass", mass, "kg/m")
    if pad_stiffness != math.inf:
        require_positive("pad_stiffness", pad_stiffness, "N/m^2")
    k, omega = np.broadcast_arrays(np.asarray(k, dtype=float), np.asarray(omega, dtype=float))
    support = strip_stiffness(ground, k, omega, width, average)
    if pad_stiffness != math.inf:
        support = 1.0 / (1.0 / pad_stiffness + 1.0 / support)
    return bending_stiffness * k**4 - mass * omega**2 + support


def _speed_limit(ground: Ground):
    """k -> the least v at which the line omega = k v meets the ground's fundamental mode."""
    if not ground.layers:
        c_r = rayleigh_speed(ground.halfspace.shear_wave_speed, ground.halfspace.poisson_ratio)
        return lambda k: np.full(np.shape(k), c_r)
    freqs = np.geomspace(0.05, 500.0, 60)
    speeds = fundamental_phase_speed(ground, freqs, points=200)

    def phase(v, k):
        return np.interp(np.log(k * v / (2 * np.pi)), np.log(freqs), speeds)

    def exact(v, k):
        return v - fundamental_phase_speed(ground, k * v / (2 * np.pi), points=200)[0]

    def refine(k):
        # the interpolated curve is off by up to ~0.5 % where c_1 falls steeply, and a root
        # of D found above the true c_1 is no root (K_eq there crosses a pole): the speed is
        # refined on the mode itself, v - c_1(k v / 2 pi) rising through zero
        guess = brentq(lambda v: v - phase(v, k), 1e-9, speeds.max(), xtol=1e-9)
        lo, hi = 0.98 * guess, min(1.02 * guess, top)
        if exact(lo, k) >= 0 or exact(hi, k) <= 0:
            lo, hi = 0.5 * ground.slowest_shear_wave_speed, top
        return brentq(exact, lo, hi, args=(k,), xtol=1e-10 * guess, rtol=1e-12)

    top = ground.halfspace.shear_wave_speed * (1.0 - 1e-9)

    def limit(k):
        return np.array([refine(kk) for kk in np.atleast_1d(k)]).reshape(np.shape(k))
    return limit


def _branch_speed(ground, ei, m, b, k, pad, limit, rtol=1e-6) -> np.ndarray:
    """The least v in (0, limit(k)) with D(k, k v) = 0 of the undamped ground, per k."""
    k = np.atleast_1d(np.asarray(k, dtype=float))
    top = limit(k)

    def f(s, kk, vv):
        v = vv * (1.0 - s * s)
        support = trapped_strip_stiffness(ground, kk, kk * v, b)
        if pad != math.inf:
            support = 1.0 / (1.0 / pad + 1.0 / support)
        d = ei * kk**4 - m * (kk * v) ** 2 + support
        return d / (ei * kk**4 + m * (kk * vv) ** 2)

    # v = top (1 - s^2): K_eq falls like sqrt(1 - v / c_R) near a Rayleigh speed, linear in s;
    # a scan from v = 0 finds the first sign change, regula falsi (Illinois) refines it
    # (down to s = 1e-5: near the end of a layered ground's branch, at the free track's
    # crossing of c_1, the root lies at s ~ 1e-3 and below)
    scan = np.concatenate([np.linspace(1.0, 0.1, 10), np.geomspace(0.1, 1e-5, 9)[1:]])
    grid = np.broadcast_to(scan, (k.size, scan.size))
    values = f(grid, k[:, None], top[:, None])
    rows = np.arange(k.size)
    first = np.argmax(values <= 0, axis=1)
    found = (values[rows, first] <= 0) & (first > 0)
    lo, f_lo = grid[rows, first - 1], values[rows, first - 1]      # f > 0 at lo
    hi, f_hi = grid[rows, first], values[rows, first]
    lo, hi, f_lo, f_hi, kk, vv = (x[found] for x in (lo, hi, f_lo, f_hi, k, top))
    side = np.zeros(kk.size)
    for _ in range(60):
        if kk.size == 0 or np.all(np.abs(hi - lo) <= rtol):
            break
        mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        f_mid = f(mid, kk, vv)
        left = f_mid > 0                      # the root lies between mid and hi
        # Illinois: an end kept twice in a row has its value halved
        f_hi = np.where(left & (side == 1), 0.5 * f_hi, f_hi)
        f_lo = np.where(~left & (side == -1), 0.5 * f_lo, f_lo)
        lo, f_lo = np.where(left, mid, lo), np.where(left, f_mid, f_lo)
        hi, f_hi = np.where(left, hi, mid), np.where(left, f_hi, f_mid)
        side = np.where(left, 1, -1)
    root = 0.5 * (lo + hi)
    speed = np.full(k.size, np.nan)
    speed[found] = vv * (1.0 - root * root)
    return speed


def beam_on_ground_dispersion(ground: Ground, bending_stiffness: float, mass: float,
                              width: float, wavenumbers, pad_stiffness: float = math.inf
                              ) -> np.ndarray:
    """The track's dispersion on the ground: the lowest real omega(k) [rad/s] with D = 0.

    Only the branch below the ground's fundamental Rayleigh mode (omega / k <
    c_1(omega), no radiation) is real; where the beam has no root there the
    result is NaN (the curve has left into the radiating region).

    Parameters
    ----------
    ground, bending_stiffness, mass, width, pad_stiffness
        As in `beam_on_ground_stiffness`; the ground's damping is ignored and
        the displacement is the one on the centre line.
    wavenumbers : array_like
        k > 0 [rad/m].

    Returns
    -------
    ndarray [rad/s], the shape of `wavenumbers`.

    Examples
    --------
    A beam's waves on a half-space run just below the Rayleigh speed 92.74 m/s:

    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0)
    >>> omega = beam_on_ground_dispersion(ground, 1e7, 3000.0, 3.0, 1.0)
    >>> bool(0.95 < float(omega[0]) / 1.0 / 92.74 < 1.0)
    True
    """
    require_positive("wavenumbers", wavenumbers, "rad/m")
    k = np.atleast_1d(np.asarray(wavenumbers, dtype=float))
    v = _branch_speed(ground, bending_stiffness, mass, width, k, pad_stiffness,
                      _speed_limit(ground))
    return k * v


@dataclass(frozen=True)
class CriticalSpeed:
    """The critical speed of a load on a beam on the ground.

    Attributes
    ----------
    speed : float
        v_cr [m/s], the least phase speed of the track's dispersion on the ground.
    wavenumber : float
        k [rad/m] where the line omega = k v_cr touches the curve.
    frequency : float
        omega / 2 pi = k v_cr / 2 pi [Hz] there.
    ground_limit : float
        The ground's fundamental mode's phase speed at that frequency [m/s]:
        v_cr reaching it means the minimum sits where the curve meets the ground's.
    """

    speed: float
    wavenumber: float
    frequency: float
    ground_limit: float


def critical_speed_on_ground(ground: Ground, bending_stiffness: float, mass: float,
                             width: float, pad_stiffness: float = math.inf,
                             points: int = 24) -> CriticalSpeed:
    """The critical speed: min over k of omega(k) / k on `beam_on_ground_dispersion`.

    `points` wavenumbers, log-spaced up to c sqrt(m / EI) (beyond it the beam's
    bending alone exceeds m k^2 c^2), bracket the minimum; a bounded Brent
    minimisation in log k refines it.

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0)
    >>> round(critical_speed_on_ground(ground, 1e7, 3000.0, 3.0).speed, 1)   # c_R = 92.74
    91.6
    """
    limit = _speed_limit(ground)
    args = (ground, bending_stiffness, mass, width)
    top = float(np.max(limit(np.geomspace(1e-3, 1e3, 13))))
    k_max = top * math.sqrt(mass / bending_stiffness)
    k = np.geomspace(1e-4 * k_max, k_max, points)
    speeds = _branch_speed(*args, k, pad_stiffness, limit)
    if np.all(np.isnan(speeds)):
        raise ValueError("the beam's dispersion on this ground has no trapped branch below the "
                         f"ground's fundamental mode for k in ({k[0]:.3g}, {k[-1]:.3g}) rad/m")
    i = int(np.nanargmin(speeds))
    bounds = np.log(k[max(i - 1, 0)]), np.log(k[min(i + 1, k.size - 1)])

    def speed(logk: float) -> float:
        v = _branch_speed(*args, math.exp(logk), pad_stiffness, limit)[0]
        return float(v) if np.isfinite(v) else 10 * top
    best = minimize_scalar(speed, bounds=bounds, method="bounded", options={"xatol": 1e-3})
    k_cr, v_cr = (math.exp(best.x), best.fun) if best.fun < speeds[i] else (k[i], speeds[i])
    return CriticalSpeed(float(v_cr), float(k_cr), float(k_cr * v_cr / (2 * np.pi)),
                         float(limit(np.array([k_cr]))[0]))
