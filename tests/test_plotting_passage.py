"""railtrack.plotting.book.passage: the dips and uplifts of a wagon passage.

Oracles: a made-up w(x) with dips and bumps at known places and depths (the
function must find exactly those), and the symmetry of the undamped track:
with no damping the response at x is the mirror image about the wagon's
centre, so the two dips and the two uplifts are equal.
"""

import types

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import passage as pp  # noqa: E402
from railtrack.plotting.style import MM  # noqa: E402

PASSAGE = rt.Passage.paper()


def fake_solution(passage):
    """w(x) with dips of -1.0 mm at x = 0.1 m and -1.2 mm at x = D + 0.2 m, bumps of 0.03 mm
    at x = 7 m (behind) and 0.05 mm at x = 15 m (ahead)."""
    def bump(x, centre, height, width=0.3):
        d = np.mod(x - centre + passage.wagon_length / 2, passage.wagon_length) - passage.wagon_length / 2
        return height * np.exp(-(d / width) ** 2)

    def w(t):
        x = np.mod(np.asarray(t) * passage.speed, passage.wagon_length)
        return (bump(x, 0.1, -1.0e-3) + bump(x, passage.wheel_spacing + 0.2, -1.2e-3)
                + bump(x, 7.0, 0.03e-3, 1.0) + bump(x, 15.0, 0.05e-3, 1.0))
    return types.SimpleNamespace(passage=passage, sleeper_displacement=w)


def test_finds_the_made_up_extremes():
    found = pp.passage_extremes(fake_solution(PASSAGE))
    assert found.front_dip == pytest.approx(-1.0e-3, rel=1e-5)
    assert found.back_dip == pytest.approx(-1.2e-3, rel=1e-5)
    assert found.rear_uplift == pytest.approx(0.03e-3, rel=1e-3)
    assert found.front_uplift == pytest.approx(0.05e-3, rel=1e-3)
    assert found.front_lag == pytest.approx(0.1 / PASSAGE.speed, abs=1e-3 / PASSAGE.speed)
    assert found.back_lag == pytest.approx(0.2 / PASSAGE.speed, abs=1e-3 / PASSAGE.speed)


def test_rejects_a_spacing_outside_half_the_wagon():
    with pytest.raises(ValueError, match="wheel spacing"):
        pp.passage_extremes(fake_solution(rt.Passage(rt.Track.paper(), rt.Train.paper(wheel_spacing=10.0))))


def test_undamped_track_is_symmetric_and_damped_track_is_not():
    law = rt.LinearFoundation(20e6, 0.0)
    undamped = pp.passage_study(PASSAGE, {"undamped": law}, [45.0],
                                undamped=dict(pad_damping=0.0))["undamped"][0]
    assert undamped.front_dip == pytest.approx(undamped.back_dip, rel=1e-4)
    assert undamped.front_uplift == pytest.approx(undamped.rear_uplift, rel=1e-3)
    damped = pp.passage_study(PASSAGE, {"paper": rt.LinearFoundation.paper()}, [45.0])["paper"][0]
    assert damped.back_dip < damped.front_dip - 0.05e-3          # measured -1.127 vs -1.059 mm
    assert damped.front_uplift > 3 * damped.rear_uplift          # measured 0.079 vs 0.018 mm


def test_plot_draws_the_study():
    speeds = [5.0, 45.0]
    study = pp.passage_study(PASSAGE, {"paper": rt.LinearFoundation.paper()}, speeds)
    fig = pp.plot_passage_study(speeds, study)
    dips, lifts = fig.axes[:2]
    lines = {line.get_gid(): line for ax in (dips, lifts) for line in ax.get_lines()}
    np.testing.assert_array_equal(lines["paper: back dip"].get_xdata(), speeds)
    np.testing.assert_allclose(lines["paper: back dip"].get_ydata(),
                               [r.back_dip * MM for r in study["paper"]])
    np.testing.assert_allclose(lines["paper: rear uplift"].get_ydata(),
                               [r.rear_uplift * MM for r in study["paper"]])
    assert "mm" in dips.get_ylabel() and "m/s" in lifts.get_xlabel()
    plt.close(fig)
