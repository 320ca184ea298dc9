"""The energy balance of the steady state (railtrack.solvers.energy).

The rail has no damping, so over one period the work of a wagon's moving
wheel loads, shared among its H/L sleepers, must be what one sleeper's pad
and foundation dissipate.  The two sides are computed from different parts
of the model (the rail field at the moving contact points against the
sleeper's own motion and pad force), so the balance checks eqs. (3)-(19) end
to end.
"""

import numpy as np
import pytest

import railtrack as rt

CASES = {
    "paper, linear": (rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper()),
    "paper, bilinear e = 0.5": (rt.Track.paper(), rt.Train.paper(), rt.BilinearFoundation.paper(0.5)),
    "paper, cubic": (rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper()),
    "light damping near resonance": (
        rt.Track.paper(pad_damping=30e3),
        rt.Train.paper(speed=365.0),
        rt.LinearFoundation(20e6, 20e3),
    ),
    "ballasted, four-axle coach": (
        rt.Track.ballasted(),
        rt.Train.passenger_coach(speed=60.0),
        rt.LinearFoundation.ballasted(),
    ),
}


@pytest.mark.parametrize("name", CASES)
def test_the_loads_work_is_what_the_pad_and_foundation_dissipate(name):
    solution = rt.solve(*CASES[name])
    assert solution.converged
    spent = rt.dissipation(solution)
    assert spent.pad > 0 and spent.foundation > 0
    assert rt.load_work(solution) == pytest.approx(spent.total, rel=1e-4)


def test_a_linear_foundation_dissipates_eta2_times_the_mean_square_velocity():
    # Parseval: int eta2 w'^2 dt = eta2 T sum_n omega_n^2 |c_n|^2.
    solution = rt.solve(*CASES["paper, linear"])
    omega, c = solution.frequencies, solution.coefficients
    expected = 0.2e6 * solution.period * np.sum(omega**2 * np.abs(c) ** 2)
    assert rt.dissipation(solution).foundation == pytest.approx(expected, rel=1e-10)


def test_an_undamped_pad_dissipates_nothing():
    track, train, law = CASES["paper, linear"]
    solution = rt.solve(track.replace(pad_damping=1e-9), train, law)
    spent = rt.dissipation(solution)
    assert abs(spent.pad) < 1e-12 * spent.foundation


def test_help_of_dissipation_lists_every_field_of_its_result():
    # help(rt.dissipation) is where a user looks for .ground and .total
    import dataclasses
    import pydoc

    shown = pydoc.render_doc(rt.dissipation, renderer=pydoc.plaintext)
    returns = shown.split("Returns", 1)[1].split("Examples", 1)[0]
    fields = [f.name for f in dataclasses.fields(rt.Dissipation)]
    properties = [name for name, value in vars(rt.Dissipation).items()
                  if isinstance(value, property)]
    assert {"ground", "total"} <= set(fields + properties)
    for name in fields + properties:
        assert f"``.{name}``" in returns, name
