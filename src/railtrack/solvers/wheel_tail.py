"""The contact force's neglected harmonics, from its own spectrum and the rail-top profile's.

Above the wheel's bounce on its Hertz spring (omega_c = sqrt(k_H / m_w),
harmonic p_c = omega_c T / 2 pi of the wagon period T) the wheel stays put
and the contact force follows the rail-top profile: P_p ~ T_P r_p, T_P a
stiffness near k_H that varies slowly with p.  The profile's harmonics r_p
are known at every p (its samples over a wagon, `PROFILE_SAMPLES`), so only
the amplitude T_P is fitted, on the top of a converged solution's own
spectrum (the largest wheel's sum of |P_p| over the sum of |r_p| on
(`WINDOW`) m), and the contact force's truncation at m is estimated by the
neglected tail

    2 T_P sum_{p > m} |r_p| / max_k Q_k,

an upper bound (triangle inequality) on max over the period of |P - P_m|
for a force that follows the profile.  The sleeper-passing harmonics
p = j H / L, which the sleepers drive and not the profile, are left out of
the fit and their own tail is bounded apart (`TailFit`).  On the 0.5 mm x 1 m dip at 45 m/s
(p_c = 94) it was 1.3-2.1 times the true error (against m = 1200) for
m = 300..900; on the coach (26.4 m, p_c = 131) 2.0 and 3.1 times at m = 458
and 687 (against m = 1031, itself some 2e-4 Q off).  Below 3 p_c, where T_P
still rises towards k_H, it was optimistic (0.4-0.9 times at 1.4-2.3 p_c):
hence the first m.  A fit of log |P_p| against log p alone was 2-35 times
the true error, its slope from -0.8 to -3.7 for the same force: the decay
steepens from p^-2 below the bounce to the profile's p^-3 above.

Where the model does not hold the fit says why and "auto" grows m by 1.5
instead (`railtrack.solvers.wheel_rounds`): a flat rail (the force is the
sleepers' passing, not a profile's), a profile whose harmonics do not fall
faster than p^-1.5, a bounce above `FIRST_MOST` harmonics (slow trains), or
a window whose bins disagree on T_P by more than `SPREAD` (another
excitation than the profile dominates the top of the spectrum).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ProfileTail", "TailFit", "profile_tail", "transfer", "tail_estimate", "harmonics_for",
           "FIRST_MOST", "WINDOW", "SPREAD", "AIM"]

PROFILE_SAMPLES = 1 << 16
"""Samples of the profile over one wagon: its harmonics to p = 32768, far beyond any m."""
FIRST_RESONANCES = 3.0
"""The first m is this many times the bounce's harmonic p_c: T_P on its plateau in (WINDOW) m."""
FIRST_MOST = 600
"""... and at most this: beyond, the fit is not used (a slow train, a very light wheel)."""
WINDOW = (0.5, 0.85)
"""T_P is fitted on these fractions of m: the top 15 % is left out, where a truncated
solution's own harmonics rise (m = 900 on the dip: bin ratios 6.6e9 N/m there, 0.9-1.8e9
below)."""
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
    passing : int
        H / L: the sleepers pass the wheels at its multiples.
    """

    magnitudes: np.ndarray
    groups: int
    scale: float
    resonance: float
    decay: float
    first: int
    passing: int


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
        return ("the rail-top profile is flat: the sleepers drive the contact force (their "
                "passing, any that differ), not a profile whose spectrum the fit could follow")
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
    passing = int(round(wagon / float(passage.sleeper_spacing)))
    return ProfileTail(magnitudes, groups, scale, resonance, decay, first, passing)


@dataclass(frozen=True)
class TailFit:
    """What a converged level says of its neglected harmonics.

    Attributes
    ----------
    stiffness : float
        T_P [N/m]: the force's harmonics off the sleepers' passing over the profile's.
    passing : float
        max p^3 |P_p| [N] over the sleeper-passing harmonics p = j H / L of (`WINDOW`[0], 1] m,
        whose own tail the profile does not drive: the smooth rail's, taken to fall at least
        as p^-3 (the rail under a wheel rolling over point supports has a jump in its third
        derivative, p^-4; p^-4.4 measured from p = 270 to 540 on the paper's track).
    """

    stiffness: float
    passing: float

    def __or__(self, other: "TailFit") -> "TailFit":
        """The larger of two fits, term by term: the estimate keeps the worst level's."""
        return TailFit(max(self.stiffness, other.stiffness), max(self.passing, other.passing))


def transfer(tail: ProfileTail, grid: np.ndarray, contact_harmonics: np.ndarray):
    """The `TailFit` of a solution on (WINDOW) m, or the reason (str) it cannot be trusted.

    T_P = max_k sum |P_{k,p}| / sum |r_p| over the window, the sleeper-passing
    harmonics left out: the ratio of the sums the estimate extrapolates, which
    averages the profile's lobes and the wheels' interference (a bin's ratio of
    maxima varied 0.8-2.3e9 N/m on the dip's plateau, the window's sum ratio 1.0-1.4e9).
    """
    m = int(grid[-1])
    forces = np.abs(contact_harmonics)
    low, high = WINDOW[0] * m, WINDOW[1] * m
    passing = grid % tail.passing == 0
    window = (grid > low) & (grid <= high) & ~passing
    if np.count_nonzero(window) < MIN_HARMONICS:
        return f"fewer than {MIN_HARMONICS} harmonics between {low:.0f} and {high:.0f}"
    ratios = []
    for inside in (*_bins(low, high, grid), window):
        inside = inside & ~passing
        if not np.any(inside):
            continue
        profile = float(np.sum(tail.magnitudes[grid[inside]]))
        if profile <= 0.0:
            return "the profile has no harmonics in part of the window"
        ratios.append(float(np.max(np.sum(forces[:, inside], axis=1))) / profile)
    whole, ratios = ratios[-1], ratios[:-1]
    if max(ratios) > SPREAD * min(ratios):
        return (f"P_p / r_p varies from {min(ratios):.1e} to {max(ratios):.1e} N/m between "
                f"p = {low:.0f} and {high:.0f}: the force does not follow the profile there")
    top = passing & (grid > low)
    if not np.any(top):
        return f"no sleeper-passing harmonic (H/L = {tail.passing}) between {low:.0f} and {m}"
    return TailFit(whole, float(np.max(forces[:, top] * grid[top] ** 3.0)))


def tail_estimate(tail: ProfileTail, fit: TailFit, m: int) -> float:
    """The contact force's truncation at m over max Q [-], estimated.

    2 T_P sum_{p > m} |r_p| + 2 passing sum_{j > J} (j H/L)^-3, J = floor(m L/H),
    the last sum bounded by (H/L)^-3 / (2 J^2).
    """
    return _tails(tail, fit, np.array([int(m)]))[0]


def _tails(tail: ProfileTail, fit: TailFit, m: np.ndarray) -> np.ndarray:
    on_grid = tail.magnitudes[tail.groups::tail.groups]
    after = np.concatenate([np.sum(on_grid) - np.cumsum(on_grid), [0.0]])
    profile = after[np.minimum(m // tail.groups - 1, after.size - 1)]
    whole = np.maximum(m // tail.passing, 1)
    return (2.0 * fit.stiffness * profile
            + fit.passing / (whole**2 * float(tail.passing) ** 3)) / tail.scale


def harmonics_for(tail: ProfileTail, fit: TailFit, target: float, most: int) -> int:
    """The smallest m (a multiple of G, at most `most`) whose estimated tail is <= target."""
    p = np.arange(tail.groups, min(most, PROFILE_SAMPLES // 2) + 1, tail.groups)
    meets = np.flatnonzero(_tails(tail, fit, p) <= target)
    return int(p[meets[0]]) if meets.size else int(p[-1])
