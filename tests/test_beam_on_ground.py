"""A beam on the ground: critical speed and moving-load response against independent truths.

Truths: the damped strip quadrature of `ground_strip` (other panels, a tail of
its own) for the undamped trapped one; Dieterman & Metrikine (1996): on a
half-space the critical velocity lies below the Rayleigh speed c_R and tends
to it as the beam gets lighter; the classic Winkler beam, v_cr = (4 k EI /
m^2)^(1/4) and the static deflection P / (8 EI beta^3) (Zimmermann), which a
thin stiff layer on a stiff base must reproduce (bed k = M b / h); and the
damped response's own peak against the undamped critical speed.
"""

import numpy as np
import pytest

from railtrack import plausibility
from railtrack.equations.beam_on_ground import beam_on_ground_dispersion, critical_speed_on_ground
from railtrack.equations.critical_estimate import mezher_critical_speed, track_phase_speed
from railtrack.equations.ground_strip import strip_stiffness
from railtrack.equations.ground_trapped import trapped_strip_stiffness, with_damping
from railtrack.equations.ground_waves import fundamental_phase_speed, rayleigh_speed
from railtrack.equations.moving_load_ground import moving_load_displacement
from railtrack.model.ground import Ground, SoilLayer

HALF = Ground.homogeneous(100.0, 0.3, 1800.0)
C_R = rayleigh_speed(100.0, 0.3)                                     # 92.741 m/s
CLAY = Ground((SoilLayer(65.0, 0.49, 1500.0, thickness=6.0),), SoilLayer(200.0, 0.45, 1900.0))
# a 2 cm layer of constrained modulus M on a base 17x faster: a Winkler bed M b / h
with plausibility("ignore"):         # meant: no soil is 2 cm thick at 11 kg/m^3
    LAYER = SoilLayer(300.0, 0.3, 11.0, thickness=0.02)
    WINKLER = Ground((LAYER,), SoilLayer(5000.0, 0.25, 2500.0))
EI, MASS, WIDTH = 6.4e6, 300.0, 2.0
BED = LAYER.constrained_modulus * WIDTH / LAYER.thickness            # 3.47e8 N/m^2


@pytest.mark.parametrize("ground, kx, omega", [(HALF, 0.5, 40.0), (HALF, 2.0, 150.0),
                                               (CLAY, 1.0, 50.0), (CLAY, 0.3, 15.0)])
def test_trapped_strip_is_the_damped_strip_without_damping(ground, kx, omega):
    undamped = trapped_strip_stiffness(ground, kx, omega, 3.0)
    with plausibility("ignore"):     # xi = 1e-9: the undamped limit, meant
        damped = strip_stiffness(with_damping(ground, 1e-9), kx, omega, 3.0)
    assert abs(damped.imag) < 1e-6 * abs(damped.real)
    assert undamped == pytest.approx(damped.real, rel=1e-8)


def test_critical_speed_on_a_half_space_lies_below_rayleigh_and_nears_it_for_a_light_beam():
    """Dieterman & Metrikine 1996: v_cr < c_R always, v_cr -> c_R as m -> 0."""
    heavy = critical_speed_on_ground(HALF, 1e6, 3000.0, 3.0, points=16).speed
    light = critical_speed_on_ground(HALF, 1e6, 300.0, 3.0, points=16).speed
    assert heavy < light < C_R
    assert 1 - light / C_R < 1e-3                                   # 1.2e-4 measured
    assert 0.8 < heavy / C_R < 0.95                                 # 0.865 measured


def test_dispersion_touches_the_line_of_the_critical_speed():
    critical = critical_speed_on_ground(HALF, 1e7, 3000.0, 3.0, points=16)
    k = critical.wavenumber * np.array([0.7, 0.9, 1.0, 1.1, 1.4])
    phase = beam_on_ground_dispersion(HALF, 1e7, 3000.0, 3.0, k) / k
    assert np.all(phase >= critical.speed * (1 - 1e-6))             # the line stays below
    assert phase[2] == pytest.approx(critical.speed, rel=1e-5)


def test_a_thin_stiff_layer_gives_the_winkler_critical_speed():
    winkler = (4 * BED * EI / MASS**2) ** 0.25                      # 561.5 m/s
    ours = critical_speed_on_ground(WINKLER, EI, MASS, WIDTH, points=12).speed
    assert ours == pytest.approx(winkler, rel=0.01)                 # +0.22 % measured


def test_the_static_deflection_on_a_thin_stiff_layer_is_zimmermanns():
    beta = (BED / (4 * EI)) ** 0.25
    w = moving_load_displacement(WINKLER, EI, MASS, WIDTH, 0.0, 1e5)
    assert float(w) == pytest.approx(1e5 / (8 * EI * beta**3), rel=0.01)   # -0.64 % measured


def test_the_damped_response_peaks_near_the_undamped_critical_speed():
    damped = with_damping(HALF, 0.02)
    v_cr = critical_speed_on_ground(HALF, 1e7, 3000.0, 3.0, points=16).speed    # 91.63 m/s
    speeds = v_cr * np.array([0.97, 0.985, 1.0])
    w = moving_load_displacement(damped, 1e7, 3000.0, 3.0, speeds, 1e5, panels_per_decade=6)
    assert w[1] > max(w[0], w[2])                                   # a peak between
    a, b, _ = np.polyfit(speeds, w, 2)
    assert -b / (2 * a) == pytest.approx(v_cr, rel=0.02)            # -1.4 % measured
    assert w[1] > 1.2 * moving_load_displacement(damped, 1e7, 3000.0, 3.0, 0.0, 1e5)


def test_the_free_track_speed_is_its_closed_form():
    """m omega^2 = EI k^4 + k_p: omega / k for a free beam and on pads."""
    omega = 2 * np.pi * 10.0
    assert track_phase_speed(1e7, 500.0, 10.0) == pytest.approx(np.sqrt(omega) * (2e4) ** 0.25)
    omega = 2 * np.pi * 30.0                                        # above sqrt(k_p/m) = 22.5 Hz
    k = ((500.0 * omega**2 - 1e7) / 1e7) ** 0.25
    assert track_phase_speed(1e7, 500.0, 30.0, 1e7) == pytest.approx(omega / k)
    assert np.isnan(track_phase_speed(1e7, 500.0, 20.0, 1e7))         # below the cut-off


def test_mezher_estimate_on_a_half_space_is_the_rayleigh_speed():
    speed, _ = mezher_critical_speed(HALF, 1e7, 500.0)
    assert speed == pytest.approx(C_R, rel=1e-8)


def test_on_soft_clay_the_branch_ends_on_the_grounds_mode_where_the_free_track_crosses_it():
    """A 6 m soft clay (65 m/s) over stiffer soil (200 m/s), a free beam on it.  Where nothing
    radiates K_eq > 0, so on the ground the track is faster than the free track at the same k
    (m omega^2 = EI k^4 + K_eq), and slower than the ground's mode c_1 at its own frequency.
    Here c_1 falls with frequency, so the branch ends on the ground's curve where the free
    track's curve crosses it, and its least phase speed is that crossing: Mezher et al.'s
    estimate.  With c_1 interpolated (up to 0.5 % off where it falls steeply) the library
    found a "root" above c_1, K_eq taken across a pole: 66.5 m/s, 11 % below the estimate,
    and slower than the free track at its wavenumber."""
    estimate, _ = mezher_critical_speed(CLAY, 1e7, 500.0)
    critical = critical_speed_on_ground(CLAY, 1e7, 500.0, 3.0, points=16)
    assert critical.speed > np.sqrt(1e7 / 500.0) * critical.wavenumber
    assert critical.speed <= fundamental_phase_speed(CLAY, critical.frequency)[0]
    assert critical.speed == pytest.approx(estimate, rel=0.005)            # +0.03 % measured


def test_the_layered_branch_lies_between_the_free_track_and_the_grounds_mode():
    """Each phase speed of the track's dispersion on CLAY, against c_1 computed at its own
    frequency (not the interpolated curve) and the free track's closed form; the branch
    exists for every k below the free track's crossing (k = 0.526 rad/m) and none above."""
    k = np.array([0.1, 0.2, 0.3, 0.4, 0.5, 0.55, 0.7])
    c = beam_on_ground_dispersion(CLAY, 1e7, 500.0, 3.0, k) / k
    below = k < 0.52
    assert np.all(np.isfinite(c[below])) and np.all(np.isnan(c[~below]))
    c_1 = fundamental_phase_speed(CLAY, k[below] * c[below] / (2 * np.pi))
    assert np.all(c[below] < c_1)
    assert np.all(c[below] > np.sqrt(1e7 / 500.0) * k[below])


def test_the_deflection_lags_behind_a_moving_load_on_a_damped_ground():
    """Statically symmetric; moving (+x) over a damped ground, the bowl trails the load.
    With omega = -k v (the wrong sign for exp(-i omega t)) it would lead instead."""
    ground = with_damping(HALF, 0.05)
    w = moving_load_displacement(ground, 1e7, 3000.0, 3.0, [0.0, 80.0], 1e5,
                                 positions=[-2.0, 0.0, 2.0], panels_per_decade=6)
    assert w[0, 0] == pytest.approx(w[0, 2], rel=1e-9)
    assert w[1, 0] > 2 * w[1, 2]                                     # 4.7e-4 m against 5.4e-5


def test_a_pad_on_a_stiff_half_space_gives_the_winkler_critical_speed():
    """The pad k_p in series with a ground 10^4 times stiffer: the bed is the pad."""
    stiff = Ground.homogeneous(5000.0, 0.25, 2500.0)
    ours = critical_speed_on_ground(stiff, EI, MASS, WIDTH, BED, points=12).speed
    assert ours == pytest.approx((4 * BED * EI / MASS**2) ** 0.25, rel=0.005)   # -0.02 %
