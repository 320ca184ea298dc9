"""The periodic response with wheels on Hertz springs, and what it tells an engineer.

Per wheel k of a wagon (first axis, the train's axles in order): the
contact force P_k(t) [N], positive in compression, the compression
delta_k(t) [m], the wheel's displacement z_k(t) [m], positive upward; and,
through `sleepers` (a `railtrack.CellSolution` loaded by the wheels' actual
forces), every sleeper's displacement, rail-seat load and foundation force.
t = 0 has axle 1 above sleeper 0, as in `railtrack.Solution`; wheel k is at
x = vt - d_k along the track.  It answers the questions every steady-state
result answers, alike (`railtrack.solvers.result_protocol`): `one_period`
gives (t, w), ``one_period(n)[0]`` the times alone.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..equations.moment import kink_sum
from ..equations.positions import check_positions, checked_times
from ..equations.wheel_receptance import wheel_receptance
from ..model.passage import Passage
from .cell_solution import CellSolution
from .field_chunks import chunk_length
from .wheel_extremes import anchor_sag, extremes, loss_of_contact, peak_samples
from .wheel_free_rail import free_rail
from .result_protocol import SharedOutputs, period_samples
from .design_figures import DesignFigures
from .export import Exports
from .result_repr import ShortRepr, wheel_rows

__all__ = ["WheelSolution"]


@dataclass(frozen=True, repr=False)
class WheelSolution(SharedOutputs, ShortRepr, DesignFigures, Exports):
    """Wheels, rail and sleepers in the steady state; ``converged`` only if the residual <= tol.

    Attributes
    ----------
    passage : Passage
    wheel : Wheel or Vehicle
    profile : callable
        r(x) [m], the rail-top profile.
    harmonics : int
        m, of the sleepers' fundamental 2 pi v / H.
    grid : ndarray
        The wheels' harmonics p (multiples of H / (N L)).
    contact_harmonics, compression_harmonics : ndarray, shape (K, lmax)
        P_{k,p} [N] and the harmonics of delta_k without the profile [m].
    lift : ndarray, shape (K,)
        Mean of delta_k minus the profile's mean [m].
    profile_harmonics : ndarray, shape (K, lmax+1)
        The profile under each wheel, its mean and harmonics p = grid [m]:
        the solution sees the profile through them.
    sleepers : CellSolution
    converged : bool
    residual : float
        Contact residual over the largest static wheel load.
    iterations : int
    message : str
    truncation_error : float
        Estimated error of the contact force from keeping m harmonics, over
        the largest static wheel load [-]; NaN if not estimated.

    Examples
    --------
    >>> import railtrack as rt
    >>> solution = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation(20e6, 0.2e6),
    ...                     wheel=rt.Wheel(600.0))          # harmonics="auto": m until P settles
    >>> solution.converged, solution.grid[:3]  # the wheels feel the 30 sleepers of a wagon
    (True, array([30, 60, 90]))
    >>> bool(solution.truncation_error < 1e-3)              # of Q, from the last refinement
    True
    >>> e = solution.extremes()
    >>> [round(float(p) / 1e3, 1) for p in e["max"]], round(float(e["mean"][0]) / 1e3, 6)
    ([75.4, 75.4], 75.0)
    """

    passage: Passage
    wheel: Any
    profile: Any
    harmonics: int
    grid: np.ndarray
    contact_harmonics: np.ndarray
    compression_harmonics: np.ndarray
    lift: np.ndarray
    profile_harmonics: np.ndarray
    sleepers: CellSolution
    converged: bool
    residual: float
    iterations: int
    message: str
    truncation_error: float = float("nan")

    @property
    def period(self) -> float:
        """T = H / v [s], one wagon passing."""
        return float(self.passage.period)

    def _series(self, harmonics: np.ndarray, t: ArrayLike) -> np.ndarray:
        omega = 2 * np.pi * self.grid / self.period
        t = checked_times(omega, t)
        flat = t.ravel()
        n = flat.size
        if self.grid.size and n > 2 * int(self.grid[-1]) and np.allclose(
                flat, np.arange(n) * (self.period / n), rtol=0.0, atol=1e-12 * self.period):
            # n instants evenly over one period (auto's comparison, one_period, extremes):
            # an inverse FFT, not the direct sum's n x l phases (0.1 s at m = 549, n = 4096)
            spectrum = np.zeros((harmonics.shape[0], n // 2 + 1), dtype=complex)
            spectrum[:, self.grid] = harmonics
            return (n * np.fft.irfft(spectrum, n, axis=-1)).reshape(
                (harmonics.shape[0],) + t.shape)
        out = np.empty((harmonics.shape[0], flat.size))
        step = chunk_length(omega.size)          # (times, lmax) blocks: bounded memory
        for start in range(0, flat.size, step):
            phases = np.exp(1j * np.multiply.outer(flat[start:start + step], omega))
            out[:, start:start + step] = 2 * (harmonics @ phases.T).real
        return out.reshape((harmonics.shape[0],) + t.shape)

    def compression(self, t: ArrayLike) -> np.ndarray:
        """delta_k(t) [m], shape (K,) + t.shape; the wheel is off the rail where < 0."""
        mean = (self.lift + self.profile_harmonics[:, 0].real).reshape((-1,) + (1,) * np.ndim(t))
        return self._series(self.compression_harmonics + self.profile_harmonics[:, 1:], t) + mean

    def contact_force(self, t: ArrayLike) -> np.ndarray:
        """P_k(t) = C_H max(delta_k, 0)^{3/2} [N], shape (K,) + t.shape."""
        return self.wheel.contact_force(self.compression(t))

    def wheel_displacement(self, t: ArrayLike) -> np.ndarray:
        """z_k(t) [m], positive upward, from the undeformed track; shape (K,) + t.shape.

        Its harmonics are ``A(omega_p) P_p`` (`railtrack.equations.wheel_receptance`:
        ``-P_p / (m_w omega_p^2)`` for a `Wheel`); its mean is the rail's
        mean under the wheel minus the mean compression.
        """
        omega = 2 * np.pi * self.grid / self.period
        if self.grid.size:
            receptance = wheel_receptance(self.wheel, omega, self.contact_harmonics.shape[0])
            harmonics = np.einsum("lkq,ql->kl", receptance, self.contact_harmonics)
        else:
            harmonics = self.contact_harmonics
        fluctuation = self._series(harmonics, t)
        return fluctuation + self._mean_height.reshape((-1,) + (1,) * np.ndim(t))

    @cached_property
    def _mean_height(self) -> np.ndarray:
        # The mean of the rail under a moving wheel takes only the wheels' static
        # loads and the sleepers' reactions (a varying force reaches the wheel at
        # its own harmonic, never the mean): the rail field of `sleepers`, read
        # along the wheel's path, less the anchor's error (`_anchor_sag`).
        # Checked against the ring to 0.01 um (tests/test_wheel_solve.py).
        # The field is band-limited to the m harmonics: 1024 samples average it
        # exactly for m < 1024.
        t = np.arange(1024) * self.period / 1024
        path = self.wheel_position(t)
        under = self.sleepers._field(np.broadcast_to(t, path.shape), path, 0)
        height = under.mean(axis=-1) - self._anchor_sag - self.lift
        height.setflags(write=False)              # computed once and shared
        return height

    @cached_property
    def _anchor_sag(self) -> float:
        """The static sag at sleeper 0 of the wheels' uneven mean load [m] (`anchor_sag`)."""
        return anchor_sag(self)

    def _check_positions(self, x: ArrayLike) -> None:
        """Refuse x whose phases round-off swamps, for the sleepers' and the wheels' harmonics."""
        top = max(float(self.sleepers.frequencies.max()),
                  2 * np.pi * float(np.max(self.grid)) / self.period)
        check_positions(self.passage, [top], x)

    def rail_displacement(self, t: ArrayLike, x: ArrayLike = 0.0) -> np.ndarray:
        """w_r(x, t) [m] anywhere along the rail (x from sleeper 0); t, x broadcast.

        The rail field of `sleepers` (their reactions and the wheels' static
        loads) plus the free rail under the wheels' varying forces, eq.
        (14.2), with the anchor at sleeper 0 corrected (`_anchor_sag`).  Any
        number of points, in blocks of bounded memory; x as
        `railtrack.CellSolution.rail_displacement` (too far or not finite: ValueError).
        """
        self._check_positions(x)
        return (self.sleepers._field(t, x, 0) + free_rail(self, t, x, 0)
                - self._anchor_sag)

    def rail_bending_moment(self, t: ArrayLike, x: ArrayLike = 0.0, *,
                            kinks: str = "closed form") -> np.ndarray:
        """EI d^2 w_r/dx^2 at time t [s] and position x [m] [N m], sagging positive.

        `railtrack.CellSolution.rail_bending_moment` (the static loads' kinks in
        closed form, or ``kinks="series"``: the plain truncated series) plus EI
        times the curvature of eq. (14.2), which is continuous across the wheel.
        """
        self._check_positions(x)
        ei = float(self.passage.rail_bending_stiffness)
        if kinks == "closed form":
            static = ei * self.sleepers._field(t, x, 1) + kink_sum(self.passage, t, x)
        elif kinks == "series":
            static = ei * self.sleepers._field(t, x, 2)
        else:
            raise ValueError(f'kinks must be "closed form" or "series"; got {kinks!r}')
        return static + ei * free_rail(self, t, x, 2)

    def rail_seat_load(self, t: ArrayLike) -> np.ndarray:
        """Each sleeper's rail-seat load [N], (N,) + t.shape, positive in compression."""
        return self.sleepers.rail_seat_load(t)

    def sleeper_displacement(self, t: ArrayLike) -> np.ndarray:
        """Each sleeper's w_j(t) [m], (N,) + t.shape, positive upward."""
        return self.sleepers.sleeper_displacement(t)

    def extremes(self, samples: int | None = None) -> dict[str, np.ndarray]:
        """Per wheel: largest and smallest P [N], where they occur [m], mean P [N].

        Positions are the wheel's distance from sleeper 0 along the track,
        within one wagon length (0 <= x < H); ``dynamic_factor`` is max P / Q.
        `samples` >= 1 times over the period (`wheel_extremes.extremes`); by
        default `peak_samples`: max(4096, 16 m), so that a short blow (a wheel
        flat's P1) is not missed between samples.
        """
        return extremes(self, peak_samples(self) if samples is None else samples)

    def loss_of_contact(self, samples: int = 8192) -> tuple[np.ndarray, np.ndarray]:
        """Per wheel: the share of the period off the rail, and the longest spell off it [s]."""
        return loss_of_contact(self, samples)

    @property
    def frequencies(self) -> np.ndarray:
        """omega_n, n = -m..m [rad/s], of the sleepers' series."""
        return self.sleepers.frequencies

    @property
    def stability(self) -> None:
        """None: a wheel solution is not judged by Floquet (yet)."""
        return None

    @property
    def sleeper_shape(self) -> tuple[int, ...]:
        """(N,): per-sleeper outputs are (N,) + t.shape (`result_protocol`)."""
        return self.sleepers.sleeper_shape

    def sleeper_velocity(self, t: ArrayLike) -> np.ndarray:
        """Each sleeper's w_j'(t) [m/s], (N,) + t.shape."""
        return self.sleepers.sleeper_velocity(t)

    def foundation_force(self, t: ArrayLike) -> np.ndarray:
        """Each sleeper's force on its foundation [N], (N,) + t.shape, positive in compression."""
        return self.sleepers.foundation_force(t)

    def rail_above_sleepers(self, t: ArrayLike) -> np.ndarray:
        """The rail above each sleeper (through its pad) [m], (N,) + t.shape."""
        return self.sleepers.rail_above_sleepers(t)

    def contact_fraction(self, samples: int = 2048) -> np.ndarray:
        """Share of the period in which each sleeper presses on its foundation [-]."""
        return self.sleepers.contact_fraction(samples)

    def at_rest(self):
        """The track under its own weight before the train arrives (`CellSolution.at_rest`)."""
        return self.sleepers.at_rest()

    _rows = wheel_rows                  # __repr__, _repr_html_ (ShortRepr)
    _table_row = "time"                 # to_dataframe: a row per instant

    def to_xarray(self, samples: int | None = None, x=None):
        """This result as an `xarray.Dataset` over one period of `samples` instants (CF units).

        Default: max(400, 4 m) instants, the results' common default
        (`railtrack.solvers.result_protocol.period_samples`); a short blow (a
        wheel flat's P1) reads up to a few percent low on it: `extremes()`
        reads the peaks on 16 m instants, or pass more `samples` here.

        Dimensions, variables and attributes: `railtrack.solvers.result_export`.
        ``x`` [m] adds the rail's displacement and moment along x (dimension x).
        """
        from .result_export import wheel_dataset
        return wheel_dataset(self, period_samples(self, samples), x)

