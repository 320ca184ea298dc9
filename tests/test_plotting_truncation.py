"""Chapter 5's truncation study: its numbers against independent solves, its figure's content."""

import numpy as np
import pytest

from railtrack import CubicFoundation, LinearFoundation, Passage, Track, Train, solve
from railtrack.plotting.book import truncation as pt

STUDY = pt.truncation_study(Passage.paper(), LinearFoundation.paper(), (18.0, 40.0))


def test_errors_are_measured_against_a_much_larger_m():
    # for the linear law eq. (23) at m = 1000 is as good as exact: its error
    # to m = 2000 on 20000 points moves `true` by 1e-7 of itself (measured)
    track, train = Track.paper(), Train.paper(wagon_length=40.0)
    exact = solve(track, train, LinearFoundation.paper(), 1000, method="analytic")
    with pytest.warns(UserWarning):
        truncated = solve(track, train, LinearFoundation.paper(), 15, method="analytic")
    t = np.linspace(0.0, train.period, 8000, endpoint=False)
    w = exact.sleeper_displacement(t)
    true = np.max(np.abs(truncated.sleeper_displacement(t) - w)) / np.max(np.abs(w))
    assert STUDY.error_15[1] == pytest.approx(true, rel=0.01)
    assert STUDY.reference_harmonics.tolist() == [180, 400]


def test_auto_column_meets_the_accuracy_and_grows_with_h():
    assert np.all(STUDY.error_auto <= STUDY.accuracy)
    assert STUDY.auto_harmonics[1] > 2 * STUDY.auto_harmonics[0]
    np.testing.assert_allclose(STUDY.spans, [30.0, 40.0 / 0.6])


def test_table_and_figure_show_every_wagon():
    table = pt.truncation_table(STUDY)
    assert table.count("\n") == 3 and "| 18 | 30 |" in table
    fig = pt.plot_truncation(STUDY)
    left, right = fig.axes
    assert len(left.lines) == 2 and np.allclose(left.lines[0].get_xdata(), [18.0, 40.0])
    assert "[m]" in left.get_xlabel() and "harmonics m" in right.get_ylabel()


def test_study_works_for_a_nonlinear_law():
    study = pt.truncation_study(Passage.paper(), CubicFoundation.paper(0.8), (18.0,))
    assert study.estimate_15[0] == pytest.approx(study.error_15[0], rel=0.2)
