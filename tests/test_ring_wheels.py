"""The ring with wheels of mass on Hertz springs (issue 20, section 4).

`simulate_time_domain(..., wheel=Wheel(...), profile=...)` makes each axle a
wheel DOF z_j on a Hertz spring to the rail element under its contact point.
The truths it is held to:

* a wheel of (almost) no mass carries exactly Q (m_w z'' = P - Q): the
  constant-force ring, solved without any wheel;
* wheel equilibrium: over a period of a periodic Newmark solution the mean
  of z'' vanishes, so the mean contact force is Q exactly (Q + k_p mean z
  with a primary spring);
* statics: at walking pace the force stays Q and the compression
  delta_0 = (Q / C_H)^{2/3};
* kinematics: over a long shallow dip at low speed the wheel follows the
  rail's top, z - z_smooth = r(x_c) (the smooth rail's run as reference);
* convergence of the contact force with the mesh and the time step.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from railtrack import LinearFoundation
from railtrack.model.passage import Passage
from railtrack.model.profile import CosineDip
from railtrack.model.wheel import Wheel
from railtrack.timedomain.ring_contact import loss_of_contact
from railtrack.timedomain.simulation import simulate_time_domain

PASSAGE = Passage.paper()
TRACK, TRAIN = PASSAGE.track, PASSAGE.train
SOUND = LinearFoundation.paper()  # 20 MN/m, 0.2 MN s/m
Q = 75e3
WHEEL = Wheel(600.0, 9.4e10)


def _run(speed=45.0, elements=2, steps=480, **options):
    options.setdefault("warn_step_error", None)
    return simulate_time_domain(
        TRACK, TRAIN.replace(speed=speed), SOUND, elements, steps, **options
    )


def test_a_massless_wheel_is_the_constant_force_ring():
    plain = _run()
    light = _run(wheel=Wheel(1e-3, 9.4e10), max_periods=6)
    peak = np.abs(plain.sleeper_displacement).max()
    assert (
        np.abs(
            light.sleeper_displacement - plain.sleeper_displacement
        ).max()
        < 1e-5 * peak
    )
    # The pad's rate carries the light wheel's unresolved rattle
    # (|P - Q| ~ 20 N): within the ring's own time-step error at 480
    # steps (~1e-3 of the peak, timestep.py).
    seat = np.abs(plain.rail_seat_loads).max()
    assert (
        np.abs(light.rail_seat_loads - plain.rail_seat_loads).max()
        < 2e-3 * seat
    )
    assert np.abs(light.contact_forces - Q).max() < 1e-3 * Q
    assert (
        light.contact_forces.shape
        == light.wheel_displacements.shape
        == (480, 2)
    )


@pytest.mark.parametrize(
    "wheel",
    [WHEEL, Wheel(600.0, primary_stiffness=5e6, primary_damping=2e4)],
)
def test_mean_contact_force_is_the_wheel_load(wheel):
    result = _run(elements=2, steps=960, wheel=wheel, tol=1e-5)
    assert result.converged
    dynamic = np.ptp(result.contact_forces)
    assert dynamic > 100.0  # the sleepers do excite the wheel
    # m z'' = P - Q - k_p z - c_p z': the means of z'' and z' vanish
    # over a period.
    expected = (
        Q
        + wheel.primary_stiffness * result.wheel_displacements.mean(axis=0)
    )
    assert (
        np.abs(result.contact_forces.mean(axis=0) - expected).max()
        < 1e-6 * Q
    )


def test_at_walking_pace_the_wheel_presses_with_q():
    result = _run(speed=1.0, steps=480, wheel=WHEEL, tol=1e-5)
    assert np.abs(result.contact_forces - Q).max() < 1e-3 * Q
    delta = result.rail_under_wheels - result.wheel_displacements
    delta0 = WHEEL.static_compression(Q)
    assert np.abs(delta - delta0).max() < 1e-3 * delta0
    share, longest = result.loss_of_contact()
    assert np.all(share == 0.0) and np.all(longest == 0.0)


def test_a_slow_wheel_follows_a_long_shallow_dip():
    dip = CosineDip(0.3e-3, 6.0, 18.0, centre=9.3)
    smooth = _run(speed=2.0, wheel=WHEEL, tol=1e-4)
    dipped = _run(speed=2.0, wheel=WHEEL, profile=dip, tol=1e-4)
    x = np.mod(
        2.0 * dipped.times[:, None] - np.array(TRAIN.axle_positions), 18.0
    )
    followed = dipped.wheel_displacements - smooth.wheel_displacements
    assert np.abs(dip(x)).max() > 0.29e-3  # both wheels cross the dip
    assert np.abs(followed - dip(x)).max() < 0.02 * dip.depth
    assert np.abs(dipped.contact_forces - Q).max() < 0.01 * Q


def test_contact_force_converges_with_mesh_and_time_step():
    """RMS of P - Q over a period, smooth rail, 45 m/s (sleeper passing).

    Measured: by steps (2 elements/span) 370.55, 361.85, 359.80 N (ratio of
    successive differences 4.2: second order in dt); by elements (960 steps)
    361.85, 334.39, 329.59 N (ratio 5.7).
    """

    def rms(elements, steps):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = _run(
                elements=elements, steps=steps, wheel=WHEEL, tol=1e-4
            )
        return float(np.sqrt(np.mean((result.contact_forces - Q) ** 2)))

    in_time = [rms(2, s) for s in (480, 960, 1920)]
    steps_ratio = (in_time[0] - in_time[1]) / (in_time[1] - in_time[2])
    in_space = [in_time[1]] + [rms(e, 960) for e in (4, 8)]   # rms(2, 960) is in_time[1]
    mesh_ratio = (in_space[0] - in_space[1]) / (in_space[1] - in_space[2])
    print(
        f"rms P - Q by steps {in_time}, ratio {steps_ratio:.2f}; "
        f"by elements {in_space}, ratio {mesh_ratio:.2f}"
    )
    assert 3.0 < steps_ratio < 5.5  # second order in dt: 4
    assert 2.5 < mesh_ratio < 12.0  # second order in h or better
    assert abs(in_space[1] - in_space[2]) < 0.02 * in_space[2]


def test_profile_must_repeat_with_the_ring():
    with pytest.raises(
        ValueError, match=r"period 7 m does not divide it .*18 / 7"
    ):
        _run(wheel=WHEEL, profile=CosineDip(1e-4, 1.0, 7.0))
    with pytest.raises(ValueError, match="repeat with the ring"):
        _run(wheel=WHEEL, profile=lambda x: 1e-4 * np.sin(x))
    # Two wagons on the ring: a dip every 36 m repeats with it.
    _run(
        steps=960,
        wheel=WHEEL,
        profile=CosineDip(1e-4, 1.0, 36.0),
        wagons=2,
        max_periods=1,
    )


@pytest.mark.parametrize(
    "arguments, error, match",
    [
        (
            dict(profile=CosineDip(1e-4, 1.0, 18.0)),
            ValueError,
            "needs wheels",
        ),
        (dict(wheel=WHEEL, start="rest"), ValueError, "static state only"),
        (
            dict(wheel=600.0),
            TypeError,
            "must be a railtrack.model.wheel.Wheel",
        ),
    ],
)
def test_bad_wheel_arguments_are_refused(arguments, error, match):
    with pytest.raises(error, match=match):
        _run(**arguments)


def test_loss_of_contact_wraps_around_the_period():
    forces = np.array(
        [
            [0.0, 1.0],
            [0.0, 1.0],
            [5.0, 1.0],
            [0.0, 1.0],
            [0.0, 1.0],
            [0.0, 1.0],
        ]
    )
    share, longest = loss_of_contact(forces, 0.1)
    assert share == pytest.approx([5 / 6, 0.0])
    assert longest == pytest.approx([0.5, 0.0])  # steps 3, 4, 5, 0, 1
    with pytest.raises(ValueError, match="no wheels"):
        _run(max_periods=1).loss_of_contact()


def test_an_unresolved_stiff_contact_is_not_reported_converged():
    # 1 kg on C_H = 1e16 (sqrt(k_H / m_w) dt ~ 1e3, unresolved): the
    # average-acceleration step pumps the stiff Hertz spring until the
    # wheel leaves the rail; that is no periodic state (a wheel with P = 0
    # all period is in free fall).
    result = _run(wheel=Wheel(1.0, 1e16), max_periods=8)
    share, _ = result.loss_of_contact()
    assert share.max() > 0.5
    assert not result.converged
