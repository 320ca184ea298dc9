"""Floquet verdicts on either side of |mu| = 1, against the linearised ring (issue 27).

On the fold track of chapter 10 the plain solution loses its stability
between 585 and 595 m/s: its dominant multiplier crosses the unit circle as
a complex pair, 0.969 then 1.023.  The time-domain ring linearised about the
same orbit (`rt.ring_multipliers`, coarse, its step error extrapolated) is an
independent method; a verdict that moved the threshold (stable up to
|mu| = 1.05, say) would call the 595 m/s state stable against the ring's
growing disturbance.
"""

import numpy as np
import pytest

import railtrack as rt

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000)


@pytest.mark.parametrize("speed, stable", [(585.0, True), (595.0, False)])
def test_the_verdict_near_the_unit_circle_is_the_rings(speed, stable):
    solution = rt.solve(FOLD_TRACK, rt.Train.paper(speed=speed), FOLD_LAW, harmonics=25,
                        stability="off")
    assert solution.converged
    hill = rt.floquet(solution)
    coarse, fine = (abs(rt.ring_multipliers(solution, elements_per_span=2,
                                            steps_per_period=steps).dominant)
                    for steps in (300, 600))
    ring = (4 * fine - coarse) / 3                        # Newmark: error ~ dt^2
    assert abs(abs(hill.dominant) - ring) < 2e-3
    assert 0.02 < abs(ring - 1) < 0.04                    # near the circle, either side
    assert (ring < 1) == stable
    assert hill.stable == stable and hill.kind == "complex"
    assert np.isfinite(hill.dominant)


def test_the_kind_of_the_dominant_multiplier_is_the_rings():
    # At 400 m/s the dominant pair sits at 2.44 rad, 0.7 rad off the negative
    # real axis: the ring's multiplier has the same argument, so "complex" it is
    solution = rt.solve(FOLD_TRACK, rt.Train.paper(speed=400.0), FOLD_LAW, harmonics=25,
                        stability="off")
    hill = rt.floquet(solution)
    ring = rt.ring_multipliers(solution, elements_per_span=2, steps_per_period=600).dominant
    assert abs(abs(np.angle(ring)) - abs(np.angle(hill.dominant))) < 0.02
    assert 0.5 < abs(np.angle(ring)) < np.pi - 0.5
    assert hill.kind == "complex" and hill.stable
