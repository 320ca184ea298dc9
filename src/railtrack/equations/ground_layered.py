"""The layered soil (`railtrack.model.ground.Ground`) as a ground for `railtrack.solve`.

`LayeredGround` gives the layered half-space the interface of
`railtrack.model.ground_protocol.GroundCompliance`: its compliance is the
strip's flexibility of `railtrack.equations.ground_strip`,

    C(k_x, omega) = 1 / K_eq(k_x, omega) = w / P   [m^2/N],

the surface's displacement under a strip of width b across the track per
unit line load P exp(i (k_x x - omega t)) [N/m].  Both modules take the same
convention, exp(i (k_x x - omega t)) with displacement and load positive in
the same sense, so the value passes unchanged: a damped soil then has
Im C >= 0 for omega > 0 (it takes work from the load), as the coupling
expects.  omega is the frequency of the sleeper's force, which is also the
soil's: the sleepers, and so the footprints, do not move with the train.

The mean.  The coupling's harmonic n = 0 (the infinite train's mean load,
q_0 = 0) asks for C(0, 0), the settlement of the soil under a uniform static
line load.  On a half-space, however stiff, it is infinite: the plane-strain
displacement under a line load grows like log(1/k_x) as k_x -> 0, and a
periodic row of footprints carrying the mean load settles without bound.
`railtrack.model.ground.Ground` has no rigid base to stop it.  Only w_0 needs
it: in eq. (G2) of `railtrack.equations.ground_balance` phi_0 = 1, the law
sees d = w - u and d_0 solves f(d_0) = -2 Q L / H whatever C(0, 0) is, so the
dynamic response and the law's forces are unaffected.  `LayeredGround` takes
C(0, 0) = 0: the m = 0 term of the lattice sum is the footprints' mean
settlement along the track (the x-average of the surface under a periodic
load is its k_x = 0 Fourier term), so u_0 and w_0 = d_0 + u_0 are measured
from the soil surface's mean level under the train, the dish round each
sleeper (the terms m != 0) included.  A rigid base, were it added, would make
C(0, 0) finite and this choice unnecessary.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.ground import Ground
from ..model.validation import require_positive
from .ground_strip import strip_flexibility

__all__ = ["LayeredGround"]


@dataclass(frozen=True)
class LayeredGround:
    """A layered soil under the sleepers, seen through a strip of width b: C = 1 / K_eq.

    Parameters
    ----------
    ground : Ground
        The soil layers over a half-space (`railtrack.model.ground.Ground`).
    width : float
        b > 0, the loaded width across the track [m] (about the sleeper's
        length, or the ballast's base).
    footprint : float
        a > 0, the sleeper's width along the track [m], <= the sleeper
        spacing L (checked by the solve).
    average : bool
        True (default): the displacement averaged over the strip's width, for
        a sleeper that moves as one across the track; False: on the centre
        line (Dieterman & Metrikine 1996).

    Notes
    -----
    ``compliance(0, 0)`` is 0 by choice, not the (infinite) settlement of a
    half-space under a uniform load: the mean w_0 is then measured from the
    soil surface's mean level (the module's note).  Each call integrates over
    the transverse wavenumber k_y for every k_x (`strip_flexibility`), the
    cost of a solve on this ground.

    Examples
    --------
    >>> soil = Ground.homogeneous(100.0, 0.3, 1800.0, 0.05)
    >>> ground = LayeredGround(soil, width=2.5, footprint=0.25)
    >>> c = ground.compliance(np.array([0.0, 5.0]), 0.0)     # m^2/N
    >>> float(c[0].real), bool(c[1].real > 0)
    (0.0, True)
    >>> bool(ground.compliance(np.array([1.0]), 200.0)[0].imag > 0)   # passive
    True
    """

    ground: Ground
    width: float
    footprint: float
    average: bool = True

    def __post_init__(self) -> None:
        if not isinstance(self.ground, Ground):
            raise TypeError("ground must be a railtrack.model.ground.Ground (layers over a "
                            f"half-space); got {type(self.ground).__name__}")
        require_positive("width", self.width, "m")
        require_positive("footprint", self.footprint, "m")
        if not isinstance(self.average, (bool, np.bool_)):
            raise TypeError(f"average must be True or False; got {self.average!r}")
        object.__setattr__(self, "width", float(self.width))
        object.__setattr__(self, "footprint", float(self.footprint))

    def compliance(self, kx, omega: float) -> np.ndarray:
        """C(k_x, omega) [m^2/N] for wavenumbers k_x [rad/m] at one omega >= 0 [rad/s]."""
        kx = np.asarray(kx, dtype=float)
        omega = float(omega)
        values = np.zeros(kx.shape, dtype=complex)
        dynamic = (kx != 0) | (omega != 0)      # C(0, 0) = 0: the mean from the mean level
        if np.any(dynamic):
            values[dynamic] = strip_flexibility(self.ground, kx[dynamic], omega, self.width,
                                                self.average)
        return values
