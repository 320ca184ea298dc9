"""How many harmonics eq. (19) needs: the truncation error and the automatic m.

The train is a row of impulses (eq. 9), so its spectrum F_n does not decay
with n until the rail and the pad filter it: the harmonics that matter reach
a few times the sleeper-passing frequency 2 pi v / L, that is n of order
H / L.  A fixed m = 15 is enough for the paper's 18 m wagon and far from
enough for a 60 m one.

**The estimate.**  Given a solution c_0..c_m, the neglected harmonics
n = m+1..M of eq. (17) are linearised about it:

    c_n ~ -(F_n + G_n[w_m]) / (omega_0^2 + i beta omega_n - omega_n^2 - P_n + (k + i omega_n eta) / M),

where G_n[w_m] are the harmonics above m already present in the foundation
force of the truncated response (by AFT) and k, eta the foundation's tangent
averaged over the period.  The estimated truncation error is the largest
value over the period of the neglected part, sum over m < |n| <= M, divided
by the peak |w| of the truncated response with that part added.  For a linear law the harmonics
decouple (eq. 23) and the estimate is exact up to harmonics beyond
M = 8 m, whose share is below 1 % since |c_n| falls faster than n^-2.
For nonlinear laws it leaves out how the tail feeds back on the kept
harmonics; the tests check it against solves at much larger m.

**The automatic m** (`railtrack.solvers.harmonics_needed`).  The same
formula with c = 0 beyond the static mean (the law linearised about its
static deflection) predicts the whole spectrum before any solve; m is the
smallest for which the predicted neglected part is below half the
accuracy asked for, then the estimate of the actual solution decides
whether m must grow.  Both use the linear coefficients of
`railtrack.solvers.spectrum`; their names and the automatic m's are
imported here too, so that they can be imported from this module.
"""

from __future__ import annotations

import numpy as np

from ..equations.harmonic_balance import HarmonicSystem, NonFiniteForceError, synthesize
from .harmonics_needed import (
    MAX_AUTO_HARMONICS,
    auto_samples,
    grown_harmonics,
    padded,
    predict_harmonics,
)
from .spectrum import (
    TAIL_FACTOR as TAIL_FACTOR,
    TrackSpectrum,
    _grid,
    _linearised_response,
    _series,
    track_spectrum,
)

__all__ = [
    "TrackSpectrum",
    "track_spectrum",
    "tail_coefficients",
    "truncation_error",
    "predict_harmonics",
    "MAX_AUTO_HARMONICS",
    "estimate_of",
    "auto_samples",
    "padded",
    "grown_harmonics",
]


def tail_coefficients(system: HarmonicSystem, coefficients: np.ndarray,
                      spectrum: TrackSpectrum) -> np.ndarray:
    """Estimated c_n of the neglected harmonics n = m+1..spectrum.upto [m] (module docstring)."""
    m, samples = system.harmonics, system.samples
    w, v = synthesize(system, np.asarray(coefficients, dtype=complex))
    force = np.asarray(system.foundation.force(w, v), dtype=float)
    stiffness, damping = (float(np.mean(np.broadcast_to(x, w.shape)))
                          for x in system.foundation.tangent(w, v))
    excess = np.zeros(spectrum.upto + 1, dtype=complex)
    generated = np.fft.rfft(force) / (samples * system.sleeper_mass)
    top = min(len(generated), spectrum.upto + 1)
    excess[m + 1 : top] = generated[m + 1 : top]
    tail = _linearised_response(spectrum, excess, stiffness, damping, system.sleeper_mass)
    return tail[m + 1 :]


def truncation_error(system: HarmonicSystem, coefficients: np.ndarray,
                     spectrum: TrackSpectrum | None = None) -> float:
    """Estimated max-norm error of w(t) from keeping m harmonics, relative to its peak [-].

    Parameters
    ----------
    system : HarmonicSystem
        The truncated system that `coefficients` solve.
    coefficients : ndarray, shape (m+1,)
        c_0..c_m [m].
    spectrum : TrackSpectrum, optional
        The linear coefficients up to at least 8 m (computed if missing).

    Returns
    -------
    float
        max_t |w_tail(t)| / max_t |w_m(t)|, the estimate of the module docstring.

    Examples
    --------
    >>> from railtrack import Track, Train, LinearFoundation, solve
    >>> solution = solve(Track.paper(), Train.paper(), LinearFoundation.paper(), harmonics=15)
    >>> 0.003 < solution.truncation_error < 0.008    # m = 15 misses about 0.5 % of the peak
    True
    """
    return _error_and_tail(system, coefficients, spectrum)[0]


def _error_and_tail(system: HarmonicSystem, coefficients: np.ndarray,
                    spectrum: TrackSpectrum | None) -> tuple[float, np.ndarray]:
    m = system.harmonics
    upto = TAIL_FACTOR * m
    if spectrum is None or spectrum.upto < upto:
        spectrum = track_spectrum(system.passage, upto)
    tail = tail_coefficients(system, coefficients, spectrum)[: upto - m]
    samples = _grid(upto)
    neglected = _series(tail, m + 1, samples)
    # The peak of the completed response, not of the truncated one, which a
    # badly truncated series underestimates (for a linear law this makes the
    # estimate the exact relative error).
    whole = _series(np.asarray(coefficients, dtype=complex), 0, samples) + neglected
    peak = float(np.max(np.abs(whole)))
    error = float(np.max(np.abs(neglected)))
    return (error / peak if peak > 0 else float("inf")), tail


def estimate_of(system: HarmonicSystem, coefficients: np.ndarray,
                spectrum: TrackSpectrum) -> tuple[float, np.ndarray | None]:
    """`truncation_error` and the estimated tail c_{m+1}..c_{8m}; (NaN, None) for a diverged iterate."""
    if not np.all(np.isfinite(coefficients)):
        return float("nan"), None
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            return _error_and_tail(system, coefficients, spectrum)
    except NonFiniteForceError:
        return float("nan"), None
