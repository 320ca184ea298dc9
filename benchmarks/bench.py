"""Speed and iteration counts of the railtrack solvers on the paper's cases.

Run with ``make bench`` (all sections), or ``python benchmarks/bench.py
stability`` for some of them (``targets``, ``solvers``, ``sweep``, ``stability``,
``cells``, ``wheels``, ``ground``, ``statistics``).  ``targets`` (benchmarks/targets.py) is issue 28's table:
each target timed beside its reference in one run.
Prints Markdown tables: the machine, the median wall time of each solve
(median over several runs, each run timing a batch of repeated solves), and
the iterations each method needs to reach a relative residual of 1e-10 of
eq. (17).  Each solve includes its truncation estimate; "auto" also picks m
(railtrack.solvers.truncation).  Times are wall-clock on whatever else the
machine is doing; the iteration counts are exact.  The stability section
times Hill's method (`rt.floquet`, `rt.check_branch`) and the linearised
ring (`rt.ring_multipliers`) on chapter 10's fold track.
"""

from __future__ import annotations

import os
import platform
import statistics
import time
import warnings

import numpy as np
import scipy

import railtrack as rt
from targets import print_targets   # benchmarks/targets.py, beside this file
from bench_flat import bench_flat
from bench_ground import bench_ground
from bench_statistics import bench_statistics

HARMONICS = 15
CASES = {
    "linear": rt.LinearFoundation.paper(),
    "bilinear e = 0.5": rt.BilinearFoundation.paper(0.5),
    "bilinear e = 0 (tensionless)": rt.BilinearFoundation.paper(0.0),
    "cubic eps = 0.8": rt.CubicFoundation.paper(0.8),
}
RUNS = 7
RATIO_RUNS = 15
"""Runs of the auto / m = 15 ratio: single runs on a shared 2-core VM range over 0.8-3x."""
BRANCH_RUNS = 3
"""Runs of `rt.check_branch` on the fold branch (about 10 s each)."""


def median_time(function, repeat: int) -> float:
    """Median over RUNS runs of the mean time of `repeat` calls [s]."""
    function()  # warm caches and imports
    runs = []
    for _ in range(RUNS):
        start = time.perf_counter()
        for _ in range(repeat):
            function()
        runs.append((time.perf_counter() - start) / repeat)
    return statistics.median(runs)


def median_ratio(slow, fast, repeat: int) -> float:
    """Median over RATIO_RUNS runs of time(slow) / time(fast), the two timed back to back.

    Timing both in the same run cancels the drift of a shared machine's
    speed, which moves separate medians by tens of per cent.
    """
    slow(), fast()
    ratios = []
    for _ in range(RATIO_RUNS):
        times = []
        for function in (slow, fast):
            start = time.perf_counter()
            for _ in range(repeat):
                function()
            times.append(time.perf_counter() - start)
        ratios.append(times[0] / times[1])
    return statistics.median(ratios)


def machine() -> str:
    cpu = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo") as info:
            cpu = next(line.split(":", 1)[1].strip() for line in info if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return (
        f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, "
        f"numpy {np.__version__}, scipy {scipy.__version__}"
    )


def main() -> None:
    track, train = rt.Track.paper(), rt.Train.paper()
    print(f"m = {HARMONICS} harmonics unless 'auto', Table 1 track, median of {RUNS} runs.\n")
    print("| case | Newton, m = 15 [ms] | Newton, m = 'auto' [ms] (m chosen) "
          "| auto / m = 15 (timed together) "
          "| fixed point, k = 100 [ms] | Newton steps to 1e-10 | fixed-point iterations "
          "to 1e-10 (N0 = m) |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, law in CASES.items():
        newton_time = median_time(lambda: rt.solve(track, train, law, HARMONICS), 50)
        auto_time = median_time(lambda: rt.solve(track, train, law), 50)
        auto = rt.solve(track, train, law)
        ratio = median_ratio(lambda: rt.solve(track, train, law), lambda: rt.solve(track, train, law, HARMONICS), 50)
        # k = 100 steps: none of these cases reaches tol = 1e-10 sooner
        fixed_time = median_time(
            lambda: rt.solve(track, train, law, HARMONICS, method="fixed-point", max_iterations=100), 5
        )
        newton = rt.solve(track, train, law, HARMONICS, tol=1e-10)
        fixed = rt.solve(track, train, law, HARMONICS, method="fixed-point", tol=1e-10,
                         max_iterations=5000)
        fixed_steps = str(fixed.iterations) if fixed.converged else f"> {fixed.iterations}"
        print(f"| {name} | {newton_time * 1e3:.2f} | {auto_time * 1e3:.2f} ({auto.harmonics}) "
              f"| {ratio:.2f} | {fixed_time * 1e3:.2f} "
              f"| {newton.iterations} | {fixed_steps} |")

    speeds = np.linspace(10.0, 100.0, 1000)
    linear = CASES["linear"]
    sweep = median_time(lambda: rt.sweep_speeds(track, train, linear, speeds, HARMONICS), 5)
    loop = median_time(
        lambda: [rt.solve(track, train.replace(speed=s), linear, HARMONICS, method="analytic")
                 for s in speeds[:100]], 1
    ) * 10
    print()
    print("| linear sweep over 1,000 train speeds (eq. 23) | time [ms] |")
    print("|---|---:|")
    print(f"| vectorised `rt.sweep_speeds` | {sweep * 1e3:.1f} |")
    print(f"| loop of `rt.solve(..., 15, method='analytic')` (100 timed, x10) | {loop * 1e3:.0f} |")

    solution = rt.solve(track, train, linear)
    x = np.linspace(-30.0, 30.0, 1001)          # 100 spans, 10 points a span
    instants = np.linspace(0.0, solution.period, 200, endpoint=False)
    bowl = median_time(lambda: solution.deflection_bowl(instants, x), 5)
    print()
    print("| post-processing (linear law, m = 'auto') | time [ms] |")
    print("|---|---:|")
    print(f"| `deflection_bowl`: 100 spans (1,001 points, 101 sleepers) at 200 instants "
          f"| {bowl * 1e3:.1f} |")

    # The axles enter only the load F_n of eq. (16): a coach should cost what the
    # paper's wagon costs per harmonic.  Both at m = 60, where the bilinear law's
    # Newton needs a few steps, so the time is the residual's, not the set-up's.
    coach = rt.Train.passenger_coach(45.0)
    law = CASES["bilinear e = 0.5"]
    print()
    print("| four-axle coach against the paper's wagon, Newton at m = 60 "
          "| time [ms] | steps | time per harmonic [ms] |")
    print("|---|---:|---:|---:|")
    for label, vehicle in (("paper's wagon (2 axles, 18 m)", train),
                           ("passenger coach (4 axles, 26.4 m)", coach)):
        spent = median_time(lambda: rt.solve(track, vehicle, law, 60), 20)
        steps = rt.solve(track, vehicle, law, 60).iterations
        print(f"| {label} | {spent * 1e3:.2f} | {steps} | {spent * 1e3 / 60:.3f} |")
    ratio = median_ratio(lambda: rt.solve(track, coach, law, 60),
                         lambda: rt.solve(track, train, law, 60), 20)
    print(f"| coach / wagon, timed back to back (median of {RATIO_RUNS}) | {ratio:.2f} | | |")


def bench_sweep() -> None:
    """10,000 cubic-law solves at m = 15 in one batch, against a loop of solve."""
    track, train = rt.Track.paper(), rt.Train.paper()
    law = CASES["cubic eps = 0.8"]
    rng = np.random.default_rng(2015)
    stiffness = rng.normal(20e6, 2e6, 10_000)       # k2 [N/m]
    damping = rng.uniform(1e5, 3e5, 10_000)         # eta2 [N s/m]
    batch = median_time(lambda: rt.sweep(track, train, law, stiffness=stiffness, damping=damping), 1)
    laws = [rt.CubicFoundation(k, 2e13, 0.8, d) for k, d in zip(stiffness[:200], damping[:200])]
    loop = median_time(lambda: [rt.solve(track, train, f, HARMONICS) for f in laws], 1) * 50
    print()
    print("| 10,000 cubic-law solves, m = 15, k2 and eta2 drawn at random | time [s] |")
    print("|---|---:|")
    print(f"| `rt.sweep` (batched Newton) | {batch:.2f} |")
    print(f"| loop of `rt.solve` (200 timed, x50) | {loop:.1f} |")
    print(f"| loop / sweep | {loop / batch:.1f} |")


def bench_stability() -> None:
    """Floquet multipliers by Hill's method against the solve, the ring and a whole branch.

    Chapter 10's fold track at m = 25: `rt.floquet` of the 525 m/s solution
    (timed back to back with the solve), `rt.ring_multipliers` of the same
    solution at 600 steps a period, and `rt.check_branch` of the branch from
    300 to 700 m/s (its target: under 10 s; the ring-based check took 424 s).
    """
    track, law = rt.Track.paper(pad_damping=1e5), rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)
    train = rt.Train.paper(speed=525.0)
    # the method alone, and with the quick look at stability that solve adds by default
    solution = rt.solve(track, train, law, harmonics=25, stability="off")
    solve_time = median_time(lambda: rt.solve(track, train, law, harmonics=25,
                                              stability="off"), 20)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.UnstableSolutionWarning)  # it is, and says so
        looked_time = median_time(lambda: rt.solve(track, train, law, harmonics=25), 20)
    floquet_time = median_time(lambda: rt.floquet(solution), 3)
    ratio = median_ratio(lambda: rt.floquet(solution),
                         lambda: rt.solve(track, train, law, harmonics=25, stability="off"), 1)
    ring_time = median_time(lambda: rt.ring_multipliers(solution, steps_per_period=600), 1)
    branch = rt.continuation(track, rt.Train.paper(speed=300.0), law, "speed", start=300.0,
                             stop=700.0, harmonics=25)
    branch_runs = []
    for _ in range(BRANCH_RUNS):
        start = time.perf_counter()
        checked = rt.check_branch(branch)
        branch_runs.append(time.perf_counter() - start)
    print()
    print("| stability on the fold track (chapter 10), m = 25 | time [ms] |")
    print("|---|---:|")
    print(f"| `rt.solve` at 525 m/s, `stability=\"off\"` (the method alone) | "
          f"{solve_time * 1e3:.1f} |")
    print(f"| `rt.solve` at 525 m/s with its quick look at stability (the default) | "
          f"{looked_time * 1e3:.1f} |")
    print(f"| `rt.floquet` of that solution (Hill's method, {solution.harmonics} harmonics) "
          f"| {floquet_time * 1e3:.0f} |")
    print(f"| floquet / solve alone, timed back to back (median of {RATIO_RUNS}) | {ratio:.0f} |")
    print(f"| `rt.ring_multipliers`, 600 steps a period | {ring_time * 1e3:.0f} |")
    print(f"| `rt.check_branch` of the 300-700 m/s branch ({len(branch.values)} points, "
          f"{len(branch.folds)} folds, {len(checked.changes)} changes; median of "
          f"{BRANCH_RUNS} runs) | {statistics.median(branch_runs) * 1e3:.0f} |")


def bench_cells() -> None:
    """Sleepers that differ (issue 19): one hanging sleeper in a cell of N, harmonics="auto".

    The paper's track and wagon at 45 m/s, sound sleepers on k2 = 20 MN/m,
    eta2 = 0.2 MN s/m, the middle one hanging 1 mm above the same ballast
    (`rt.GapFoundation`); the cost against N = 1 (today's solve of the sound
    track, harmonics="auto") and its growth with N.  The issue's target: under
    0.5 s at N = 30.
    """
    track, train = rt.Track.paper(), rt.Train.paper()
    passage = rt.Passage(track, train)
    sound = rt.LinearFoundation(20e6, 0.2e6)
    today = median_time(lambda: rt.solve(track, train, sound, stability="off"), 10)
    print()
    print("| one hanging sleeper (1 mm) in a cell of N, harmonics=\"auto\" | m | time [ms] "
          "| / N = 1 |")
    print("|---|---:|---:|---:|")
    print(f"| today's solve, N = 1, sound track | "
          f"{rt.solve(track, train, sound, stability='off').harmonics} | {today * 1e3:.1f} | 1 |")
    for n in (10, 30, 60, 100):
        cell = rt.SleeperCell.identical(passage, sound, n).with_sleeper(
            n // 2, foundation=rt.GapFoundation(1e-3, 20e6, 0.2e6))
        result = rt.solve(track, train, cell)
        elapsed = median_time(lambda: rt.solve(track, train, cell), 1)
        print(f"| N = {n} | {result.harmonics} | {elapsed * 1e3:.0f} | {elapsed / today:.0f} |")
    # every sleeper nonlinear: the reduced system is the whole one, solved by GMRES
    cubic = rt.SleeperCell.identical(passage, rt.CubicFoundation.paper(), 30).with_sleeper(
        15, foundation=rt.CubicFoundation(10e6, 2e13, 0.8, 0.2e6))
    result = rt.solve(track, train, cubic)
    elapsed = median_time(lambda: rt.solve(track, train, cubic), 1)
    print(f"| N = 30, every sleeper cubic (eq. 25), one on half the k2 | {result.harmonics} "
          f"| {elapsed * 1e3:.0f} | {elapsed / today:.0f} |")


def bench_wheels() -> None:
    """Wheels on Hertz springs (issue 20): harmonic balance at harmonics="auto" against
    today's constant-force solve of the same track and against the time-domain ring.

    The paper's track and wagon, m_w = 600 kg, C_H = 9.4e10 N/m^1.5.  The issue's
    targets: within ten times today's solve, at least 100 times faster than the ring.
    The ring runs at the resolution of the chapter's agreement table (8 elements a
    bay, 120 steps a sleeper passage), timed RING_RUNS times.
    """
    track, train = rt.Track.paper(), rt.Train.paper()
    wheel = rt.Wheel(600.0)
    dip = rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.3)
    cases = (("smooth rail, linear ballast", rt.LinearFoundation(20e6, 0.2e6), None),
             ("smooth rail, cubic law (eq. 25)", rt.CubicFoundation.paper(), None),
             ("0.5 mm x 1 m dip, linear ballast", rt.LinearFoundation(20e6, 0.2e6), dip))
    print()
    print("| 45 m/s | m | wheels [ms] | constant forces [ms] | ratio | ring [s] | ring / wheels |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, law, profile in cases:
        result = rt.solve(track, train, law, wheel=wheel, profile=profile)
        repeat = 5 if profile is None else 1
        wheels = median_time(lambda: rt.solve(track, train, law, wheel=wheel, profile=profile),
                             repeat)
        today = median_time(lambda: rt.solve(track, train, law, stability="off"), 10)
        ring = statistics.median(_timed(lambda: rt.simulate_time_domain(
            track, train, law, 8, 3600, wheel=wheel, profile=profile, tol=1e-5,
            warn_step_error=None)) for _ in range(RING_RUNS))
        print(f"| {name} | {result.harmonics} | {wheels * 1e3:.0f} | {today * 1e3:.1f} "
              f"| {wheels / today:.0f} | {ring:.1f} | {ring / wheels:.0f} |")


RING_RUNS = 3
"""Runs of each ring (5-20 s each)."""


def _timed(function) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


SECTIONS = {"targets": print_targets, "solvers": main, "sweep": bench_sweep,
            "stability": bench_stability,
            "cells": bench_cells, "wheels": bench_wheels,
            "flat": bench_flat, "ground": bench_ground,
            "statistics": bench_statistics}


if __name__ == "__main__":
    import sys
    import warnings

    warnings.simplefilter("ignore", rt.TruncationWarning)   # m = 15 is the paper's choice here
    unknown = [name for name in sys.argv[1:] if name not in SECTIONS]
    if unknown:
        sys.exit(f"unknown section(s) {unknown}; choose from {sorted(SECTIONS)} (none: all)")
    threads = os.environ.get("OMP_NUM_THREADS", "unset (BLAS's default)")
    print(f"Machine: {machine()}, OMP_NUM_THREADS {threads}\n")
    for name in sys.argv[1:] or SECTIONS:
        SECTIONS[name]()
