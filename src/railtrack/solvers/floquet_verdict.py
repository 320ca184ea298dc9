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

The estimate and what it rests on: `railtrack.solvers.floquet_bound`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .export import Exports
from .floquet_bound import growth_bound
from .result_repr import ShortRepr, floquet_rows

__all__ = ["Floquet", "VERDICTS", "MIN_POINTS", "NEUTRAL", "BOUND_MARGIN", "growth_bound",
           "search_verdict"]     # growth_bound lives in floquet_bound: imported from here too

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

    _rows = floquet_rows                # __repr__, _repr_html_ (ShortRepr)
    _table_row = "multiplier"           # to_dataframe: a row per multiplier

    def to_xarray(self):
        """The multipliers as an `xarray.Dataset` (CF units; `railtrack.solvers.floquet_export`)."""
        from .floquet_export import floquet_dataset
        return floquet_dataset(self)


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
