"""harmonics="auto" at its cap on a cell says what m would do, and that m does it (issue 28).

A gap law with a force jump at contact converges slowly (the seat load's
max-norm error falls about as 1/m): on the paper's wagon at 45 m/s a 1 mm
void in a cell of 100 still has 0.3 % at m = 400, the largest m that "auto"
takes for a cell.  The warning names the cap and the m that the last
estimate's spectrum needs, and the capped result says converged=False; solved
there, the estimate meets the accuracy.
The cap is lowered here so that the check stays small.
"""

import warnings

import pytest

import railtrack as rt
from railtrack.solvers import cell_auto

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = rt.Passage(TRACK, TRAIN)


def test_the_cap_names_an_m_that_meets_the_accuracy(monkeypatch):
    monkeypatch.setattr(cell_auto, "MAX_CELL_HARMONICS", 60)
    cell = rt.SleeperCell.identical(PAPER, rt.LinearFoundation(20e6, 0.2e6), 5).with_sleeper(
        2, foundation=rt.GapFoundation(1e-3, 20e6, 0.2e6))
    accuracy = 5e-3
    with pytest.warns(rt.ConvergenceWarning, match="stops at 60 for a cell") as caught:
        capped = rt.solve(TRACK, TRAIN, cell, accuracy=accuracy, stability="off")
    # short of the accuracy asked for: a failure, not a converged answer
    assert not capped.converged and capped.harmonics == 60
    assert capped.truncation_error > accuracy
    text = str(caught[0].message)
    needed = int(text.split("about harmonics=")[1].split()[0])
    assert needed > 60
    with warnings.catch_warnings():
        warnings.simplefilter("error", rt.TruncationWarning)
        there = rt.solve(TRACK, TRAIN, cell, needed, stability="off")
    assert there.converged and there.truncation_error <= accuracy
