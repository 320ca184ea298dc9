"""The P2 force of Jenkins et al. (1974), the cosine dip's angle and the equivalent track.

Truths used: the formula computed by hand from its written form; the damped
one-mass oscillator it approximates, integrated numerically; the dip's slope
by finite differences and by SymPy; a beam on a Winkler foundation (Hetenyi's
point stiffness 8 EI beta^3, beta^4 = k / (4 EI)) in the limit of close
sleepers; a finite-element rail on discrete pads, sleepers and ballast.
"""

import math

import numpy as np
import pytest
import scipy.sparse as sp
import sympy
from scipy.integrate import solve_ivp
from scipy.sparse.linalg import spsolve

from railtrack import LinearFoundation, Track
from railtrack.model.profile import CosineDip
from railtrack.studies.p2_force import (
    EquivalentTrack,
    dip_angle,
    equivalent_track,
    fit_equivalent_track,
    p2_force,
    point_receptance,
)

# Not the defaults anywhere: P0, 2 alpha, v, m_u, m_t, k_t, c_t.
CASE = (50e3, 4e-3, 25.0, 500.0, 300.0, 100e6, 40e3)


def test_formula_against_a_hand_computation():
    p0, angle, v, m_u, m_t, k_t, c_t = CASE
    m = m_u + m_t
    by_hand = p0 + angle * v * math.sqrt(m_u / m) * (
        1 - c_t * math.pi / (4 * math.sqrt(k_t * m))) * math.sqrt(k_t * m_u)
    assert p2_force(*CASE) == pytest.approx(by_hand, rel=1e-13)
    # 0.1 * 0.790569 * 0.888928 * 223606.8 = 15714 N, worked out on paper
    assert p2_force(*CASE) == pytest.approx(65714.0, abs=2.0)


def test_static_load_at_zero_speed_or_zero_angle():
    p0, angle, v, *track = CASE
    assert p2_force(p0, angle, 0.0, *track) == p0
    assert p2_force(p0, 0.0, v, *track) == p0


def test_increases_with_speed_and_dip_angle():
    p0, angle, v, *track = CASE
    speeds = np.linspace(0.0, 80.0, 9)
    angles = np.linspace(0.0, 0.02, 9)
    assert np.all(np.diff([p2_force(p0, angle, s, *track) for s in speeds]) > 0)
    assert np.all(np.diff(p2_force(p0, angles, v, *track)) > 0)   # arrays broadcast


def test_damping_bracket():
    p0, angle, v, m_u, m_t, k_t, _ = CASE
    undamped = p2_force(p0, angle, v, m_u, m_t, k_t, 0.0) - p0
    assert undamped == pytest.approx(angle * v * m_u * math.sqrt(k_t / (m_u + m_t)), rel=1e-13)
    # the bracket falls linearly, and reaches 0 at c_t = 4 sqrt(k_t (m_u + m_t)) / pi
    zero = 4 * math.sqrt(k_t * (m_u + m_t)) / math.pi
    half = p2_force(p0, angle, v, m_u, m_t, k_t, 0.5 * zero) - p0
    assert half == pytest.approx(0.5 * undamped, rel=1e-12)
    assert p2_force(p0, angle, v, m_u, m_t, k_t, zero) == pytest.approx(p0, abs=1e-6)
    with pytest.raises(ValueError, match="damping bracket"):
        p2_force(p0, angle, v, m_u, m_t, k_t, 1.01 * zero)


@pytest.mark.parametrize("zeta", [0.0, 0.01, 0.03])
def test_formula_is_the_first_order_peak_of_the_oscillator(zeta):
    # m_u + m_t on (k_t, c_t), started with the velocity 2 alpha v m_u / (m_u + m_t):
    # the first peak of the spring force k_t x(t) is P2 - P0 up to O(zeta^2).
    p0, angle, v, m_u, m_t, k_t, _ = CASE
    m = m_u + m_t
    c_t = 2 * zeta * math.sqrt(k_t * m)
    omega = math.sqrt(k_t / m)

    def motion(t, y):
        return [y[1], -(k_t * y[0] + c_t * y[1]) / m]

    t = np.linspace(0.0, 0.75 * 2 * math.pi / omega, 20001)
    run = solve_ivp(motion, (0.0, t[-1]), [0.0, angle * v * m_u / m], t_eval=t,
                    rtol=1e-11, atol=1e-16, method="DOP853")
    peak = k_t * run.y[0].max()
    formula = p2_force(p0, angle, v, m_u, m_t, k_t, c_t) - p0
    # the exact peak is exp(-zeta acos(zeta) / sqrt(1 - zeta^2)) = 1 - zeta pi/2
    # + (1 + pi^2/8) zeta^2 + ...: a wrong first-order term would miss by O(zeta)
    assert abs(formula / peak - 1) <= 2.5 * zeta**2 + 1e-8


def test_bad_inputs_name_the_argument():
    p0, angle, v, m_u, m_t, k_t, c_t = CASE
    for index, name in [(3, "unsprung_mass"), (4, "track_mass"), (5, "track_stiffness")]:
        for bad in (0.0, -1.0, np.nan):
            args = list(CASE)
            args[index] = bad
            with pytest.raises(ValueError, match=name):
                p2_force(*args)
    for index, name in [(0, "static_load"), (1, "dip_angle"), (2, "speed"), (6, "track_damping")]:
        args = list(CASE)
        args[index] = -1.0
        with pytest.raises(ValueError, match=name):
            p2_force(*args)
    with pytest.raises(TypeError, match="speed"):
        p2_force(p0, angle, "fast", m_u, m_t, k_t, c_t)


def test_equivalent_track_record():
    british = EquivalentTrack.british()
    assert (british.mass, british.stiffness, british.damping) == (245.0, 150e6, 55.4e3)
    with pytest.raises(ValueError, match="stiffness"):
        EquivalentTrack(245.0, 0.0, 1.0)
    with pytest.raises(ValueError, match="damping"):
        EquivalentTrack(245.0, 1e8, -1.0)
    with pytest.raises(AttributeError):
        british.mass = 1.0


def test_dip_angle_against_finite_differences_and_sympy():
    dip = CosineDip(0.7e-3, 1.3, 19.5, centre=4.0)
    x = np.linspace(dip.centre - dip.length, dip.centre + dip.length, 400001)
    slope = np.gradient(dip(x), x)
    assert dip_angle(dip) == pytest.approx(slope.max() - slope.min(), rel=1e-8)
    s, depth, length = sympy.symbols("s d l", positive=True)
    r = -depth / 2 * (1 + sympy.cos(2 * sympy.pi * s / length))
    steepest = sympy.diff(r, s).subs(s, length / 4)     # where d2r/ds2 = 0 on the ascent
    assert sympy.diff(r, s, 2).subs(s, length / 4) == 0
    total = sympy.simplify(2 * steepest)
    assert total == 2 * sympy.pi * depth / length
    assert dip_angle(dip) == pytest.approx(float(total.subs({depth: 0.7e-3, length: 1.3})))
    with pytest.raises(TypeError, match="CosineDip"):
        dip_angle(0.5e-3)


def _winkler_track(spacing, modulus, damping=0.0):
    """Sleepers `spacing` apart whose supports add up to a Winkler bed `modulus` [N/m^2]."""
    track = Track.paper(sleeper_spacing=spacing, sleeper_mass=1e-9, pad_stiffness=1e14,
                        pad_damping=0.0)
    return track, LinearFoundation(modulus * spacing, damping * spacing)


def _hetenyi(track, modulus, damping, omega):
    """Point receptance 1 / (8 EI beta^3) of a beam on a Winkler bed, 4 EI beta^4 = K(omega)."""
    bed = modulus + 1j * omega * damping - track.rail_linear_mass * omega**2
    beta = (bed / (4 * track.rail_bending_stiffness)) ** 0.25
    return 1 / (8 * track.rail_bending_stiffness * beta**3)


@pytest.mark.parametrize("omega", [0.0, 2 * np.pi * 40.0])
def test_point_receptance_tends_to_the_winkler_beam(omega):
    modulus, damping = 50e6, 80e3
    errors = []
    for spacing in (0.2, 0.1, 0.05):
        track, law = _winkler_track(spacing, modulus, damping)
        exact = _hetenyi(track, modulus, damping, omega)
        errors.append(abs(point_receptance(track, law, omega) / exact - 1))
    assert errors[-1] < 2e-4
    assert errors[1] / errors[2] > 3.5 and errors[0] / errors[1] > 3.5     # O(spacing^2)


def _fe_receptance(track, law, omega, spans=160, per_span=8):
    """Rail of Hermite elements on pads, sleeper masses and ballast; unit force at the centre."""
    ei, rho, span = track.rail_bending_stiffness, track.rail_linear_mass, track.sleeper_spacing
    h = span / per_span
    k_e = ei / h**3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                                [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    m_e = rho * h / 420 * np.array([[156, 22 * h, 54, -13 * h],
                                    [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                                    [54, 13 * h, 156, -22 * h],
                                    [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
    nodes = spans * per_span + 1
    size = 2 * nodes + spans + 1
    rows, cols, vals = [], [], []
    block = k_e - omega**2 * m_e
    for e in range(nodes - 1):
        dofs = np.arange(2 * e, 2 * e + 4)
        rows += list(np.repeat(dofs, 4))
        cols += list(np.tile(dofs, 4))
        vals += list(block.ravel())
    pad = track.pad_stiffness + 1j * omega * track.pad_damping
    below = law.stiffness + 1j * omega * law.damping - track.sleeper_mass * omega**2
    for i in range(spans + 1):
        rail, sleeper = 2 * i * per_span, 2 * nodes + i
        rows += [rail, rail, sleeper, sleeper, sleeper]
        cols += [rail, sleeper, rail, sleeper, sleeper]
        vals += [pad, -pad, -pad, pad, below]
    matrix = sp.csc_matrix((np.array(vals, dtype=complex), (rows, cols)), shape=(size, size))
    force = np.zeros(size, dtype=complex)
    centre = 2 * (spans // 2) * per_span
    force[centre] = 1.0
    return spsolve(matrix, force)[centre]


@pytest.mark.parametrize("hertz", [0.0, 30.0, 120.0, 400.0])
def test_point_receptance_against_finite_elements(hertz):
    track, law = Track.paper(), LinearFoundation(20e6, 0.2e6)
    omega = 2 * np.pi * hertz
    fe = _fe_receptance(track, law, omega)
    assert point_receptance(track, law, omega) == pytest.approx(fe, rel=2e-5)


def test_undamped_track_in_a_stop_band_and_in_a_pass_band():
    # below the sleeper's band the undamped track has no free wave: a real receptance;
    # at 150 Hz waves run freely, the Bloch integral has poles on its path and is refused
    track, law = Track.paper(pad_damping=0.0), LinearFoundation(20e6, 0.0)
    omega = 2 * np.pi * 50.0
    assert point_receptance(track, law, omega) == pytest.approx(
        _fe_receptance(track, law, omega).real, rel=2e-5)
    with pytest.raises(ValueError, match="damping"):
        point_receptance(track, law, 2 * np.pi * 150.0, phases=256)


@pytest.mark.parametrize("mass, stiffness, damping", [(80.0, 40e6, 0.0), (700.0, 3e8, 2e5)])
def test_fit_recovers_a_one_mass_track(mass, stiffness, damping):
    fit = fit_equivalent_track(lambda w: 1 / (stiffness - mass * w**2 + 1j * damping * w))
    assert fit.mass == pytest.approx(mass, rel=1e-10)
    assert fit.stiffness == pytest.approx(stiffness, rel=1e-12)
    assert fit.damping == pytest.approx(damping, rel=1e-10, abs=1e-6)


def test_fit_reports_a_missing_resonance():
    with pytest.raises(ValueError, match="omega_max"):
        fit_equivalent_track(lambda w: 1 / (1e8 - 1.0 * w**2 + 0j), omega_max=100.0)


def test_equivalent_track_of_a_close_winkler_track():
    # static stiffness 8 EI beta^3; the mass and damping reproduce D at the phase resonance
    modulus, damping = 50e6, 40e3
    track, law = _winkler_track(0.05, modulus, damping)
    fit = equivalent_track(track, law, omega_max=2 * np.pi * 400.0)
    assert fit.stiffness == pytest.approx(1 / _hetenyi(track, modulus, damping, 0.0).real, rel=2e-4)
    resonance = math.sqrt(fit.stiffness / fit.mass)
    stiffness = 1 / _hetenyi(track, modulus, damping, resonance)
    assert abs(stiffness.real) < 1e-3 * fit.stiffness
    assert stiffness.imag / resonance == pytest.approx(fit.damping, rel=1e-3)
