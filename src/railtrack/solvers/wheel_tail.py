"""The contact force's neglected harmonics, from its own spectrum and the rail-top profile's.

Above the wheel's bounce on its Hertz spring (omega_c = sqrt(k_H / m_w),
harmonic p_c = omega_c T / 2 pi of the wagon period T) the wheel stays put
and the contact force follows the rail-top profile: P_p ~ T_P r_p, T_P a
stiffness near k_H that varies slowly with p.  The profile's harmonics r_p
are known at every p (its samples over a wagon, `PROFILE_SAMPLES`), so only
the amplitude T_P is fitted, on the top of a converged solution's own
spectrum (bin maxima over both wheels of |P_p| over those of |r_p|, on
(`WINDOW`) m), and the contact force's truncation at m is estimated by the
neglected tail

    2 T_P sum_{p > m} |r_p| / max_k Q_k,

an upper bound (triangle inequality) on max over the period of |P - P_m|
for a force that follows the profile.  On the 0.5 mm x 1 m dip at 45 m/s it
was 1.0-2.3 times the true error (m = 1200) for m = 135..458; on the coach
(26.4 m) 0.9-2.5 times for m = 120..458.  A fit of log |P_p| against log p
alone was 2-35 times it, with slopes from -0.8 to -3.7 for the same force:
the decay steepens from p^-2 below the bounce to the profile's p^-3 above.

Where the model does not hold the fit says why and "auto" grows m by 1.5
instead (`railtrack.solvers.wheel_rounds`): a flat rail (the force is the
sleepers' passing, not a profile's), a profile whose harmonics do not fall
faster than p^-1.5, a bounce above `FIRST_MOST` harmonics (slow trains), or
a window whose bins disagree on T_P by more than `SPREAD` (another
excitation, e.g. the sleepers' passing, dominates the top of the spectrum).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ProfileTail", "profile_tail", "transfer", "tail_estimate", "harmonics_for",
           "FIRST_MOST", "WINDOW", "SPREAD", "AIM"]

PROFILE_SAMPLES = 1 << 16
"""Samples of the profile over one wagon: its harmonics to p = 32768, far beyond any m."""
FIRST_RESONANCES = 3.0
"""The first m is this many times the bounce's harmonic p_c: T_P on its plateau in (WINDOW) m."""
FIRST_MOST = 600
"""... and at most this: beyond, the fit is not used (a slow train, a very light wheel)."""
WINDOW = (0.5, 0.85)
"""T_P is fitted on these fractions of m: the top 15 % is left out, where a truncated
solution's own harmonics rise (m = 900 on the dip: 5.4e9 N/m there, 0.9-1.8e9 below)."""
BINS_PER_OCTAVE = 4
MIN_HARMONICS = 8
"""Harmonics at least in the window for a fit."""
SPREAD = 4.0
"""The bins' T_P may differ by at most this factor for the model to be taken as holding."""
AIM = 0.9
"""The next m is chosen for a tail of AIM x accuracy: room for T_P refitted at the new m to
come out up to 10 % higher without a third solve."""
DECAY_MOST = -1.5
"""The profile's harmonics must fall at least as p^DECAY_MOST for its tail to be summed."""


@dataclass(frozen=True)
class ProfileTail:
    """The rail-top profile's spectrum as the wheels see it, and what the fit needs.

    Attributes
    ----------
    magnitudes : ndarray
        |r_p| [m], p = 0 .. PROFILE_SAMPLES / 2 (every wheel sees the same).
    groups : int
        G: the wheels' harmonics are its multiples.
    scale : float
        max_k Q_k [N].
    resonance : float
        p_c, the wheel's bounce on its Hertz spring at the largest static load.
    decay : float
        The profile's harmonics fall as p^decay beyond the first m (fitted).
    first : int
        The first m "auto" solves at.
    """

    magnitudes: np.ndarray
    groups: int
    scale: float
    resonance: float
    decay: float
    first: int

    def beyond(self, m: int) -> float:
        """sum_{p > m, p in G Z} |r_p| [m]."""
        start = (int(m) // self.groups + 1) * self.groups
        return float(np.sum(self.magnitudes[start::self.groups]))


def _bins(low: float, high: float, grid: np.ndarray):
    edges = np.geomspace(low, high, max(2, int(np.ceil(np.log2(high / low) * BINS_PER_OCTAVE))
                                        + 1))
    for a, b in zip(edges[:-1], edges[1:]):
        inside = (grid > a) & (grid <= b)
        if np.any(inside):
            yield inside


def profile_tail(passage, wheel, profile, groups: int, most: int):
    """A `ProfileTail`, or the reason (str) the fit cannot be used on this profile."""
    wagon = float(passage.wagon_length)
    x = np.arange(PROFILE_SAMPLES) * wagon / PROFILE_SAMPLES
    magnitudes = np.abs(np.fft.rfft(np.asarray(profile(x), float))) / PROFILE_SAMPLES
    magnitudes[0] = 0.0
    if not np.any(magnitudes > 0.0):
        return ("the rail-top profile is flat: the contact force follows the sleepers' passing, "
                "which the profile's spectrum does not describe")
    scale = float(np.max(passage.axle_loads))
    bounce = np.sqrt(float(wheel.contact_stiffness(wheel.static_compression(scale)))
                     / float(wheel.unsprung_mass))
    resonance = bounce * float(passage.period) / (2 * np.pi)
    first = max(4 * groups, 60, int(np.ceil(FIRST_RESONANCES * resonance / groups)) * groups)
    if first > FIRST_MOST:
        return (f"the wheel's bounce on its Hertz spring is at p = {resonance:.0f}, beyond "
                f"which the force follows the profile: too high to fit below m = {FIRST_MOST}")
    grid = np.arange(first, min(most, PROFILE_SAMPLES // 2) + 1, groups)
    peaks = [(np.log(grid[b][np.argmax(magnitudes[grid[b]])]), np.log(magnitudes[grid[b]].max()))
             for b in _bins(first, float(grid[-1]), grid) if magnitudes[grid[b]].max() > 0.0]
    decay = float(np.polyfit(*np.array(peaks).T, 1)[0]) if len(peaks) >= 3 else 0.0
    if not decay < DECAY_MOST:
        return (f"the profile's harmonics fall as p^{decay:.1f} beyond m = {first}, not faster "
                f"than p^{DECAY_MOST}: their tail cannot be summed")
    return ProfileTail(magnitudes, groups, scale, resonance, decay, first)


def transfer(tail: ProfileTail, grid: np.ndarray, contact_harmonics: np.ndarray):
    """T_P [N/m] fitted on (WINDOW) m, or the reason (str) it cannot be trusted there."""
    m = int(grid[-1])
    env = np.max(np.abs(contact_harmonics), axis=0)
    low, high = WINDOW[0] * m, WINDOW[1] * m
    if np.count_nonzero((grid > low) & (grid <= high)) < MIN_HARMONICS:
        return f"fewer than {MIN_HARMONICS} harmonics between {low:.0f} and {high:.0f}"
    ratios = []
    for inside in _bins(low, high, grid):
        top = tail.magnitudes[grid[inside]].max()
        if top <= 0.0:
            return "the profile has no harmonics in part of the window"
        ratios.append(env[inside].max() / top)
    if max(ratios) > SPREAD * min(ratios):
        return (f"P_p / r_p varies from {min(ratios):.1e} to {max(ratios):.1e} N/m between "
                f"p = {low:.0f} and {high:.0f}: the force does not follow the profile there")
    return float(max(ratios))


def tail_estimate(tail: ProfileTail, stiffness: float, m: int) -> float:
    """2 T_P sum_{p > m} |r_p| / max Q [-]: the contact force's truncation at m, estimated."""
    return 2.0 * stiffness * tail.beyond(m) / tail.scale


def harmonics_for(tail: ProfileTail, stiffness: float, target: float, most: int) -> int:
    """The smallest m (a multiple of G, at most `most`) whose estimated tail is <= target."""
    p = np.arange(tail.groups, min(most, PROFILE_SAMPLES // 2) + 1, tail.groups)
    on_grid = tail.magnitudes[tail.groups::tail.groups]
    after = 2.0 * stiffness * (np.sum(on_grid) - np.cumsum(on_grid))[:p.size] / tail.scale
    meets = np.flatnonzero(after <= target)
    return int(p[meets[0]]) if meets.size else int(p[-1])
