"""What the wheels do under their contact forces: the receptance above the rail, per harmonic.

The harmonic balance with wheels (`railtrack.equations.wheel_harmonic_balance`)
needs, at each wheel harmonic omega_p != 0, the wheels' displacements z_p
(positive upward) caused by the contact forces P_p (positive pressing the
wheel up) of one wagon's K wheels on the modelled rail:

    z_p = A(omega_p) P_p,      A (K x K) [m/N].

* A `railtrack.Wheel`: each wheel alone, ``A = diag(1 / (k_p + i omega c_p - m_w omega^2))``
  (k_p = c_p = 0: the unsprung mass, -1 / (m_w omega^2)).
* A `railtrack.Vehicle`: the wheelsets are coupled through the bogies and
  the body, ``A = 2 D(omega)^-1`` with D the vehicle's dynamic stiffness at
  its wheelsets (`railtrack.equations.vehicle_response.wheelset_dynamic_stiffness`,
  which holds the wheelsets' masses: they are not added again).  The factor 2:
  the modelled rail carries one wheel of each wheelset, and the other rail
  pushes alike, so a wheelset feels 2 P_p.  For an infinitely heavy body and
  bogies on an infinitely soft primary, D -> -m_w omega^2 I and A is the
  `Wheel`'s of mass m_w / 2 (`railtrack.Vehicle.unsprung_mass`).

At p = 0 a vehicle (a body on two supports, each bogie on two: statically
determinate) carries its static loads whatever the wheels' mean heights,
D(0) = 0: the mean contact force is the static wheel load, as for a `Wheel`
without a primary suspension.
"""

from __future__ import annotations

import numpy as np

from ..model.vehicle import Vehicle
from ..model.wheel import Wheel
from .vehicle_response import wheelset_dynamic_stiffness

__all__ = ["wheel_receptance"]


def wheel_receptance(wheel, omega, count: int) -> np.ndarray:
    """A(omega) [m/N], complex, shape ``omega.shape + (count, count)``: z_p = A P_p.

    Parameters
    ----------
    wheel : Wheel or Vehicle
    omega : array_like
        omega_p != 0 [rad/s].
    count : int
        K, the wheels of a wagon on the modelled rail (4 for a `Vehicle`; 4n
        for a period of n wagons, `railtrack.Train.tiled`).

    Examples
    --------
    >>> A = wheel_receptance(Wheel(600.0), [10.0], 2)
    >>> (A[0].real * 600.0 * 10.0**2).tolist()             # -1 / (m_w omega^2)
    [[-1.0, 0.0], [0.0, -1.0]]
    >>> car = Vehicle.manchester()
    >>> A = wheel_receptance(car, [2 * np.pi * 60.0], 4)   # 60 Hz: nearly the wheelsets alone
    >>> round(float(A[0, 0, 0].real * car.unsprung_mass * (2 * np.pi * 60.0) ** 2), 2)
    -1.01
    """
    omega = np.asarray(omega, dtype=float)
    if np.any(omega == 0):
        raise ValueError("omega must be non-zero: the mean (p = 0) is the static balance")
    if isinstance(wheel, Vehicle):
        if count < 4 or count % 4:
            raise ValueError(f"a Vehicle has 4 wheels on the modelled rail per wagon; the "
                             f"train has {count} axles")
        one = 2.0 * np.linalg.inv(wheelset_dynamic_stiffness(wheel, omega))
        # a period of n wagons (`railtrack.Train.tiled`): n vehicles, each on its own four
        out = np.zeros(omega.shape + (count, count), dtype=complex)
        for start in range(0, count, 4):
            out[..., start:start + 4, start:start + 4] = one
        return out
    if not isinstance(wheel, Wheel):
        raise TypeError(f"wheel must be a railtrack.Wheel or railtrack.Vehicle; got "
                        f"{type(wheel).__name__}")
    own = 1.0 / (float(wheel.primary_stiffness) + 1j * omega * float(wheel.primary_damping)
                 - float(wheel.unsprung_mass) * omega**2)
    return own[..., None, None] * np.eye(int(count))
