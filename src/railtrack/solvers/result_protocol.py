"""One kind of result: the questions `Solution`, `CellSolution` and `WheelSolution` all answer.

The three results of a steady-state solve answer the same questions under
the same names, with the same arguments in the same order (time t [s]
first, position x [m] second) and the same axis order: **sleepers or
wheels first, time last**.  `SteadyStateResult` writes the protocol down;
tests/test_result_protocol.py holds each class to it.

Shapes, for times t of any shape:

- per sleeper (`sleeper_displacement`, `sleeper_velocity`,
  `rail_above_sleepers`, `rail_seat_load`, `foundation_force`):
  ``sleeper_shape + t.shape``, with ``sleeper_shape == (N,)`` for the N
  sleepers of a cell, sleeper j at x = jL;
- per wheel (`wheel_position`, `contact_force`, `rail_under_wheels`):
  ``(K,) + t.shape``, the train's axles in the order of ``axle_positions``;
- along the rail (`rail_displacement`, `rail_bending_moment`): the
  broadcast shape of t and x.

**The single-sleeper Solution is a cell of one sleeper.**  Its equations
are the cell's with N = 1 (a uniform track: every sleeper j moves as
sleeper 0 delayed by jL/v, which the test checks against a cell of N
identical sleepers).  Its sleeper axis, of length one, is dropped:
``sleeper_shape == ()`` and its per-sleeper arrays have the shape of t, as
the book and every study have always read them.  Code written for any
result reads ``sleeper_shape`` (or uses ``np.reshape(a, (-1,) + t.shape)``).

**one_period.**  ``one_period(samples=None)`` returns ``(t, w)``: ``samples``
times evenly over [0, T) [s] and `sleeper_displacement` there [m].  The
default takes ``max(400, 4 m)`` samples (`period_samples`), m the highest
harmonic kept: 400 as before for the sleeper and the cell (m <= 100), and
at least four samples per shortest wave for the wheels, whose m reaches
hundreds.

Questions one class alone answers, and why the others do not:
`Solution.deflection_bowl` and `Solution.truncation_errors` (per output)
are built on the single sleeper's closed forms; `WheelSolution.extremes`,
`compression`, `wheel_displacement` and `loss_of_contact` concern a wheel
on a Hertz spring: under the moving constant loads of `Solution` and
`CellSolution` the contact force is Q_k at every instant (`contact_force`
says so) and there is no wheel mass to move.  A wheel solution is not
judged by Floquet (its `stability` is None).
"""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike

from ..model.cell import SleeperCell
from ..model.passage import Passage
from .cell_static import AtRest, cell_at_rest

__all__ = ["SteadyStateResult", "PER_SLEEPER", "PER_WHEEL", "ALONG_RAIL", "SHARED_METHODS",
           "SHARED_ATTRIBUTES", "period_samples", "period_times", "one_period",
           "wheel_positions", "moving_contact_force", "rail_under_wheels", "contact_fraction",
           "single_at_rest", "SharedOutputs", "top_harmonic"]

PER_SLEEPER = ("sleeper_displacement", "sleeper_velocity", "rail_above_sleepers",
               "rail_seat_load", "foundation_force")
PER_WHEEL = ("wheel_position", "contact_force", "rail_under_wheels")
ALONG_RAIL = ("rail_displacement", "rail_bending_moment")
SHARED_METHODS = PER_SLEEPER + PER_WHEEL + ALONG_RAIL + ("one_period", "contact_fraction",
                                                          "at_rest")
SHARED_ATTRIBUTES = ("passage", "harmonics", "converged", "residual", "iterations", "message",
                     "truncation_error", "stability", "period", "frequencies", "sleeper_shape")
MIN_SAMPLES = 400
"""Fewest samples of `one_period` by default (the sleeper's plots since chapter 1)."""


@runtime_checkable
class SteadyStateResult(Protocol):
    """What every steady periodic result answers (module docstring: shapes and signs).

    Displacements are positive upward, loads and foundation forces positive
    in compression, bending moments positive when sagging; t = 0 has a
    wagon's first axle above sleeper 0.
    """

    passage: Passage
    harmonics: int
    converged: bool
    residual: float
    iterations: int
    message: str
    truncation_error: float

    @property
    def stability(self) -> Any: ...            # a Floquet, or None if not computed
    @property
    def period(self) -> float: ...             # T = H / v [s]
    @property
    def frequencies(self) -> np.ndarray: ...   # omega_n, n = -m..m [rad/s]
    @property
    def sleeper_shape(self) -> tuple[int, ...]: ...   # () or (N,)

    def sleeper_displacement(self, t: ArrayLike) -> np.ndarray: ...      # [m]
    def sleeper_velocity(self, t: ArrayLike) -> np.ndarray: ...          # [m/s]
    def rail_above_sleepers(self, t: ArrayLike) -> np.ndarray: ...       # [m]
    def rail_seat_load(self, t: ArrayLike) -> np.ndarray: ...            # [N]
    def foundation_force(self, t: ArrayLike) -> np.ndarray: ...          # [N]
    def wheel_position(self, t: ArrayLike) -> np.ndarray: ...            # [m]
    def contact_force(self, t: ArrayLike) -> np.ndarray: ...             # [N]
    def rail_under_wheels(self, t: ArrayLike) -> np.ndarray: ...         # [m]
    def rail_displacement(self, t: ArrayLike, x: ArrayLike = 0.0) -> np.ndarray: ...   # [m]
    def rail_bending_moment(self, t: ArrayLike, x: ArrayLike = 0.0, *,
                            kinks: str = "closed form") -> np.ndarray: ...          # [N m]
    def one_period(self, samples: int | None = None) -> tuple[np.ndarray, np.ndarray]: ...
    def contact_fraction(self, samples: int = 2048) -> np.ndarray: ...   # [-]
    def at_rest(self) -> AtRest: ...


def top_harmonic(result) -> int:
    """The highest harmonic a result holds: m, or its wheels' highest p if higher."""
    grid = getattr(result, "grid", None)
    return max(int(result.harmonics), int(np.max(grid)) if grid is not None and
               np.size(grid) else 0)


def period_samples(result, samples: int | None = None) -> int:
    """`samples`, or by default max(400, 4 m) with m the highest harmonic of `result`."""
    if samples is None:
        return max(MIN_SAMPLES, 4 * top_harmonic(result))
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 1:
        raise ValueError(f"samples must be a positive integer or None; got {samples!r}")
    return int(samples)


def period_times(period: float, samples: int) -> np.ndarray:
    """`samples` times evenly over [0, T) [s]."""
    return np.linspace(0.0, float(period), int(samples), endpoint=False)


def one_period(result, samples: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(t, w): times over [0, T) [s] and `result.sleeper_displacement` there [m]."""
    t = period_times(result.period, period_samples(result, samples))
    return t, result.sleeper_displacement(t)


def wheel_positions(passage: Passage, t: ArrayLike) -> np.ndarray:
    """x_k(t) = v t - d_k [m], wheel k's distance past sleeper 0; shape (K,) + t.shape."""
    t = np.asarray(t, dtype=float)
    d = np.asarray(passage.axle_positions, dtype=float)
    return float(passage.speed) * t[None] - d.reshape((-1,) + (1,) * t.ndim)


def moving_contact_force(passage: Passage, t: ArrayLike) -> np.ndarray:
    """Q_k at every t [N], shape (K,) + t.shape: a moving constant load presses with its weight."""
    t = np.asarray(t, dtype=float)
    q = np.asarray(passage.axle_loads, dtype=float)
    return np.broadcast_to(q.reshape((-1,) + (1,) * t.ndim), q.shape + t.shape).copy()


def rail_under_wheels(result, t: ArrayLike) -> np.ndarray:
    """The rail at each wheel's contact point, ``rail_displacement(t, x_k(t))`` [m], (K,) + t."""
    x = result.wheel_position(t)
    return result.rail_displacement(np.broadcast_to(np.asarray(t, dtype=float), x.shape), x)


def contact_fraction(result, samples: int = 2048) -> np.ndarray:
    """Share of the period in which each sleeper presses on its foundation (force > 0) [-]."""
    t = period_times(result.period, period_samples(result, samples))
    return np.mean(result.foundation_force(t) > 0.0, axis=-1)


def single_at_rest(passage: Passage, foundation) -> AtRest:
    """`cell_at_rest` of the one-sleeper cell, its sleeper axis dropped (floats).

    The single sleeper's model has no self-weight (the paper's), so this is
    where its law alone settles without load: 0 for every law of the book.
    """
    rest = cell_at_rest(passage, SleeperCell.identical(passage, foundation, 1))
    return AtRest(*(float(np.asarray(a)[0]) for a in rest[:3]), rest.converged)


class SharedOutputs:
    """The protocol's methods that every result computes alike from its other outputs.

    `one_period`, `wheel_position`, `rail_under_wheels` and `contact_fraction`
    read the class's `period`, `sleeper_displacement`, `rail_displacement` and
    `foundation_force`; `contact_force` is that of loads moving at constant
    force (`Solution`, `CellSolution`): a `WheelSolution` gives its own.
    """

    def one_period(self, samples: int | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(t, w): `samples` times over [0, T) [s], (samples,), and w there, sleeper_shape + (samples,) [m].

        max(400, 4 m) samples by default (module docstring); ``one_period(n)[0]``
        are the times alone, e.g. for `contact_force`.
        """
        return one_period(self, samples)

    def wheel_position(self, t: ArrayLike) -> np.ndarray:
        """x_k(t) = v t - d_k [m], wheel k's distance past sleeper 0 (the observed one); (K,) + t.shape.

        Take it modulo the wagon length H to read it within one wagon, where
        the track and the loads repeat.
        """
        return wheel_positions(self.passage, t)

    def contact_force(self, t: ArrayLike) -> np.ndarray:
        """Q_k at every t [N], (K,) + t.shape: the loads move at constant force."""
        return moving_contact_force(self.passage, t)

    def rail_under_wheels(self, t: ArrayLike) -> np.ndarray:
        """The rail at each wheel's contact point, ``rail_displacement(t, x_k(t))`` [m].

        Shape (K,) + t.shape: axle k in the order of ``train.axle_positions``
        (wheels first, time last).
        """
        return rail_under_wheels(self, t)

    def contact_fraction(self, samples: int = 2048) -> np.ndarray:
        """Share of the period in which each sleeper presses on its foundation (force > 0) [-]."""
        return contact_fraction(self, samples)
