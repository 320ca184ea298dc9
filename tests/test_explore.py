"""railtrack.plotting.explorer: the classroom explorer (sliders -> solve -> three panels).

Oracles: `rt.solve` called directly on the same case built by hand from the
presets (Track.paper, Train.*, the foundation laws' .paper()); the bilinear
law with e = 1, which is the linear law; the Solution's own histories and
rail displacement for what the panels draw; the widget's state after a
slider changes.
"""

import importlib
import sys

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
# The module itself (railtrack.explore is the function that calls it).
ex = importlib.import_module("railtrack.plotting.explorer")


def _same(a: rt.Solution, b: rt.Solution) -> float:
    """Largest |w_a - w_b| over one period, relative to the peak |w_b|."""
    assert a.harmonics == b.harmonics
    t = np.linspace(0.0, b.period, 800, endpoint=False)
    wa, wb = a.sleeper_displacement(t), b.sleeper_displacement(t)
    return float(np.max(np.abs(wa - wb)) / np.max(np.abs(wb)))


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.mark.parametrize("values, foundation", [
    ({}, rt.LinearFoundation.paper()),
    ({"law": "bilinear", "ratio": 0.5}, rt.BilinearFoundation.paper(ratio=0.5)),
    ({"law": "bilinear", "ratio": 0.0}, rt.BilinearFoundation.paper(ratio=0.0)),
    ({"law": "cubic", "epsilon": 0.8}, rt.CubicFoundation.paper(epsilon=0.8)),
])
def test_paper_cases_equal_a_direct_solve(values, foundation):
    state = ex.explorer_state(**values)
    direct = rt.solve(rt.Track.paper(), rt.Train.paper(), foundation, harmonics="auto")
    assert state.error is None and state.solution.converged
    assert np.max(np.abs(state.solution.coefficients - direct.coefficients)) < 1e-15
    assert _same(state.solution, direct) < 1e-12


def test_cubic_paper_case_has_the_readme_peak():
    s = ex.solve_case(law="cubic", epsilon=0.8)
    t = np.linspace(0.0, s.period, 4000, endpoint=False)
    assert s.sleeper_displacement(t).min() * 1e3 == pytest.approx(-0.857, abs=1e-3)


def test_units_of_the_sliders_become_si():
    track, train, law = ex.case_inputs(speed=30.0, pad_damping=250.0, foundation_damping=50.0,
                                       foundation_stiffness=35.0, law="bilinear", ratio=0.25,
                                       train="freight_wagon")
    assert track == rt.Track.paper(pad_damping=2.5e5)
    assert train == rt.Train.freight_wagon(speed=30.0)
    assert law == rt.BilinearFoundation(35e6, 0.25 * 35e6, 5e4)
    _, coach, cubic = ex.case_inputs(law="cubic", epsilon=1.5, train="passenger_coach")
    assert coach == rt.Train.passenger_coach(speed=45.0)
    assert cubic == rt.CubicFoundation(20e6, 2e13, 1.5, 2e5)
    assert ex.DEFAULTS == dict(speed=45.0, pad_damping=1000.0, foundation_damping=200.0,
                               foundation_stiffness=20.0, law="linear", ratio=0.5, epsilon=0.8,
                               train="paper")


def test_other_trains_equal_a_direct_solve():
    state = ex.explorer_state(train="passenger_coach", speed=60.0, foundation_stiffness=40.0)
    direct = rt.solve(rt.Track.paper(), rt.Train.passenger_coach(speed=60.0),
                      rt.LinearFoundation(40e6, 2e5))
    assert state.error is None and _same(state.solution, direct) < 1e-12


def test_bilinear_with_e_equal_one_is_the_linear_law():
    for speed in (20.0, 45.0, 90.0):
        bilinear = ex.solve_case(law="bilinear", ratio=1.0, speed=speed)
        linear = ex.solve_case(law="linear", speed=speed)
        assert bilinear.converged and _same(bilinear, linear) < 1e-10


def test_figure_has_three_labelled_panels_that_show_the_solution():
    state = ex.explorer_state(law="cubic", epsilon=0.8)
    fig = ex.explorer_figure(state)
    axes = fig.axes
    assert len(axes) == 3
    assert "[ms]" in axes[0].get_xlabel() and "[mm]" in axes[0].get_ylabel()
    assert "[ms]" in axes[1].get_xlabel() and "[kN]" in axes[1].get_ylabel()
    assert "[m]" in axes[2].get_xlabel() and "[mm]" in axes[2].get_ylabel()
    s = state.solution
    (w,) = [line for line in axes[0].lines if line.get_gid() == "sleeper"]
    t = np.asarray(w.get_xdata()) / 1e3
    assert t.min() == 0.0 and 0.99 * s.period < t.max() < s.period          # one period, in ms
    assert np.allclose(w.get_ydata(), s.sleeper_displacement(t) * 1e3, rtol=0, atol=1e-12)
    (load,) = [line for line in axes[1].lines if line.get_gid() == "rail_seat"]
    assert np.allclose(load.get_ydata(), s.rail_seat_load(t) / 1e3, rtol=0, atol=1e-9)
    (rail,) = [line for line in axes[2].lines if line.get_gid() == "rail"]
    x, wr = np.asarray(rail.get_xdata()), np.asarray(rail.get_ydata())
    at_zero = np.argmin(np.abs(x))
    assert x[at_zero] == pytest.approx(0.0, abs=1e-9)
    assert wr[at_zero] == pytest.approx(s.rail_displacement(0.0, 0.0) * 1e3, abs=1e-9)
    title = fig._suptitle.get_text()
    assert "cubic ε = 0.8" in title and f"m = {s.harmonics}" in title


def test_figure_of_a_bare_solution():
    s = rt.solve(rt.Track.paper(), rt.Train.paper(speed=30.0), rt.LinearFoundation.paper())
    fig = ex.explorer_figure(s)
    assert "18 m wagon, 30 m/s" in fig._suptitle.get_text()
    assert len(fig.axes[0].lines) > 0


@pytest.mark.parametrize("values, words", [
    ({"speed": -5.0}, "speed"),
    ({"foundation_stiffness": 0.0}, "stiffness"),
    ({"law": "quadratic"}, "law must be in"),
    ({"colour": "red"}, "colour"),
])
def test_bad_input_is_reported_in_the_figure(values, words):
    state = ex.explorer_state(**values)                 # does not raise
    assert state.solution is None and words in state.error
    fig = ex.explorer_figure(state)
    assert "NOT DRAWN" in fig._suptitle.get_text() and words in fig._suptitle.get_text()
    assert all(len(ax.lines) == 0 for ax in fig.axes)   # nothing drawn
    assert "[mm]" in fig.axes[0].get_ylabel()            # but still labelled


def test_non_convergence_is_reported_not_drawn():
    values = dict(law="bilinear", ratio=0.0, speed=120.0, foundation_stiffness=1.0,
                  pad_damping=0.0, foundation_damping=0.0)
    direct = rt.solve(*ex.case_inputs(**values))
    assert not direct.converged                          # the case really fails
    state = ex.explorer_state(**values)
    assert state.error.startswith("not converged")
    fig = ex.explorer_figure(state)
    assert "not converged" in fig._suptitle.get_text()
    assert all(len(ax.lines) == 0 for ax in fig.axes)
    assert all(len(ax.lines) == 0 for ax in ex.explorer_figure(direct).axes)


# --- the widget -----------------------------------------------------------------------------

def test_missing_ipywidgets_names_the_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "ipywidgets", None)
    with pytest.raises(ImportError, match="pip install ipywidgets"):
        ex.explore()


@pytest.fixture
def panel():
    pytest.importorskip("ipywidgets")
    return ex.explore()


def _shown_title(panel) -> str:
    (output,) = panel.output.outputs
    assert output["data"]["image/png"]                   # a figure is shown
    return output["data"]["text/plain"]


def test_widget_has_the_named_controls(panel):
    import ipywidgets

    assert list(panel.controls) == ["train", "speed", "pad_damping", "foundation_stiffness",
                                    "foundation_damping", "law", "ratio", "epsilon"]
    units = dict(speed="[m/s]", pad_damping="[kN s/m]", foundation_damping="[kN s/m]",
                 foundation_stiffness="[MN/m]", ratio="e", epsilon="ε")
    for name, unit in units.items():
        slider = panel.controls[name]
        assert isinstance(slider, ipywidgets.FloatSlider) and unit in slider.description
        assert slider.continuous_update is False and slider.value == ex.DEFAULTS[name]
    assert set(panel.controls["law"].options) >= {(text, key) for key, text in ex.LAWS.items()}
    assert [key for _, key in panel.controls["train"].options] == list(ex.TRAINS)
    assert panel.output in panel.children
    assert "45 m/s" in _shown_title(panel) and panel.state.error is None


def test_speed_change_redraws_with_the_new_speed(panel):
    panel.controls["speed"].value = 60.0
    assert panel.state.values["speed"] == 60.0
    assert float(panel.state.solution.train.speed) == 60.0
    direct = rt.solve(rt.Track.paper(), rt.Train.paper(speed=60.0), rt.LinearFoundation.paper())
    assert _same(panel.state.solution, direct) < 1e-12
    assert "60 m/s" in _shown_title(panel) and "45 m/s" not in _shown_title(panel)


def test_law_and_train_choices_redraw_and_enable_their_slider(panel):
    assert panel.controls["ratio"].disabled and panel.controls["epsilon"].disabled
    panel.controls["law"].value = "bilinear"
    assert not panel.controls["ratio"].disabled and panel.controls["epsilon"].disabled
    panel.controls["ratio"].value = 0.25
    assert panel.state.solution.foundation == rt.BilinearFoundation.paper(ratio=0.25)
    panel.controls["train"].value = "freight_wagon"
    assert panel.state.solution.train == rt.Train.freight_wagon(speed=45.0)
    assert "freight wagon" in _shown_title(panel) and "bilinear e = 0.25" in _shown_title(panel)


def test_negative_speed_from_the_widget_is_shown_not_raised(panel):
    panel.controls["speed"].min = -10.0
    panel.controls["speed"].value = -5.0                 # the callback must not raise
    assert panel.state.solution is None and "speed" in panel.state.error
    assert "NOT DRAWN" in _shown_title(panel)


def test_unexpected_failure_in_the_callback_is_shown_not_raised(panel, monkeypatch):
    def broken(**values):
        raise RuntimeError("solver exploded")

    monkeypatch.setattr(ex, "solve_case", broken)
    panel.controls["foundation_damping"].value = 300.0
    assert "RuntimeError: solver exploded" in panel.state.error
    assert "solver exploded" in _shown_title(panel)


def test_unknown_initial_setting_is_refused():
    pytest.importorskip("ipywidgets")
    with pytest.raises(TypeError, match="colour"):
        ex.explore(colour="red")
    assert ex.explore(speed=30.0, law="cubic").state.values["speed"] == 30.0


def test_the_speed_slider_reaches_the_resonance_of_a_lightly_damped_track():
    # eta1 = 30 kN s/m, eta2 = 20 kN s/m: eq. (23) peaks near 365 m/s at about
    # 2.5 times the static dip (chapter 10); the slider must get there.
    assert ex.CONTROLS["speed"][2] >= 700.0
    light = {"pad_damping": 30.0, "foundation_damping": 20.0}
    slow = ex.explorer_state(speed=5.0, **light)
    peak = ex.explorer_state(speed=365.0, **light)
    assert slow.error is None and peak.error is None
    ratio = peak.solution.one_period(2000)[1].min() / slow.solution.one_period(2000)[1].min()
    assert ratio == pytest.approx(2.48, abs=0.03)
