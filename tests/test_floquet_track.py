"""Floquet multipliers continued from a neighbouring solution (``rt.floquet(..., guess=)``).

Truth: the full contour search of the same solution (Beyn's method over the
whole box and every phase), an independent computation of the same
exponents, and at one point the ring linearised about the orbit
(`rt.ring_multipliers`).  The continuation must give the same multipliers,
the same verdict where it is trusted, never a "stable" the search behind it
did not prove, and must hand over to the full search where the spectrum
moved too far.
"""

import numpy as np
import pytest

import railtrack as rt

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)


def _solved(speed, m, initial=None):
    solution = rt.solve(FOLD_TRACK, rt.Train.paper(speed=speed), FOLD_LAW, harmonics=m,
                        initial=initial, stability="off")
    assert solution.converged
    return solution


@pytest.mark.parametrize("speed, m, verdict", [(450.0, 25, "stable"), (525.0, 25, "unstable"),
                                                (595.0, 25, "unstable"), (450.0, 60, "stable")])
def test_continued_multipliers_are_the_full_searchs(speed, m, verdict):
    before = _solved(speed - 2.0, m)
    after = _solved(speed, m, before.coefficients[m:])
    full = rt.floquet(after)
    continued = rt.floquet(after, guess=rt.floquet(before))
    assert continued.continued and not full.continued
    assert continued.verdict == full.verdict == verdict
    assert abs(continued.dominant - full.dominant) < 1e-8
    # every multiplier the search found above the ceiling, by the same one continued;
    # the ceiling bounds those not continued, and lies below the dominant one
    assert full.ceiling == 0.01 and continued.ceiling < 0.8 * abs(full.dominant)
    listed = np.abs(full.multipliers) > continued.ceiling
    count = int(listed.sum())
    assert np.all(np.abs(continued.multipliers[:count]) > continued.ceiling)
    np.testing.assert_allclose(continued.multipliers[:count], full.multipliers[listed],
                               atol=1e-8)
    np.testing.assert_allclose(continued.phases[:count], full.phases[listed], atol=1e-9)
    assert "continued by Newton" in continued.message


def test_the_continued_dominant_multiplier_is_the_rings():
    # 595 m/s: just past the torus of the plain branch, |mu| = 1.023 (the ring, coarse
    # and extrapolated in its time step, test_floquet_threshold)
    before = _solved(593.0, 25)
    after = _solved(595.0, 25, before.coefficients[25:])
    continued = rt.floquet(after, guess=rt.floquet(before))
    coarse, fine = (abs(rt.ring_multipliers(after, elements_per_span=2,
                                            steps_per_period=steps).dominant)
                    for steps in (300, 600))
    assert continued.continued
    assert abs(abs(continued.dominant) - (4 * fine - coarse) / 3) < 2e-3


def test_too_far_a_guess_hands_over_to_the_full_search():
    # From 300 to 450 m/s the spectrum moves by more than the continuation trusts
    far = rt.floquet(_solved(300.0, 25))
    after = _solved(450.0, 25)
    result = rt.floquet(after, guess=far)
    full = rt.floquet(after)
    assert not result.continued and result.verdict == "stable"
    np.testing.assert_allclose(result.multipliers, full.multipliers, atol=1e-8)


def test_a_continued_stable_needs_a_searched_stable_behind_it():
    before, after = _solved(448.0, 25), _solved(450.0, 25)
    guess = rt.floquet(before, max_multiplier=2.0)      # box below the estimate: unknown
    assert guess.verdict == "unknown"
    continued = rt.floquet(after, guess=guess)
    assert continued.continued and continued.verdict == "unknown" and continued.stable is None
    with pytest.raises(ValueError, match="theta"):
        rt.floquet(after, np.pi / 30, guess=rt.floquet(before))
    with pytest.raises(TypeError, match="guess"):
        rt.floquet(after, guess=after)


@pytest.fixture(scope="module")
def across_the_torus():
    branch = rt.continuation(FOLD_TRACK, rt.Train.paper(speed=575.0), FOLD_LAW, "speed",
                             start=575.0, stop=605.0, harmonics=25)
    return branch, rt.check_branch(branch)


def test_check_branch_continues_and_agrees_with_the_full_search(across_the_torus):
    branch, marked = across_the_torus
    continued = [i for i, check in marked.checks.items() if check.continued]
    assert len(continued) > len(branch) // 2
    for i in range(len(branch)):
        full = rt.floquet(branch.solution(i), points=16)
        assert marked.checks[i].verdict == full.verdict
        assert abs(marked.multipliers[i] - full.dominant) < 1e-8
    # the one change, a complex pair leaving the unit circle: its stable side searched
    # in full, its unstable side in full or by a multiplier found outside
    [change] = marked.changes
    assert change.kind == "complex" and not change.gains and 587.9 < change.value < 596.3
    assert not marked.checks[change.index].continued
    assert marked.checks[change.index + 1].verdict == "unstable"


def test_hill_slope_is_the_cauchy_integral_of_the_condensed_stiffness():
    # D'(s) = (1 / 2 pi i) \oint D(w) / (w - s)^2 dw on a small circle: D is analytic in s
    from railtrack.equations.hill import condensed_stiffness, hill_matrix, hill_matrix_slope
    passage = rt.Passage(FOLD_TRACK, rt.Train.paper(speed=450.0))
    m = 6
    toeplitz = np.zeros((2, 2 * m + 1, 2 * m + 1))
    toeplitz[0] = 1e6 * np.eye(2 * m + 1)
    exponent, theta = np.array([-20.0 + 35.0j, 3.0 - 60.0j]), np.array([0.3, 2.0])
    matrix, slope = hill_matrix_slope(passage, toeplitz, exponent, theta)
    np.testing.assert_allclose(matrix, hill_matrix(passage, toeplitz, exponent, theta),
                               rtol=1e-14)
    k = np.arange(-m, m + 1)
    omega = passage.fundamental_frequency
    s = exponent[:, None] + 1j * omega * k
    q = k * omega * passage.sleeper_spacing / passage.speed - theta[:, None]
    circle = 5.0 * np.exp(2j * np.pi * np.arange(64) / 64)
    values = condensed_stiffness(passage, s[..., None] + circle, q[..., None])
    cauchy = np.mean(values / circle, axis=-1)
    np.testing.assert_allclose(slope, cauchy, rtol=1e-8)
