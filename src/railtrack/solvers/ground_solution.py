"""The periodic response of a sleeper on a foundation law on a compliant ground.

A `Solution` whose ``coefficients`` are the sleeper's displacement w_n (so
that the rail, the rail-seat load and the deflection bowl are eq. 6's as on a
rigid ground), and which also keeps the ground's displacement under the
sleeper u_n = R_g,n f_n (eq. G1 of `railtrack.equations.ground_lattice`) and
the law's relative displacement d_n = w_n - u_n, on which the law acts.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..equations.ground_beside import surface_receptance
from ..equations.harmonic_balance import two_sided
from .result_repr import KN, MM, extent, period_samples, solution_rows
from .solution import Solution
from .time_histories import fourier_series

__all__ = ["GroundSolution"]


@dataclass(frozen=True, eq=False, repr=False)
class GroundSolution(Solution):
    """`railtrack.Solution` of ``solve(..., ground=...)``: the sleeper on a law on a ground.

    Attributes
    ----------
    ground : GroundCompliance
        The ground that was solved on (`railtrack.model.ground_protocol`).
    ground_coefficients : ndarray, shape (2m+1,)
        u_n, n = -m..m, the ground's displacement under the sleeper's footprint [m].
    relative_coefficients : ndarray, shape (2m+1,)
        d_n = w_n - u_n, the law's compression, positive upward [m].
    force_coefficients : ndarray, shape (2m+1,)
        f_n, the sleeper's force on the ground, signed as w [N] (u_n = R_g,n f_n).

    Notes
    -----
    ``truncation_error`` and ``residual`` are those of eq. (G2), the
    equation in d.  The stability look (Floquet) is not done on a ground.

    Examples
    --------
    >>> import railtrack as rt
    >>> from railtrack.model.ground_protocol import WinklerGround
    >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
    ...              harmonics=15, ground=WinklerGround(2e8, 0.25))
    >>> ratio = s.mean_displacement / s.relative_coefficients[15].real   # (k + a s) / (a s)
    >>> bool(s.converged), round(float(ratio), 3)
    (True, 1.4)
    """

    ground: Any = None
    ground_coefficients: np.ndarray | None = None
    relative_coefficients: np.ndarray | None = None
    force_coefficients: np.ndarray | None = None

    def ground_displacement(self, t: ArrayLike) -> np.ndarray:
        """u(t), the ground's surface under the sleeper, averaged over its footprint [m]."""
        return fourier_series(self.ground_coefficients, self.frequencies, t)

    def surface_displacement(self, t: ArrayLike, offset: float) -> np.ndarray:
        """u(t; y), the soil's surface at x = 0, y = offset from the centre line [m].

        The point beside sleeper 0's cross-section (not averaged over the
        footprint), in the train-periodic steady state: u_n(y) = R_y,n f_n,
        eq. (G1y) of `railtrack.equations.ground_beside` (eq. 16.6 of
        chapter 16 with the strip's displacement on the line y and one sinc).
        Each line's mean is measured from its own mean level along the track
        (C_y(0, 0) = 0, as for `ground_displacement`).

        Parameters
        ----------
        t : array_like
            Times [s].
        offset : float
            y [m], finite; either side of the centre line alike.

        Returns
        -------
        ndarray, shaped like t [m], positive upward.

        Raises
        ------
        TypeError
            A ground without ``surface_compliance`` (e.g. a WinklerGround).
        ValueError
            An offset that is not finite.

        Examples
        --------
        >>> import railtrack as rt
        >>> soil = rt.Ground.homogeneous(100.0, 0.3, 1800.0, 0.05)
        >>> ground = rt.LayeredGround(soil, width=2.5, footprint=0.25)
        >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
        ...              ground=ground)
        >>> t = np.linspace(0.0, s.period, 200)
        >>> near, far = (np.ptp(s.surface_displacement(t, y)) for y in (0.0, 5.0))
        >>> bool(0 < far < near)
        True
        """
        m = self.harmonics
        receptance, _ = surface_receptance(self.ground, self.frequencies[m:],
                                           float(self.passage.speed),
                                           float(self.passage.sleeper_spacing), offset)
        coefficients = two_sided(receptance * self.force_coefficients[m:])
        return fourier_series(coefficients, self.frequencies, t)

    def relative_displacement(self, t: ArrayLike) -> np.ndarray:
        """d(t) = w(t) - u(t), the displacement the foundation law sees [m]."""
        return fourier_series(self.relative_coefficients, self.frequencies, t)

    def foundation_force(self, t: ArrayLike) -> np.ndarray:
        """Force that the sleeper puts on the foundation, -f(d, d'), positive in compression [N]."""
        omega = self.frequencies
        velocity = fourier_series(1j * omega * self.relative_coefficients, omega, t)
        return -np.asarray(self.foundation.force(self.relative_displacement(t), velocity),
                           dtype=float)

    def _rows(self):
        title, rows = solution_rows(self)
        t = np.arange(period_samples(self)) * self.period / period_samples(self)
        force = self.foundation_force(t)[None, :]
        rows = [("foundation force [kN]", extent(force, KN, 2, "max", "sleeper"))
                if name == "foundation force [kN]" else (name, value) for name, value in rows]
        ground = self.ground_displacement(t)[None, :]
        return title, rows[:-1] + [("ground under sleeper [mm]",
                                    extent(ground, MM, 3, "min", "sleeper")), rows[-1]]
