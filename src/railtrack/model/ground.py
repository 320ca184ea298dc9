"""The ground beneath the track: horizontal soil layers over an elastic half-space (issue 31).

Each `SoilLayer` is a homogeneous, isotropic, linear viscoelastic layer:
thickness h [m], shear-wave speed c_s [m/s], Poisson's ratio nu, density
rho [kg/m^3] and hysteretic damping ratio xi.  A `Ground` is a tuple of
layers, top first, over a half-space (a `SoilLayer` of infinite thickness).

Damping convention.  The equations of `railtrack.equations.ground_stiffness`
take the time dependence exp(-i omega t); the complex Lame moduli are then

    mu* = mu (1 - 2 i xi sgn(omega)),    lambda* = lambda (1 - 2 i xi sgn(omega)),

which is the usual mu (1 + 2 i xi) of the exp(+i omega t) convention: the
same hysteretic loss (a loss factor 2 xi, a phase lag independent of
frequency), conjugated for negative omega so that a real load gives a real
displacement.  Both moduli carry the same xi, so nu stays real.  At omega = 0
the moduli are the elastic ones (the static limit).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .plausibility_check import check_plausible, check_value, quantities_to_si
from .validation import require_finite, require_non_negative, require_positive

__all__ = ["SoilLayer", "Ground"]


def _require_damping_ratio(xi) -> None:
    require_non_negative("damping_ratio", xi)
    if not xi < 0.5:
        raise ValueError(f"damping_ratio must be < 0.5 (a ratio, not a percentage); got {xi!r}")


@dataclass(frozen=True)
class SoilLayer:
    """One homogeneous soil layer (or, with ``thickness=inf``, the half-space).

    Parameters
    ----------
    shear_wave_speed : float
        c_s > 0 [m/s].
    poisson_ratio : float
        nu, strictly between 0 and 0.5 [-].
    density : float
        rho > 0 [kg/m^3].
    damping_ratio : float
        Hysteretic damping ratio xi, 0 <= xi < 0.5 [-] (mu* = mu (1 - 2 i xi)
        for exp(-i omega t), see the module's note).
    thickness : float
        h > 0 [m]; ``math.inf`` for the half-space (the default).

    Examples
    --------
    >>> clay = SoilLayer(65.0, 0.49, 1500.0, 0.02, thickness=6.0)
    >>> round(clay.shear_modulus / 1e6, 2), round(clay.p_wave_speed, 1)
    (6.34, 464.2)
    """

    shear_wave_speed: float
    poisson_ratio: float
    density: float
    damping_ratio: float = 0.0
    thickness: float = math.inf

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("shear_wave_speed", self.shear_wave_speed, "m/s")
        require_finite("poisson_ratio", self.poisson_ratio)
        if not 0.0 < self.poisson_ratio < 0.5:
            raise ValueError("poisson_ratio must lie strictly between 0 and 0.5 (0 < nu < 0.5); "
                             f"got {self.poisson_ratio!r}")
        require_positive("density", self.density, "kg/m^3")
        _require_damping_ratio(self.damping_ratio)
        if self.thickness != math.inf:
            require_positive("thickness", self.thickness, "m")
        for name in ("shear_wave_speed", "poisson_ratio", "density", "damping_ratio",
                     "thickness"):
            object.__setattr__(self, name, float(getattr(self, name)))
        check_plausible(self)       # c_s in km/s, h in mm: PlausibilityWarning

    def with_damping(self, damping_ratio: float) -> SoilLayer:
        """This layer with the damping ratio xi [-]; only xi is checked again.

        The other fields were checked (and warned about) when this layer was
        built: a library routine that sets xi (0 for the undamped waves)
        does not warn about them a second time.

        >>> SoilLayer(100.0, 0.3, 1800.0, 0.02).with_damping(0.05).damping_ratio
        0.05
        """
        _require_damping_ratio(damping_ratio)
        check_value("SoilLayer.damping_ratio", damping_ratio, "soil_damping_ratio")
        return self._damped(damping_ratio)

    def _damped(self, damping_ratio) -> SoilLayer:
        layer = object.__new__(SoilLayer)       # unchecked: the caller checked xi
        for name in ("shear_wave_speed", "poisson_ratio", "density", "thickness"):
            object.__setattr__(layer, name, getattr(self, name))
        object.__setattr__(layer, "damping_ratio", float(damping_ratio))
        return layer

    @classmethod
    def from_young_modulus(cls, young_modulus: float, poisson_ratio: float, density: float,
                           damping_ratio: float = 0.0, thickness: float = math.inf
                           ) -> SoilLayer:
        """The layer of Young's modulus E [Pa]: c_s = sqrt(E / (2 (1 + nu) rho)).

        >>> round(SoilLayer.from_young_modulus(26e6, 0.3, 1800.0).shear_wave_speed, 2)
        74.54
        """
        require_positive("young_modulus", young_modulus, "Pa")
        require_positive("density", density, "kg/m^3")
        require_finite("poisson_ratio", poisson_ratio)
        speed = math.sqrt(young_modulus / (2.0 * (1.0 + poisson_ratio) * density))
        return cls(speed, poisson_ratio, density, damping_ratio, thickness)

    @property
    def shear_modulus(self) -> float:
        """mu = rho c_s^2 [Pa]."""
        return self.density * self.shear_wave_speed**2

    @property
    def young_modulus(self) -> float:
        """E = 2 (1 + nu) mu [Pa]."""
        return 2.0 * (1.0 + self.poisson_ratio) * self.shear_modulus

    @property
    def lame_lambda(self) -> float:
        """lambda = 2 mu nu / (1 - 2 nu) [Pa]."""
        return 2.0 * self.shear_modulus * self.poisson_ratio / (1.0 - 2.0 * self.poisson_ratio)

    @property
    def constrained_modulus(self) -> float:
        """M = lambda + 2 mu [Pa], the oedometric modulus of a laterally confined column."""
        return self.lame_lambda + 2.0 * self.shear_modulus

    @property
    def p_wave_speed(self) -> float:
        """c_p = c_s sqrt(2 (1 - nu) / (1 - 2 nu)) [m/s]."""
        nu = self.poisson_ratio
        return self.shear_wave_speed * math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))

    def damping_factor(self, omega) -> np.ndarray:
        """1 - 2 i xi sgn(omega) [-], the factor of both Lame moduli at omega [rad/s]."""
        return 1.0 - 2j * self.damping_ratio * np.sign(np.asarray(omega, dtype=float))


@dataclass(frozen=True)
class Ground:
    """Horizontal soil layers, top first, over a half-space.

    Parameters
    ----------
    layers : tuple of SoilLayer
        Each of finite thickness; may be empty (a homogeneous half-space).
    halfspace : SoilLayer
        The half-space below, of infinite thickness.

    Examples
    --------
    >>> ground = Ground((SoilLayer(100.0, 0.3, 1800.0, 0.02, thickness=5.0),),
    ...                 SoilLayer(300.0, 0.3, 2000.0, 0.02))
    >>> ground.depth, ground.slowest_shear_wave_speed
    (5.0, 100.0)
    """

    layers: tuple[SoilLayer, ...]
    halfspace: SoilLayer

    def __post_init__(self) -> None:
        layers = tuple(self.layers)
        object.__setattr__(self, "layers", layers)
        for i, layer in enumerate(layers):
            if not isinstance(layer, SoilLayer):
                raise TypeError(f"layers[{i}] must be a SoilLayer; got {type(layer).__name__}")
            if layer.thickness == math.inf:
                raise ValueError(f"layers[{i}] must have a finite thickness [m]; got inf "
                                 "(the half-space goes in `halfspace`)")
        if not isinstance(self.halfspace, SoilLayer):
            raise TypeError(f"halfspace must be a SoilLayer; got {type(self.halfspace).__name__}")
        if self.halfspace.thickness != math.inf:
            raise ValueError("halfspace must have thickness=inf; got "
                             f"{self.halfspace.thickness!r} m (put a finite layer in `layers`)")

    @classmethod
    def homogeneous(cls, shear_wave_speed: float, poisson_ratio: float, density: float,
                    damping_ratio: float = 0.0) -> Ground:
        """A homogeneous half-space (no layers).

        >>> Ground.homogeneous(100.0, 0.25, 1800.0).layers
        ()
        """
        return cls((), SoilLayer(shear_wave_speed, poisson_ratio, density, damping_ratio))

    def with_damping(self, damping_ratio: float) -> Ground:
        """The same strata with the damping ratio xi [-] in every one (`SoilLayer.with_damping`)."""
        _require_damping_ratio(damping_ratio)
        check_value("Ground.damping_ratio", damping_ratio, "soil_damping_ratio")
        return Ground(tuple(layer._damped(damping_ratio) for layer in self.layers),
                      self.halfspace._damped(damping_ratio))

    @property
    def strata(self) -> tuple[SoilLayer, ...]:
        """The layers and then the half-space."""
        return self.layers + (self.halfspace,)

    @property
    def depth(self) -> float:
        """The total thickness of the layers [m]."""
        return float(sum(layer.thickness for layer in self.layers))

    @property
    def slowest_shear_wave_speed(self) -> float:
        """min c_s over the layers and the half-space [m/s]."""
        return min(layer.shear_wave_speed for layer in self.strata)
