"""The vehicle alone: its matrices, natural frequencies and static loads (issue 32, item 1).

Truths: a second assembly by Lagrange's equations in SymPy (the Hessians of
the kinetic energy, the strain energy and Rayleigh's dissipation, written
spring by spring); the closed forms of the symmetric vehicle on a rigid
track, which splits into a bounce pair, a pitch pair and the bogies'
pitches (2 x 2 eigenproblems solved by the quadratic formula); statics
(the weight shared by four wheelsets); and two limits: a rigid suspension
leaves one body on the contact springs (its bogies pitching on pivots), an
infinitely heavy body and bogies leave each wheelset on its primary and
contact springs (today's `railtrack.Wheel` with a primary suspension).
"""

import numpy as np
import pytest
import sympy as sp

import railtrack as rt

from railtrack.equations.vehicle_matrices import (static_wheelset_loads, vehicle_frequencies,
                                                  vehicle_matrices)
from railtrack.model.vehicle import Vehicle

MANCHESTER = Vehicle.manchester()
# an unrelated wagon (a freight car, round numbers), so that no coincidence of the preset helps
FREIGHT = Vehicle(body_mass=60e3, body_pitch_inertia=1.5e6, bogie_mass=4000.0,
                  bogie_pitch_inertia=2500.0, wheelset_mass=1200.0,
                  secondary_stiffness=4e6, secondary_damping=60e3,
                  primary_stiffness=15e6, primary_damping=25e3,
                  bogie_spacing=12.0, wheelbase=1.8)
VEHICLES = [MANCHESTER, FREIGHT]
G = 9.81


def _lagrange(vehicle):
    """(M, C, K) from the energies, by SymPy, numerically."""
    q = sp.symbols("zc thc zb1 thb1 zb2 thb2 zw1 zw2 zw3 zw4")
    v = sp.symbols("vzc vthc vzb1 vthb1 vzb2 vthb2 vzw1 vzw2 vzw3 vzw4")
    mc, jc, mb, jb, mw, k2, c2, k1, c1, a, b = sp.symbols("mc jc mb jb mw k2 c2 k1 c1 a b")
    zc, thc, zb1, thb1, zb2, thb2, zw1, zw2, zw3, zw4 = q
    kinetic = sp.Rational(1, 2) * (mc * v[0] ** 2 + jc * v[1] ** 2 + mb * v[2] ** 2
                                   + jb * v[3] ** 2 + mb * v[4] ** 2 + jb * v[5] ** 2
                                   + mw * (v[6] ** 2 + v[7] ** 2 + v[8] ** 2 + v[9] ** 2))

    def stretches(x):
        zc, thc, zb1, thb1, zb2, thb2, zw1, zw2, zw3, zw4 = x
        secondary = [zb1 - (zc + a * thc), zb2 - (zc - a * thc)]
        primary = [zw1 - (zb1 + b * thb1), zw2 - (zb1 - b * thb1),
                   zw3 - (zb2 + b * thb2), zw4 - (zb2 - b * thb2)]
        return secondary, primary

    sec, pri = stretches(q)
    strain = sp.Rational(1, 2) * (k2 * sum(e ** 2 for e in sec) + k1 * sum(e ** 2 for e in pri))
    sec_v, pri_v = stretches(v)
    rayleigh = sp.Rational(1, 2) * (c2 * sum(e ** 2 for e in sec_v)
                                    + c1 * sum(e ** 2 for e in pri_v))
    values = {mc: vehicle.body_mass, jc: vehicle.body_pitch_inertia, mb: vehicle.bogie_mass,
              jb: vehicle.bogie_pitch_inertia, mw: vehicle.wheelset_mass,
              k2: vehicle.secondary_stiffness, c2: vehicle.secondary_damping,
              k1: vehicle.primary_stiffness, c1: vehicle.primary_damping,
              a: vehicle.bogie_spacing / 2, b: vehicle.wheelbase / 2}
    return tuple(np.array(sp.hessian(energy, x).subs(values), dtype=float)
                 for energy, x in ((kinetic, v), (rayleigh, v), (strain, q)))


@pytest.mark.parametrize("vehicle", VEHICLES, ids=["manchester", "freight"])
def test_the_matrices_are_lagranges(vehicle):
    for assembled, derived in zip(vehicle_matrices(vehicle), _lagrange(vehicle)):
        assert np.allclose(assembled, derived, rtol=1e-13, atol=1e-9 * np.abs(derived).max())


def _pair(m1, m2, k11, k22, k12):
    """The two natural frequencies [Hz] of det(K - w^2 M) = 0, M = diag(m1, m2)."""
    a, b, c = m1 * m2, -(k11 * m2 + k22 * m1), k11 * k22 - k12 ** 2
    root = np.sqrt(b * b - 4 * a * c)
    return [np.sqrt((-b - root) / (2 * a)) / (2 * np.pi), np.sqrt((-b + root) / (2 * a)) / (2 * np.pi)]


@pytest.mark.parametrize("vehicle", VEHICLES, ids=["manchester", "freight"])
def test_the_frequencies_on_a_rigid_track_are_the_decoupled_closed_forms(vehicle):
    mc, jc, mb, jb = (vehicle.body_mass, vehicle.body_pitch_inertia, vehicle.bogie_mass,
                      vehicle.bogie_pitch_inertia)
    k2, k1, a, b = (vehicle.secondary_stiffness, vehicle.primary_stiffness,
                    vehicle.bogie_spacing / 2, vehicle.wheelbase / 2)
    # bounce: body on 2 k2 over both bogies (2 m_b) on 4 k1
    bounce = _pair(mc, 2 * mb, 2 * k2, 2 * k2 + 4 * k1, -2 * k2)
    # pitch: body on k2 at +-a over the bogies moving in antiphase (u, -u) on 4 k1
    pitch = _pair(jc, 2 * mb, 2 * k2 * a ** 2, 2 * k2 + 4 * k1, -2 * k2 * a)
    # each bogie pitching on k1 at +-b
    bogie = [np.sqrt(2 * k1 * b ** 2 / jb) / (2 * np.pi)] * 2
    expected = np.sort(bounce + pitch + bogie)
    assert np.allclose(vehicle_frequencies(vehicle), expected, rtol=1e-10)


def test_the_manchester_body_bounces_near_1_hz_as_a_body_on_springs_in_series():
    # bogies massless: the body on 2 k2 in series with 4 k1
    series = 1 / (1 / (2 * MANCHESTER.secondary_stiffness) + 1 / (4 * MANCHESTER.primary_stiffness))
    estimate = np.sqrt(series / MANCHESTER.body_mass) / (2 * np.pi)        # 1.08 Hz
    assert vehicle_frequencies(MANCHESTER)[0] == pytest.approx(estimate, rel=0.02)


@pytest.mark.parametrize("vehicle", VEHICLES, ids=["manchester", "freight"])
def test_the_wheelsets_share_the_weight_equally(vehicle):
    loads = static_wheelset_loads(vehicle, G)
    assert np.allclose(loads, vehicle.total_mass * G / 4, rtol=1e-12)
    assert np.sum(loads) == pytest.approx(vehicle.total_mass * G, rel=1e-12)


def test_the_manchester_loads_are_the_passenger_coachs():
    # Train.passenger_coach sums the same masses by hand: half a wheelset's load per wheel
    wheel = rt.Train.passenger_coach().axle_loads
    assert np.allclose(static_wheelset_loads(MANCHESTER, rt.model.train.STANDARD_GRAVITY) / 2,
                       wheel, rtol=1e-12)


def _rigid(vehicle, factor):
    return Vehicle(**{**vehicle.__dict__,
                      "secondary_stiffness": factor * vehicle.secondary_stiffness,
                      "primary_stiffness": factor * vehicle.primary_stiffness})


@pytest.mark.parametrize("vehicle", VEHICLES, ids=["manchester", "freight"])
def test_a_rigid_suspension_leaves_one_body_with_its_bogies_on_pivots(vehicle):
    # the secondary is one vertical spring at each bogie's centre: made rigid, it pins the
    # bogie there and leaves it free to pitch; the primaries rigid, the wheelsets follow
    contact = 1.4e9                                # two Hertz springs at ~100 kN, N/m
    a, b = vehicle.bogie_spacing / 2, vehicle.wheelbase / 2
    mb, mw = vehicle.bogie_mass, vehicle.wheelset_mass
    bounce = np.sqrt(4 * contact / vehicle.total_mass)
    pitch = np.sqrt(4 * contact * a ** 2 / (vehicle.body_pitch_inertia + 2 * mb * a ** 2
                                            + 4 * mw * a ** 2))
    bogie = np.sqrt(2 * contact * b ** 2 / (vehicle.bogie_pitch_inertia + 2 * mw * b ** 2))
    expected = np.sort([bounce, pitch, bogie, bogie]) / (2 * np.pi)
    errors = []
    for factor in (1e5, 1e7):
        lowest = vehicle_frequencies(_rigid(vehicle, factor), contact)[:4]
        errors.append(np.max(np.abs(lowest / expected - 1)))
    assert errors[1] < 2e-4 and errors[1] < errors[0] / 50        # converging as 1 / factor


def test_an_infinitely_heavy_body_leaves_todays_wheel_on_its_primary_spring():
    contact = 1.4e9
    heavy = Vehicle(**{**FREIGHT.__dict__, "body_mass": 1e15, "body_pitch_inertia": 1e17,
                       "bogie_mass": 1e15, "bogie_pitch_inertia": 1e15})
    # today's Wheel(m_w, primary_stiffness=k_p) per rail: half of everything, the same frequency
    wheel = np.sqrt((contact + FREIGHT.primary_stiffness) / FREIGHT.wheelset_mass) / (2 * np.pi)
    assert np.allclose(vehicle_frequencies(heavy, contact)[-4:], wheel, rtol=1e-9)


@pytest.mark.parametrize("change, error, words", [
    (dict(body_mass=-1.0), ValueError, "body_mass"),
    (dict(primary_stiffness=0.0), ValueError, "primary_stiffness"),
    (dict(secondary_damping=-5.0), ValueError, "secondary_damping"),
    (dict(wheelbase=20.0), ValueError, "wheelbase"),
    (dict(bogie_mass=True), TypeError, "bogie_mass"),
    (dict(bogie_mass=[1.0, 2.0]), TypeError, "bogie_mass"),
])
def test_an_impossible_vehicle_is_refused_by_name(change, error, words):
    with pytest.raises(error, match=words):
        Vehicle(**{**MANCHESTER.__dict__, **change})


def test_a_negative_contact_stiffness_is_refused():
    with pytest.raises(ValueError, match="contact_stiffness"):
        vehicle_frequencies(MANCHESTER, -1.0)


def test_a_vehicle_takes_quantities_with_units():
    pint = pytest.importorskip("pint")
    ureg = pint.UnitRegistry()
    car = Vehicle(**{**MANCHESTER.__dict__, "body_mass": 32 * ureg.tonne,
                     "secondary_stiffness": 860 * ureg("kN/m"),
                     "body_pitch_inertia": 1.97 * ureg("t m^2") * 1e3,
                     "wheelbase": 2560 * ureg.mm})
    assert np.allclose(list(car.__dict__.values()), list(MANCHESTER.__dict__.values()),
                       rtol=1e-12, atol=0)


def test_the_vehicles_train_carries_its_static_loads_on_its_axles():
    coach = MANCHESTER.train(26.4, 45.0)
    assert np.allclose(coach.axle_loads, static_wheelset_loads(MANCHESTER, 9.81) / 2, rtol=1e-12)
    positions = np.asarray(coach.axle_positions)
    spacing = np.diff(positions)
    assert np.allclose(spacing, [2.56, 19.0 - 2.56, 2.56], rtol=1e-12)
    # the bogie centres, mid-way between their axles, are the bogie spacing apart
    centres = positions.reshape(2, 2).mean(axis=1)
    assert np.diff(centres)[0] == pytest.approx(MANCHESTER.bogie_spacing, rel=1e-12)


def test_the_vehicles_wheel_is_the_heavy_body_limit_per_rail():
    contact = 1.4e9
    heavy = Vehicle(**{**MANCHESTER.__dict__, "body_mass": 1e15, "body_pitch_inertia": 1e17,
                       "bogie_mass": 1e15, "bogie_pitch_inertia": 1e15})
    wheel = MANCHESTER.wheel()
    # one wheel on half the contact stiffness: the same frequency as the wheelset on all of it
    alone = np.sqrt((contact / 2 + wheel.primary_stiffness) / wheel.unsprung_mass) / (2 * np.pi)
    assert np.allclose(vehicle_frequencies(heavy, contact)[-4:], alone, rtol=1e-9)
    assert wheel.primary_damping == pytest.approx(MANCHESTER.primary_damping / 2)
