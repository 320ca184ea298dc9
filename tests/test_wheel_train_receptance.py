"""The free rail under a train of wheels whose forces vary in time (issue 20).

Truths: the sum over the wagon pattern's wavenumbers (Poisson's form, summed
term by term) for the closed form; the paper's moving-load term of eq. (6)
for a constant force read at a fixed point.
"""

import numpy as np
import pytest

from railtrack.equations.cell_receptance import cell_moving_load
from railtrack.equations.wheel_train_receptance import (
    wheel_train_at_fixed_point,
    wheel_train_receptance,
    wheel_train_receptance_lattice_sum,
)
from railtrack.model.passage import Passage


@pytest.mark.parametrize("speed", [45.0, 150.0])
@pytest.mark.parametrize("p", [1, 3, 29, 30, 31, 90])
def test_closed_form_is_the_sum_over_wavenumbers(speed, p):
    passage = Passage.paper(speed=speed)
    omega = p * 2 * np.pi * speed / passage.wagon_length
    offsets = np.array([0.0, 0.3, 3.0, 9.0, 17.9])
    closed = wheel_train_receptance(passage, omega, offsets)
    summed = wheel_train_receptance_lattice_sum(passage, omega, offsets)
    np.testing.assert_allclose(closed, summed, rtol=2e-6, atol=2e-6 * np.abs(summed).max())


def test_offsets_a_wagon_apart_are_the_same_point():
    passage = Passage.paper()
    omega = 5 * 2 * np.pi * passage.speed / passage.wagon_length
    a = wheel_train_receptance(passage, omega, [1.0, 4.0])
    b = wheel_train_receptance(passage, omega, [1.0 + 18.0, 4.0 - 36.0])
    np.testing.assert_allclose(a, b, rtol=1e-12)


def test_a_constant_force_at_a_fixed_point_is_the_papers_load_term():
    passage = Passage.paper()
    n = np.arange(1, 40)
    omega_n = n * 2 * np.pi * passage.speed / passage.wagon_length
    # eq. (6)'s moving-load term for the paper's wagon, per unit downward wheel load
    paper = cell_moving_load(passage, omega_n, 1)[:, 0] / sum(passage.axle_loads)
    ours = sum(-wheel_train_at_fixed_point(passage, 0.0, n, d) * q / sum(passage.axle_loads)
               for d, q in zip(passage.axle_positions, passage.axle_loads))
    np.testing.assert_allclose(ours, paper, rtol=1e-12, atol=1e-12 * np.abs(paper).max())


def test_bad_frequencies_are_refused():
    passage = Passage.paper()
    with pytest.raises(ValueError, match="non-zero"):
        wheel_train_receptance(passage, 0.0, [0.0])
    with pytest.raises(ValueError, match="multiple"):
        wheel_train_at_fixed_point(passage, 1.234, [1], 0.0)
