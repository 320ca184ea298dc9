"""A linear cell of N differing sleepers solved per harmonic (issue 19, second block).

Independent truths used here:
* eq. (23) for N = 1 (`analytic_coefficients`, another closed form);
* today's travelling wave for N identical sleepers: sleeper j is sleeper 0
  delayed by jL/v, also when N L does not divide H;
* statics by a different method: a finite-element rail (Hermite cubic beam
  elements, exact at the nodes) on springs k1 k2/(k1 + k2), for the mean
  (n = 0, the train's mean weight spread along the rail, at any speed) and for
  the whole period at a crawling speed (quasi-static wheel loads);
* equilibrium: the foundations and the pads carry, on average, the train's
  mean weight per sleeper, sum Q L / H.
"""

import numpy as np
import pytest

from railtrack.equations.cell_linear import LinearCell, cell_linear_coefficients
from railtrack.equations.cell_receptance import cell_moving_load, cell_receptance
from railtrack.equations.linear import analytic_coefficients
from railtrack.model.foundations import LinearFoundation
from railtrack.model.passage import Passage

PAPER = Passage.paper()
LAW = LinearFoundation.paper()


def delayed(passage, coefficients, n):
    """c_n e^{-i omega_n j L / v} for j = 0..n-1, shape (n, 2m+1)."""
    m = (coefficients.size - 1) // 2
    omega = passage.harmonic_frequencies(m)
    j = np.arange(n)[:, None]
    return coefficients[None, :] * np.exp(-1j * omega * j * passage.sleeper_spacing
                                          / passage.speed)


@pytest.mark.parametrize("passage, law", [
    (PAPER, LAW),
    (Passage.paper(pad_damping=2e3), LinearFoundation(20e6, 1e3)),
    (Passage.paper(speed=120.0), LinearFoundation(60e6, 5e4)),
])
def test_one_sleeper_is_eq_23(passage, law):
    m = 45      # n = 30 puts mode 0 on a pole of eq. (3) (H / L = 30)
    expected = analytic_coefficients(passage, law, m)
    got = cell_linear_coefficients(passage, LinearCell.identical(passage, law, 1), m)
    np.testing.assert_allclose(got[0], expected, rtol=0, atol=1e-12 * np.abs(expected).max())


@pytest.mark.parametrize("passage, n", [
    (PAPER, 2), (PAPER, 3), (PAPER, 30),
    (PAPER, 7),                                         # N L = 4.2 m does not divide H = 18 m
    (Passage.paper(sleeper_spacing=0.65, speed=70.0), 30),   # N L = 19.5 m
])
def test_identical_sleepers_are_today_delayed(passage, n):
    m = 40
    today = analytic_coefficients(passage, LAW, m)
    got = cell_linear_coefficients(passage, LinearCell.identical(passage, LAW, n), m)
    np.testing.assert_allclose(got, delayed(passage, today, n), rtol=0,
                               atol=1e-12 * np.abs(today).max())


@pytest.mark.parametrize("passage", [PAPER, Passage.paper(speed=110.0, sleeper_spacing=0.7)])
def test_differing_sleepers_solve_the_stated_equations_in_sleeper_coordinates(passage):
    # for n >= 1 the sleeper and rail equations, as printed, in c and r, with the
    # cell matrix eta of the first block: no Floquet modes, no scaling
    rng = np.random.default_rng(19)
    n, m = 6, 25
    cell = LinearCell(rng.uniform(80, 160, n), rng.uniform(0.5e8, 3e8, n),
                      rng.uniform(0, 2e4, n), rng.uniform(5e6, 6e7, n), rng.uniform(0, 3e5, n))
    sleeper, rail = cell_linear_coefficients(passage, cell, m, rail=True)
    omega = passage.harmonic_frequencies(m)[m + 1:]
    s = 1j * omega[:, None]
    pad = cell.pad_stiffness + s * cell.pad_damping
    own = cell.sleeper_mass * s**2 + pad + cell.stiffness + s * cell.damping
    eta = cell_receptance(passage, omega, n)
    system = np.zeros((omega.size, 2 * n, 2 * n), dtype=complex)
    system[:, :n, :n] = own[..., None] * np.eye(n)
    system[:, :n, n:] = -pad[..., None] * np.eye(n)
    system[:, n:, :n] = -eta * pad[:, None, :]
    system[:, n:, n:] = np.eye(n) + eta * pad[:, None, :]
    right = np.concatenate([np.zeros((omega.size, n)), cell_moving_load(passage, omega, n)], -1)
    direct = np.linalg.solve(system, right[..., None])[..., 0]
    scale = np.abs(sleeper).max()
    np.testing.assert_allclose(sleeper[:, m + 1:], direct[:, :n].T, rtol=0, atol=1e-11 * scale)
    np.testing.assert_allclose(rail[:, m + 1:], direct[:, n:].T, rtol=0, atol=1e-11 * scale)


def beam_on_springs(span, ei, springs, nodes, loads):
    """Rail deflection at the nodes of a finite-element rail on springs [m].

    Hermite cubic beam elements between nodes x = i L (i = 0..nodes-1),
    ``springs[i]`` at node i, and point loads (position x, force upward) turned
    into consistent nodal loads; for `nodes` = None the rail is one periodic
    cell of len(springs) elements with a uniform load ``loads`` [N/m].
    """
    periodic = nodes is None
    count = len(springs) if periodic else nodes
    size = 2 * count
    k = ei / span**3 * np.array([[12, 6 * span, -12, 6 * span],
                                 [6 * span, 4 * span**2, -6 * span, 2 * span**2],
                                 [-12, -6 * span, 12, -6 * span],
                                 [6 * span, 2 * span**2, -6 * span, 4 * span**2]])
    stiffness = np.zeros((size, size))
    for e in range(count if periodic else count - 1):
        dofs = np.array([2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]) % size
        stiffness[np.ix_(dofs, dofs)] += k
    stiffness[np.arange(0, size, 2), np.arange(0, size, 2)] += springs
    if periodic:
        force = np.zeros(size)
        for e in range(count):
            dofs = np.array([2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]) % size
            force[dofs] += loads * np.array([span / 2, span**2 / 12, span / 2, -span**2 / 12])
        return np.linalg.solve(stiffness, force)[::2]
    force = np.zeros((size, len(loads)))
    for column, case in enumerate(loads):
        for x, value in case:
            e = min(int(np.floor(x / span)), count - 2)
            xi = x / span - e
            shape = np.array([1 - 3 * xi**2 + 2 * xi**3, span * (xi - 2 * xi**2 + xi**3),
                              3 * xi**2 - 2 * xi**3, span * (-xi**2 + xi**3)])
            force[2 * e:2 * e + 4, column] += value * shape
    return np.linalg.solve(stiffness, force)[::2]


def soft_cell(passage, n, soft, factor=0.5):
    cell = LinearCell.identical(passage, LAW, n)
    return cell.with_sleeper(soft, stiffness=factor * cell.stiffness[soft])


@pytest.mark.parametrize("speed, n", [(45.0, 5), (45.0, 7), (150.0, 4)])
def test_mean_is_the_static_rail_on_springs_under_the_mean_weight(speed, n):
    passage = Passage.paper(speed=speed)
    cell = soft_cell(passage, n, 2, factor=0.3)
    m = 20
    sleeper, rail = cell_linear_coefficients(passage, cell, m, rail=True)
    k1, k2 = cell.pad_stiffness, cell.stiffness
    springs = k1 * k2 / (k1 + k2)
    weight = -passage.wagon_load / passage.wagon_length                # N/m, downward
    static = beam_on_springs(passage.sleeper_spacing, passage.rail_bending_stiffness,
                             springs, None, weight)
    np.testing.assert_allclose(rail[:, m], static, rtol=1e-10, atol=0)
    np.testing.assert_allclose(sleeper[:, m], static * springs / k2, rtol=1e-10, atol=0)


def test_crawling_train_is_quasi_static():
    passage = Passage.paper(speed=1e-3)
    n, soft = 5, 2
    cell = soft_cell(passage, n, soft, factor=0.4)
    m = 200
    sleeper = cell_linear_coefficients(passage, cell, m)
    samples = 24
    tau = np.arange(samples) / samples                     # t / T
    history = (sleeper[:, None, :] * np.exp(2j * np.pi * tau[:, None]
                                            * np.arange(-m, m + 1))).sum(-1).real

    # a 144 m rail on 241 springs, sleeper j of the cell at node 120 + j
    span, h = passage.sleeper_spacing, passage.wagon_length
    nodes, middle = 241, 120
    k1, k2 = cell.pad_stiffness, cell.stiffness
    pattern = (np.arange(nodes) - middle) % n
    springs = (k1 * k2 / (k1 + k2))[pattern]
    cases = []
    for t in tau:
        # the first axle of a wagon is over sleeper 0 at t = 0; the train runs towards +x
        first = middle * span + t * h + h * np.arange(-12, 13)
        axles = (first[:, None] - np.asarray(passage.axle_positions)).ravel()
        loads = np.broadcast_to(-np.asarray(passage.axle_loads), (first.size, len(
            passage.axle_loads))).ravel()
        inside = (axles >= 0) & (axles <= (nodes - 1) * span)
        cases.append(list(zip(axles[inside], loads[inside])))
    rail = beam_on_springs(span, passage.rail_bending_stiffness, springs, nodes, cases)
    static = (rail[middle:middle + n] * (springs / k2[pattern])[middle:middle + n, None])
    scale = np.abs(static).max()
    np.testing.assert_allclose(history, static, rtol=0, atol=3e-5 * scale)   # 6e-6 measured
    # the soft sleeper dips most when a wheel is over it
    assert history[soft].min() < history[np.arange(n) != soft].min()


@pytest.mark.parametrize("passage, n", [(PAPER, 10), (Passage.paper(speed=80.0), 7)])
def test_weak_zone_dips_and_the_cell_carries_the_train(passage, n):
    soft = 4
    m = 60
    cell = soft_cell(passage, n, soft)
    sleeper, rail = cell_linear_coefficients(passage, cell, m, rail=True)
    assert sleeper[soft, m].real < min(sleeper[soft - 1, m].real, sleeper[soft + 1, m].real)
    tau = np.linspace(0.0, 1.0, 512, endpoint=False)
    history = (sleeper[:, None, :] * np.exp(2j * np.pi * tau[:, None]
                                            * np.arange(-m, m + 1))).sum(-1).real
    low = history.min(axis=1)
    assert low[soft] < min(low[soft - 1], low[soft + 1])
    weight = passage.wagon_load * passage.sleeper_spacing / passage.wagon_length
    foundation = cell.stiffness * sleeper[:, m]
    seat = cell.pad_stiffness * (rail[:, m] - sleeper[:, m])       # what the rail gives the pad
    np.testing.assert_allclose(foundation.mean(), -weight, rtol=1e-12)
    np.testing.assert_allclose(seat.mean(), -weight, rtol=1e-12)
    np.testing.assert_allclose(seat, foundation, rtol=1e-12)        # the sleeper is at rest, n = 0
    # the soft sleeper's foundation takes less, its neighbours more than the weight
    assert -foundation[soft].real < weight < -foundation[soft - 1].real


def test_real_signal_and_shapes():
    cell = soft_cell(PAPER, 3, 1)
    sleeper, rail = cell_linear_coefficients(PAPER, cell, 8, rail=True)
    assert sleeper.shape == rail.shape == (3, 17)
    np.testing.assert_array_equal(sleeper[:, :8], np.conj(sleeper[:, :8:-1]))
    np.testing.assert_array_equal(sleeper[:, 8].imag, 0.0)


@pytest.mark.parametrize("changes, match", [
    (dict(sleeper_mass=[100.0, 0.0]), "sleeper_mass"),
    (dict(stiffness=[20e6, -1.0]), "stiffness"),
    (dict(pad_stiffness=[np.nan, 1e8]), "pad_stiffness"),
    (dict(damping=[0.0, -1.0]), "damping"),
    (dict(pad_damping=[0.0, 1.0, 2.0]), "same count"),
    (dict(stiffness=[[20e6, 20e6]]), "1-D"),
])
def test_cell_is_validated(changes, match):
    values = dict(sleeper_mass=[100.0, 100.0], pad_stiffness=[1e8, 1e8], pad_damping=[0.0, 0.0],
                  stiffness=[20e6, 20e6], damping=[0.0, 0.0])
    values.update(changes)
    with pytest.raises(ValueError, match=match):
        LinearCell(**values)


def test_bad_arguments_are_named():
    cell = LinearCell.identical(PAPER, LAW, 2)
    with pytest.raises(TypeError, match="LinearCell"):
        cell_linear_coefficients(PAPER, LAW, 5)
    with pytest.raises(ValueError, match="harmonics"):
        cell_linear_coefficients(PAPER, cell, 0)
    with pytest.raises(TypeError, match="no field"):
        cell.with_sleeper(0, mass=1.0)
