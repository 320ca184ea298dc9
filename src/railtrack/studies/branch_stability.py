"""Stability along a branch: Floquet multipliers at every point, or the ring on a sample.

`check_branch` judges every point of a branch from `railtrack.continuation`.
By default (``method="floquet"``) each point gets its Floquet multipliers by
Hill's method (`railtrack.floquet`): searched in full at the first point,
then continued by Newton from the previous point's (``guess=``, about as
costly as a solve), with a full search wherever the continuation cannot be
trusted and on both sides of every change of the verdict
(`_continued_checks`); where the verdict changes between two neighbouring
points, the change is located: at a fold (a real multiplier through +1) it is the
fold's own value, elsewhere the parameter where the dominant multiplier
crosses the unit circle is found by solving between the two points.  Each
change is listed on the branch (`railtrack.studies.branch.StabilityChange`)
with its kind: a fold, a real multiplier through +1 away from a fold,
through -1 (period doubling), or a complex pair (Neimark–Sacker).

``method="time-domain"`` keeps the older check
(`railtrack.studies.branch_ring`): the time-domain ring
(`railtrack.check_stability`) on a sample of the points.  At a fold one
multiplier passes +1, so stability changes there as a rule, and the
sample is split at the folds: every segment between folds is checked at a
few points (and at the branch's two ends), and wherever two neighbouring
checks of one segment disagree the point between them is checked too,
until the change is located to one step of the branch.  A point takes the
verdict of the nearest checked point of its segment, so a stable stretch
of a segment between two sampled points is missed.  Near a loss of
stability without a fold the departure grows by little more than 1 per
period, and ``confirm=n`` watches the stable point next to each located
change for n periods.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..solvers.floquet import floquet
from ..solvers.threads import blas_threads
from ..solvers.solve import solve
from .branch import Branch, StabilityChange, replaced
from ..solvers.progress import PROGRESS_WORK, progress_bar, show_progress
from .branch_ring import ring_branch, segments

__all__ = ["segments", "check_branch", "METHODS"]

METHODS = ("floquet", "time-domain")
FOLD_STEP = 0.02
"""Where a point just past a fold is solved, as a fraction of the way to the next point [-]."""
VERDICT_POINTS = 16
"""Contour points per phase for the verdicts of `check_branch` (see `_floquet_branch`)."""


def check_branch(branch: Branch, method: str = "floquet", *, theta=None,
                 resolution: float | None = None, per_segment: int | None = None,
                 locate: bool = True, confirm: int | None = None, max_checks: int | None = None,
                 progress: bool | None = None, **options) -> Branch:
    """The branch with the stability of every point, and where it changes.

    Parameters
    ----------
    branch : Branch
        From `railtrack.continuation`, with every point converged.
    method : {"floquet", "time-domain"}
        Floquet multipliers by Hill's method at every point (default), or
        the time-domain ring on a sample of the points.
    theta : None, float, array_like or "scan"
        ``method="floquet"``: the Bloch phases of the disturbances
        (`railtrack.floquet`); None, those that repeat every wagon.
    resolution : float or None
        ``method="floquet"``: a change between two points away from a fold
        is located to this many units of the parameter; default 1e-4 of
        the larger of the two values.
    per_segment : int
        ``method="time-domain"`` only, as `locate`, `confirm` and
        `max_checks`.  Points checked inside each segment between folds (>= 1); the first
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
        Most `check_stability` runs in all (default 40); a ValueError if the sample needs
        more (before any run, if the first sample does).
    progress : bool or None
        A ``tqdm`` bar (`railtrack.solvers.progress`): of the points judged
        by Hill's method, shown by default when points x (2m + 1)^2 reaches
        `railtrack.solvers.progress.PROGRESS_WORK` (chapter 10's 173 points
        at m = 25 stay below it); of the ring's runs, shown by default when
        the first sample needs `railtrack.studies.branch_ring.PROGRESS_RUNS` or more.
        True or False force it.
    **options
        Passed to `railtrack.floquet` (min_multiplier, ...) or to
        `railtrack.check_stability` (periods, tol, elements_per_span,
        steps_per_period, wagons, max_periods, ...).

    Returns
    -------
    Branch
        A copy with ``stable`` (one per point: True, False, or None where
        the Floquet search could have missed a multiplier outside the unit
        circle, `railtrack.Floquet.verdict` "unknown"; changes are located
        only between a stable and an unstable point) and ``checks`` (point
        index -> `Floquet`, or -> `StabilityCheck` with the longer watch
        where there was one) set; with Hill's method also ``multipliers``
        (the dominant one per point) and ``changes``.

    Raises
    ------
    TypeError
        If `branch` is not a `Branch` (e.g. a `Solution`: judge it with
        `railtrack.floquet` or `railtrack.check_stability`).
    ValueError
        A point not converged, an unknown method, or options of the other method.

    Examples
    --------
    >>> import railtrack as rt
    >>> branch = rt.continuation(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
    ...                          "speed", start=40.0, stop=50.0, harmonics=30)
    >>> bool(check_branch(branch).stable.all())
    True
    >>> marked = check_branch(branch, "time-domain", per_segment=1, periods=3,
    ...                       elements_per_span=2, steps_per_period=600)
    >>> bool(marked.stable.all()), [check.verdict for check in marked.checks.values()]
    (True, ['stays', 'stays', 'stays'])
    """
    if not isinstance(branch, Branch):
        raise TypeError(f"check_branch takes a Branch from rt.continuation; got a "
                        f"{type(branch).__name__}" + (": judge one solution with "
                        "rt.floquet(solution) or rt.check_stability(solution)"
                        if hasattr(branch, "coefficients") else ""))
    show_progress(progress, False)  # a TypeError before any work
    if method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}; got {method!r}")
    if not np.all(branch.converged):
        bad = np.flatnonzero(~np.asarray(branch.converged))
        raise ValueError(f"every point must be converged to judge its stability; points {bad[:5]} "
                         "are not")
    if method == "floquet":
        ring_only = {"per_segment": per_segment, "confirm": confirm, "max_checks": max_checks}
        given = [name for name, value in ring_only.items() if value is not None]
        if given or not locate:
            raise ValueError(f"{', '.join(given) or 'locate'} apply to method='time-domain' "
                             "only; Hill's method judges every point")
        shown = show_progress(progress, len(branch) * (2 * branch.harmonics + 1) ** 2
                              >= PROGRESS_WORK)
        with progress_bar(shown, len(branch), "check_branch", "points") as bar:
            return _floquet_branch(branch, theta, resolution, bar, **options)
    return ring_branch(branch, per_segment, locate, confirm, max_checks, progress, options)


def _floquet_branch(branch: Branch, theta, resolution: float | None, bar, **options) -> Branch:
    """`check_branch` by Hill's method: every point, then each change located."""
    with blas_threads(1):
        # The verdict needs only the dominant multiplier, which 16 contour points find
        # as 48 do at every point of chapter 10's fold branch (tests/test_floquet.py);
        # the full set of multipliers needs `floquet`'s default 24.
        options.setdefault("points", VERDICT_POINTS)
        checks = _continued_checks(branch, theta, options, bar)
        stable = np.array([checks[i].stable for i in range(len(branch))], dtype=object)
        verdicts = [checks[i].verdict for i in range(len(branch))]
        dominant = np.array([checks[i].dominant for i in range(len(branch))])
        folds = {fold.index: fold for fold in branch.folds}
        changes = []
        values = np.asarray(branch.values, dtype=float)
        # A change is located only between a point shown stable and one shown unstable: next
        # to an "unknown" point the search could have missed what would place it.
        for i in range(len(branch) - 1):
            if {verdicts[i], verdicts[i + 1]} != {"stable", "unstable"}:
                continue
            ends = [(values[k], branch.coefficients[k], checks[k]) for k in (i, i + 1)]
            kind = None
            if i in folds:
                # At the fold a real multiplier passes +1; stability changes there unless
                # another multiplier is still outside on the stable side.  A point just
                # past the fold on that side tells.
                steady = i if verdicts[i] == "stable" else i + 1
                near = folds[i].value + FOLD_STEP * (values[steady] - folds[i].value)
                trial = _solved(branch, near, branch.coefficients[steady])
                past = None if trial is None else floquet(trial, theta, guess=checks[steady],
                                                          **options)
                if past is None or past.verdict != "unstable":
                    kind, value, frequency, phase = "fold", folds[i].value, 0.0, 0.0
                else:
                    ends[1 - (steady - i)] = (near, trial.coefficients[branch.harmonics:], past)
            if kind is None:
                value, unstable = _locate(branch, ends, theta, resolution, options)
                kind, frequency, phase = unstable.kind, unstable.frequency, unstable.theta
            changes.append(StabilityChange(float(value), i, kind, float(frequency), float(phase),
                                           bool(stable[i + 1])))
        return dataclasses.replace(branch, stable=stable, checks=checks, multipliers=dominant,
                                   changes=tuple(changes))


def _continued_checks(branch: Branch, theta, options, bar) -> dict:
    """The `Floquet` of every point: searched in full, or continued from its neighbour.

    Each point's multipliers are continued by Newton from the previous
    point's (`railtrack.floquet` with ``guess=``, which searches in full
    where the continuation cannot be trusted: `railtrack.solvers.floquet_track`).
    Where the verdict changes, the points on either side not proved unstable
    (a continued "unstable" is proved by the multiplier found outside) are
    searched in full, and if a full search disagrees with a continued
    verdict, the points before it are searched in full back to one that
    agrees: every change the branch lists lies between a point searched in
    full and one searched in full or proved unstable.
    """
    checks: dict = {}

    def full(i: int):
        return floquet(branch.solution(i), theta, **options)

    for i in range(len(branch)):
        # a result without eigenvectors (e.g. one whose search found no exponent to
        # continue) gives the next point nothing to start from: it is searched in full
        previous = checks.get(i - 1)
        continuable = previous is not None and previous.vectors is not None
        checks[i] = floquet(branch.solution(i), theta, guess=previous, **options) \
            if continuable else full(i)
        bar.to(i + 1)
        if i == 0 or checks[i].verdict == checks[i - 1].verdict:
            continue
        # a continued "unstable" is proved (a multiplier found outside); the others rest
        # on continuity, and next to a change the full search decides
        if checks[i].continued and checks[i].verdict != "unstable":
            checks[i] = full(i)
        k = i - 1
        while k >= 0 and checks[k].continued and checks[k].verdict != "unstable":
            verdict, checks[k] = checks[k].verdict, full(k)
            if checks[k].verdict == verdict:
                break
            k -= 1
    return checks


def _solved(branch: Branch, value: float, guess: np.ndarray):
    """The branch's problem solved at parameter `value` from `guess`, or None."""
    problem = replaced(branch.track, branch.train, branch.foundation, branch.parameter, value)
    trial = solve(*problem, harmonics=branch.harmonics, initial=guess, method="newton",
                  stability="off")  # judged by the caller
    return trial if trial.converged else None


def _locate(branch: Branch, ends, theta, resolution, options):
    """The parameter between two solved points where |dominant multiplier| = 1.

    `ends` holds (parameter, one-sided coefficients, `Floquet`) of each end.
    Regula falsi on log|mu| against the parameter, each trial point solved
    from the coefficients interpolated between the two ends.  Returns the
    value and the `Floquet` of the nearest unstable trial.
    """
    (a, ca, left), (b, cb, right) = ends
    fa, fb = np.log(abs(left.dominant)), np.log(abs(right.dominant))
    unstable = left if fa > 0 else right
    tol = 1e-4 * max(abs(a), abs(b)) if resolution is None else float(resolution)
    while abs(b - a) > tol:
        weight = float(np.clip(fa / (fa - fb), 0.1, 0.9))
        value = a + weight * (b - a)
        trial = _solved(branch, value, (1 - weight) * ca + weight * cb)
        if trial is None:
            break
        # only the dominant multiplier's modulus places the change: continued from the
        # nearer end of the bracket, whose two ends were searched in full
        result = floquet(trial, theta, guess=left if weight < 0.5 else right, **options)
        f = np.log(abs(result.dominant))
        if (f > 0) == (fa > 0):
            a, fa, ca, left = value, f, trial.coefficients[branch.harmonics:], result
        else:
            b, fb, cb, right = value, f, trial.coefficients[branch.harmonics:], result
        if f > 0:
            unstable = result
    return a + fa / (fa - fb) * (b - a), unstable
