"""`random_support` solved as a batch (issue 28): the same draws as one by one, anywhere.

Independent truth: each draw rebuilt here as a `SleeperCell` from the
sample's own factors and solved alone by `railtrack.solve` at the m the batch
kept; its peaks read from the `CellSolution` (the seat load at 512 instants,
the moment under each wheel at 8 points a span).  The batch must give the
same numbers to round-off (it solves the same equations, with its operators
shared), whatever executor runs its chunks, and write nothing unless asked.
"""

from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import numpy as np
import pytest
from threadpoolctl import threadpool_info

import railtrack as rt
from railtrack.solvers.threads import blas_threads

TRACK = rt.Track.paper()
TRAIN = rt.Train(18.0, (0.0, 3.0), (60e3, 90e3), 45.0)
PASSAGE = rt.Passage(TRACK, TRAIN)
LAW = rt.LinearFoundation(20e6, 0.2e6)


def hand_built(factors, law=LAW):
    cell = rt.SleeperCell.identical(PASSAGE, law, len(factors))
    for j, x in enumerate(factors):
        cell = cell.with_sleeper(j, foundation=rt.LinearFoundation(law.stiffness * x,
                                                                   law.damping))
    return cell


def peaks(solution, sleepers):
    t = solution.one_period(512)[0]
    seat = solution.rail_seat_load(t).max()
    x = np.arange(sleepers * 8) * PASSAGE.sleeper_spacing / 8
    under = np.mod((x[:, None] + np.asarray(TRAIN.axle_positions)) / TRAIN.speed,
                   solution.period)
    return seat, solution.rail_bending_moment(under, x[:, None]).max()


@pytest.mark.parametrize("harmonics", [30, "auto"])
def test_each_batched_draw_is_its_cell_solved_alone(harmonics):
    sample = rt.random_support(TRACK, TRAIN, LAW, sleepers=6, variation=0.4, draws=4,
                               seed=11, harmonics=harmonics)
    assert sample.converged.all()
    assert sample.stability.tolist() == ["stable"] * 4        # linear laws
    for row, m, seat, moment in zip(sample.factors, sample.harmonics,
                                    sample.peak_seat_load, sample.peak_moment):
        alone = rt.solve(TRACK, TRAIN, hand_built(row), int(m), stability="off")
        own_seat, own_moment = peaks(alone, 6)
        assert seat == pytest.approx(own_seat, rel=1e-10)
        assert moment == pytest.approx(own_moment, rel=1e-10)
        if harmonics == "auto":
            # the level kept meets "auto"'s accuracy for this draw by its own estimate
            assert alone.truncation_error <= 1e-3


def test_auto_steps_up_the_draws_that_miss_the_accuracy(monkeypatch):
    # the mean cell's m (48 here) is enough for every draw of a real scatter;
    # start the levels at m = 20 instead, and every draw must be stepped up to
    # an m at which its own estimate (rt.solve's, alone) meets "auto"'s 1e-3
    from types import SimpleNamespace

    import railtrack.studies.random_support_batch as batch

    monkeypatch.setattr(batch, "solve_cell_auto",
                        lambda *args, **kw: SimpleNamespace(harmonics=20))
    sample = rt.random_support(TRACK, TRAIN, LAW, sleepers=6, variation=0.6, draws=3,
                               seed=2)
    assert sample.converged.all() and sample.harmonics.min() > 20
    for row, m in zip(sample.factors, sample.harmonics):
        alone = rt.solve(TRACK, TRAIN, hand_built(row), int(m), stability="off")
        assert alone.truncation_error <= 1e-3
        # and the level below would not have done (m grows by 10 % at least)
        assert rt.solve(TRACK, TRAIN, hand_built(row), 20,
                        stability="off").truncation_error > 1e-3


OPTIONS = dict(sleepers=4, variation=0.3, draws=120, seed=5, harmonics=20)


@pytest.mark.parametrize("pool", [ThreadPoolExecutor, ProcessPoolExecutor])
def test_an_executor_gives_the_serial_answer(pool):
    serial = rt.random_support(TRACK, TRAIN, LAW, **OPTIONS)
    with pool(max_workers=2) as executor:
        spread = rt.random_support(TRACK, TRAIN, LAW, executor=executor, **OPTIONS)
    for name in ("peak_seat_load", "peak_moment"):
        np.testing.assert_allclose(getattr(spread, name), getattr(serial, name),
                                   rtol=1e-12, atol=0)
    np.testing.assert_array_equal(spread.converged, serial.converged)
    np.testing.assert_array_equal(spread.harmonics, serial.harmonics)


def test_a_nonlinear_law_is_solved_draw_by_draw_on_an_executor_too():
    law = rt.BilinearFoundation(20e6, 10e6, 2e5)
    options = dict(sleepers=3, variation=0.2, draws=3, seed=1, harmonics=30)
    serial = rt.random_support(TRACK, TRAIN, law, **options)
    with ThreadPoolExecutor(max_workers=2) as executor:
        spread = rt.random_support(TRACK, TRAIN, law, executor=executor, **options)
    assert serial.converged.all()
    np.testing.assert_allclose(spread.peak_seat_load, serial.peak_seat_load, rtol=1e-12)


def test_progress_writes_only_when_asked(capsys):
    options = dict(sleepers=3, draws=2, harmonics=30)
    rt.random_support(TRACK, TRAIN, LAW, **options)
    rt.random_support(TRACK, TRAIN, LAW, progress=False, **options)
    quiet = capsys.readouterr()
    assert quiet.out == "" and quiet.err == ""
    rt.random_support(TRACK, TRAIN, LAW, progress=True, **options)
    assert "random_support" in capsys.readouterr().err
    with pytest.raises(TypeError, match="progress"):
        rt.random_support(TRACK, TRAIN, LAW, progress="yes", **options)
    with pytest.raises(TypeError, match="executor"):
        rt.random_support(TRACK, TRAIN, LAW, executor=object(), **options)



def test_a_sweep_the_size_of_the_books_shows_no_progress(capsys):
    # chapter 10 sweeps 10,000 members: a bar there is output nbval reads as changed
    stiffness = np.linspace(15e6, 25e6, 10_000)
    rt.sweep(TRACK, rt.Train.paper(), rt.CubicFoundation.paper(), 15,
             stiffness=stiffness, stability="off")
    shown = capsys.readouterr()
    assert shown.out == "" and shown.err == ""
    rt.sweep(TRACK, rt.Train.paper(), rt.CubicFoundation.paper(), 15,
             stiffness=stiffness[:100], stability="off", progress=True)
    assert "sweep" in capsys.readouterr().err

def _blas_threads():
    return [pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas"]


def test_blas_threads_limits_inside_and_restores_after():
    before = _blas_threads()
    with blas_threads(1):
        assert all(n == 1 for n in _blas_threads())
    assert _blas_threads() == before


def test_a_sweep_gives_the_same_members_on_an_executor_and_in_blocks(monkeypatch):
    import railtrack.studies.sweep as sweep_module

    law = rt.CubicFoundation.paper()
    speeds = np.linspace(30.0, 90.0, 7)
    serial = rt.sweep(TRACK, rt.Train.paper(), law, 15, speed=speeds, stability="off")
    monkeypatch.setattr(sweep_module, "BLOCK", 3)          # three blocks
    with ThreadPoolExecutor(max_workers=2) as executor:
        spread = rt.sweep(TRACK, rt.Train.paper(), law, 15, speed=speeds,
                          stability="off", executor=executor)
    np.testing.assert_allclose(spread.coefficients, serial.coefficients, rtol=1e-12,
                               atol=1e-12 * np.abs(serial.coefficients).max())
    np.testing.assert_array_equal(spread.converged, serial.converged)


def test_any_object_with_submit_runs_the_chunks_in_order():
    # a Dask Client's futures are not concurrent.futures ones: only
    # submit(...).result() is used, and the results keep the chunks' order
    from railtrack.solvers.chunk_map import map_chunks

    class Later:
        def __init__(self, value):
            self.value = value

        def result(self):
            return self.value

    class Client:
        def submit(self, function, *args):
            return Later(function(*args))

    assert map_chunks(pow, [(2, k) for k in range(5)], [1] * 5,
                      executor=Client()) == [1, 2, 4, 8, 16]


def test_the_seat_peak_of_many_harmonics_is_the_same_sum():
    # from m = 256 the 512 instants alias an FFT: the peak is then summed
    # directly; with the harmonics above 254 zero both ways must agree
    from railtrack.studies.random_support_batch import _seat_peaks

    rng = np.random.default_rng(3)
    seat = np.zeros((2, 3, 301), dtype=complex)
    seat[..., :255] = rng.normal(size=(2, 3, 255)) + 1j * rng.normal(size=(2, 3, 255))
    seat[..., 0] = seat[..., 0].real
    np.testing.assert_allclose(_seat_peaks(seat), _seat_peaks(seat[..., :255]),
                               rtol=1e-12)
