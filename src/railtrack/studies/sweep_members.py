"""The members of a `railtrack.sweep`: the swept fields sorted, checked, sized and cut into blocks.

`split_fields` sorts the swept values into the track's, the train's and the
law's fields, as (B, 1) arrays; `require_fits` refuses a sweep whose results
would exceed `MAX_RESULT_BYTES` before anything is allocated;
`check_members_conditioning` refuses a member for which eq. (3) loses
accuracy, as `railtrack.solve` does; `rows` cuts the batched passage and law
into blocks of `BLOCK` members, which `solve_block` solves (on any executor:
plain arrays in and out); `polynomial_samples` and `predicted_harmonics`
choose the AFT samples and the first m.
"""

from __future__ import annotations

import dataclasses
import warnings
from typing import TYPE_CHECKING

import numpy as np

from ..model.foundations import CubicFoundation, LinearFoundation
from ..model.passage import Passage
from ..model.track import Track
from ..model.train import Train
from ..equations.harmonic_balance import harmonic_system, two_sided
from ..solvers.batch import batch_truncation, member, newton_batch
from ..solvers.conditioning import ROUNDOFF_LIMIT, check_conditioning
from ..solvers.solution import ConvergenceWarning, TruncationWarning
from ..solvers.solve import WARN_TRUNCATION
from ..solvers.threads import blas_threads
from ..solvers.truncation import predict_harmonics
from .period_extremes import period_extremes

if TYPE_CHECKING:  # sweep_result imports this module
    from .sweep_result import Sweep

__all__ = ["BLOCK", "MAX_RESULT_BYTES", "result_bytes", "require_fits", "split_fields",
           "check_members_conditioning", "predicted_harmonics", "polynomial_samples", "rows",
           "warn_members", "solve_block"]

BLOCK = 8192
"""Members solved together: bounds the working memory (the AFT grids and Jacobians)."""
MAX_RESULT_BYTES = 2**30
"""Largest memory the results of one sweep may take (1 GiB)."""


def result_bytes(size: int, harmonics: int) -> int:
    """Memory of a `Sweep`'s arrays: 2m + 1 complex coefficients and 10 reals a member [B]."""
    return size * ((2 * harmonics + 1) * 16 + 10 * 8)


def require_fits(size: int, m: int) -> None:
    """Refuse, before allocating them, results larger than `MAX_RESULT_BYTES`."""
    needed = result_bytes(size, m)
    if needed > MAX_RESULT_BYTES:
        fits = MAX_RESULT_BYTES // result_bytes(1, m)
        raise ValueError(f"a sweep of {size} members at m = {m} harmonics would hold "
                         f"{needed / 2**30:.2f} GiB of results (limit {MAX_RESULT_BYTES / 2**30:g} "
                         f"GiB); sweep the values in parts of at most {fits} members")


def split_fields(track: Track, train: Train, foundation,
                 values: dict) -> tuple[dict, dict, dict, int]:
    """Sort the swept fields into track, train and law, as (B, 1) arrays; B."""
    owners = {"track": {f.name for f in dataclasses.fields(track)},
              "train": {f.name for f in dataclasses.fields(train)}
              - {"axle_positions", "axle_loads"},
              "foundation": {f.name for f in dataclasses.fields(foundation)}}
    if not values:
        raise TypeError("sweep needs at least one field to sweep, "
                        "e.g. speed=np.linspace(10, 100, 50)")
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
            raise ValueError(f"{name} must be a 1-D array of values to sweep; "
                             f"got shape {array.shape}")
        if size is not None and array.size != size:
            raise ValueError(f"the swept fields must have equal lengths; {name} has {array.size}, "
                             f"the first had {size}")
        size = array.size
        parts[owner][name] = array[:, None]
    return parts["track"], parts["train"], parts["foundation"], size


def check_members_conditioning(passage: Passage, size: int, values: dict) -> None:
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


def predicted_harmonics(passage: Passage, law, size: int, accuracy: float) -> int:
    """The largest m that `railtrack.solve` predicts at up to nine members spread over the sweep."""
    picks = np.unique(np.linspace(0, size - 1, min(size, 9)).round().astype(int))
    return max(predict_harmonics(Passage(member(passage.track, i), member(passage.train, i)),
                                 member(law, i), accuracy / 2)[0] for i in picks)


def polynomial_samples(law, harmonics: int) -> int | None:
    """N for a law whose AFT is exact once N > 4m (linear, cubic): the smallest power of two."""
    if isinstance(law, (LinearFoundation, CubicFoundation)):
        return max(16, 1 << int(np.floor(np.log2(4 * harmonics)) + 1))
    return None


def rows(value, index: np.ndarray, size: int):
    """A batched dataclass (or Passage) restricted to the members `index`."""
    if isinstance(value, Passage):
        return Passage(rows(value.track, index, size), rows(value.train, index, size))
    if len(index) == size:
        return value
    changes = {f.name: getattr(value, f.name)[index] for f in dataclasses.fields(value)
               if isinstance(getattr(value, f.name), np.ndarray)
               and getattr(value, f.name).ndim == 2 and getattr(value, f.name).shape[0] == size}
    return dataclasses.replace(value, **changes) if changes else value


def warn_members(result: Sweep, automatic: bool, accuracy: float, swept: tuple) -> Sweep:
    """The sweep's warnings: unconverged members, and truncation above the limit.

    With harmonics="auto", a member converged at the last m whose estimate
    misses `accuracy` (or has none) is a failure, as in `railtrack.solve`
    (`railtrack.solvers.guards.hold_to_accuracy`): the sweep returned has it
    ``converged=False``, its coefficients and estimate kept, and the one
    `ConvergenceWarning` counts it.
    """
    short = automatic & result.converged & ~(result.truncation_error <= accuracy)
    if short.any():
        result = dataclasses.replace(result, converged=result.converged & ~short)
    failed = int((~result.converged).sum())
    if failed:
        first = int(np.flatnonzero(~result.converged)[0])
        hint = (" Newton stalls near folds of the response in speed: rt.continuation follows "
                "such a branch through them." if "speed" in swept else "")
        fell = (f" {int(short.sum())} of them are solved at m = {result.harmonics}, but "
                f"harmonics='auto' fell short of accuracy = {accuracy:.1e} there (estimates up "
                f"to {np.nanmax(np.where(short, result.truncation_error, np.nan)):.1e}): pass "
                "an explicit larger harmonics or loosen accuracy." if short.any() else "")
        warnings.warn(ConvergenceWarning(
            f"{failed} of {len(result)} members of the sweep did not converge (the first is "
            f"member {first}); their coefficients are not solutions (Sweep.converged).{fell}"
            f"{hint}"), stacklevel=3)
    errors = np.where(result.converged, result.truncation_error, np.nan)
    limit = accuracy if automatic else WARN_TRUNCATION
    if np.any(errors > limit):
        worst = int(np.nanargmax(errors))
        warnings.warn(TruncationWarning(
            f"harmonics={result.harmonics}: {int(np.sum(errors > limit))} member(s) of the sweep "
            f"have an estimated truncation error above {limit:.0%}, up to {errors[worst]:.1%} "
            f"at member {worst} (pass a larger harmonics or use 'auto')"), stacklevel=3)
    return result


def solve_block(passage: Passage, law, size: int, m: int, samples, tol: float,
                max_iterations: int, initial=None) -> tuple:
    """One block of members at m: (c two-sided, converged, iterations, residual, errors, extremes).

    `passage` and `law` are the block's `size` rows (`rows`); `initial` its starting
    coefficients (B, m+1) or None.  A top-level function of arrays, so that an
    executor's worker process can run it; BLAS on one thread (stacks of small
    Jacobians gain nothing from more, `railtrack.solvers.threads`).
    """
    with blas_threads(1):
        system = harmonic_system(passage, law, m, samples)
        outcome = newton_batch(system, size, max_iterations, tol, initial)
        errors = batch_truncation(system, outcome.coefficients, size)[0]
        extremes = period_extremes(system, outcome.coefficients, size)
    return (two_sided(outcome.coefficients), outcome.converged, outcome.iterations,
            outcome.residual, errors, extremes)
