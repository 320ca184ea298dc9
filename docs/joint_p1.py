"""P1 at a dipped joint: harmonic balance against m, and the ring.

Issue 32, item 5.  From the repository root, with PYTHONPATH=src:

    python docs/joint_p1.py hb 300 600 1200 2400   # rt.solve at these m
    python docs/joint_p1.py ring 8:3600 16:7200    # elements:steps
    python docs/joint_p1.py ring 4:7200:1e-3       # ...:tol

One case: the ballasted track and foundation, the paper's train at 30 m/s, a
600 kg wheel on the Hertz spring, a DippedJoint of 10 mrad over 1 m in the
middle of a span (x = 9.3 m), one joint a wagon (18 m).  Prints one line per
run: the resolution, the wall time, the largest contact force P1 [kN] and,
for harmonic balance, the truncation estimate (of Q) and where P1 occurs.
"""

import sys
import time

import numpy as np

import railtrack as rt

SPEED, ANGLE, LENGTH, CENTRE = 30.0, 10e-3, 1.0, 9.3


def case():
    return (rt.Track.ballasted(), rt.Train.paper(speed=SPEED),
            rt.LinearFoundation.ballasted(), rt.Wheel(600.0),
            rt.DippedJoint(ANGLE, LENGTH, 18.0, centre=CENTRE))


def harmonic_balance(m: int) -> None:
    track, train, law, wheel, joint = case()
    start = time.perf_counter()
    s = rt.solve(track, train, law, m, wheel=wheel, profile=joint)
    seconds = time.perf_counter() - start
    samples = 16 * m  # 16 samples a period of harmonic m
    t = np.arange(samples) * s.period / samples
    p = s.contact_force(t)
    k = int(np.argmax(p[0]))
    x = SPEED * t[k] % 18.0
    print(f"hb m={m:5d} {seconds:7.1f} s  P1 {p.max() / 1e3:7.2f} kN  "
          f"trunc {100 * s.truncation_error:5.2f} %  at x={x:.3f} m  "
          f"min {p.min() / 1e3:6.2f} kN  conv={s.converged}", flush=True)


def ring(elements: int, steps: int, tol: float = 1e-5) -> None:
    track, train, law, wheel, joint = case()
    start = time.perf_counter()
    r = rt.simulate_time_domain(
        track, train, law, elements, steps, wheel=wheel, profile=joint,
        tol=tol, warn_step_error=None)
    seconds = time.perf_counter() - start
    p = r.contact_forces
    print(f"ring {elements}:{steps}:{tol:g} {seconds:7.1f} s  "
          f"P1 {p.max() / 1e3:7.2f} kN  min {p.min() / 1e3:6.2f} kN  "
          f"conv={r.converged}", flush=True)


if __name__ == "__main__":
    kind, *runs = sys.argv[1:]
    for run in runs:
        if kind == "hb":
            harmonic_balance(int(run))
        else:
            elements, steps, *tol = run.split(":")
            ring(int(elements), int(steps), *map(float, tol))
