"""`solve(..., ground=...)` (eq. G2 of railtrack.equations.ground_lattice) against a rigid
ground, the Winkler limit (a spring in series with the law), a per-harmonic closed form of
the linear track with the ground in series, and the sleeper's own equation (17) with the
ground's motion summed over sleepers in space."""

import dataclasses

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations.aft_jacobian import residual_jacobian
from railtrack.equations.harmonic_balance import (harmonic_system, nonlinear_coefficients,
                                                  residual, residual_norm, to_real, from_real)
from railtrack.model.passage import Passage
from railtrack.solvers.truncation import track_spectrum

from ground_doubles import SmearedLayer

TRACK, TRAIN, A = rt.Track.paper(), rt.Train.paper(), 0.25
M = 15
LAWS = {
    "linear": rt.LinearFoundation.paper(),
    "bilinear": rt.BilinearFoundation.paper(ratio=0.5),
    "cubic": rt.CubicFoundation.paper(0.8),
    "callable": rt.CallableFoundation(lambda w, v: 2e7 * w + 1e13 * w**3 + 2e5 * v),
}


class RigidGround:
    footprint = A

    def compliance(self, kx, omega):
        return np.zeros(np.shape(kx), dtype=complex)


def _relative(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


@pytest.mark.parametrize("name", sorted(LAWS))
def test_a_rigid_ground_is_todays_solve(name):
    plain = rt.solve(TRACK, TRAIN, LAWS[name], harmonics=M)
    grounded = rt.solve(TRACK, TRAIN, LAWS[name], harmonics=M, ground=RigidGround())
    assert grounded.converged and isinstance(grounded, rt.GroundSolution)
    assert _relative(grounded.coefficients, plain.coefficients) <= 1e-10
    assert np.all(grounded.ground_coefficients == 0)
    t = np.linspace(0, plain.period, 7)
    np.testing.assert_allclose(grounded.foundation_force(t), plain.foundation_force(t),
                               rtol=1e-9, atol=1e-9 * np.max(np.abs(plain.foundation_force(t))))


def test_a_rigid_ground_picks_todays_m_too():
    plain = rt.solve(TRACK, TRAIN, LAWS["cubic"], stability="off")
    grounded = rt.solve(TRACK, TRAIN, LAWS["cubic"], ground=RigidGround())
    assert grounded.harmonics == plain.harmonics
    assert grounded.truncation_error == pytest.approx(plain.truncation_error, rel=1e-8)
    assert _relative(grounded.coefficients, plain.coefficients) <= 1e-10


def _eq23_with_series(passage, harmonics, law_stiffness, ground_receptance):
    """Eq. (23) per harmonic with the law's stiffness in series with the ground's 1 / R_g."""
    system = harmonic_system(passage, rt.LinearFoundation(2e7), harmonics)  # law unused
    series = 1.0 / (1.0 / law_stiffness + ground_receptance)
    return -system.load / (system.operator + series / float(passage.sleeper_mass))


def test_winkler_ground_is_a_spring_in_series_with_a_linear_law():
    k, s = 2e7, 2e8      # the law, and a bed of s per metre: a s = 5e7 N/m per sleeper
    plain = rt.solve(TRACK, TRAIN, rt.LinearFoundation(k * A * s / (k + A * s)), harmonics=M)
    grounded = rt.solve(TRACK, TRAIN, rt.LinearFoundation(k), harmonics=M,
                        ground=rt.WinklerGround(s, A))
    assert _relative(grounded.coefficients, plain.coefficients) <= 1e-8
    # the ground carries the law's force: u = f / (a s)
    force = k * grounded.relative_coefficients
    np.testing.assert_allclose(grounded.ground_coefficients * A * s, force, rtol=0,
                               atol=1e-10 * np.max(np.abs(force)))


def test_damped_winkler_ground_against_series_spring_and_dashpot_per_harmonic():
    law = rt.LinearFoundation.paper()             # 20 MN/m, 0.2 MN s/m
    s, eta = 2e8, 4e5
    grounded = rt.solve(TRACK, TRAIN, law, harmonics=M, ground=rt.WinklerGround(s, A, eta))
    passage = Passage(TRACK, TRAIN)
    omega = passage.fundamental_frequency * np.arange(M + 1)
    truth = _eq23_with_series(passage, M, law.stiffness + 1j * omega * law.damping,
                              1 / (A * (s + 1j * omega * eta)))
    assert _relative(grounded.coefficients[M:], truth) <= 1e-8


def test_cubic_law_on_winkler_ground_is_todays_solve_of_the_series_law():
    cubic, s = rt.CubicFoundation(2e7, 2e13, 0.8), 1e8     # no damping: a law in w alone
    spring = A * s

    def series(w, v):
        # d + f(d) / (a s) = w, solved for d by Newton per sample; the force is f(d)
        d = w * spring / (spring + 2e7)
        for _ in range(60):
            d = d - (d + cubic.force(d, 0 * d) / spring - w) / (1 + cubic.tangent(d, 0 * d)[0]
                                                                   / spring)
        return cubic.force(d, 0 * d)

    # At finite m the two truncate differently (here d has m harmonics, there w has, and d
    # more): they agree to within the truncation error, and ever closer as m grows.
    for m, within in ((15, 1e-5), (60, 1e-7)):
        plain = rt.solve(TRACK, TRAIN, rt.CallableFoundation(series), harmonics=m)
        grounded = rt.solve(TRACK, TRAIN, cubic, harmonics=m, ground=rt.WinklerGround(s, A))
        assert plain.converged and grounded.converged
        assert _relative(grounded.coefficients, plain.coefficients) <= within
    assert _relative(grounded.coefficients, plain.coefficients) <= 1e-3 * plain.truncation_error


@pytest.mark.parametrize("speed", [45.0, 90.0])
def test_linear_law_on_smeared_layer_against_its_sum_over_sleepers_in_space(speed):
    layer, law = SmearedLayer(), rt.LinearFoundation.paper()
    train = TRAIN.replace(speed=speed)
    grounded = rt.solve(TRACK, train, law, harmonics=M, ground=layer)
    passage = Passage(TRACK, train)
    omega = passage.fundamental_frequency * np.arange(M + 1)
    receptance = np.array([layer.space_sum(w, w * passage.sleeper_spacing / speed)
                           for w in omega])
    truth = _eq23_with_series(passage, M, law.stiffness + 1j * omega * law.damping, receptance)
    assert _relative(grounded.coefficients[M:], truth) <= 1e-6


@pytest.mark.parametrize("name", ["bilinear", "cubic"])
def test_nonlinear_law_on_smeared_layer_solves_the_sleepers_equation(name):
    layer, law = SmearedLayer(s0=5e7), LAWS[name]
    grounded = rt.solve(TRACK, TRAIN, law, harmonics=M, ground=layer)
    assert grounded.converged and grounded.iterations >= 2
    # eq. (17) in w, with the law on d = w - u and u from the sum over sleepers in space
    passage = Passage(TRACK, TRAIN)
    system = harmonic_system(passage, law, M)
    w, d = grounded.coefficients[M:], grounded.relative_coefficients[M:]
    forces = nonlinear_coefficients(system, d)
    receptance = np.array([layer.space_sum(x, x * passage.sleeper_spacing / passage.speed)
                           for x in system.omega])
    np.testing.assert_allclose(w - d, receptance * forces * passage.sleeper_mass,
                               rtol=0, atol=1e-7 * np.max(np.abs(w)))
    balance = system.operator * w + forces + system.load
    assert residual_norm(system, balance) <= 1e-6
    assert np.ptp(grounded.ground_displacement(np.linspace(0, 0.4, 50))) > 0.05 * np.ptp(
        grounded.sleeper_displacement(np.linspace(0, 0.4, 50)))      # the ground matters here


@pytest.mark.parametrize("name", ["bilinear", "cubic", "callable"])
def test_jacobian_on_a_ground_against_finite_differences(name):
    passage = Passage(TRACK, TRAIN)
    spectrum = track_spectrum(passage, 8 * M, SmearedLayer(s0=5e7))
    system = spectrum.system(passage, LAWS[name], M)
    d = rt.solve(TRACK, TRAIN, LAWS[name], harmonics=M,
                 ground=SmearedLayer(s0=5e7)).relative_coefficients[M:]
    d = d * (1 + 0.1 * np.cos(np.arange(M + 1)))          # off the solution, not at a kink
    x = to_real(d)
    jacobian = residual_jacobian(system, d)
    step = 1e-7 * np.max(np.abs(x))
    numeric = np.empty_like(jacobian)
    for j in range(len(x)):
        e = np.zeros_like(x)
        e[j] = step
        numeric[:, j] = (to_real(residual(system, from_real(x + e)))
                         - to_real(residual(system, from_real(x - e)))) / (2 * step)
    assert np.max(np.abs(jacobian - numeric)) <= 1e-5 * np.max(np.abs(numeric))
    # the coupling is in it: the rigid ground's Jacobian differs
    rigid = residual_jacobian(harmonic_system(passage, LAWS[name], M), d)
    assert np.max(np.abs(jacobian - rigid)) > 1e-2 * np.max(np.abs(numeric))


def test_what_a_ground_does_not_take_is_refused_by_name():
    ground = rt.WinklerGround(2e8, A)
    for kwargs, name in ((dict(method="fixed-point"), "method"),
                         (dict(method="analytic"), "method"),
                         (dict(stability="full"), "stability"),
                         (dict(fallback=True), "fallback"),
                         (dict(wheel=rt.Wheel.paper() if hasattr(rt.Wheel, "paper")
                               else rt.Wheel(500.0)), "wheel")):
        with pytest.raises(ValueError, match=name):
            rt.solve(TRACK, TRAIN, LAWS["linear"], ground=ground, **kwargs)
    with pytest.raises(TypeError, match="compliance"):
        rt.solve(TRACK, TRAIN, LAWS["linear"], ground=object())
    with pytest.raises(ValueError, match="footprint"):
        rt.solve(TRACK, TRAIN, LAWS["linear"], ground=rt.WinklerGround(2e8, 0.9))


def test_a_split_or_an_accuracy_not_used_on_a_ground_warns_at_the_callers_line():
    # Newton takes no split and an explicit m no accuracy: each warns, and the
    # warning names the line that called solve (this file), as without a ground.
    ground = rt.WinklerGround(2e8, A)
    for kwargs, text in ((dict(split=3), "split is used"),
                         (dict(accuracy=1e-3), "accuracy is used")):
        with pytest.warns(UserWarning, match=text) as caught:
            rt.solve(TRACK, TRAIN, LAWS["linear"], M, ground=ground, **kwargs)
        ours = [w for w in caught if text in str(w.message)]
        assert len(ours) == 1 and ours[0].filename == __file__, \
            [(w.filename, w.lineno) for w in ours]


@pytest.mark.parametrize("name", ["linear", "cubic"])
def test_energy_balance_on_a_damped_ground(name):
    # the wheel loads' work = pad + law + what the ground takes: a conservation law that
    # checks the coupling's sign and phase (a wrong conj would make the ground give energy)
    ground = SmearedLayer(s0=5e7, eta=5e5)
    s = rt.solve(TRACK, TRAIN, LAWS[name], harmonics=40, ground=ground)
    energy = rt.dissipation(s)
    assert energy.ground > 0.05 * energy.total
    assert abs(rt.load_work(s) / energy.total - 1) < 1e-6


def test_truncation_errors_on_a_ground_against_a_solve_at_eight_times_m():
    # a linear law: the estimate of the neglected harmonics is exact (eq. 23 per harmonic),
    # here with the soft smeared layer in series (a tail taken on the rigid ground is 7 % off)
    ground, law, m = SmearedLayer(s0=3e7), rt.LinearFoundation.paper(), 12
    s = rt.solve(TRACK, TRAIN, law, harmonics=m, ground=ground)
    fine = rt.solve(TRACK, TRAIN, law, harmonics=8 * m, ground=ground)
    t = np.linspace(0, s.period, 2048, endpoint=False)
    whole = fine.sleeper_displacement(t)
    actual = np.max(np.abs(whole - s.sleeper_displacement(t))) / np.max(np.abs(whole))
    estimate = s.truncation_errors()["sleeper_displacement"]
    assert abs(estimate / actual - 1) < 0.005


class _CountedLayer(SmearedLayer):
    """A smeared layer that counts its compliance calls; hashable by value like a frozen ground."""

    calls = 0

    def compliance(self, kx, omega):
        type(self).calls += 1
        return super().compliance(kx, omega)

    def __hash__(self):
        return hash((self.s0, self.s2, self.rho, self.eta, self.footprint))

    def __eq__(self, other):
        return type(other) is type(self) and hash(other) == hash(self)


@pytest.mark.filterwarnings("ignore::railtrack.TruncationWarning")
def test_a_second_solve_on_the_same_ground_and_speed_costs_no_lattice_sum():
    track, train = rt.Track.paper(), rt.Train.paper()
    first = rt.solve(track, train, rt.CubicFoundation.paper(0.8), harmonics=6,
                     ground=_CountedLayer())
    calls = _CountedLayer.calls
    assert calls > 0
    again = rt.solve(track, train, rt.CubicFoundation.paper(0.5), harmonics=6,
                     ground=_CountedLayer())                # equal by value: the same memo
    assert _CountedLayer.calls == calls
    fresh = rt.solve(track, train, rt.CubicFoundation.paper(0.5), harmonics=6,
                     ground=SmearedLayer())                 # equal only to itself: a new memo
    assert np.allclose(again.coefficients, fresh.coefficients, rtol=1e-12, atol=0)
    assert not np.allclose(first.coefficients, again.coefficients, rtol=1e-3, atol=0)
    rt.solve(track, dataclasses.replace(train, speed=30.0), rt.CubicFoundation.paper(0.5),
             harmonics=6, ground=_CountedLayer())
    assert _CountedLayer.calls > calls                       # another speed: new lattice sums
