"""The dynamic wheel load's statistics (issue 32): ``python benchmarks/bench.py statistics``.

The Manchester vehicle (one wagon, H = 26.4 m) on the paper's track and
linear foundation, rails of the FRA spectrum between 1.5 and 25 m
(`railtrack.studies.wheel_load_statistics`).  First the times: one solve,
the spectral integral on the track, and a Monte Carlo of 1000 realisations
on a class-4 track at 45 m/s (some 8 minutes on one core).  Then the
table: sigma / Q of the wheel load by a Monte Carlo of 100 realisations
(all of it, and without the sleepers' part), by the spectral sum over the
same harmonics and by the integral on the track, on a rigid track, and
Eisenmann's n phi for a very good, good and poor track
(`railtrack.equations.eisenmann`), each for the wheel with the largest
sigma.  Three decimals: the realisations' spread moves none of them.
"""

from __future__ import annotations

import statistics
import time

import numpy as np

import railtrack as rt
from railtrack.equations.eisenmann import eisenmann_std_ratio
from railtrack.equations.track_wheel_load import track_wheel_load_std
from railtrack.equations.vehicle_response import spectral_wheel_load_std
from railtrack.model.irregularity import FRASpectrum
from railtrack.model.random_profile import RandomProfile
from railtrack.studies.wheel_load_statistics import wheel_load_statistics

CAR = rt.Vehicle.manchester()
TRACK, LAW = rt.Track.paper(), rt.LinearFoundation.paper()
H, BAND = 26.4, (1.5, 25.0)
LONG_RUN = 1000
TABLE_RUN = 100
CLASSES, SPEEDS = (3, 4, 5), (30.0, 45.0, 55.0)
"""55 m/s = 198 km/h: Eisenmann's speed factor stops at 200 km/h."""


def _time(function) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def print_times(realisations: int = LONG_RUN) -> None:
    spectrum, speed = FRASpectrum(4), 45.0
    train = CAR.train(H, speed)
    rail = RandomProfile(spectrum, BAND, H, seed=0)
    one = statistics.median(_time(lambda: rt.solve(TRACK, train, LAW, wheel=CAR, profile=rail))
                            for _ in range(5))
    integral = _time(lambda: track_wheel_load_std(CAR, TRACK, LAW, spectrum, speed, BAND, H))
    start = time.perf_counter()
    found = wheel_load_statistics(TRACK, LAW, CAR, spectrum, speed, wagon_length=H,
                                  realisations=realisations, progress=False)
    total = time.perf_counter() - start
    print()
    print("| FRA class 4, 45 m/s, Manchester wagon, paper's track | time [s] |")
    print("|---|---:|")
    print(f"| one `rt.solve` with the vehicle on a random rail (median of 5) | {one:.2f} |")
    print(f"| the spectral integral on the track (4 wheelsets) | {integral:.2f} |")
    print(f"| Monte Carlo of {realisations} realisations | {total:.0f} |")
    print(f"\n{found.summary()}")


def print_table(realisations: int = TABLE_RUN) -> None:
    print()
    print(f"| FRA class | v [m/s] | MC ({realisations}) | MC, rail only | spectral sum "
          f"| spectral integral | rigid track | Eisenmann 0.1/0.2/0.3 | not conv. | MC [s] |")
    print("|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|")
    for level in CLASSES:
        spectrum = FRASpectrum(level)
        for speed in SPEEDS:
            start = time.perf_counter()
            found = wheel_load_statistics(TRACK, LAW, CAR, spectrum, speed, wagon_length=H,
                                          realisations=realisations, progress=False)
            seconds = time.perf_counter() - start
            q = found.static_load
            k = int(np.argmax(found.pooled_std))
            # the spectral functions give the wheelset's force: twice the wheel's
            on = [track_wheel_load_std(CAR, TRACK, LAW, spectrum, speed, BAND, H,
                                       period=p)[k] / (2 * q) for p in (H, None)]
            rigid = spectral_wheel_load_std(CAR, spectrum, speed, BAND)[k] / (2 * q)
            eisenmann = "/".join(f"{eisenmann_std_ratio(speed, c):.2f}"
                                 for c in ("very good", "good", "poor"))
            print(f"| {level} | {speed:.0f} | {found.pooled_std[k] / q:.3f} "
                  f"| {found.rail_std[k] / q:.3f} | {on[0]:.3f} | {on[1]:.3f} "
                  f"| {rigid:.3f} | {eisenmann} | {found.failed} | {seconds:.0f} |")


def bench_statistics() -> None:
    print_times()
    print_table()
