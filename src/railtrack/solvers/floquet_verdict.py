"""The verdict of a Floquet search: stable, unstable, or unknown when the search could miss.

`railtrack.floquet` looks for multipliers only inside a box, min <= |mu| <=
max, with a contour of a given number of quadrature points.  Finding a
resolved multiplier outside the unit circle proves the solution unstable,
whatever the box.  Finding none proves it stable only if nothing can hide:

* above the box.  An a-priori estimate of the growth per period
  (`growth_bound`) says how large a multiplier the linearised track can
  have; the box must reach above it (``max_multiplier >= BOUND_MARGIN``
  times the bound).
* between the quadrature points.  Beyn's method with too few points misses
  eigenvalues inside the contour (on the fold track of chapter 10, one or two
  points find nothing at 525 m/s where |mu| = 2.0).  Fewer than
  `MIN_POINTS` points cannot prove stability: 16 points give the
  dominant multiplier that 48 give at every point of chapter 10's fold
  branch (tests/test_floquet.py), and already 3 do there.
* in the phases not looked at (``shifts=False``, the quick look of `solve`).

Otherwise the verdict is "unknown", and `Floquet.stable` is None.

The bound, and what it rests on.  Linearised about the orbit, the track is
the rail and pads (constant, passive) and, under each sleeper of mass m_s,
the foundation's tangent stiffness k(t) and damping d(t).  With any shift
kappa that makes k~ = k + kappa > 0, the energy E_s = 1/2 m_s w'^2 +
1/2 k~ w^2 of one sleeper on its foundation alone obeys

    dE_s/dt <= [ (k~'/k~)_+ + 2 max(-d, 0) / m_s + kappa / sqrt(m_s min k~) ] E_s,

since a positive d dissipates, 1/2 k~' w^2 <= (k~'/k~)_+ 1/2 k~ w^2 and
|kappa w w'| <= kappa E_s / sqrt(m_s min k~), so its amplitude grows per
period T by at most

    log |mu| <= 1/2 (upward variation of log k~ over T)
                + int_0^T max(-d, 0) / m_s dt + T kappa / (2 sqrt(m_s min k~)).

This is a proof for a sleeper that the rail leaves alone, not for the
coupled track: the passive rail and pads move energy between sleepers that
sit at different points of their cycle, and the bound that survives that
exchange (over a wagon's window of sleepers, the largest of their rates at
each instant) is e^16 to e^40 on chapter 10's fold branch, above any useful
box.  So `growth_bound` is an estimate of how large a multiplier can be,
exact in the limit of a soft rail; on the fold branch it lies above the
ring's |mu| (3 to 6,400 against at most 2.7, tests/test_floquet_verdicts.py),
and the default box (1e6) stays far above it.  A verdict of "stable" thus
says: no multiplier up to max_multiplier, and max_multiplier well above what
this estimate allows.  For a cell the estimate is the largest over its
sleepers.  A kinked law (bilinear, gap) gives finite jumps of log k~, so it
stays finite.  Several shifts are tried and the least kept.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .export import Exports
from .result_repr import ShortRepr, floquet_rows

__all__ = ["Floquet", "VERDICTS", "MIN_POINTS", "NEUTRAL", "BOUND_MARGIN", "growth_bound", "search_verdict"]

VERDICTS = ("stable", "unstable", "unknown")
MIN_POINTS = 16
"""Fewest contour points per phase for which a search that finds nothing outside proves stability."""
NEUTRAL = 1e-8
"""A multiplier within this of |mu| = 1 is neutral, not unstable: an undamped mode that
neither grows nor dies.  The rail's pinned-pinned modes are such (nodes at every sleeper,
so no pad damps them; the rail has no damping of its own): a cell's Hill matrix carries
them from m = omega_pp / Omega up (on the fold track at 420 m/s, m = 61, where
|mu| - 1 = 3e-14), while one sleeper's condensed matrix cannot see them."""
BOUND_MARGIN = 2.0
"""The box must reach this many times above the a-priori estimate of |mu| (`growth_bound`) [-]."""
BOUND_SAMPLES = 4096
"""Samples of the orbit over one period for the bound (its sampled variation of log k~)."""
SHIFT_FRACTIONS = (1e-3, 1e-2, 1e-1, 1.0)
"""Shifts kappa tried, above -min k, as fractions of the range of k (and kappa = 0 if min k > 0)."""


@dataclass(frozen=True, eq=False, repr=False)
class Floquet(ShortRepr, Exports):
    """The Floquet multipliers of a periodic solution (`railtrack.floquet`).

    Attributes
    ----------
    multipliers : ndarray of complex
        mu = e^{lambda T}, by decreasing modulus.
    exponents : ndarray of complex
        lambda [1/s], |Im lambda| <= pi / T.
    phases : ndarray of float
        The Bloch phase per sleeper of each [rad], in [0, 2 pi).
    tail : ndarray of float
        Share of each eigenvector's norm on the top fifth of the harmonics [-].
    resolved : ndarray of bool
        ``tail <= TAIL_LIMIT``: the truncation resolves the exponent.
    dominant : complex
        The resolved multiplier of largest modulus (0 if none in the box).
    stable : bool or None
        True for the verdict "stable", False for "unstable", None for
        "unknown": no multiplier outside the unit circle was found, but the
        search could have missed one (`verdict`).
    kind : {"real +", "real -", "complex", "none"}
        The dominant multiplier: real and positive (through +1: a fold, or a
        branch point), real and negative (through -1: period doubling), or
        one of a complex pair (Neimark–Sacker: a quasi-periodic response if the
        crossing is supercritical).
    frequency : float
        arg(dominant) / 2 pi, the disturbance's frequency in the frame of the
        train as a fraction of v / H, in [0, 0.5] [-].
    theta : float
        Bloch phase per sleeper of the dominant multiplier [rad].
    base_phases : ndarray of float
        The phases theta asked for (each stands for its N_s shifts) [rad].
    most_unstable : float
        The base phase whose multipliers reach the largest modulus [rad].
    period : float
        T = H / v [s].
    harmonics : int
    message : str
    verdict : {"stable", "unstable", "unknown"}
        "unstable" if a resolved multiplier lies outside the unit circle;
        "stable" if none does and the search could not have missed one
        (`railtrack.solvers.floquet_verdict`); "unknown" otherwise.
    bound : float
        The a-priori estimate of |mu| of the linearised track (`growth_bound`)
        [-]; NaN if not computed.
    vectors : ndarray of complex or None
        The eigenvector of each multiplier on harmonics -m..m, unit norm, shape
        (count, 2m+1); None where not kept (a cell's).  `railtrack.floquet`
        continues them with ``guess=``.
    continued : bool
        True if the multipliers were continued by Newton from a neighbouring
        solution's (``guess=``), not searched for
        (`railtrack.solvers.floquet_track` says what its "stable" means).
    ceiling : float
        The largest |mu| a multiplier not listed can have [-]: the box's
        min_multiplier after a full search; for a continued result, that of
        the last full search plus how far the spectrum moved since
        (`railtrack.solvers.floquet_track`).  NaN if not known.
    """

    multipliers: np.ndarray
    exponents: np.ndarray
    phases: np.ndarray
    tail: np.ndarray
    resolved: np.ndarray
    dominant: complex
    stable: bool | None
    kind: str
    frequency: float
    theta: float
    base_phases: np.ndarray
    most_unstable: float
    period: float
    harmonics: int
    message: str
    verdict: str | None = None
    bound: float = float("nan")
    vectors: np.ndarray | None = None
    continued: bool = False
    ceiling: float = float("nan")

    def __post_init__(self) -> None:
        if self.verdict is None:      # built from a bare flag: it says what the flag says
            object.__setattr__(self, "verdict", {True: "stable", False: "unstable"}.get(
                None if self.stable is None else bool(self.stable), "unknown"))
        if self.verdict not in VERDICTS:
            raise ValueError(f"verdict must be one of {VERDICTS}; got {self.verdict!r}")
        object.__setattr__(self, "stable", {"stable": True, "unstable": False}.get(self.verdict))

    _rows = floquet_rows     # __repr__, _repr_html_: ShortRepr

    _table_row = "multiplier"     # to_dataframe: a row per multiplier

    def to_xarray(self):
        """The multipliers as an `xarray.Dataset` (CF units; `railtrack.solvers.floquet_export`)."""
        from .floquet_export import floquet_dataset
        return floquet_dataset(self)


def growth_bound(solution) -> float:
    """An estimate of the largest |mu| per period T = H / v any disturbance of `solution` can have [-].

    From the energy of the linearised track (module docstring); inf if the
    foundation's tangent along the orbit is not finite.  An estimate: a proof
    for a sleeper the rail leaves alone (module docstring).  For a
    `CellSolution`, the largest of its sleepers' estimates.

    Examples
    --------
    >>> import railtrack as rt
    >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper())
    >>> growth_bound(s)      # constant k, positive d: no disturbance grows
    1.0
    """
    period, m = float(solution.period), int(solution.harmonics)
    samples = max(BOUND_SAMPLES, 16 * m)
    cell = getattr(solution, "cell", None)
    rows = np.atleast_2d(solution.coefficients)[:, m:]
    laws = [solution.foundation] if cell is None else list(cell.foundations)
    masses = np.broadcast_to(np.asarray(
        solution.passage.sleeper_mass if cell is None else cell.sleeper_mass, float), len(laws))
    omega = np.asarray(solution.frequencies, dtype=float)[-(m + 1):]
    increments = []
    for c, law, mass in zip(rows, laws, masses):
        # w and w' over one period at t_j = j T / N, by an inverse FFT of c_0..c_m
        spectrum = np.zeros(samples // 2 + 1, dtype=complex)
        spectrum[: m + 1] = c
        w = np.fft.irfft(spectrum, samples) * samples
        spectrum[: m + 1] *= 1j * omega
        v = np.fft.irfft(spectrum, samples) * samples
        stiffness, damping = (np.broadcast_to(np.asarray(part, dtype=float), w.shape)
                              for part in law.tangent(w, v))
        if not (np.all(np.isfinite(stiffness)) and np.all(np.isfinite(damping))):
            return float("inf")
        increments.append(_least_increments(stiffness, damping, float(mass), period))
    if any(part is None for part in increments):
        return float("inf")
    return float(np.exp(max(float(np.sum(part)) for part in increments)))


def _least_increments(stiffness: np.ndarray, damping: np.ndarray, mass: float,
                      period: float) -> np.ndarray | None:
    """Per sample, the growth of log E / 2 over the shift kappa with the least total.

    1/2 (rise of log k~)_+ + max(-d, 0) dt / m_s + dt kappa / (2 sqrt(m_s min k~)),
    whose sum over the period is log of the bound (module docstring).
    """
    dt = period / stiffness.size
    low, high = float(stiffness.min()), float(stiffness.max())
    shifts = [0.0] if low > 0 else []
    spread = max(high - low, abs(high), np.finfo(float).tiny)
    shifts += [max(-low, 0.0) + f * spread for f in SHIFT_FRACTIONS]
    best, chosen = float("inf"), None
    for kappa in shifts:
        shifted = stiffness + kappa
        if shifted.min() <= 0:
            continue
        log_k = np.log(np.append(shifted, shifted[0]))
        steps = (0.5 * np.maximum(np.diff(log_k), 0.0) + np.maximum(-damping, 0.0) * dt / mass
                 + 0.5 * dt * kappa / np.sqrt(mass * shifted.min()))
        if steps.sum() < best:
            best, chosen = float(steps.sum()), steps
    return chosen


def neutral_note(dominant: complex) -> str:
    """A note for a neutral dominant multiplier (`NEUTRAL`), else ""."""
    if dominant != 0 and abs(abs(dominant) - 1.0) <= NEUTRAL:
        return ("; the largest multiplier is neutral (|mu| = 1 to within 1e-8: an undamped "
                "mode, such as the rail's pinned-pinned mode, neither grows nor dies)")
    return ""


def search_verdict(dominant: complex, *, max_multiplier: float, bound: float, points: int,
                   shifts: bool) -> tuple[str, str]:
    """"stable", "unstable" or "unknown" for a search that found `dominant`, and why.

    Parameters
    ----------
    dominant : complex
        The resolved multiplier of largest modulus found (0 if none).
    max_multiplier : float
        The top of the box searched [-].
    bound : float
        `growth_bound` of the solution [-].
    points : int
        Contour points per phase.
    shifts : bool
        Whether every phase of the family was searched.

    Returns
    -------
    verdict, reason : str
        `reason` names what the search could have missed ("" unless unknown).

    Examples
    --------
    >>> search_verdict(0.5, max_multiplier=1e6, bound=4.6, points=24, shifts=True)
    ('stable', '')
    >>> search_verdict(0.5, max_multiplier=1.04, bound=4.6, points=24, shifts=True)[0]
    'unknown'
    >>> search_verdict(2.0, max_multiplier=1.04, bound=4.6, points=1, shifts=False)[0]
    'unstable'
    """
    if abs(dominant) > 1.0 + NEUTRAL:
        return "unstable", ""
    gaps = []
    if not max_multiplier >= BOUND_MARGIN * bound:
        gaps.append(f"the box stops at |mu| = max_multiplier = {max_multiplier:g}, below "
                    f"{BOUND_MARGIN:g} x the a-priori estimate {bound:.3g} on |mu| of this orbit")
    if points < MIN_POINTS:
        gaps.append(f"points = {points} contour points can miss multipliers inside the box "
                    f"(at least {MIN_POINTS} prove stability)")
    if not shifts:
        gaps.append("shifts=False searched one phase of the family")
    return ("unknown", "; ".join(gaps)) if gaps else ("stable", "")
