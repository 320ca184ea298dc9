"""railtrack.plotting.book.model: the tables and figures of book chapters 1–3.

The tables must show the library's own numbers in the units they state, and
each figure must plot what the library computes (not a copy or a rescaled
guess of it).
"""

import dataclasses

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import railtrack as rt  # noqa: E402
from railtrack.plotting.book import model  # noqa: E402

PASSAGE = rt.Passage.paper()


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _line(fig, gid):
    lines = [line for ax in fig.axes for line in ax.get_lines() if line.get_gid() == gid]
    assert len(lines) == 1, f"expected one line with gid {gid!r}, found {len(lines)}"
    return lines[0]


def test_table1_values_are_track_fields_in_stated_units():
    units = {"pad_stiffness": ("MN/m", 1e6), "rail_bending_stiffness": ("MN·m²", 1e6),
             "wheel_load": ("kN", 1e3), "pad_damping": ("MN·s/m", 1e6), "speed": ("m/s", 1.0)}
    rows = model.table1_rows(PASSAGE)
    # every field of the track, and of the train with its two axles as the paper's D and Q
    train_fields = {f.name for f in dataclasses.fields(rt.Train)} - {"axle_positions", "axle_loads"}
    expected = ({f.name for f in dataclasses.fields(rt.Track)} | train_fields
                | {"wheel_spacing", "wheel_load"})
    assert {r["field"] for r in rows} == expected
    for row in rows:
        assert row["value"] * row["scale"] == pytest.approx(getattr(PASSAGE, row["field"]), rel=1e-15)
        if row["field"] in units:
            assert (row["unit"], row["scale"]) == units[row["field"]]
    # The printed values of the paper's Table 1, in its units.
    printed = {r["field"]: r["value"] for r in rows}
    assert printed["pad_stiffness"] == 220 and printed["rail_bending_stiffness"] == 6.3
    assert printed["wheel_load"] == 75 and printed["pad_damping"] == 1.0


def test_table1_markdown_follows_the_track():
    text = model.table1(PASSAGE.replace(speed=30.0, pad_stiffness=150e6))
    assert "| Train speed | $v$ | 30 | m/s |" in text
    assert "| Pad stiffness | $k_1$ | 150 | MN/m |" in text
    assert len(text.splitlines()) == 2 + len(model.table1_rows(PASSAGE))


def test_foundation_table_units():
    rows = model.foundation_rows(rt.LinearFoundation.paper(), rt.BilinearFoundation.paper(0.5),
                                 rt.CubicFoundation.paper(0.8))
    for row in rows:
        assert row["value"] * row["scale"] == pytest.approx(row["si"], rel=1e-15)
    k3 = next(r for r in rows if r["symbol"] == "$k_3$")
    assert k3["value"] == pytest.approx(20.0) and k3["unit"] == "kN/mm³"   # Section 4.3
    tension = next(r for r in rows if r["symbol"].startswith("$k_2^-"))
    assert tension["value"] == pytest.approx(10.0) and tension["unit"] == "MN/m"


@pytest.mark.parametrize("sleepers, observed, back", [(9, 6, 3), (5, 3, 1), (12, 8, 2)])
def test_schematic_counts(sleepers, observed, back):
    fig = model.draw_track_schematic(PASSAGE, sleepers=sleepers, observed=observed,
                                     back_wheel=back)
    patches = fig.axes[0].patches
    count = lambda gid: sum(p.get_gid() == gid for p in patches)  # noqa: E731
    assert count("sleeper") == sleepers
    assert count("foundation") == sleepers
    assert count("wheel") == 2
    assert count("next-wheel") == 1
    # the front wheel is above the observed sleeper (t = 0 convention)
    wheels = sorted(p.center[0] for p in patches if p.get_gid() == "wheel")
    sleeper_x = sorted(p.get_x() + p.get_width() / 2 for p in patches if p.get_gid() == "sleeper")
    assert wheels[1] == pytest.approx(sleeper_x[observed])
    assert wheels[0] == pytest.approx(sleeper_x[back])


def test_schematic_rejects_bad_layout():
    with pytest.raises(ValueError):
        model.draw_track_schematic(PASSAGE, sleepers=5, observed=2, back_wheel=3)


def test_receptance_plot_data_is_rail_receptance():
    omega = np.geomspace(0.2, 3000.0, 500)
    fig = model.plot_receptance(PASSAGE, omega, harmonics=10)
    line = _line(fig, "eta_E")
    np.testing.assert_array_equal(line.get_xdata(), omega)
    expected = np.abs(rt.rail_receptance(PASSAGE, omega)) * model.RECEPTANCE_UNIT
    np.testing.assert_allclose(line.get_ydata(), expected, rtol=1e-14)
    marks = _line(fig, "harmonics")
    np.testing.assert_allclose(marks.get_xdata(), PASSAGE.fundamental_frequency * np.arange(1, 11))
    # mm/kN: 1 m/N is 1e6 mm/kN
    assert model.RECEPTANCE_UNIT == 1e6


def test_pole_frequencies_satisfy_the_pole_condition():
    poles = model.receptance_pole_frequencies(PASSAGE, 5000.0)
    assert poles[0] == pytest.approx(model.critical_frequency(PASSAGE))
    assert poles[0] == pytest.approx(6.2493, rel=1e-4)
    kb = rt.equations.receptance.bending_wavenumber(PASSAGE, poles)
    L, v = PASSAGE.sleeper_spacing, PASSAGE.speed
    np.testing.assert_allclose(np.cos(kb * L), np.cos(poles * L / v), atol=1e-9)
    # no pole missed: cos(k_b L) - cos(omega L / v) changes sign only at the listed poles
    omega = np.linspace(1.0, 5000.0, 400_001)
    kb = rt.equations.receptance.bending_wavenumber(PASSAGE, omega)
    gap = np.cos(kb * L) - np.cos(omega * L / v)
    crossings = np.count_nonzero(np.diff(np.sign(gap)) != 0)
    assert crossings == len(poles)


def test_coupling_plot_data_is_rail_coupling():
    omega = np.geomspace(0.5, 2000.0, 300)
    fig = model.plot_rail_coupling(PASSAGE, omega)
    P = rt.rail_coupling(PASSAGE, omega)
    np.testing.assert_allclose(_line(fig, "P").get_ydata(), np.abs(P), rtol=1e-14)
    np.testing.assert_allclose(_line(fig, "phase").get_ydata(), np.degrees(np.angle(P)),
                               rtol=1e-14)


def test_rail_and_sleeper_plot_in_mm():
    solution = rt.solve(PASSAGE.track, PASSAGE.train, rt.LinearFoundation.paper(), method="analytic")
    fig = model.plot_rail_and_sleeper(solution, samples=200)
    rail, sleeper = _line(fig, "rail"), _line(fig, "sleeper")
    t = rail.get_xdata()
    assert t[0] == 0.0 and t[-1] == pytest.approx(PASSAGE.period)
    np.testing.assert_allclose(rail.get_ydata(), 1e3 * solution.rail_displacement(t), rtol=1e-12)
    np.testing.assert_allclose(sleeper.get_ydata(), 1e3 * solution.sleeper_displacement(t),
                               rtol=1e-12)
    mean = _line(fig, "mean-compression").get_ydata()[0]
    assert mean == pytest.approx(1e3 * 2 * 75e3 * 0.6 / (18 * 220e6))


def test_receptance_check_table_rows():
    text = model.receptance_check_table(PASSAGE, [5.0, 50.0])
    lines = text.splitlines()
    assert len(lines) == 4
    closed = float(lines[3].split("|")[2])
    assert closed == pytest.approx(rt.rail_receptance(PASSAGE, 50.0) * 1e6, rel=1e-8)


def test_notation_table_is_complete_and_lists_each_symbol_once():
    from railtrack.plotting.book.tables import notation_table

    rows = notation_table().splitlines()[2:]
    symbols = [row.split("|")[1].strip() for row in rows]
    assert len(symbols) == len(set(symbols))
    text = " ".join(symbols)
    for needed in (r"\beta", r"\omega_0", "$e$", r"\varepsilon", "N_0", r"\mathcal{F}_{nk}",
                   "k_2,", r"\eta_2", "k_3", "k_2^+", "$g(w, w')$", "$D$", r"\ell_j"):
        assert needed in text, needed
