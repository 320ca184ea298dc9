"""The parameter a branch follows: which field it is, its value, where the branch turns.

`replaced` sets the named scalar field of the Track, the Train or the
foundation law; `check_parameter` and `scalar` check the name and a value
with messages that name them; `hermite_turning_value` places a fold
between two points of a branch.  `railtrack.studies.continuation` traces
the branch with them, `railtrack.studies.branch.Branch` rebuilds its points
(both import them from `branch`, which re-exports them).
"""

from __future__ import annotations

import dataclasses
from dataclasses import replace
from typing import Any

import numpy as np

from ..model.track import Track
from ..model.train import Train

__all__ = ["TRACK_FIELDS", "TRAIN_FIELDS", "replaced", "check_parameter", "scalar",
           "hermite_turning_value"]

TRACK_FIELDS = ("rail_linear_mass", "rail_bending_stiffness", "sleeper_mass",
                "sleeper_spacing", "pad_stiffness", "pad_damping")
TRAIN_FIELDS = ("wagon_length", "speed")
"""The scalar fields of `Train`; axle_positions and axle_loads are tuples."""


def replaced(track: Track, train: Train, foundation: Any, parameter: str,
             value: float) -> tuple[Track, Train, Any]:
    """(track, train, foundation) with the field named `parameter` set to `value`.

    The owner of the field is found by name: the track, then the train,
    then the foundation (a frozen dataclass, changed with
    `dataclasses.replace`, which validates it again).
    """
    if parameter in TRACK_FIELDS:
        return track.replace(**{parameter: value}), train, foundation
    if parameter in TRAIN_FIELDS:
        return track, train.replace(**{parameter: value}), foundation
    return track, train, replace(foundation, **{parameter: value})


def check_parameter(track, train, foundation, parameter) -> None:
    """Raise a ValueError naming `parameter` unless it is a scalar field of the problem."""
    names = list(TRACK_FIELDS) + list(TRAIN_FIELDS)
    if dataclasses.is_dataclass(foundation):
        names += [f.name for f in dataclasses.fields(foundation)
                  if isinstance(getattr(foundation, f.name), (int, float, np.floating))]
    if parameter not in names:
        raise ValueError(f"parameter {parameter!r} is not a scalar field of the Track, the Train "
                         f"or the foundation; choose one of {names}")


def scalar(name: str, parameter: str, value) -> float:
    """`value` as a float, or a ValueError naming `name` and `parameter`."""
    if isinstance(value, bool) or np.ndim(value) != 0 or np.asarray(value).dtype.kind not in "iuf":
        raise ValueError(f"{name} (the value of {parameter!r}) must be a real scalar; got {value!r}")
    if not np.isfinite(value):
        raise ValueError(f"{name} (the value of {parameter!r}) must be finite; got {value!r}")
    return float(value)


def hermite_turning_value(p0, p1, d0, d1, length):
    """Turning value of the cubic Hermite p(s) = p0 + d0 s + a s^2 + b s^3 on [0, length]."""
    a = 3 * (p1 - p0) / length ** 2 - (2 * d0 + d1) / length
    b = (d0 + d1) / length ** 2 - 2 * (p1 - p0) / length ** 3
    roots = np.roots([3 * b, 2 * a, d0])
    roots = roots[np.isreal(roots)].real
    inside = roots[(roots >= 0) & (roots <= length)]
    s = inside[0] if len(inside) else length * d0 / (d0 - d1)
    return p0 + s * (d0 + s * (a + s * b))
