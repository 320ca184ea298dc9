"""Parameters of the track and of the train (Table 1 of Hoang et al. 2015).

All quantities are SI: metres, seconds, kilograms, newtons.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["Track", "require_positive", "require_non_negative", "as_float64"]


def _as_real(name: str, value: ArrayLike, unit: str) -> np.ndarray:
    """`value` as float64, or a ``TypeError`` naming `name` if it is not a real number."""
    array = np.asarray(value)
    if array.dtype.kind not in "iuf":
        kind = {"b": "a boolean", "c": "a complex number", "U": "a string", "S": "a string"}.get(
            array.dtype.kind, f"of type {type(value).__name__}"
        )
        raise TypeError(
            f"{name} must be a real number{' in ' + unit if unit else ''}; got {value!r}, {kind}"
        )
    return array.astype(np.float64)


def require_positive(name: str, value: ArrayLike, unit: str = "") -> None:
    """Raise unless every element of `value` is a finite real number > 0.

    ``TypeError`` for booleans, complex numbers, strings and other non-real
    values; ``ValueError`` for values that are not finite or not > 0.
    """
    array = _as_real(name, value, unit)
    if not np.all(np.isfinite(array)) or not np.all(array > 0):
        raise ValueError(
            f"{name} must be a finite number > 0{' ' + unit if unit else ''}; got {value!r}"
        )


def require_non_negative(name: str, value: ArrayLike, unit: str = "") -> None:
    """Raise unless every element of `value` is a finite real number >= 0 (see `require_positive`)."""
    array = _as_real(name, value, unit)
    if not np.all(np.isfinite(array)) or not np.all(array >= 0):
        raise ValueError(
            f"{name} must be a finite number >= 0{' ' + unit if unit else ''}; got {value!r}"
        )


def as_float64(instance) -> None:
    """Store every field of a frozen dataclass as float64 (a float, or an array for batches).

    Single precision or integer input would otherwise leak into the sums of
    eq. (3), which lose digits in float32.
    """
    for field in dataclasses.fields(instance):
        value = getattr(instance, field.name)
        if not isinstance(value, (int, float, np.number, np.ndarray)) or isinstance(value, bool):
            continue
        array = np.asarray(value, dtype=np.float64)
        object.__setattr__(instance, field.name, float(array) if array.ndim == 0 else array)


@dataclass(frozen=True)
class Track:
    """A periodically supported rail, its sleepers and pads, and the train on it.

    The rail is an infinite Euler–Bernoulli beam resting on identical sleepers
    spaced `sleeper_spacing` apart (Fig. 1 of the paper).  A pad (spring
    `pad_stiffness`, dashpot `pad_damping`) joins the rail to each sleeper.
    The train is an endless row of identical wagons of length `wagon_length`,
    each with two wheels `wheel_spacing` apart carrying `wheel_load` each,
    running at `speed` (eq. 9).

    Parameters
    ----------
    rail_linear_mass : float
        Mass of the rail per unit length, rho*S [kg/m].
    rail_bending_stiffness : float
        Bending stiffness of the rail, E*I [N m^2].
    speed : float
        Train speed v [m/s].
    wheel_load : float
        Load Q carried by each wheel [N].  Loads push the rail down.
    sleeper_mass : float
        Mass M of one sleeper [kg].
    sleeper_spacing : float
        Distance L between neighbouring sleepers [m].
    wheel_spacing : float
        Distance D between the front and the back wheel of a wagon [m],
        with ``0 < D < H``.
    wagon_length : float
        Length H of a wagon, the spatial period of the load [m].
    pad_stiffness : float
        Rail-pad stiffness k1 [N/m].
    pad_damping : float
        Rail-pad viscous damping eta1 [N s/m], may be zero.

    Notes
    -----
    Every field may also be a numpy array; all formulas of the package are
    elementwise, so arrays that broadcast against each other and against the
    frequency axis describe a batch of tracks: give batched fields a trailing
    axis of length one, shape ``(..., 1)``, so that the last axis stays the
    harmonic axis (see `railtrack.sweep_speeds`).

    Examples
    --------
    >>> track = Track.paper()
    >>> track.period        # H / v, seconds
    0.4
    >>> round(track.static_load_per_sleeper)   # 2 Q L / H, newtons
    5000
    """

    rail_linear_mass: float
    rail_bending_stiffness: float
    speed: float
    wheel_load: float
    sleeper_mass: float
    sleeper_spacing: float
    wheel_spacing: float
    wagon_length: float
    pad_stiffness: float
    pad_damping: float

    def __post_init__(self) -> None:
        require_positive("rail_linear_mass", self.rail_linear_mass, "kg/m")
        require_positive("rail_bending_stiffness", self.rail_bending_stiffness, "N m^2")
        require_positive("speed", self.speed, "m/s")
        require_positive("wheel_load", self.wheel_load, "N")
        require_positive("sleeper_mass", self.sleeper_mass, "kg")
        require_positive("sleeper_spacing", self.sleeper_spacing, "m")
        require_positive("wheel_spacing", self.wheel_spacing, "m")
        require_positive("wagon_length", self.wagon_length, "m")
        require_positive("pad_stiffness", self.pad_stiffness, "N/m")
        require_non_negative("pad_damping", self.pad_damping, "N s/m")
        if not np.all(np.asarray(self.wheel_spacing) < np.asarray(self.wagon_length)):
            raise ValueError(
                "wheel_spacing must be smaller than wagon_length (0 < D < H); got "
                f"D={self.wheel_spacing!r}, H={self.wagon_length!r}"
            )
        as_float64(self)

    @classmethod
    def paper(cls, **changes: float) -> "Track":
        """The UIC60 track and train of Table 1, optionally with some fields changed.

        >>> Track.paper(speed=30.0).speed
        30.0
        """
        values = dict(
            rail_linear_mass=60.0,
            rail_bending_stiffness=6.3e6,
            speed=45.0,
            wheel_load=75e3,
            sleeper_mass=100.0,
            sleeper_spacing=0.6,
            wheel_spacing=3.0,
            wagon_length=18.0,
            pad_stiffness=220e6,
            pad_damping=1.0e6,
        )
        values.update(changes)
        return cls(**values)

    def replace(self, **changes: float) -> "Track":
        """Return a copy with some fields changed (validated again)."""
        return dataclasses.replace(self, **changes)

    @property
    def period(self) -> float:
        """Period T = H / v of the load seen by one sleeper, eq. (13) [s]."""
        return self.wagon_length / self.speed

    @property
    def fundamental_frequency(self) -> float:
        """Angular frequency 2 pi v / H of the first harmonic, eq. (11) [rad/s]."""
        return 2.0 * np.pi * self.speed / self.wagon_length

    @property
    def static_load_per_sleeper(self) -> float:
        """Mean force 2 Q L / H that the train puts on each sleeper [N]."""
        return 2.0 * self.wheel_load * self.sleeper_spacing / self.wagon_length

    @property
    def pad_natural_frequency_squared(self) -> float:
        """omega_0^2 = k1 / M of eq. (8) [rad^2/s^2]."""
        return self.pad_stiffness / self.sleeper_mass

    @property
    def pad_damping_rate(self) -> float:
        """beta = eta1 / M of eq. (8) [1/s]."""
        return self.pad_damping / self.sleeper_mass

    def harmonic_frequencies(self, harmonics: int) -> np.ndarray:
        """omega_n = 2 pi n v / H for n = -m..m, eq. (11) [rad/s].

        With array-valued fields (shape ``(..., 1)``) the harmonic axis is the
        last one.
        """
        n = np.arange(-harmonics, harmonics + 1)
        return np.asarray(self.fundamental_frequency) * n
