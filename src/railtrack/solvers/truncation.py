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

**The automatic m.**  The same formula with c = 0 beyond the static mean
(the law linearised about its static deflection) predicts the whole
spectrum before any solve; m is the smallest for which the predicted
neglected part is below half the accuracy asked for, then the estimate of
the actual solution decides whether m must grow.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .foundation_at_rest import static_deflection
from ..model.foundations import as_foundation
from ..equations.harmonic_balance import HarmonicSystem, NonFiniteForceError, default_samples, synthesize
from ..equations.sleeper import coupling_and_transfer, sleeper_operator
from ..model.passage import Passage
from ..equations.load import load_coefficients
from ..equations.ground_balance import on_ground

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

TAIL_FACTOR = 8
"""The estimate sums the neglected harmonics up to M = TAIL_FACTOR * m."""
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


@dataclass(frozen=True, eq=False)
class TrackSpectrum:
    """omega_n, P_n, F_n and the linear operator of eq. (17) for n = 0..upto.

    A `HarmonicSystem` for any m <= upto is a slice of it (`system`).
    """

    omega: np.ndarray
    coupling: np.ndarray
    load: np.ndarray
    operator: np.ndarray
    receptance: np.ndarray | None = None
    """R_g,n [m/N] on a ground (eq. G1), None on a rigid one."""

    @property
    def upto(self) -> int:
        return len(self.omega) - 1

    def system(self, passage: Passage, foundation, harmonics: int, samples: int | None = None) -> HarmonicSystem:
        """The `HarmonicSystem` of harmonics 0..m, without evaluating eq. (3) again."""
        if harmonics > self.upto:
            raise ValueError(f"the spectrum holds harmonics up to {self.upto}; asked for {harmonics}")
        keep = slice(0, harmonics + 1)
        return HarmonicSystem(
            passage, as_foundation(foundation), harmonics,
            default_samples(harmonics) if samples is None else int(samples),
            self.omega[keep], self.coupling[keep], self.load[keep], self.operator[keep],
        )


def track_spectrum(passage: Passage, upto: int, ground=None) -> TrackSpectrum:
    """The linear coefficients of eq. (17) (eqs. 3, 8, 16) for n = 0..upto.

    On a `ground`, those of eq. (G2) for the relative displacement d
    (`railtrack.equations.ground_balance.on_ground`), once per spectrum.
    """
    omega = passage.fundamental_frequency * np.arange(upto + 1)
    coupling, transfer = coupling_and_transfer(passage, omega)
    load = load_coefficients(passage, omega, transfer)
    operator = sleeper_operator(passage, omega) - coupling
    # a HarmonicSystem takes m <= upto / TAIL_FACTOR; the rest is the estimate's
    operator, load, receptance = on_ground(passage, omega, operator, load, ground,
                                           upto // TAIL_FACTOR)
    return TrackSpectrum(omega, coupling, load, operator, receptance)


def _linearised_response(spectrum: TrackSpectrum, excess: np.ndarray, stiffness: float,
                         damping: float, mass: float) -> np.ndarray:
    """c_n = -(F_n + G_n) / (operator_n + (k + i omega_n eta) / M), elementwise."""
    law = (stiffness + 1j * spectrum.omega * damping) / mass
    return -(spectrum.load + excess) / (spectrum.operator + law)


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


def _series(coefficients: np.ndarray, first: int, samples: int) -> np.ndarray:
    """sum over n >= first of c_n e^{i omega_n t} + conj, at `samples` times per period."""
    spectrum = np.zeros(samples // 2 + 1, dtype=complex)
    count = min(len(coefficients), samples // 2 + 1 - first)
    spectrum[first : first + count] = coefficients[:count]
    # irfft(X) = (1/N) [X_0 + 2 Re sum X_n e^{...}], so X_n = N c_n for n >= 1
    # gives 2 Re sum c_n e^{...}, and X_0 = N c_0 gives c_0.
    return np.fft.irfft(spectrum * samples, samples)


def _grid(upto: int) -> int:
    return 1 << int(np.ceil(np.log2(4 * (upto + 1))))


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


def predict_harmonics(passage: Passage, foundation, accuracy: float,
                      ground=None) -> tuple[int, TrackSpectrum]:
    """Smallest m whose neglected harmonics, predicted before solving, are below `accuracy`.

    The prediction is eq. (23) with the law linearised about its static
    deflection (module docstring); the error is measured as in
    `truncation_error`, max norm over the period relative to the peak.

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
