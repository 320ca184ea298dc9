"""The cell's receptance matrix diagonalised: one eigenvalue per Floquet mode (issue 19).

The matrix eta_jj' of `railtrack.equations.cell_receptance` is Toeplitz and
theta-circulant, so the cell's Floquet vectors ``v_s(j) = e^{-i phi_s j}``,
``phi_s = omega L/v + 2 pi s/N``, diagonalise it; each eigenvalue is eq. (3)
with q replaced by phi_s, written here as a finite numerator over a
denominator so that the linear cell solve (`railtrack.equations.cell_linear`)
and the modes (`railtrack.equations.cell_modes`) can cancel its poles.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from .cell_receptance import _check_sleepers, cell_receptance  # noqa: F401 (doctest)
from .receptance import _sech, bending_wavenumber, receptance_factors

__all__ = ["CellReceptanceModes", "cell_receptance_modes"]


class CellReceptanceModes(NamedTuple):
    """Floquet modes of the cell matrix; see `cell_receptance_modes`.

    ``eta_jj' = (1/N) sum_s (numerator_s / denominator_s) e^{-i phase_s (j - j')}``.
    """

    phase: np.ndarray
    numerator: np.ndarray
    denominator: np.ndarray


def _a_series(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(sin a cosh a - cos a sinh a)/a^3 and (sin a - sinh a)/a^3 by their series, a <= 1."""
    z = a**4
    first = np.zeros_like(a)
    second = np.zeros_like(a)
    power = np.ones_like(a)
    for m in range(8):      # a^32 / 35! is far below round-off for a <= 1
        fact = float(np.prod(np.arange(1, 4 * m + 4, dtype=float)))
        first = first + (-1) ** m * 4.0**(m + 1) * power / fact
        second = second - 2.0 * power / fact
        power = power * z
    return first, second


def _mode_factors(passage: Passage, a: np.ndarray, phase: np.ndarray):
    """Eq. (3) with q -> phase: finite numerator [-] and denominator [N/m], as `receptance_factors`.

    numerator = [sin a (cosh a - c) - sinh a (cos a - c)] / (a^3 cosh a),
    denominator = 4 EI (cos a - c)(cosh a - c) / (L^3 cosh a), c = cos(phase).
    """
    c = np.cos(phase)
    small = a <= 1.0
    s = np.where(small, a, 1.0)
    first, second = _a_series(s)
    big = np.where(small, 1.0, a)
    sech = _sech(big)
    direct = (np.sin(big) * (1.0 - c * sech) - np.tanh(big) * (np.cos(big) - c)) / big**3
    numerator = np.where(small, (first - c * second) * _sech(s), direct)
    cosh_part = np.where(small, 2.0 * (np.sinh(0.5 * s) ** 2 + np.sin(0.5 * phase) ** 2)
                         * _sech(s), 1.0 - c * sech)
    cos_part = -2.0 * np.sin(0.5 * (a + phase)) * np.sin(0.5 * (a - phase))
    scale = 4.0 * passage.rail_bending_stiffness / passage.sleeper_spacing**3
    return numerator, scale * cos_part * cosh_part


def cell_receptance_modes(passage: Passage, omega: ArrayLike,
                          sleepers: int) -> CellReceptanceModes:
    """The eigenvalues of eta_jj' in finite factors, one per Floquet mode [m/N].

    ``sum_j' eta_jj' e^{-i phi_s j'} = lambda_s e^{-i phi_s j}`` with
    ``phi_s = omega L/v + 2 pi s/N`` and lambda_s eq. (3) with q replaced by
    phi_s, ``lambda_s = (1/(EI L)) sum_t 1/(((phi_s + 2 pi t)/L)^4 - k_b^4)``.
    Mode 0 is today's eta_E, taken from
    `railtrack.equations.receptance.receptance_factors` (the only mode infinite
    at omega = 0); modes s >= 1 are finite there (series in (k_b L)^4 for
    k_b L <= 1).  A mode is infinite where ``cos k_b L = cos phi_s``.

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Angular frequency [rad/s], shape (...).
    sleepers : int
        N >= 1.

    Returns
    -------
    CellReceptanceModes
        ``phase`` phi_s [rad], ``numerator`` [-], ``denominator`` [N/m], each
        shape (..., N); ``lambda_s = numerator / denominator``.

    Examples
    --------
    >>> import numpy as np
    >>> passage = Passage.paper()
    >>> modes = cell_receptance_modes(passage, 80.0, 4)
    >>> lam = modes.numerator / modes.denominator
    >>> j = np.arange(4)
    >>> rebuilt = (lam * np.exp(-1j * np.subtract.outer(j, j)[..., None] * modes.phase)).mean(-1)
    >>> bool(np.allclose(rebuilt, cell_receptance(passage, 80.0, 4), rtol=1e-10))
    True
    """
    n = _check_sleepers(sleepers)
    omega = np.asarray(omega, dtype=float)
    phase = (omega * passage.sleeper_spacing / passage.speed)[..., None] \
        + 2.0 * np.pi * np.arange(n) / n
    a = np.broadcast_to((bending_wavenumber(passage, omega) * passage.sleeper_spacing)[..., None],
                        phase.shape)
    numerator, denominator = _mode_factors(passage, a, phase)
    zero = receptance_factors(passage, omega)
    numerator[..., 0] = zero.numerator
    denominator[..., 0] = zero.denominator
    return CellReceptanceModes(phase, numerator, denominator)
