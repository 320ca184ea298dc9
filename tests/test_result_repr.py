"""Short reprs (issue 29): every result and study prints in a dozen lines, numbers that hold.

The generated dataclass reprs printed every array: 2,500 characters for a
Solution, 5,300 for a cell, 11,000 for a sweep, 43,000-100,000 for a
WheelSolution.  Here each repr must be at most 12 lines and under 1,000
characters on large cases, its extremes must be the arrays' own to the
printed digits (recomputed here by the public methods, a direct sum where
the repr takes an inverse FFT), and the HTML table must parse and carry the
same rows.  A result that did not converge, or holds NaNs, must still print.
"""

import dataclasses
import warnings
from html.parser import HTMLParser

import numpy as np
import pytest

import railtrack as rt

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
LAW = rt.CubicFoundation.paper()
PASSAGE = rt.Passage(TRACK, TRAIN)

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    SINGLE = rt.solve(TRACK, TRAIN, LAW, stability="full")
    CELL = rt.solve(TRACK, TRAIN, rt.SleeperCell.identical(PASSAGE, LAW, 30).with_sleeper(
        7, foundation=rt.LinearFoundation(8e6, 0.1e6)), 30)
    WHEELS = rt.solve(TRACK, TRAIN, rt.LinearFoundation(20e6, 0.2e6), 510, wheel=rt.Wheel(600.0))
    SWEEP = rt.sweep(TRACK, TRAIN, LAW, 20, speed=np.linspace(20.0, 120.0, 120))
    BRANCH = rt.continuation(TRACK, TRAIN, rt.LinearFoundation.paper(), "speed", start=40.0,
                             stop=60.0)
    RANDOM = rt.random_support(TRACK, TRAIN, rt.LinearFoundation.paper(), sleepers=6, draws=8,
                               harmonics=20)
    RING = rt.simulate_time_domain(TRACK, TRAIN, rt.LinearFoundation.paper(), 4, 420)
RESULTS = {"Solution": SINGLE, "CellSolution": CELL, "WheelSolution": WHEELS, "Sweep": SWEEP,
           "Branch": BRANCH, "RandomSupport": RANDOM, "TimeDomainSolution": RING,
           "Floquet": SINGLE.stability}


def line(text: str, name: str) -> str:
    """The value of row `name` in a repr."""
    (found,) = [row.split(": ", 1)[1] for row in text.splitlines() if row.startswith(f"  {name}:")]
    return found


class Table(HTMLParser):
    """Collects the cells' text and checks that every tag closes in order."""

    def __init__(self):
        super().__init__()
        self.open, self.cells, self.caption = [], [], ""

    def handle_starttag(self, tag, attrs):
        self.open.append(tag)

    def handle_endtag(self, tag):
        assert self.open and self.open.pop() == tag, f"</{tag}> closes nothing open"

    def handle_data(self, data):
        if self.open and self.open[-1] in ("th", "td"):
            self.cells.append(data)
        elif self.open and self.open[-1] == "caption":
            self.caption += data


def test_the_large_cases_are_large():
    assert WHEELS.harmonics >= 500 and CELL.sleepers == 30 and len(SWEEP) == 120


@pytest.mark.parametrize("kind", RESULTS)
def test_every_repr_is_a_dozen_short_lines(kind):
    result = RESULTS[kind]
    assert type(result).__name__ == kind
    text = repr(result)
    assert len(text.splitlines()) <= 12 and len(text) < 1000, (len(text), text)
    assert kind in text.splitlines()[0]


@pytest.mark.parametrize("kind", RESULTS)
def test_the_html_table_parses_and_holds_the_same_rows(kind):
    result = RESULTS[kind]
    table = Table()
    table.feed(result._repr_html_())
    table.close()
    assert table.open == []
    rows = repr(result).splitlines()
    assert table.caption == rows[0]
    assert [f"  {name}: {value}" for name, value in zip(table.cells[::2], table.cells[1::2])] \
        == rows[1:]


def test_the_steady_state_extremes_are_the_arrays_own():
    for result in (SINGLE, CELL, WHEELS):
        text = repr(result)
        t, w = result.one_period()
        assert line(text, "sleeper w [mm]").startswith(f"min {w.min() * 1e3:.3f}")
        assert f"max {w.max() * 1e3:.3f}" in line(text, "sleeper w [mm]")
        seat = result.rail_seat_load(t)
        assert line(text, "rail-seat load [kN]").startswith(f"max {seat.max() / 1e3:.2f}")
        assert f"min {seat.min() / 1e3:.2f}" in line(text, "rail-seat load [kN]")
        force = result.foundation_force(t)
        assert line(text, "foundation force [kN]").startswith(f"max {force.max() / 1e3:.2f}")
        rail = result.rail_above_sleepers(t)
        assert line(text, "rail above sleeper [mm]").startswith(f"min {rail.min() * 1e3:.3f}")
        assert f"m = {result.harmonics}," in line(text, "solve")
    seat = CELL.rail_seat_load(CELL.one_period()[0])
    sleeper = np.unravel_index(np.argmax(seat), seat.shape)[0]
    assert f"(sleeper {sleeper})" in line(repr(CELL), "rail-seat load [kN]")
    force = WHEELS.contact_force(WHEELS.one_period()[0])
    assert line(repr(WHEELS), "contact force [kN]").startswith(f"max {force.max() / 1e3:.2f}")
    assert f"max {force.max() / 75e3:.3f}" in line(repr(WHEELS), "dynamic factor")


def test_the_studies_extremes_are_the_arrays_own():
    text = repr(SWEEP)
    i = int(np.nanargmin(SWEEP.lowest))
    assert line(text, "lowest sleeper w [mm]") == (
        f"min {SWEEP.lowest[i] * 1e3:.3f} at speed = {SWEEP.values['speed'][i]:.4g} m/s")
    # the sweep's member is the solution at that speed: its own period holds the same low
    lowest = SWEEP.solution(i).one_period(4096)[1].min()
    assert abs(lowest - SWEEP.lowest[i]) < 1e-3 * abs(lowest)
    assert f"{int(np.sum(SWEEP.converged))} of 120" in line(text, "converged")
    seat = RANDOM.peak_seat_load / 1e3
    assert line(repr(RANDOM), "peak rail-seat load [kN]").startswith(f"mean {seat.mean():.2f}")
    w = RING.sleeper_displacements
    assert line(repr(RING), "sleeper w [mm]").startswith(f"min {w.min() * 1e3:.3f}")
    assert line(repr(BRANCH), "lowest sleeper w [mm]").startswith(
        f"min {BRANCH.minimum_displacement().min() * 1e3:.3f}")


def test_a_result_that_failed_or_holds_nans_still_prints():
    broken = dataclasses.replace(SINGLE, coefficients=np.full_like(SINGLE.coefficients, np.nan),
                                 converged=False, residual_history=np.array([np.nan]))
    text = repr(broken)
    assert "NOT converged" in text and "nan" in line(text, "sleeper w [mm]")
    assert len(text.splitlines()) <= 12 and "<table>" in broken._repr_html_()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        stopped = rt.solve(TRACK, TRAIN, rt.LinearFoundation(20e6, 0.2e6), 60,
                           wheel=rt.Wheel(600.0), max_iterations=0,
                           profile=rt.CosineDip(5e-3, 1.0, 18.0, centre=9.3))
    assert not stopped.converged and "NOT converged" in repr(stopped).splitlines()[0]
