"""The wheel loads per unit harmonic of the rail on a linear track, sleepers averaged.

A train of identical wagons (length H) runs at speed v over the rail-top
harmonic e^{i Omega x}; wheel k of every wagon is d_k behind the wagon's
first axle, so wagon n's wheel k meets e^{i Omega (v t - d_k - n H)}: all at
omega = Omega v, wagon n lagging by e^{-i Omega n H}.  Linearised about the
static state, the contact forces P_k e^{i omega t} on the modelled rail
(positive pressing the wheel up) solve

    (I / k_H + U + A_w) P = e^{-i Omega d},

from delta = u + r - z (`railtrack.equations.wheel_harmonic_balance`):
k_H the Hertz tangent at the static load, A_w = 2 D(omega)^-1 the wheels'
receptance through the vehicle (`railtrack.equations.wheel_receptance`), and
U the track's 4 x 4 receptance between the moving wheels: the rail's
displacement at wheel k per unit upward force of wheel k' in every wagon,

    U_kk' = (1/H) sum_r e^{i kappa_r (d_k' - d_k)} / Pi(kappa_r),
    kappa_r = Omega + 2 pi r / H,
    Pi(kappa) = EI kappa^4 - rho S (omega - kappa v)^2 + k_s(omega - kappa v) / L,

the lattice sum of `railtrack.equations.wheel_train_receptance` (its free
rail, k_s = 0, at Omega = 2 pi j / H) with the sleepers smeared along the
rail: each supports the rail over its spacing L with the dynamic stiffness
k_s of pad, sleeper mass and foundation in series, at the frequency
omega - kappa v a point of the rail sees.  Smearing averages over the
sleeper positions: the sleeper-passing modulation (a wheel over a sleeper
or between two) and the sidebands it makes are left out.  The wheelset's
force is 2 P (the other rail pushes alike).  On a rigid track (U = 0,
k_H infinite) 2 P = D e^{-i Omega d}: `vehicle_response.wheel_load_transfer`
up to the common phase of the reference point.
"""

from __future__ import annotations

import numpy as np

from ..model.foundations import LinearFoundation
from ..model.passage import Passage
from ..model.vehicle import Vehicle
from .vehicle_response import band_std, wheelset_dynamic_stiffness

__all__ = ["support_stiffness", "moving_wheels_receptance", "track_wheel_load_transfer",
           "track_wheel_load_std"]

LATTICE_TERMS = 3000
"""|r| <= this in the lattice sum: its tail falls as terms^-3 (below 1e-8 here)."""


def support_stiffness(passage: Passage, foundation: LinearFoundation, omega) -> np.ndarray:
    """k_s(omega) [N/m], complex: pad, sleeper mass and foundation in series, per sleeper."""
    if not isinstance(foundation, LinearFoundation):
        raise TypeError(f"the spectral wheel load needs a LinearFoundation; got "
                        f"{type(foundation).__name__}")
    omega = np.asarray(omega, dtype=float)
    pad = float(passage.pad_stiffness) + 1j * omega * float(passage.pad_damping)
    below = (float(foundation.stiffness) + 1j * omega * float(foundation.damping)
             - float(passage.sleeper_mass) * omega ** 2)
    return pad * below / (pad + below)


def moving_wheels_receptance(passage: Passage, foundation: LinearFoundation, wavenumber: float,
                             offsets, terms: int = LATTICE_TERMS) -> np.ndarray:
    """U [m/N] of the module docstring at Omega = `wavenumber` [rad/m], per offset d_k' - d_k [m].

    Examples
    --------
    >>> import railtrack as rt
    >>> p = rt.Passage(rt.Track.paper(), rt.Train.paper())
    >>> U = moving_wheels_receptance(p, rt.LinearFoundation.paper(), 0.5, [0.0, 3.0])
    >>> bool(abs(U[0]) > abs(U[1]))                        # nearest the wheel, largest
    True
    """
    wagon, speed = float(passage.wagon_length), float(passage.speed)
    omega = float(wavenumber) * speed
    kappa = float(wavenumber) + 2 * np.pi * np.arange(-terms, terms + 1) / wagon
    seen = omega - kappa * speed
    pi = (float(passage.rail_bending_stiffness) * np.square(np.square(kappa))
          - float(passage.rail_linear_mass) * seen ** 2
          + support_stiffness(passage, foundation, seen) / float(passage.sleeper_spacing))
    offsets = np.asarray(offsets, dtype=float)
    phases = np.exp(1j * np.multiply.outer(offsets, kappa))
    return phases @ (1.0 / pi) / wagon


def track_wheel_load_transfer(vehicle: Vehicle, passage: Passage, foundation: LinearFoundation,
                              wavenumbers, contact_stiffness: float | None = None) -> np.ndarray:
    """The wheelsets' forces per unit harmonic e^{i Omega x} of the rail [N/m], on the track.

    Parameters
    ----------
    vehicle : Vehicle
    passage : Passage
        The track and ``vehicle.train(H, v)``.
    foundation : LinearFoundation
    wavenumbers : array_like
        Omega > 0 [rad/m].
    contact_stiffness : float, optional
        k_H [N/m]; default the Hertz tangent at the static wheel load;
        ``numpy.inf`` for a rigid contact.

    Returns
    -------
    ndarray, complex, shape ``wavenumbers.shape + (4,)``
        2 P_k, leading wheelset first (module docstring).
    """
    wavenumbers = np.asarray(wavenumbers, dtype=float)
    if np.any(~np.isfinite(wavenumbers) | (wavenumbers <= 0)):
        raise ValueError("wavenumbers must be finite and > 0 [rad/m]")
    vehicle.check_train(passage.train)
    if contact_stiffness is None:
        load = vehicle.static_wheel_load()
        contact_stiffness = float(vehicle.contact_stiffness(vehicle.static_compression(load)))
    compliance = 1.0 / float(contact_stiffness)
    d = np.asarray(passage.axle_positions, dtype=float)
    offsets = d[None, :] - d[:, None]                                 # d_k' - d_k
    flat = wavenumbers.ravel()
    wheels = 2 * np.linalg.inv(wheelset_dynamic_stiffness(vehicle, flat * float(passage.speed)))
    out = np.empty((flat.size, d.size), dtype=complex)
    for i, wavenumber in enumerate(flat):
        system = (compliance * np.eye(d.size) + wheels[i]
                  + moving_wheels_receptance(passage, foundation, wavenumber, offsets))
        out[i] = 2 * np.linalg.solve(system, np.exp(-1j * wavenumber * d))
    return out.reshape(wavenumbers.shape + (d.size,))


def track_wheel_load_std(vehicle: Vehicle, track, foundation, spectrum, speed: float,
                         wavelengths: tuple, wagon_length: float, *,
                         period: float | None = None,
                         contact_stiffness: float | None = None) -> np.ndarray:
    """The standard deviation [N] of each wheelset's force over a random rail on the track.

    As `spectral_wheel_load_std`, with |H_j|^2 of the linearised track, Hertz
    contact and vehicle (module docstring: the sleepers
    smeared along the rail, the sleeper-passing modulation left out), for a
    train of such wagons of length `wagon_length` [m].  `period` and
    `contact_stiffness` as `band_std` and `track_wheel_load_transfer`.

    Examples
    --------
    >>> import railtrack as rt
    >>> from railtrack.model.irregularity import FRASpectrum
    >>> sigma = track_wheel_load_std(rt.Vehicle.manchester(), rt.Track.paper(),
    ...     rt.LinearFoundation.paper(), FRASpectrum(4), 45.0, (1.5, 25.0), 26.4)
    >>> bool(0.1 < sigma[0] / 109e3 < 0.4)             # of the wheelset's static load
    True
    """
    passage = Passage(track, vehicle.train(wagon_length, speed))
    return band_std(lambda omega: track_wheel_load_transfer(
        vehicle, passage, foundation, omega, contact_stiffness), spectrum, wavelengths, period)
