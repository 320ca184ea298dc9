"""The ground's equivalent stiffness under a strip against an independent quadrature and limits.

Truths: scipy's adaptive `quad` (QUADPACK's QAGS and, for the oscillating
tail to infinity, QAWF) on the same integral (Dieterman & Metrikine 1996,
eq. 10) without our panels or closed-form tail; plane strain for a
strip much wider than the wavelength along the track, w/P -> F(k_x)/b; the
reality of a real load (omega -> -omega conjugates, k_x -> -k_x changes
nothing); and Dieterman & Metrikine's critical velocity: a load moving at v
sees K_eq(k_x, k_x v), which for a half-space vanishes as v -> c_R.
"""

import numpy as np
import pytest
from scipy.integrate import quad

from railtrack.equations.ground_stiffness import surface_flexibility
from railtrack.equations.ground_strip import strip_flexibility, strip_stiffness
from railtrack.equations.ground_waves import rayleigh_speed
from railtrack.model.ground import Ground, SoilLayer

HALF = Ground.homogeneous(100.0, 0.3, 1800.0, 0.02)
CLAY = Ground((SoilLayer(65.0, 0.49, 1500.0, 0.02, thickness=6.0),),
              SoilLayer(200.0, 0.45, 1900.0, 0.02))
WIDTH = 3.0


def _by_quad(ground, kx, omega, average, split=20.0):
    """(1/pi) int_0^inf F sinc dk_y by adaptive quadrature: QUADPACK's QAGS up to `split`,
    its Fourier-integral QAWF beyond (no panels of ours, no closed-form tail)."""
    a = WIDTH / 2
    unit = ground.strata[0].shear_modulus          # O(1) values: QAWF's epsabs is absolute

    def f(y, take, extra):
        return take(surface_flexibility(ground, np.hypot(kx, y), omega) * extra(y)) * unit

    total = 0.0
    for take, part in ((np.real, 1.0), (np.imag, 1j)):
        shape = (lambda y: np.sinc(a * y / np.pi) ** (2 if average else 1))   # noqa: E731
        near = quad(f, 0.0, split, args=(take, shape), epsabs=0, epsrel=1e-10, limit=2000)[0]
        if average:      # sin^2 = (1 - cos 2ay) / 2
            over = (lambda y: 1 / (2 * a * a * y * y))                          # noqa: E731
            far = (quad(f, split, np.inf, args=(take, over), epsabs=0, epsrel=1e-10)[0]
                   - quad(f, split, np.inf, args=(take, over), weight="cos", wvar=2 * a,
                          limlst=200, epsabs=1e-13)[0])
        else:
            far = quad(f, split, np.inf, args=(take, lambda y: 1 / (a * y)), weight="sin",
                       wvar=a, limlst=200, epsabs=1e-13)[0]
        total += (near + far) * part
    return total / np.pi / unit


@pytest.mark.parametrize("ground, kx, omega, average", [
    (HALF, 0.5, 0.0, False), (HALF, 0.2, 60.0, True), (CLAY, 0.3, 60.0, False),
    (CLAY, 1.5, 150.0, True), (CLAY, 5.0, 30.0, False), (HALF, 0.01, 100.0, False),
    # short waves, where the top stratum's static 1/k is split off and integrated in closed form
    (CLAY, 300.0, 400.0, True), (HALF, 150.0, 0.0, True), (CLAY, 60.0, 900.0, False)])
def test_the_strip_integral_agrees_with_adaptive_quadrature(ground, kx, omega, average):
    ours = strip_flexibility(ground, kx, omega, WIDTH, average)
    assert abs(ours / _by_quad(ground, kx, omega, average) - 1) < 2e-6


def _by_quad_beside(ground, kx, omega, y, split=20.0):
    """The displacement at y from the centre line: sinc(a k_y) cos(y k_y) as two sines beyond."""
    a = WIDTH / 2
    unit = ground.strata[0].shear_modulus

    def f(k, take, extra):
        return take(surface_flexibility(ground, np.hypot(kx, k), omega) * extra(k)) * unit

    total = 0.0
    for take, part in ((np.real, 1.0), (np.imag, 1j)):
        shape = (lambda k: np.sinc(a * k / np.pi) * np.cos(y * k))            # noqa: E731
        near = quad(f, 0.0, split, args=(take, shape), epsabs=0, epsrel=1e-10, limit=4000)[0]
        far = sum(np.sign(c) * quad(f, split, np.inf, args=(take, lambda k: 1 / (2 * a * k)),
                                    weight="sin", wvar=abs(c), limlst=400, epsabs=1e-13)[0]
                  for c in (a + y, a - y) if c != 0)
        total += (near + far) * part
    return total / np.pi / unit


@pytest.mark.parametrize("ground, kx, omega, y", [
    (HALF, 0.5, 0.0, 5.0), (CLAY, 0.3, 60.0, 1.5), (HALF, 1.0, 80.0, -4.0)])
def test_the_ground_beside_the_strip_agrees_with_adaptive_quadrature(ground, kx, omega, y):
    ours = strip_flexibility(ground, kx, omega, WIDTH, offset=y)
    assert abs(ours / _by_quad_beside(ground, kx, omega, y) - 1) < 2e-6
    assert abs(ours) < abs(strip_flexibility(ground, kx, omega, WIDTH))   # less than beneath


def test_the_static_stiffness_is_real_and_positive():
    for ground in (HALF, CLAY):
        stiffness = strip_stiffness(ground, np.geomspace(0.01, 20.0, 12), 0.0, WIDTH)
        assert np.all(np.abs(stiffness.imag) < 1e-12 * stiffness.real)
        assert np.all(stiffness.real > 0)
    # on a half-space it grows with k_x (on the clay it dips near k_x h ~ 1: the sinc's lobes)
    assert np.all(np.diff(strip_stiffness(HALF, np.geomspace(0.01, 20.0, 12), 0.0, WIDTH)) > 0)


@pytest.mark.parametrize("omega", [0.0, 100.0])
def test_a_wide_strip_is_in_plane_strain(omega):
    width, kx = 100.0, 2.0                                       # k_x b = 200
    ratio = strip_flexibility(HALF, kx, omega, width) * width / surface_flexibility(HALF, kx,
                                                                                    omega)
    assert abs(ratio - 1) < 1e-5


def test_a_real_load_gives_a_real_displacement():
    kx = np.array([-2.0, -0.4, 0.4, 2.0])
    ahead, behind = strip_stiffness(CLAY, kx, 80.0, WIDTH), strip_stiffness(CLAY, kx, -80.0, WIDTH)
    assert np.allclose(behind, np.conj(ahead), rtol=1e-12, atol=0)
    assert np.allclose(ahead, ahead[::-1], rtol=1e-12, atol=0)


@pytest.mark.parametrize("kx", [0.3, 1.0, 3.0])
def test_the_critical_velocity_of_a_load_on_the_half_space_is_the_rayleigh_speed(kx):
    ground = Ground.homogeneous(100.0, 0.3, 1800.0, 0.01)
    c_r = rayleigh_speed(100.0, 0.3)
    speeds = c_r * np.linspace(0.8, 1.2, 81)                     # steps of 0.5 % of c_R
    stiffness = np.abs(strip_stiffness(ground, kx, kx * speeds, WIDTH))
    assert abs(speeds[np.argmin(stiffness)] / c_r - 1) < 0.006
    assert stiffness.min() < 0.5 * min(stiffness[20], stiffness[60])   # against 0.9 and 1.1 c_R
    # the dip deepens towards Dieterman & Metrikine's zero as the damping goes
    lighter = Ground.homogeneous(100.0, 0.3, 1800.0, 0.001)
    assert abs(strip_stiffness(lighter, kx, kx * c_r, WIDTH)) < 0.5 * stiffness.min()


def test_pairs_of_wavenumber_and_frequency_are_each_the_scalar_call():
    kx, omega = np.array([[0.2, 1.0, 4.0]]), np.array([[0.0], [35.0], [-90.0]])
    together = strip_stiffness(CLAY, kx, omega, WIDTH, average=True)
    assert together.shape == (3, 3)
    for (i, j), value in np.ndenumerate(together):
        alone = strip_stiffness(CLAY, kx[0, j], omega[i, 0], WIDTH, average=True)
        # one frequency with many nodes reads F from a table (railtrack.equations.ground_table),
        # good to ~3e-8: a call alone and a call in a batch agree to that, not to round-off
        assert np.shape(alone) == () and value == pytest.approx(alone, rel=1e-8)


def test_bad_strips_are_refused_by_name():
    with pytest.raises(ValueError, match="damping"):
        strip_stiffness(Ground.homogeneous(100.0, 0.3, 1800.0), 1.0, 50.0, WIDTH)
    with pytest.raises(ValueError, match="kx"):
        strip_stiffness(HALF, [0.0, 1.0], 0.0, WIDTH)
    with pytest.raises(ValueError, match="width"):
        strip_stiffness(HALF, 1.0, 0.0, -3.0)
    with pytest.raises(ValueError, match="offset"):
        strip_flexibility(HALF, 1.0, 0.0, WIDTH, average=True, offset=2.0)


def test_a_nearly_static_frequency_is_continuous_and_stays_cheap():
    # as omega -> 0 the strip tends to the static strip of the damped moduli (hysteretic
    # damping is complex at any omega != 0, real at 0: the limit is not omega = 0 itself);
    # at 1e-6 rad/s the panel grid once grew to 7.5 million panels (the fine cap of the
    # surface waves ran past them to the next point)
    from railtrack.equations.ground_strip import _breakpoints
    soil = Ground((SoilLayer(45.0, 0.49, 1300.0, 0.03, thickness=4.0),),
                  SoilLayer(150.0, 0.45, 1800.0, 0.03))
    for average in (False, True):
        slow, slower = (strip_flexibility(soil, 1.0, w, 3.0, average) for w in (1e-3, 1e-6))
        assert abs(slower / slow - 1) < 1e-6
    assert _breakpoints(soil, 1.0, 1e-6, 3.0).size < 1000
