"""Wheels on Hertz springs against truths the solver does not contain (issue 27).

* Gravity on a linear track is a static load: it adds the state at rest, whose
  rail sags between the sleepers under its own weight by the continuous
  beam's closed form ``-q L^4 B4(x/L) / (24 EI)`` (Bernoulli's B4, the
  pads' reactions qL at the sleepers).  A wheel feels that sag as it would a
  rail-top profile: with gravity the wheels press exactly as they do without
  it on a rail ground to that profile.  The sleepers' own weight does not
  reach the rail: it goes through the sleeper to the ballast.
* Statics: over a period the foundations carry the wheels' loads and the
  weight of the rail and the sleepers.
* The kinematics of the contact: the compression is the rail under the wheel
  plus the profile, less the wheel, for any Hertz constant; and as C_H grows
  the compression's swing vanishes as C_H^(-2/3) and the forces approach the
  rigid contact's as fast.
* The equilibrium of the rail: over a period the sleepers' mean seat loads
  add up to the wheels' mean contact forces.
* A solve that stops early says so; ``"auto"`` meets its accuracy against a
  much finer solve computed here.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.train import STANDARD_GRAVITY as G
from railtrack.solvers.wheel_newton import solve_wheels

TRACK = rt.Track.paper()
LAW = rt.LinearFoundation(20e6, 0.2e6)
DIP = rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.3)


def own_weight_sag(passage):
    """The rail's sag between rigid reactions qL under its weight q = rho S g, less its mean [m]."""
    span, ei = passage.sleeper_spacing, passage.rail_bending_stiffness
    q = passage.rail_linear_mass * G

    def sag(x):
        u = np.mod(np.asarray(x, dtype=float) / span, 1.0)
        return -q * span**4 * (u**4 - 2 * u**3 + u**2 - 1.0 / 30.0) / (24 * ei)
    sag.period = span
    return sag


def test_own_weight_sag_is_the_continuous_beams():
    # the closed form's own check: midspan sits q L^4 / (384 EI) below the supports
    passage = rt.Passage(TRACK, rt.Train.paper())
    sag = own_weight_sag(passage)
    q, span = passage.rail_linear_mass * G, passage.sleeper_spacing
    assert sag(0.0) - sag(span / 2) == pytest.approx(
        q * span**4 / (384 * passage.rail_bending_stiffness), rel=1e-12)


@pytest.mark.parametrize("speed", [45.0, 100.0])
def test_with_gravity_the_wheels_ride_the_rails_own_sag(speed):
    train = rt.Train.paper(speed=speed)
    passage = rt.Passage(TRACK, train)
    heavy = rt.solve(TRACK, train, rt.SleeperCell.identical(passage, LAW, 1, gravity=G), 120,
                     wheel=rt.Wheel(600.0))
    light = rt.solve(TRACK, train, rt.SleeperCell.identical(passage, LAW, 1), 120,
                     wheel=rt.Wheel(600.0), profile=own_weight_sag(passage))
    assert heavy.converged and light.converged
    t = heavy.one_period(1024)[0]
    force = heavy.contact_force(t)
    assert np.ptp(force) > 500.0                         # the sleepers' passing is felt
    # a sleeper's weight wrongly on the rail would press it 1.6 kN a sleeper: 10 N here
    np.testing.assert_allclose(force, light.contact_force(t), rtol=0, atol=0.05)
    # the sleepers: the same motion, shifted by the state at rest
    shift = heavy.sleeper_displacement(t) - light.sleeper_displacement(t)
    rest = heavy.sleepers.at_rest().sleeper_displacement
    np.testing.assert_allclose(shift, np.broadcast_to(rest[:, None], shift.shape), rtol=1e-6)


def test_the_foundations_carry_the_wheels_and_the_weight_of_rail_and_sleepers():
    train = rt.Train(18.0, (0.0, 3.0), (60e3, 90e3), 60.0)
    passage = rt.Passage(TRACK, train)
    cell = rt.SleeperCell.identical(passage, LAW, 30, gravity=G).with_sleeper(
        7, foundation=rt.LinearFoundation(8e6, 0.1e6))
    result = rt.solve(TRACK, train, cell, 120, wheel=rt.Wheel(600.0), profile=DIP)
    assert result.converged
    t = result.one_period(4096)[0]
    span = passage.sleeper_spacing
    weight = (passage.sleeper_mass + passage.rail_linear_mass * span) * G
    total = result.sleepers.foundation_force(t).sum(axis=0).mean()
    assert total == pytest.approx(150e3 + 30 * weight, rel=1e-6)
    # the rail's balance: the pads carry the wheels and the rail, not the sleepers
    seats = result.rail_seat_load(t).sum(axis=0).mean()
    assert seats == pytest.approx(150e3 + 30 * passage.rail_linear_mass * span * G, rel=1e-6)


def band_limited_dip(depth=0.5e-3, centre=9.3, wagon=18.0, power=8):
    """-depth ((1 + cos(2 pi (x - centre) / H)) / 2)^power: harmonics of H up to `power` only."""
    def profile(x):
        return -depth * ((1 + np.cos(2 * np.pi * (np.asarray(x, float) - centre) / wagon)) / 2
                         ) ** power
    profile.period = wagon
    return profile


def test_the_compression_is_the_rail_under_the_wheel_plus_the_profile_less_the_wheel():
    # delta = w_r(v t - d_k) + r(v t - d_k) - z_k: the rail field (sleepers' reactions
    # plus eq. 13.2) and the wheel (its own receptance) are computed apart; the
    # profile has 40 harmonics, so that the solution sees all of it
    bump = band_limited_dip(power=40)
    result = rt.solve(TRACK, rt.Train.paper(speed=100.0), LAW, 150, wheel=rt.Wheel(600.0),
                      profile=bump)
    assert result.converged
    t = np.linspace(8.3, 10.3, 8) / 100.0                 # wheel 1 crossing the dip
    x = result.wheel_position(t)
    rail = result.rail_displacement(np.broadcast_to(t, x.shape), x)
    kinematic = rail + bump(x) - result.wheel_displacement(t)
    swing = np.ptp(result.compression(t))
    assert swing > 10e-6
    np.testing.assert_allclose(kinematic, result.compression(t), rtol=0, atol=2e-3 * swing)


def test_a_stiffening_contact_approaches_the_rigid_one_as_c_h_to_the_minus_two_thirds():
    # A real wheel (600 kg) on the dip at 45 m/s: the contact's compliance
    # delta - delta_static ~ (P - Q) / k_H, with k_H ~ C_H^(2/3) Q^(1/3).  The
    # compression's swing falls as C_H^(-2/3); the force's changes too, so
    # that the forces converge to the rigid contact's (a Cauchy sequence).
    swings, forces = [], []
    for hertz in (1e12, 1e13, 1e14):
        result = rt.solve(TRACK, rt.Train.paper(speed=45.0), LAW, 150,
                          wheel=rt.Wheel(600.0, hertz_constant=hertz), profile=DIP)
        assert result.converged
        t = result.one_period(2048)[0]
        swings.append(np.ptp(result.compression(t)))
        forces.append(result.contact_force(t))
    ratio = 10 ** (-2 / 3)
    assert swings[1] / swings[0] == pytest.approx(ratio, rel=0.05)
    assert swings[2] / swings[1] == pytest.approx(ratio, rel=0.05)
    first, second = (np.abs(b - a).max() for a, b in zip(forces, forces[1:]))
    assert second / first == pytest.approx(ratio, rel=0.1)
    assert np.ptp(forces[-1]) > 20e3                     # the limit is no constant force


def test_the_rail_balances_its_wheels_and_each_wheel_presses_with_its_load():
    # Unequal wheels (60 and 90 kN) on the dip: the rail's vertical equilibrium
    # (the sleepers' mean seat loads over a wagon = the wheels' mean forces), and
    # each wheel's own (m_w z'' = Q_k - P_k over a period, z periodic), read from
    # Hertz's law of the compression on a grid finer than the solver's
    train = rt.Train(18.0, (0.0, 3.0), (60e3, 90e3), 45.0)
    result = rt.solve(TRACK, train, LAW, 150, wheel=rt.Wheel(600.0), profile=DIP)
    assert result.converged
    t = result.one_period(8192)[0]
    force = result.wheel.contact_force(result.compression(t))
    assert np.ptp(force[0]) > 20e3
    seats = result.rail_seat_load(t).mean(axis=1).sum()
    assert force.mean(axis=1).sum() == pytest.approx(seats, rel=1e-6)
    np.testing.assert_allclose(force.mean(axis=1), [60e3, 90e3], rtol=1e-6)


def test_a_wheel_solve_stopped_early_says_it_did_not_converge():
    train = rt.Train.paper(speed=45.0)
    passage = rt.Passage(TRACK, train)
    cell = rt.SleeperCell.identical(passage, LAW, 30)
    deep = rt.CosineDip(5e-3, 1.0, 18.0, centre=9.3)
    for steps in (0, 1):
        early = solve_wheels(passage, cell, rt.Wheel(600.0), deep, 60, max_iterations=steps)
        assert not early.converged and early.residual > 1e-9
        # the residual it reports is the one its own outputs show: Hertz's law of the
        # compression against the forces it returns, harmonic by harmonic
        hertz = np.fft.rfft(rt.Wheel(600.0).contact_force(early.compression), axis=-1)
        hertz = hertz[:, early.grid] / early.compression.shape[-1]
        assert np.abs(hertz - early.contact_harmonics).max() > 1e-3 * 75e3
    done = solve_wheels(passage, cell, rt.Wheel(600.0), DIP, 60)
    assert done.converged


def test_auto_meets_its_accuracy_against_a_much_finer_solve():
    train = rt.Train.paper(speed=100.0)
    reference = rt.solve(TRACK, train, LAW, 1200, wheel=rt.Wheel(600.0))
    t = reference.one_period(4096)[0]
    for accuracy in (1e-3, 1e-4):
        auto = rt.solve(TRACK, train, LAW, wheel=rt.Wheel(600.0), accuracy=accuracy)
        assert auto.converged
        error = np.abs(auto.contact_force(t) - reference.contact_force(t)).max() / 75e3
        assert error <= accuracy
        assert auto.truncation_error <= accuracy
