"""Data functions of `railtrack.plotting.book.verification` (book chapter 9).

Coarse FE settings (2 elements per span, 600 steps per period) keep the file
fast; their error against eq. (23) was measured at 4.1e-8 m (linear law),
against a 1.13e-3 m peak.  Oracles: eq. (23) summed here as a real cosine
series; the mean -2 Q L / (H k2) of a linear law (harmonic 0 of eq. 17);
the fixed point's mean after k steps from zero, c_0 (1 - q^k) with
q = 1 - k2 / k1 (Section 4.1); exact power laws for `observed_orders`.
"""

import dataclasses
import types

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import verification as vf  # noqa: E402
from railtrack.plotting.style import MM  # noqa: E402

PASSAGE = rt.Passage.paper()
LINEAR = rt.LinearFoundation.paper()
COARSE = dict(elements_per_span=2, steps_per_period=600)


@pytest.fixture(scope="module")
def linear():
    return vf.compare_case(PASSAGE, LINEAR, "linear", **COARSE)


@pytest.fixture(scope="module")
def tensionless():
    return vf.compare_case(PASSAGE, rt.BilinearFoundation.paper(0.0), "bilinear, e = 0", **COARSE)


def eq23(times, harmonics):
    c = rt.analytic_coefficients(PASSAGE, LINEAR, harmonics)[harmonics:]
    phase = PASSAGE.fundamental_frequency * np.outer(times, np.arange(1, harmonics + 1))
    return c[0].real + 2.0 * (np.cos(phase) @ c[1:].real - np.sin(phase) @ c[1:].imag)


def test_compare_case_curves_on_the_fe_grid(linear):
    np.testing.assert_allclose(linear.times, np.arange(600) * PASSAGE.period / 600, rtol=0, atol=1e-15)
    np.testing.assert_allclose(linear.curves["reference"], eq23(linear.times, 200), rtol=0, atol=1e-15)
    np.testing.assert_allclose(linear.curves["newton"], eq23(linear.times, 15), rtol=0, atol=1e-15)
    static = -2 * PASSAGE.wheel_load * PASSAGE.sleeper_spacing / (PASSAGE.wagon_length * LINEAR.stiffness)
    for key in ("newton", "reference", "fe"):
        assert linear.means[key] == pytest.approx(static, rel=1e-9)
    # k = 100 steps of eq. (21) from zero leave c_0 q^k of the mean.
    q = 1.0 - LINEAR.stiffness / PASSAGE.pad_stiffness
    assert linear.means["paper"] == pytest.approx(static * (1 - q**100), rel=1e-9)


def test_errors_separate_fe_truncation_and_iteration(linear):
    # measured 4.1e-8 m (coarse FE), 5.9e-6 m (m = 15), 5.6e-8 m (k = 100)
    assert linear.error("fe") < 1e-7
    assert 5e-6 < linear.error("newton") < 7e-6
    assert linear.error("paper", "newton") < 1e-7
    assert linear.error("newton") == pytest.approx(np.max(np.abs(eq23(linear.times, 15) - eq23(linear.times, 200))))
    assert linear.peak == pytest.approx(-linear.curves["reference"].min())
    np.testing.assert_allclose(vf.fe_against_harmonics(linear, [15, 200]),
                               [linear.error("fe", "newton"), linear.error("fe")], rtol=1e-9)
    assert linear.stats("fe") == (linear.curves["fe"].min(), linear.curves["fe"].max(), linear.means["fe"])


def test_lag_mismatch_detects_a_wrong_delay(linear):
    assert linear.lag_mismatch() < 1e-6  # the period tolerance of simulate_time_domain
    record = linear.fe.sleeper_displacements
    steps, sleepers = record.shape
    wrong = np.stack([np.roll(record[:, 0], -i * steps // sleepers) for i in range(sleepers)], 1)
    fake = types.SimpleNamespace(sleeper_displacements=wrong)
    assert vf.CaseComparison("x", linear.times, {}, {}, fake, 0.0).lag_mismatch() > 1e-2
    odd = types.SimpleNamespace(sleeper_displacements=record[:-1])
    with pytest.raises(ValueError, match="multiple"):
        vf.CaseComparison("x", linear.times, {}, {}, odd, 0.0).lag_mismatch()


def test_comparison_table_rounds_the_stats(linear, tensionless):
    lines = vf.comparison_table([linear, tensionless]).splitlines()
    assert len(lines) == 2 + 2 * 3
    cells = [[cell.strip() for cell in line.split("|")[1:-1]] for line in lines[2:]]
    assert cells[0][0] == "linear" and cells[3][0] == "bilinear, e = 0"
    assert [c[1] for c in cells] == ["min", "max", "mean"] * 2
    for row, (case, i) in zip(cells, [(linear, 0), (linear, 1), (linear, 2), (tensionless, 0),
                                      (tensionless, 1), (tensionless, 2)]):
        expected = [f"{case.stats(k)[i] * MM:.4f}" for k in ("newton", "reference", "fe")]
        assert row[2:5] == expected
    assert cells[2][6] == "< 1e-9"  # the m = 15 mean of a linear law is exact


def test_truncation_table_names_the_larger_error(linear, tensionless):
    # The paper's k = 100 leaves the tensionless case far from converged
    # (measured 6.6e-5 m, 11 times the m = 15 truncation error).
    assert tensionless.error("paper", "newton") > 5 * tensionless.error("newton")
    rows = vf.truncation_table([linear, tensionless]).splitlines()[2:]
    assert rows[0].endswith("| truncation |") and rows[1].endswith("| iteration |")
    assert f"{linear.peak * MM:.4f}" in rows[0]


def test_observed_orders_of_exact_power_laws():
    sizes = np.array([1.0, 0.5, 0.25])
    np.testing.assert_allclose(vf.observed_orders(sizes, 3 * sizes**2), [2, 2], rtol=1e-12)
    np.testing.assert_allclose(vf.observed_orders(1 / np.array([1, 2, 4]), [8.0, 1.0, 0.125]), [3, 3])


def test_convergence_study_coarse():
    study = vf.convergence_study(PASSAGE, LINEAR, elements=(1, 2), steps=(300, 600), fixed_steps=600,
                                 fixed_elements=2, reference_harmonics=400)
    assert study.element_errors[1] == study.step_errors[1]  # the shared (2, 600) run
    assert np.all(np.diff(study.element_errors) < 0) and np.all(np.diff(study.step_errors) < 0)
    assert 1e-10 < study.reference_error < 1e-9  # measured 5.6e-10 m (m = 200 against 400)
    table = vf.convergence_table(study)
    assert f"{study.step_errors[0] * MM:.2e}" in table and table.count("\n") == 5
    fig = vf.plot_convergence(study)
    assert len(fig.axes) == 2
    plt.close(fig)


def test_plots_draw_every_case(linear, tensionless):
    fig = vf.plot_comparison([linear, tensionless])
    full = fig.axes[0::2]
    assert [ax.get_title("left") for ax in full] == ["linear", "bilinear, e = 0"]
    assert len(full[0].lines) == 3
    np.testing.assert_allclose(full[1].lines[0].get_ydata(), tensionless.curves["fe"] * MM)
    # the zoom shows the deepest point of the reference, in ms
    zoom = fig.axes[3]
    trough = np.argmin(tensionless.curves["reference"])
    assert zoom.lines[1].get_ydata().min() == tensionless.curves["reference"][trough] * MM
    assert zoom.lines[1].get_xdata()[0] < tensionless.times[trough] * 1e3 < zoom.lines[1].get_xdata()[-1]
    plt.close(fig)
    fig = vf.plot_error_budget([linear, tensionless])
    assert len(fig.axes[0].lines) == 3
    plt.close(fig)
    assert vf.newton_solve_time(PASSAGE, LINEAR, repeats=3) > 0


def test_identical_cases_share_one_row(linear, tensionless):
    copy = dataclasses.replace(linear, label="bilinear, e = 1")
    groups = vf.distinct_cases([linear, tensionless, copy])
    assert [[c.label for c in g] for g in groups] == [["linear", "bilinear, e = 1"], ["bilinear, e = 0"]]
    fig = vf.plot_comparison([linear, tensionless, copy])
    assert len(fig.axes) == 4 and fig.axes[0].get_title("left") == "linear = bilinear, e = 1"
    plt.close(fig)
