"""Short reprs of the results: a dozen lines an engineer reads at a glance (issue 29).

A dataclass's generated repr prints every array in full: 2,500 characters
for a `Solution`, 43,000 and more for a `WheelSolution`.  These reprs say
instead what was solved (speed, axles, foundation law, sleepers, wheels),
how well (m, converged, residual, truncation estimate) and the key extremes
in mm and kN.  ``_repr_html_`` gives the same rows as a small HTML table
for notebooks.

The extremes are taken over ``one_period()``'s default times (max(400, 4 m)
samples of [0, T), `railtrack.solvers.result_protocol`), by an inverse FFT
of the harmonics: no new solve, and cheap for any m.  Nothing here raises:
a result that did not converge, or holds NaNs, prints "nan" or "n/a".
"""

from __future__ import annotations

import warnings
from collections import Counter
from html import escape
from typing import Callable

import numpy as np

from ..equations.rail_field import seat_load_coefficients
from .result_protocol import period_samples
from .wheel_extremes import peak_samples

__all__ = ["render_text", "render_html", "solution_rows", "cell_rows", "wheel_rows",
           "floquet_rows", "result_repr", "result_html", "ShortRepr", "case_text", "law_text",
           "extent", "quantity", "rows_of",
           "safe", "MM", "KN"]

MM, KN = 1e3, 1e-3
"""Factors from m to mm and from N to kN."""
Rows = list[tuple[str, str]]


def render_text(title: str, rows: Rows) -> str:
    """The title, then one indented ``name: value`` line per row."""
    return "\n".join([title] + [f"  {name}: {value}" for name, value in rows])


def render_html(title: str, rows: Rows) -> str:
    """The same rows as a two-column HTML table, the title its caption."""
    cells = "".join(f"<tr><th style=\"text-align:left\">{escape(name)}</th>"
                    f"<td style=\"text-align:left\">{escape(value)}</td></tr>"
                    for name, value in rows)
    return f"<table><caption>{escape(title)}</caption><tbody>{cells}</tbody></table>"


def safe(compute: Callable[[], object]):
    """compute() as a float array, or None if it fails: a repr must never raise."""
    try:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return np.asarray(compute(), dtype=float)
    except Exception:       # noqa: BLE001 - any failure reads "n/a"
        return None


def extent(values, scale: float, digits: int, order: str = "min", label: str = "") -> str:
    """"min a, max b" (or "max b, min a") of `values` times `scale`; "n/a" if None or empty.

    With a `label` ("sleeper", "wheel"), the first extreme names the row of
    `values` (rows, times) where it occurs: "min a (sleeper j), max b".
    """
    if values is None or np.size(values) == 0:
        return "n/a"
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        low, high = float(np.min(values)) * scale, float(np.max(values)) * scale
    parts = [f"min {low:.{digits}f}", f"max {high:.{digits}f}"]
    if order != "min":
        parts = parts[::-1]
    if label and np.ndim(values) == 2 and values.shape[0] > 1 and np.all(np.isfinite(values)):
        pick = np.argmin if order == "min" else np.argmax
        parts[0] += f" ({label} {int(np.unravel_index(pick(values), values.shape)[0])})"
    return ", ".join(parts)


def quantity(value, scale: float = 1.0) -> str:
    """A field that may be swept: "a" for a scalar, "a to b" for an array."""
    values = np.asarray(value, dtype=float) * scale
    if values.size == 1:
        return f"{float(values.ravel()[0]):.4g}"
    return f"{np.nanmin(values):.4g} to {np.nanmax(values):.4g}"


def case_text(passage) -> str:
    """Speed, wagon, axle loads and spacing in a line (ranges where a sweep varies them)."""
    loads = np.asarray(passage.axle_loads, dtype=float) * KN
    shown = (f"{loads.size} x {loads.ravel()[0]:.4g} kN" if np.all(loads == loads.ravel()[0])
             else ", ".join(f"{q:.4g}" for q in loads.ravel()[:4])
             + (" ..." if loads.size > 4 else "") + " kN")
    return (f"v = {quantity(passage.speed)} m/s ({quantity(passage.speed, 3.6)} km/h), wagon "
            f"{quantity(passage.wagon_length)} m, axles {shown}, "
            f"L = {quantity(passage.sleeper_spacing)} m")


def law_text(laws) -> str:
    """The foundation laws by kind, with how many sleepers each holds."""
    counts = Counter(type(law).__name__ for law in laws)
    if len(counts) == 1 and len(laws) == 1:
        return next(iter(counts))
    shown = ", ".join(f"{n} x {name}" for name, n in counts.most_common(3))
    return shown + (" ..." if len(counts) > 3 else "")


def solve_text(result) -> str:
    """m, iterations and the residual."""
    return (f"m = {int(result.harmonics)}, {int(result.iterations)} iterations, residual "
            f"{float(result.residual):.2e}, truncation error {float(result.truncation_error):.1e}")


def period_series(coefficients: np.ndarray, samples: int) -> np.ndarray:
    """Re sum_n c_{j,n} e^{2 pi i n k / samples}, n = -m..m, k = 0..samples-1: (rows, samples)."""
    c = np.atleast_2d(coefficients)
    m = (c.shape[1] - 1) // 2
    spectrum = np.zeros((c.shape[0], samples), dtype=complex)
    np.add.at(spectrum, (slice(None), np.arange(-m, m + 1) % samples), c)
    return (np.fft.ifft(spectrum, axis=1) * samples).real


def sleeper_rows(w, rail, seat, force) -> Rows:
    """The extremes of the per-sleeper histories (rows, times), in mm and kN."""
    return [("sleeper w [mm]", extent(w, MM, 3, "min", "sleeper")),
            ("rail above sleeper [mm]", extent(rail, MM, 3, "min", "sleeper")),
            ("rail-seat load [kN]", extent(seat, KN, 2, "max", "sleeper")),
            ("foundation force [kN]", extent(force, KN, 2, "max", "sleeper"))]


def _forces(laws, w, v):
    return -np.stack([np.asarray(law.force(wj, vj), dtype=float)
                      for law, wj, vj in zip(laws, w, v)])


def solution_rows(s) -> tuple[str, Rows]:
    """Title and rows of a `railtrack.Solution`."""
    n = period_samples(s)
    omega, c = s.frequencies, s.coefficients
    w = safe(lambda: period_series(c, n))
    rail = safe(lambda: period_series(s.rail_coefficients(), n))
    seat = safe(lambda: period_series(seat_load_coefficients(s.passage, omega, c), n))
    force = safe(lambda: _forces([s.foundation], w, period_series(1j * omega * c, n)))
    title = f"Solution ({s.method}): {'converged' if s.converged else 'NOT converged'}"
    rows = [("case", case_text(s.passage)),
            ("foundation", law_text([s.foundation]) + ", one sleeper (every one alike)"),
            ("solve", solve_text(s)), *sleeper_rows(w, rail, seat, force)]
    if s.stability is not None:
        rows.append(("stability", _verdict(s.stability)))
    return title, rows + [("extremes over", f"{n} times of one period T = {s.period:.4g} s")]


def _cell_histories(c, n: int):
    """(w, rail above, seat load, foundation force) of every sleeper of a `CellSolution`."""
    cell, omega = c.cell, c.frequencies
    w = safe(lambda: period_series(c.coefficients, n))
    pad = cell.pad_stiffness[:, None] + 1j * omega * cell.pad_damping[:, None]
    rail = safe(lambda: period_series(c.coefficients + c.seat_harmonics / pad, n))
    seat = safe(lambda: -period_series(c.seat_harmonics, n))
    force = safe(lambda: _forces(cell.foundations, w, period_series(1j * omega * c.coefficients,
                                                                    n)))
    return w, rail, seat, force


def cell_rows(c) -> tuple[str, Rows]:
    """Title and rows of a `railtrack.CellSolution`."""
    n = period_samples(c)
    w, rail, seat, force = _cell_histories(c, n)
    title = (f"CellSolution of {c.sleepers} sleepers: "
             f"{'converged' if c.converged else 'NOT converged'}")
    rows = [("case", case_text(c.passage)), ("foundation", law_text(c.cell.foundations)),
            ("solve", solve_text(c)), *sleeper_rows(w, rail, seat, force)]
    if c.stability is not None:
        rows.append(("stability", _verdict(c.stability)))
    return title, rows + [("extremes over", f"{n} times of one period T = {c.period:.4g} s")]


def wheel_rows(s) -> tuple[str, Rows]:
    """Title and rows of a `railtrack.WheelSolution`."""
    n = period_samples(s)
    peaks = peak_samples(s, n)           # a short blow must not fall between samples
    t = np.linspace(0.0, s.period, peaks, endpoint=False)
    contact = safe(lambda: s.contact_force(t))
    w, rail, seat, force = _cell_histories(s.sleepers, n)
    loads = np.asarray(s.passage.axle_loads, dtype=float)
    factor = safe(lambda: np.max(contact, axis=1) / loads)
    off = safe(lambda: np.mean(contact <= 0.0, axis=1))
    wheel = s.wheel
    title = (f"WheelSolution of {loads.size} wheels on {s.sleepers.sleepers} sleepers: "
             f"{'converged' if s.converged else 'NOT converged'}")
    rows = [("case", case_text(s.passage)),
            ("wheel", ("" if not hasattr(wheel, "body_mass") else
                       f"under a Vehicle (body {float(wheel.body_mass):.4g} kg), ")
                      + f"m_w = {float(wheel.unsprung_mass):.4g} kg, C_H = "
                      f"{float(wheel.hertz_constant):.3g} N/m^1.5, profile "
                      f"{type(s.profile).__name__}"
                      + (f" on wheel {s.profile.wheel}" if isinstance(
                          getattr(s.profile, "wheel", None), int) else "")),
            ("foundation", law_text(s.sleepers.cell.foundations)), ("solve", solve_text(s)),
            ("contact force [kN]", extent(contact, KN, 2, "max", "wheel")),
            ("dynamic factor", ("n/a" if factor is None or off is None else
                                f"max {np.max(factor):.3f}; off the rail "
                                f"{np.max(off):.1%} of the period at most")),
            *sleeper_rows(w, rail, seat, force)]
    return title, rows + [("extremes over", f"{n} times of one period T = {s.period:.4g} s "
                                            f"(the contact force: {peaks})")]


def _verdict(floquet) -> str:
    dominant = complex(floquet.dominant)
    return f"{floquet.verdict} (|mu| = {abs(dominant):.4f}, {floquet.kind})"


def floquet_rows(f) -> tuple[str, Rows]:
    """Title and rows of a `railtrack.Floquet`."""
    message = str(f.message)
    dominant = complex(f.dominant)
    rows = [("dominant multiplier", f"{dominant:.4f}, |mu| = {abs(dominant):.4f}"),
            ("kind", f"{f.kind}, frequency {float(f.frequency):.3f} v/H, "
                     f"theta {float(f.theta):.3f} rad"),
            ("multipliers", f"{np.size(f.multipliers)} found, "
                            f"{int(np.sum(f.resolved))} resolved"),
            ("bound, ceiling", f"{float(f.bound):.4g}, {float(f.ceiling):.4g}"),
            ("harmonics", f"m = {int(f.harmonics)}, T = {float(f.period):.4g} s"),
            ("message", message if len(message) <= 70 else message[:67] + "...")]
    return f"Floquet: {f.verdict}" + (" (continued)" if f.continued else ""), rows


def rows_of(result) -> tuple[str, Rows]:
    """The rows of `result` by its class's ``_rows``, or a line saying why they could not be built.

    Never raises: a repr must not hide the object.
    """
    try:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return type(result)._rows(result)
    except Exception as error:      # noqa: BLE001 - a repr must not hide the object
        return type(result).__name__, [("repr", f"not available ({type(error).__name__}: "
                                                f"{str(error)[:60]})")]


def result_repr(result) -> str:
    """The short text repr of a result or study (a `ShortRepr`)."""
    return render_text(*rows_of(result))


def result_html(result) -> str:
    """The HTML table of a result or study (a `ShortRepr`)."""
    return render_html(*rows_of(result))


class ShortRepr:
    """``__repr__`` and ``_repr_html_`` from the class's ``_rows``, a function of an instance.

    ``_rows(result)`` gives the title and the ``(name, value)`` rows
    (`solution_rows`, ..., `railtrack.studies.study_repr.sweep_rows`,
    `railtrack.timedomain.td_repr.time_domain_rows`).  A dataclass that
    inherits this says ``repr=False``, or its generated repr would win.
    """

    def __repr__(self) -> str:
        return result_repr(self)

    def _repr_html_(self) -> str:
        return result_html(self)
