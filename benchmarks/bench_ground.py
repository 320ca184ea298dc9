"""The sleepers on a layered soil (issue 31): ``python benchmarks/bench.py ground``.

One row per soil under the paper's track and wagon at 45 m/s with the cubic
law of eq. (25) at harmonics="auto": the plain solve on a rigid ground, the
first solve on the soil (its lattice sums R_g for every harmonic the solve
and its truncation estimate use, up to 8 m), and a second solve at the same
speed with another law (eps = 0.5), which finds R_g remembered.  The issue's
target: a solve on the ground within 10 times a solve on springs at the same
m, the ground's stiffness computed once per speed.
"""

from __future__ import annotations

import statistics
import time

import railtrack as rt
from railtrack.equations.ground_layered import LayeredGround
from railtrack.model.ground import Ground, SoilLayer
from railtrack.solvers import ground_solve

SOILS = {
    "two layers (80 m/s, 3 m, over 250 m/s)": Ground(
        (SoilLayer(80.0, 0.3, 1800.0, 0.05, thickness=3.0),), SoilLayer(250.0, 0.3, 2000.0, 0.03)),
    "soft clay (65 m/s, 6 m, over 200 m/s)": Ground(
        (SoilLayer(65.0, 0.49, 1500.0, 0.02, thickness=6.0),),
        SoilLayer(200.0, 0.45, 1900.0, 0.02)),
    "half-space (100 m/s)": Ground.homogeneous(100.0, 0.3, 1800.0, 0.02),
}
WIDTH, FOOTPRINT = 2.5, 0.25          # the strip under the sleepers [m], the footprint [m]
RUNS = 5


def _time(function) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def bench_ground() -> None:
    track, train = rt.Track.paper(), rt.Train.paper()
    law, other = rt.CubicFoundation.paper(0.8), rt.CubicFoundation.paper(0.5)
    print()
    print("| 45 m/s, eq. (25), auto m | m | springs [ms] | first on the soil [s] | ratio "
          "| again, same speed [ms] | ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, soil in SOILS.items():
        ground = LayeredGround(soil, WIDTH, FOOTPRINT)
        plain = statistics.median(_time(lambda: rt.solve(track, train, law, stability="off"))
                                  for _ in range(RUNS))
        ground_solve._GROUNDS.clear()                   # nothing remembered: the first solve
        first = _time(lambda: rt.solve(track, train, law, ground=ground, stability="off"))
        again = statistics.median(_time(lambda: rt.solve(track, train, other, ground=ground,
                                                         stability="off")) for _ in range(RUNS))
        m = rt.solve(track, train, law, ground=ground, stability="off").harmonics
        print(f"| {name} | {m} | {plain * 1e3:.1f} | {first:.1f} | {first / plain:.0f} "
              f"| {again * 1e3:.1f} | {again / plain:.1f} |")
