"""The engineer's P2 force at a dipped joint or weld, and the track it needs (issue 20).

A wheel rolling over a dip whose rail slopes change by 2 alpha has its
vertical velocity changed by 2 alpha v.  British Rail's P2 force (Jenkins et
al. 1974) is the peak of the slow oscillation that follows: the unsprung mass
m_u and an *equivalent track* (mass m_t, stiffness k_t, damping c_t per wheel)
bouncing together,

    P2 = P0 + 2 alpha v sqrt(m_u / (m_u + m_t))
              [1 - c_t pi / (4 sqrt(k_t (m_u + m_t)))] sqrt(k_t m_u).

`p2_force` evaluates it; `dip_angle` gives 2 alpha of the project's
`railtrack.model.profile.CosineDip`; `equivalent_track` fits (m_t, k_t, c_t)
to a `railtrack.Track`'s own point receptance above a sleeper
(`railtrack.studies.point_receptance`, the Floquet–Bloch integral of eq. (3)).

Sources.  The formula is the one stated in issue 20; no copy of Jenkins et
al. (1974) [1]_, nor of a text quoting it, could be read for this module.  The
tests check it against the model it condenses: its bracket is the first-order
term, in zeta = c_t / (2 sqrt(k_t (m_u + m_t))), of the first peak of k_t x(t)
for the mass m_u + m_t on (k_t, c_t) started at 2 alpha v m_u / (m_u + m_t).
One public code seen (citing Esveld, *Modern Railway Track*, eq. 6.23) has
1 - c_t pi / sqrt(k_t m_t) instead: 0.09 for the British track where this gives
0.88 (m_u = 600 kg), and not that expansion; we take it for a transcription error.

References
----------
.. [1] Jenkins et al. (1974), The effect of track and vehicle parameters on
   wheel/rail vertical dynamic forces, Railway Engineering Journal 3(1), 2-16.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import brentq

from ..model.plausibility_check import check_plausible, check_value, quantities_to_si
from ..model.profile import CosineDip
from ..model.track import as_float64, require_non_negative, require_positive
from ..model.validation import to_si
from .point_receptance import one_law, point_receptance

__all__ = ["EquivalentTrack", "p2_force", "dip_angle", "point_receptance", "fit_equivalent_track",
           "equivalent_track"]


@dataclass(frozen=True)
class EquivalentTrack:
    """A track seen by one wheel as one mass on a spring and a dashpot (per wheel).

    Parameters
    ----------
    mass, stiffness, damping : float
        m_t > 0 [kg], k_t > 0 [N/m], c_t >= 0 [N s/m].

    Examples
    --------
    >>> EquivalentTrack(245.0, 150e6, 55.4e3).damping
    55400.0
    """

    mass: float
    stiffness: float
    damping: float

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("mass", self.mass, "kg")
        require_positive("stiffness", self.stiffness, "N/m")
        require_non_negative("damping", self.damping, "N s/m")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def british(cls) -> "EquivalentTrack":
        """m_t = 245 kg, k_t = 150 MN/m, c_t = 55.4 kN s/m per wheel: British track.

        The values given in issue 20, attributed there to Jenkins et al. (1974).
        Not checked: of that paper and of British Railways Board standard
        GM/TT0088 (1993, whose section 6 is on vertical dynamic forces) only
        the first pages could be read.
        """
        return cls(245.0, 150e6, 55.4e3)


_P2_ARGUMENTS = ("static_load", "dip_angle", "speed", "unsprung_mass", "track_mass",
                 "track_stiffness", "track_damping")
_P2_UNITS = ("N", "rad", "m/s", "kg", "kg", "N/m", "N s/m")
_P2_ROWS = ("wheel_load", "dip_angle", "speed", "unsprung_mass", "track_mass", "track_stiffness",
            "track_damping")


def p2_force(static_load: ArrayLike, dip_angle: ArrayLike, speed: ArrayLike,
             unsprung_mass: ArrayLike, track_mass: ArrayLike, track_stiffness: ArrayLike,
             track_damping: ArrayLike):
    """P2 force of Jenkins et al. (1974) at a dipped joint or weld [N].

        P2 = P0 + 2 alpha v sqrt(m_u / (m_u + m_t))
                  [1 - c_t pi / (4 sqrt(k_t (m_u + m_t)))] sqrt(k_t m_u)

    Parameters
    ----------
    static_load, dip_angle, speed : array_like
        P0 >= 0 the static wheel load [N]; 2 alpha >= 0 the total change of
        rail slope across the dip [rad] (`dip_angle`); v >= 0 [m/s].
    unsprung_mass : array_like
        m_u > 0, per wheel [kg].
    track_mass, track_stiffness, track_damping : array_like
        m_t > 0 [kg], k_t > 0 [N/m], c_t >= 0 [N s/m] of the equivalent
        track per wheel (`EquivalentTrack`).

    Returns
    -------
    float or ndarray
        P2 [N], broadcast over the inputs.

    Raises
    ------
    ValueError
        For an input out of range, or where the damping bracket is negative:
        the formula is first order in zeta = c_t / (2 sqrt(k_t (m_u + m_t)))
        and means nothing once zeta pi / 2 > 1.

    Examples
    --------
    >>> t = EquivalentTrack.british()
    >>> round(p2_force(75e3, 2e-3, 45.0, 600.0, t.mass, t.stiffness, t.damping))
    94971
    """
    static_load, dip_angle, speed, unsprung_mass, track_mass, track_stiffness, track_damping = (
        to_si(name, value, unit) for name, value, unit in zip(_P2_ARGUMENTS, (
            static_load, dip_angle, speed, unsprung_mass, track_mass, track_stiffness,
            track_damping), _P2_UNITS))
    require_non_negative("static_load", static_load, "N")
    require_non_negative("dip_angle", dip_angle, "rad")
    require_non_negative("speed", speed, "m/s")
    require_positive("unsprung_mass", unsprung_mass, "kg")
    require_positive("track_mass", track_mass, "kg")
    require_positive("track_stiffness", track_stiffness, "N/m")
    require_non_negative("track_damping", track_damping, "N s/m")
    for name, value, row in zip(_P2_ARGUMENTS, (static_load, dip_angle, speed, unsprung_mass,
                                               track_mass, track_stiffness, track_damping),
                                _P2_ROWS):
        check_value(name, value, row)
    m_u, m_t = np.asarray(unsprung_mass, float), np.asarray(track_mass, float)
    k_t, c_t = np.asarray(track_stiffness, float), np.asarray(track_damping, float)
    bracket = 1.0 - c_t * np.pi / (4.0 * np.sqrt(k_t * (m_u + m_t)))
    if np.any(bracket < 0):
        worst = float(np.min(bracket))
        zeta = (1.0 - worst) * 2.0 / np.pi
        raise ValueError(f"the damping bracket 1 - c_t pi / (4 sqrt(k_t (m_u + m_t))) is "
                         f"{worst:.3g} < 0 (damping ratio {zeta:.3g}): the track is too damped "
                         "for the P2 formula, which is first order in the damping ratio")
    dynamic = (np.asarray(dip_angle, float) * np.asarray(speed, float) * np.sqrt(m_u / (m_u + m_t))
               * bracket * np.sqrt(k_t * m_u))
    total = np.asarray(static_load, float) + dynamic
    return float(total) if total.ndim == 0 else total


def dip_angle(dip: CosineDip) -> float:
    """Total dip angle 2 alpha of a cosine dip: 2 pi depth / length [rad].

    A joint dipped by alpha on each side turns the rail by 2 alpha: the wheel
    runs down at slope -alpha and up at +alpha.  The cosine dip
    r(s) = -(d/2)(1 + cos(2 pi s / l)) has no corner; its slope
    (pi d / l) sin(2 pi s / l) runs from -pi d / l (steepest descent,
    s = -l/4) to +pi d / l (steepest ascent, s = +l/4), so we take
    2 alpha = 2 pi d / l, the total change of slope between them.  That
    change is spread over the half-length l/2, i.e. over l / (2 v) seconds,
    where the formula assumes a corner: `p2_force` is meant for dips whose
    l / (2 v) is short against the P2 period 2 pi sqrt((m_u + m_t) / k_t).

    Examples
    --------
    >>> round(dip_angle(CosineDip(0.5e-3, 1.0, 18.0)), 6)
    0.003142
    """
    if not isinstance(dip, CosineDip):
        raise TypeError(f"dip must be a railtrack CosineDip; got {type(dip).__name__}")
    return 2.0 * np.pi * dip.depth / dip.length


def fit_equivalent_track(receptance: Callable[[np.ndarray], np.ndarray],
                         omega_max: float = 2 * np.pi * 1000.0,
                         step: float = 2 * np.pi * 2.0) -> EquivalentTrack:
    """(m_t, k_t, c_t) of the one-mass track with the same stiffness and phase resonance.

    With D = 1 / alpha: k_t = D(0), the static stiffness; omega_r the lowest
    frequency where Re D = 0 (force in phase with velocity);
    m_t = k_t / omega_r^2 and c_t = Im D(omega_r) / omega_r.  For
    D = k - m omega^2 + i c omega that is (m, k, c) exactly; a real track's D
    is matched at 0 and omega_r only.  Re D is scanned upward in `step` [rad/s]
    up to `omega_max` [rad/s], then the crossing refined (Brent).

    Examples
    --------
    >>> t = fit_equivalent_track(lambda w: 1 / (150e6 - 245 * w**2 + 55.4e3j * w))
    >>> round(t.mass, 6), round(t.stiffness), round(t.damping, 6)
    (245.0, 150000000, 55400.0)
    """
    require_positive("omega_max", omega_max, "rad/s")
    require_positive("step", step, "rad/s")

    def stiffness(w):
        return 1.0 / receptance(np.asarray(w, dtype=float))

    static = complex(stiffness(0.0))
    if not static.real > 0 or abs(static.imag) > 1e-9 * abs(static.real):
        raise ValueError(f"the receptance at omega = 0 must be real and > 0; 1/alpha = {static}")
    low = 0.0
    while low < omega_max:
        grid = np.linspace(low, min(low + 32 * step, omega_max), 33)[1:]
        below = np.flatnonzero(stiffness(grid).real <= 0)
        if below.size:
            high = grid[below[0]]
            low = grid[below[0] - 1] if below[0] else low
            break
        low = grid[-1]
    else:
        raise ValueError(f"Re(1/alpha) stays > 0 up to omega_max = {omega_max:.4g} rad/s: "
                         "no phase resonance to fit a mass to; raise omega_max")
    resonance = brentq(lambda w: float(stiffness(w).real), low, high, xtol=1e-12, rtol=1e-14)
    damping = float(stiffness(resonance).imag) / resonance
    return EquivalentTrack(static.real / resonance**2, static.real, damping)


def equivalent_track(passage, foundation, omega_max: float = 2 * np.pi * 1000.0) -> EquivalentTrack:
    """The equivalent track of a `railtrack.Track` on `foundation`, per wheel.

    `fit_equivalent_track` of `point_receptance` above a sleeper; `passage`
    may be a Passage or a Track, `foundation` any law or callable ``f(w, v)``
    (its linearization at rest); a TypeError names anything else, a
    `railtrack.SleeperCell` included (pass one of its laws).

    Examples
    --------
    >>> from railtrack import Track, LinearFoundation
    >>> t = equivalent_track(Track.paper(), LinearFoundation(20e6, 0.2e6))
    >>> round(t.mass, 1), round(t.stiffness / 1e6, 2), round(t.damping / 1e3, 1)
    (49.7, 58.32, 339.6)
    """
    law = one_law(passage, foundation)
    return fit_equivalent_track(lambda w: point_receptance(passage, law, w), omega_max)
