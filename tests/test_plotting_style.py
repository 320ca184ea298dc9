"""railtrack.plotting.style.plot_sweep draws exactly the data it is given."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from railtrack.plotting.style import plot_sweep  # noqa: E402


def test_plot_sweep_draws_each_curve_and_mark():
    x = np.linspace(1.0, 5.0, 9)
    curves = {"square": x**2, "cube": x**3}
    fig = plot_sweep(x, curves, xlabel="x [m]", ylabel="y [mm]", marks={"paper": 3.0}, ylim_bottom=0)
    ax = fig.axes[0]
    lines = {line.get_gid(): line for line in ax.get_lines() if line.get_gid()}
    for label, values in curves.items():
        np.testing.assert_array_equal(lines[label].get_xdata(), x)
        np.testing.assert_array_equal(lines[label].get_ydata(), values)
    verticals = [line for line in ax.get_lines() if line.get_label() == "paper"]
    assert len(verticals) == 1 and verticals[0].get_xdata()[0] == 3.0
    assert ax.get_xlabel() == "x [m]" and ax.get_ylabel() == "y [mm]"
    assert ax.get_ylim()[0] == 0
    plt.close(fig)
