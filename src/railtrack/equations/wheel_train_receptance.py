"""The free rail under a train of wheels whose forces vary in time: eq. (14.2) of the book.

A wheel at x = vt - d in every wagon (period H along the track) pushes the
rail up with a force whose harmonic p is ``e^{i omega_p t}`` (omega_p = p 2 pi v/H).
The free rail (no sleepers: their forces are added separately, as in eq. 6)
answers, in the frame of the train, with the wavenumbers kappa_r = 2 pi r / H
of the wagon pattern (the book's gamma_mu).  For EI u'''' + rho S u'' = f and the moving
pattern ``e^{i omega_p t} e^{i kappa_r (x - vt)}``,

    u(x, t) = e^{i omega_p t} (1/H) sum_r e^{i kappa_r (x - vt + d)} / Pi_p(kappa_r),
    Pi_p(kappa) = EI kappa^4 - rho S (omega_p - kappa v)^2,

(kappa v - omega_p is the frequency a point of the rail sees).  Two readings
of it are needed:

* at another wheel of the train, x - vt = -d', the rail moves at the same
  frequency omega_p with ``U_p(Delta) = (1/H) sum_r e^{i kappa_r Delta} / Pi_p(kappa_r)``,
  Delta = d - d' (mod H): `wheel_train_receptance`;
* at a fixed point x = 0 (above sleeper 0) it moves at omega_p - kappa_r v
  = omega_{p-r}: harmonic n of the rail there takes r = p - n,
  ``(1/H) e^{i kappa_{p-n} d} / (EI kappa_{p-n}^4 - rho S omega_n^2)`` per unit force
  (for p = 0 the paper's moving-load term of eq. 6, up to the sign of the force).

With the four roots a_i of Pi_p and Fourier's series of e^{ibx} on (0, 2 pi),
``sum_r e^{i kappa_r Delta} / (kappa_r - a) = -i H e^{i a Delta} / (e^{i a H} - 1)``
for 0 <= Delta < H, so that

    U_p(Delta) = sum_i -i e^{i a_i Delta} / (Pi_p'(a_i) (e^{i a_i H} - 1)),

evaluated without overflow for any Im a_i.  D is infinite where a root is
real and a multiple of 2 pi / H (a free wave of the rail that fits the
wagon pattern), and for omega_p = 0 (r = 0: a rigid lift of the free rail):
like eq. 3 these singularities cancel against the sleepers' part.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage

__all__ = ["wheel_train_receptance", "wheel_train_receptance_lattice_sum",
           "wheel_train_at_fixed_point"]


def _roots(passage: Passage, omega: np.ndarray) -> np.ndarray:
    """The four roots kappa of P(kappa) = EI kappa^4 - rho S (omega - kappa v)^2 [1/m].

    For an array of omega (shape W): shape W + (4,), the eigenvalues of the
    monic quartic's companion matrices (as `np.roots`, for all omega at once).
    """
    ei, rho_s, v = (float(passage.rail_bending_stiffness), float(passage.rail_linear_mass),
                    float(passage.speed))
    omega = np.asarray(omega, dtype=float)
    companion = np.zeros(omega.shape + (4, 4))
    companion[..., 1, 0] = companion[..., 2, 1] = companion[..., 3, 2] = 1.0
    companion[..., 0, 1] = rho_s * v**2 / ei
    companion[..., 0, 2] = -2.0 * rho_s * omega * v / ei
    companion[..., 0, 3] = rho_s * omega**2 / ei
    return np.linalg.eigvals(companion)


def wheel_train_receptance(passage: Passage, omega: float, offset: ArrayLike,
                           order: int = 0) -> np.ndarray:
    """U_p(Delta) of the module docstring [m/N]: the free rail a distance Delta ahead of a wheel.

    Parameters
    ----------
    passage : Passage
        Scalar rail (EI, rho S), wagon length H and speed v.
    omega : float or array_like
        omega_p != 0 [rad/s], the frequency of the wheels' forces; an array
        gives one answer per omega (shape omega.shape + offset.shape).
    offset : array_like
        Delta = d - d' [m], how far the point read (x = vt - d') is ahead of
        the loaded wheel (x = vt - d), taken modulo H.
    order : int
        0 for U_p, 2 for its second derivative in Delta (the rail's curvature,
        continuous across the wheel) [1/(N m)].

    Returns
    -------
    ndarray
        Complex, shaped like `offset` (for a scalar omega): the rail's
        displacement there per unit upward force of every wagon's wheel, at
        the frequency omega.

    Examples
    --------
    >>> p = Passage.paper()
    >>> w = 2 * np.pi * p.speed / p.wagon_length * 3
    >>> bool(np.allclose(wheel_train_receptance(p, w, [0.0, 3.0]),
    ...                  wheel_train_receptance_lattice_sum(p, w, [0.0, 3.0]), rtol=1e-6))
    True
    """
    omega = np.asarray(omega, dtype=float)
    if np.any(omega == 0):
        raise ValueError("omega must be non-zero: at omega = 0 the free rail's rigid lift "
                         "(r = 0) is infinite; the mean is carried by the sleepers")
    wagon = float(passage.wagon_length)
    delta = np.mod(np.asarray(offset, dtype=float), wagon)
    ei, rho_s, v = (float(passage.rail_bending_stiffness), float(passage.rail_linear_mass),
                    float(passage.speed))
    roots = _roots(passage, omega).reshape(omega.shape + (1,) * delta.ndim + (4,))
    derivative = 4 * ei * roots**3 + 2.0 * rho_s * v * (omega.reshape(
        omega.shape + (1,) * (delta.ndim + 1)) - roots * v)
    at = delta[..., None]
    upper = roots.imag >= 0
    # |e^{iaH}| <= 1: the form as written; |e^{iaH}| > 1: divided through by e^{iaH}
    # (each root in its own branch; the other branch sees a harmless stand-in)
    up, down = np.where(upper, roots, 1j), np.where(upper, -1j, roots)
    term = np.where(upper, -1j * np.exp(1j * up * at) / (np.exp(1j * up * wagon) - 1.0),
                    -1j * np.exp(1j * down * (at - wagon)) / (1.0 - np.exp(-1j * down * wagon)))
    return np.sum(term * (1j * roots) ** order / derivative, axis=-1)


def wheel_train_receptance_lattice_sum(passage: Passage, omega: float, offset: ArrayLike,
                                       terms: int = 200_000) -> np.ndarray:
    """U_p(Delta) by its sum over the wagon pattern's wavenumbers, |r| <= terms [m/N].

    The independent check of `wheel_train_receptance`; the neglected tail falls
    like terms^-3 relative to the sum.
    """
    wagon = float(passage.wagon_length)
    ei, rho_s, v = (float(passage.rail_bending_stiffness), float(passage.rail_linear_mass),
                    float(passage.speed))
    kappa = 2 * np.pi * np.arange(-terms, terms + 1) / wagon
    weights = 1.0 / (ei * kappa**4 - rho_s * (omega - kappa * v) ** 2)
    delta = np.atleast_1d(np.asarray(offset, dtype=float))
    return np.array([np.sum(weights * np.exp(1j * kappa * d)) for d in delta]) / wagon


def wheel_train_at_fixed_point(passage: Passage, omega_force: float, harmonic: ArrayLike,
                               position: float) -> np.ndarray:
    """Harmonic n of the free rail at x = 0 per unit force e^{i omega_p t} of a wheel at d [m/N].

    ``(1/H) e^{i kappa_{p-n} d} / (EI kappa_{p-n}^4 - rho S omega_n^2)``, with
    kappa_r = 2 pi r / H and omega_p = p 2 pi v/H (module docstring): a force
    varying at omega_p reaches a fixed point of the rail at every harmonic n.
    For p = 0 it is the paper's moving-load term of eq. (6) per unit upward force.

    Parameters
    ----------
    passage : Passage
    omega_force : float
        omega_p [rad/s], a multiple of 2 pi v / H.
    harmonic : array_like of int
        n, the harmonics read at x = 0.
    position : float
        d [m], the wheel's place behind the wagon's first axle.

    Returns
    -------
    ndarray
        Complex, shaped like `harmonic`; infinite where the denominator is 0
        (n = p = 0, or a free wave of the rail).
    """
    wagon = float(passage.wagon_length)
    fundamental = 2 * np.pi * float(passage.speed) / wagon
    p = omega_force / fundamental
    if abs(p - round(p)) > 1e-9:
        raise ValueError(f"omega_force must be a multiple of 2 pi v / H = {fundamental:.6g} rad/s")
    n = np.asarray(harmonic)
    kappa = 2 * np.pi * (round(p) - n) / wagon
    omega_n = n * fundamental
    denominator = (float(passage.rail_bending_stiffness) * kappa**4
                   - float(passage.rail_linear_mass) * omega_n**2)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.exp(1j * kappa * position) / (wagon * denominator)
