"""Following a branch of periodic solutions in one parameter (pseudo-arclength).

A softening or hardening foundation bends the response curve, so that over a
range of speeds eq. (17) has several periodic solutions, and a sweep of
single solves jumps between them (or misses some).  Pseudo-arclength
continuation (Keller 1977) follows the curve R(x, p) = 0 itself, through
its turning points, with x = to_real(c) (2m + 1 reals) and p the parameter.

The steps themselves (scaling, bordered Jacobian, corrector) are in
`railtrack.solvers.arclength`, which `railtrack.solve` shares for its fallback.

**Harmonics.**  By default (``harmonics="auto"``) m is chosen as
`railtrack.solve` chooses it: predicted at both ends of the range to half the
accuracy asked for, then, once the branch is traced, the truncation error of
every point is estimated (`railtrack.solvers.truncation`); if the worst is
above the accuracy, m grows to what that point's spectrum needs and the
branch is traced again.  An explicit m is kept, and warns
(`railtrack.TruncationWarning`) where a point's estimate exceeds 1 %.

The loop that traces one branch at a given m is in
`railtrack.studies.continuation_trace`.
"""

from __future__ import annotations

import dataclasses
import math
import warnings

from ..solvers.arguments import require_count, require_fraction
from .branch import TRACK_FIELDS, TRAIN_FIELDS, Branch, Fold, check_parameter, replaced, scalar
from .continuation_trace import trace as _trace
from ..model.cell import SleeperCell
from ..model.passage import Passage
from ..solvers.solution import ConvergenceWarning, TruncationWarning
from ..solvers.solve import AUTO_ROUNDS, DEFAULT_ACCURACY, WARN_TRUNCATION
from ..solvers.progress import show_progress
from ..solvers.threads import blas_threads
from ..solvers.truncation import MAX_AUTO_HARMONICS, predict_harmonics

__all__ = ["continuation", "Branch", "Fold"]


def continuation(track, train, foundation, parameter: str = "speed", start=None, stop=None,
                 harmonics: int | str = "auto", step: float | None = None, max_points: int = 400,
                 tol: float = 1e-10, *, accuracy: float | None = None,
                 min_step: float | None = None, max_step: float | None = None,
                 samples: int | None = None, initial=None, max_corrector: int = 8,
                 progress: bool | None = None) -> Branch:
    """Follow the periodic solution of eq. (17) from ``parameter = start`` to `stop`.

    Parameters
    ----------
    track, train, foundation
        The problem, as for `railtrack.solve`; the foundation must be a
        dataclass (one of the package's laws) if `parameter` is one of its fields.
    parameter : str
        A scalar field of the Track (e.g. "pad_damping"), of the Train
        ("speed", "wagon_length") or of the foundation ("epsilon",
        "damping", "tension_stiffness", ...), in that field's unit.
    start : float, optional
        First value (default: the value in the given objects).
    stop : float
        The branch ends when it reaches this value, landing exactly on it.
    harmonics : int or "auto"
        m, the same at every point.  "auto" (default): the smallest m that
        keeps the estimated truncation error of every point below
        `accuracy` (module docstring); the branch's message gives m and the
        worst estimate.  An explicit m whose worst point exceeds 1 % warns
        (`railtrack.TruncationWarning`).  Each point's estimate is
        ``branch.solution(i).truncation_error``.
    step : float, optional
        First arclength step, in the unit of the parameter: on a flat stretch
        the change of p per step (default (stop - start) / 50).
    max_points : int
        Largest number of points, the start included.
    tol : float
        Every point solves eq. (17) to ||R|| / ||F|| <= tol.
    accuracy : float, optional
        For ``harmonics="auto"``: the largest estimated truncation error of a
        point, as for `railtrack.solve` (default 1e-3).
    min_step, max_step : float, optional
        Bounds of the step, same unit as `step` (default step / 1000 and
        (stop - start) / 10).  A corrector failing at `min_step` ends the branch.
    samples : int, optional
        AFT samples per period, > 4m; needs an explicit m.
    initial : ndarray, optional
        Starting c_0..c_m for the first solve; needs an explicit m.
    max_corrector : int
        Newton steps allowed to each corrector.
    progress : bool or None
        A ``tqdm`` counter of the points traced, with the parameter reached
        (`railtrack.solvers.progress`): None shows it when `max_points` x
        (2m + 1)^2 reaches `railtrack.solvers.progress.PROGRESS_WORK`
        (400 points at m = 50), True or False force it.

    Returns
    -------
    Branch
        With the points, their coefficients (one-sided), the folds and a message.
        A branch that ends before `stop` warns (`railtrack.ConvergenceWarning`)
        with the reason.

    Raises
    ------
    ValueError
        Unknown or non-scalar parameter, start or stop not real scalars,
        start == stop, bad harmonics, tol or step.
    TypeError
        A `railtrack.SleeperCell` as foundation (the message names the alternatives).

    Examples
    --------
    >>> import railtrack as rt
    >>> branch = continuation(rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper(),
    ...                       "epsilon", start=0.0, stop=1.0)
    >>> bool(branch.converged.all()), float(branch.values[-1]), len(branch.folds)
    (True, 1.0, 0)
    """
    with blas_threads(1):
        if isinstance(foundation, SleeperCell):
            raise TypeError(
                f"continuation follows one law under every sleeper; foundation is a SleeperCell of "
                f"{foundation.sleepers} sleepers.  Solve the cell at each value instead, "
                "rt.solve(track, train.replace(speed=v), cell); if its sleepers are all alike, pass "
                "their one law, cell.foundations[0], to continuation or rt.sweep")
        if not isinstance(parameter, str):
            raise ValueError(f"parameter must be the name of a field; got {parameter!r}")
        check_parameter(track, train, foundation, parameter)
        if start is None:
            start = getattr(track if parameter in TRACK_FIELDS else train if parameter in TRAIN_FIELDS
                            else foundation, parameter)
        start, stop = scalar("start", parameter, start), scalar("stop", parameter, stop)
        if start == stop:
            raise ValueError(f"start and stop of {parameter!r} must differ; both are {start!r}")
        automatic = isinstance(harmonics, str) and harmonics == "auto"
        if not automatic:
            require_count("harmonics", harmonics, 1)
        elif samples is not None or initial is not None:
            raise ValueError("samples and initial need an explicit harmonics=m; 'auto' chooses m itself")
        if accuracy is not None and not automatic:
            warnings.warn("accuracy is used by harmonics='auto' only; ignored for an explicit m")
        accuracy = DEFAULT_ACCURACY if accuracy is None else require_fraction("accuracy", accuracy)
        require_count("max_points", max_points, 2)
        tol = require_fraction("tol", tol)
        span = abs(stop - start)
        step = span / 50 if step is None else scalar("step", parameter, step)
        bounds = (step / 1000 if min_step is None else min_step, span / 10 if max_step is None else max_step)
        if not 0 < bounds[0] <= step <= bounds[1] or step > span:
            raise ValueError(f"need 0 < min_step <= step <= max_step and step <= |stop - start| for "
                             f"{parameter!r}; got {bounds[0]!r}, {step!r}, {bounds[1]!r}")

        show_progress(progress, False)  # a TypeError now, not after the first solve
        settings = (track, train, foundation, parameter, start, stop, step, bounds, max_points, tol,
                    max_corrector, progress)
        if not automatic:
            branch, worst = _trace(*settings, harmonics, samples, initial)
            if worst[0] > WARN_TRUNCATION:
                warnings.warn(TruncationWarning(
                    f"harmonics={harmonics}: the estimated truncation error reaches {worst[0]:.1%} "
                    f"of the peak sleeper displacement at {parameter} = {worst[1]:.6g}; "
                    f"harmonics='auto' would take m = {worst[2]} there (pass a larger harmonics "
                    "or use 'auto')"), stacklevel=2)
            return _warned(branch)
        m = max(_predicted(track, train, foundation, parameter, p, accuracy) for p in (start, stop))
        for _round in range(AUTO_ROUNDS + 1):
            branch, worst = _trace(*settings, m, None, None)
            if worst[0] <= accuracy or m >= MAX_AUTO_HARMONICS or not branch.converged.all():
                break
            m = min(MAX_AUTO_HARMONICS, max(math.ceil(1.1 * m), worst[2]))
        note = (f"; harmonics='auto' chose m = {branch.harmonics}, largest estimated truncation "
                f"error {worst[0]:.1e} at {parameter} = {worst[1]:.6g}")
        if worst[0] > accuracy:
            warnings.warn(TruncationWarning(
                f"harmonics='auto' stopped at m = {branch.harmonics} with an estimated truncation "
                f"error of {worst[0]:.1%} at {parameter} = {worst[1]:.6g} (pass a larger harmonics)"),
                stacklevel=2)
        return _warned(dataclasses.replace(branch, message=branch.message + note))


def _predicted(track, train, foundation, parameter, value, accuracy) -> int:
    """The m that `railtrack.solve` predicts at ``parameter = value`` (1 if it cannot)."""
    try:
        track, train, foundation = replaced(track, train, foundation, parameter, value)
        return predict_harmonics(Passage(track, train), foundation, accuracy / 2)[0]
    except (ValueError, ArithmeticError):
        return 1


def _warned(branch: Branch) -> Branch:
    """`branch`, with a `ConvergenceWarning` to the caller if it ended before its stop."""
    if not branch.message.startswith("reached"):
        warnings.warn(ConvergenceWarning(
            f"the branch in {branch.parameter} ended early, after {len(branch)} point(s): "
            f"{branch.message}"), stacklevel=3)
    return branch
