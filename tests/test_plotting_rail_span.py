"""railtrack.plotting.book.rail_span: the rail along one span.

Oracles: a made-up solution whose rail_displacement is a known function of
(t, x), so the sampled profiles and the plotted lines must be exactly that
function in mm; and, on a real solve, the profile's ends equal the rail above
the sleepers at x = 0 and x = L (the latter a delayed copy, L/v earlier).
"""

import types

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import rail_span as rs  # noqa: E402
from railtrack.plotting.style import MM  # noqa: E402

PASSAGE = rt.Passage.paper()


def fake_solution():
    def w(t, x=0.0):
        return -1e-3 * np.cos(np.asarray(x)) * (1.0 + np.asarray(t))
    return types.SimpleNamespace(passage=PASSAGE, rail_displacement=w)


def test_profiles_sample_the_field_at_the_wheel_instants():
    x, w = rs.rail_span_profiles(fake_solution(), [0.0, 0.3], points=11)
    assert np.allclose(x, np.linspace(0.0, PASSAGE.sleeper_spacing, 11))
    t = np.array([0.0, 0.3 / PASSAGE.speed])[:, None]
    assert np.allclose(w, -1e-3 * np.cos(x) * (1.0 + t))


def test_plot_draws_one_line_per_position_in_mm_against_m():
    positions = [-0.3, 0.0, 0.3]
    fig = rs.plot_rail_span(fake_solution(), positions, points=21)
    ax = fig.axes[0]
    lines = [line for line in ax.get_lines() if line.get_gid()]
    assert len(lines) == 3
    x, w = rs.rail_span_profiles(fake_solution(), positions, points=21)
    for line, values in zip(lines, w):
        assert np.allclose(line.get_xdata(), x)
        assert np.allclose(line.get_ydata(), values * MM)
    assert "[mm]" in ax.get_ylabel() and "[m]" in ax.get_xlabel()
    plt.close(fig)


def test_profile_ends_are_the_rail_above_the_two_sleepers():
    sol = rt.solve(PASSAGE.track, PASSAGE.train, rt.LinearFoundation.paper(), 15)
    positions = [0.0, 0.3]
    x, w = rs.rail_span_profiles(sol, positions)
    t = np.array(positions) / PASSAGE.speed
    assert np.allclose(w[:, 0], sol.rail_displacement(t), rtol=0, atol=1e-15)
    later = sol.rail_displacement(t - PASSAGE.sleeper_spacing / PASSAGE.speed)
    assert np.allclose(w[:, -1], later, rtol=0, atol=1e-15)
    assert w[0, 0] < 0 and w[0, 0] == w[0].min()   # deepest under the wheel above the sleeper
