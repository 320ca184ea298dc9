"""The V-shaped dipped joint (issue 32, item 5): its shape, its harmonics, its P1.

Independent truths: the slope integrates to the height; the Fourier
coefficients of the V have a closed form (they fall like 1/n^2, the mark of
the slope's jumps); and the harmonic balance's own truncation estimate must
bound what doubling m actually changes in the peak contact force P1.  The long
convergence study (m up to 4800, the ring at two resolutions) is in
docs/joint_p1.md, not here.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations.wheel_harmonic_balance import profile_harmonics

ANGLE, LENGTH, PERIOD, CENTRE = 10e-3, 1.0, 18.0, 9.3


def closed_form_coefficient(n, angle=ANGLE, length=LENGTH, period=PERIOD):
    """(1/P) int r(s) exp(-i k s) ds of the V centred at s = 0, k = 2 pi n / P.

    With alpha = angle/2 and a = length/2: 2 alpha int_0^a (s - a) cos(k s) ds
    = -2 alpha (1 - cos k a) / k^2.
    """
    k = 2 * np.pi * np.asarray(n, float) / period
    return -angle * (1 - np.cos(k * length / 2)) / (k ** 2 * period)


def test_shape_depth_slopes_and_period():
    joint = rt.DippedJoint(ANGLE, LENGTH, PERIOD, centre=CENTRE)
    assert joint.depth == pytest.approx(ANGLE * LENGTH / 4)
    assert joint(CENTRE) == pytest.approx(-joint.depth)
    assert joint(CENTRE + PERIOD) == pytest.approx(-joint.depth)
    h = 1e-9
    jump = joint.slope(CENTRE + h) - joint.slope(CENTRE - h)
    assert jump == pytest.approx(ANGLE)          # the dip angle 2 alpha
    end = CENTRE + LENGTH / 2
    assert joint.slope(end - h) - joint.slope(end + h) == pytest.approx(ANGLE / 2)
    # the slope integrates to the height, from the level rail to anywhere
    x = np.linspace(CENTRE - 2.0, CENTRE + 2.0, 400_001)
    slope = joint.slope(x)
    height = np.concatenate(([0.0], np.cumsum((slope[1:] + slope[:-1]) / 2 * np.diff(x))))
    # the trapezoid rule errs by (step) (jump) / 2 at each of the three corners
    assert np.max(np.abs(height - joint(x))) < 2 * ANGLE * (x[1] - x[0])


def test_refuses_and_warns():
    with pytest.raises(ValueError, match="shorter than its period"):
        rt.DippedJoint(ANGLE, 18.0, 18.0)
    with pytest.raises(ValueError):
        rt.DippedJoint(-1e-3, 1.0, 18.0)
    with pytest.warns(UserWarning):
        rt.DippedJoint(0.5, 1.0, 18.0)            # 500 mrad: not a joint


def test_harmonics_fall_like_one_over_n_squared():
    joint = rt.DippedJoint(ANGLE, LENGTH, PERIOD)  # centred at 0: real coefficients
    samples = 1 << 18
    x = np.arange(samples) * PERIOD / samples
    spectrum = np.fft.rfft(joint(x)) / samples
    n = np.arange(1, 2001)
    exact = closed_form_coefficient(n)
    assert np.max(np.abs(spectrum[n] - exact)) < 1e-4 * np.max(np.abs(exact))
    # the envelope 2 angle / (k^2 P) times n^2 is a constant: 1/n^2, no faster
    envelope = 2 * ANGLE * PERIOD / (2 * np.pi) ** 2
    assert np.max(np.abs(exact) * n ** 2) == pytest.approx(envelope, rel=1e-3)


def test_the_solver_sees_the_closed_form_harmonics():
    passage = rt.Passage(rt.Track.ballasted(), rt.Train.paper(speed=30.0))
    joint = rt.DippedJoint(ANGLE, LENGTH, PERIOD, centre=CENTRE)
    grid = np.arange(1, 601)
    seen = profile_harmonics(passage, joint, grid, 4096)
    for k, d in enumerate(np.asarray(passage.axle_positions, float)):
        # r(v t - d): the joint passes under wheel k at t = (CENTRE + d) / v
        shift = np.exp(-2j * np.pi * grid * (CENTRE + d) / PERIOD)
        expected = closed_form_coefficient(grid) * shift
        assert np.max(np.abs(seen[k, 1:] - expected)) < 1e-3 * abs(expected[0])


def test_truncation_estimate_bounds_what_doubling_m_changes_in_p1():
    track, law = rt.Track.ballasted(), rt.LinearFoundation.ballasted()
    train, wheel = rt.Train.paper(speed=30.0), rt.Wheel(600.0)
    joint = rt.DippedJoint(ANGLE, LENGTH, PERIOD, centre=CENTRE)
    peaks, estimates = [], []
    for m in (300, 600):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")        # the truncation warning itself
            s = rt.solve(track, train, law, m, wheel=wheel, profile=joint)
        assert s.converged
        t = np.arange(16 * m) * s.period / (16 * m)
        peaks.append(float(s.contact_force(t).max()))
        estimates.append(s.truncation_error * float(s.contact_force(t).mean()))
    # P1 far above the static load (the corner's blow), and the change on
    # doubling m within the estimate made at the smaller m
    assert peaks[1] > 1.5 * 75e3
    assert abs(peaks[1] - peaks[0]) < estimates[0]


def test_harmonic_balance_p1_agrees_with_the_ring_within_their_errors():
    # Two methods: the ring (finite elements, Newmark; its P1 error is what
    # halving dt changes) and harmonic balance at m = 1200 (its error is its
    # own truncation estimate).  docs/joint_p1.md has both converged.
    track, law = rt.Track.ballasted(), rt.LinearFoundation.ballasted()
    train, wheel = rt.Train.paper(speed=30.0), rt.Wheel(600.0)
    joint = rt.DippedJoint(ANGLE, LENGTH, PERIOD, centre=CENTRE)
    ring = []
    for steps in (7200, 14400):  # dt = 83 and 42 us; P1 rises in ~0.3 ms
        r = rt.simulate_time_domain(
            track, train, law, 4, steps, wheel=wheel, profile=joint,
            tol=1e-3, warn_step_error=None)
        assert r.converged
        ring.append(float(r.contact_forces.max()))
    ring_error = abs(ring[1] - ring[0])
    assert ring_error < 0.01 * ring[1]
    m = 1200
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the truncation warning itself
        s = rt.solve(track, train, law, m, wheel=wheel, profile=joint)
    t = np.arange(16 * m) * s.period / (16 * m)
    p1 = float(s.contact_force(t).max())
    q = float(s.contact_force(t).mean())
    assert abs(p1 - ring[1]) < s.truncation_error * q + ring_error
