"""The hanging sleeper's law itself, against its closed form (issue 27).

Harmonic balance and the time-domain ring agree on the hanging sleeper
(tests/test_hanging_sleeper.py), but they call the same `GapFoundation`, so
they would agree on a wrong law.  Here the law is checked on its own, by
hand: a sleeper g above its ballast, w positive upward, penetration
p = -(w + g); no force while p <= 0; once in, Hooke's k2 p (pushing up, f < 0)
plus a dashpot eta2 w' whose share grows as min(p / ramp, 1); and the ballast
never pulls.  Then its tangent against finite differences of the force.
"""

import numpy as np
import pytest

import railtrack as rt

GAP, K2, ETA2, RAMP = 1e-3, 20e6, 0.2e6, 0.1e-3


def by_hand(w, v):
    p = -(w + GAP)
    if p <= 0:
        return 0.0
    force = -K2 * p + ETA2 * v * min(p / RAMP, 1.0)
    return min(force, 0.0)


def test_the_force_is_the_closed_form_at_every_state():
    law = rt.GapFoundation(GAP, K2, ETA2, RAMP)
    w = np.array([0.0, -0.5e-3, -1e-3, -1.02e-3, -1.05e-3, -1.1e-3, -1.5e-3, -3e-3, 1e-3])
    v = np.array([-0.2, -0.01, 0.0, 0.01, 0.05, 0.2, 1.0])
    force = law.force(w[:, None], v[None, :])
    expected = np.array([[by_hand(a, b) for b in v] for a in w])
    np.testing.assert_allclose(force, expected, rtol=1e-12, atol=1e-9)


def test_the_force_in_numbers():
    law = rt.GapFoundation(GAP, K2, ETA2, RAMP)
    # 0.5 mm into the ballast at rest: 10 kN up; moving down at 0.1 m/s: 20 kN more
    assert float(law.force(-1.5e-3, 0.0)) == pytest.approx(-10e3, rel=1e-12)
    assert float(law.force(-1.5e-3, -0.1)) == pytest.approx(-30e3, rel=1e-12)
    # half-way into the ramp the dashpot counts half: 50 um in, 1 kN, plus 0.5 x 20 kN
    assert float(law.force(-1.05e-3, -0.1)) == pytest.approx(-11e3, rel=1e-12)
    # leaving fast, the dashpot would pull: the ballast lets go instead
    assert float(law.force(-1.05e-3, 0.1)) == 0.0
    # in the gap nothing at any speed; the force is continuous at first touch
    assert float(law.force(-0.999e-3, -5.0)) == 0.0
    assert abs(float(law.force(-1e-3 - 1e-12, -5.0))) < 0.02


def test_the_tangent_is_the_derivative_of_the_force():
    law = rt.GapFoundation(GAP, K2, ETA2, RAMP)
    rng = np.random.default_rng(2)
    w = -GAP - rng.uniform(5e-6, 3e-4, 40)                 # in contact, in and past the ramp
    v = rng.uniform(-0.3, 0.0, 40)
    stiffness, damping = law.tangent(w, v)
    h = 1e-9
    np.testing.assert_allclose(stiffness, (law.force(w + h, v) - law.force(w - h, v)) / (2 * h),
                               rtol=1e-5)
    np.testing.assert_allclose(damping, (law.force(w, v + 1e-6) - law.force(w, v - 1e-6)) / 2e-6,
                               rtol=1e-5, atol=1e-3)
    free = law.tangent(np.array([-0.5e-3]), np.array([-1.0]))
    assert free[0][0] == 0.0 and free[1][0] == 0.0
