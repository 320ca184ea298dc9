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

    def ground_displacement(self, t: ArrayLike) -> np.ndarray:
        """u(t), the ground's surface under the sleeper, averaged over its footprint [m]."""
        return fourier_series(self.ground_coefficients, self.frequencies, t)

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
