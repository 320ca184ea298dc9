"""A linear cell of N differing sleepers, solved exactly per harmonic (issue 19, second block).

Sleeper j of the cell (mass M_j, pad k1_j, eta1_j, foundation k2_j, eta2_j)
moves as ``w_j(t) = sum_n c_{j,n} e^{i omega_n t}`` and the rail above it as
``sum_n r_{j,n} e^{i omega_n t}``, with omega_n = 2 pi n v / H (eq. 11) and w
positive upward.  For each harmonic, with s = i omega,
``A_j = k1_j + i omega eta1_j`` (the pad) and ``B_j = k2_j + i omega eta2_j``
(the foundation, eq. 22):

    sleeper (eq. 4):   (M_j s^2 + A_j + B_j) c_j - A_j r_j = 0,
    rail (eq. 3):      r = eta R + m,   R_j = A_j (c_j - r_j),

with eta the cell's receptance matrix and m the free rail under the train
(`railtrack.equations.cell_receptance`).  Write ``p_j = (M_j s^2 + B_j) c_j =
-R_j``, the force the sleeper passes to its inertia and its foundation; then
``r = c + A^{-1} p`` and the rail equation becomes

    c + (A^{-1} + eta) p = m,   i.e.   [I + (A^{-1} + eta) S] c = m,   S = diag(M s^2 + B),

the cell's eq. (23): for N = 1 it is ``c = m A / (A + S (1 + A eta_E))``.

At omega = 0 both eta (in its Floquet mode 0) and m are infinite: a rigid
translation of the rail costs no force.  The system is therefore solved in
the Floquet modes ``c = F c_hat``, ``F_js = e^{-i phi_s j}/sqrt(N)``, where
``eta = F diag(num_s/den_s) F^H`` and m lies in mode 0 alone,
``m = sqrt(N) m_0 F[:, 0]``.  Row s is multiplied by den_s:

    [diag(den) (I + F^H A^{-1} F S_hat) + diag(num) S_hat] c_hat = den_0 sqrt(N) m_0 e_0,

with ``S_hat = F^H S F``.  Every entry is finite, for every omega, and
``den_0 m_0 = -4 (sum_k Q_k e^{-i omega d_k/v}) gap L / H``
(`railtrack.equations.receptance.receptance_factors`), ``-sum Q_k L / H`` at
omega = 0.  There row 0 reads ``sum_j k2_j c_j = -N sum Q_k L / H``: the
foundation carries the train's weight.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from ..model.cell import cell_size, sleeper_array
from ..model.passage import Passage
from .cell_receptance_modes import cell_receptance_modes
from .load import axle_factor
from .receptance import receptance_factors

__all__ = ["LinearCell", "cell_linear_coefficients"]

_UNITS = {"sleeper_mass": "kg", "pad_stiffness": "N/m", "pad_damping": "N s/m",
          "stiffness": "N/m", "damping": "N s/m"}


@dataclass(frozen=True)
class LinearCell:
    """The sleepers of a repeating cell, each with its own mass, pad and linear foundation.

    Sleeper j (j = 0..N-1) sits at x = jL; sleeper j + pN is a copy of
    sleeper j.  The rail, the spacing L and the train come from the `Passage`.

    Parameters
    ----------
    sleeper_mass : sequence of float, length N
        M_j > 0 [kg].
    pad_stiffness : sequence of float, length N
        k1_j > 0 [N/m].
    pad_damping : sequence of float, length N
        eta1_j >= 0 [N s/m].
    stiffness : sequence of float, length N
        Foundation k2_j > 0 [N/m] (eq. 22).
    damping : sequence of float, length N
        Foundation eta2_j >= 0 [N s/m].

    Examples
    --------
    >>> from railtrack.model.foundations import LinearFoundation
    >>> cell = LinearCell.identical(Passage.paper(), LinearFoundation.paper(), 3)
    >>> cell.sleepers, float(cell.stiffness[1])
    (3, 20000000.0)
    >>> float(cell.with_sleeper(1, stiffness=10e6).stiffness[1])
    10000000.0
    """

    sleeper_mass: np.ndarray
    pad_stiffness: np.ndarray
    pad_damping: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray

    def __post_init__(self) -> None:
        lengths = {}
        for field in fields(self):
            name = field.name
            array = sleeper_array(name, getattr(self, name), _UNITS[name])
            object.__setattr__(self, name, array)
            lengths[name] = array.size
        if len(set(lengths.values())) != 1:
            raise ValueError("every field of a LinearCell needs one value per sleeper, the same "
                             f"count N; got lengths {lengths}")

    @property
    def sleepers(self) -> int:
        """N, the number of sleepers in the cell."""
        return int(self.sleeper_mass.size)

    @classmethod
    def identical(cls, passage: Passage, foundation, sleepers: int) -> "LinearCell":
        """N copies of the passage's sleeper and pad on `foundation` (a LinearFoundation)."""
        n = cell_size(sleepers)
        return cls(*(np.full(n, float(value)) for value in (
            passage.sleeper_mass, passage.pad_stiffness, passage.pad_damping,
            foundation.stiffness, foundation.damping)))

    def with_sleeper(self, index: int, **changes: float) -> "LinearCell":
        """A copy with sleeper `index`'s fields changed by name, e.g. ``stiffness=10e6``."""
        names = [field.name for field in fields(self)]
        unknown = set(changes) - set(names)
        if unknown:
            raise TypeError(f"no field named {sorted(unknown)} in LinearCell; fields: {names}")
        values = {name: getattr(self, name).copy() for name in names}
        for name, value in changes.items():
            values[name][index] = value
        return LinearCell(**values)


def _mode_system(passage: Passage, cell: LinearCell, omega: np.ndarray):
    """The scaled mode matrices and right-hand sides, and F, for omega >= 0; shapes (W, N, N)."""
    n = cell.sleepers
    modes = cell_receptance_modes(passage, omega, n)                  # (W, N) each
    j = np.arange(n)
    basis = np.exp(-1j * j[None, :, None] * modes.phase[:, None, :]) / np.sqrt(n)   # F (W, j, s)
    s = 1j * omega[:, None]
    pad = cell.pad_stiffness + s * cell.pad_damping                                 # A_j (W, N)
    support = cell.sleeper_mass * s**2 + cell.stiffness + s * cell.damping          # S_j (W, N)
    adjoint = np.conj(np.swapaxes(basis, -1, -2))
    s_hat = adjoint @ (support[..., None] * basis)
    a_hat = adjoint @ (basis / pad[..., None])
    matrix = (modes.denominator[..., None] * (np.eye(n) + a_hat @ s_hat)
              + modes.numerator[..., None] * s_hat)
    gap = receptance_factors(passage, omega).gap
    right = np.zeros((omega.size, n), dtype=complex)
    right[:, 0] = (-4.0 * np.sqrt(n) * axle_factor(passage, omega) * gap
                   * passage.sleeper_spacing / passage.wagon_length)
    return matrix, right, basis, pad, support


def cell_linear_coefficients(passage: Passage, cell: LinearCell, harmonics: int,
                             rail: bool = False):
    """Sleeper coefficients c_{j,n} of a linear cell, eq. (23) for N differing sleepers [m].

    Solves ``[I + (A^{-1} + eta) S] c = m`` (module docstring) for each
    harmonic omega_n = 2 pi n v / H, n = 0..m, in the Floquet modes scaled by
    eq. (3)'s finite denominators, so that n = 0 is solved exactly at
    omega = 0; ``c_{j,-n} = conj(c_{j,n})``.

    Parameters
    ----------
    passage : Passage
        Scalar-valued rail (EI, rho S), spacing L and train (v, H, axles).
        Its sleeper_mass, pad_stiffness and pad_damping are not used: the
        cell's are.
    cell : LinearCell
        The N sleepers, pads and foundations of the repeating cell.
    harmonics : int
        m >= 1.
    rail : bool
        Also return the rail above each sleeper, ``r_{j,n} = c_{j,n} + p_{j,n} / A_j``.

    Returns
    -------
    sleeper : ndarray, shape (N, 2m+1)
        Complex c_{j,n}, n = -m..m along the last axis [m], w positive upward.
    rail : ndarray, shape (N, 2m+1)
        r_{j,n} [m], only if `rail` is true.

    Raises
    ------
    ValueError
        If the system of a harmonic is singular or not finite (an undamped
        cell exactly at a resonance, or eq. 3 overflowing).

    Examples
    --------
    >>> from railtrack.model.foundations import LinearFoundation
    >>> passage = Passage.paper()
    >>> cell = LinearCell.identical(passage, LinearFoundation.paper(), 2).with_sleeper(
    ...     1, stiffness=10e6)
    >>> c = cell_linear_coefficients(passage, cell, 15)
    >>> c.shape
    (2, 31)
    >>> # the foundations carry the train's mean weight per sleeper, sum Q L / H = 5 kN
    >>> round(float(-(cell.stiffness * c[:, 15].real).mean()), 6)
    5000.0
    """
    if not isinstance(cell, LinearCell):
        raise TypeError(f"cell must be a LinearCell; got {type(cell).__name__}")
    if isinstance(harmonics, bool) or not isinstance(harmonics, (int, np.integer)) or harmonics < 1:
        raise ValueError(f"harmonics must be an integer >= 1; got {harmonics!r}")
    if np.ndim(passage.speed) or np.ndim(passage.rail_bending_stiffness):
        raise ValueError("cell_linear_coefficients needs a scalar-valued passage (no batch)")
    m = int(harmonics)
    omega = passage.harmonic_frequencies(m)[m:]
    matrix, right, basis, pad, support = _mode_system(passage, cell, omega)
    bad = ~np.all(np.isfinite(matrix), axis=(-1, -2))
    if bad.any():
        raise ValueError(f"the cell's system is not finite at omega = {omega[bad][0]:.4g} rad/s: "
                         "eq. (3) overflows there; check the rail's EI, rho S and L")
    try:
        modal = np.linalg.solve(matrix, right[..., None])[..., 0]
    except np.linalg.LinAlgError:
        sizes = np.abs(np.linalg.det(matrix))
        where = float(omega[np.argmin(sizes)])
        raise ValueError(f"the cell's system is singular at omega = {where:.4g} rad/s: an "
                         "undamped cell exactly at a resonance; give a pad or foundation "
                         "damping > 0, or change the speed slightly") from None
    positive = np.einsum("wjs,ws->jw", basis, modal)
    positive[:, 0] = positive[:, 0].real        # the mean of a real signal (round-off in F)
    sleeper = np.concatenate([np.conj(positive[:, :0:-1]), positive], axis=-1)
    if not np.all(np.isfinite(sleeper)):
        raise ValueError("the cell's solution is not finite: an undamped cell at a resonance")
    if not rail:
        return sleeper
    above = positive + support.T * positive / pad.T
    return sleeper, np.concatenate([np.conj(above[:, :0:-1]), above], axis=-1)
