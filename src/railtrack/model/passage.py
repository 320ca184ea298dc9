"""A train passing over a track: the pair that every equation of the paper needs.

The receptance of eq. (3) depends on the speed, the load of eq. (16) on the
axles and the wagon length, the harmonics of eq. (11) on both.  `Passage`
holds a `Track` and a `Train` and reads their fields by name, so that the
functions below `railtrack.solve` take one argument, ``passage``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .track import Track
from .train import Train

__all__ = ["Passage"]

_TRACK_FIELDS = tuple(f.name for f in dataclasses.fields(Track))
_TRAIN_FIELDS = tuple(f.name for f in dataclasses.fields(Train))


@dataclass(frozen=True)
class Passage:
    """`train` running over `track`; fields of either are read as attributes.

    Examples
    --------
    >>> passage = Passage.paper()
    >>> passage.speed, passage.sleeper_spacing
    (45.0, 0.6)
    >>> round(passage.static_load_per_sleeper)      # sum Q_j L / H [N]
    5000
    >>> passage.replace(speed=30.0, pad_damping=0.0).train.speed
    30.0
    """

    track: Track
    train: Train

    def __post_init__(self) -> None:
        if not isinstance(self.track, Track):
            raise TypeError(f"track must be a railtrack.Track; got {type(self.track).__name__}")
        if not isinstance(self.train, Train):
            raise TypeError(f"train must be a railtrack.Train; got {type(self.train).__name__}")

    @classmethod
    def paper(cls, **changes) -> "Passage":
        """The paper's track and wagon (Table 1), with fields of either changed."""
        return cls(Track.paper(), Train.paper()).replace(**changes)

    def replace(self, **changes) -> "Passage":
        """A copy with fields of the track or of the train changed, by name."""
        unknown = set(changes) - set(_TRACK_FIELDS) - set(_TRAIN_FIELDS)
        if unknown:
            raise TypeError(f"no field named {sorted(unknown)} in Track or Train")
        track = {k: v for k, v in changes.items() if k in _TRACK_FIELDS}
        train = {k: v for k, v in changes.items() if k in _TRAIN_FIELDS}
        return Passage(self.track.replace(**track) if track else self.track,
                       self.train.replace(**train) if train else self.train)

    def __getattr__(self, name: str):
        # Only called for names that are not attributes of Passage itself.
        if name in _TRACK_FIELDS or name in ("pad_natural_frequency_squared", "pad_damping_rate"):
            return getattr(self.track, name)
        if name in _TRAIN_FIELDS or name in ("period", "fundamental_frequency",
                                             "harmonic_frequencies", "axle_count", "wagon_load",
                                             "wheel_spacing", "wheel_load"):
            return getattr(self.train, name)
        raise AttributeError(f"'Passage' object has no attribute {name!r}")

    @property
    def static_load_per_sleeper(self) -> float:
        """Mean force sum Q_j L / H that the train puts on each sleeper [N]."""
        return self.train.wagon_load * self.track.sleeper_spacing / self.train.wagon_length

    @property
    def axle_times(self) -> np.ndarray:
        """Times within one period [0, T) at which an axle is above the observed sleeper [s]."""
        return np.asarray(self.train.axle_positions) / self.train.speed
