"""The result of a solve: Fourier coefficients and the time histories they define.

`Solution` is a cell of one sleeper: every sleeper of a uniform track moves
as the observed one, delayed by L / v, so its per-sleeper outputs keep no
sleeper axis (``sleeper_shape == ()``); otherwise it answers the questions of
`railtrack.CellSolution` and `railtrack.WheelSolution` under the same names,
arguments and axis order (wheels first, time last), and the same
`one_period` (`railtrack.solvers.result_protocol`).  Its repr is a dozen
lines (`railtrack.solvers.result_repr`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..equations.rail_field import seat_load_coefficients
from ..equations.sleeper import rail_coefficients
from ..model.passage import Passage
from ..equations.bowl import DeflectionBowl, deflection_bowl
from ..equations.load import load_coefficients
from ..equations.moment import kink_sum
from .convergence import ConvergenceError, ConvergenceWarning, TruncationWarning
from .output_errors import output_truncation_errors
from .result_protocol import SharedOutputs, single_at_rest
from .time_histories import fourier_series, rail_field_series
from .design_figures import DesignFigures
from .export import Exports
from .result_repr import ShortRepr, solution_rows

__all__ = ["Solution", "ConvergenceError", "ConvergenceWarning", "TruncationWarning", "DeflectionBowl",
           "fourier_series"]     # fourier_series lives in time_histories: imported from here too


@dataclass(frozen=True, eq=False, repr=False)
class Solution(SharedOutputs, ShortRepr, DesignFigures, Exports):
    """Periodic steady response of the sleeper (eq. 12) found by `railtrack.solve`.

    Attributes
    ----------
    passage : Passage
        The train on the track (also `track` and `train`).
    foundation : object
        The foundation law that was solved for.
    harmonics : int
        m, the highest harmonic kept.
    coefficients : ndarray, shape (2m+1,)
        Complex c_n of the sleeper displacement for n = -m..m [m].
    method : str
        "newton", "fixed-point" or "analytic".
    converged : bool
        Whether the relative residual of eq. (17) reached the tolerance.
    iterations : int
        Steps taken (0 for "analytic").
    residual_history : ndarray
        Relative residual ||R|| / ||F|| of eq. (17) at each iterate.
    message : str
        How the solve ended, in words.
    split : int or None
        N0 used by the fixed point, eq. (21).
    samples : int or None
        AFT samples per period.
    truncation_error : float
        Estimated error of the sleeper displacement from keeping m harmonics:
        max over the period of the neglected part over the peak |w| [-]
        (`railtrack.solvers.truncation.truncation_error`); NaN if the solve diverged.
        The rail-seat load and the moment have their own, larger errors:
        `truncation_errors`.
    stability : railtrack.Floquet or None
        The Floquet multipliers, where ``solve(..., stability="full")`` computed
        them (`railtrack.floquet`); None otherwise.
    """

    passage: Passage
    foundation: Any
    harmonics: int
    coefficients: np.ndarray
    method: str
    converged: bool
    iterations: int
    residual_history: np.ndarray
    message: str
    split: int | None = None
    samples: int | None = None
    truncation_error: float = float("nan")
    stability: Any = None

    @property
    def track(self):
        """The `railtrack.Track` that was solved for."""
        return self.passage.track

    @property
    def train(self):
        """The `railtrack.Train` that was solved for."""
        return self.passage.train

    @property
    def residual(self) -> float:
        """Final relative residual of eq. (17)."""
        return float(self.residual_history[-1])

    @property
    def harmonic_numbers(self) -> np.ndarray:
        """n = -m..m."""
        return np.arange(-self.harmonics, self.harmonics + 1)

    @property
    def frequencies(self) -> np.ndarray:
        """omega_n for n = -m..m [rad/s], eq. (11)."""
        return self.passage.harmonic_frequencies(self.harmonics)

    @property
    def period(self) -> float:
        """T = H / v [s]."""
        return self.passage.period

    @property
    def mean_displacement(self) -> float:
        """c_0, the mean sleeper displacement [m]."""
        return float(self.coefficients[self.harmonics].real)

    def sleeper_displacement(self, t: ArrayLike) -> np.ndarray:
        """Sleeper displacement w(t) [m], eq. (19); t in seconds, any shape.

        w is positive upward; t = 0 when a wagon's first axle is above the sleeper.
        """
        return fourier_series(self.coefficients, self.frequencies, t)

    def sleeper_velocity(self, t: ArrayLike) -> np.ndarray:
        """Sleeper velocity w'(t) [m/s], eq. (18)."""
        omega = self.frequencies
        return fourier_series(1j * omega * self.coefficients, omega, t)

    def rail_coefficients(self) -> np.ndarray:
        """Fourier coefficients of the rail displacement above the sleeper, eq. (6) [m]."""
        omega = self.frequencies
        return rail_coefficients(
            self.passage, omega, self.coefficients, load_coefficients(self.passage, omega)
        )

    def rail_displacement(self, t: ArrayLike, x: ArrayLike = 0.0) -> np.ndarray:
        """Rail displacement w_r(x, t) [m], eq. (6) at x = 0, `railtrack.equations.rail_field` elsewhere.

        Parameters
        ----------
        t : array_like
            Time [s] (t = 0: a wagon's first axle above the observed sleeper).
        x : array_like, optional
            Position along the rail ahead of the observed sleeper (towards +x,
            the direction of travel) [m], any real value; broadcast with `t`.
            x = 0 (the default) is the rail above the sleeper, eq. (6).

        Returns
        -------
        ndarray
            w_r, positive upward, shape ``np.broadcast(t, x).shape``.
        """
        if np.all(np.asarray(x) == 0.0):
            values = fourier_series(self.rail_coefficients(), self.frequencies, t)
            return values + np.zeros(np.shape(x))
        return rail_field_series(self, t, x, 0)

    def rail_bending_moment(self, t: ArrayLike, x: ArrayLike = 0.0, *,
                            kinks: str = "closed form") -> np.ndarray:
        """Bending moment of the rail EI d^2 w_r / dx^2 at (x, t) [N m].

        Positive when sagging (the rail concave upward, as under a wheel),
        since w is positive upward.  `t` and `x` as in `rail_displacement`.
        Under a wheel the moment has a kink in time; by default the kinks are
        summed in closed form (`railtrack.equations.moment`), so that the series
        converges without the 1/m error of a kink.  Its neglected harmonics
        still fall more slowly than the displacement's: at
        ``harmonics="auto"`` the moment of the paper's wagon and of a
        four-axle coach is within 0.3 % of its peak of an 800-harmonic sum,
        and its peak within 0.3 % of the time-domain ring's
        (tests/test_forces.py), but at 250 m/s 0.7 % off where the
        displacement is within 5e-4; `truncation_errors` estimates it for
        any case (tests/test_output_accuracy.py).  ``kinks="series"`` gives
        the plain truncated Fourier series instead, for comparison: it
        converges like 1/m at the kinks.
        """
        ei = self.passage.rail_bending_stiffness
        if kinks == "closed form":
            return ei * rail_field_series(self, t, x, 1) + kink_sum(self.passage, t, x)
        if kinks == "series":
            return ei * rail_field_series(self, t, x, 2)
        raise ValueError(f'kinks must be "closed form" or "series"; got {kinks!r}')

    def truncation_errors(self, x: float = 0.0) -> dict[str, float]:
        """Estimated truncation error of each output from keeping m harmonics [-].

        `truncation_error` is the sleeper displacement's; the rail-seat load
        and the bending moment converge more slowly in m, and
        ``harmonics="auto"`` aims at the displacement only (on the paper's
        track at 250 m/s: w within 5e-4 of its peak, the load 1 %, the
        moment 0.7 %).  Ask for a larger m if an output you use is off by
        more than you accept.

        Parameters
        ----------
        x : float
            Position of the rail ahead of the sleeper for its displacement and
            moment [m].

        Returns
        -------
        dict
            ``"sleeper_displacement"``, ``"rail_displacement"``,
            ``"rail_seat_load"`` and ``"rail_bending_moment"``, each the
            largest neglected share over the period relative to that
            output's peak (`railtrack.solvers.output_errors`).
        """
        return output_truncation_errors(self, x)

    def rail_seat_load(self, t: ArrayLike) -> np.ndarray:
        """Pad force on the sleeper, positive in compression [N], eq. (5).

        ``k1 (w - w_r) + eta1 (w - w_r)'`` at x = 0, which is the reaction R(t)
        that the pad gives the rail (upward); its mean is sum Q_j L / H.
        The pad is linear, so it pulls (negative load) where the rail lifts
        more than the sleeper: a real pad clip would hold the rail down there.
        """
        omega = self.frequencies
        return fourier_series(
            seat_load_coefficients(self.passage, omega, self.coefficients), omega, t)

    def foundation_force(self, t: ArrayLike) -> np.ndarray:
        """Force that the sleeper puts on the foundation, positive in compression [N].

        It is ``-f(w, w')`` with f the law of eq. (15): the foundation pushes
        the sleeper up by -f, and the sleeper presses on it as much.  Its mean
        is sum Q_j L / H, for the sleeper's inertia averages out.  The dashpot of a law acts in tension as well,
        so even a tensionless law may report a small negative force.
        """
        return -np.asarray(
            self.foundation.force(self.sleeper_displacement(t), self.sleeper_velocity(t)),
            dtype=float,
        )

    def deflection_bowl(self, t: ArrayLike, x: ArrayLike) -> DeflectionBowl:
        """The rail and the sleepers along the track at one instant, or at several [m].

        See `railtrack.equations.bowl.deflection_bowl`, which this calls.
        """
        return deflection_bowl(self, t, x)

    @property
    def sleeper_shape(self) -> tuple[int, ...]:
        """(), the sleeper axis of a cell of one sleeper dropped (`result_protocol`)."""
        return ()

    def rail_above_sleepers(self, t: ArrayLike) -> np.ndarray:
        """The rail above the sleeper, ``rail_displacement(t, 0)`` [m], shape of t."""
        return self.rail_displacement(t, 0.0)

    def at_rest(self):
        """The sleeper before the train arrives (this model has no self-weight): 0 N, 0 m."""
        return single_at_rest(self.passage, self.foundation)

    _rows = solution_rows               # __repr__, _repr_html_ (ShortRepr)
    _table_row = "time"                 # to_dataframe: a row per instant

    def to_xarray(self, samples: int = 400, x=None):
        """This result as an `xarray.Dataset` over one period of `samples` instants (CF units).

        Dimensions, variables and attributes: `railtrack.solvers.result_export`.
        ``x`` [m] adds the rail's displacement and moment along x (dimension x).
        """
        from .result_export import solution_dataset
        return solution_dataset(self, samples, x)

