"""The train: an endless row of identical wagons at constant speed (eq. 9).

One wagon is its length H (the spatial period of the load) and its axles:
their positions d_j behind the wagon's first axle and the load Q_j that each
puts on the one rail the model represents (half the axle load).  The paper's
wagon has two axles, d = (0, D); real vehicles have four or more, and a
single axle is a wagon long enough that its neighbours do not matter.
All quantities are SI.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .plausibility_check import check_plausible, quantities_to_si
from .validation import as_float64, require_non_negative, require_positive

__all__ = ["Train", "STANDARD_GRAVITY", "SINGLE_AXLE_LENGTH", "MAX_SPEED"]

STANDARD_GRAVITY = 9.81
"""g [m/s^2], to turn the masses of the vehicle presets into loads."""

SINGLE_AXLE_LENGTH = 60.0
"""Default wagon length of `Train.single_axle` [m]."""

MAX_SPEED = float(np.sqrt(np.finfo(np.float64).max))
"""1.34e154 m/s: above it v^2, which eq. (3) needs, overflows double precision [m/s]."""


def _as_tuple(name: str, values) -> tuple[float, ...]:
    array = np.atleast_1d(np.asarray(values))
    if array.ndim != 1 or array.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be a sequence of real numbers; got {values!r}")
    return tuple(float(v) for v in array)


@dataclass(frozen=True)
class Train:
    """An endless row of identical wagons at speed v, eq. (9) generalised to any axles.

    Parameters
    ----------
    wagon_length : float
        Length H of a wagon, the spatial period of the load [m].
    axle_positions : sequence of float
        Distance d_j of each axle behind the wagon's first axle [m]:
        first 0, increasing, all < H.
    axle_loads : sequence of float
        Load Q_j of each axle's wheel on the modelled rail [N] (half the
        axle load); loads push the rail down.
    speed : float
        Train speed v [m/s], towards +x, > 0 and at most `MAX_SPEED`
        (1.34e154 m/s, where v^2 overflows).  May be an array of shape
        ``(..., 1)`` for a batch (`railtrack.sweep_speeds`).

    Examples
    --------
    >>> train = Train.paper()
    >>> train.axle_positions, train.axle_loads
    ((0.0, 3.0), (75000.0, 75000.0))
    >>> train.period                       # H / v [s], eq. (13)
    0.4
    >>> Train.paper(wheel_spacing=2.5, speed=30.0).axle_positions
    (0.0, 2.5)
    """

    wagon_length: float
    axle_positions: tuple[float, ...]
    axle_loads: tuple[float, ...]
    speed: float

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_non_negative("axle_positions", self.axle_positions, "m")
        require_positive("axle_loads", self.axle_loads, "N")
        object.__setattr__(self, "axle_positions", _as_tuple("axle_positions", self.axle_positions))
        object.__setattr__(self, "axle_loads", _as_tuple("axle_loads", self.axle_loads))
        if not self.axle_positions:
            raise ValueError(f"axle_positions must list at least one axle (0.0 for the first); "
                             f"got {self.axle_positions!r}")
        require_positive("wagon_length", self.wagon_length, "m")
        require_positive("speed", self.speed, "m/s")
        if np.any(np.asarray(self.speed, dtype=float) > MAX_SPEED):
            raise ValueError(f"speed must be at most {MAX_SPEED:.3g} m/s, above which v^2 "
                             f"overflows double precision; got {self.speed!r} m/s")
        positions, length = np.array(self.axle_positions), np.asarray(self.wagon_length)
        if len(positions) != len(self.axle_loads):
            raise ValueError(
                f"axle_positions and axle_loads must have one entry per axle; got "
                f"{len(positions)} positions and {len(self.axle_loads)} loads")
        if positions[0] != 0.0 or np.any(np.diff(positions) <= 0):
            raise ValueError(
                "axle_positions must start at 0 (the wagon's first axle) and increase; "
                f"got {self.axle_positions}")
        if not np.all(positions[-1] < length):
            raise ValueError(
                "every axle must lie within the wagon, d_j < wagon_length; got last axle "
                f"at {positions[-1]:g} m and wagon_length={self.wagon_length!r}")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def paper(cls, wheel_spacing: float = 3.0, wheel_load: float = 75e3, **changes) -> "Train":
        """The paper's wagon (Table 1): H = 18 m, two axles D = 3 m apart, Q = 75 kN, 45 m/s.

        `wheel_spacing` (D) and `wheel_load` (Q) set the two axles; `changes`
        may set `wagon_length` and `speed`.
        """
        values = dict(wagon_length=18.0, axle_positions=(0.0, wheel_spacing),
                      axle_loads=(wheel_load, wheel_load), speed=45.0)
        values.update(changes)
        return cls(**values)

    @classmethod
    def passenger_coach(cls, speed: float = 45.0) -> "Train":
        """A four-axle passenger coach: UIC type Z body on two bogies, 109 kN per axle.

        Length over buffers 26.4 m and bogie pivots 19 m apart (UIC type Z,
        UIC leaflet 567); bogie wheelbase 2.5 m (Minden-Deutz bogies).  The
        axle load 109.1 kN is the static load of the Manchester benchmark
        coach (Iwnicki 1998: body 32 t, two 2.615 t bogie frames, four
        1.813 t wheelsets), whose bogie pivots are also 19 m apart: 54.5 kN
        per wheel.  Axles at 0, 2.5, 19 and 21.5 m; 4.9 m to the next coach.
        """
        wheel = (32000.0 + 2 * 2615.0 + 4 * 1813.0) * STANDARD_GRAVITY / 4 / 2
        return cls(26.4, (0.0, 2.5, 19.0, 21.5), (wheel,) * 4, speed)

    @classmethod
    def freight_wagon(cls, speed: float = 20.0) -> "Train":
        """A four-axle heavy-haul coal wagon of the Chinese C80 class, 25 t per axle.

        Length 12.0 m over couplers and 100 t gross on two bogies of 25 t
        axle load: 122.6 kN per wheel.  The bogie pivots (8.2 m apart) and the
        bogie wheelbase (1.83 m) are typical of this class of wagon and bogie
        but were not checked against a maker's data sheet.  Axles at 0,
        1.83, 8.2 and 10.03 m; 1.97 m to the next wagon.
        """
        wheel = 25e3 * STANDARD_GRAVITY / 2
        return cls(12.0, (0.0, 1.83, 8.2, 10.03), (wheel,) * 4, speed)

    @classmethod
    def single_axle(cls, wheel_load: float = 75e3, speed: float = 45.0,
                    wagon_length: float = SINGLE_AXLE_LENGTH) -> "Train":
        """One axle, its neighbours `wagon_length` away (default 60 m).

        The response to a row of axles H apart tends to that of one axle as
        H grows, for the bowl under an axle dies out within a few metres.
        At 60 m the peak sleeper and rail displacements and the peak
        rail-seat load differ from those at 480 m by less than 0.1 %, at 10
        to 100 m/s on the paper's and on the ballasted track
        (tests/test_train.py).  The harmonics needed grow like H, so a
        longer wagon only costs time.
        """
        return cls(wagon_length, (0.0,), (wheel_load,), speed)

    def replace(self, **changes) -> "Train":
        """Return a copy with some fields changed (validated again)."""
        return dataclasses.replace(self, **changes)

    def tiled(self, wagons: int) -> "Train":
        """`wagons` wagons of this train as one wagon of length n H, the axles repeated [m, N].

        For a steady state that repeats every n wagons (a rail-top profile of
        period n H): its wheels are then the n H-long wagon's 4n axles.

        Examples
        --------
        >>> Train.paper().tiled(2).axle_positions
        (0.0, 3.0, 18.0, 21.0)
        """
        if isinstance(wagons, bool) or not isinstance(wagons, (int, np.integer)) or wagons < 1:
            raise ValueError(f"wagons must be an integer >= 1; got {wagons!r}")
        if wagons == 1:
            return self
        length = float(self.wagon_length)
        positions = (length * np.arange(wagons)[:, None]
                     + np.asarray(self.axle_positions, dtype=float)).ravel()
        return Train(wagons * length, tuple(positions.tolist()),
                     tuple(np.tile(self.axle_loads, wagons).tolist()), self.speed)

    @property
    def axle_count(self) -> int:
        """Number of axles per wagon."""
        return len(self.axle_positions)

    @property
    def wagon_load(self) -> float:
        """Sum of the wheel loads of one wagon on the modelled rail, sum Q_j [N]."""
        return float(sum(self.axle_loads))

    @property
    def wheel_spacing(self) -> float:
        """The distance D of the paper between the two axles of a two-axle wagon [m]."""
        if self.axle_count != 2:
            raise AttributeError(f"wheel_spacing (D) is defined for a two-axle wagon; "
                                 f"this one has {self.axle_count} axles (see axle_positions)")
        return self.axle_positions[1]

    @property
    def wheel_load(self) -> float:
        """The load Q of the paper on every wheel, when all wheels carry the same [N]."""
        if len(set(self.axle_loads)) != 1:
            raise AttributeError(f"wheel_load (Q) needs equal axle loads; got {self.axle_loads}")
        return self.axle_loads[0]

    @property
    def period(self) -> float:
        """Period T = H / v of the load seen by one sleeper, eq. (13) [s]."""
        return self.wagon_length / self.speed

    @property
    def fundamental_frequency(self) -> float:
        """Angular frequency 2 pi v / H of the first harmonic, eq. (11) [rad/s]."""
        return 2.0 * np.pi * self.speed / self.wagon_length

    def harmonic_frequencies(self, harmonics: int) -> np.ndarray:
        """omega_n = 2 pi n v / H for n = -m..m, eq. (11) [rad/s].

        With an array speed (shape ``(..., 1)``) the harmonic axis is the last.
        """
        n = np.arange(-harmonics, harmonics + 1)
        return np.asarray(self.fundamental_frequency) * n
