"""Short reprs of the studies' results: `Sweep`, `Branch`, `RandomSupport` (issue 29).

A dozen lines at most: what was varied and over what range, how many
members converged, and the extremes over the study in mm and kN, with where
they occur.  Extremes are over the members with finite values (a failed
member carries NaN); nothing is solved again, and nothing here raises.
The rows render as text (`railtrack.solvers.result_repr.render_text`) or as
an HTML table.
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from ..model.passage import Passage
from ..solvers.result_repr import KN, MM, case_text, law_text, quantity, safe

__all__ = ["sweep_rows", "branch_rows", "random_support_rows", "finite_extreme", "verdict_counts"]


def finite_extreme(values, along, scale: float, digits: int, pick: str, name: str,
                   unit: str = "") -> str:
    """"a at name = b": the min or max of the finite `values` times `scale`, and `along` there."""
    values = safe(lambda: values)
    if values is None or not np.any(np.isfinite(values)):
        return "n/a"
    index = int(np.nanargmin(values) if pick == "min" else np.nanargmax(values))
    where = "" if along is None else f" at {name} = {float(along[index]):.4g}{unit}"
    return f"{pick} {float(values[index]) * scale:.{digits}f}{where}"


def verdict_counts(flags) -> str:
    """"a stable, b unstable, c unknown" from True / False / None flags; "not judged" if None."""
    if flags is None:
        return "not judged"
    counts = Counter({True: "stable", False: "unstable"}.get(
        None if flag is None else bool(flag), "unknown") for flag in np.ravel(flags))
    return ", ".join(f"{counts[k]} {k}" for k in ("stable", "unstable", "unknown") if counts[k])


def _range(values) -> str:
    values = np.asarray(values, dtype=float)
    return f"{np.nanmin(values):.4g} to {np.nanmax(values):.4g}" if values.size else "empty"


def _largest(values) -> str:
    values = safe(lambda: values)
    if values is None or not np.any(np.isfinite(values)):
        return "n/a"
    return f"{np.nanmax(values):.1e}"


def sweep_rows(s) -> tuple[str, list[tuple[str, str]]]:
    """Title and rows of a `railtrack.Sweep`."""
    names = list(s.values)
    name = names[0] if names else "value"
    along = s.values[name] if names else None
    size = len(s.converged)
    unit = " m/s" if name == "speed" else ""
    title = (f"Sweep over {', '.join(names) or 'nothing'}: {size} members, "
             f"{_range(along) if along is not None else ''}{unit}")
    rows = [("case", case_text(s.passage)), ("foundation", law_text([s.foundation])),
            ("converged", f"{int(np.sum(s.converged))} of {size}; m = {int(s.harmonics)}"),
            ("largest residual, truncation error",
             f"{_largest(s.residual)}, {_largest(s.truncation_error)}"),
            ("lowest sleeper w [mm]", finite_extreme(s.lowest, along, MM, 3, "min", name, unit)),
            ("highest sleeper w [mm]", finite_extreme(s.highest, along, MM, 3, "max", name, unit)),
            ("rail-seat load [kN]", finite_extreme(s.seat_load_peak, along, KN, 2, "max", name,
                                                   unit)),
            ("foundation force [kN]", finite_extreme(s.foundation_force_peak, along, KN, 2,
                                                     "max", name, unit)),
            ("stability", verdict_counts(s.stable))]
    return title, rows


def branch_rows(b) -> tuple[str, list[tuple[str, str]]]:
    """Title and rows of a `railtrack.Branch`."""
    lowest = safe(lambda: b.minimum_displacement())
    folds = ", ".join(f"{fold.value:.4g}" for fold in b.folds[:4]) + (
        " ..." if len(b.folds) > 4 else "")
    message = str(b.message)
    title = f"Branch in {b.parameter}: {len(b.values)} points, {_range(b.values)}"
    rows = [("case", case_text(_passage(b))), ("foundation", law_text([b.foundation])),
            ("converged", f"{int(np.sum(b.converged))} of {len(b.converged)}; "
                          f"m = {int(b.harmonics)}, largest residual {_largest(b.residuals)}"),
            ("folds", f"{len(b.folds)}" + (f" at {b.parameter} = {folds}" if b.folds else "")),
            ("lowest sleeper w [mm]", finite_extreme(lowest, b.values, MM, 3, "min",
                                                     b.parameter)),
            ("stability", verdict_counts(b.stable) + (
                f"; {len(b.changes)} changes" if b.changes else "")),
            ("message", message if len(message) <= 70 else message[:67] + "...")]
    return title, rows


def _passage(b) -> Passage:
    return Passage(b.track, b.train)


def random_support_rows(r) -> tuple[str, list[tuple[str, str]]]:
    """Title and rows of a `railtrack.RandomSupport`."""
    draws, sleepers = np.shape(r.factors)[0], np.shape(r.factors)[-1]
    title = (f"RandomSupport: {draws} draws of {sleepers} sleepers, "
             f"variation {float(r.variation):.3g}")
    harmonics = np.asarray(r.harmonics)
    seat, moment = safe(lambda: r.peak_seat_load), safe(lambda: r.peak_moment)
    rows = [("converged", f"{int(np.sum(r.converged))} of {draws}; m = "
                          f"{quantity(harmonics) if harmonics.size else 'n/a'}"),
            ("peak rail-seat load [kN]", _spread(seat, KN)),
            ("peak bending moment [kN m]", _spread(moment, KN)),
            ("stability", ", ".join(f"{n} {k}" for k, n in Counter(
                np.ravel(r.stability).tolist()).items()) or "not judged")]
    return title, rows


def _spread(values, scale: float) -> str:
    if values is None or not np.any(np.isfinite(values)):
        return "n/a"
    finite = values[np.isfinite(values)] * scale
    return (f"mean {finite.mean():.2f}, max {finite.max():.2f} (draw "
            f"{int(np.nanargmax(values))}), min {finite.min():.2f}")

