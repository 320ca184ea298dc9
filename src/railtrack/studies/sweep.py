"""Many nonlinear solves at once: `sweep` over any field of the track, the train or the law.

``sweep(track, train, foundation, speed=values)`` replaces one field (or
several, of equal length) by an array, builds one batched harmonic system
and solves it with `railtrack.solvers.batch.newton_batch`.  The result, `Sweep`,
keeps every member, converged or not, and gives the extremes over a period
of the sleeper displacement, the rail-seat load and the foundation force,
and each member's estimated truncation error.

**Harmonics.**  ``harmonics="auto"`` (default) meets the accuracy of
`railtrack.solve`'s "auto" at every member: m is predicted at up to nine
members spread over the sweep, every member's truncation error is then
estimated (`railtrack.solvers.batch.batch_truncation`), and while the worst
converged member misses the accuracy, m grows to what its spectrum needs
and the sweep is solved again, from the previous solutions.  An explicit m
is kept, and warns (`railtrack.TruncationWarning`) if a member's estimate
exceeds 1 %.

**Size.**  The members are solved in blocks of `BLOCK`, so that the working
memory does not grow with the sweep; the results themselves (2m + 1 complex
coefficients a member) are estimated before anything is allocated, and a
sweep whose results would exceed `MAX_RESULT_BYTES` is refused with the
largest size that fits.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..solvers.arguments import require_count, require_fraction
from ..solvers.batch import batch_truncation, member, newton_batch
from ..solvers.conditioning import ROUNDOFF_LIMIT, check_conditioning
from ..model.foundations import CubicFoundation, LinearFoundation, as_foundation
from ..equations.harmonic_balance import harmonic_system, require_jacobian_samples, two_sided
from ..model.passage import Passage
from ..equations.rail_field import seat_load_coefficients
from ..solvers.solution import ConvergenceWarning, Solution, TruncationWarning
from ..solvers.solve import AUTO_ROUNDS, DEFAULT_ACCURACY, WARN_TRUNCATION
from ..solvers.truncation import (MAX_AUTO_HARMONICS, auto_samples, grown_harmonics,
                                  predict_harmonics)
from ..model.track import Track
from ..model.train import Train

__all__ = ["Sweep", "sweep", "BLOCK", "MAX_RESULT_BYTES"]

GRID = 256
"""Fewest samples per period at which the extremes are read, each refined by a parabola;
more for m > 31, so that the highest harmonic has at least 8 samples a period."""
BLOCK = 8192
"""Members solved together: bounds the working memory (the AFT grids and Jacobians)."""
MAX_RESULT_BYTES = 2**30
"""Largest memory the results of one sweep may take (1 GiB)."""


def _grid(harmonics: int) -> int:
    return max(GRID, 1 << int(np.ceil(np.log2(8 * (harmonics + 1)))))


def _result_bytes(size: int, harmonics: int) -> int:
    """Memory of a `Sweep`'s arrays: 2m + 1 complex coefficients and 10 reals a member [B]."""
    return size * ((2 * harmonics + 1) * 16 + 10 * 8)


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
    truncation_error : ndarray, shape (B,)
        Estimated truncation error of each member, as `railtrack.Solution`'s
        (NaN where a member diverged).
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
    truncation_error: np.ndarray
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
            truncation_error=float(self.truncation_error[index]),
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
        raw = np.asarray(value)
        if raw.dtype.kind not in "iuf":
            raise ValueError(f"{name} must be real numbers; got {raw.dtype.name} values "
                             f"({np.ravel(raw)[:3].tolist()}...)" if raw.size else
                             f"{name} must be a 1-D array of values to sweep; got {value!r}")
        array = np.array(raw, dtype=float)            # a copy: the caller's array may change
        if array.ndim != 1 or array.size == 0:
            raise ValueError(f"{name} must be a 1-D array of values to sweep; got shape {array.shape}")
        if size is not None and array.size != size:
            raise ValueError(f"the swept fields must have equal lengths; {name} has {array.size}, "
                             f"the first had {size}")
        size = array.size
        parts[owner][name] = array[:, None]
    return parts["track"], parts["train"], parts["foundation"], size


def sweep(track: Track, train: Train, foundation, harmonics: int | str = "auto", *,
          accuracy: float | None = None, tol: float = 1e-10, max_iterations: int = 100,
          samples: int | None = None, **values) -> Sweep:
    """Solve eq. (17) for every value of the swept field(s), all at once.

    Parameters
    ----------
    track, train : Track, Train
    foundation : LinearFoundation, BilinearFoundation or CubicFoundation
        A dataclass law, so that its fields can be swept and evaluated for
        the whole batch at once.
    harmonics : int or "auto"
        m, the same for every member.  "auto" (default): the smallest m for
        which every converged member's estimated truncation error is below
        `accuracy` (module docstring).  An explicit m (the paper's is 15)
        warns with a `railtrack.TruncationWarning` if a member's estimate
        exceeds 1 %.
    accuracy : float, optional
        For ``harmonics="auto"``, as for `railtrack.solve` (default 1e-3).
    tol, max_iterations, samples
        As for `railtrack.solve` with ``method="newton"``; samples needs an
        explicit m.
    **values : array_like of real numbers, shape (B,)
        The field(s) to sweep by name, e.g. ``speed=...``, ``pad_damping=...``,
        ``stiffness=...``, ``epsilon=...``; several fields sweep together.
        They are copied.

    Returns
    -------
    Sweep
        Members that did not converge are kept, and warn
        (`railtrack.ConvergenceWarning`).

    Raises
    ------
    ValueError
        Bad values (not real, not 1-D, unequal lengths, out of a field's
        range), a member for which eq. (3) loses accuracy (as `railtrack.solve`
        refuses it), or results larger than `MAX_RESULT_BYTES`.

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack import Track, Train, CubicFoundation
    >>> result = sweep(Track.paper(), Train.paper(), CubicFoundation.paper(), harmonics=15,
    ...                speed=[30.0, 45.0])
    >>> bool(result.converged.all()), np.round(result.lowest * 1e3, 3).tolist()
    (True, [-0.854, -0.853])
    """
    if not dataclasses.is_dataclass(foundation):
        raise TypeError(f"sweep takes a dataclass foundation law (Linear, Bilinear, Cubic); "
                        f"got {type(foundation).__name__}")
    automatic = isinstance(harmonics, str) and harmonics == "auto"
    if not automatic:
        harmonics = require_count("harmonics", harmonics, 1)
    elif samples is not None:
        raise ValueError("samples needs an explicit harmonics=m; 'auto' chooses m itself")
    if accuracy is not None and not automatic:
        warnings.warn("accuracy is used by harmonics='auto' only; ignored for an explicit m")
    accuracy = DEFAULT_ACCURACY if accuracy is None else require_fraction("accuracy", accuracy)
    max_iterations = require_count("max_iterations", max_iterations, 0)
    tol = require_fraction("tol", tol)
    track_changes, train_changes, law_changes, size = _split(track, train, foundation, values)
    passage = Passage(track.replace(**track_changes), train.replace(**train_changes))
    law = as_foundation(dataclasses.replace(foundation, **law_changes))
    if samples is not None:
        require_jacobian_samples(samples, harmonics)
    _require_fits(size, 1 if automatic else harmonics)
    _check_conditioning(passage, size, values)
    m = harmonics if not automatic else _predicted(passage, law, size, accuracy)
    run = dict(passage=passage, law=law, size=size, tol=tol, max_iterations=max_iterations)
    result = _solve(m, samples, None, automatic, **run)
    for _round in range(AUTO_ROUNDS if automatic else 0):
        worst = _worst(result)
        if worst is None or result.truncation_error[worst] <= accuracy or m >= MAX_AUTO_HARMONICS:
            break
        member_system = harmonic_system(Passage(member(passage.track, worst),
                                                member(passage.train, worst)),
                                        member(law, worst), m)
        c = result.coefficients[worst, m:]
        tail = batch_truncation(member_system, c[None, :], 1)[1][0]
        grown = min(MAX_AUTO_HARMONICS, max(math.ceil(1.1 * m), grown_harmonics(c, tail, 0.8 * accuracy)))
        start = np.zeros((size, grown + 1), dtype=complex)
        start[:, : m + 1] = result.coefficients[:, m:]
        m = grown
        result = _solve(m, None, start, automatic, **run)
    _warn(result, automatic, accuracy, tuple(values))
    return dataclasses.replace(result, values={k: np.array(v, dtype=float) for k, v in values.items()})


def _require_fits(size: int, m: int) -> None:
    """Refuse, before allocating them, results larger than `MAX_RESULT_BYTES`."""
    needed = _result_bytes(size, m)
    if needed > MAX_RESULT_BYTES:
        fits = MAX_RESULT_BYTES // _result_bytes(1, m)
        raise ValueError(f"a sweep of {size} members at m = {m} harmonics would hold "
                         f"{needed / 2**30:.2f} GiB of results (limit {MAX_RESULT_BYTES / 2**30:g} "
                         f"GiB); sweep the values in parts of at most {fits} members")


def _check_conditioning(passage: Passage, size: int, values: dict) -> None:
    """`railtrack.solvers.conditioning.check_conditioning` for every member, as `solve` does."""
    omega_1 = 2.0 * np.pi * passage.speed / passage.wagon_length
    ratio = np.sqrt(passage.rail_bending_stiffness / passage.rail_linear_mass) / passage.speed**2
    estimate = np.broadcast_to(np.finfo(float).eps * omega_1 * ratio, (size, 1))[:, 0]
    bad = np.flatnonzero(~(estimate <= ROUNDOFF_LIMIT))
    if len(bad):
        i = int(bad[0])
        named = ", ".join(f"{k} = {float(np.ravel(v)[i])!r}" for k, v in values.items())
        try:
            check_conditioning(Passage(member(passage.track, i), member(passage.train, i)))
        except ValueError as error:
            others = f", and {len(bad) - 1} other(s)," if len(bad) > 1 else ""
            raise ValueError(f"member {i} ({named}) of the sweep{others}: {error}") from None


def _predicted(passage: Passage, law, size: int, accuracy: float) -> int:
    """The largest m that `railtrack.solve` predicts at up to nine members spread over the sweep."""
    picks = np.unique(np.linspace(0, size - 1, min(size, 9)).round().astype(int))
    return max(predict_harmonics(Passage(member(passage.track, i), member(passage.train, i)),
                                 member(law, i), accuracy / 2)[0] for i in picks)


def _worst(result: Sweep) -> int | None:
    """Index of the converged member with the largest truncation estimate (None if none)."""
    errors = np.where(result.converged & np.isfinite(result.truncation_error),
                      result.truncation_error, -np.inf)
    return int(np.argmax(errors)) if np.isfinite(errors.max()) else None


def _solve(m, samples, initial, automatic, *, passage, law, size, tol, max_iterations) -> Sweep:
    """Every member at m harmonics, `BLOCK` members at a time."""
    _require_fits(size, m)
    if samples is None:
        # exact for these laws, and a quarter of solve's default work per member;
        # a kinked law takes what solve takes: its default, or auto's for 'auto'
        samples = _polynomial_samples(law, m) or (auto_samples(m) if automatic else None)
    parts = []
    for start in range(0, size, BLOCK):
        index = np.arange(start, min(start + BLOCK, size))
        block_passage = _rows(passage, index, size)
        block_law = _rows(law, index, size)
        system = harmonic_system(block_passage, block_law, m, samples)
        outcome = newton_batch(system, len(index), max_iterations, tol,
                               None if initial is None else initial[index])
        errors = batch_truncation(system, outcome.coefficients, len(index))[0]
        parts.append((two_sided(outcome.coefficients), outcome.converged, outcome.iterations,
                      outcome.residual, errors, _extremes(system, outcome.coefficients, len(index))))
    joined = [np.concatenate(column) for column in list(zip(*parts))[:5]]
    extremes = {k: np.concatenate([p[5][k] for p in parts]) for k in parts[0][5]}
    return Sweep(values={}, harmonics=m, coefficients=joined[0], converged=joined[1],
                 iterations=joined[2], residual=joined[3], truncation_error=joined[4],
                 passage=passage, foundation=law, **extremes)


def _rows(value, index: np.ndarray, size: int):
    """A batched dataclass (or Passage) restricted to the members `index`."""
    if isinstance(value, Passage):
        return Passage(_rows(value.track, index, size), _rows(value.train, index, size))
    if len(index) == size:
        return value
    changes = {f.name: getattr(value, f.name)[index] for f in dataclasses.fields(value)
               if isinstance(getattr(value, f.name), np.ndarray)
               and getattr(value, f.name).ndim == 2 and getattr(value, f.name).shape[0] == size}
    return dataclasses.replace(value, **changes) if changes else value


def _warn(result: Sweep, automatic: bool, accuracy: float, swept: tuple) -> None:
    """The sweep's warnings: unconverged members, and truncation above the limit."""
    failed = int((~result.converged).sum())
    if failed:
        first = int(np.flatnonzero(~result.converged)[0])
        hint = (" Newton stalls near folds of the response in speed: rt.continuation follows "
                "such a branch through them." if "speed" in swept else "")
        warnings.warn(ConvergenceWarning(
            f"{failed} of {len(result)} members of the sweep did not converge (the first is "
            f"member {first}); their coefficients are not solutions (Sweep.converged).{hint}"),
            stacklevel=3)
    errors = np.where(result.converged, result.truncation_error, np.nan)
    limit = accuracy if automatic else WARN_TRUNCATION
    if np.any(errors > limit):
        worst = int(np.nanargmax(errors))
        advice = ("'auto' stopped growing m; pass a larger harmonics" if automatic
                  else "pass a larger harmonics or use 'auto'")
        warnings.warn(TruncationWarning(
            f"harmonics={result.harmonics}: {int(np.sum(errors > limit))} member(s) of the sweep "
            f"have an estimated truncation error above {limit:.0%}, up to {errors[worst]:.1%} "
            f"at member {worst} ({advice})"), stacklevel=3)


def _extremes(system, coefficients: np.ndarray, size: int) -> dict:
    """Extremes over a period of w, the rail-seat load and the foundation force."""
    m = system.harmonics
    grid = _grid(m)
    # omega is (m+1,) unless the passage is swept: seat_load_coefficients is
    # elementwise, so it evaluates the rail's factors once per harmonic, not
    # once per member and harmonic, and broadcasts them over the batch.
    omega = system.omega
    spectrum = np.zeros((3, size, grid // 2 + 1), dtype=complex)
    spectrum[0, :, : m + 1] = coefficients * grid
    spectrum[1, :, : m + 1] = 1j * omega * coefficients * grid
    spectrum[2, :, : m + 1] = seat_load_coefficients(system.passage, omega, coefficients) * grid
    w, rate, seat = np.fft.irfft(spectrum, grid, axis=-1)
    with np.errstate(invalid="ignore", over="ignore"):
        force = -np.broadcast_to(np.asarray(system.foundation.force(w, rate), dtype=float), w.shape)
    return dict(lowest=_peak(w, -1.0), highest=_peak(w, 1.0), seat_load_peak=_peak(seat, 1.0),
                seat_load_lowest=_peak(seat, -1.0), foundation_force_peak=_peak(force, 1.0),
                foundation_force_lowest=_peak(force, -1.0))
