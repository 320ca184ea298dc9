"""Many nonlinear solves at once: `sweep` over any field of the track, the train or the law.

``sweep(track, train, foundation, speed=values)`` replaces one field (or
several, of equal length) by an array, builds one batched harmonic system
and solves it with `railtrack.solvers.batch.newton_batch`.  The result, `Sweep`,
keeps every member, converged or not, and gives the extremes over a period
of the sleeper displacement, the rail-seat load and the foundation force.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..solvers.arguments import require_count, require_fraction
from ..solvers.batch import member, newton_batch
from ..model.foundations import CubicFoundation, LinearFoundation, as_foundation
from ..equations.harmonic_balance import harmonic_system, require_jacobian_samples, two_sided
from ..model.passage import Passage
from ..equations.rail_field import seat_load_coefficients
from ..solvers.solution import Solution
from ..model.track import Track
from ..model.train import Train

__all__ = ["Sweep", "sweep"]

GRID = 256
"""Samples per period at which the extremes are read, each refined by a parabola."""


def _polynomial_samples(law, harmonics: int) -> int | None:
    """N for a law whose AFT is exact once N > 4m (linear, cubic): the smallest power of two."""
    if isinstance(law, (LinearFoundation, CubicFoundation)):
        return max(16, 1 << int(np.floor(np.log2(4 * harmonics)) + 1))
    return None


def _peak(values: np.ndarray, sign: float) -> np.ndarray:
    """sign * the max over the last (periodic) axis of sign * values, refined by a parabola."""
    scaled = sign * values
    i = np.argmax(scaled, axis=-1)[..., None]
    n = values.shape[-1]
    left, middle, right = (np.take_along_axis(scaled, (i + k) % n, axis=-1)[..., 0] for k in (-1, 0, 1))
    curvature = left - 2.0 * middle + right
    with np.errstate(divide="ignore", invalid="ignore"):
        offset = np.where(curvature < 0, 0.5 * (left - right) / curvature, 0.0)
    return sign * (middle - 0.25 * (left - right) * offset)


@dataclass(frozen=True, eq=False)
class Sweep:
    """The members of a `sweep`, in the order of the swept values.

    Attributes
    ----------
    values : dict of str to ndarray, shape (B,)
        The swept field(s) [SI units of the field].
    harmonics : int
        m, the same for every member.
    coefficients : ndarray, shape (B, 2m+1)
        Two-sided c_n, n = -m..m, of each member [m].
    converged : ndarray of bool, shape (B,)
    iterations : ndarray of int, shape (B,)
    residual : ndarray, shape (B,)
        Final relative residual of eq. (17) (inf where the law was not finite).
    lowest, highest : ndarray, shape (B,)
        Extremes of the sleeper displacement over a period [m] (w < 0 is down).
    seat_load_peak, seat_load_lowest : ndarray, shape (B,)
        Extremes of the rail-seat load, compression positive [N].
    foundation_force_peak, foundation_force_lowest : ndarray, shape (B,)
        Extremes of the force on the foundation, compression positive [N].
    passage, foundation
        The batched passage and law (fields of shape (B, 1) where swept).
    """

    values: dict
    harmonics: int
    coefficients: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    residual: np.ndarray
    lowest: np.ndarray
    highest: np.ndarray
    seat_load_peak: np.ndarray
    seat_load_lowest: np.ndarray
    foundation_force_peak: np.ndarray
    foundation_force_lowest: np.ndarray
    passage: Passage
    foundation: Any

    def __len__(self) -> int:
        return len(self.converged)

    def solution(self, index: int) -> Solution:
        """Member `index` as a `railtrack.Solution` (for its rail, moments, bowl ...)."""
        passage = Passage(member(self.passage.track, index), member(self.passage.train, index))
        state = "converged" if self.converged[index] else "did not converge"
        return Solution(
            passage=passage, foundation=member(self.foundation, index), harmonics=self.harmonics,
            coefficients=self.coefficients[index], method="newton (batch)",
            converged=bool(self.converged[index]), iterations=int(self.iterations[index]),
            residual_history=np.array([self.residual[index]]),
            message=f"member {index} of a sweep: {state}, relative residual "
                    f"{self.residual[index]:.2e} after {self.iterations[index]} Newton steps")


def _split(track: Track, train: Train, foundation, values: dict) -> tuple[dict, dict, dict, int]:
    """Sort the swept fields into track, train and law, as (B, 1) arrays; B."""
    owners = {"track": {f.name for f in dataclasses.fields(track)},
              "train": {f.name for f in dataclasses.fields(train)} - {"axle_positions", "axle_loads"},
              "foundation": {f.name for f in dataclasses.fields(foundation)}}
    if not values:
        raise TypeError("sweep needs at least one field to sweep, e.g. speed=np.linspace(10, 100, 50)")
    parts: dict[str, dict] = {"track": {}, "train": {}, "foundation": {}}
    size = None
    for name, value in values.items():
        owner = next((o for o, names in owners.items() if name in names), None)
        if owner is None:
            known = sorted(set().union(*owners.values()))
            raise TypeError(f"cannot sweep {name!r}: not a scalar field of the track, the train "
                            f"or {type(foundation).__name__} ({', '.join(known)})")
        array = np.asarray(value, dtype=float)
        if array.ndim != 1 or array.size == 0:
            raise ValueError(f"{name} must be a 1-D array of values to sweep; got shape {array.shape}")
        if size is not None and array.size != size:
            raise ValueError(f"the swept fields must have equal lengths; {name} has {array.size}, "
                             f"the first had {size}")
        size = array.size
        parts[owner][name] = array[:, None]
    return parts["track"], parts["train"], parts["foundation"], size


def sweep(track: Track, train: Train, foundation, harmonics: int = 15, *, tol: float = 1e-10,
          max_iterations: int = 100, samples: int | None = None, **values) -> Sweep:
    """Solve eq. (17) for every value of the swept field(s), all at once.

    Parameters
    ----------
    track, train : Track, Train
    foundation : LinearFoundation, BilinearFoundation or CubicFoundation
        A dataclass law, so that its fields can be swept and evaluated for
        the whole batch at once.
    harmonics : int
        m for every member (default 15, the paper's).  Check with
        ``solve(..., harmonics="auto")`` at the most demanding member that
        it is enough: the sweep does not estimate its truncation error.
    tol, max_iterations, samples
        As for `railtrack.solve` with ``method="newton"``.
    **values : array_like, shape (B,)
        The field(s) to sweep by name, e.g. ``speed=...``, ``pad_damping=...``,
        ``stiffness=...``, ``epsilon=...``; several fields sweep together.

    Returns
    -------
    Sweep

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack import Track, Train, CubicFoundation
    >>> result = sweep(Track.paper(), Train.paper(), CubicFoundation.paper(), speed=[30.0, 45.0])
    >>> bool(result.converged.all()), np.round(result.lowest * 1e3, 3).tolist()
    (True, [-0.854, -0.853])
    """
    if not dataclasses.is_dataclass(foundation):
        raise TypeError(f"sweep takes a dataclass foundation law (Linear, Bilinear, Cubic); "
                        f"got {type(foundation).__name__}")
    harmonics = require_count("harmonics", harmonics, 1)
    max_iterations = require_count("max_iterations", max_iterations, 0)
    tol = require_fraction("tol", tol)
    track_changes, train_changes, law_changes, size = _split(track, train, foundation, values)
    passage = Passage(track.replace(**track_changes), train.replace(**train_changes))
    law = as_foundation(dataclasses.replace(foundation, **law_changes))
    if samples is not None:
        require_jacobian_samples(samples, harmonics)
    else:
        # exact for these laws, and a quarter of solve's default work per member
        samples = _polynomial_samples(law, harmonics)
    system = harmonic_system(passage, law, harmonics, samples)
    outcome = newton_batch(system, size, max_iterations, tol)
    extremes = _extremes(system, outcome.coefficients, size)
    return Sweep(
        values={k: np.asarray(v, dtype=float) for k, v in values.items()}, harmonics=harmonics,
        coefficients=two_sided(outcome.coefficients), converged=outcome.converged,
        iterations=outcome.iterations, residual=outcome.residual, passage=passage,
        foundation=law, **extremes)


def _extremes(system, coefficients: np.ndarray, size: int) -> dict:
    """Extremes over a period of w, the rail-seat load and the foundation force."""
    m = system.harmonics
    # omega is (m+1,) unless the passage is swept: seat_load_coefficients is
    # elementwise, so it evaluates the rail's factors once per harmonic, not
    # once per member and harmonic, and broadcasts them over the batch.
    omega = system.omega
    spectrum = np.zeros((3, size, GRID // 2 + 1), dtype=complex)
    spectrum[0, :, : m + 1] = coefficients * GRID
    spectrum[1, :, : m + 1] = 1j * omega * coefficients * GRID
    spectrum[2, :, : m + 1] = seat_load_coefficients(system.passage, omega, coefficients) * GRID
    w, rate, seat = np.fft.irfft(spectrum, GRID, axis=-1)
    with np.errstate(invalid="ignore", over="ignore"):
        force = -np.broadcast_to(np.asarray(system.foundation.force(w, rate), dtype=float), w.shape)
    return dict(lowest=_peak(w, -1.0), highest=_peak(w, 1.0), seat_load_peak=_peak(seat, 1.0),
                seat_load_lowest=_peak(seat, -1.0), foundation_force_peak=_peak(force, 1.0),
                foundation_force_lowest=_peak(force, -1.0))
