"""railtrack.plotting.book.speed: critical speeds, peak finding, halved spacing, figures.

Oracles: the Winkler formula by hand; the smeared track with a vanishing
sleeper mass tends to it; a parabola's vertex is found exactly; halving the
spacing keeps every per-metre value; the linear law's peak on a lightly
damped track lies within 5 % above the smeared prediction.
"""

import matplotlib

matplotlib.use("Agg")

import dataclasses  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import speed as sp  # noqa: E402
from railtrack.plotting.branch import plot_branch, ramp_on_branch  # noqa: E402

LIGHT = rt.Track.paper(pad_damping=30e3), rt.LinearFoundation(20e6, 20e3)


def test_winkler_critical_speed_by_hand():
    k = 220e6 * 20e6 / 240e6 / 0.6
    assert sp.winkler_critical_speed(*LIGHT) == pytest.approx((4 * k * 6.3e6 / 60.0 ** 2) ** 0.25, rel=1e-14)
    assert sp.lower_branch_bound(*LIGHT) == pytest.approx(np.sqrt(240e6 / 100.0), rel=1e-14)


def test_smeared_speed_tends_to_winkler_without_sleeper_mass():
    track, law = LIGHT
    light = dataclasses.replace(track, sleeper_mass=1e-4)
    assert sp.smeared_critical_speed(light, law) == pytest.approx(sp.winkler_critical_speed(light, law), rel=1e-3)
    assert sp.smeared_critical_speed(track, law) < 0.6 * sp.winkler_critical_speed(track, law)


def test_peak_speed_finds_a_parabola_vertex_between_grid_points():
    v = np.linspace(0.0, 10.0, 11)
    speed, lowest = sp.peak_speed(v, (v - 4.3) ** 2 - 1.0)
    assert speed == pytest.approx(4.3, abs=1e-12) and lowest == pytest.approx(0.09 - 1.0)


def test_halved_spacing_keeps_per_metre_values():
    track, law = sp.halved_spacing(*LIGHT)
    for field in ("sleeper_mass", "pad_stiffness", "pad_damping"):
        assert getattr(track, field) / track.sleeper_spacing == pytest.approx(getattr(LIGHT[0], field) / 0.6)
    assert law.stiffness / track.sleeper_spacing == pytest.approx(20e6 / 0.6)
    assert law.damping / track.sleeper_spacing == pytest.approx(20e3 / 0.6)


def test_linear_peak_sits_just_above_the_smeared_prediction_and_plots():
    speeds = np.linspace(200.0, 500.0, 301)
    curves = sp.lowest_over_speed({"light": LIGHT}, rt.Train.paper(), speeds)
    v_peak, _ = sp.peak_speed(speeds, curves["light"])
    assert 1.0 < v_peak / sp.smeared_critical_speed(*LIGHT) < 1.05
    fig = sp.plot_speed_curves(speeds, curves, marks={"smeared": sp.smeared_critical_speed(*LIGHT)})
    assert [line.get_gid() for line in fig.axes[0].lines][0] == "light"
    fig2 = sp.plot_seat_load_histogram(np.random.default_rng(0).normal(0.37, 0.01, 500))
    assert len(fig2.axes[0].get_legend().get_texts()) == 3
    plt.close("all")


@pytest.fixture(scope="module")
def fold_branch():
    return rt.continuation(rt.Track.paper(pad_damping=1e5), rt.Train.paper(speed=300.0),
                           rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0), "speed", start=300.0,
                           stop=600.0, harmonics=25)


def test_branch_dips_at_a_speed_are_those_of_polished_solves(fold_branch):
    dips, before = sp.branch_dips_at(fold_branch, 525.0)
    assert len(dips) == 5 and np.all(np.diff(before) > 0)
    track, train, law = fold_branch.problem(0)
    for c, dip in zip(fold_branch.solutions_at(525.0), dips):
        polished = rt.solve(track, train.replace(speed=525.0), law, harmonics=25, initial=c)
        t = np.linspace(0.0, polished.period, 512, endpoint=False)
        assert polished.converged and abs(polished.sleeper_displacement(t).min() - dip) < 2e-5


def test_a_ramp_state_is_matched_to_its_crossing_and_the_branch_plots_its_stability(fold_branch):
    dips, before = sp.branch_dips_at(fold_branch, 525.0)
    ramp = rt.SpeedRamp(np.array([525.0, 525.0]), np.array([dips[3] + 1e-7, np.nan]),
                        np.zeros(2), np.array([True, False]), np.array([30, 80]), np.zeros(2),
                        (np.zeros(1), np.zeros(1)))
    assert ramp_on_branch(ramp, fold_branch)[0][0] == before[3]
    assert ramp_on_branch(ramp, fold_branch)[1] is None
    stable = np.arange(len(fold_branch)) < 50
    marked = dataclasses.replace(fold_branch, stable=stable, checks={10: None, 80: None})
    fig = plot_branch(marked, ramps={"rising": ramp})
    lines = {line.get_gid(): line for line in fig.axes[0].lines}
    solid = np.isfinite(lines["branch-stable"].get_ydata()).sum()
    dotted = np.isfinite(lines["branch-unstable"].get_ydata()).sum()
    assert (solid, dotted) == (51, len(fold_branch) - 50)   # they share the point at the change
    assert len(lines["checked"].get_xdata()) == 2 and "ramp-0" in lines
    plt.close("all")
