"""Where the energy goes: the work of the pads and the foundation over one period.

In the steady state every sleeper repeats its motion each period T = H/v,
so the elastic parts of the pad and foundation forces give back over a
period what they store, and what is left is dissipated by their dashpots
(and, for a law with hysteresis, by the law itself).  Per sleeper and period

    E_pad = int_0^T R_pad(t) delta'(t) dt,      delta = w - w_r(0, t),
    E_fdn = int_0^T f(w, w') w'(t) dt,

with R_pad the rail-seat load of eq. (5) (positive in compression) and f the
foundation law of eq. (15).  The rail itself has no damping, so the work
that the moving wheel loads do on the rail over one period, shared among the
H/L sleepers of a wagon, must equal E_pad + E_fdn: an energy balance that
checks the whole chain of eqs. (3)-(19) (tests/test_energy.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Dissipation", "dissipation", "load_work"]


@dataclass(frozen=True)
class Dissipation:
    """Energy dissipated per sleeper and period [J].

    Attributes
    ----------
    pad : float
        By the rail pad, ``int R_pad (w - w_r)' dt``.
    foundation : float
        By the foundation, ``int f(w, w') w' dt``; on a ground ``int f(d, d') d' dt``.
    ground : float
        Taken in by the ground, ``int f u' dt``, u its displacement under the
        sleeper (`railtrack.GroundSolution`; it radiates or dissipates it); 0 on
        a rigid ground.
    total : float
        pad + foundation + ground, the work of the wheel loads (`load_work`).
    pad_share : float
        pad / total [-].
    """

    pad: float
    foundation: float
    ground: float = 0.0

    @property
    def total(self) -> float:
        """pad + foundation + ground [J]."""
        return self.pad + self.foundation + self.ground

    @property
    def pad_share(self) -> float:
        """The pad's share of the total [-]."""
        return self.pad / self.total


def _period_grid(solution, samples: int | None) -> np.ndarray:
    # A product of two trigonometric polynomials of degree m has degree 2m,
    # so its mean over a uniform grid of more than 2m points is exact.
    n = max(int(samples or 0), 4 * solution.harmonics + 4)
    return np.linspace(0.0, solution.period, n, endpoint=False)


def dissipation(solution, samples: int | None = None) -> Dissipation:
    """Energy dissipated by the pad and by the foundation of one sleeper per period.

    Parameters
    ----------
    solution : railtrack.Solution or railtrack.GroundSolution
        A steady-state solution (eq. 19), on a rigid base or on a ground.
    samples : int, optional
        Points over the period; at least 4 m + 4, where the means of the
        products are exact for the pad (the foundation's only for a linear law).

    Returns
    -------
    Dissipation
        Energies per sleeper and period [J]:

        - ``.pad``: dissipated by the rail pad;
        - ``.foundation``: by the foundation law (its dashpot or hysteresis);
        - ``.ground``: taken in by the ground under a `railtrack.GroundSolution`,
          radiated or damped by the soil; 0 on a rigid base;
        - ``.total``: pad + foundation + ground, the wheel loads' work
          (`load_work`);
        - ``.pad_share``: pad / total [-].

    Examples
    --------
    >>> import railtrack as rt
    >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper())
    >>> e = rt.dissipation(s)
    >>> bool(0.0 < e.pad < e.foundation)
    True
    """
    t = _period_grid(solution, samples)
    omega = solution.frequencies
    from .solution import fourier_series  # the result type sits above this module

    sleeper = solution.coefficients
    pad = sleeper - solution.rail_coefficients()  # compression of the pad [m]
    pad_rate = fourier_series(1j * omega * pad, omega, t)
    # on a ground the law sees d = w - u, and the ground takes f u'
    relative = getattr(solution, "relative_coefficients", None)
    relative = sleeper if relative is None else relative
    rate = fourier_series(1j * omega * relative, omega, t)
    force = np.asarray(solution.foundation.force(fourier_series(relative, omega, t), rate), float)
    ground_rate = fourier_series(1j * omega * (sleeper - relative), omega, t)
    period = solution.period
    return Dissipation(
        pad=float(np.mean(solution.rail_seat_load(t) * pad_rate) * period),
        foundation=float(np.mean(force * rate) * period),
        ground=float(np.mean(force * ground_rate) * period),
    )


def load_work(solution, samples: int | None = None) -> float:
    """Work of a wagon's wheel loads on the rail over one period, per sleeper [J].

    Each wheel pushes down with Q_j on the rail point under it, whose
    velocity is the time derivative of w_r at fixed x, taken here from the
    rail field by a central difference of 1e-6 T.  Divided by the H/L
    sleepers of a wagon, it equals `dissipation(solution).total` in the
    steady state.

    Examples
    --------
    >>> import railtrack as rt
    >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper())
    >>> bool(abs(rt.load_work(s) / rt.dissipation(s).total - 1) < 1e-3)
    True
    """
    t = _period_grid(solution, samples)
    passage = solution.passage
    speed = float(passage.speed)
    offsets = np.asarray(passage.axle_positions, float)
    loads = np.broadcast_to(np.asarray(passage.axle_loads, float), offsets.shape)
    step = 1e-6 * solution.period
    work = 0.0
    for offset, load in zip(offsets, loads):
        x = speed * t - offset
        rate = (solution.rail_displacement(t + step, x) - solution.rail_displacement(t - step, x)) / (
            2 * step
        )
        work += -load * float(np.mean(rate)) * solution.period
    sleepers = passage.wagon_length / passage.sleeper_spacing
    return work / sleepers
