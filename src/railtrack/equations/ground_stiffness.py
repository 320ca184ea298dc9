"""The layered ground's dynamic stiffness by the stiffness-matrix method (Kausel & Roesset 1981).

A load exp(i (k_x x + k_y y - omega t)) on the surface of the horizontally
layered ground of `railtrack.model.ground.Ground` excites P-SV waves in the
vertical plane of the radial wavenumber k = sqrt(k_x^2 + k_y^2); the vertical
response depends on k and omega only.  Depth z points down.  In each stratum
the vertical wavenumbers are

    q_p = sqrt(k^2 - omega^2 rho / M*),   q_s = sqrt(k^2 - omega^2 rho / mu*),

(Re q >= 0 and, for omega > 0, Im q <= 0: waves decay and radiate downwards for
exp(-i omega t)),
with the complex moduli of `railtrack.model.ground`.  A real load's response
is real: F(k, -omega) is the complex conjugate of F(k, omega), so a caller
using exp(+i omega t) passes -omega.  Each layer has a 4x4
stiffness matrix (the forces on its faces for the displacements (u, w) of its
faces), the half-space a 2x2 one; they add at the interfaces like bars of a
frame (Kausel & Roesset 1981: their layer and half-space matrices for P-SV waves;
the matrices here are the same physics in another basis, so their entries are
not copied from the paper but follow from Hooke's law and the wave equation).

Stability (the reason this module does not copy their hyperbolic forms).
Every wave is written decaying from the face where it starts, exp(-q z)
or exp(-q (h - z)), so no entry grows with k h; and the S wave enters as
the divided difference (k S - q_s P) / (q_s - q_p), whose limits at
q_s -> q_p (the static limit omega / k -> 0, where P and S waves become the
same field) are written out, so the static stiffness comes from the same
formula without cancellation (the Boussinesq limit, checked in the tests).
"""

from __future__ import annotations

import numpy as np

from ..model.ground import Ground, SoilLayer

__all__ = ["layer_stiffness", "halfspace_stiffness", "global_stiffness", "surface_flexibility"]


def _vertical_wavenumber(k2, kappa2, omega) -> np.ndarray:
    """sqrt(k^2 - kappa^2) with Re >= 0 (decaying downward) and, on the branch cut of an
    undamped stratum, Im of sign -sgn(omega) (radiating downward for exp(-i omega t))."""
    q = np.sqrt(k2 - kappa2 + 0j)
    return np.where(q.real == 0, -1j * np.sign(omega) * np.abs(q.imag), q)


def _waves(layer: SoilLayer, k: np.ndarray, omega: np.ndarray):
    """q_p, q_s, mu*, and the slownesses squared s_s = rho/mu*, s_p = rho/M* of `layer`."""
    factor = layer.damping_factor(omega)
    mu = layer.shear_modulus * factor
    s_s = layer.density / mu
    s_p = layer.density / (layer.constrained_modulus * factor)
    w2 = omega**2
    return (_vertical_wavenumber(k**2, w2 * s_p, omega),
            _vertical_wavenumber(k**2, w2 * s_s, omega), mu, s_s, s_p)


def _down_going(k, omega, waves, z):
    """Displacements (u, w) and tractions (tau_xz, sigma_zz) at depth z >= 0 of the two
    down-going basis fields, as arrays (..., 2, 2): row (u, w) or (tau, sigma), column field.

    Field 1 is -i times the P wave exp(-q_p z); field 2 is (k S - q_s P1) / (q_s - q_p),
    written with E = (exp(-q_s z) - exp(-q_p z)) / (q_s - q_p) and the ratios
    R = (k^2 - q_s q_p) / (q_s - q_p) and Q = omega^2 s_s / (q_s - q_p) in forms finite
    at q_s = q_p.
    """
    q_p, q_s, mu, s_s, s_p = waves
    k2, w2 = k**2, omega**2
    delta = w2 * (s_p - s_s) / (q_s + q_p)                    # q_s - q_p, without cancelling
    ratio_r = (k2 * (s_s + s_p) - w2 * s_s * s_p) * (q_s + q_p) / ((k2 + q_s * q_p)
                                                                   * (s_p - s_s))
    ratio_q = s_s * (q_s + q_p) / (s_p - s_s)
    e_p = np.exp(-q_p * z)
    x = -delta * z
    with np.errstate(all="ignore"):
        small = np.abs(x) < 1.0
        phi = np.where(x == 0, 1.0, np.expm1(x) / np.where(x == 0, 1.0, x))
        direct = (np.exp(-q_s * z) - e_p) / np.where(delta == 0, 1.0, delta)
        e_diff = np.where(small, -z * e_p * phi, direct)     # each branch finite where taken
    kss = k2 + q_s**2
    disp = np.stack([np.stack([k * e_p, k * q_s * e_diff], -1),
                     np.stack([1j * q_p * e_p, 1j * (k2 * e_diff + ratio_r * e_p)], -1)], -2)
    trac = np.stack([np.stack([-2 * mu * k * q_p * e_p,
                               -mu * k * (kss * e_diff + (ratio_r + q_s) * e_p)], -1),
                     np.stack([-1j * mu * kss * e_p,
                               -1j * mu * q_s * (2 * k2 * e_diff + ratio_q * e_p)], -1)], -2)
    return disp, trac


def _prepare(k, omega):
    k = np.asarray(k, dtype=float)
    if not np.all(np.isfinite(k)) or not np.all(k > 0):
        raise ValueError("k (the radial wavenumber) must be finite and > 0 rad/m; "
                         f"got {k if k.size < 6 else f'values from {k.min()} to {k.max()}'}")
    omega = np.asarray(omega, dtype=float)
    if not np.all(np.isfinite(omega)):
        raise ValueError(f"omega must be finite [rad/s]; got {omega}")
    return np.broadcast_arrays(k, omega)


def layer_stiffness(layer: SoilLayer, k, omega) -> np.ndarray:
    """The 4x4 dynamic stiffness of a layer for P-SV waves (Kausel & Roesset 1981).

    Parameters
    ----------
    layer : SoilLayer
        Of finite thickness h [m].
    k, omega : array_like
        Radial wavenumber k > 0 [rad/m] and circular frequency [rad/s], broadcast.

    Returns
    -------
    ndarray, shape (..., 4, 4), complex [Pa/m]
        Forces per unit area on the faces (top: -(tau_xz, sigma_zz), bottom:
        +(tau_xz, sigma_zz)) per displacement (u_top, w_top, u_bottom, w_bottom).

    Examples
    --------
    Statically a thin layer is a column in oedometric compression, M / h:

    >>> layer = SoilLayer(100.0, 0.25, 2000.0, thickness=0.1)
    >>> K = layer_stiffness(layer, 1e-4, 0.0)
    >>> round(float(K[3, 3].real) / (layer.constrained_modulus / 0.1), 6)
    1.0
    """
    k, omega = _prepare(k, omega)
    waves = _waves(layer, k, omega)
    h = layer.thickness
    d_top, t_top = _down_going(k, omega, waves, 0.0)
    d_bot, t_bot = _down_going(k, omega, waves, h)
    mirror = np.array([1.0, -1.0])[:, None]                  # (u, w) -> (u, -w) upside down
    disp = np.concatenate([np.concatenate([d_top, mirror * d_bot], -1),
                           np.concatenate([d_bot, mirror * d_top], -1)], -2)
    # the up-going fields' tractions are (-tau, sigma) of the down-going ones at h - z
    forces = np.concatenate([np.concatenate([-t_top, mirror * t_bot], -1),
                             np.concatenate([t_bot, -mirror * t_top], -1)], -2)
    return np.swapaxes(np.linalg.solve(np.swapaxes(disp, -1, -2),
                                       np.swapaxes(forces, -1, -2)), -1, -2)


def halfspace_stiffness(layer: SoilLayer, k, omega) -> np.ndarray:
    """The 2x2 dynamic stiffness of a half-space for P-SV waves (Kausel & Roesset 1981).

    Forces -(tau_xz, sigma_zz) on its surface per its displacement (u, w), shape
    (..., 2, 2), complex [Pa/m]; `layer`'s thickness is ignored.

    Examples
    --------
    >>> K = halfspace_stiffness(SoilLayer(100.0, 0.25, 2000.0), 2.0, 0.0)
    >>> round(float(K[1, 1].real) / (2 * 2.0 * 2e7), 6)      # 2 k mu M / (M + mu)
    0.75
    """
    k, omega = _prepare(k, omega)
    disp, trac = _down_going(k, omega, _waves(layer, k, omega), 0.0)
    return -np.swapaxes(np.linalg.solve(np.swapaxes(disp, -1, -2),
                                        np.swapaxes(trac, -1, -2)), -1, -2)


def global_stiffness(ground: Ground, k, omega) -> np.ndarray:
    """The assembled stiffness of the layers and the half-space, shape (..., 2n+2, 2n+2).

    Degrees of freedom (u_j, w_j) of the interfaces j = 0 (the surface) to n
    (the top of the half-space), in that order [Pa/m].

    >>> global_stiffness(Ground.homogeneous(100.0, 0.3, 1800.0), [1.0, 2.0], 50.0).shape
    (2, 2, 2)
    """
    k, omega = _prepare(k, omega)
    size = 2 * len(ground.layers) + 2
    total = np.zeros(k.shape + (size, size), dtype=complex)
    for j, layer in enumerate(ground.layers):
        total[..., 2 * j:2 * j + 4, 2 * j:2 * j + 4] += layer_stiffness(layer, k, omega)
    total[..., -2:, -2:] += halfspace_stiffness(ground.halfspace, k, omega)
    return total


def surface_flexibility(ground: Ground, k, omega) -> np.ndarray:
    """The ground's vertical surface flexibility w / p for a load p exp(i (k_x x + k_y y - omega t)).

    Parameters
    ----------
    ground : Ground
    k : array_like
        Radial wavenumber sqrt(k_x^2 + k_y^2) > 0 [rad/m].
    omega : array_like
        Circular frequency [rad/s] (negative gives the complex conjugate).

    Returns
    -------
    ndarray, complex [m/Pa]
        The surface's vertical displacement per unit vertical stress, both
        positive downward; statically (1 - nu) / (mu k) on a homogeneous
        half-space (Boussinesq's problem in the wavenumber domain).

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.25, 2000.0)
    >>> f = surface_flexibility(ground, 0.5, 0.0)
    >>> round(float(f.real) * 2e7 * 0.5 / (1 - 0.25), 9)
    1.0
    """
    k, omega = _prepare(k, omega)
    stiffness = global_stiffness(ground, k, omega)
    load = np.zeros(stiffness.shape[:-1], dtype=complex)
    load[..., 1] = 1.0
    return np.linalg.solve(stiffness, load[..., None])[..., 1, 0]
