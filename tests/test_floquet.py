"""Floquet multipliers by Hill's method (railtrack.equations.hill, railtrack.solvers.floquet).

Independent truths: the lattice sum of the free beam's Green function for
the receptance at complex frequency; a finite difference of the residual
of eq. (17) for Hill's matrix at lambda = 0; on a linear foundation, where
Hill's matrix is diagonal, a scalar Newton iteration on each diagonal
entry; and the time-domain ring's watched verdicts at 525 m/s on the fold
track of chapter 10.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations.aft_jacobian import tangent_harmonics
from railtrack.equations.harmonic_balance import harmonic_system, residual, two_sided
from railtrack.equations.hill import (
    bloch_phases,
    complex_receptance,
    condensed_stiffness,
    hill_matrix,
    tangent_toeplitz,
)
from railtrack.solvers.floquet import floquet

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000)


def lattice_receptance(passage, s, q, terms=20_000):
    """sum_j 1 / (EI L (kappa_j^4 - k_b^4)), kappa_j = (q + 2 pi j) / L, k_b^4 = -rho S s^2 / EI."""
    span, stiffness = passage.sleeper_spacing, passage.rail_bending_stiffness
    a4 = -passage.rail_linear_mass / stiffness * np.asarray(s, complex) ** 2 * span**4
    j = np.arange(-terms, terms + 1)
    total = np.sum(1.0 / ((np.asarray(q)[..., None] + 2 * np.pi * j) ** 4 - a4[..., None]), axis=-1)
    return (total + 2.0 / (3.0 * terms**3 * (2 * np.pi) ** 4)) * span**3 / stiffness


def test_receptance_at_complex_frequency_is_the_lattice_sum():
    passage = rt.Passage.paper()
    s = np.array([3 + 200j, -50 + 10j, 1e-4 + 1e-5j, 0.01j, 2000j, -300 + 4000j, -80.0])
    q = np.array([0.3, 1.0, 0.0, 0.2, 2.5, 0.0, 3.0])
    np.testing.assert_allclose(complex_receptance(passage, s, q), lattice_receptance(passage, s, q),
                               rtol=1e-9)


def test_rigid_rail_limit_at_zero_frequency_and_phase():
    # s -> 0 at q = 0: every sleeper pushes the rail alike, which moves as a mass rho S L
    passage = rt.Passage.paper()
    s = 1e-3 + 2e-3j
    expected = 1.0 / (passage.rail_linear_mass * passage.sleeper_spacing * s**2)
    assert abs(complex_receptance(passage, s, 0.0) / expected - 1) < 1e-6
    assert abs(condensed_stiffness(passage, 0.0, 0.0)) < 1e-6  # the track moves as a body


@pytest.fixture(scope="module")
def fold_solution():
    return rt.solve(FOLD_TRACK, rt.Train.paper(speed=525.0), FOLD_LAW, harmonics=25)


def test_hill_matrix_at_zero_is_the_jacobian(fold_solution):
    solution, m = fold_solution, fold_solution.harmonics
    system = harmonic_system(solution.passage, solution.foundation, m)
    toeplitz = tangent_toeplitz(*tangent_harmonics(system, solution.coefficients[m:]))
    hill = hill_matrix(solution.passage, toeplitz, 0.0, 0.0)
    rng = np.random.default_rng(1)
    direction = rng.normal(size=m + 1) + 1j * rng.normal(size=m + 1)
    direction[0] = direction[0].real
    c, step = solution.coefficients[m:], 1e-9
    change = (residual(system, c + step * direction) - residual(system, c - step * direction)) / (
        2 * step)
    product = (hill @ two_sided(direction))[m:]
    scale = np.max(np.abs(product))
    assert np.max(np.abs(product - solution.passage.sleeper_mass * change)) < 1e-8 * scale


def lattice_stiffness(passage, s, q):
    """M s^2 + A / (1 + A eta), A = k1 + eta1 s, eta by the lattice sum: the sleeper, its pad
    and the rail of eqs. (4)-(8) at complex frequency, written out here."""
    pad = passage.pad_stiffness + passage.pad_damping * s
    return passage.sleeper_mass * s**2 + pad / (1 + pad * lattice_receptance(passage, s, q))


def test_condensed_stiffness_at_complex_frequency_is_the_lattice_sleeper():
    passage = rt.Passage(rt.Track.paper(pad_damping=30e3), rt.Train.paper(speed=300.0))
    s = np.array([3 + 200j, -50 + 10j, 0.01j, 2000j, -300 + 4000j, -80.0, 40 - 900j])
    q = np.array([0.3, 1.0, 0.2, 2.5, 0.0, 3.0, -1.2])
    np.testing.assert_allclose(condensed_stiffness(passage, s, q), lattice_stiffness(passage, s, q),
                               rtol=1e-8)


def test_condensed_stiffness_is_analytic_in_s():
    # Cauchy-Riemann: dD/dRe(s) = -i dD/dIm(s), by central differences, away from
    # the real axis and across the series/closed-form switch of the bending functions
    passage = rt.Passage(rt.Track.paper(pad_damping=30e3), rt.Train.paper(speed=300.0))
    for s, q in ((3 + 200j, 0.3), (-40 + 1500j, 1.1), (25 - 3000j, 2.0), (-5 + 60j, 0.0)):
        h = 1e-4 * abs(s)
        along = (condensed_stiffness(passage, s + h, q) - condensed_stiffness(passage, s - h, q))
        across = (condensed_stiffness(passage, s + 1j * h, q)
                  - condensed_stiffness(passage, s - 1j * h, q))
        assert abs(along + 1j * across) < 1e-6 * abs(along)


def _secant_root(function, z0, z1, steps=60):
    f0, f1 = function(z0), function(z1)
    for _ in range(steps):
        z0, z1 = z1, z1 - f1 * (z1 - z0) / (f1 - f0)
        f0, f1 = f1, function(z1)
        if abs(z1 - z0) < 1e-12 * max(1.0, abs(z1)):
            return z1
    raise AssertionError("no convergence")


def test_linear_foundation_exponents_are_the_free_waves():
    # K and C are constants, so H is diagonal: each exponent solves, for one k,
    # M s^2 + A / (1 + A eta(s, q)) + k2 + eta2 s = 0, s = lambda + i k Omega,
    # written here with the lattice sum of eq. (3) (not with hill.py)
    law = rt.LinearFoundation(20e6, 20e3)
    track = rt.Track.paper(pad_damping=30e3)
    solution = rt.solve(track, rt.Train.paper(speed=300.0), law, harmonics=20)
    result = floquet(solution)
    passage = solution.passage
    omega = passage.fundamental_frequency
    assert result.stable and result.resolved.sum() >= 4
    k = np.arange(-20, 21)
    for exponent, phase in zip(result.exponents[:6], result.phases[:6]):
        def diagonal(lam, row):
            s = lam + 1j * k[row] * omega
            q = k[row] * omega * passage.sleeper_spacing / passage.speed - phase
            return complex(lattice_stiffness(passage, s, q) + law.stiffness + law.damping * s)
        sizes = [abs(diagonal(exponent, row)) for row in range(k.size)]
        row = int(np.argmin(sizes))
        scale = passage.sleeper_mass * abs(exponent + 1j * k[row] * omega) ** 2 + law.stiffness
        assert sizes[row] < 1e-6 * scale
        root = _secant_root(lambda z: diagonal(z, row), exponent + 0.3, exponent + 0.3 + 1e-3j)
        assert abs(root - exponent) < 1e-7 * abs(exponent)


@pytest.fixture(scope="module")
def fold_branch():
    return rt.continuation(FOLD_TRACK, rt.Train.paper(speed=300.0), FOLD_LAW, parameter="speed",
                           start=300.0, stop=560.0, harmonics=25)


@pytest.fixture(scope="module")
def five_solutions(fold_branch):
    return [rt.solve(FOLD_TRACK, rt.Train.paper(speed=525.0), FOLD_LAW, harmonics=25, initial=c)
            for c in fold_branch.solutions_at(525.0)]


def test_verdicts_at_525_match_the_ring(five_solutions):
    # chapter 10: the ring keeps the -2.54 and -1.51 mm solutions and leaves the
    # other three; it leaves the -1.607 mm one growing 1.92-fold per period.
    # The ring here is the linearised one (rt.ring_multipliers): its Newmark map
    # over a period, coarse (2 elements a span, 300 and 600 steps a period, the
    # step error extrapolated), an independent method for each verdict.
    dips = np.array([s.one_period()[1].min() * 1e3 for s in five_solutions])
    assert len(dips) == 5
    verdicts = {round(d, 2): floquet(s) for d, s in zip(dips, five_solutions)}
    assert sorted(d for d, f in verdicts.items() if f.stable) == [-2.54, -1.51]
    leaving = verdicts[-1.61]
    assert leaving.kind == "complex" and abs(abs(leaving.dominant) - 1.92) < 0.1
    # the two between the folds leave by a real multiplier above +1
    assert {verdicts[-2.41].kind, verdicts[-1.87].kind} == {"real +"}
    for dip, solution in zip(dips, five_solutions):
        ring = [rt.ring_multipliers(solution, elements_per_span=2, steps_per_period=steps)
                for steps in (300, 600)]
        extrapolated = _richardson(*(r.dominant for r in ring))
        hill = verdicts[round(dip, 2)]
        assert (extrapolated < 1) == hill.stable
        assert abs(extrapolated - abs(hill.dominant)) < 0.02 * max(1.0, abs(hill.dominant))


def test_bloch_phases_refuse_a_fractional_number_of_sleepers():
    passage = rt.Passage.paper().replace(wagon_length=18.0000001)
    with pytest.raises(ValueError, match="H/L = 30.00000016"):
        bloch_phases(passage)


def test_unconverged_solution_is_refused(fold_solution):
    bad = rt.solve(FOLD_TRACK, rt.Train.paper(speed=525.0), FOLD_LAW, harmonics=25,
                   max_iterations=1)
    assert not bad.converged
    with pytest.raises(ValueError, match="unconverged"):
        floquet(bad)


def _richardson(coarse, fine):
    """The ring's |mu| extrapolated from two step counts in the ratio 2 (Newmark: error ~ dt^2)."""
    return (4 * abs(fine) - abs(coarse)) / 3


@pytest.mark.slow
def test_multipliers_match_the_monodromy_of_the_linearised_ring(five_solutions):
    # The third, independent method: the ring's Newmark map linearised about the
    # same orbit, over one period (rt.ring_multipliers).  Both linearise the m = 25
    # orbit, Hill's matrix with 40 harmonics so that its own truncation is out
    # of the comparison; the ring's time-step error is extrapolated away.
    for solution in five_solutions:
        hill = abs(rt.floquet(solution, harmonics=40).dominant)
        ring = [rt.ring_multipliers(solution, steps_per_period=steps).dominant
                for steps in (1200, 2400)]
        assert abs(hill - _richardson(*ring)) < 1e-3


@pytest.mark.slow
def test_multipliers_of_disturbances_two_wagons_long_match_a_ring_of_two_wagons(five_solutions):
    # A ring of two wagons also carries disturbances that alternate from wagon
    # to wagon: Bloch phase pi per wagon, pi / 30 per sleeper.  Three of the
    # five solutions have a real negative multiplier there, on the edge of the
    # strip |Im lambda T| <= pi that Hill's exponents are kept in.
    kinds = []
    for solution in five_solutions:
        hill = rt.floquet(solution, np.pi / 30, harmonics=40)
        ring = []
        for steps in (2400, 4800):  # over the ring's period, two wagon periods
            r = rt.ring_multipliers(solution, wagons=2, steps_per_period=steps)
            sector = (np.abs(r.bloch_phase - np.pi) < 1e-9) & (r.sleeper_share > 1e-3)
            ring.append(r.multipliers[sector][0])
        assert abs(abs(hill.dominant) - _richardson(*ring)) < 1e-3
        kinds.append(hill.kind)
    assert kinds.count("real -") == 3


@pytest.mark.slow
def test_stable_to_disturbances_of_one_wagon_unstable_to_those_of_two(fold_branch):
    # At 539 m/s, between the second and the third fold, a solution is stable to
    # every disturbance that repeats each wagon, but not to one that alternates
    # from wagon to wagon (Bloch phase pi / 30 per sleeper): the one-wagon ring
    # stays on it, the two-wagon ring kicked by a small random disturbance leaves.
    solutions = [rt.solve(FOLD_TRACK, rt.Train.paper(speed=539.0), FOLD_LAW, harmonics=25,
                          initial=c) for c in fold_branch.solutions_at(539.0)]
    stable = sorted((s for s in solutions if rt.floquet(s).stable),
                    key=lambda s: s.one_period()[1].min())
    # three solutions, two of them stable: the deeper (-1.74 mm) is the one
    # between the folds, the other (-1.45 mm) is on the last part
    assert len(solutions) == 3 and len(stable) == 2
    solution = stable[0]
    scan = rt.floquet(solution, theta="scan")
    assert not scan.stable and scan.most_unstable > 0
    alternating = rt.floquet(solution, np.pi / 30)
    assert abs(alternating.dominant) > 1.2
    ring = dict(periods=20, max_periods=40, elements_per_span=4, kick=1e-4)
    one = rt.check_stability(solution, steps_per_period=600, **ring)
    two = rt.check_stability(solution, steps_per_period=1200, wagons=2, **ring)
    assert one.stable and not two.stable


@pytest.mark.slow
def test_coarse_contours_find_the_dominant_multiplier_and_24_points_find_all(fold_branch):
    # The contour integral finds candidates, Newton refines them: with too few
    # quadrature points a candidate can be missed.  check_branch's 16 points must
    # give the dominant multiplier, floquet's default 24 every multiplier, as 48
    # points do, on a sample of the fold branch from 300 to 560 m/s.
    def key(result):
        return sorted((round(abs(mu), 6), round(float(np.angle(mu)), 5), round(th, 6))
                      for mu, th in zip(result.multipliers, result.phases))
    for i in range(0, len(fold_branch), 9):
        solution = fold_branch.solution(i)
        fine = rt.floquet(solution, points=48)
        assert abs(rt.floquet(solution, points=16).dominant - fine.dominant) < 1e-9
        assert fine.theta <= np.pi and (fine.kind != "complex" or fine.dominant.imag > 0
                                        or fine.theta > 0)
        assert key(rt.floquet(solution)) == key(fine)
