"""The ground beneath the sleepers, as `railtrack.solve` sees it: a compliance per wavenumber.

A ground is any object with

* ``compliance(kx, omega)``: C(k_x, omega) [m per N/m = m^2/N], the
  vertical displacement of the ground's surface under the track's centre
  line per unit line load ``exp(i (k_x x - omega t))`` [N/m] along the
  track, both positive upward, for an array of wavenumbers k_x [rad/m] and
  one frequency omega >= 0 [rad/s]; a complex array shaped like k_x.  The
  time convention is exp(-i omega t): a passive ground has Im C >= 0.
  A real ground has C(-k_x, -omega) = conj C(k_x, omega);
* ``footprint``: the sleeper's width a along the track [m], over which it
  presses with a uniform pressure, 0 < a <= L.

`WinklerGround` is the simplest one (a bed of independent springs and
dashpots, C independent of k_x); a layered soil (`railtrack.model.ground.Ground`)
is another through `railtrack.equations.ground_layered.LayeredGround`.  How the
compliance enters the harmonic balance: `railtrack.equations.ground_lattice` (eq. G1)
and `railtrack.equations.ground_balance` (eq. G2).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np

from .ground import Ground, SoilLayer
from .plausibility_check import check_plausible, quantities_to_si

__all__ = ["GroundCompliance", "WinklerGround", "check_ground"]


@runtime_checkable
class GroundCompliance(Protocol):
    """What `railtrack.solve` needs of a ground (module docstring)."""

    footprint: float

    def compliance(self, kx: np.ndarray, omega: float) -> np.ndarray: ...


@dataclass(frozen=True)
class WinklerGround:
    """A bed of springs and dashpots per unit length under the sleepers: C = 1 / (s - i omega eta).

    Parameters
    ----------
    modulus : float
        s > 0, the bed's stiffness per unit length of track [N/m per m = N/m^2].
    footprint : float
        a > 0, the sleeper's width along the track [m].
    damping : float
        eta >= 0, its damping per unit length [N s/m^2].

    Notes
    -----
    A sleeper of width a on this bed meets a spring a s and a dashpot a eta
    (`railtrack.equations.ground_lattice`, the Winkler limit R_g = C / a).

    Examples
    --------
    >>> ground = WinklerGround(modulus=1e8, footprint=0.25)
    >>> complex(ground.compliance(np.array([0.0]), 0.0)[0])    # m^2/N
    (1e-08+0j)
    """

    modulus: float
    footprint: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        quantities_to_si(self)
        for name, value, low in (("modulus", self.modulus, "> 0"),
                                 ("footprint", self.footprint, "> 0"),
                                 ("damping", self.damping, ">= 0")):
            if isinstance(value, bool) or not isinstance(value, (int, float, np.floating,
                                                                 np.integer)):
                raise TypeError(f"{name} must be a real number; got {value!r}")
            bad = value < 0 if low == ">= 0" else value <= 0
            if not np.isfinite(value) or bad:
                raise ValueError(f"{name} must be finite and {low}; got {value!r}")
        check_plausible(self)       # a footprint in mm: PlausibilityWarning

    def compliance(self, kx, omega):
        kx = np.asarray(kx, dtype=float)
        return np.full(kx.shape, 1.0 / (self.modulus - 1j * omega * self.damping))


def check_ground(ground, spacing: float) -> None:
    """Raise ``TypeError``/``ValueError`` unless `ground` is a usable `GroundCompliance` for sleeper spacing L.

    Examples
    --------
    >>> check_ground(WinklerGround(1e8, 0.25), spacing=0.6)
    >>> check_ground(WinklerGround(1e8, 0.7), spacing=0.6)
    Traceback (most recent call last):
    ...
    ValueError: ground.footprint (the sleeper's width along the track) must be finite, > 0 and <= the sleeper spacing L = 0.6 m (footprints do not overlap); got 0.7
    """
    if isinstance(ground, (Ground, SoilLayer)):       # the soil itself, not yet under sleepers
        soil = "soil" if isinstance(ground, Ground) else "rt.Ground((), soil)"
        raise TypeError(f"ground= takes the soil as the sleepers load it: wrap the "
                        f"{type(ground).__name__} soil in rt.LayeredGround({soil}, width=2.6, "
                        "footprint=0.25), width [m] the strip loaded across the track (about "
                        "the sleeper's length), footprint [m] the sleeper's width along it")
    if not callable(getattr(ground, "compliance", None)) or not hasattr(ground, "footprint"):
        raise TypeError("ground must have a compliance(kx, omega) method and a footprint "
                        f"width [m] (railtrack.model.ground_protocol.GroundCompliance); got {type(ground).__name__}")
    a = ground.footprint
    if (isinstance(a, bool) or not isinstance(a, (int, float, np.floating, np.integer))
            or not np.isfinite(a) or not 0 < a <= spacing):
        raise ValueError(
            "ground.footprint (the sleeper's width along the track) must be finite, > 0 and "
            f"<= the sleeper spacing L = {spacing:g} m (footprints do not overlap); got {a!r}")
