"""Data and plots of Figures 3–7 (`railtrack.plotting.book.paper_figures`).

Oracles: eq. (23) for the linear law, evaluated here independently as a
real cosine/sine sum; the geometric error of eq. (21) for the mean, which for
a linear law is exactly (1 - k2/k1)^k after k steps from c = 0 (Section 4.1:
harmonic 0 decouples and its factor is |P_0 - k2/M| / omega_0^2 with
P_0 = omega_0^2 = k1/M); the static balance of harmonic 0 of eq. (17),
mean foundation force = 2QL/H (compression positive) for any law; and the reduction of the
bilinear (e = 1) and cubic (eps = 0) laws to the linear one.
"""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import paper_figures as pf  # noqa: E402
from railtrack.plotting.style import MM  # noqa: E402

PASSAGE = rt.Passage.paper()
LINEAR = rt.LinearFoundation.paper()
PEAK_SCALE = 1.1e-3  # |w| at the peak of the linear response [m], a scale for tolerances


@pytest.fixture(scope="module")
def fig3():
    return pf.figure3_data(iterations=(5, 15, 100, 400))


@pytest.fixture(scope="module")
def fig4():
    return pf.figure4_data()


@pytest.fixture(scope="module")
def fig5():
    return pf.figure5_data()


@pytest.fixture(scope="module")
def fig6():
    return pf.figure6_data()


@pytest.fixture(scope="module")
def fig7():
    return pf.figure7_data()


def eq23_series(times, harmonics=15):
    """w(t) from eq. (23) as c_0 + 2 sum_n Re(c_n e^{i omega_n t}), n = 1..m."""
    c = rt.analytic_coefficients(PASSAGE, LINEAR, harmonics)[harmonics:]
    n = np.arange(1, harmonics + 1)
    phase = PASSAGE.fundamental_frequency * np.outer(times, n)
    return c[0].real + 2.0 * (np.cos(phase) @ c[1:].real - np.sin(phase) @ c[1:].imag)


# ---------------------------------------------------------------- Figure 3

def test_figure3_reference_is_eq23(fig3):
    np.testing.assert_allclose(fig3.reference, eq23_series(fig3.times), rtol=0, atol=1e-15)
    assert fig3.reference_means == pytest.approx(
        -2 * PASSAGE.wheel_load * PASSAGE.sleeper_spacing / (PASSAGE.wagon_length * LINEAR.stiffness),
        rel=1e-13,
    )


def test_figure3_newton_equals_eq23(fig3):
    np.testing.assert_allclose(fig3.extra["Newton"], fig3.reference, rtol=0, atol=1e-12 * PEAK_SCALE)


def test_figure3_fixed_point_approaches_eq23_geometrically(fig3):
    errors = fig3.errors()
    assert np.all(np.diff(errors) < 0), errors
    # k = 400 stops once the residual reaches 1e-10 (at 236 steps), so its
    # error is that of a converged iterate, not of 400 steps.
    longest = fig3.solutions[fig3.values.index(400)]
    assert longest.converged and longest.iterations < 400
    assert errors[fig3.values.index(400)] < 1e-9 * PEAK_SCALE
    # the mean (harmonic 0) after k steps from zero: c0 (1 - q^k), q = 1 - k2/k1
    q = 1 - LINEAR.stiffness / PASSAGE.pad_stiffness
    expected = np.array([q**s.iterations for s in fig3.solutions])
    np.testing.assert_allclose(fig3.mean_errors(), expected, rtol=1e-6, atol=1e-14)


def test_figure3_fifteen_iterations_are_far_from_converged(fig3):
    # the book states these numbers: 24 % short on the mean, ~0.2 mm off at the worst time
    k15 = fig3.values.index(15)
    assert fig3.mean_errors()[k15] == pytest.approx(0.2394, abs=1e-4)
    assert 0.15e-3 < fig3.errors()[k15] < 0.25e-3


# ---------------------------------------------------------------- Figure 4

def test_figure4_converges_in_harmonics(fig4):
    upper, _ = fig4
    errors = dict(zip(upper.values, upper.errors()))
    assert errors[10] > errors[15] > errors[20]
    assert errors[15] < 0.01e-3  # m = 15 within 0.01 mm of Newton at m = 40
    assert errors[5] > 0.1e-3  # too few harmonics are visibly wrong


def test_figure4_converges_in_iterations(fig4):
    _, lower = fig4
    errors = lower.errors()
    assert np.all(np.diff(errors) < 0), errors
    assert errors[-1] < 1e-3 * PEAK_SCALE
    assert lower.values[-1] == 100 and all(s.harmonics == 15 for s in lower.solutions)


# ---------------------------------------------------------------- Figure 5

def test_figure5_e1_is_the_linear_solution(fig5):
    i = fig5.values.index(1.0)
    np.testing.assert_allclose(fig5.reference[i], eq23_series(fig5.times), rtol=0, atol=1e-10 * PEAK_SCALE)
    np.testing.assert_allclose(fig5.displacements[i], fig5.reference[i], rtol=0, atol=1e-4 * PEAK_SCALE)


def test_figure5_uplift_grows_as_tension_stiffness_drops(fig5):
    assert list(fig5.values) == sorted(fig5.values, reverse=True)
    uplift = fig5.reference.max(axis=-1)
    means = fig5.reference_means
    assert np.all(np.diff(uplift) > 0), uplift
    assert np.all(np.diff(means) > 0), means  # mean deflection shrinks
    peaks = fig5.reference.min(axis=-1)
    assert np.ptp(peaks) < 0.01e-3  # the downward peak barely moves


def test_figure5_mean_foundation_force_balances_the_train(fig5):
    # foundation_force is positive in compression: the mean carries the train's weight
    static = 2 * PASSAGE.wheel_load * PASSAGE.sleeper_spacing / PASSAGE.wagon_length
    for solution in fig5.reference_solutions:
        t = np.arange(solution.samples) * PASSAGE.period / solution.samples
        assert solution.foundation_force(t).mean() == pytest.approx(static, rel=1e-8)


# ---------------------------------------------------------------- Figure 6

def test_figure6_converges_in_iterations(fig6):
    errors = fig6.errors()
    assert np.all(np.diff(errors) < 0), errors
    assert errors[fig6.values.index(100)] < 1e-5 * PEAK_SCALE
    # k = 15 is still 9 % of the peak away from the converged curve
    peak = -fig6.reference.min()
    assert 0.08 < errors[fig6.values.index(15)] / peak < 0.10


# ---------------------------------------------------------------- Figure 7

def test_figure7_eps0_is_the_linear_solution(fig7):
    i = fig7.values.index(0.0)
    np.testing.assert_allclose(fig7.reference[i], eq23_series(fig7.times), rtol=0, atol=1e-10 * PEAK_SCALE)


def test_figure7_amplitude_decreases_with_eps(fig7):
    assert list(fig7.values) == sorted(fig7.values)
    assert np.all(np.diff(fig7.reference.min(axis=-1)) > 0)
    assert np.all(np.diff(fig7.reference.max(axis=-1)) < 0)
    assert np.all(np.diff(np.ptp(fig7.reference, axis=-1)) < 0)
    # the fixed-point curves (the paper's) agree with Newton at k = 100
    assert fig7.errors().max() < 1e-4 * PEAK_SCALE


# ---------------------------------------------------------------- Plots and tables

@pytest.mark.parametrize(
    "name, axes, lines",
    [("figure3", 1, 4), ("figure4", 2, 7 + 5), ("figure5", 1, 10), ("figure6", 1, 6), ("figure7", 1, 12)],
)
def test_figures_draw_every_curve_with_units(name, axes, lines):
    fig = getattr(pf, name)()
    try:
        assert len(fig.axes) == axes
        drawn = sum(len([ln for ln in ax.get_lines() if len(ln.get_xdata()) > 2]) for ax in fig.axes)
        assert drawn == lines
        for ax in fig.axes:
            assert "[mm]" in ax.get_ylabel()
            assert ax.get_xlim() == pytest.approx((0.0, PASSAGE.period))
        assert "[s]" in fig.axes[-1].get_xlabel()
        # plotted in mm: the deepest point is about -1 mm, not -1e-3
        low = min(ln.get_ydata().min() for ax in fig.axes for ln in ax.get_lines()
                  if len(ln.get_xdata()) > 2)
        assert -1.5 < low < -0.5
    finally:
        plt.close(fig)


def test_table_lists_every_curve_in_mm(fig7):
    rows = fig7.table().splitlines()
    assert len(rows) == 2 + len(fig7.values)
    first = rows[2].split("|")
    assert float(first[2]) == pytest.approx(fig7.minima()[0] * MM, abs=1e-4)


def test_bad_points_is_rejected():
    with pytest.raises(ValueError, match="points"):
        pf.figure6_data(points=1)


def test_harmonic_convergence_separates_truncation():
    data = pf.harmonic_convergence_data(harmonics=(5, 10, 15, 20), reference_harmonics=40)
    assert all(s.method == "newton" and s.converged for s in data.solutions)
    errors = data.errors()
    assert np.all(np.diff(errors) < 0), errors
    assert errors[data.values.index(15)] < 0.01e-3


def test_reference_table_needs_one_reference_per_curve(fig5, fig6):
    rows = fig5.reference_table().splitlines()
    assert len(rows) == 2 + len(fig5.values)
    assert float(rows[-1].split("|")[3]) == pytest.approx(fig5.reference[-1].max() * MM, abs=1e-4)
    with pytest.raises(ValueError, match="one reference per curve"):
        fig6.reference_table()
