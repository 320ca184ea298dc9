"""A wheel flat's P1 (issue 32): ``python benchmarks/bench.py flat``.

Harmonic balance at m = 1200 against the time-domain ring on the case of
docs/flat_p1.md, both timed here in one run, with the ratio of their times.
"""

from __future__ import annotations

import statistics
import time
import warnings

import numpy as np

import railtrack as rt

RING_RUNS = 3
"""Runs of the ring (about 10 s each)."""


def _median(function, repeat: int) -> float:
    """The median wall time [s] of `repeat` calls."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def bench_flat() -> None:
    """A wheel flat's P1 (issue 32): harmonic balance at m = 1200 against the ring.

    The case of docs/flat_p1.md: the ballasted track, the paper's wagon at 30 m/s,
    a 600 kg wheel, a 0.5 mm x 100 mm flat on the second wheel (circumference 3.0 m).
    The ring at the resolution of chapter 17's check (4 elements a span, 14400 steps).
    """
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    law, wheel = rt.LinearFoundation.ballasted(), rt.Wheel(600.0)
    flat = rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1, centre=0.3)
    m = 1200
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.TruncationWarning)
        solved = rt.solve(track, train, law, m, wheel=wheel, profile=flat)
        harmonic = _median(lambda: rt.solve(track, train, law, m, wheel=wheel,
                                            profile=flat), 3)
    t = np.arange(16 * m) * solved.period / (16 * m)
    ring = rt.simulate_time_domain(track, train, law, 4, 14400, wheel=wheel, profile=flat,
                                   tol=1e-3, warn_step_error=None)
    ring_time = _median(lambda: rt.simulate_time_domain(
        track, train, law, 4, 14400, wheel=wheel, profile=flat, tol=1e-3,
        warn_step_error=None), RING_RUNS)
    print()
    print("| wheel flat, 30 m/s | P1 [kN] | time [s] | ring / harmonic balance |")
    print("|---|---:|---:|---:|")
    print(f"| harmonic balance, m = {m} | {solved.contact_force(t)[1].max() / 1e3:.1f} "
          f"| {harmonic:.2f} | |")
    print(f"| ring, 4 elements a span, 14400 steps | {ring.contact_forces[:, 1].max() / 1e3:.1f} "
          f"| {ring_time:.1f} | {ring_time / harmonic:.0f} |")
