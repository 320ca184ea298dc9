"""The periodic response of a cell of N sleepers, and what a track engineer reads from it.

Every output is per sleeper of the cell (first axis j = 0..N-1, sleeper j at
x = jL), or along the rail at any x; sleeper j + pN repeats sleeper j
delayed by pNL/v.  Signs as `railtrack.Solution`: displacements positive
upward, rail-seat load and foundation force positive in compression,
bending moment positive when sagging.  The questions and axes are those of
every steady-state result (`railtrack.solvers.result_protocol`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..equations.cell_rail_field import cell_rail_field_coefficients
from ..equations.moment import kink_coefficients, kink_sum
from ..equations.positions import check_positions, checked_times
from ..model.passage import Passage
from .cell_static import cell_at_rest
from .field_chunks import CHUNK_ENTRIES, fourier_field
from .result_protocol import SharedOutputs
from .design_figures import DesignFigures
from .export import Exports
from .result_repr import ShortRepr, cell_rows

__all__ = ["CellSolution"]


@dataclass(frozen=True, repr=False)
class CellSolution(SharedOutputs, ShortRepr, DesignFigures, Exports):
    """A cell's periodic response; ``converged`` is True only if ``residual <= tol``.

    Attributes
    ----------
    passage : Passage
        Rail, spacing and train (its sleeper and pad fields are not used).
    cell : SleeperCell
        The sleepers, pads and laws solved for.
    coefficients : ndarray, shape (N, 2m+1)
        c_{j,n}, n = -m..m [m], w positive upward.
    foundation_harmonics : ndarray, shape (N, 2m+1)
        Harmonics of f_j(w_j, w_j') [N] (by AFT), negative in compression.
    seat_harmonics : ndarray, shape (N, 2m+1)
        Harmonics of p_j = M_j w_j'' + f_j [N], the pad's force on the sleeper
        with w's sign: minus the rail-seat load.
    harmonics, samples, iterations : int
    converged : bool
    residual : float
        Relative residual ||R|| / ||g|| of the last iterate.
    residual_history : ndarray
    message : str
    truncation_error : float
        Estimated max-norm error from keeping m harmonics, relative to the
        largest peak in the cell, of the sleepers' displacements or of the
        rail-seat loads, whichever is larger [-]; NaN if not estimated.
    rail_field_note : str
        Non-empty where `rail_displacement` and `rail_bending_moment` do not
        hold (the sleepers of a `railtrack.WheelSolution`): why, raised as the
        error's message.
    stability : Floquet or None
        The Floquet multipliers when solved with ``stability="full"`` (`floquet`).
    """

    passage: Passage
    cell: Any
    coefficients: np.ndarray
    foundation_harmonics: np.ndarray
    seat_harmonics: np.ndarray
    harmonics: int
    samples: int
    converged: bool
    residual: float
    iterations: int
    residual_history: np.ndarray
    message: str
    truncation_error: float = float("nan")
    rail_field_note: str = ""
    stability: Any = None

    def floquet(self, theta=None, **options):
        """The Floquet multipliers of this solution (`railtrack.solvers.cell_floquet.cell_floquet`).

        Phases are per cell; `options` as `railtrack.floquet`.  ``rt.floquet(s)`` calls this.
        """
        from .cell_floquet import cell_floquet
        return cell_floquet(self, theta, **options)

    @property
    def sleepers(self) -> int:
        """N, the sleepers of the cell."""
        return int(self.coefficients.shape[0])

    @property
    def period(self) -> float:
        """T = H / v [s]."""
        return float(self.passage.period)

    @property
    def frequencies(self) -> np.ndarray:
        """omega_n, n = -m..m [rad/s]."""
        return self.passage.fundamental_frequency * np.arange(-self.harmonics, self.harmonics + 1)

    def _series(self, coefficients: np.ndarray, t: ArrayLike) -> np.ndarray:
        t = checked_times(self.frequencies, t)
        phases = np.exp(1j * np.multiply.outer(t, self.frequencies))        # (..., 2m+1)
        return np.moveaxis((phases @ coefficients.T).real, -1, 0)

    def sleeper_displacement(self, t: ArrayLike) -> np.ndarray:
        """w_j(t) [m], shape (N,) + t.shape; t = 0 when a wagon's first axle is above sleeper 0."""
        return self._series(self.coefficients, t)

    def sleeper_velocity(self, t: ArrayLike) -> np.ndarray:
        """w_j'(t) [m/s], shape (N,) + t.shape."""
        return self._series(1j * self.frequencies * self.coefficients, t)

    def rail_seat_load(self, t: ArrayLike) -> np.ndarray:
        """Pad force on each sleeper, positive in compression [N], shape (N,) + t.shape.

        The pad is linear, so it pulls (a negative load) where the rail lifts
        more than the sleeper: a real clip would hold the rail down there.
        """
        return -self._series(self.seat_harmonics, t)

    def foundation_force(self, t: ArrayLike) -> np.ndarray:
        """-f_j(w_j, w_j'), the force on each foundation, positive in compression [N]."""
        w, v = self.sleeper_displacement(t), self.sleeper_velocity(t)
        out = np.empty_like(w)
        for j, law in enumerate(self.cell.foundations):
            out[j] = -np.asarray(law.force(w[j], v[j]), dtype=float)
        return out + 0.0     # a law that never pushes reads 0 N, not -0 N

    def rail_above_sleepers(self, t: ArrayLike) -> np.ndarray:
        """Rail above each sleeper, w_j + p_j / (k1_j + eta1_j d/dt) [m], (N,) + t.shape."""
        cell = self.cell
        pad = cell.pad_stiffness[:, None] + 1j * self.frequencies * cell.pad_damping[:, None]
        return self._series(self.coefficients + self.seat_harmonics / pad, t)

    def _field(self, t: ArrayLike, x: ArrayLike, which: int, *,
               entries: int = CHUNK_ENTRIES) -> np.ndarray:
        """Re sum_n r_n(x) e^{i omega_n t}: displacement (0), curvature less its kinks (1),
        curvature (2); in blocks of about `entries` complex numbers (`fourier_field`)."""
        m = self.harmonics
        omega = self.frequencies[m:]
        weights = np.where(np.arange(m + 1) == 0, 1.0, 2.0)
        ei = self.passage.rail_bending_stiffness
        check_positions(self.passage, omega, x)
        t = checked_times(omega, t)

        def coefficients_at(xs: np.ndarray) -> np.ndarray:
            (field,) = cell_rail_field_coefficients(
                self.passage, omega, self.coefficients[:, m:], self.seat_harmonics[:, m:],
                self.cell.pad_stiffness, xs, derivatives=(min(which, 1) * 2,))
            if which == 1:
                field = field - kink_coefficients(self.passage, omega, xs) / ei
            return field * weights

        return fourier_field(t, x, coefficients_at, omega, entries=entries)

    def rail_displacement(self, t: ArrayLike, x: ArrayLike = 0.0) -> np.ndarray:
        """w_r(x, t) [m] anywhere along the rail (x from sleeper 0, towards +x); t, x broadcast.

        `railtrack.equations.cell_rail_field`; at a sleeper it is
        `rail_above_sleepers`, and for a cell of identical sleepers it is
        `railtrack.Solution.rail_displacement`.  Any number of points, in
        blocks of bounded memory (`railtrack.solvers.field_chunks`).  Refuses
        (ValueError) a non-finite x, or |x| so far that round-off leaves the
        phases omega_m x / v no digits (`railtrack.equations.positions`).
        """
        self._check_rail_field()
        return self._field(t, x, 0)

    def _check_rail_field(self) -> None:
        if self.rail_field_note:
            raise NotImplementedError(self.rail_field_note)

    def rail_bending_moment(self, t: ArrayLike, x: ArrayLike = 0.0, *,
                            kinks: str = "closed form") -> np.ndarray:
        """EI d^2 w_r/dx^2 at time t [s] and position x [m] (in that order) [N m], sagging positive.

        The kinks under the wheels are summed in closed form
        (`railtrack.equations.moment`), as `railtrack.Solution.rail_bending_moment`
        does; ``kinks="series"`` gives the plain truncated series.
        """
        self._check_rail_field()
        ei = self.passage.rail_bending_stiffness
        if kinks == "closed form":
            return ei * self._field(t, x, 1) + kink_sum(self.passage, t, x)
        if kinks == "series":
            return ei * self._field(t, x, 2)
        raise ValueError(f'kinks must be "closed form" or "series"; got {kinks!r}')

    def at_rest(self):
        """The same track under its own weight before the train arrives (`cell_at_rest`).

        Per sleeper: displacement [m], rail-seat load and foundation force [N]
        (positive in compression).  Without gravity (``cell.gravity == 0``,
        the paper's model) nothing weighs, and every value is 0.
        """
        return cell_at_rest(self.passage, self.cell)

    @property
    def sleeper_shape(self) -> tuple[int, ...]:
        """(N,): per-sleeper outputs are (N,) + t.shape (`result_protocol`)."""
        return (self.sleepers,)

    _rows = cell_rows                   # __repr__, _repr_html_ (ShortRepr)
    _table_row = "time"                 # to_dataframe: a row per instant

    def to_xarray(self, samples: int = 400, x=None):
        """This result as an `xarray.Dataset` over one period of `samples` instants (CF units).

        Dimensions, variables and attributes: `railtrack.solvers.result_export`.
        ``x`` [m] adds the rail's displacement and moment along x (dimension x).
        """
        from .result_export import cell_dataset
        return cell_dataset(self, samples, x)

