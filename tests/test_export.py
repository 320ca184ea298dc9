"""Every result and study exports to xarray, pandas, netCDF and CSV (issue 29, item 4).

For each type: the dataset round-trips through a netCDF file (values and
attributes); its values are the result's own methods evaluated here, at
times made here, and agree with a truth that does not come from the
export (a mean load from statics, a lowest displacement from a finer
grid, a draw solved again); every variable and coordinate has CF units and
a long name; the dimensions are named; the CSV read back is the table.
"""

import dataclasses
import numbers
import warnings

import numpy as np
import pandas as pd
import pytest
import xarray as xr

import railtrack as rt

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
CUBIC = rt.CubicFoundation.paper()
SOUND = rt.LinearFoundation(20e6, 0.2e6)
# sum_j Q_j L / H: what the sleepers carry on average, by statics [N]
MEAN_SEAT_LOAD = sum(TRAIN.axle_loads) * TRACK.sleeper_spacing / TRAIN.wagon_length
SAMPLES = 64


def _close(actual, desired, err_msg=""):
    """Equal to round-off: the export may sum the series on a grid, the method point by point."""
    desired = np.asarray(desired)
    np.testing.assert_allclose(actual, desired, rtol=1e-10, atol=1e-10 * np.abs(desired).max(),
                               err_msg=err_msg)


def _quietly(function, *args, **options):
    """A result built without its warnings (explicit m, an unconverged member on purpose)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return function(*args, **options)


def _times(period, samples=SAMPLES):
    return np.linspace(0.0, period, samples, endpoint=False)


@pytest.fixture(scope="module")
def solution():
    return _quietly(rt.solve, TRACK, TRAIN, CUBIC, 15, stability="full")


@pytest.fixture(scope="module")
def cell():
    cell = rt.SleeperCell.identical(rt.Passage(TRACK, TRAIN), SOUND, 3).with_sleeper(
        1, foundation=rt.LinearFoundation(10e6, 0.1e6))
    return _quietly(rt.solve, TRACK, TRAIN, cell, 12)


@pytest.fixture(scope="module")
def wheels():
    return _quietly(rt.solve, TRACK, TRAIN, SOUND, 30, wheel=rt.Wheel(600.0),
                    profile=rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.3))


@pytest.fixture(scope="module")
def multipliers():
    # the fold track of chapter 10 at 450 m/s: six multipliers in the box
    track = rt.Track.paper(pad_damping=1e5)
    orbit = _quietly(rt.solve, track, rt.Train.paper(speed=450.0),
                     rt.CubicFoundation(20e6, 2e13, 0.8, 5e3), 12, stability="off")
    return rt.floquet(orbit, shifts=False)


@pytest.fixture(scope="module")
def ring():
    return _quietly(rt.simulate_time_domain, TRACK, TRAIN, SOUND, elements_per_span=1,
                                   steps_per_period=120)


@pytest.fixture(scope="module")
def speeds():
    # 3 Newton steps: the first member does not converge and stays "unknown"
    return _quietly(rt.sweep, TRACK, TRAIN, CUBIC, 10, max_iterations=3,
                    speed=[30.0, 300.0, 600.0])


@pytest.fixture(scope="module")
def branch():
    return _quietly(rt.continuation, TRACK, TRAIN, CUBIC, "speed", start=40.0, stop=60.0,
                    harmonics=10)


@pytest.fixture(scope="module")
def draws():
    return _quietly(rt.random_support, TRACK, TRAIN, SOUND, sleepers=4, variation=0.3, draws=3,
                    seed=5)


CASES = {   # fixture, arguments of to_xarray, dimensions expected
    "solution": ("solution", dict(samples=SAMPLES, x=[0.0, 0.3]),
                 {"time", "sleeper", "harmonic", "x"}),
    "cell": ("cell", dict(samples=SAMPLES), {"time", "sleeper", "harmonic"}),
    "wheels": ("wheels", dict(samples=SAMPLES),
               {"time", "sleeper", "harmonic", "wheel", "wheel_harmonic"}),
    "multipliers": ("multipliers", {}, {"multiplier", "base_phase", "harmonic"}),
    "ring": ("ring", {}, {"time", "sleeper", "period", "period_step"}),
    "speeds": ("speeds", {}, {"speed", "harmonic"}),
    "branch": ("branch", {}, {"point", "harmonic"}),
    "draws": ("draws", {}, {"draw", "sleeper"}),
}


def _result(request, case):
    name, options, dims = CASES[case]
    return request.getfixturevalue(name), options, dims


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_dataset_round_trips_through_netcdf(request, tmp_path, case):
    result, options, _ = _result(request, case)
    dataset = result.to_xarray(**options)
    path = result.to_netcdf(tmp_path / f"{case}.nc", **options)
    with xr.open_dataset(path) as back:
        back = back.load()
    xr.testing.assert_allclose(back, dataset, rtol=1e-14, atol=0.0)
    assert back.attrs.keys() == dataset.attrs.keys()
    for key, value in dataset.attrs.items():
        np.testing.assert_array_equal(back.attrs[key], value, err_msg=key)
    for name, array in dataset.variables.items():   # flags and words come back as such
        assert back[name].dtype.kind == array.dtype.kind or {back[name].dtype.kind,
                                                             array.dtype.kind} <= {"U", "O"}


@pytest.mark.parametrize("case", sorted(CASES))
def test_every_variable_has_cf_units_and_a_long_name_and_named_dimensions(request, case):
    result, options, dims = _result(request, case)
    dataset = result.to_xarray(**options)
    assert set(dataset.dims) == dims
    assert dataset.attrs["Conventions"] == "CF-1.10"
    assert dataset.attrs["railtrack_version"] == rt.__version__
    for name, array in dataset.variables.items():
        assert array.attrs.get("units") and array.attrs.get("long_name"), name
        assert not np.iscomplexobj(array.values), name
    for key, value in dataset.attrs.items():     # what netCDF holds as an attribute
        ok = isinstance(value, (str, numbers.Number)) or (
            isinstance(value, np.ndarray) and value.ndim == 1 and value.dtype.kind in "iuf")
        assert ok and not isinstance(value, bool), (key, value)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_csv_read_back_is_the_table(request, tmp_path, case):
    result, options, _ = _result(request, case)
    options = {k: v for k, v in options.items() if k != "x"}
    table = result.to_dataframe(**options)
    back = pd.read_csv(result.to_csv(tmp_path / f"{case}.csv", **options))
    assert len(table) and list(back.columns) == list(table.columns)
    pd.testing.assert_frame_equal(back, table, check_exact=True,
                                  check_dtype=True)


def test_a_solution_is_its_own_methods_at_the_times_given(solution):
    dataset = solution.to_xarray(samples=SAMPLES, x=[0.0, 0.3])
    t = _times(solution.period)
    np.testing.assert_array_equal(dataset["time"], t)
    one = dataset.sel(sleeper=0)
    for name, values in [("sleeper_displacement", solution.sleeper_displacement(t)),
                         ("sleeper_velocity", solution.sleeper_velocity(t)),
                         ("rail_seat_load", solution.rail_seat_load(t)),
                         ("foundation_force", solution.foundation_force(t)),
                         ("rail_displacement_at_sleeper", solution.rail_displacement(t))]:
        _close(one[name], values, err_msg=name)
    _close(dataset["rail_bending_moment"].sel(x=0.3), solution.rail_bending_moment(t, 0.3))
    c = one["sleeper_displacement_coefficient_real"] + 1j * one[
        "sleeper_displacement_coefficient_imag"]
    np.testing.assert_array_equal(c, solution.coefficients)
    # statics: the sleeper carries sum Q L / H on average
    assert float(one["rail_seat_load"].mean()) == pytest.approx(MEAN_SEAT_LOAD, rel=1e-9)
    attrs = dataset.attrs
    assert (attrs["train_speed"], attrs["foundation_law"]) == (TRAIN.speed, "CubicFoundation")
    assert attrs["foundation_law_cubic_stiffness"] == CUBIC.cubic_stiffness
    assert (attrs["converged"], attrs["harmonics"]) == (1, 15)
    assert attrs["residual"] == solution.residual
    assert attrs["truncation_error"] == solution.truncation_error
    assert attrs["stability_verdict"] == solution.stability.verdict
    np.testing.assert_array_equal(attrs["train_axle_loads"], TRAIN.axle_loads)
    assert "train_speed: m s-1" in attrs["input_units"]
    table = solution.to_dataframe(samples=SAMPLES)
    np.testing.assert_array_equal(table["rail_seat_load[0]"], one["rail_seat_load"])


def test_a_cell_gives_every_sleeper_its_own_history_and_law(cell):
    dataset = cell.to_xarray(samples=SAMPLES)
    t = _times(cell.period)
    for j in range(3):
        sleeper = dataset.sel(sleeper=j)
        _close(sleeper["sleeper_displacement"], cell.sleeper_displacement(t)[j])
        _close(sleeper["rail_seat_load"], cell.rail_seat_load(t)[j])
        x = j * TRACK.sleeper_spacing
        assert float(sleeper["sleeper_position"]) == pytest.approx(x)
        # the pads' relation (the export) and the rail field (the method) agree
        peak = float(np.abs(sleeper["rail_displacement_at_sleeper"]).max())
        np.testing.assert_allclose(sleeper["rail_displacement_at_sleeper"],
                                   cell.rail_displacement(t, x), rtol=1e-9, atol=1e-9 * peak)
        _close(sleeper["rail_bending_moment_at_sleeper"], cell.rail_bending_moment(t, x))
    np.testing.assert_array_equal(dataset["foundation_stiffness"], [20e6, 10e6, 20e6])
    assert list(dataset["foundation_law"].values) == ["LinearFoundation"] * 3
    # the softer sleeper carries less, and the cell as a whole sum Q L / H per sleeper
    mean = dataset["rail_seat_load"].mean("time")
    assert float(mean[1]) < float(mean[0])
    assert float(mean.mean()) == pytest.approx(MEAN_SEAT_LOAD, rel=1e-9)


def test_wheels_carry_their_static_loads_on_average(wheels):
    dataset = wheels.to_xarray(samples=256)
    t = _times(wheels.period, 256)
    for k in range(2):
        _close(dataset["contact_force"].sel(wheel=k), wheels.contact_force(t)[k])
        _close(dataset["wheel_displacement"].sel(wheel=k), wheels.wheel_displacement(t)[k])
    j = 15
    _close(dataset["sleeper_displacement"].sel(sleeper=j), wheels.sleeper_displacement(t)[j])
    _close(dataset["rail_seat_load"].sel(sleeper=j), wheels.rail_seat_load(t)[j])
    x = j * TRACK.sleeper_spacing
    _close(dataset["rail_bending_moment_at_sleeper"].sel(sleeper=j),
           wheels.rail_bending_moment(t, x))
    _close(dataset["rail_displacement_at_sleeper"].sel(sleeper=j), wheels.rail_displacement(t, x))
    # statics: each wheel presses with its axle load Q on average
    np.testing.assert_allclose(dataset["contact_force"].mean("time"), dataset["axle_load"],
                               rtol=1e-9)
    p = dataset["contact_force_harmonic_real"] + 1j * dataset["contact_force_harmonic_imag"]
    np.testing.assert_array_equal(p, wheels.contact_harmonics)
    assert dataset.attrs["wheel_unsprung_mass"] == 600.0
    assert dataset.attrs["profile"] == "CosineDip" and dataset.attrs["profile_depth"] == 0.5e-3


def test_floquet_multipliers_split_into_parts(multipliers):
    dataset = multipliers.to_xarray()
    mu = dataset["multiplier_real"] + 1j * dataset["multiplier_imag"]
    assert mu.size == multipliers.multipliers.size > 0
    np.testing.assert_array_equal(mu, multipliers.multipliers)
    np.testing.assert_allclose(dataset["multiplier_modulus"],
                               np.exp(dataset["exponent_real"] * multipliers.period),
                               rtol=1e-9)           # |mu| = e^{Re lambda T}
    np.testing.assert_array_equal(dataset["resolved"], multipliers.resolved)
    assert dataset.attrs["verdict"] == multipliers.verdict


def test_the_ring_keeps_its_own_grid_and_every_sleeper(ring):
    dataset = ring.to_xarray()
    np.testing.assert_array_equal(dataset["time"], ring.times)
    for i in (0, 7):
        np.testing.assert_array_equal(dataset["sleeper_displacement"].sel(sleeper=i),
                                      ring.sleeper_displacements[:, i])
        np.testing.assert_array_equal(dataset["rail_seat_load"].sel(sleeper=i),
                                      ring.rail_seat_loads[:, i])
    np.testing.assert_array_equal(dataset["rail_displacement_at_sleeper_0"],
                                  ring.rail_displacement)
    assert float(dataset["rail_seat_load"].sel(sleeper=0).mean()) == pytest.approx(
        MEAN_SEAT_LOAD, rel=1e-3)
    assert dataset.attrs["converged"] == int(ring.converged)
    assert dataset.attrs["steps_per_period"] == 120


def test_a_sweep_member_that_failed_stays_unknown_and_nan(speeds):
    dataset = speeds.to_xarray()
    assert not speeds.converged[0] and speeds.converged[1:].all()
    assert list(dataset["stability"].values)[0] == "unknown"
    assert np.isnan(dataset["dominant_multiplier_real"][0])
    assert np.isnan(dataset["dominant_multiplier_imag"][0])     # no made-up 0j
    np.testing.assert_array_equal(dataset["converged"], speeds.converged)
    for i, v in enumerate(speeds.values["speed"]):
        member = speeds.solution(i)
        t = _times(member.period, 8192)      # the sweep reads 256 samples and a parabola
        assert float(dataset["seat_load_peak"].sel(speed=v)) == pytest.approx(
            member.rail_seat_load(t).max(), rel=1e-4)
        assert float(dataset["lowest"].sel(speed=v)) == pytest.approx(
            member.sleeper_displacement(t).min(), rel=1e-4)
    table = speeds.to_dataframe()
    assert list(table["speed"]) == [30.0, 300.0, 600.0]
    assert table["stability"][0] == "unknown"


def test_a_sweep_of_two_fields_runs_along_member():
    both = _quietly(rt.sweep, TRACK, TRAIN, CUBIC, 8, speed=[30.0, 50.0],
                    pad_damping=[1e5, 2e5])
    dataset = both.to_xarray()
    assert dataset["converged"].dims == ("member",)
    np.testing.assert_array_equal(dataset["pad_damping"], [1e5, 2e5])
    assert dataset["pad_damping"].attrs["units"] == "N s m-1"
    assert "train_speed" not in dataset.attrs and "track_pad_damping" not in dataset.attrs


def test_a_branch_exports_each_point(branch):
    dataset = branch.to_xarray()
    np.testing.assert_array_equal(dataset["speed"], branch.values)
    assert dataset["speed"].attrs["units"] == "m s-1"
    for i in (0, len(branch) - 1):
        point = branch.solution(i)
        fine = point.sleeper_displacement(_times(point.period, 4096)).min()
        assert float(dataset["minimum_displacement"][i]) == pytest.approx(fine, rel=1e-4)
        c = dataset["sleeper_displacement_coefficient_real"][i] + 1j * dataset[
            "sleeper_displacement_coefficient_imag"][i]
        np.testing.assert_array_equal(c, point.coefficients[branch.harmonics:])
        assert float(dataset["truncation_error"][i]) == point.truncation_error
    assert dataset.attrs["parameter"] == "speed"


def test_random_support_records_its_inputs_and_each_draw(draws):
    dataset = draws.to_xarray()
    np.testing.assert_array_equal(dataset["factor"], draws.factors)
    assert dataset.attrs["seed"] == 5 and dataset.attrs["variation"] == 0.3
    assert dataset.attrs["foundation_law_stiffness"] == SOUND.stiffness
    # draw 1 solved again, alone: its largest rail-seat load
    base = rt.SleeperCell.identical(rt.Passage(TRACK, TRAIN), SOUND, 4)
    laws = tuple(dataclasses.replace(SOUND, stiffness=SOUND.stiffness * x)
                 for x in draws.factors[1])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        alone = rt.solve(TRACK, TRAIN, dataclasses.replace(base, foundations=laws),
                         int(draws.harmonics[1]))
    peak = alone.rail_seat_load(_times(alone.period, 512)).max()
    assert float(dataset["peak_seat_load"][1]) == pytest.approx(peak, rel=1e-3)
    table = draws.to_dataframe()
    assert list(table.columns[:2]) == ["draw", "factor[0]"]


def test_a_ring_of_a_cell_and_with_wheels_exports_them(ring):
    cell = rt.SleeperCell.identical(rt.Passage(TRACK, TRAIN), SOUND, 3).with_sleeper(
        1, foundation=rt.LinearFoundation(10e6, 0.1e6))
    of_cell = _quietly(rt.simulate_time_domain, TRACK, TRAIN, cell, elements_per_span=1,
                       steps_per_period=120).to_xarray()
    np.testing.assert_array_equal(of_cell["cell_foundation_stiffness"], [20e6, 10e6, 20e6])
    assert of_cell.attrs["foundation_law"] == "SleeperCell"
    # the ring's wheel outputs, mapped by name: (steps, J) becomes (wheel, time)
    forces = np.outer(np.cos(2 * np.pi * ring.times / ring.times[-1]), [1.0, 2.0]) + 75e3
    with_wheels = dataclasses.replace(ring, contact_forces=forces, wheel=rt.Wheel(600.0),
                                      wheel_displacements=-forces * 1e-8,
                                      rail_under_wheels=-forces * 2e-8).to_xarray()
    np.testing.assert_array_equal(with_wheels["contact_force"].sel(wheel=1), forces[:, 1])
    np.testing.assert_array_equal(with_wheels["rail_under_wheel"].sel(wheel=0),
                                  -forces[:, 0] * 2e-8)
    assert with_wheels.attrs["wheel_unsprung_mass"] == 600.0
    assert set(with_wheels.dims) >= {"wheel", "time", "sleeper"}


def test_folds_and_stability_changes_of_a_branch_round_trip(branch, tmp_path):
    k = len(branch)
    judged = dataclasses.replace(
        branch, folds=(rt.Fold(50.0, 3),),
        changes=(rt.StabilityChange(50.0, 3, "fold", 0.0, 0.0, False),),
        stable=np.array([True] * 4 + [None] * (k - 4), dtype=object),
        multipliers=np.r_[np.full(4, 0.5 + 0.1j), np.full(k - 4, np.nan)])
    dataset = judged.to_xarray()
    assert list(dataset["stability"].values[3:5]) == ["stable", "unknown"]
    assert np.isnan(dataset["dominant_multiplier_imag"][4])
    assert float(dataset["fold_value"][0]) == 50.0
    assert dataset["fold_value"].attrs["units"] == "m s-1"
    with xr.open_dataset(judged.to_netcdf(tmp_path / "judged.nc")) as back:
        xr.testing.assert_identical(back.load(), dataset)
    assert bool(back["change_gains"][0]) is False and str(back["change_kind"][0].values) == "fold"


def test_bad_arguments_are_named(solution):
    with pytest.raises(ValueError, match="samples"):
        solution.to_xarray(samples=1)
    with pytest.raises(ValueError, match="x .*1-D"):
        solution.to_xarray(x=np.zeros((2, 2)))


def test_a_law_given_as_a_function_is_recorded_by_name(tmp_path):
    def ballast(w, v):
        return 20e6 * w + 0.2e6 * v

    solution = _quietly(rt.solve, TRACK, TRAIN, ballast, 10)
    dataset = solution.to_xarray(samples=16)
    assert (dataset.attrs["foundation_law"], dataset.attrs["foundation_law_law"]) == (
        "CallableFoundation", "test_a_law_given_as_a_function_is_recorded_by_name.<locals>.ballast")
    with xr.open_dataset(solution.to_netcdf(tmp_path / "f.nc", samples=16)) as back:
        assert back.attrs["foundation_law_law"] == dataset.attrs["foundation_law_law"]
