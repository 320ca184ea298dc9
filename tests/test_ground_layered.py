"""The layered soil as a ground for `solve` (railtrack.equations.ground_layered.LayeredGround):
its sign convention (a damped soil takes work: Im C >= 0), the mean it leaves out (C(0, 0) = 0),
and the Winkler limit end to end: a thin layer on a near-rigid half-space under the track is
today's solve with the law in series with the spring (lambda + 2 mu) / h * a * b per sleeper."""

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations.ground_layered import LayeredGround
from railtrack.model.ground import Ground, SoilLayer

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
A, B = 0.25, 0.3                     # footprint along, strip width across the track [m]


def test_a_damped_soil_takes_work_and_the_mean_is_left_out():
    soil = Ground((SoilLayer(80.0, 0.3, 1800.0, 0.05, thickness=3.0),),
                  SoilLayer(250.0, 0.3, 2000.0, 0.03))
    ground = LayeredGround(soil, width=2.5, footprint=A)
    kx = np.array([-40.0, -3.0, -0.2, 0.2, 3.0, 40.0])
    for omega in (15.0, 150.0, 600.0):
        c = ground.compliance(kx, omega)
        assert np.all(c.imag > 0)                      # exp(-i omega t): the soil dissipates
        assert np.allclose(c[::-1], c, rtol=1e-12)     # even in k_x
    static = ground.compliance(np.concatenate([kx, [0.0]]), 0.0)
    assert np.all(static[:-1].real > 0) and np.all(static.imag == 0)
    assert static[-1] == 0                             # C(0, 0) := 0, the mean level


def test_bad_arguments_are_named():
    soil = Ground.homogeneous(100.0, 0.3, 1800.0, 0.05)
    with pytest.raises(TypeError, match="ground must be a railtrack.model.ground.Ground"):
        LayeredGround(rt.WinklerGround(1e8, A), B, A)
    with pytest.raises(ValueError, match="width"):
        LayeredGround(soil, -1.0, A)
    for rails in (0, 1.5, True):
        with pytest.raises(ValueError, match="rails"):
            LayeredGround(soil, 2.5, A, rails=rails)
    with pytest.raises(ValueError, match="footprint"):
        rt.solve(TRACK, TRAIN, rt.LinearFoundation(1e8), harmonics=2,
                 ground=LayeredGround(soil, B, 0.7))         # a > L = 0.6 m


@pytest.mark.parametrize("raw", ["ground", "halfspace"])
def test_the_soil_itself_passed_as_ground_is_told_to_wrap_it(raw):
    # rt.Ground (or one SoilLayer) has no sleepers to load it: the message names
    # the wrapper, and the call it proposes builds the wrapped soil
    soil = Ground.homogeneous(100.0, 0.3, 1800.0, 0.05)
    given = soil if raw == "ground" else soil.halfspace
    with pytest.raises(TypeError, match=r"wrap the (Ground|SoilLayer) soil in "
                                        r"rt\.LayeredGround\(") as info:
        rt.solve(TRACK, TRAIN, rt.LinearFoundation(1e8), harmonics=2, ground=given)
    proposal = str(info.value).split("in rt.LayeredGround(", 1)[1].split("), width [m]")[0]
    wrapped = eval(f"rt.LayeredGround({proposal})", {"rt": rt, "soil": given})
    assert wrapped.ground == soil and (wrapped.width, wrapped.footprint) == (2.6, 0.25)


def _thin_layer(h):
    with rt.plausibility("ignore"):      # a layer of cm on a base 100 times as dense: meant
        layer = SoilLayer(100.0, 0.3, 1900.0, thickness=h)
        base = SoilLayer(1000.0, 0.3, 190000.0, 0.05)
    # a half-space 100 times as stiff in shear and 100 times as dense (mu 1e4 times the
    # layer's): its own compliance ~ 1 / (mu_hs k_x) stays below 1e-3 of the layer's h / M
    # at the k_x that carry the sum; only it is damped (the strip's quadrature needs a loss)
    return layer, Ground((layer,), base)


def test_a_thin_layer_on_a_rigid_base_tends_to_the_winkler_compliance():
    # C -> h / (M b) as h -> 0 at the k_x that carry the lattice sum (|k_x| <~ 2 pi / a):
    # the O(h / b) edge effect and the O((k_x h)^2) of short waves shrink with h
    kx = np.array([0.35, 2 * np.pi / 0.6, 30.0, 100.0])
    worst = []
    for h in (0.08, 0.04, 0.01):
        layer, soil = _thin_layer(h)
        c = LayeredGround(soil, B, A, rails=1).compliance(kx, 16.0)
        worst.append(np.max(np.abs(c * layer.constrained_modulus * B / h - 1)))
        # both rails load the strip: one rail's share of the sleeper settles twice as much
        assert np.allclose(LayeredGround(soil, B, A).compliance(kx, 16.0), 2 * c, rtol=1e-14)
    assert worst[-1] < 0.02 and worst[-1] < worst[1] < worst[0]


def test_a_thin_stiff_layer_on_a_rigid_base_is_the_winkler_spring_in_series():
    # end to end: the law k_f in series with k_s = M a (b / 2) / h (M = lambda + 2 mu) is one
    # linear spring, today's solve: the track models one rail, whose half sleeper stands on
    # half the strip (rails=2).  The mean: LayeredGround drops the uniform settlement
    # 2 C(0, 0) / L f_0 = 2 h / (M b L) f_0 (infinite on a half-space), put back here.
    # At h = 1 cm the compliance is within 1.3 % of Winkler (the test above); measured 1.2e-3
    # at h = 1 cm against 1.7e-2 at h = 4 cm, and 8e-2 without the mean put back.  ~30 s: the
    # strip's k_y quadrature for 129 wavenumbers per harmonic (docs/ground_coupling.md).
    k_f, m, h = 1.2e8, 2, 0.01
    spacing = float(rt.Passage(TRACK, TRAIN).sleeper_spacing)
    layer, soil = _thin_layer(h)
    k_s = layer.constrained_modulus * A * (B / 2) / h
    with pytest.warns(rt.TruncationWarning):
        winkler = rt.solve(TRACK, TRAIN, rt.LinearFoundation(k_f * k_s / (k_f + k_s)),
                           harmonics=m)
        ours = rt.solve(TRACK, TRAIN, rt.LinearFoundation(k_f), harmonics=m,
                        ground=LayeredGround(soil, B, A))
    assert ours.converged
    w, truth = np.asarray(ours.coefficients), np.array(winkler.coefficients, dtype=complex)
    mean = truth.size // 2                                   # two-sided: n = 0 in the middle
    f_0 = k_f * k_s / (k_f + k_s) * truth[mean]              # the mean force per sleeper [N]
    truth[mean] -= f_0 * h / (layer.constrained_modulus * (B / 2) * spacing)
    assert np.max(np.abs(w - truth)) < 5e-3 * np.max(np.abs(truth))


class _Remembered:
    """The layered ground with its compliance remembered per (omega, k_x): the solve and the
    Jacobian check below share the strip's quadrature (the expensive part)."""

    def __init__(self, ground):
        self.ground, self.footprint, self.values = ground, ground.footprint, {}

    def compliance(self, kx, omega):
        key = (float(omega), np.asarray(kx, dtype=float).tobytes())
        if key not in self.values:
            self.values[key] = self.ground.compliance(kx, omega)
        return self.values[key]


def test_a_cubic_law_on_a_layered_soil_converges_with_the_jacobian_of_finite_differences():
    from railtrack.equations.aft_jacobian import residual_jacobian
    from railtrack.equations.harmonic_balance import (from_real, harmonic_system, residual,
                                                      to_real)
    from railtrack.model.passage import Passage
    from railtrack.solvers.truncation import track_spectrum

    m, law = 2, rt.CubicFoundation.paper(0.8)
    soil = Ground((SoilLayer(80.0, 0.3, 1800.0, 0.05, thickness=2.0),),
                  SoilLayer(200.0, 0.3, 2000.0, 0.03))
    ground = _Remembered(LayeredGround(soil, B, A))
    with pytest.warns(rt.TruncationWarning):
        solution = rt.solve(TRACK, TRAIN, law, harmonics=m, ground=ground)
    assert solution.converged
    passage = Passage(TRACK, TRAIN)
    system = track_spectrum(passage, m, ground).system(passage, law, m)
    d = np.asarray(solution.relative_coefficients)[m:]
    assert np.linalg.norm(to_real(residual(system, d))) < 1e-6 * np.linalg.norm(
        to_real(system.load))                                 # eq. (G2) holds at the result
    d = d * (1 + 0.1 * np.cos(np.arange(m + 1)))              # off the solution
    x = to_real(d)
    jacobian, step = residual_jacobian(system, d), 1e-7 * np.max(np.abs(x))
    numeric = np.empty_like(jacobian)
    for j in range(len(x)):
        e = np.zeros_like(x)
        e[j] = step
        numeric[:, j] = (to_real(residual(system, from_real(x + e)))
                         - to_real(residual(system, from_real(x - e)))) / (2 * step)
    assert np.max(np.abs(jacobian - numeric)) <= 1e-5 * np.max(np.abs(numeric))
    # the soil is in it (measured 2.5e-3 of the largest entry at these low harmonics, 250
    # times the agreement asked of the finite differences)
    rigid = residual_jacobian(harmonic_system(passage, law, m), d)
    assert np.max(np.abs(jacobian - rigid)) > 1e-3 * np.max(np.abs(numeric))


def test_a_linear_law_on_a_layered_soil_is_eq_23_with_the_soil_in_series():
    # consistency: per harmonic, the law's impedance k + i omega c in series with the soil's
    # 1 / R_g (eq. G1 from the same compliance) in eq. (23); the solve goes through eq. (G2)
    from railtrack.equations.ground_lattice import ground_receptance
    from railtrack.equations.harmonic_balance import harmonic_system
    from railtrack.model.passage import Passage

    m, law = 2, rt.LinearFoundation.paper()
    soil = Ground((SoilLayer(80.0, 0.3, 1800.0, 0.05, thickness=2.0),),
                  SoilLayer(200.0, 0.3, 2000.0, 0.03))
    ground = _Remembered(LayeredGround(soil, B, A))
    with pytest.warns(rt.TruncationWarning):
        grounded = rt.solve(TRACK, TRAIN, law, harmonics=m, ground=ground)
    passage = Passage(TRACK, TRAIN)
    omega = passage.fundamental_frequency * np.arange(m + 1)
    r_g = ground_receptance(ground, omega, float(passage.speed), float(passage.sleeper_spacing))
    system = harmonic_system(passage, law, m)
    series = 1.0 / (1.0 / (law.stiffness + 1j * omega * law.damping) + r_g)
    truth = -system.load / (system.operator + series / float(passage.sleeper_mass))
    got = np.asarray(grounded.coefficients)[m:]
    assert np.max(np.abs(got - truth)) <= 1e-8 * np.max(np.abs(truth))
    rigid = -system.load / (system.operator + law.stiffness / float(passage.sleeper_mass)
                            + 1j * omega * law.damping / float(passage.sleeper_mass))
    assert np.max(np.abs(got - rigid)) > 1e-2 * np.max(np.abs(truth))   # the soil matters


SOILS = [Ground((SoilLayer(80.0, 0.3, 1800.0, 0.05, thickness=3.0),),
                SoilLayer(250.0, 0.3, 2000.0, 0.03)),
         Ground((SoilLayer(250.0, 0.3, 2000.0, 0.03, thickness=0.5),               # stiff crust
                 SoilLayer(60.0, 0.4, 1600.0, 0.03, thickness=4.0)),
                SoilLayer(300.0, 0.3, 2000.0, 0.03))]


def _integrated(monkeypatch, soil, kx, omega):
    """strip_flexibility at every k_x with F computed at every node (no table)."""
    import railtrack.equations.ground_strip as strip
    with monkeypatch.context() as patch:
        patch.setattr(strip, "radial_flexibility",
                      lambda ground, k, w: strip.surface_flexibility(ground, k, w))
        return strip.strip_flexibility(soil, kx, omega, 2.5, average=True)


@pytest.mark.parametrize("soil", SOILS)
@pytest.mark.parametrize("omega", [0.0, 40.0, 400.0, 1500.0])
def test_the_short_waves_interpolated_agree_with_the_strip_integrated_at_every_wavenumber(
        soil, omega, monkeypatch):
    # the lattice sum's 129 wavenumbers of one harmonic: LayeredGround integrates |k_x| < K
    # and interpolates beyond, reading F from a table; the truth integrates each of them
    kx = (0.37 + 2 * np.pi * np.arange(-64, 65)) / 0.6
    ours = LayeredGround(soil, 2.5, A, rails=1).compliance(kx, omega)
    assert np.max(np.abs(ours / _integrated(monkeypatch, soil, kx, omega) - 1)) < 3e-7


def test_an_interpolant_that_fails_its_check_gives_way_to_the_integral(monkeypatch):
    import railtrack.equations.ground_layered as layered
    import railtrack.equations.ground_table as table
    kx = (0.37 + 2 * np.pi * np.arange(-64, 65)) / 0.6
    ground = LayeredGround(SOILS[0], 2.5, A, rails=1)
    interpolated = ground.compliance(kx, 400.0)
    exact = _integrated(monkeypatch, SOILS[0], kx, 400.0)
    monkeypatch.setattr(layered, "_CHECK", 0.0)          # no interpolant passes
    monkeypatch.setattr(table, "_CHECK", 0.0)            # nor any table
    integrated = ground.compliance(kx, 400.0)
    assert np.max(np.abs(integrated / exact - 1)) < 1e-13
    assert 0 < np.max(np.abs(interpolated / exact - 1)) < 3e-7


@pytest.mark.parametrize("law", [rt.LinearFoundation.paper(), rt.CubicFoundation.paper(0.8)],
                         ids=["linear", "cubic"])
def test_the_wheel_loads_work_is_what_pad_law_and_soil_take(law):
    # a conservation law, the check a time-domain run would give: over a period the moving
    # loads' work = pad + law + the soil (radiated and damped); a wrong conjugate in eq. (G1)
    # or a wrong sign of Im C would make the soil give energy back (measured: 7e-8, 7e-11)
    soil = Ground((SoilLayer(45.0, 0.49, 1300.0, 0.03, thickness=4.0),),
                  SoilLayer(150.0, 0.45, 1800.0, 0.03))
    ground = LayeredGround(soil, width=3.0, footprint=A)
    s = rt.solve(TRACK, TRAIN, law, harmonics=12, ground=ground)
    energy = rt.dissipation(s)
    assert s.converged
    assert energy.ground > 0.5 * energy.total          # most of it goes into the soft soil
    assert abs(rt.load_work(s) / energy.total - 1) < 1e-6
