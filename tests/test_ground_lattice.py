"""The ground's lattice sum R_g (eq. G1 of railtrack.equations.ground_lattice) against
independent truths: the Winkler limit C / a (Poisson's formula), a direct sum over sleepers
in space of a smeared layer's Green function, and a brute-force sum of two million terms."""

import numpy as np
import pytest
import sympy as sp

from railtrack.equations.ground_lattice import ground_receptance, lattice_sum
from railtrack.model.ground_protocol import WinklerGround, check_ground

from ground_doubles import SmearedLayer

L, A = 0.6, 0.25


def test_footprint_transform_and_eq_g2_by_sympy():
    k, a, x = sp.symbols("k a x", positive=True)
    transform = sp.integrate(sp.exp(-sp.I * k * x) / a, (x, -a / 2, a / 2))
    assert sp.simplify((transform - sp.sin(k * a / 2) / (k * a / 2)).rewrite(sp.exp)) == 0
    # eq. (17) in w = d + u with u = R_g M G is eq. (G2): phi times eq. (17) with op/phi, F/phi
    op, r, mass, g, f, d = sp.symbols("operator R_g M G F d")
    phi = 1 + mass * r * op
    assert sp.simplify(op * (d + r * mass * g) + g + f - phi * (op / phi * d + g + f / phi)) == 0


def test_footprint_averages_by_sympy():
    x, y, g, a, d = sp.symbols("x y gamma a d", positive=True)
    inner = sp.integrate(sp.exp(-g * (x - y)), (y, -a / 2, x)) + sp.integrate(
        sp.exp(-g * (y - x)), (y, x, a / 2))
    self_average = sp.integrate(inner, (x, -a / 2, a / 2)) / a**2
    assert sp.simplify(self_average - 2 * (g * a - 1 + sp.exp(-g * a)) / (g * a) ** 2) == 0
    # two footprints d >= a apart: x - y = d + s - t > 0 throughout
    s, t = sp.symbols("s t", real=True)
    pair = sp.integrate(sp.exp(-g * (d + s - t)), (s, -a / 2, a / 2), (t, -a / 2, a / 2)) / a**2
    assert sp.simplify((pair - sp.exp(-g * d) * (sp.sinh(g * a / 2) / (g * a / 2)) ** 2)
                       .rewrite(sp.exp)) == 0


@pytest.mark.parametrize("omega, q", [(0.0, 0.0), (150.0, 0.7), (900.0, 3.1), (2500.0, 6.0)])
@pytest.mark.parametrize("c", [3e-9, 2e-9 + 5e-10j])
def test_winkler_limit_is_c_over_a_exactly(omega, q, c):
    value, error = lattice_sum(lambda k, w: np.full(k.shape, c, dtype=complex), omega, q, L, A)
    assert abs(value - c / A) <= 1e-12 * abs(c / A)
    assert error <= 1e-12 * abs(c / A)
    # and a plain truncation would be far off: sinc^2 alone falls like m^-2
    m = np.arange(-64, 65)
    plain = c * np.sum(np.sinc((q + 2 * np.pi * m) / L * A / (2 * np.pi)) ** 2) / L
    assert abs(plain - c / A) > 1e-3 * abs(c / A)


def test_winkler_receptance_is_a_spring_and_dashpot_per_sleeper():
    ground = WinklerGround(modulus=1.2e8, footprint=A, damping=3e5)
    omega = np.array([0.0, 40.0, 400.0, 4000.0])
    r = ground_receptance(ground, omega, speed=50.0, spacing=L)
    # eq. (12)'s convention e^{+i omega t}: stiffness a s, damping a eta per sleeper
    np.testing.assert_allclose(r, 1 / (A * (1.2e8 + 1j * omega * 3e5)), rtol=1e-12)


@pytest.mark.parametrize("omega, speed", [(0.0, 50.0), (150.0, 50.0), (700.0, 80.0),
                                          (1500.0, 200.0)])
def test_smeared_layer_against_the_sum_over_sleepers_in_space(omega, speed):
    layer = SmearedLayer()
    r = ground_receptance(layer, np.array([omega]), speed, L)[0]
    truth = layer.space_sum(omega, omega * L / speed)
    assert abs(r - truth) <= 1e-6 * abs(truth)


def _halfspace_like(k, w):
    # falls like 1/|k|, as a half-space's compliance does
    return 1.0 / (1e8 * (np.abs(k) + 2.0) - 1j * w * 1e5)


@pytest.mark.parametrize("omega, q", [(0.0, 0.0), (300.0, 1.3), (800.0, 5.0)])
def test_tail_of_a_compliance_falling_like_one_over_k(omega, q):
    m = np.arange(-2_000_000, 2_000_001)
    k = (q + 2 * np.pi * m) / L
    weights = np.sinc(k * A / (2 * np.pi)) ** 2
    brute = np.sum(_halfspace_like(k, omega) * weights) / L  # its own tail is ~1e-13 relative
    value, error = lattice_sum(_halfspace_like, omega, q, L, A, terms=64)
    assert abs(value - brute) <= 1e-6 * abs(brute)
    assert abs(value - brute) <= error                 # the estimate bounds the error
    inside = np.abs(m) <= 64
    plain = np.sum(_halfspace_like(k[inside], omega) * weights[inside]) / L
    assert abs(plain - brute) > 1e-5 * abs(brute)      # the tail correction is what did it


def test_bad_grounds_are_refused_with_their_reason():
    with pytest.raises(TypeError, match="compliance"):
        check_ground(object(), L)
    with pytest.raises(ValueError, match="footprint"):
        check_ground(WinklerGround(1e8, 0.7), L)
    with pytest.raises(ValueError, match="modulus"):
        WinklerGround(-1.0, A)

    class Wrong:
        footprint = A

        def compliance(self, kx, omega):
            return np.ones(3)

    with pytest.raises(ValueError, match="shaped like kx"):
        ground_receptance(Wrong(), np.array([0.0]), 50.0, L)

    class HalfSpace:        # no rigid base: the infinite train's mean settles without bound
        footprint = A

        def compliance(self, kx, omega):
            with np.errstate(divide="ignore"):
                return 1.0 / (1e8 * np.abs(kx)) + 0j

    with pytest.raises(ValueError, match="not finite at kx = 0"):
        ground_receptance(HalfSpace(), np.array([0.0]), 50.0, L)

    class Lopsided:         # C(-k, 0) != conj C(k, 0): no real ground
        footprint = A

        def compliance(self, kx, omega):
            return 1e-9 * (1 + 0.5j * np.sign(kx + 1.0))

    with pytest.raises(ValueError, match="static compliance .* not real"):
        ground_receptance(Lopsided(), np.array([0.0]), 50.0, L)


@pytest.mark.parametrize("terms", [16, 64])
def test_a_phase_many_turns_round_is_summed_about_k_zero(terms):
    # q_n = 2 pi n L / H passes 2 pi many times for the harmonics of the truncation estimate;
    # the sum is 2 pi-periodic in q, and its kept window must stay where C is large
    layer, omega, q = SmearedLayer(), 1500.0, 0.9
    truth = np.conj(layer.space_sum(omega, q))
    for turns in (0, 3, 20, -7):
        value, _ = lattice_sum(layer.compliance, omega, q + 2 * np.pi * turns, L, A, terms)
        assert abs(value - truth) <= (1e-4 if terms == 16 else 1e-6) * abs(truth)
