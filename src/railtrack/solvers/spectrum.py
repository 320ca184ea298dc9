"""The linear coefficients of eq. (17) over a range of harmonics, and the series they sum to.

`track_spectrum` evaluates omega_n, P_n, F_n and the linear operator of
eq. (17) for n = 0..upto once (eqs. 3, 8, 16; on a ground, eq. G2), and a
`TrackSpectrum` slices a `HarmonicSystem` of any m <= upto out of them:
the solve, its truncation estimate (`railtrack.solvers.truncation`) and
the choice of m (`railtrack.solvers.harmonics_needed`) share one
evaluation of eq. (3).  `TAIL_FACTOR` is how far past m the estimate
looks.  The helpers `_linearised_response` (the harmonics of the law
linearised), `_series` (a one-sided spectrum summed over a period) and
`_grid` (the samples for it) serve both.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.foundations import as_foundation
from ..equations.harmonic_balance import HarmonicSystem, default_samples
from ..equations.sleeper import coupling_and_transfer, sleeper_operator
from ..model.passage import Passage
from ..equations.load import load_coefficients
from ..equations.ground_balance import on_ground

__all__ = ["TrackSpectrum", "track_spectrum", "TAIL_FACTOR"]

TAIL_FACTOR = 8
"""The estimate sums the neglected harmonics up to M = TAIL_FACTOR * m."""


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
