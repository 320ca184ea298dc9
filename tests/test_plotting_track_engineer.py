"""railtrack.plotting.book.track_engineer: bowl, rail-seat load and bending moment.

Oracles: the static Winkler beam (Hetényi 1946), whose deflection under one
load P is -(P lambda / 2k) e^{-lambda|x|}(cos lambda x + sin lambda x),
lambda = (k / 4EI)^{1/4}, k = k_s / L, k_s = k1 k2 / (k1 + k2); its moment is
EI w'' (checked by finite differences) and the bed under it carries P in all;
the mean rail-seat load and foundation force equal sum Q_j L / H; the
quasi-static solve on the smeared track approaches the Winkler bowl; the
mirror symmetry of the undamped response; Richardson's limit of a 1/m error.
"""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import track_engineer as te  # noqa: E402
from railtrack.plotting.style import MM  # noqa: E402

TRACK, LAW = rt.Track.paper(), rt.LinearFoundation.paper()


@pytest.fixture(scope="module")
def paper():
    return rt.solve(TRACK, rt.Train.paper(), LAW)


def test_support_stiffness_and_lambda_by_hand():
    k_s = 220e6 * 20e6 / 240e6
    k, lam = te.winkler_parameters(TRACK, LAW)
    assert te.support_stiffness(TRACK, LAW) == pytest.approx(k_s, rel=1e-14)
    assert k == pytest.approx(k_s / 0.6, rel=1e-14)
    assert lam == pytest.approx((k_s / 0.6 / (4 * 6.3e6)) ** 0.25, rel=1e-14)
    bilinear = rt.BilinearFoundation(20e6, 0.0, 2e5)         # compression stiffness counts
    assert te.support_stiffness(TRACK, bilinear) == pytest.approx(k_s, rel=1e-14)


def test_winkler_bowl_closed_form_symmetry_and_equilibrium():
    k, lam = te.winkler_parameters(TRACK, LAW)
    x = np.linspace(-20.0, 20.0, 40001)
    w = te.winkler_bowl(TRACK, LAW, x, [0.0], [75e3])
    r = lam * np.abs(x)
    assert np.allclose(w, -(75e3 * lam / (2 * k)) * np.exp(-r) * (np.cos(r) + np.sin(r)),
                       rtol=1e-12, atol=0)
    assert np.allclose(w, w[::-1], rtol=0, atol=1e-15)                  # symmetric
    assert w[20000] == pytest.approx(-75e3 * lam / (2 * k), rel=1e-12)
    bed = -k * np.trapezoid(w, x)                                        # the bed carries P
    assert bed == pytest.approx(75e3, rel=1e-6)
    # largest uplift where w' = -(P lambda^2 / k) e^{-r} sin r vanishes: r = pi
    assert abs(x[np.argmax(w)]) == pytest.approx(np.pi / lam, abs=1e-3)
    assert w.max() == pytest.approx(75e3 * lam / (2 * k) * np.exp(-np.pi), rel=1e-6)


def test_winkler_moment_is_ei_times_curvature():
    x = np.linspace(0.05, 6.0, 3001)                                    # away from the kink at 0
    h = x[1] - x[0]
    w = te.winkler_bowl(TRACK, LAW, x, [0.0, -3.0], [75e3, 50e3])
    curvature = (w[2:] - 2 * w[1:-1] + w[:-2]) / h**2
    moment = te.winkler_moment(TRACK, LAW, x[1:-1], [0.0, -3.0], [75e3, 50e3])
    assert np.allclose(TRACK.rail_bending_stiffness * curvature, moment, rtol=0, atol=2.0)
    _, lam = te.winkler_parameters(TRACK, LAW)
    assert te.winkler_moment(TRACK, LAW, [0.0], [0.0], [75e3])[0] == pytest.approx(75e3 / (4 * lam))


def test_wheel_positions_of_the_paper_train():
    positions, loads = te.wheel_positions(rt.Train.paper(), front=1.0, wagons=1)
    assert sorted(positions) == pytest.approx([-20.0, -17.0, -2.0, 1.0, 16.0, 19.0])
    assert np.all(loads == 75e3)


def test_quasi_static_bowl_approaches_winkler():
    slow = rt.solve(TRACK, rt.Train.paper(speed=1.0), LAW)
    x = np.linspace(-9.0, 9.0, 361)
    bowl = slow.deflection_bowl(0.0, x)
    static = te.static_bowl(TRACK, rt.Train.paper(), LAW, x)
    peak = -static.min()
    # discrete supports and the pad's own deflection: within 7 % of the peak, not exact
    assert np.abs(bowl.rail - static).max() < 0.07 * peak
    assert abs(bowl.rail.min() - static.min()) < 0.05 * peak


def test_mean_loads_equal_sum_q_l_over_h(paper):
    mean = 2 * 75e3 * 0.6 / 18.0
    p = te.load_peaks(paper, 1000)
    assert p["seat_mean"] == pytest.approx(mean, rel=1e-9)
    assert p["foundation_mean"] == pytest.approx(mean, rel=1e-9)
    assert p["seat_max"] > 4 * mean and p["seat_min"] < 0                  # the pad pulls at times
    coach = rt.solve(TRACK, rt.Train.passenger_coach(45.0), LAW)
    assert te.load_peaks(coach, 1000)["seat_mean"] == pytest.approx(
        coach.train.wagon_load * 0.6 / 26.4, rel=1e-9)


def test_load_table_rows_are_the_peaks_over_q(paper):
    rows = te.load_distribution_table({("paper", "linear"): paper}, 75e3, 1000)
    p = te.load_peaks(paper, 1000)
    assert rows[0]["seat_max"] == pytest.approx(p["seat_max"] / 75e3)
    assert rows[0]["foundation_min"] == pytest.approx(p["foundation_min"] / 75e3)
    assert rows[0]["m"] == paper.harmonics
    text = te.table_markdown(rows)
    assert text.count("\n") == 2 and f"{p['seat_max'] / 75e3:.3f}" in text


def test_undamped_single_axle_is_symmetric_about_the_wheel():
    track = TRACK.replace(pad_damping=0.0)
    s = rt.solve(track, rt.Train.single_axle(75e3, 20.0), rt.LinearFoundation(20e6, 0.0))
    x = np.linspace(-6.0, 6.0, 241)
    bowl = s.deflection_bowl(0.0, x)
    assert np.allclose(bowl.rail, bowl.rail[::-1], rtol=0, atol=1e-6 * abs(bowl.rail.min()))
    ahead, behind = te.bowl_uplift(bowl)
    assert ahead == pytest.approx(behind, rel=1e-5) and ahead > 0


def test_wheel_moments_are_the_moment_at_the_wheel_instants(paper):
    moments = te.wheel_moments(paper, 0.3)
    t = np.array([0.3, 3.3]) / 45.0
    assert np.allclose(moments, paper.rail_bending_moment(t, 0.3))
    peaks = te.moment_peaks(paper, 500)
    assert peaks["midspan_sagging"] == moments.max() and peaks["sleeper_hogging"] < 0


def test_richardson_removes_a_one_over_m_error():
    assert te.richardson(100, 3.0 - 5.0 / 100, 400, 3.0 - 5.0 / 400) == pytest.approx(3.0)


def test_damping_ratio_and_self_weight_by_hand():
    assert te.pad_damping_ratio(TRACK) == pytest.approx(1e6 / (2 * np.sqrt(220e6 * 100.0)))
    assert te.self_weight_per_seat(TRACK) == pytest.approx(9.81 * (100.0 + 36.0))
    assert te.self_weight_per_seat(TRACK, 50.0) == pytest.approx(9.81 * 86.0)


def test_figures_draw_the_data_in_mm_and_kn(paper):
    x = np.linspace(-6.0, 6.0, 121)
    bowl = paper.deflection_bowl(0.0, x)
    fig = te.plot_bowls({"paper": (bowl, te.static_bowl(TRACK, paper.train, LAW, x))})
    ax = fig.axes[0]
    rail = next(line for line in ax.lines if line.get_gid() == "rail")
    assert np.allclose(rail.get_ydata(), bowl.rail * MM)
    sleepers = next(line for line in ax.lines if line.get_gid() == "sleepers")
    assert np.allclose(sleepers.get_xdata(), bowl.sleeper_positions)
    plt.close(fig)
    h = te.load_histories(paper, 200)
    fig = te.plot_load_histories({"paper": h}, 75e3)
    assert np.allclose(fig.axes[0].lines[0].get_ydata(), h.rail_seat / 1e3)
    plt.close(fig)
    times = np.linspace(0.0, paper.period, 4, endpoint=False)
    bowls = paper.deflection_bowl(times, x)
    anim = te.animate_bowl(bowls, times)
    anim._func(2)
    line = anim._fig.axes[0].lines[0]
    assert np.allclose(line.get_ydata(), bowls.rail[2] * MM)
    html = te.offline_jshtml(anim)                   # self-contained: frames inline, nothing fetched
    assert html.count("data:image/png;base64") == 4
    assert "http" not in html and "<link" not in html and 'class="fa' not in html
    plt.close(anim._fig)
    plt.close(te.plot_bowl_frame(bowls, 1, times[1]))
    plt.close(te.plot_moments({"paper": paper}, 100))
