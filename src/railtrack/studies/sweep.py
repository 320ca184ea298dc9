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
and the sweep is solved again, from the previous solutions; a member still
short of the accuracy where "auto" stops is a failure (``converged=False``,
as in `railtrack.solve`).  An explicit m is kept, and warns
(`railtrack.TruncationWarning`) if a member's estimate exceeds 1 %.

**Size.**  The members are solved in blocks of `BLOCK`, so that the working
memory does not grow with the sweep; the results themselves (2m + 1 complex
coefficients a member) are estimated before anything is allocated, and a
sweep whose results would exceed `MAX_RESULT_BYTES` is refused with the
largest size that fits (`railtrack.studies.sweep_members`; the extremes are
read by `railtrack.studies.period_extremes`).
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np

from ..equations.harmonic_balance import harmonic_system, require_jacobian_samples
from ..model.foundations import as_foundation
from ..model.passage import Passage
from ..model.track import Track
from ..model.train import Train
from ..solvers.arguments import require_count, require_fraction
from ..solvers.batch import batch_truncation, member
from ..solvers.chunk_map import chunk_bounds, map_chunks, show_progress
from ..solvers.solve import AUTO_ROUNDS, DEFAULT_ACCURACY
from ..solvers.truncation import MAX_AUTO_HARMONICS, auto_samples, grown_harmonics
from .sweep_members import (BLOCK, MAX_RESULT_BYTES, check_members_conditioning, warn_members,
                            polynomial_samples, predicted_harmonics, require_fits, rows,
                            solve_block, split_fields)
from .sweep_stability import member_stability, require_whole_sleepers, stability_mode
from .sweep_result import Sweep

__all__ = ["Sweep", "sweep", "BLOCK", "MAX_RESULT_BYTES"]     # Sweep lives in sweep_result

PROGRESS_MEMBERS = 50_000
"""A sweep of this many members or more shows its progress unless told otherwise."""


def sweep(track: Track, train: Train, foundation, harmonics: int | str = "auto", *,
          accuracy: float | None = None, tol: float = 1e-10, max_iterations: int = 100,
          samples: int | None = None, stability: str | bool = "quick", progress=None,
          executor=None, **values) -> Sweep:
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
        `accuracy` (module docstring); a member still above it where "auto"
        stops is returned with ``converged=False``.  An explicit m (the paper's is 15)
        warns with a `railtrack.TruncationWarning` if a member's estimate
        exceeds 1 %.
    accuracy : float, optional
        For ``harmonics="auto"``, as for `railtrack.solve` (default 1e-3).
    tol, max_iterations, samples
        As for `railtrack.solve` with ``method="newton"``; samples needs an
        explicit m.
    stability : {"quick", "full", "off"} or bool
        Judge every converged member as `railtrack.solve` does
        (`Sweep.stable`, `Sweep.dominant_multiplier`; one
        `railtrack.UnstableSolutionWarning` for all unstable members).
        "quick" (default): finds unstable members, proves none stable.
        "full" (or True): `railtrack.floquet` at the sweep's m,
        wagon-periodic disturbances; needs H / L an integer for every
        member.  "off" (or False): nothing.  Either look runs per member, in
        a loop, and costs far more than the batched solve: on a shared
        2-core machine "quick" takes about 9 ms a member of a nonlinear law
        at m = 15 and 35 ms at m = 30; at m = 25 "full" about 70 ms a member on the fold
        track of chapter 10 (480-545 m/s) and 280 ms on the paper's track
        (30-100 m/s), against 0.5-5 ms a member for the sweep itself.
    progress : bool or None
        A ``tqdm`` bar over the blocks of `BLOCK` members: None shows it
        from `PROGRESS_MEMBERS` members (10,000 solve in about a second),
        True or False force it.
    executor : concurrent.futures.Executor, optional
        Runs the blocks (a ``ProcessPoolExecutor``, a Dask ``Client``);
        default: this process.  The results do not depend on it.
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
        refuses it), results larger than `MAX_RESULT_BYTES`, or
        ``stability="full"`` with a member whose H / L is not an integer.

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack import Track, Train, CubicFoundation
    >>> result = sweep(Track.paper(), Train.paper(), CubicFoundation.paper(), harmonics=15,
    ...                speed=[30.0, 45.0])
    >>> bool(result.converged.all()), np.round(result.lowest * 1e3, 3).tolist()
    (True, [-0.854, -0.853])
    """
    stability = stability_mode(stability)
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
    track_changes, train_changes, law_changes, size = split_fields(track, train, foundation, values)
    passage = Passage(track.replace(**track_changes), train.replace(**train_changes))
    law = as_foundation(dataclasses.replace(foundation, **law_changes))
    if samples is not None:
        require_jacobian_samples(samples, harmonics)
    require_fits(size, 1 if automatic else harmonics)
    check_members_conditioning(passage, size, values)
    if stability == "full":
        require_whole_sleepers(passage, size, values)
    m = harmonics if not automatic else predicted_harmonics(passage, law, size, accuracy)
    run = dict(passage=passage, law=law, size=size, tol=tol, max_iterations=max_iterations,
               executor=executor, progress=show_progress(progress, size >= PROGRESS_MEMBERS))
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
        grown = min(MAX_AUTO_HARMONICS,
                    max(math.ceil(1.1 * m), grown_harmonics(c, tail, 0.8 * accuracy)))
        start = np.zeros((size, grown + 1), dtype=complex)
        start[:, : m + 1] = result.coefficients[:, m:]
        m = grown
        result = _solve(m, None, start, automatic, **run)
    result = warn_members(result, automatic, accuracy, tuple(values))
    verdicts = {} if stability == "off" else dict(zip(
        ("stable", "dominant_multiplier"), member_stability(result, values, stability)))
    return dataclasses.replace(result, values={k: np.array(v, dtype=float)
                                               for k, v in values.items()}, **verdicts)


def _worst(result: Sweep) -> int | None:
    """Index of the converged member with the largest truncation estimate (None if none)."""
    errors = np.where(result.converged & np.isfinite(result.truncation_error),
                      result.truncation_error, -np.inf)
    return int(np.argmax(errors)) if np.isfinite(errors.max()) else None


def _solve(m, samples, initial, automatic, *, passage, law, size, tol, max_iterations,
           executor=None, progress=False) -> Sweep:
    """Every member at m harmonics, `BLOCK` members at a time (on `executor` if given)."""
    require_fits(size, m)
    if samples is None:
        # exact for these laws, and a quarter of solve's default work per member;
        # a kinked law takes what solve takes: its default, or auto's for 'auto'
        samples = polynomial_samples(law, m) or (auto_samples(m) if automatic else None)
    bounds = chunk_bounds(size, BLOCK)
    arguments = []
    for start, stop in bounds:
        index = np.arange(start, stop)
        arguments.append((rows(passage, index, size), rows(law, index, size), len(index), m,
                          samples, tol, max_iterations,
                          None if initial is None else initial[index]))
    parts = map_chunks(solve_block, arguments, [b - a for a, b in bounds], executor=executor,
                       progress=progress, description=f"sweep, m = {m}")
    joined = [np.concatenate(column) for column in list(zip(*parts))[:5]]
    extremes = {k: np.concatenate([p[5][k] for p in parts]) for k in parts[0][5]}
    return Sweep(values={}, harmonics=m, coefficients=joined[0], converged=joined[1],
                 iterations=joined[2], residual=joined[3], truncation_error=joined[4],
                 passage=passage, foundation=law, **extremes)
