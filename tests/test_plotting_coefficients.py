"""The figures of chapters 4 and 5 show the library's numbers.

Each test finds a data series by its gid and compares it with an
independent call of the library (or a closed form), so a plot that drew
the wrong quantity, the wrong units or the wrong solve would fail.
"""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.solvers.fixed_point import contraction_factors  # noqa: E402
from railtrack.equations.harmonic_balance import (  # noqa: E402
    harmonic_system,
    nonlinear_coefficients,
    synthesize,
)
from railtrack.plotting.book import coefficients as pc  # noqa: E402

PASSAGE = rt.Passage.paper()


def _line(fig, gid):
    lines = [line for ax in fig.axes for line in ax.get_lines() if line.get_gid() == gid]
    assert len(lines) == 1, f"expected one line with gid {gid!r}, found {len(lines)}"
    return lines[0]


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def test_dirichlet_kernel_equals_closed_form():
    x = np.linspace(0.1, 6.0, 50)  # avoid the removable 0/0 at x = 0
    for J in (0, 1, 4):
        closed = np.sin((2 * J + 1) * x / 2) / np.sin(x / 2)
        np.testing.assert_allclose(pc.dirichlet_kernel(x, J), closed, rtol=1e-10, atol=1e-12)
    fig = pc.plot_dirichlet_kernel(orders=(3,), points=101)
    line = _line(fig, "kernel-3")
    np.testing.assert_allclose(line.get_ydata(), pc.dirichlet_kernel(2 * np.pi * line.get_xdata(), 3))


def test_spectra_plot_the_library_coefficients():
    m = 15
    fig = pc.plot_load_spectra(PASSAGE, m)
    omega = PASSAGE.fundamental_frequency * np.arange(m + 1)
    P = _line(fig, "P-harmonics")
    F = _line(fig, "F-harmonics")
    np.testing.assert_array_equal(P.get_xdata(), np.arange(m + 1))
    np.testing.assert_allclose(P.get_ydata(), np.abs(rt.rail_coupling(PASSAGE, omega)) / 1e6, rtol=1e-12)
    np.testing.assert_allclose(F.get_ydata(), np.abs(rt.load_coefficients(PASSAGE, omega)), rtol=1e-12)
    # F_0 = 2QL/(MH) = 50 m/s^2 is the first point
    assert F.get_ydata()[0] == pytest.approx(50.0, rel=1e-12)
    # the cancelling harmonics: omega_n D / v an odd multiple of pi, D/H = 1/6
    np.testing.assert_array_equal(_line(fig, "F-vanishing").get_xdata(), [3, 9, 15])


def test_vanishing_harmonics_follow_the_wheel_spacing():
    # D/H = 1/4: omega_n D/v = pi n / 2 is an odd multiple of pi for n = 2, 6, 10
    passage = rt.Passage(rt.Track.paper(), rt.Train.paper(wheel_spacing=4.5))
    np.testing.assert_array_equal(pc.vanishing_harmonics(passage, 12), [2, 6, 10])


def test_table_lists_every_harmonic_with_rounded_values():
    table = pc.load_spectrum_table(PASSAGE, 15).splitlines()
    assert len(table) == 2 + 16
    assert table[2].startswith("| 0 | 0.0 | 2.2000 | 0.0000 | 50 | 0.0 |")
    assert sum("wheels cancel" in row for row in table) == 3


def test_aft_plot_shows_the_samples_and_the_harmonics():
    solution = rt.solve(PASSAGE.track, PASSAGE.train, rt.CubicFoundation.paper(0.8), 15)
    fig = pc.plot_aft(solution, samples=128)
    system = harmonic_system(PASSAGE, solution.foundation, 15, 128)
    c = solution.coefficients[15:]
    w, v = synthesize(system, c)
    samples = _line(fig, "w-samples")
    np.testing.assert_allclose(samples.get_xdata(), np.arange(128) * PASSAGE.period / 128)
    np.testing.assert_allclose(samples.get_ydata(), w * 1e3, rtol=1e-12)  # mm
    g = solution.foundation.force(w, v) / PASSAGE.sleeper_mass
    np.testing.assert_allclose(_line(fig, "g-samples").get_ydata(), g, rtol=1e-12)
    kept = _line(fig, "G-kept")
    np.testing.assert_allclose(kept.get_ydata(), np.abs(nonlinear_coefficients(system, c)), rtol=1e-12)
    # the series line is the solution's own w(t), in mm
    series = _line(fig, "w-series")
    np.testing.assert_allclose(series.get_ydata(), solution.sleeper_displacement(series.get_xdata()) * 1e3)


def test_contraction_plot_shows_both_branches():
    system = harmonic_system(PASSAGE, rt.LinearFoundation.paper(), 15)
    fig = pc.plot_contraction_factors(system)
    np.testing.assert_allclose(_line(fig, "first-branch").get_ydata(), contraction_factors(system, 15))
    second = _line(fig, "second-branch").get_ydata()
    np.testing.assert_allclose(second, contraction_factors(system, -1))
    # n = 0 in the second branch would be 1 + k2/k1, in the first 1 - k2/k1
    assert second[0] == pytest.approx(1 + 20e6 / 220e6, rel=1e-12)


def test_convergence_plot_has_one_line_per_method_with_the_solve_history():
    laws = {"linear": rt.LinearFoundation.paper(), "cubic": rt.CubicFoundation.paper(0.8)}
    histories = pc.convergence_histories(PASSAGE, laws)
    fig = pc.plot_convergence(histories)
    visible = [ax for ax in fig.axes if ax.get_visible()]
    assert [ax.get_title() for ax in visible] == ["linear", "cubic"]
    for ax, (name, law) in zip(visible, laws.items()):
        assert ax.get_yscale() == "log"
        lines = {line.get_gid(): line for line in ax.get_lines() if line.get_gid()}
        assert sorted(lines) == ["fixed-point", "newton"]
        expected = {
            "fixed-point": rt.solve(PASSAGE.track, PASSAGE.train, law, 15, method="fixed-point",
                                    max_iterations=3000),
            "newton": rt.solve(PASSAGE.track, PASSAGE.train, law, 15, method="newton"),
        }
        for method, solution in expected.items():
            np.testing.assert_array_equal(lines[method].get_ydata(), solution.residual_history)
            np.testing.assert_array_equal(lines[method].get_xdata(), np.arange(len(solution.residual_history)))
        # the fixed point starts from c = 0, where the residual is ||F|| / ||F|| = 1
        assert lines["fixed-point"].get_ydata()[0] == pytest.approx(1.0)
        assert lines["fixed-point"].get_ydata()[-1] <= 1e-10


def test_convergence_table_reports_the_solves():
    laws = {"linear": rt.LinearFoundation.paper()}
    histories = pc.convergence_histories(PASSAGE, laws)
    rows = pc.convergence_table(histories).splitlines()
    fixed = histories["linear"]["fixed-point"]
    cells = [cell.strip() for cell in rows[2].strip("|").split("|")]
    assert cells[:4] == ["linear", str(fixed.iterations), "0.909", "0"]
    # the linear fixed point's measured factor is 1 - k2/k1
    assert float(cells[2]) == pytest.approx(1 - 20 / 220, abs=1e-3)


def test_change_is_a_fraction_of_the_error():
    rows = pc.change_and_error_table(PASSAGE, rt.LinearFoundation.paper(), iterations=(15, 30)).splitlines()
    assert len(rows) == 4
    for row in rows[2:]:
        k, change, error, ratio = (float(cell) for cell in row.strip("|").split("|"))
        assert ratio == pytest.approx(20 / 220, rel=1e-3)  # (1 - rho_0) = k2 / k1
        assert error == pytest.approx(0.25 * (1 - 20 / 220) ** k, rel=1e-3)  # mm, from c_0 = -0.25 mm
