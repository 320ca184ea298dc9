"""Pseudo-arclength continuation (`railtrack.continuation`), against independent solves.

The truth is never the continuation itself: single solves of eq. (23) for a
linear law, `railtrack.solve` at the end points, the residual of eq. (17)
recomputed from scratch, and a multi-start Newton search that counts the
periodic solutions at one speed without knowing the branch.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.studies.continuation import Branch, continuation
from railtrack.equations.aft_jacobian import residual_jacobian
from railtrack.equations.harmonic_balance import harmonic_system, residual, residual_norm
from railtrack.solvers.newton import iterate_newton, linear_guess

# The case with folds (GitHub issue 9): stiff-damped pads, a softly damped
# hardening foundation.  m = 25: the estimated truncation error stays below
# 1e-3 over the whole branch and the folds move by < 0.03 m/s from m = 25 to
# 40, where m = 15 leaves 3 % and shifts the first fold by 2 m/s.
FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)
FOLD_M = 25


@pytest.fixture(scope="module")
def fold_branch() -> Branch:
    return continuation(FOLD_TRACK, rt.Train.paper(speed=300.0), FOLD_LAW, "speed",
                        start=300.0, stop=600.0, harmonics=FOLD_M)


def _distinct(solutions, rtol=1e-6):
    kept = []
    for c in solutions:
        if not any(np.linalg.norm(c - k) <= rtol * np.linalg.norm(k) for k in kept):
            kept.append(c)
    return kept


def _multistart(speed: float, starts: int = 480) -> list[np.ndarray]:
    """Distinct solutions at `speed` from damped Newton started at random points.

    The starts are the linear responses of foundations 1 to 20 times stiffer
    than k2 at rest, scaled by 0.5..2 with random amplitude and phase
    perturbations of each harmonic; nothing is taken from the branch.  The
    solutions on the middle of an S of the curve have small basins: 240
    starts find all of them at neither 500 nor 520 m/s, 480 do.
    """
    rng = np.random.default_rng(0)
    passage = rt.Passage(FOLD_TRACK, rt.Train.paper(speed=speed))
    system = harmonic_system(passage, FOLD_LAW, FOLD_M)
    guesses = [linear_guess(harmonic_system(passage, rt.LinearFoundation(k, 5000.0), FOLD_M))
               for k in np.geomspace(20e6, 4e8, 8)]
    found = []
    for i in range(starts):
        c = guesses[i % len(guesses)] * rng.uniform(0.5, 2.0)
        c[1:] *= rng.uniform(0.5, 1.5, FOLD_M) * np.exp(1j * rng.normal(0.0, 0.7, FOLD_M))
        outcome = iterate_newton(system, 60, 1e-10, initial=c)
        if outcome.converged:
            found.append(outcome.coefficients)
    return _distinct(found)


def _polished(branch: Branch, speed: float) -> list[np.ndarray]:
    """The branch's solutions at `speed`: its crossings, polished by Newton at that speed."""
    system = harmonic_system(rt.Passage(FOLD_TRACK, rt.Train.paper(speed=speed)), FOLD_LAW, FOLD_M)
    polished = []
    for c in branch.solutions_at(speed):
        outcome = iterate_newton(system, 20, 1e-10, initial=c)
        assert outcome.converged, outcome.message
        polished.append(outcome.coefficients)
    return _distinct(polished)


def test_linear_branch_equals_single_analytic_solves():
    track, train, law = rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper()
    branch = continuation(track, train, law, "speed", start=20.0, stop=120.0, harmonics=15)
    assert branch.folds == () and branch.message.startswith("reached speed = 120.0")
    assert branch.values[0] == 20.0 and branch.values[-1] == 120.0
    assert np.all(np.diff(branch.values) > 0)
    for value, c in zip(branch.values, branch.coefficients):
        exact = rt.solve(track, train.replace(speed=value), law, 15, method="analytic")
        truth = exact.coefficients[15:]
        assert np.linalg.norm(c - truth) <= 1e-8 * np.linalg.norm(truth), value


@pytest.mark.parametrize("parameter, start, stop, changed", [
    ("pad_damping", 50e3, 150e3, "track"),
    ("epsilon", 0.0, 1.0, "foundation"),
    ("wagon_length", 18.0, 24.0, "train"),
])
def test_end_point_equals_a_solve_there(parameter, start, stop, changed):
    track, train, law = rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper()
    branch = continuation(track, train, law, parameter, start=start, stop=stop, harmonics=25)
    assert branch.values[-1] == stop and branch.parameter == parameter
    parts = {"track": track, "train": train, "foundation": law}
    parts[changed] = (
        parts[changed].replace(**{parameter: stop}) if changed != "foundation"
        else rt.CubicFoundation(law.stiffness, law.cubic_stiffness, stop, law.damping))
    truth = rt.solve(parts["track"], parts["train"], parts["foundation"], 25).coefficients
    end = branch.solution(-1)
    assert getattr(end.passage if changed != "foundation" else end.foundation, parameter) == stop
    assert np.linalg.norm(end.coefficients - truth) <= 1e-8 * np.linalg.norm(truth)


@pytest.mark.slow
def test_branch_holds_every_solution_that_multistart_finds(fold_branch):
    folds = fold_branch.fold_values
    assert len(folds) == 4
    for speed, count in ((500.0, 3), (520.0, 5)):
        assert folds.min() < speed < folds.max()
        searched, on_branch = _multistart(speed), _polished(fold_branch, speed)
        assert len(searched) == len(on_branch) == count, speed
        for c in searched:   # each solution found is one of the branch's
            assert min(np.linalg.norm(c - b) for b in on_branch) <= 1e-6 * np.linalg.norm(c)
    for speed in (folds.min() - 5.0, folds.max() + 5.0):   # outside the folds: one solution
        assert len(_multistart(speed, 48)) == len(_polished(fold_branch, speed)) == 1, speed


def test_folds_are_where_the_jacobian_is_singular(fold_branch):
    """At a fold dR/dx is singular: its determinant changes sign across each reported fold."""
    def sign(i):
        system = harmonic_system(rt.Passage(FOLD_TRACK, rt.Train.paper(speed=fold_branch.values[i])),
                                 FOLD_LAW, FOLD_M)
        return np.linalg.slogdet(residual_jacobian(system, fold_branch.coefficients[i]))[0]
    signs = np.array([sign(i) for i in range(len(fold_branch))])
    flips = np.flatnonzero(signs[1:] != signs[:-1])
    assert [fold.index for fold in fold_branch.folds] == flips.tolist()
    for fold in fold_branch.folds:
        # the turning value lies beyond both neighbours, on the side the branch turns back from
        near = fold_branch.values[fold.index : fold.index + 2]
        assert near.max() <= fold.value + 1e-9 or near.min() >= fold.value - 1e-9
        assert abs(fold.value - near.mean()) < 5.0


def test_every_point_converged_and_solves_eq_17(fold_branch):
    assert fold_branch.message.startswith("reached speed = 600.0")
    assert fold_branch.converged.shape == fold_branch.values.shape and fold_branch.converged.all()
    for value, c in zip(fold_branch.values, fold_branch.coefficients):
        system = harmonic_system(rt.Passage(FOLD_TRACK, rt.Train.paper(speed=value)),
                                 FOLD_LAW, FOLD_M)
        assert residual_norm(system, residual(system, c)) <= 1e-10
    assert fold_branch.stable is None
    assert max(fold_branch.solution(i).truncation_error for i in range(0, len(fold_branch), 7)) < 1e-3


@pytest.mark.parametrize("changes, match", [
    (dict(parameter="sped", start=40.0, stop=50.0), "'sped'"),
    (dict(parameter="axle_loads", start=40.0, stop=50.0), "'axle_loads'"),
    (dict(parameter="speed", start=45.0, stop=45.0), "'speed'"),
    (dict(parameter="speed", start=[40.0, 45.0], stop=50.0), "'speed'"),
    (dict(parameter="speed", start=40.0, stop="fast"), "'speed'"),
    (dict(parameter="damping", start=1.0, stop=np.inf), "'damping'"),
])
def test_bad_input_names_the_parameter(changes, match):
    with pytest.raises(ValueError, match=match):
        continuation(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(), **changes)
