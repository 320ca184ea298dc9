"""The table of the ground's surface flexibility in k (railtrack.equations.ground_table) against
the stiffness-matrix solve at every wavenumber, and its fallback when its check fails."""

import numpy as np
import pytest

import railtrack.equations.ground_table as table
from railtrack.equations.ground_stiffness import surface_flexibility
from railtrack.model.ground import Ground, SoilLayer

SOILS = [Ground.homogeneous(100.0, 0.3, 1800.0, 0.02),
         Ground((SoilLayer(65.0, 0.49, 1500.0, 0.02, thickness=6.0),),
                SoilLayer(200.0, 0.45, 1900.0, 0.02)),
         Ground((SoilLayer(250.0, 0.3, 2000.0, 0.03, thickness=0.5),
                 SoilLayer(60.0, 0.4, 1600.0, 0.03, thickness=4.0)),
                SoilLayer(300.0, 0.3, 2000.0, 0.03))]


@pytest.mark.parametrize("soil", SOILS)
@pytest.mark.parametrize("omega", [0.0, 30.0, 500.0, 4000.0])
def test_the_table_reads_the_flexibility_of_every_wavenumber(soil, omega):
    # 40 000 wavenumbers at random, from the long waves to ten times the slowest surface wave's
    k = np.sort(np.random.default_rng(7).uniform(0.05, 10.0 * max(omega, 50.0) / 50.0, 40000))
    exact = surface_flexibility(soil, k, omega) * k
    ours = table.radial_flexibility(soil, k, omega) * k
    assert np.max(np.abs(ours - exact)) < 3e-7 * np.max(np.abs(exact))


def test_a_table_that_fails_its_check_gives_way_to_every_wavenumber(monkeypatch):
    k = np.linspace(0.1, 60.0, 30000)
    soil = SOILS[1]
    read = table.radial_flexibility(soil, k, 500.0)
    monkeypatch.setattr(table, "_CHECK", 0.0)
    assert np.array_equal(table.radial_flexibility(soil, k, 500.0),
                          surface_flexibility(soil, k, 500.0))
    assert not np.array_equal(read, surface_flexibility(soil, k, 500.0))
