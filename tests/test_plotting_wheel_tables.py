"""The tables of chapter 14 ("The wheel on the rail") print the library's numbers.

Each table is read back and its cells compared with an independent reading of
the same solution: the contact force sampled densely over one period (not the
solution's own `extremes`), the rail-seat load at those samples, and, for the
P2 table, dynamic increments worked out by hand.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.plotting.book import wheel_tables as wt

TRACK, LAW, Q = rt.Track.paper(), rt.LinearFoundation(20e6, 0.2e6), 75e3
WHEEL = rt.Wheel(600.0)


def _rows(table):
    lines = table.splitlines()
    return [[c.strip() for c in line.strip("|").split("|")] for line in lines[2:]]


def _per_wheel(cell):
    return np.array([float(x) for x in cell.split("/")])


@pytest.fixture(scope="module")
def smooth():
    return {"45 m/s": rt.solve(TRACK, rt.Train.paper(speed=45.0), LAW, 60, wheel=WHEEL)}


@pytest.fixture(scope="module")
def dipped():
    dip = rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.3)
    # 120 harmonics leave ~1 % of Q of truncation error (the chapter keeps 300): the
    # table is compared with this same solution, so the warning is expected here
    with pytest.warns(rt.TruncationWarning):
        solution = rt.solve(TRACK, rt.Train.paper(speed=45.0), LAW, 120, wheel=WHEEL,
                            profile=dip)
    return {"45 m/s": solution}


def test_smooth_rail_row_is_the_densely_sampled_force(smooth):
    (row,) = _rows(wt.smooth_rail_table(smooth))
    s = smooth["45 m/s"]
    force = s.contact_force(s.one_period(16384)[0]) * 1e-3  # kN, one row per wheel
    assert row[0] == "45 m/s" and int(row[1]) == s.harmonics == 60
    assert np.allclose(_per_wheel(row[2]), force.max(axis=1), atol=0.01)
    assert np.allclose(_per_wheel(row[3]), force.min(axis=1), atol=0.01)
    assert abs(float(row[4]) - (force.max(axis=1) - force.min(axis=1)).max()) < 0.01
    # the swing is a real one: the sleepers pass, the wheel feels them
    assert float(row[4]) > 0.1


def test_dipped_weld_row_is_the_densely_sampled_force(dipped):
    (row,) = _rows(wt.dipped_weld_table(dipped))
    s = dipped["45 m/s"]
    t = s.one_period(16384)[0]
    force = s.contact_force(t) * 1e-3
    x = np.mod(s.wheel_position(t), 18.0)
    assert np.allclose(_per_wheel(row[1]), force.max(axis=1), atol=0.06)
    assert np.allclose(_per_wheel(row[3]), force.min(axis=1), atol=0.06)
    assert abs(float(row[2]) - x[0][force[0].argmax()]) < 0.01
    assert abs(float(row[4]) - x[0][force[0].argmin()]) < 0.01
    assert abs(float(row[5]) - force.max() / (Q * 1e-3)) < 0.006
    assert abs(float(row[6]) - s.rail_seat_load(t).max() * 1e-3) < 0.06
    # the dip loads the wheel: largest force past the lowest point, above Q
    assert 9.3 < float(row[2]) < 9.8 and float(row[5]) > 1.05


def test_p2_table_puts_the_dynamic_increments_side_by_side():
    speeds = np.array([20.0, 40.0])
    table = wt.p2_table(speeds, {"1 m dip": np.array([80e3, 90e3]), "short": [81e3, 91e3]},
                        {"fitted": np.array([85e3, 95e3]), "British": [86e3, 99e3]}, Q)
    header = table.splitlines()[0]
    assert "HB, 1 m dip [kN]" in header and "P2, British [kN]" in header
    rows = _rows(table)
    # by hand: (80 - 75) / (85 - 75) and (90 - 75) / (95 - 75)
    assert [r[-1] for r in rows] == ["0.50", "0.75"]
    assert rows[1][:5] == ["40", "90.0", "91.0", "95.0", "99.0"]
