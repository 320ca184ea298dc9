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
from ..model.plausibility_check import check_plausible, quantities_to_si
from ..model.validation import require_finite, require_positive
from .ground_strip import static_strip_flexibility, strip_flexibility

__all__ = ["LayeredGround"]

_NODES = 12                       # Chebyshev points in u = K / |k_x| for the short waves
_CHECK = 1e-7                     # the interpolant's largest error at the check point, of C


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
    rails : int
        How many rails load the strip alike (default 2).  `railtrack.Track`
        models one rail and the share of the sleeper under it, so the force
        its law passes is 1/rails of the strip's line load per sleeper: C is
        rails times the strip's w / P, the settlement per newton of one
        rail's share.  ``rails=1`` is a strip under one rail alone.

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
    rails: int = 2

    def __post_init__(self) -> None:
        quantities_to_si(self)
        if not isinstance(self.ground, Ground):
            raise TypeError("ground must be a railtrack.model.ground.Ground (layers over a "
                            f"half-space); got {type(self.ground).__name__}")
        require_positive("width", self.width, "m")
        require_positive("footprint", self.footprint, "m")
        if not isinstance(self.average, (bool, np.bool_)):
            raise TypeError(f"average must be True or False; got {self.average!r}")
        if not isinstance(self.rails, (int, np.integer)) or isinstance(self.rails, bool) \
                or self.rails < 1:
            raise ValueError(f"rails must be a whole number >= 1 (2: both rails of the track "
                             f"load the strip); got {self.rails!r}")
        object.__setattr__(self, "width", float(self.width))
        object.__setattr__(self, "footprint", float(self.footprint))
        check_plausible(self)       # a width in mm (2600 for 2.6 m): PlausibilityWarning

    def compliance(self, kx, omega: float) -> np.ndarray:
        """C(k_x, omega) [m^2/N] for wavenumbers k_x [rad/m] at one omega >= 0 [rad/s]."""
        return self._compliance(kx, omega, self.average, 0.0)

    def surface_compliance(self, kx, omega: float, offset: float) -> np.ndarray:
        """C_y(k_x, omega) [m^2/N]: the surface on the line y = offset [m] from the centre line.

        The strip's displacement at y (not averaged over its width) per unit
        line load, times ``rails`` as in `compliance`: the kernel of the
        displacement beside the track (`railtrack.equations.ground_beside`).
        C_y(0, 0) = 0 as in `compliance`: a line's mean is measured from that
        line's own mean level along the track.  Beyond the strip
        (|y| > b/2) C_y falls like exp(-sqrt(k_x^2 - k_R^2) (|y| - b/2)), k_R
        the slowest surface wave's wavenumber (taken as omega / (0.8 min c_s),
        above it, as in the strip's quadrature); where that is below e^-36
        it is returned as 0 without integrating.

        Examples
        --------
        >>> soil = Ground.homogeneous(100.0, 0.3, 1800.0, 0.05)
        >>> ground = LayeredGround(soil, width=2.5, footprint=0.25)
        >>> near, far = ground.surface_compliance(np.array([1.0, 200.0]), 0.0, 4.0)
        >>> bool(near.real > 0), complex(far)      # e^(-200 * 2.75): nothing
        (True, 0j)
        """
        require_finite("offset", offset, "m")
        return self._compliance(kx, omega, False, abs(float(offset)))

    def _compliance(self, kx, omega, average, offset):
        kx = np.asarray(kx, dtype=float)
        omega = float(omega)
        values = np.zeros(kx.shape, dtype=complex)
        dynamic = (kx != 0) | (omega != 0)      # C(0, 0) = 0: the mean from the mean level
        beyond = offset - 0.5 * self.width
        if beyond > 0:                          # exp(-36) of the decay beside the strip
            slow = omega / (0.8 * self.ground.slowest_shear_wave_speed)
            dynamic &= np.abs(kx) < np.hypot(slow, 36.0 / beyond)
        if np.any(dynamic):
            # C is even in k_x: each |k_x| once
            wanted, back = np.unique(np.abs(kx[dynamic]), return_inverse=True)
            values[dynamic] = self.rails * self._even(wanted, omega, average, offset)[back]
        return values

    def _flexibility(self, kx, omega, average, offset):
        return strip_flexibility(self.ground, kx, omega, self.width, average, offset)

    def _even(self, kx: np.ndarray, omega: float, average: bool,
              offset: float) -> np.ndarray:
        """C at sorted |k_x| >= 0: exact below K, interpolated beyond (the module's note)."""
        layers = self.ground.layers
        reach = max(2.0 * omega / (0.8 * self.ground.slowest_shear_wave_speed),
                    2.0 * np.pi / self.width, 8.0 / layers[0].thickness if layers else 0.0)
        far = kx > reach
        if np.count_nonzero(far) <= _NODES + 1:
            return self._flexibility(kx, omega, average, offset)
        u_end = reach / kx[-1]
        nodes = self._nodes(u_end, _NODES)
        check = 0.5 * (nodes[_NODES // 2] + nodes[_NODES // 2 + 1])
        near_values = self._flexibility(np.concatenate([kx[~far], reach / nodes,
                                                        [reach / check]]), omega, average, offset)
        exact_near, at_nodes, at_check = np.split(near_values,
                                                  [np.count_nonzero(~far), -1])
        def rest(k, value):
            return (value - self._static(k, omega, average, offset)) * k**3
        fit = np.polynomial.chebyshev.Chebyshev.fit(
            nodes, rest(reach / nodes, at_nodes), _NODES - 1, domain=[u_end, 1.0])
        guess = fit(check) / (reach / check) ** 3 + self._static(reach / check, omega,
                                                                 average, offset)
        if abs(guess - at_check[0]) > _CHECK * abs(at_check[0]):
            return self._flexibility(kx, omega, average, offset)
        out = np.empty(kx.size, dtype=complex)
        out[~far] = exact_near
        out[far] = fit(reach / kx[far]) / kx[far] ** 3 + self._static(kx[far], omega, average,
                                                                      offset)
        return out

    @staticmethod
    def _nodes(start: float, count: int) -> np.ndarray:
        """Chebyshev points of the first kind on [start, 1]."""
        x = np.cos(np.pi * (np.arange(count) + 0.5) / count)
        return start + (1.0 - start) * (x + 1.0) / 2.0

    def _static(self, kx, omega, average, offset):
        return static_strip_flexibility(self.ground, kx, omega, self.width, average, offset)
