"""Stability along a branch: the ring's verdict on a sample of its points.

`check_stability` judges one periodic solution by starting the time-domain
ring on it, at a cost of tens of periods of the ring.  A branch from
`railtrack.continuation` has hundreds of points, so `check_branch` judges a
sample and carries each verdict to its neighbours.

Why the folds are where the sample is split: at a fold (a saddle-node of
periodic solutions) one Floquet multiplier of the periodic solution passes
through +1, so stability changes there as a rule, and two points on either
side of a fold must not share a verdict.  Between two folds stability can
still change, where a pair of multipliers leaves the unit circle (a
Neimark-Sacker bifurcation, leading to a quasi-periodic response) or one
passes -1 (period doubling, which a one-wagon ring cannot carry); the branch
alone does not show those.  So every segment between folds is sampled at a
few points (and at the branch's two ends, which are no folds), and wherever
two neighbouring samples of one segment disagree, the point between them is
checked too, until the change is located to one step of the branch.  A
point takes the verdict of the nearest checked point of its segment;
`checks` keeps what the ring did at each checked point.

Near a loss of stability without a fold the deciding multiplier is close
to the unit circle, the departure grows by little more than 1 per period,
and a short watch calls a slowly unstable point stable.  ``confirm=n``
watches the stable point next to each located change for n periods, and
goes on searching if it turns out unstable.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .branch import Branch
from .stability import check_stability

__all__ = ["segments", "check_branch"]


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


def check_branch(branch: Branch, per_segment: int = 2, *, locate: bool = True,
                 confirm: int | None = None, max_checks: int = 40, **options) -> Branch:
    """The branch with `stable` filled from the ring's verdicts on a sample of its points.

    Parameters
    ----------
    branch : Branch
        From `railtrack.continuation`, with every point converged.
    per_segment : int
        Points checked inside each segment between folds (>= 1); the first
        and the last point of the branch are checked as well.
    locate : bool
        Where two neighbouring checked points of one segment disagree, bisect
        the points between them until the change is located to one step.
    confirm : int or None
        Periods of a second, longer watch of the stable point next to each
        located change.  Near a loss of stability without a fold the growth
        per period tends to 1, and a short watch calls a slowly unstable
        point stable; if the long watch disagrees, the search goes on.
    max_checks : int
        Most `check_stability` runs in all; a ValueError if the sample needs
        more (before any run, if the first sample does).
    **options
        Passed to `railtrack.check_stability` (periods, tol, elements_per_span,
        steps_per_period, wagons, max_periods, ...).

    Returns
    -------
    Branch
        A copy with ``stable`` (bool, one per point) and ``checks`` (point
        index -> `StabilityCheck`, the longer watch where there was one) set.

    Examples
    --------
    >>> import railtrack as rt
    >>> branch = rt.continuation(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
    ...                          "speed", start=40.0, stop=50.0, harmonics=30)
    >>> marked = check_branch(branch, per_segment=1, periods=3, elements_per_span=2,
    ...                       steps_per_period=600)
    >>> bool(marked.stable.all()), [check.verdict for check in marked.checks.values()]
    (True, ['stays', 'stays', 'stays'])
    """
    if isinstance(per_segment, bool) or not isinstance(per_segment, (int, np.integer)) \
            or per_segment < 1:
        raise ValueError(f"per_segment must be an integer >= 1; got {per_segment!r}")
    whole = not isinstance(confirm, bool) and isinstance(confirm, (int, np.integer))
    if confirm is not None and not (whole and confirm >= 2):
        raise ValueError(f"confirm must be None or an integer >= 2 (periods); got {confirm!r}")
    if not np.all(branch.converged):
        bad = np.flatnonzero(~np.asarray(branch.converged))
        raise ValueError(f"every point must be converged to judge its stability; points {bad[:5]} "
                         "are not")
    parts = segments(branch)
    needed = len(parts) * per_segment + 2
    if needed > max_checks:
        raise ValueError(f"{len(parts)} segments x per_segment = {per_segment} and the two ends "
                         f"need {needed} runs, more than max_checks = {max_checks}")
    checks: dict = {}
    confirmed: set = set()

    def run(i: int, **override) -> None:
        if len(checks) + len(confirmed) >= max_checks:
            raise ValueError(f"the sample needs more than max_checks = {max_checks} runs")
        checks[i] = check_stability(branch.solution(i), **{**options, **override})

    stable = np.zeros(len(branch), dtype=bool)
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
    return dataclasses.replace(branch, stable=stable, checks=dict(sorted(checks.items())))
