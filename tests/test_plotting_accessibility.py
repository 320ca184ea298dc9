"""No two legend entries of a book figure are told apart by colour alone.

Every figure function of `railtrack.plotting` is built on small (mostly
made-up) inputs, and in each of its axes the labelled lines, the legend
entries, are compared pair by pair:

* two entries of different colours must also differ in line style (dash
  pattern) or marker, so that a reader with a colour-vision deficiency, or
  a grey-scale print, still tells them apart;
* no pair of their colours is a red against a green, nor a pair that a
  normal viewer sees as clearly different (CIE76 distance in CIELAB at
  least 40) but a protanope or deuteranope sees as nearly the same (less
  than 15), simulated with the full-severity matrices of Machado, Oliveira
  and Fernandes (2009) in linear RGB.  Matplotlib's old default blue,
  orange, green and red fail this (orange against green falls from 101 to
  5 for a protanope); the book's Okabe-Ito palette passes it (its worst
  pair, at 18, is bluish green against reddish purple).

A last test checks that every public figure function is covered, so that a
new one cannot slip past.
"""

import colorsys
import importlib
import inspect
import itertools
import pkgutil
import re
import types

import matplotlib

matplotlib.use("Agg")

import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
import railtrack.plotting  # noqa: E402
from railtrack.equations.harmonic_balance import harmonic_system  # noqa: E402
from railtrack.plotting.book import coefficients as pc  # noqa: E402
from railtrack.plotting.book import model as pm  # noqa: E402
from railtrack.plotting.book import paper_figures as pf  # noqa: E402
from railtrack.plotting.book import passage as pp  # noqa: E402
from railtrack.plotting.book import rail_span as rs  # noqa: E402
from railtrack.plotting.book import sleepers as slp  # noqa: E402
from railtrack.plotting.book import wheels as whl  # noqa: E402
from railtrack.plotting.book import speed as sp  # noqa: E402
from railtrack.plotting.branch import plot_branch, plot_multipliers  # noqa: E402
from railtrack.plotting.solution import plot_solution  # noqa: E402
from railtrack.plotting.book import speed_laws as sl  # noqa: E402
from railtrack.plotting.book import track_engineer as te  # noqa: E402
from railtrack.plotting.book import truncation as pt  # noqa: E402
from railtrack.plotting import style  # noqa: E402
from railtrack.plotting.book import verification as vf  # noqa: E402
from railtrack.plotting.style import plot_sweep  # noqa: E402

PASSAGE = rt.Passage.paper()
LINEAR = rt.LinearFoundation.paper()

# ---------------------------------------------------------------- colour vision

_PROTANOPIA = np.array([[0.152286, 1.052583, -0.204868],
                        [0.114503, 0.786281, 0.099216],
                        [-0.003882, -0.048116, 1.051998]])
_DEUTERANOPIA = np.array([[0.367322, 0.860646, -0.227968],
                          [0.280085, 0.672501, 0.047413],
                          [-0.011820, 0.042940, 0.968881]])
_XYZ = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]])


def _linear_rgb(colour) -> np.ndarray:
    c = np.array(mcolors.to_rgb(colour))
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _lab(linear_rgb) -> np.ndarray:
    xyz = _XYZ @ np.clip(linear_rgb, 0.0, 1.0) / (_XYZ @ np.ones(3))
    f = np.where(xyz > (6 / 29) ** 3, np.cbrt(xyz), xyz / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.array([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


def colour_distance(a, b, vision=None) -> float:
    """CIE76 distance between two colours, seen normally or through a 3x3 `vision` matrix."""
    la, lb = _linear_rgb(a), _linear_rgb(b)
    if vision is not None:
        la, lb = vision @ la, vision @ lb
    return float(np.linalg.norm(_lab(la) - _lab(lb)))


def _hue_saturation_value(colour):
    h, s, v = colorsys.rgb_to_hsv(*mcolors.to_rgb(colour))
    return 360.0 * h, s, v


def is_red(colour) -> bool:
    h, s, v = _hue_saturation_value(colour)
    return s >= 0.5 and v >= 0.3 and (h >= 345.0 or h <= 15.0)


def is_green(colour) -> bool:
    h, s, v = _hue_saturation_value(colour)
    return s >= 0.4 and v >= 0.3 and 75.0 <= h <= 155.0


def red_green_confusion(a, b) -> bool:
    """A red against a green, or a pair that protanopes or deuteranopes cannot tell apart."""
    if (is_red(a) and is_green(b)) or (is_green(a) and is_red(b)):
        return True
    seen = min(colour_distance(a, b, _PROTANOPIA), colour_distance(a, b, _DEUTERANOPIA))
    return colour_distance(a, b) >= 40.0 and seen < 15.0


def test_the_colour_checks_catch_the_old_pairs_and_pass_the_book_palette():
    for a, b in (("tab:red", "tab:green"), ("r", "g"), ("tab:orange", "tab:green")):
        assert red_green_confusion(a, b), (a, b)
    assert len(set(style.PALETTE)) == 7
    for a, b in itertools.combinations(style.PALETTE, 2):
        assert not red_green_confusion(a, b), (a, b)


def test_plain_plots_on_a_book_axes_differ_in_colour_and_line_style():
    fig, ax = style.new_figure()
    lines = [ax.plot([0.0, 1.0], [k, k + 1.0], label=f"{k}")[0] for k in range(len(style.PALETTE))]
    assert [mcolors.to_hex(line.get_color()) for line in lines] == [c.lower() for c in style.PALETTE]
    assert colour_only_pairs(fig) == [] and red_green_pairs(fig) == []
    assert len({appearance(line) for line in lines}) == len(lines)


# ---------------------------------------------------------------- line appearance

_NO_MARKER = {None, "", " ", "None", "none"}


def _marker(line):
    marker = line.get_marker()
    return None if marker in _NO_MARKER else str(marker)


def appearance(line) -> tuple:
    """What tells a line apart without its colour: dash pattern and marker."""
    style = line.get_linestyle()
    dashes = None if style in ("None", "none", " ", "") else (style, line._unscaled_dash_pattern)
    return dashes, _marker(line)


def colours(line) -> set:
    """The colours a reader sees on a line: the line's, and its marker's face and edge."""
    found = set()
    if line.get_linestyle() not in ("None", "none", " ", ""):
        found.add(mcolors.to_hex(line.get_color()))
    if _marker(line) is not None:
        for colour in (line.get_markerfacecolor(), line.get_markeredgecolor()):
            if not (isinstance(colour, str) and colour.lower() == "none"):
                found.add(mcolors.to_hex(colour))
    return found


def legend_lines(ax) -> list:
    return [line for line in ax.get_lines() if not line.get_label().startswith("_")]


def colour_only_pairs(fig) -> list:
    """(axes index, label, label) of every pair of legend entries that only colour tells apart."""
    found = []
    for k, ax in enumerate(fig.axes):
        for a, b in itertools.combinations(legend_lines(ax), 2):
            if appearance(a) == appearance(b) and colours(a) != colours(b):
                found.append((k, a.get_label(), b.get_label()))
    return found


def red_green_pairs(fig) -> list:
    """(axes index, label, colour, label, colour) of every red-green pair of legend entries."""
    found = []
    for k, ax in enumerate(fig.axes):
        for a, b in itertools.combinations(legend_lines(ax), 2):
            for ca, cb in itertools.product(colours(a), colours(b)):
                if red_green_confusion(ca, cb):
                    found.append((k, a.get_label(), ca, b.get_label(), cb))
    return found


# ---------------------------------------------------------------- the figures, on small inputs

def _branch(stable):
    """A made-up speed branch with two folds: 300 -> 500 m/s, back to 450, on to 600."""
    values = np.concatenate([np.linspace(300.0, 500.0, 30), np.linspace(495.0, 450.0, 10),
                             np.linspace(455.0, 600.0, 21)])
    dips = -1e-3 * (1.0 + np.linspace(0.0, 2.0, len(values)))
    return types.SimpleNamespace(
        values=values, minimum_displacement=lambda: dips, folds=[types.SimpleNamespace(index=29),
                                                                 types.SimpleNamespace(index=39)],
        stable=None if stable is None else np.arange(len(values)) < 29, checks={10: None, 45: None})


def _floquet_branch():
    """The made-up branch judged by Hill's method: |mu| crosses 1 at the folds and once more."""
    branch = _branch(True)
    size = np.where(branch.stable, 0.8, 1.3)
    size[50:] = 0.9
    changes = [types.SimpleNamespace(value=500.0, index=29, kind="fold", gains=False),
               types.SimpleNamespace(value=452.0, index=40, kind="complex", gains=True)]
    return types.SimpleNamespace(**{**vars(branch), "multipliers": size.astype(complex),
                                    "changes": changes, "stable": size < 1})


def _ramp(speeds):
    speeds = np.asarray(speeds, float)
    converged = np.ones(len(speeds), bool)
    converged[len(speeds) // 2] = False
    return types.SimpleNamespace(speeds=speeds, minimum=-1e-3 * (1.0 + speeds / 300.0),
                                 converged=converged)


def _law_curves():
    v = np.linspace(300.0, 460.0, 41)
    return v, {name: dict(lowest=-1e-3 * (1.0 + k + np.exp(-((v - 370.0 - 5 * k) / 20.0) ** 2)),
                          highest=1e-4 * (1.0 + k + np.exp(-((v - 360.0 + 5 * k) / 20.0) ** 2)),
                          seat_load=-40e3 * (1.0 + np.exp(-((v - 370.0) / 20.0) ** 2)))
               for k, name in enumerate(sl.foundation_laws())}


def _case(label, scale):
    t = np.linspace(0.0, PASSAGE.period, 200, endpoint=False)
    w = -scale * 1e-3 * (1.0 + np.cos(2 * np.pi * t / PASSAGE.period))
    curves = {"reference": w, "newton": 1.001 * w, "paper": 1.002 * w, "fe": 0.999 * w}
    return vf.CaseComparison(label, t, curves, {k: float(c.mean()) for k, c in curves.items()},
                             None, 0.0)


def _histories():
    def run(r):
        return types.SimpleNamespace(residual_history=np.array(r), iterations=len(r) - 1)
    return {name: {"fixed-point": run(np.geomspace(1.0, 1e-11, 40)), "newton": run([1.0, 1e-4, 1e-12])}
            for name in ("linear", "cubic", "bilinear")}


def _bowl(shift=0.0):
    x = np.linspace(-4.0, 20.0, 121)
    sleepers = np.arange(-4.0, 20.0, 0.6)
    return types.SimpleNamespace(x=x, rail=-1e-3 * np.exp(-((x - shift) / 2.0) ** 2),
                                 sleeper_positions=sleepers,
                                 sleepers=-0.9e-3 * np.exp(-((sleepers - shift) / 2.0) ** 2),
                                 wheel_positions=np.array([shift, shift - 3.0]))


def _bowls():
    frames = [_bowl(s) for s in (0.0, 1.0, 2.0)]
    return types.SimpleNamespace(x=frames[0].x, rail=np.array([b.rail for b in frames]),
                                 sleeper_positions=frames[0].sleeper_positions,
                                 sleepers=np.array([b.sleepers for b in frames]),
                                 wheel_positions=[b.wheel_positions for b in frames])


def _extremes(scale):
    return pp.PassageExtremes(-scale * 1e-3, -1.1 * scale * 1e-3, 0.02e-3 * scale,
                              0.03e-3 * scale, 1e-3, 2e-3)


def _solution():
    return rt.solve(PASSAGE.track, PASSAGE.train, LINEAR, 15, method="analytic")


def _paper_and_ballasted():
    return {"paper's": _solution(),
            "ballasted": rt.solve(rt.Track.ballasted(), PASSAGE.train, rt.LinearFoundation.ballasted(),
                                  "auto", method="analytic")}


def _cells():
    sound = rt.SleeperCell.identical(PASSAGE, LINEAR, 4)
    hanging = sound.with_sleeper(2, foundation=rt.GapFoundation(1e-3, 20e6, 0.2e6))
    return {name: rt.solve(PASSAGE.track, PASSAGE.train, cell, 10)
            for name, cell in (("sound track", sound), ("gap 1 mm", hanging))}


def _support(variation):
    return rt.random_support(PASSAGE.track, PASSAGE.train, LINEAR, sleepers=4,
                             variation=variation, draws=5, harmonics=10)


def _wheels():
    return {f"{v:.0f} m/s": rt.solve(PASSAGE.track, rt.Train.paper(speed=v), LINEAR, 60,
                                     wheel=rt.Wheel(600.0))
            for v in (45.0, 100.0)}


FIGURES = {
    "wheels.plot_contact_along_track": lambda: whl.plot_contact_along_track(
        _wheels(), window=(6.0, 7.8), samples=512, dip=rt.CosineDip(0.5e-3, 1.0, 18.0, centre=7.0)),
    "wheels.plot_dip_against_speed": lambda: whl.plot_dip_against_speed(
        np.array([20.0, 40.0]), {"a": np.array([80e3, 90e3]), "b": np.array([82e3, np.nan])},
        75e3),
    "wheels.plot_loss_of_contact": lambda: whl.plot_loss_of_contact(
        _wheels()["45 m/s"], (6.0, 7.8), samples=512,
        dip=rt.CosineDip(0.5e-3, 1.0, 18.0, centre=7.0)),
    "wheels.plot_sleeper_passing": lambda: whl.plot_sleeper_passing(
        {"a": (np.array([20.0, 40.0]), np.array([300.0, 900.0]), 35.0),
         "b": (np.array([20.0, 40.0]), np.array([200.0, 400.0]), None)}),
    "wheels.plot_rail_receptances": lambda: whl.plot_rail_receptances(
        np.linspace(20.0, 2000.0, 50), {"a": np.linspace(1, 2, 50) * 1e-9,
                                        "b": np.linspace(2, 1, 50) * 1e-9}, {"mark": 1000.0}),
    "sleepers.plot_bowl": lambda: slp.plot_bowl(_cells(), 2, reach=2, points=61),
    "sleepers.plot_seat_histories": lambda: slp.plot_seat_histories(_cells(), (1, 2)),
    "sleepers.plot_random_support": lambda: slp.plot_random_support(
        {0.2: _support(0.2), 0.4: _support(0.4)}, (25e3, 18e3)),
    "style.plot_sweep": lambda: plot_sweep(
        np.linspace(0.25, 9.0, 11), {"deepest": np.linspace(1, 2, 11), "highest": np.linspace(0, 1, 11)},
        xlabel="D [m]", ylabel="w [mm]", marks={"1 % limit": 2.0, "paper, D = 3 m": 3.0}),
    "speed.plot_speed_curves": lambda: sp.plot_speed_curves(
        np.linspace(5.0, 700.0, 140),
        {name: -1e-3 * (1.0 + k * np.exp(-((np.linspace(5.0, 700.0, 140) - 350.0) / 50.0) ** 2))
         for k, name in enumerate(("paper's track", "lightly damped", "ballasted"))},
        marks={"smeared": 340.0, "Winkler": 500.0, "bound": 600.0}, title="t"),
    "branch.plot_branch (no stability)": lambda: plot_branch(
        _branch(None), linear=(np.linspace(300.0, 600.0, 31), -1e-3 * np.ones(31))),
    "branch.plot_branch (stability and ramps)": lambda: plot_branch(
        _branch(True), linear=(np.linspace(300.0, 600.0, 31), -1e-3 * np.ones(31)),
        ramps={"ring, rising speed": _ramp(np.linspace(440.0, 700.0, 14)),
               "ring, falling speed": _ramp(np.linspace(700.0, 440.0, 14))}),
    "branch.plot_branch (stability by Floquet)": lambda: plot_branch(_floquet_branch()),
    "branch.plot_multipliers": lambda: plot_multipliers(
        _floquet_branch(), scanned=np.full(61, 1.1)),
    "speed.plot_seat_load_histogram": lambda: sp.plot_seat_load_histogram(
        np.random.default_rng(0).normal(0.37, 0.01, 500)),
    "speed_laws.plot_law_curves": lambda: sl.plot_law_curves(*_law_curves(), title="t"),
    "paper_figures.figure3": pf.figure3,
    "paper_figures.figure4": pf.figure4,
    "paper_figures.figure5": pf.figure5,
    "paper_figures.figure6": pf.figure6,
    "paper_figures.figure7": pf.figure7,
    "verification.plot_comparison": lambda: vf.plot_comparison(
        [_case("linear", 1.0), _case("bilinear, e = 0", 1.2), _case("cubic, ε = 0.8", 0.8)]),
    "verification.plot_error_budget": lambda: vf.plot_error_budget(
        [_case("linear", 1.0), _case("bilinear, e = 0", 1.2)]),
    "verification.plot_convergence": lambda: vf.plot_convergence(vf.ConvergenceStudy(
        (1, 2, 4), np.array([1e-3, 1.2e-4, 1.6e-5]), 4800, (600, 1200, 2400),
        np.array([1e-4, 2.5e-5, 6e-6]), 8, 800, 1e-9)),
    "truncation.plot_truncation": lambda: pt.plot_truncation(pt.TruncationStudy(
        np.array([18.0, 40.0, 80.0]), np.array([30.0, 67.0, 133.0]), np.array([0.01, 0.05, 0.2]),
        np.array([0.012, 0.06, 0.25]), np.array([20, 45, 90]), np.array([5e-4, 6e-4, 7e-4]),
        np.array([6e-4, 7e-4, 8e-4]), np.array([180, 400, 800]), 1e-3)),
    "coefficients.plot_dirichlet_kernel": lambda: pc.plot_dirichlet_kernel(orders=(2, 5, 20), points=301),
    "coefficients.plot_load_spectra": lambda: pc.plot_load_spectra(PASSAGE, 15, points=200),
    "coefficients.plot_aft": lambda: pc.plot_aft(
        rt.solve(PASSAGE.track, PASSAGE.train, rt.CubicFoundation.paper(0.8), 15), samples=128),
    "coefficients.plot_contraction_factors": lambda: pc.plot_contraction_factors(
        harmonic_system(PASSAGE, LINEAR, 15)),
    "coefficients.plot_convergence": lambda: pc.plot_convergence(_histories()),
    "track_engineer.plot_bowls": lambda: te.plot_bowls(
        {"paper's wagon": (_bowl(), -1.1e-3 * np.exp(-(_bowl().x / 2.0) ** 2)), "coach": (_bowl(1.0), None)}),
    "track_engineer.plot_bowl_frame": lambda: te.plot_bowl_frame(_bowls(), 1, 0.2),
    "track_engineer.plot_load_histories": lambda: te.plot_load_histories(
        {name: te.load_histories(s, 200) for name, s in _paper_and_ballasted().items()}, 75e3),
    "track_engineer.plot_moments": lambda: te.plot_moments(_paper_and_ballasted(), 100),
    "passage.plot_passage_study": lambda: pp.plot_passage_study(
        [20.0, 45.0, 80.0], {name: [_extremes(s * k) for s in (1.0, 1.1, 1.3)]
                             for k, name in zip((1.0, 1.2, 1.4), ("paper's damping", "no η2", "undamped"))}),
    "rail_span.plot_rail_span": lambda: rs.plot_rail_span(_solution(), [-0.3, 0.0, 0.15, 0.3, 0.6], points=41),
    "model.plot_receptance": lambda: pm.plot_receptance(PASSAGE, np.geomspace(0.1, 5000.0, 400)),
    "model.plot_rail_coupling": lambda: pm.plot_rail_coupling(PASSAGE, np.geomspace(0.1, 5000.0, 400)),
    "model.plot_rail_and_sleeper": lambda: pm.plot_rail_and_sleeper(_solution(), samples=100),
    "model.draw_track_schematic": lambda: pm.draw_track_schematic(PASSAGE),
    "solution.plot_solution": lambda: plot_solution(_solution()),
}

# Public functions that draw no figure of their own.
NOT_FIGURES = {
    "solution.draw_bowl": "draws into the axes of plot_bowls, plot_bowl_frame and plot_solution",
    "solution.draw_solution": "draws into the axes of plot_solution and the explorer",
    "track_engineer.animate_bowl": "animates the axes of plot_bowl_frame",
}


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.mark.parametrize("name", FIGURES)
def test_no_two_legend_entries_differ_by_colour_alone(name):
    fig = FIGURES[name]()
    assert colour_only_pairs(fig) == []


@pytest.mark.parametrize("name", FIGURES)
def test_no_red_against_green(name):
    fig = FIGURES[name]()
    assert red_green_pairs(fig) == []


def _qualified(function) -> str:
    return f"{function.__module__}.{function.__name__}"


def test_every_figure_function_is_checked():
    found = set()
    packages = ("railtrack.plotting", "railtrack.plotting.book")
    for package in packages:
        for module in pkgutil.iter_modules(importlib.import_module(package).__path__):
            mod = importlib.import_module(f"{package}.{module.name}")
            for fname, function in inspect.getmembers(mod, inspect.isfunction):
                if re.fullmatch(r"plot_\w+|figure\d|draw_\w+|animate_\w+", fname):
                    found.add(_qualified(function))

    def resolve(name):       # "module.function (variant)" -> where the function is defined
        module, fname = name.split(" ")[0].split(".")
        for package in packages:
            try:
                found_module = importlib.import_module(f"{package}.{module}")
            except ModuleNotFoundError:
                continue
            return _qualified(getattr(found_module, fname))
        raise ModuleNotFoundError(module)

    checked = {resolve(name) for name in FIGURES} | {resolve(name) for name in NOT_FIGURES}
    assert found - checked == set()
