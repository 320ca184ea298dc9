"""The train speeds up on nonlinear foundations: how the laws move and bend the peak.

Data functions return dicts and floats in SI units; `plot_law_curves` draws
them in mm and m/s.  The yardstick for loss of contact is the secant
stiffness of the foundation over the period, the least-squares slope of its
elastic force against the displacement about their means: the stiffness of
the linear law that would swing the same way (equivalent linearization).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ...model.foundations import BilinearFoundation, CubicFoundation, LinearFoundation
from ...studies.sweep import sweep
from .speed import _ring_peak, peak_speed
from ..style import MM, new_figure, series_style

__all__ = ["foundation_laws", "law_curves", "law_peaks", "secant_stiffness", "plot_law_curves"]


def foundation_laws(stiffness: float = 20e6, damping: float = 20e3, ratios=(0.5, 0.25, 0.0),
                    cubic_stiffness: float = 2e13, epsilon: float = 0.8) -> dict:
    """The linear law and its nonlinear variants with the same k2 and eta2.

    Parameters
    ----------
    stiffness : float
        k2, the stiffness in compression (k2+ of the bilinear law) [N/m].
    damping : float
        eta2 [N s/m].
    ratios : sequence of float
        Tension ratios e = k2- / k2+ of the bilinear laws [-]; 0 is tensionless.
    cubic_stiffness : float
        k3 of the cubic law [N/m^3].
    epsilon : float
        eps of the cubic law [-].

    Returns
    -------
    dict of str -> law
        "linear", "bilinear e = ..." (or "tensionless" for e = 0) and "cubic".
    """
    laws = {"linear": LinearFoundation(stiffness, damping)}
    for e in ratios:
        name = "tensionless" if e == 0 else f"bilinear e = {e:g}"
        laws[name] = BilinearFoundation(stiffness, e * stiffness, damping)
    laws["cubic"] = CubicFoundation(stiffness, cubic_stiffness, epsilon, damping)
    return laws


def law_curves(track, train, laws: dict, speeds, harmonics: int = 30) -> dict:
    """Extremes of the periodic response over speed for each law, by `railtrack.sweep`.

    Parameters
    ----------
    track, train : Track, Train
        The train's own speed is ignored.
    laws : dict of str -> law
        Dataclass laws (Linear, Bilinear, Cubic).
    speeds : array_like, shape (S,)
        Train speeds [m/s].
    harmonics : int
        m for every speed; check it with ``solve(..., harmonics="auto")``.

    Returns
    -------
    dict of str -> dict of str -> ndarray, shape (S,)
        Per law: "lowest" and "highest" sleeper displacement over a period [m]
        (w < 0 down), "mean" displacement c0 [m], "seat_load" peak rail-seat
        load [N] and "converged" (bool).
    """
    curves = {}
    for name, law in laws.items():
        # stability="off": the quick look costs ~35 ms a member at m = 30, 600 members a law; on
        # chapter 10's lightly damped track it found no unstable member at 61 speeds
        # from 100 to 700 m/s for any of the laws (issue 27)
        s = sweep(track, train, law, harmonics=harmonics, speed=np.asarray(speeds, float),
                  stability="off")
        curves[name] = dict(lowest=s.lowest, highest=s.highest,
                            mean=s.coefficients[:, s.harmonics].real,
                            seat_load=s.seat_load_peak, converged=s.converged)
    return curves


def law_peaks(speeds, curve: dict) -> dict:
    """Speed and height of the peaks of one law's curves (`railtrack.plotting.book.speed.peak_speed`).

    Parameters
    ----------
    speeds : array_like, shape (S,)
        Increasing speeds [m/s].
    curve : dict
        One entry of `law_curves`.

    Returns
    -------
    dict of str -> (float, float)
        "dip": (v [m/s], -min w [m]); "uplift": (v, max w [m]);
        "swing": (v, max w - min w [m]); "seat_load": (v, peak load [N]).
    """
    low, high = np.asarray(curve["lowest"]), np.asarray(curve["highest"])
    out = {}
    for key, values in (("dip", low), ("uplift", -high), ("swing", low - high),
                        ("seat_load", -np.asarray(curve["seat_load"]))):
        v, w = peak_speed(speeds, values)
        out[key] = (v, -w)
    return out


def secant_stiffness(solution, samples: int = 2048) -> tuple[float, float, float]:
    """Secant stiffness of the foundation over one period, and how long it is lifted.

    k_sec = <(f - <f>)(w - <w>)> / <(w - <w>)^2>, f the elastic force
    f(w, 0) of the law and <.> the mean over the period: the stiffness of
    the linear spring that best fits the law along this motion.  For a
    linear law it is k2; for a bilinear one it lies between k2- and k2+.

    Parameters
    ----------
    solution : railtrack.Solution
    samples : int
        Points per period.

    Returns
    -------
    stiffness : float
        k_sec [N/m].
    lifted : float
        Fraction of the period with w > 0, in tension or lifted off [-].
    mean : float
        <w> [m].
    """
    t = np.linspace(0.0, float(solution.period), samples, endpoint=False)
    w = np.asarray(solution.sleeper_displacement(t), float)
    f = np.asarray(solution.foundation.force(w, np.zeros_like(w)), float)
    dw = w - w.mean()
    return float(np.mean((f - f.mean()) * dw) / np.mean(dw ** 2)), float(np.mean(w > 0)), \
        float(w.mean())


def plot_law_curves(speeds, curves: dict, *, title: str | None = None) -> Figure:
    """Dip -min w and uplift max w [mm] over speed [m/s], one line per law, peaks ringed.

    Each law keeps its colour, line style and marker in both panels.

    Parameters
    ----------
    speeds : array_like, shape (S,)
        [m/s]
    curves : dict of str -> dict
        Legend label -> an entry of `law_curves` ("lowest", "highest" [m]).
    title : str, optional
    """
    fig, axes = new_figure(2, 1, sharex=True, height=3.0)
    for n, (label, curve) in enumerate(curves.items()):
        style = series_style(n, len(curves), points=len(speeds), marker=True)
        for ax, key, lowest in ((axes[0], "dip", np.asarray(curve["lowest"])),
                                (axes[1], "uplift", -np.asarray(curve["highest"]))):
            line, = ax.plot(speeds, -lowest * MM, label=label, gid=f"{label}: {key}", **style)
            _ring_peak(ax, speeds, lowest, line)
    axes[0].set_ylabel("deepest dip −min w [mm]")
    axes[1].set_ylabel("highest uplift max w [mm]")
    axes[1].set_xlabel("train speed v [m/s]")
    for ax in axes:
        ax.set_ylim(bottom=0)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8, ncol=2)
    if title:
        axes[0].set_title(title, fontsize=9)
    return fig
