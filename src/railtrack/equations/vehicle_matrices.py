"""The vehicle's equations of motion, M q'' + C q' + K q = f, and what follows from them.

The ten coordinates q of a `railtrack.model.vehicle.Vehicle`, all positive
upward (a pitch positive when it lifts the leading end), measured from the
unloaded springs:

    q = [z_c, theta_c, z_b1, theta_b1, z_b2, theta_b2, z_w1, z_w2, z_w3, z_w4],

body, leading bogie, trailing bogie, wheelsets from the leading one.  Each
spring (and its dashpot, in parallel) stretches by d . q, d its
connectivity row: the secondary of bogie i by z_bi - (z_c + s_i theta_c),
s_i = +-a; the primary of wheelset j on bogie i by
z_wj - (z_bi + e_j theta_bi), e_j = +-b.  So K = sum k d d^T, C = sum c d d^T
(the Hessians of the strain energy and of Rayleigh's dissipation), and M is
diagonal.
"""

from __future__ import annotations

import numpy as np

from ..model.vehicle import Vehicle

__all__ = ["vehicle_matrices", "vehicle_frequencies", "static_wheelset_loads", "DOFS",
           "WHEELSETS"]

DOFS = ("z_c", "theta_c", "z_b1", "theta_b1", "z_b2", "theta_b2",
        "z_w1", "z_w2", "z_w3", "z_w4")
"""The order of the vehicle's coordinates [m or rad]."""
WHEELSETS = slice(6, 10)
"""Where the wheelsets' coordinates sit in q."""


def _springs(vehicle: Vehicle):
    """(connectivity row d, stiffness, damping) of each suspension."""
    rows = []
    for i, s in enumerate(vehicle.bogie_positions):
        d = np.zeros(10)
        d[0], d[1], d[2 + 2 * i] = -1.0, -s, 1.0
        rows.append((d, vehicle.secondary_stiffness, vehicle.secondary_damping))
    half = 0.5 * vehicle.wheelbase
    for j in range(4):
        bogie, e = divmod(j, 2)[0], (half if j % 2 == 0 else -half)
        d = np.zeros(10)
        d[2 + 2 * bogie], d[3 + 2 * bogie], d[6 + j] = -1.0, -e, 1.0
        rows.append((d, vehicle.primary_stiffness, vehicle.primary_damping))
    return rows


def vehicle_matrices(vehicle: Vehicle) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The mass, damping and stiffness matrices (M, C, K), each 10 x 10, of `DOFS`.

    Units: M in kg (kg m^2 on the pitches), C in N s/m, K in N/m (mixed with
    N and N m/rad where a pitch meets a bounce).

    Examples
    --------
    >>> M, C, K = vehicle_matrices(Vehicle.manchester())
    >>> M.diagonal()[:3].tolist()
    [32000.0, 1970000.0, 2615.0]
    >>> bool(np.allclose(K, K.T)) and bool(np.allclose(K @ np.r_[1, 0, 1, 0, 1, 0, 1, 1, 1, 1], 0))
    True
    """
    mass = np.diag([vehicle.body_mass, vehicle.body_pitch_inertia,
                    vehicle.bogie_mass, vehicle.bogie_pitch_inertia,
                    vehicle.bogie_mass, vehicle.bogie_pitch_inertia]
                   + [vehicle.wheelset_mass] * 4).astype(float)
    stiffness, damping = np.zeros((10, 10)), np.zeros((10, 10))
    for d, k, c in _springs(vehicle):
        stiffness += k * np.outer(d, d)
        damping += c * np.outer(d, d)
    return mass, damping, stiffness


def vehicle_frequencies(vehicle: Vehicle, contact_stiffness: float | None = None) -> np.ndarray:
    """The undamped natural frequencies [Hz], ascending.

    Parameters
    ----------
    vehicle : Vehicle
    contact_stiffness : float or None
        None: the wheelsets held on a rigid track (6 frequencies, body and
        bogies).  A stiffness k_H > 0 [N/m]: each wheelset on a spring k_H
        to a rigid ground (e.g. the linearised Hertz contact, both wheels;
        10 frequencies).

    Examples
    --------
    >>> vehicle_frequencies(Vehicle.manchester()).round(2).tolist()
    [1.07, 1.3, 7.47, 7.48, 11.71, 11.71]
    """
    mass, _, stiffness = vehicle_matrices(vehicle)
    if contact_stiffness is None:
        keep = np.arange(6)
    else:
        contact = float(contact_stiffness)
        if not (np.isfinite(contact) and contact > 0):
            raise ValueError(f"contact_stiffness must be a finite number > 0 N/m or None "
                             f"(wheelsets held); got {contact_stiffness!r}")
        stiffness = stiffness.copy()
        stiffness[WHEELSETS, WHEELSETS] += contact * np.eye(4)
        keep = np.arange(10)
    # M is diagonal and positive: M^-1/2 K M^-1/2 is symmetric, eigvalsh is exact for it
    scale = 1.0 / np.sqrt(mass.diagonal()[keep])
    symmetric = scale[:, None] * stiffness[np.ix_(keep, keep)] * scale[None, :]
    squares = np.linalg.eigvalsh(0.5 * (symmetric + symmetric.T))
    return np.sqrt(np.maximum(squares, 0.0)) / (2 * np.pi)


def static_wheelset_loads(vehicle: Vehicle, gravity: float = 9.81) -> np.ndarray:
    """The forces [N] the track carries under each wheelset at rest, leading first.

    The body and bogies settle on the suspensions with the wheelsets held:
    K_rr q_r = -g M_r 1, and each wheelset's contact force is what holds it,
    P_j = m_w g + (K q)_j.  Each of its two wheels carries P_j / 2.

    Examples
    --------
    >>> (static_wheelset_loads(Vehicle.manchester()) / 1e3).round(3).tolist()
    [109.092, 109.092, 109.092, 109.092]
    """
    mass, _, stiffness = vehicle_matrices(vehicle)
    weight = -float(gravity) * mass.diagonal() * np.array([1, 0, 1, 0, 1, 0, 1, 1, 1, 1])
    q = np.zeros(10)
    q[:6] = np.linalg.solve(stiffness[:6, :6], weight[:6])
    return vehicle.wheelset_mass * float(gravity) + stiffness[WHEELSETS, :6] @ q[:6]
