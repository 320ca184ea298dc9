"""railtrack.equations.rail_field and the Solution's rail between sleepers.

Oracles, each independent of the closed form under test:
* eq. (3) and today's ``rail_displacement(t)`` at x = 0;
* the brute-force Poisson sum over wavenumbers (no partial fractions);
* the rail's periodicity w_r(x + L, t) = w_r(x, t - L/v);
* a static finite-element beam on discrete springs (Hermite cubics, exact
  for point loads at nodes) at a very low train speed;
* Winkler's beam on an elastic foundation (Zimmermann) as L -> 0 with the
  support stiffness per metre fixed;
* statics of the rail (mean rail-seat load 2 Q L / H), the pad law of eq. (5)
  and the sleeper's equation of motion;
* finite differences in x.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations import rail_field as rf
from railtrack.equations.receptance import bending_wavenumber, critical_frequency, rail_receptance

PASSAGE = rt.Passage.paper()
L = PASSAGE.sleeper_spacing
LINEAR = rt.LinearFoundation(20e6, 0.2e6)


def solved(passage=PASSAGE, foundation=LINEAR, m=15, method="newton"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.TruncationWarning)
        return rt.solve(passage.track, passage.train, foundation, m, method=method)


# --- x = 0 and the closed form ------------------------------------------------

def test_offset_receptance_at_zero_is_eq_3():
    omega = np.array([-400.0, -3.0, 0.5, 15.7, 80.0, 900.0, 5000.0])
    value = rf.offset_receptance(PASSAGE, omega, [0.0])[0]
    assert np.max(np.abs(value - rail_receptance(PASSAGE, omega)) / np.abs(value)) < 1e-13


def test_rail_displacement_at_zero_is_todays_result():
    sol = solved()
    t = np.linspace(0.0, sol.period, 300)
    today = sol.rail_displacement(t)
    assert np.array_equal(sol.rail_displacement(t, 0.0), today)
    both = sol.rail_displacement(t[:, None], np.array([0.0, 0.25]))
    assert np.max(np.abs(both[:, 0] - today)) <= 1e-15 * np.max(np.abs(today))


@pytest.mark.parametrize("derivative", [0, 2])
def test_closed_form_equals_brute_force_poisson_sum(derivative):
    omega = np.array([-300.0, -5.0, 1e-3, 3.0, 50.0, 500.0, 3000.0])
    x = np.array([0.0, 0.1, 0.3, 0.55, 0.6, -0.4, 1.7])
    closed = rf.offset_receptance(PASSAGE, omega, x, derivative)
    brute = rf.offset_receptance_lattice_sum(PASSAGE, omega, x, derivative, terms=200_000)
    # the curvature's brute sum falls like 1/terms
    tolerance = 1e-12 if derivative == 0 else 3e-6
    assert np.max(np.abs(closed - brute) / np.abs(brute)) < tolerance


def brute_kernels(passage, omega, xi, terms=200_000):
    """Lambda, Lambda_2 by summing j != 0 directly; Lambda_2's 1/(2 pi j)^2 part is summed as
    the Fourier series of a parabola, sum e^{-2 pi i j xi}/(2 pi j)^2 = (xi^2 - xi + 1/6)/2."""
    from railtrack.equations.receptance import receptance_factors
    q = omega * passage.sleeper_spacing / passage.speed
    a = bending_wavenumber(passage, omega) * passage.sleeper_spacing
    gap = receptance_factors(passage, omega).gap
    j = np.arange(-terms, terms + 1)
    j = j[j != 0][:, None]
    u = q + 2 * np.pi * j
    f = 1.0 / (u**4 - a**4)
    lam, lam2 = [], []
    for s in xi:
        e = np.exp(-2j * np.pi * j * s)
        lam.append(np.sum((e - 1.0) * f, axis=0))
        rest = np.sum(q**2 * f - e * (u**2 * f - 1.0 / (2 * np.pi * j) ** 2), axis=0)
        lam2.append(rest - (s * s - s + 1.0 / 6.0) / 2.0)
    shift = np.exp(-1j * np.outer(xi, q))
    return 4 * gap * shift * np.array(lam), 4 * gap * shift * np.array(lam2)


def test_difference_kernels_against_brute_force_including_the_singular_frequencies():
    star = critical_frequency(PASSAGE)
    omega = np.array([0.0, 1e-6, 1e-2, 3.0, star, star * (1 + 1e-9), 15.7, 50.0, 120.0,
                      500.0, 3000.0, -50.0])
    xi = np.array([0.0, 0.1, 0.5, 0.77, 1.0])
    lam, lam2 = rf.difference_kernels(PASSAGE, omega, xi)
    ref, ref2 = brute_kernels(PASSAGE, omega, xi)
    assert np.all(np.isfinite(lam)) and np.all(np.isfinite(lam2))
    assert np.max(np.abs(lam - ref)) < 1e-12 * np.max(np.abs(ref))
    assert np.max(np.abs(lam2 - ref2)) < 1e-10 * np.max(np.abs(ref2))


# --- periodicity ---------------------------------------------------------------

def test_periodicity_across_spans():
    sol = solved(foundation=rt.BilinearFoundation.paper(ratio=0.5))
    t = np.linspace(0.0, sol.period, 257)
    v = PASSAGE.speed
    w0 = sol.rail_displacement(t - L / v)
    scale = np.max(np.abs(w0))
    # just below x = L the closed form (xi -> 1) must meet the next sleeper's history
    assert np.max(np.abs(sol.rail_displacement(t, L * (1 - 1e-12)) - w0)) < 1e-12 * scale
    assert np.max(np.abs(sol.rail_displacement(t, L) - w0)) < 1e-14 * scale
    for x in (0.17, 0.45, -0.2):
        ahead = sol.rail_displacement(t, x + L)
        here = sol.rail_displacement(t - L / v, x)
        assert np.max(np.abs(ahead - here)) < 1e-13 * scale
    m_left = sol.rail_bending_moment(t, -1e-12)
    m_zero = sol.rail_bending_moment(t, 0.0)
    assert np.max(np.abs(m_left - m_zero)) < 1e-9 * np.max(np.abs(m_zero))


# --- static limit: a finite-element beam on springs ----------------------------

def fe_beam(ei, span, k_s, loads, x_obs, half_length=40.0, per_span=4):
    """Static Euler-Bernoulli beam, Hermite elements of span/per_span, springs k_s at x = n span.

    loads: (position, downward force) pairs at nodes.  Returns w [m] and EI w'' [N m] at x_obs
    (nodes).  Exact for point loads at nodes, up to the free ends far away.
    """
    h = span / per_span
    nodes = np.arange(-round(half_length / h), round(half_length / h) + 1) * h
    n = nodes.size
    stiffness = np.zeros((2 * n, 2 * n))
    force = np.zeros(2 * n)
    ke = ei / h**3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                               [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    for e in range(n - 1):
        stiffness[2 * e:2 * e + 4, 2 * e:2 * e + 4] += ke
    on_sleeper = np.isclose(np.mod(nodes / span + 0.5, 1.0) - 0.5, 0.0, atol=1e-9)
    dof = 2 * np.flatnonzero(on_sleeper)
    stiffness[dof, dof] += k_s
    for position, load in loads:
        i = int(np.argmin(np.abs(nodes - position)))
        assert abs(nodes[i] - position) < 1e-9
        force[2 * i] -= load
    u = np.linalg.solve(stiffness, force)
    w, moment = [], []
    for x in x_obs:
        i = int(np.argmin(np.abs(nodes - x)))
        e, s = (i, 0.0) if i < n - 1 else (i - 1, 1.0)
        b = np.array([(-6 + 12 * s) / h**2, (-4 + 6 * s) / h, (6 - 12 * s) / h**2, (-2 + 6 * s) / h])
        w.append(u[2 * i])
        moment.append(ei * b @ u[2 * e:2 * e + 4])
    return np.array(w), np.array(moment)


def test_static_limit_equals_a_beam_on_discrete_springs():
    passage = PASSAGE.replace(speed=1e-3, wagon_length=120 * L)   # neighbours 72 m away
    k2 = 20e6
    k_s = passage.pad_stiffness * k2 / (passage.pad_stiffness + k2)
    foundation = rt.LinearFoundation(k2, 0.0)
    sols = {m: solved(passage, foundation, m, "analytic") for m in (1600, 3200)}
    x_obs = np.array([0.0, L / 2])
    for front in (0.0, L / 4, L / 2):        # front wheel above the sleeper, a quarter, mid-span
        t = front / passage.speed
        loads = [(front, passage.wheel_load), (front - passage.wheel_spacing, passage.wheel_load)]
        w_fe, m_fe = fe_beam(passage.rail_bending_stiffness, L, k_s, loads, x_obs)
        w = sols[1600].rail_displacement(t, x_obs)
        assert np.max(np.abs(w - w_fe) / np.abs(w_fe)) < 1e-6
        moment = sols[3200].rail_bending_moment(t, x_obs)
        # under a wheel the moment has a kink in t, where its Fourier series converges
        # like 1/m: there extrapolate m = 1600, 3200 to m -> infinity (Richardson)
        under = np.isclose(x_obs, front)
        moment[under] = (2 * moment - sols[1600].rail_bending_moment(t, x_obs))[under]
        assert np.max(np.abs(moment - m_fe) / np.abs(m_fe)) < 3e-4
    assert w_fe[1] < 0 and m_fe[1] > 0       # wheel at mid-span: rail down, sagging


# --- Winkler limit ------------------------------------------------------------------

def test_winkler_limit_of_closely_spaced_sleepers():
    base = rt.Passage(rt.Track.paper(), rt.Train.paper(wheel_spacing=6.0, speed=1e-3, wagon_length=12.0))
    k2 = 20e6
    per_metre = base.pad_stiffness * k2 / (base.pad_stiffness + k2) / L
    ei, load = base.rail_bending_stiffness, base.wheel_load
    lam = (per_metre / (4 * ei)) ** 0.25
    d = 6.0 * np.arange(-40, 41)             # every wheel of the periodic train, 6 m apart
    decay = np.exp(-lam * np.abs(d))
    w_ref = -(load * lam / (2 * per_metre)) * np.sum(decay * (np.cos(lam * d) + np.sin(lam * np.abs(d))))
    m_ref = (load / (4 * lam)) * np.sum(decay * (np.cos(lam * d) - np.sin(lam * np.abs(d))))
    assert abs(w_ref / (-load * lam / (2 * per_metre)) - 1) < 5e-3   # nearly one load alone
    w_err, m_err = [], []
    for span in (0.6, 0.3, 0.15, 0.075):
        s = span / L
        passage = base.replace(sleeper_spacing=span, pad_stiffness=base.pad_stiffness * s,
                               sleeper_mass=base.sleeper_mass * s)
        foundation = rt.LinearFoundation(k2 * s, 0.0)
        one, two = (solved(passage, foundation, m, "analytic") for m in (1000, 2000))
        w_err.append(two.rail_displacement(0.0)[()] / w_ref - 1)
        moment = 2 * two.rail_bending_moment(0.0) - one.rail_bending_moment(0.0)
        m_err.append(moment[()] / m_ref - 1)
    w_err, m_err = np.abs(w_err), np.abs(m_err)
    assert np.all(np.diff(w_err) < 0) and w_err[-1] < 1e-6
    assert np.all(np.diff(m_err) < 0) and m_err[-1] < 2e-3
    assert 3.0 < m_err[-2] / m_err[-1] < 5.0    # the moment's error falls like L^2


# --- rail-seat load -----------------------------------------------------------------

@pytest.mark.parametrize("foundation", [
    LINEAR, rt.BilinearFoundation.paper(ratio=0.5), rt.BilinearFoundation.paper(ratio=0.0),
    rt.CubicFoundation.paper()], ids=["linear", "bilinear-0.5", "bilinear-0", "cubic"])
def test_mean_rail_seat_load_is_the_train_weight_per_sleeper(foundation):
    sol = solved(foundation=foundation, m=31)
    t = np.linspace(0.0, sol.period, 4096, endpoint=False)
    seat = sol.rail_seat_load(t)
    target = 2 * PASSAGE.wheel_load * L / PASSAGE.wagon_length
    assert abs(seat.mean() / target - 1) < 1e-12
    assert seat.max() > target                # compression positive: peaks under the wheels
    # the foundation carries the same mean in compression (foundation_force is positive in
    # compression; the sleeper's mass has no mean acceleration); the solver balances the mean
    # on its own AFT grid, so a kinked law sampled more finely differs by a few 1e-6
    assert abs(sol.foundation_force(t).mean() / target - 1) < 1e-4
    # the pad law of eq. (5), with the rail's velocity by central differences
    h = 1e-7
    rail_velocity = (sol.rail_displacement(t + h) - sol.rail_displacement(t - h)) / (2 * h)
    pad = (PASSAGE.pad_stiffness * (sol.sleeper_displacement(t) - sol.rail_displacement(t))
           + PASSAGE.pad_damping * (sol.sleeper_velocity(t) - rail_velocity))
    assert np.max(np.abs(seat - pad)) < 1e-6 * np.max(np.abs(seat))


def test_rail_seat_load_balances_the_sleeper():
    sol = solved(m=31)
    t = np.linspace(0.0, sol.period, 600)
    omega = sol.frequencies
    acceleration = np.real(np.exp(1j * np.outer(t, omega)) @ (-(omega**2) * sol.coefficients))
    # eq. (4): M w'' + f = -(pad force on the sleeper, compression positive), where the law's
    # f is minus the foundation force (which is compression positive)
    sleeper = sol.foundation_force(t) - PASSAGE.sleeper_mass * acceleration
    seat = sol.rail_seat_load(t)
    assert np.max(np.abs(seat - sleeper)) < 1e-9 * np.max(np.abs(seat))


# --- bending moment against finite differences -------------------------------------

def test_bending_moment_is_ei_times_the_second_difference_of_the_displacement():
    sol = solved(foundation=rt.CubicFoundation.paper(), m=25)
    h = 1e-3
    x = np.array([0.07, 0.2, 0.31, 0.52, 1.1, -0.25])
    t = np.array([0.05, 0.13, 0.31]) * sol.period    # no wheel within h of these x
    wheels = np.mod(PASSAGE.speed * t[:, None] - np.array([0.0, -PASSAGE.wheel_spacing]), PASSAGE.wagon_length)
    assert np.min(np.abs(np.mod(wheels[..., None] - x, PASSAGE.wagon_length))) > 0.01
    T, X = np.meshgrid(t, x, indexing="ij")
    # the moment at m = 25 sums its kinks in closed form; the displacement's
    # second difference has them only up to m, so take it from m = 400, where
    # away from the wheels the plain series has converged
    fine = solved(foundation=rt.CubicFoundation.paper(), m=400)
    second = (fine.rail_displacement(T, X + h) - 2 * fine.rail_displacement(T, X)
              + fine.rail_displacement(T, X - h)) / h**2
    moment = sol.rail_bending_moment(T, X)
    ei = PASSAGE.rail_bending_stiffness
    assert np.max(np.abs(moment - ei * second)) < 2e-3 * np.max(np.abs(moment))
