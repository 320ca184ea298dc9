"""The vehicle from its wheelsets, and its steady ride over a rigid irregular track.

Truths: the receptance of the free vehicle at its wheelsets by modal
superposition (an eigendecomposition, not the Schur complement), whose
inverse is the dynamic stiffness; the limit of an infinitely heavy body and
bogies, today's `railtrack.Wheel` on its primary spring; and a time
integration (scipy's DOP853) of the body and bogies driven by the
wheelsets riding the profile and its slope, run until the start has died away;
and, for the spectral integral of |H|^2 S, the variance of one long
realisation (the midpoint rule of that integral, within its bound).
"""

import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.linalg import eigh

from railtrack.equations.vehicle_matrices import static_wheelset_loads, vehicle_matrices
from railtrack.equations.vehicle_response import (rigid_track_ride, spectral_wheel_load_std,
                                                  wheel_load_transfer, wheelset_dynamic_stiffness)
from railtrack.model.irregularity import FRASpectrum
from railtrack.model.random_profile import RandomProfile
from railtrack.model.vehicle import Vehicle

MANCHESTER = Vehicle.manchester()
G = 9.81


def test_the_dynamic_stiffness_inverts_the_undamped_modal_receptance():
    undamped = Vehicle(**{**MANCHESTER.__dict__, "primary_damping": 0.0,
                          "secondary_damping": 0.0})
    mass, _, stiffness = vehicle_matrices(undamped)
    squares, modes = eigh(stiffness, mass)                # mass-normalised, free wheelsets
    squares[:2] = 0.0                                     # the vehicle's bounce and pitch
    for omega in (3.0, 20.0, 150.0, 900.0):
        receptance = (modes[6:] / (squares - omega ** 2)) @ modes[6:].T
        D = wheelset_dynamic_stiffness(undamped, omega)
        assert np.allclose(D.imag, 0.0, atol=1e-9 * np.abs(D).max())
        assert np.allclose(D.real @ receptance, np.eye(4), atol=1e-8)


def test_an_infinitely_heavy_body_leaves_each_wheelset_on_its_primary_suspension():
    heavy = Vehicle(**{**MANCHESTER.__dict__, "body_mass": 1e16, "body_pitch_inertia": 1e18,
                       "bogie_mass": 1e16, "bogie_pitch_inertia": 1e16})
    omega = np.array([0.5, 30.0, 400.0])
    D = wheelset_dynamic_stiffness(heavy, omega)
    wheel = (MANCHESTER.primary_stiffness + 1j * omega * MANCHESTER.primary_damping
             - omega ** 2 * MANCHESTER.wheelset_mass)
    assert np.allclose(D, wheel[:, None, None] * np.eye(4), rtol=0,
                       atol=1e-8 * np.abs(wheel).max())


def test_the_wheelsets_alone_remain_at_high_frequency():
    omega = 2 * np.pi * 2000.0
    D = wheelset_dynamic_stiffness(MANCHESTER, omega)
    assert np.allclose(D / (-omega ** 2 * MANCHESTER.wheelset_mass), np.eye(4), atol=0.02)


def _ode_forces(vehicle, rail, speed, periods):
    """Contact forces over the last ride period, by time integration from rest."""
    mass, damping, stiffness = vehicle_matrices(vehicle)
    r, w = slice(0, 6), slice(6, 10)
    s = vehicle.wheelset_positions
    gravity = -G * mass.diagonal() * np.array([1, 0, 1, 0, 1, 0, 1, 1, 1, 1])
    inverse = np.linalg.inv(mass[r, r])

    def wheelsets(t):
        x = speed * t + s
        return rail(x), speed * rail.slope(x)

    def rhs(t, y):
        z, v = wheelsets(t)
        force = (gravity[r] - damping[r, r] @ y[6:] - stiffness[r, r] @ y[:6]
                 - damping[r, w] @ v - stiffness[r, w] @ z)
        return np.concatenate([y[6:], inverse @ force])

    start = np.linalg.solve(stiffness[r, r], gravity[r])          # at rest on a level track
    ride = rail.period / speed
    times = ride * (periods - 1) + np.arange(64) * ride / 64
    result = solve_ivp(rhs, (0.0, times[-1]), np.concatenate([start, np.zeros(6)]),
                       method="DOP853", t_eval=times, rtol=1e-10, atol=1e-12)
    h = 1e-4
    forces = []
    for t, y in zip(times, result.y.T):
        z, v = wheelsets(t)
        x = speed * t + s
        acceleration = speed ** 2 * (rail.slope(x + h) - rail.slope(x - h)) / (2 * h)
        forces.append(mass[w, w] @ acceleration + damping[w, r] @ y[6:] + stiffness[w, r] @ y[:6]
                      + damping[w, w] @ v + stiffness[w, w] @ z - gravity[w])
    return np.array(forces).T


def test_the_ride_over_a_rigid_rail_is_the_time_integrations_steady_state():
    # 45 m/s over FRA class 4, 1.5-25 m: +-49 kN on 109 kN; after 12 s the start has
    # died away to 2e-6 of that (1e-8 after 30 s), well inside the 1e-4 asked
    speed = 45.0
    rail = RandomProfile(FRASpectrum(4), (1.5, 25.0), 18.0, seed=4)
    times, forces = rigid_track_ride(MANCHESTER, rail, speed, rail.period, samples=64)
    truth = _ode_forces(MANCHESTER, rail, speed, int(np.ceil(12.0 / (rail.period / speed))))
    static = static_wheelset_loads(MANCHESTER, G)[:, None]
    assert np.max(np.abs(truth - static)) > 0.3 * static.max()
    assert np.max(np.abs(forces - truth)) < 1e-4 * np.max(np.abs(truth - static))
    assert np.allclose(forces.mean(axis=1), static[:, 0], rtol=1e-12)


def _midpoint_bound(density, omega, step):
    """dOmega^2/24 * sum over cells of max|g''| * dOmega, g'' by central differences."""
    points = omega[:, None] + step * np.linspace(-0.5, 0.5, 5)[None, :]
    h = 1e-4                                              # rad/m; the band starts at 0.25
    second = (density(points + h) - 2 * density(points) + density(points - h)) / h ** 2
    return step ** 2 / 24 * np.sum(np.abs(second).max(axis=1), axis=0) * step


def test_the_spectral_integral_is_the_long_rails_wheel_load_variance():
    # one realisation over 30 wagons: its mean square per wheelset is, phase by phase,
    # sum |H_j|^2 S dOmega, the midpoint rule of the spectral integral
    speed, band, spectrum = 45.0, (1.5, 25.0), FRASpectrum(4)
    rail = RandomProfile(spectrum, band, 30 * 18.0, seed=9)
    _, forces = rigid_track_ride(MANCHESTER, rail, speed, rail.period, samples=1024)
    variance = forces.var(axis=1)
    omega, step = rail.wavenumbers, 2 * np.pi / rail.period

    def density(w):
        w = np.asarray(w, dtype=float)
        return np.abs(wheel_load_transfer(MANCHESTER, speed, w)) ** 2 * spectrum(w)[..., None]

    cells = np.array([quad(lambda w, j=j: density(w)[j], omega[0] - step / 2,
                           omega[-1] + step / 2, limit=400, epsrel=1e-10)[0] for j in range(4)])
    bound = _midpoint_bound(density, omega, step)
    assert np.all(np.abs(variance - cells) <= 1.5 * bound)
    assert np.all(bound < 0.02 * cells)
    low, high = 2 * np.pi / band[1], 2 * np.pi / band[0]
    edges = step / 2 * (density(low - step / 2) + density(high - step / 2))
    sigma = spectral_wheel_load_std(MANCHESTER, spectrum, speed, band)
    assert np.all(np.abs(variance - sigma ** 2) <= 1.5 * bound + edges)
