"""The m that a spectrum needs for an accuracy: the automatic m of ``harmonics="auto"``.

The estimate of `railtrack.solvers.truncation` with c = 0 beyond the
static mean (the law linearised about its static deflection) predicts the
whole spectrum before any solve; `predict_harmonics` takes the smallest m
for which the predicted neglected part is below the accuracy asked for
(`railtrack.solvers.auto_harmonics` asks for half of it), then the
estimate of the actual solution decides whether m must grow
(`grown_harmonics`, from a solution and its estimated tail, which also
give the next solve its warm start, `padded`).  `auto_samples` is the AFT
grid of an automatic m, `MAX_AUTO_HARMONICS` the largest m it takes.
"""

from __future__ import annotations

import numpy as np

from .foundation_at_rest import static_deflection
from ..model.passage import Passage
from .spectrum import TAIL_FACTOR, TrackSpectrum, _grid, _linearised_response, _series, track_spectrum

__all__ = [
    "predict_harmonics",
    "MAX_AUTO_HARMONICS",
    "auto_samples",
    "padded",
    "grown_harmonics",
]

MAX_AUTO_HARMONICS = 2000
"""Largest m that harmonics="auto" picks: Newton's dense Jacobian is (2m+1)^2."""


def auto_samples(harmonics: int) -> int:
    """AFT samples N for harmonics="auto": the smallest power of two >= 8 (m + 1), at least 64.

    Half of `railtrack.equations.harmonic_balance.default_samples`.  Still exact for
    the cubic law (N > 4m); for a kinked law the aliasing of harmonic n <= m
    is of order (m / N)^2 = 1/64 of that harmonic's share of the truncation
    error, which "auto" keeps below its accuracy.
    """
    return max(64, 1 << int(np.ceil(np.log2(8 * (harmonics + 1)))))


def predict_harmonics(passage: Passage, foundation, accuracy: float,
                      ground=None) -> tuple[int, TrackSpectrum]:
    """Smallest m whose neglected harmonics, predicted before solving, are below `accuracy`.

    The prediction is eq. (23) with the law linearised about its static
    deflection (module docstring); the error is measured as in
    `railtrack.solvers.truncation.truncation_error`, max norm over the period relative to the peak.

    Parameters
    ----------
    passage : Passage
    foundation : Foundation
    accuracy : float
        Target relative error [-], 0 < accuracy < 1.
    ground : GroundCompliance, optional
        The solve is on this ground (eq. G2): m is predicted on the rigid
        ground and the spectrum returned is the ground's, up to 8 m.

    Returns
    -------
    m : int
        Between 1 and `MAX_AUTO_HARMONICS`.
    spectrum : TrackSpectrum
        The linear coefficients up to at least 8 m, for the solve and its estimate.
    """
    if ground is not None:
        # predicted on the rigid ground, whose spectrum costs nothing: on a soil the lattice
        # sums of the ~300 harmonics the prediction scans would cost most of the solve; the
        # solution's own estimate, on the ground, then grows m if the soil needs more
        chosen, _ = predict_harmonics(passage, foundation, accuracy)
        return chosen, track_spectrum(passage, TAIL_FACTOR * chosen, ground)
    mass = float(passage.sleeper_mass)
    mean = static_deflection(foundation, float(passage.static_load_per_sleeper))
    if np.isfinite(mean):
        stiffness, damping = (float(np.ravel(x)[0]) for x in
                              foundation.tangent(np.array([mean]), np.zeros(1)))
    else:
        stiffness, damping = foundation.linearization()
    # m is usually below H / L; room for a quarter more spares a second
    # evaluation of eq. (3) when the solve asks for a larger m
    upto = TAIL_FACTOR * max(8, int(np.ceil(1.25 * passage.wagon_length / passage.sleeper_spacing)))
    while True:
        spectrum = track_spectrum(passage, upto, ground)
        response = _linearised_response(spectrum, 0.0, stiffness, damping, mass)
        if np.isfinite(mean):
            response[0] = mean
        # a coarser grid than the estimate's: the prediction is only a start
        chosen = _smallest_fitting_m(response, accuracy, _grid(upto) // 2)
        if chosen <= upto // TAIL_FACTOR or upto >= TAIL_FACTOR * MAX_AUTO_HARMONICS:
            return max(1, min(chosen, MAX_AUTO_HARMONICS)), spectrum
        upto *= 2


def _smallest_fitting_m(response: np.ndarray, accuracy: float, samples: int) -> int:
    """Smallest m with max_t |sum_{|n| > m} c_n e^{i omega_n t}| <= accuracy * max_t |w(t)|."""
    budget = accuracy * float(np.max(np.abs(_series(response, 0, samples))))
    # Between two cheap bounds of the max norm of the neglected part, from
    # above 2 sum_{n > m} |c_n| and from below its r.m.s., bisect on m.
    above = 2.0 * np.cumsum(np.abs(response[::-1]))[::-1]
    below = np.sqrt(2.0 * np.cumsum((np.abs(response) ** 2)[::-1])[::-1])
    fits_above = np.flatnonzero(np.append(above[1:], 0.0) <= budget)
    fits_below = np.flatnonzero(np.append(below[1:], 0.0) <= budget)
    high = int(fits_above[0]) if len(fits_above) else len(response) - 1
    low = int(fits_below[0]) - 1 if len(fits_below) else high - 1
    while high - low > 1:       # the error at `high` fits, at `low` it does not
        middle = (low + high) // 2
        if np.max(np.abs(_series(response[middle + 1 :], middle + 1, samples))) <= budget:
            high = middle
        else:
            low = middle
    return max(1, high)


def padded(coefficients: np.ndarray, tail: np.ndarray, harmonics: int) -> np.ndarray:
    """c_0..c_m' from a smaller solution and its estimated tail: a warm start for m' harmonics."""
    start = np.zeros(harmonics + 1, dtype=complex)
    known = np.concatenate([coefficients, tail])[: harmonics + 1]
    start[: len(known)] = known
    return start


def grown_harmonics(coefficients: np.ndarray, tail: np.ndarray, accuracy: float) -> int:
    """The m that the spectrum c_0..c_m plus its estimated tail needs for `accuracy`."""
    spectrum = np.concatenate([np.asarray(coefficients, dtype=complex), tail])
    return _smallest_fitting_m(spectrum, accuracy, _grid(len(spectrum) - 1) // 2)
