"""The wheel's parameters and the rail-top profile (issue 20, first block).

Truths: the static compression carries the wheel load exactly; the contact
stiffness is the derivative of the force (central differences); the cosine
dip has its depth at the centre, nothing outside, repeats with its period,
and its slope is the derivative of its profile.
"""

import numpy as np
import pytest

from railtrack.model.profile import CosineDip, smooth_rail
from railtrack.model.wheel import Wheel


def test_the_static_compression_carries_the_wheel_load():
    wheel = Wheel(600.0, 9.4e10)
    delta = wheel.static_compression(75e3)
    assert float(wheel.contact_force(delta)) == pytest.approx(75e3, rel=1e-12)
    assert float(wheel.contact_force(-1e-6)) == 0.0           # no tension: loss of contact


def test_the_contact_stiffness_is_the_derivative_of_the_force():
    wheel = Wheel(600.0, 9.4e10)
    delta, h = np.array([1e-6, 5e-5, 1e-4]), 1e-10
    numeric = (wheel.contact_force(delta + h) - wheel.contact_force(delta - h)) / (2 * h)
    np.testing.assert_allclose(wheel.contact_stiffness(delta), numeric, rtol=1e-6)
    assert float(wheel.contact_stiffness(-1e-6)) == 0.0


def test_the_cosine_dip():
    dip = CosineDip(0.5e-3, 1.0, 18.0, centre=9.0)
    assert float(dip(9.0)) == pytest.approx(-0.5e-3)
    assert float(dip(9.0 + 18.0 * 3)) == pytest.approx(-0.5e-3)
    assert float(dip(9.5)) == 0.0 and float(dip(3.0)) == 0.0
    x, h = np.linspace(8.4, 9.6, 13), 1e-7
    np.testing.assert_allclose(dip.slope(x), (dip(x + h) - dip(x - h)) / (2 * h), atol=1e-8)
    assert np.all(smooth_rail(x) == 0.0)


@pytest.mark.parametrize("bad", [dict(unsprung_mass=0.0),
                                 dict(unsprung_mass=600.0, hertz_constant=-1.0),
                                 dict(unsprung_mass=600.0, primary_stiffness=-1.0)])
def test_bad_wheels_are_named(bad):
    with pytest.raises(ValueError):
        Wheel(**bad)


def test_a_dip_longer_than_its_period_is_refused():
    with pytest.raises(ValueError, match="shorter"):
        CosineDip(1e-3, 20.0, 18.0)
