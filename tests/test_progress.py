"""Progress bars on the studies that run step by step (issue 29, item 7).

`rt.continuation`, `rt.check_branch`, the ring (`rt.simulate_time_domain`)
and `rt.speed_ramp` take ``progress=None|True|False``: a ``tqdm`` bar on
stderr when forced, none on a small case by default, and none for any call
the book makes (a bar is output, and nbval would read it as a changed cell).
"""

import warnings

import pytest

import railtrack as rt
import railtrack.studies.branch_stability as branch_stability
import railtrack.studies.continuation_trace as continuation_trace
import railtrack.studies.ramp as ramp
import railtrack.timedomain.ring_setup as ring_setup
from railtrack.solvers.progress import PROGRESS_WORK
from railtrack.timedomain.runcost import (LONG_RUN_SECONDS, TYPICAL_PERIODS, LongRunWarning,
                                         check_run_cost, estimate_run_cost)

TRACK, TRAIN, LAW = rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper()
RING = dict(elements_per_span=2, steps_per_period=480)


@pytest.fixture(scope="module")
def branch():
    return rt.continuation(TRACK, TRAIN, LAW, "speed", start=40.0, stop=50.0, harmonics=30)


def _quiet(capsys):
    shown = capsys.readouterr()
    return shown.out == "" and shown.err == ""


CALLS = {
    "continuation": (lambda **kw: rt.continuation(TRACK, TRAIN, LAW, "speed", start=40.0,
                                                  stop=50.0, harmonics=30, **kw)),
    "ring": lambda **kw: rt.simulate_time_domain(TRACK, TRAIN, LAW, **RING, **kw),
    "speed_ramp": lambda **kw: rt.speed_ramp(TRACK, TRAIN, LAW, [40.0, 45.0], **RING, **kw),
}


@pytest.mark.parametrize("name", CALLS)
def test_a_bar_only_when_asked_on_a_small_case(name, capsys):
    CALLS[name]()
    CALLS[name](progress=False)
    assert _quiet(capsys)
    CALLS[name](progress=True)
    assert name in capsys.readouterr().err
    with pytest.raises(TypeError, match="progress"):
        CALLS[name](progress="yes")


@pytest.mark.parametrize("method, label", [("floquet", "check_branch"),
                                           ("time-domain", "check_branch, the ring")])
def test_check_branch_shows_a_bar_only_when_asked(branch, method, label, capsys):
    ring = dict(per_segment=1, periods=3, **RING) if method == "time-domain" else {}
    rt.check_branch(branch, method, **ring)
    assert _quiet(capsys)
    rt.check_branch(branch, method, progress=True, **ring)
    assert label in capsys.readouterr().err
    with pytest.raises(TypeError, match="progress"):
        rt.check_branch(branch, method, progress=1, **ring)


def test_the_bar_counts_what_was_done(branch, capsys):
    # the final count on the bar is the branch's points, and the ring's periods
    rt.continuation(TRACK, TRAIN, LAW, "speed", start=40.0, stop=50.0, harmonics=30,
                    progress=True)
    assert f"{len(branch)} points" in capsys.readouterr().err
    result = rt.simulate_time_domain(TRACK, TRAIN, LAW, **RING, progress=True)
    assert f"{result.periods}/40" in capsys.readouterr().err


def test_large_studies_show_the_bar_by_default(branch, monkeypatch, capsys):
    # the thresholds lowered: the default (None) shows the bar where the work is large
    monkeypatch.setattr(continuation_trace, "PROGRESS_WORK", 1.0)
    monkeypatch.setattr(branch_stability, "PROGRESS_WORK", 1.0)
    monkeypatch.setattr(ring_setup, "LONG_RUN_SECONDS", 0.0)
    monkeypatch.setattr(ramp, "LONG_RUN_SECONDS", 0.0)
    rt.continuation(TRACK, TRAIN, LAW, "speed", start=40.0, stop=50.0, harmonics=30)
    rt.check_branch(branch)
    rt.simulate_time_domain(TRACK, TRAIN, LAW, **RING)
    err = capsys.readouterr().err
    assert all(label in err for label in ("continuation in speed", "check_branch", "ring, 480"))
    rt.speed_ramp(TRACK, TRAIN, LAW, [40.0], **RING)
    assert "speed_ramp" in capsys.readouterr().err


def _ring_shows(sleepers, elements, steps, max_periods=40):
    cost = estimate_run_cost(sleepers, elements, steps)
    return cost.seconds(min(TYPICAL_PERIODS, max_periods)) > LONG_RUN_SECONDS


def test_no_call_the_book_makes_shows_a_bar():
    """The sizes of the book's largest calls (grep book/*.ipynb) against the defaults' thresholds.

    The paper's wagon is 30 sleepers (H = 18 m, L = 0.6 m)."""
    # continuation: chapters 10 and 14, max_points 400 at m = 30 and m = 25
    assert 400 * (2 * 30 + 1) ** 2 < PROGRESS_WORK
    # check_branch: chapter 10's branch, 173 points at m = 25
    assert 173 * (2 * 25 + 1) ** 2 < PROGRESS_WORK
    # the ring: chapter 14's finest (16 elements a span, 7200 steps), chapter 13's
    # (16, 4800), chapter 10's two wagons (60 sleepers, 4, 1200), the defaults (8, 2400)
    for sleepers, elements, steps in ((30, 16, 7200), (30, 16, 4800), (60, 4, 1200),
                                      (30, 8, 2400)):
        assert not _ring_shows(sleepers, elements, steps)
    # speed_ramp: chapter 10, 7 speeds on (4, 600), max_periods 80
    cost = estimate_run_cost(30, 4, 600).seconds(TYPICAL_PERIODS)
    assert 7 * cost < LONG_RUN_SECONDS
    # and a run that warns LongRunWarning shows its bar: the same criterion
    assert _ring_shows(30, 2000, 2400)


def test_a_long_ring_warns_and_would_show_its_bar():
    """The ring's default bar follows `LongRunWarning`: a run that warns is one that shows."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_run_cost(30, 2000, 2400, 40)
    assert any(issubclass(w.category, LongRunWarning) for w in caught)
