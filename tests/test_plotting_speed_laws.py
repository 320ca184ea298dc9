"""railtrack.plotting.book.speed_laws: speed curves of the nonlinear laws, secant stiffness, figure.

Oracles: a bilinear law with e = 1 is the linear law, and both match eq. (23);
the secant stiffness of a linear law is its k2 and of a bilinear law lies
between k2- and k2+; the mean foundation force equals the mean wheel load per
sleeper, 2 Q L / H, whatever the law (static balance of the period means);
hardening moves the peak up in speed, loss of contact moves the uplift peak down.
"""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import speed_laws as sl  # noqa: E402

TRACK, WAGON = rt.Track.paper(pad_damping=30e3), rt.Train.paper()
SPEEDS = np.linspace(300.0, 460.0, 161)
MEAN_LOAD = 2 * WAGON.wheel_load * TRACK.sleeper_spacing / WAGON.wagon_length   # N per sleeper


@pytest.fixture(scope="module")
def curves():
    laws = sl.foundation_laws(ratios=(1.0, 0.5, 0.0))
    return laws, sl.law_curves(TRACK, WAGON, laws, SPEEDS)


def test_names_of_the_laws():
    assert list(sl.foundation_laws()) == ["linear", "bilinear e = 0.5", "bilinear e = 0.25",
                                          "tensionless", "cubic"]


def test_bilinear_with_equal_stiffnesses_is_the_linear_law_and_eq_23(curves):
    _, c = curves
    for key in ("lowest", "highest", "mean", "seat_load"):
        np.testing.assert_allclose(c["bilinear e = 1"][key], c["linear"][key], rtol=1e-9)
    low, high = rt.sweep_extremes(TRACK, WAGON, rt.LinearFoundation(20e6, 20e3), SPEEDS)
    scale = np.abs(low).max()                       # m = 30 and 256 samples against m = 60
    np.testing.assert_allclose(c["linear"]["lowest"], low, rtol=0, atol=1e-4 * scale)
    np.testing.assert_allclose(c["linear"]["highest"], high, rtol=0, atol=1e-4 * scale)


def test_linear_mean_is_the_static_deflection_under_the_mean_load(curves):
    _, c = curves
    np.testing.assert_allclose(c["linear"]["mean"], -MEAN_LOAD / 20e6, rtol=1e-9)


@pytest.mark.parametrize("name", ["bilinear e = 0.5", "tensionless", "cubic"])
def test_mean_foundation_force_carries_the_mean_load(curves, name):
    laws, _ = curves
    s = rt.solve(TRACK, WAGON.replace(speed=370.0), laws[name], harmonics=30)
    t = np.linspace(0.0, s.period, 4096, endpoint=False)
    assert s.foundation_force(t).mean() == pytest.approx(MEAN_LOAD, rel=1e-4)


def test_secant_stiffness_of_linear_and_bilinear_laws(curves):
    laws, _ = curves
    linear = rt.solve(TRACK, WAGON.replace(speed=360.0), laws["linear"], harmonics=30)
    k, lifted, mean = sl.secant_stiffness(linear)
    assert k == pytest.approx(20e6, rel=1e-10) and mean == pytest.approx(-MEAN_LOAD / 20e6)
    assert 0.0 < lifted < 1.0
    half = rt.solve(TRACK, WAGON.replace(speed=360.0), laws["bilinear e = 0.5"], harmonics=30)
    k_half, lifted_half, mean_half = sl.secant_stiffness(half)
    assert 10e6 < k_half < 20e6 and mean_half > mean


def test_loss_of_contact_and_hardening_move_the_peaks(curves):
    laws, c = curves
    lin, half, free = (sl.law_peaks(SPEEDS, c[n])
                       for n in ("linear", "bilinear e = 0.5", "tensionless"))
    assert half["uplift"][0] < lin["uplift"][0] - 5 and half["uplift"][1] > lin["uplift"][1]
    assert half["dip"][1] < lin["dip"][1] and free["uplift"][1] > 2 * lin["uplift"][1]
    cubic = sl.law_curves(TRACK, WAGON, {"cubic": sl.foundation_laws()["cubic"]},
                          np.linspace(380.0, 480.0, 101))["cubic"]
    v_cubic, w_cubic = sl.law_peaks(np.linspace(380.0, 480.0, 101), cubic)["dip"]
    assert v_cubic > lin["dip"][0] + 30 and w_cubic < lin["dip"][1]


def test_law_peaks_of_a_parabola():
    v = np.linspace(0.0, 10.0, 11)
    curve = dict(lowest=(v - 4.3) ** 2 - 1.0, highest=1.0 - (v - 6.2) ** 2, seat_load=v)
    peaks = sl.law_peaks(v, curve)
    assert peaks["dip"][0] == pytest.approx(4.3) and peaks["uplift"][0] == pytest.approx(6.2)
    assert peaks["seat_load"] == (10.0, 10.0)


def test_plot_has_two_panels_in_mm_over_m_per_s(curves):
    _, c = curves
    fig = sl.plot_law_curves(SPEEDS, {n: c[n] for n in ("linear", "tensionless")}, title="t")
    top, bottom = fig.axes
    assert "mm" in top.get_ylabel() and "mm" in bottom.get_ylabel()
    assert "m/s" in bottom.get_xlabel()
    assert top.lines[0].get_gid() == "linear: dip"
    assert bottom.lines[2].get_gid() == "tensionless: uplift"
    np.testing.assert_allclose(top.lines[0].get_ydata(), -c["linear"]["lowest"] * 1e3)
    plt.close("all")
