"""Tables of the chapter "The wheel on the rail": contact forces and the P2 formula.

Each function formats what the library computed; the only arithmetic is
sampling a solution over one period, the swing max - min of its contact
force and the ratio of two dynamic increments.  Units on the page: kN, m.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .tables import markdown_table

__all__ = ["dipped_weld_table", "p2_table", "smooth_rail_table"]

KN = 1e-3


def _per_wheel(values, digits: int) -> str:
    return " / ".join(f"{x * KN:.{digits}f}" for x in values)


def smooth_rail_table(solutions: Mapping) -> str:
    """The contact force on a smooth rail, one row per solution.

    Parameters
    ----------
    solutions : mapping of str to WheelSolution
        A label (e.g. ``"45 m/s"``) to a solution of ``rt.solve(..., wheel=...)``.

    Returns
    -------
    str
        A markdown table: the label, the harmonics kept ``m``, the largest and
        the smallest contact force of each wheel [kN] and the largest swing,
        max - min over one period, of any wheel [kN].
    """
    rows = []
    for label, solution in solutions.items():
        e = solution.extremes()
        rows.append([label, solution.harmonics, _per_wheel(e["max"], 2),
                     _per_wheel(e["min"], 2), f"{(e['max'] - e['min']).max() * KN:.2f}"])
    header = ["speed", "m", "Q_c max [kN], wheel 1 / 2", "Q_c min [kN]",
              "swing [kN]"]
    return markdown_table(header, rows)


def dipped_weld_table(solutions: Mapping, samples: int = 4096) -> str:
    """The contact force through a dip in the rail's top, one row per solution.

    Parameters
    ----------
    solutions : mapping of str to WheelSolution
        A label to a solution with a wheel under every axle and a profile.
    samples : int
        Samples of one period at which the rail-seat load is read.

    Returns
    -------
    str
        A markdown table: the label; the largest contact force of each wheel
        [kN] and where along the track wheel 1 meets it [m]; the same for the
        smallest; the largest dynamic factor Q_c max / Q of any wheel; the
        largest rail-seat load [kN].
    """
    rows = []
    for label, solution in solutions.items():
        e = solution.extremes()
        t = solution.one_period(samples)[0]
        rows.append([label, _per_wheel(e["max"], 1), f"{e['where_max'][0]:.2f}",
                     _per_wheel(e["min"], 1), f"{e['where_min'][0]:.2f}",
                     f"{e['dynamic_factor'].max():.2f}",
                     f"{solution.rail_seat_load(t).max() * KN:.1f}"])
    header = ["speed", "Q_c max [kN], wheel 1 / 2", "at x, wheel 1 [m]", "Q_c min [kN]",
              "at x, wheel 1 [m]", "dynamic factor", "max seat load [kN]"]
    return markdown_table(header, rows)


def p2_table(speeds: np.ndarray, computed: Mapping, formula: Mapping,
             static_load: float) -> str:
    """Largest contact forces of the harmonic balance beside the P2 formula's.

    Parameters
    ----------
    speeds : array of float
        Train speeds [m/s].
    computed : mapping of str to array
        A label (e.g. ``"1 m dip"``) to the harmonic balance's largest
        contact force [N] at each speed.
    formula : mapping of str to array
        A label (e.g. ``"fitted"``) to the P2 force [N] at each speed.
    static_load : float
        The static wheel load Q [N].

    Returns
    -------
    str
        A markdown table, one row per speed: every computed and every formula
        column [kN], and the dynamic part Q_c - Q of the first computed column
        over that of the first formula column.
    """
    speeds = np.asarray(speeds, dtype=float)
    first, reference = next(iter(computed)), next(iter(formula))
    ratio = ((np.asarray(computed[first]) - static_load)
             / (np.asarray(formula[reference]) - static_load))
    columns = [np.asarray(c) for c in (*computed.values(), *formula.values())]
    rows = [[f"{v:.0f}", *(f"{c[i] * KN:.1f}" for c in columns), f"{ratio[i]:.2f}"]
            for i, v in enumerate(speeds)]
    header = ["v [m/s]", *(f"HB, {name} [kN]" for name in computed),
              *(f"P2, {name} [kN]" for name in formula),
              f"Q_c - Q, HB {first} over P2 {reference}"]
    return markdown_table(header, rows)
