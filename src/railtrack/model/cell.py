"""A repeating cell of N sleepers, each with its own mass, pad and foundation law.

Sleeper j (j = 0..N-1) sits at x = jL; sleeper j + pN is a copy of sleeper j,
so a track whose pattern repeats every N sleepers is one cell.  N = 1 is the
paper's track.  The rail, the spacing L and the train stay in the `Passage`.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from .foundations import as_foundation
from .passage import Passage
from .plausibility_check import FIELDS, check_plausible, quantities_to_si
from .validation import require_non_negative, require_positive, to_si

__all__ = ["SleeperCell", "sleeper_array", "cell_size"]


def sleeper_array(name: str, value, unit: str) -> np.ndarray:
    """`value` as a read-only 1-D float array, one entry per sleeper of a cell.

    Dampings (a `name` containing "damping") may be zero, the rest must be
    positive; every entry finite.  A ValueError names the field otherwise.
    """
    (require_non_negative if "damping" in name else require_positive)(name, value, unit)
    array = np.array(value, dtype=np.float64)
    if array.ndim != 1 or array.size == 0:
        raise ValueError(f"{name} must be a non-empty 1-D sequence, one value per "
                         f"sleeper of the cell; got shape {array.shape}")
    array.setflags(write=False)
    return array


def cell_size(sleepers) -> int:
    """N, the sleepers of a cell, as an int >= 1, or a ValueError."""
    # Whole floats (3.0) pass, as before; NaN, strings and None are named, not int()'s error.
    whole = isinstance(sleepers, (int, np.integer)) or (
        isinstance(sleepers, (float, np.floating)) and float(sleepers).is_integer())
    if isinstance(sleepers, bool) or not whole or sleepers < 1:
        raise ValueError(f"sleepers must be an integer >= 1; got {sleepers!r}")
    return int(sleepers)


@dataclass(frozen=True)
class SleeperCell:
    """The N sleepers of a repeating cell: mass, pad and foundation law of each.

    Parameters
    ----------
    sleeper_mass, pad_stiffness, pad_damping : sequence of float, length N
        M_j > 0 [kg], k1_j > 0 [N/m], eta1_j >= 0 [N s/m].
    foundations : sequence of laws, length N
        Any foundation object of `railtrack.model.foundations` or a callable
        ``f(w, v)`` [N] (w positive upward, f < 0 in compression).
    gravity : float
        g >= 0 [m/s^2].  0 (the default, as the paper) leaves out the weight
        of rail and sleepers: w is then measured from the unloaded track at
        rest, and a law is stressed only by the train.  With g > 0 (e.g.
        `railtrack.model.train.STANDARD_GRAVITY`) the rail (rho S g per metre)
        and each sleeper (M_j g) weigh on the foundations, and w is measured
        from where each sleeper would touch an unloaded, weightless ballast:
        a tensionless or hanging sleeper's law then sees its real preload.

    Examples
    --------
    >>> from railtrack.model.foundations import CubicFoundation, LinearFoundation
    >>> cell = SleeperCell.identical(Passage.paper(), CubicFoundation.paper(), 3)
    >>> cell.with_sleeper(1, foundation=LinearFoundation(10e6)).sleepers
    3
    """

    sleeper_mass: np.ndarray
    pad_stiffness: np.ndarray
    pad_damping: np.ndarray
    foundations: tuple
    gravity: float = 0.0

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_non_negative("gravity", self.gravity, "m/s^2")
        object.__setattr__(self, "gravity", float(self.gravity))
        for name, unit in (("sleeper_mass", "kg"), ("pad_stiffness", "N/m"),
                           ("pad_damping", "N s/m")):
            object.__setattr__(self, name, sleeper_array(name, getattr(self, name), unit))
        if not isinstance(self.foundations, (list, tuple)):
            raise TypeError(f"foundations must be a list or tuple of laws, one per sleeper; "
                            f"got {type(self.foundations).__name__}")
        object.__setattr__(self, "foundations", tuple(as_foundation(f) for f in self.foundations))
        lengths = {f.name: len(getattr(self, f.name)) for f in fields(self)
                   if f.name != "gravity"}
        if len(set(lengths.values())) != 1:
            raise ValueError(f"a SleeperCell needs one value per sleeper in every field; "
                             f"got lengths {lengths}")
        check_plausible(self)

    @property
    def sleepers(self) -> int:
        """N, the number of sleepers in the cell."""
        return int(self.sleeper_mass.size)

    @classmethod
    def identical(cls, passage: Passage, foundation, sleepers: int,
                  gravity: float = 0.0) -> "SleeperCell":
        """N copies of the passage's sleeper and pad on one law."""
        n = cell_size(sleepers)
        return cls(*(np.full(n, float(value)) for value in (
            passage.sleeper_mass, passage.pad_stiffness, passage.pad_damping)),
            (as_foundation(foundation),) * n, gravity)

    def weights(self, passage: Passage) -> tuple[np.ndarray, float]:
        """(M_j g [N] per sleeper, rho S g [N/m] of the rail); zeros without gravity."""
        return self.sleeper_mass * self.gravity, float(passage.rail_linear_mass) * self.gravity

    def with_sleeper(self, index: int, *, foundation=None, **changes: float) -> "SleeperCell":
        """A copy with sleeper `index` changed: its ``foundation`` law and/or mass, pad fields."""
        known = ("sleeper_mass", "pad_stiffness", "pad_damping")
        unknown = set(changes) - set(known)
        if unknown:
            raise TypeError(f"no field named {sorted(unknown)} in SleeperCell; fields: "
                            f"{list(known)} and foundation")
        if isinstance(index, bool) or not -self.sleepers <= int(index) < self.sleepers \
                or int(index) != index:
            raise IndexError(f"sleeper index {index!r} is not in this cell of {self.sleepers} "
                             f"sleepers (0 to {self.sleepers - 1})")
        values = {name: getattr(self, name).copy() for name in known}
        for name, value in changes.items():
            value = to_si(name, value, FIELDS["SleeperCell"][name][0])
            # Checked before it enters the float array, where True would become 1.0.
            (require_non_negative if "damping" in name else require_positive)(name, value)
            values[name][index] = value
        laws = list(self.foundations)
        if foundation is not None:
            laws[index] = as_foundation(foundation)
        return replace(self, foundations=tuple(laws), **values)


