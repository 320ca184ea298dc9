"""P1 under a wheel flat: harmonic balance against m, and the ring.

Issue 32, item 5.  From the repository root, with PYTHONPATH=src:

    python docs/flat_p1.py hb 600 1200 2400 auto   # rt.solve at these m
    python docs/flat_p1.py ring 4:7200 4:14400     # elements:steps[:tol]

One case: the ballasted track and foundation, the paper's train at 30 m/s
(two wheels a wagon, 18 m), a 600 kg wheel on the Hertz spring, and on the
second wheel of every wagon a flat 0.5 mm deep worn round over 100 mm, on a
wheel of circumference 3.0 m (R = 0.477 m) striking at x = 0.3 m (mod 3 m),
a fifth of the way between two sleepers.  Prints one line per run: the
resolution, the wall time, the largest contact force P1 [kN] of the flat
wheel and the other wheel's, and the least (0: the wheel leaves the rail).
"""

import sys
import time

import numpy as np

import railtrack as rt

SPEED = 30.0


def case(speed=SPEED):
    return (rt.Track.ballasted(), rt.Train.paper(speed=speed),
            rt.LinearFoundation.ballasted(), rt.Wheel(600.0),
            rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1, centre=0.3))


def harmonic_balance(m) -> None:
    track, train, law, wheel, flat = case()
    start = time.perf_counter()
    s = rt.solve(track, train, law, m if m == "auto" else int(m), wheel=wheel,
                 profile=flat)
    seconds = time.perf_counter() - start
    samples = 16 * s.harmonics
    t = np.arange(samples) * s.period / samples
    p = s.contact_force(t)
    print(f"hb m={s.harmonics:5d} {seconds:7.1f} s  P1 {p[1].max() / 1e3:7.2f} kN  "
          f"other {p[0].max() / 1e3:6.2f} kN  min {p[1].min() / 1e3:6.2f} kN  "
          f"trunc {100 * s.truncation_error:5.2f} %  conv={s.converged}", flush=True)


def ring(elements: int, steps: int, tol: float = 1e-5) -> None:
    track, train, law, wheel, flat = case()
    start = time.perf_counter()
    r = rt.simulate_time_domain(track, train, law, elements, steps, wheel=wheel,
                                profile=flat, tol=tol, warn_step_error=None)
    seconds = time.perf_counter() - start
    p = r.contact_forces
    print(f"ring {elements}:{steps}:{tol:g} {seconds:7.1f} s  "
          f"P1 {p[:, 1].max() / 1e3:7.2f} kN  other {p[:, 0].max() / 1e3:6.2f} kN  "
          f"min {p[:, 1].min() / 1e3:6.2f} kN  conv={r.converged}", flush=True)


if __name__ == "__main__":
    kind, *runs = sys.argv[1:]
    for run in runs:
        if kind == "hb":
            harmonic_balance(run)
        else:
            elements, steps, *tol = run.split(":")
            ring(int(elements), int(steps), *map(float, tol))
