"""`check_branch(branch, method="time-domain")`: the ring on a sample of the branch's points.

At a fold one multiplier passes +1, so stability changes there as a rule,
and the sample is split at the folds (`segments`): every segment between
folds is checked by `railtrack.check_stability` at a few points (and at
the branch's two ends), and wherever two neighbouring checks of one segment
disagree the point between them is checked too, until the change is
located to one step of the branch.  `railtrack.studies.branch_stability`
holds the entry point and Hill's method, the default.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..solvers.progress import progress_bar, show_progress
from .branch import Branch
from .stability import check_stability

__all__ = ["segments", "ring_branch", "PROGRESS_RUNS"]

PROGRESS_RUNS = 10
"""Ring runs in the first sample from which ``method="time-domain"`` shows its progress."""


def segments(branch: Branch) -> list[range]:
    """Index ranges of the branch between its folds, in order.

    Fold ``k`` lies between points ``index`` and ``index + 1``, so a branch
    with F folds has F + 1 segments.

    >>> import numpy as np
    >>> from railtrack.studies.branch import Fold
    >>> class Fake:
    ...     values, folds = np.arange(10.0), (Fold(3.5, 3), Fold(6.5, 6))
    >>> [list(s) for s in segments(Fake())]
    [[0, 1, 2, 3], [4, 5, 6], [7, 8, 9]]
    """
    cuts = [0] + [fold.index + 1 for fold in branch.folds] + [len(branch.values)]
    return [range(a, b) for a, b in zip(cuts[:-1], cuts[1:]) if b > a]


def _sample(segment: range, per_segment: int) -> list[int]:
    """`per_segment` indices spread over the segment, away from its ends (near a fold the
    deciding multiplier is close to 1 and the ring needs many periods to tell)."""
    n = len(segment)
    picks = {segment[int(round((q + 1) * (n - 1) / (per_segment + 1)))] for q in range(per_segment)}
    return sorted(picks)


def ring_branch(branch: Branch, per_segment, locate: bool, confirm, max_checks, progress,
                options: dict) -> Branch:
    """`check_branch`'s time-domain method: its arguments, as `check_branch` documents them."""
    per_segment = 2 if per_segment is None else per_segment
    max_checks = 40 if max_checks is None else max_checks
    if isinstance(per_segment, bool) or not isinstance(per_segment, (int, np.integer)) \
            or per_segment < 1:
        raise ValueError(f"per_segment must be an integer >= 1; got {per_segment!r}")
    whole = not isinstance(confirm, bool) and isinstance(confirm, (int, np.integer))
    if confirm is not None and not (whole and confirm >= 2):
        raise ValueError(f"confirm must be None or an integer >= 2 (periods); got {confirm!r}")
    parts = segments(branch)
    needed = len(parts) * per_segment + 2
    if needed > max_checks:
        raise ValueError(f"{len(parts)} segments x per_segment = {per_segment} and the two ends "
                         f"need {needed} runs, more than max_checks = {max_checks}")
    checks: dict = {}
    confirmed: set = set()
    shown = show_progress(progress, needed >= PROGRESS_RUNS)

    def run(i: int, **override) -> None:
        if len(checks) + len(confirmed) >= max_checks:
            raise ValueError(f"the sample needs more than max_checks = {max_checks} runs")
        checks[i] = check_stability(branch.solution(i), **{**options, **override})
        bar.to(len(checks) + len(confirmed), f"point {i}: {checks[i].verdict}")

    stable = np.zeros(len(branch), dtype=bool)
    with progress_bar(shown, None, "check_branch, the ring", "runs") as bar:
        for k, segment in enumerate(parts):
            # the branch's own two ends are no folds: check them too
            ends = ([segment[0]] if k == 0 else []) + ([segment[-1]] if k == len(parts) - 1 else [])
            for i in sorted(set(_sample(segment, per_segment) + ends)):
                run(i)
            while locate:
                known = sorted(i for i in checks if i in segment)
                changes = [(a, b) for a, b in zip(known[:-1], known[1:])
                           if checks[a].stable != checks[b].stable]
                wide = [(a, b) for a, b in changes if b - a > 1]
                doubtful = {i for pair in changes for i in pair
                            if checks[i].stable and i not in confirmed} if confirm else set()
                if not wide and not doubtful:
                    break
                for a, b in wide:
                    run((a + b) // 2)
                for i in sorted(doubtful) if not wide else ():
                    confirmed.add(i)
                    run(i, periods=confirm, max_periods=max(confirm, options.get("max_periods", 0)))
            known = np.array(sorted(i for i in checks if i in segment))
            for i in segment:
                stable[i] = checks[int(known[np.argmin(np.abs(known - i))])].stable
    return dataclasses.replace(branch, stable=stable.astype(object),
                               checks=dict(sorted(checks.items())))
