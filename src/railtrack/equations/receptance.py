"""Section 2.1: the reduced force–displacement relation of the rail, eq. (3).

The rail is loaded by the sleeper reactions R(t - nL/v) at x = nL.  Its
displacement above sleeper 0 then obeys, in the frequency domain,

    w_r(0, omega) = R(omega) eta_E(omega) - (moving-load term),

with the receptance of the periodically supported rail (eq. 3)

    eta_E = [sin(a)/(cos(a) - cos(q)) - sinh(a)/(cosh(a) - cos(q))] / (4 k_b^3 EI),

where ``k_b^4 = rho S omega^2 / EI``, ``a = k_b L`` and ``q = omega L / v``.

Written this way eta_E, and the quantities built from it, are 0/0 or inf/inf
at omega = 0 and where ``a = q``.  This module therefore factors eq. (3)
into pieces that stay finite and accurate everywhere (see
`receptance_factors`); `railtrack.equations.sleeper` and `railtrack.equations.load` combine
them into P_n, Gamma and F_n without ever dividing by zero.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage

__all__ = [
    "bending_wavenumber",
    "rail_receptance",
    "rail_receptance_lattice_sum",
    "moving_load_receptance",
    "critical_frequency",
    "receptance_pole_frequencies",
    "receptance_factors",
    "ReceptanceFactors",
]


def _sinc(x: np.ndarray) -> np.ndarray:
    """sin(x)/x with the value 1 at 0."""
    return np.sinc(x / np.pi)


def _tanhc(x: np.ndarray) -> np.ndarray:
    """tanh(x)/x with the value 1 at 0."""
    safe = np.where(x == 0, 1.0, x)
    return np.where(x == 0, 1.0, np.tanh(safe) / safe)


def _sech(x: np.ndarray) -> np.ndarray:
    """1/cosh(x) for x >= 0, without overflow."""
    e = np.exp(-x)
    return 2.0 * e / (1.0 + e * e)


def bending_wavenumber(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """Free bending wavenumber k_b = (rho S omega^2 / EI)^(1/4) of eq. (3) [1/m].

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Angular frequency [rad/s], any sign.

    Returns
    -------
    ndarray
        k_b >= 0, same shape as `omega` (broadcast with the track's fields).
    """
    omega = np.asarray(omega, dtype=float)
    ratio = passage.rail_linear_mass / passage.rail_bending_stiffness
    return np.sqrt(np.abs(omega)) * ratio**0.25


class ReceptanceFactors(NamedTuple):
    """Finite factors of eq. (3); see `receptance_factors`.

    ``eta_E = numerator / denominator`` and ``(cos a - cos q)(cosh a - cos q)
    = cosh(a) * gap * (q^4 - a^4)``.
    """

    numerator: np.ndarray
    denominator: np.ndarray
    gap: np.ndarray


def receptance_factors(passage: Passage, omega: ArrayLike) -> ReceptanceFactors:
    """Split eta_E of eq. (3) into finite, well-conditioned factors.

    With ``a = k_b L``, ``q = |omega| L / v`` and ``r = q / a`` (which is
    ``sqrt(|omega|) (EI/rho S)^(1/4) / v`` and so finite),

    * ``gap = (cos a - cos q)(cosh a - cos q) / ((q^4 - a^4) cosh a)``,
      equal to 1/4 at omega = 0 and smooth through ``a = q``;
    * ``numerator = [sin a (cosh a - cos q) - sinh a (cos a - cos q)] / (a^3 cosh a)``,
      equal to 1 at omega = 0;
    * ``denominator = 4 EI gap (q^4 - a^4) / L^3``, zero at omega = 0.

    so that ``eta_E = numerator / denominator`` exactly.  The differences of
    cosines are evaluated as products of sines, and every ``x/x`` as a sinc,
    so no factor loses precision near omega = 0, near ``a = q`` or at large a.

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Angular frequency [rad/s].

    Returns
    -------
    ReceptanceFactors
        ``numerator`` [-], ``denominator`` [N/m], ``gap`` [-].
    """
    omega = np.asarray(omega, dtype=float)
    span = passage.sleeper_spacing
    a = bending_wavenumber(passage, omega) * span
    q = np.abs(omega) * span / passage.speed
    r = (
        np.sqrt(np.abs(omega))
        * (passage.rail_bending_stiffness / passage.rail_linear_mass) ** 0.25
        / passage.speed
    )
    sech_a = _sech(a)
    # (cos a - cos q) / (q^2 - a^2), from cos a - cos q = -2 sin((a+q)/2) sin((a-q)/2)
    cos_gap = 0.5 * _sinc(0.5 * (a + q)) * _sinc(0.5 * (a - q))
    # (cosh a - cos q) / ((q^2 + a^2) cosh a), from cosh a - 1 = 2 sinh^2(a/2)
    # and 1 - sech a = tanh(a/2) tanh(a)
    cosh_gap = (
        0.5 * _tanhc(0.5 * a) * _tanhc(a) + 0.5 * r**2 * _sinc(0.5 * q) ** 2 * sech_a
    ) / (1.0 + r**2)
    gap = cos_gap * cosh_gap
    numerator = _sinc(a) * cosh_gap * (1.0 + r**2) + _tanhc(a) * cos_gap * (1.0 - r**2)
    denominator = (
        4.0 * passage.rail_bending_stiffness / span**3 * gap * a**4 * (r**4 - 1.0)
    )
    return ReceptanceFactors(numerator, denominator, gap)


def rail_receptance(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """Receptance eta_E(omega) of the periodically supported rail, eq. (3) [m/N].

    The displacement of the rail above a sleeper per unit reaction of the
    sleepers, when all the sleepers push with the same force history delayed
    by L/v from one sleeper to the next.

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Angular frequency [rad/s].

    Returns
    -------
    ndarray
        Real eta_E, same shape as `omega`.  It has genuine poles, where
        ``cos(k_b L) = cos(omega L / v)`` (omega = 0 among them); there it is
        ``inf``.  P_n, Gamma and F_n stay finite at those poles.

    Examples
    --------
    >>> import numpy as np
    >>> passage = Passage.paper()
    >>> omega = np.array([50.0, 500.0])
    >>> np.allclose(rail_receptance(passage, omega),
    ...             rail_receptance_lattice_sum(passage, omega), rtol=1e-8)
    True
    """
    factors = receptance_factors(passage, omega)
    with np.errstate(divide="ignore"):
        return factors.numerator / factors.denominator


def rail_receptance_lattice_sum(
    passage: Passage, omega: ArrayLike, terms: int = 20_000
) -> np.ndarray:
    """eta_E by Poisson summation of the free beam's Green function (check of eq. 3).

    Summing the free Euler–Bernoulli beam's Green function over the supports,
    ``sum_n G(nL) exp(-i omega n L / v)``, is by Poisson's formula a sum over
    wavenumbers ``kappa_j = omega/v + 2 pi j / L``:

        eta_E = (1 / (EI L)) sum_j 1 / (kappa_j^4 - k_b^4),

    which converges like j^-4.  This is independent of the closed form of
    eq. (3) and is used to test it.  The tail beyond ``|j| = terms`` is added
    from its asymptotic value.

    Parameters
    ----------
    passage : Passage
        Scalar-valued track.
    omega : array_like
        Angular frequency [rad/s].
    terms : int
        Number of wavenumbers on each side.

    Returns
    -------
    ndarray
        eta_E [m/N].
    """
    omega = np.asarray(omega, dtype=float)
    span = passage.sleeper_spacing
    q = (omega * span / passage.speed)[..., None]
    a4 = ((bending_wavenumber(passage, omega) * span) ** 4)[..., None]
    j = np.arange(-terms, terms + 1)
    total = np.sum(1.0 / ((q + 2.0 * np.pi * j) ** 4 - a4), axis=-1)
    # sum over |j| > J of 1/(2 pi j)^4 ~ 2 / (3 J^3 (2 pi)^4)
    tail = 2.0 / (3.0 * terms**3 * (2.0 * np.pi) ** 4)
    return (total + tail) * span**3 / passage.rail_bending_stiffness


def moving_load_receptance(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """1 / (v EI [(omega/v)^4 - k_b^4]), the moving-load factor of eq. (3) [m s/N].

    Multiplied by ``-Q exp(-i omega D_j / v)`` it is the displacement of the
    free rail at x = 0 under the moving load j.  Infinite where omega/v = k_b.
    """
    omega = np.asarray(omega, dtype=float)
    kb = bending_wavenumber(passage, omega)
    with np.errstate(divide="ignore"):
        return 1.0 / (
            passage.speed * passage.rail_bending_stiffness * ((omega / passage.speed) ** 4 - kb**4)
        )


def critical_frequency(passage: Passage) -> float:
    """omega* = v^2 sqrt(rho S / EI), where omega / v equals k_b [rad/s]."""
    return float(passage.speed**2 * np.sqrt(passage.rail_linear_mass / passage.rail_bending_stiffness))


def receptance_pole_frequencies(passage: Passage, omega_max: float) -> np.ndarray:
    """Frequencies 0 < omega <= omega_max where cos(k_b L) = cos(omega L / v) [rad/s].

    There eta_E of eq. (3) is infinite: a free bending wave of the rail
    (wavenumber k_b) matches a spatial harmonic omega/v + 2 pi j / L of the
    sleeper forces.  With s = sqrt(omega) and c = (rho S/EI)^(1/4) the
    conditions ``omega L / v - 2 pi m = -+ k_b L`` are quadratics in s:
    ``s = v [+-c + sqrt(c^2 + 8 pi m / (v L))] / 2``, m = 0, 1, 2, ...
    (m = 0 with the + sign is omega* of `critical_frequency`).

    Returns
    -------
    ndarray
        Sorted pole frequencies (omega = 0 itself is not listed).
    """
    c = (passage.rail_linear_mass / passage.rail_bending_stiffness) ** 0.25
    v, span = passage.speed, passage.sleeper_spacing
    poles = [critical_frequency(passage)]
    m = 1
    while True:
        root = np.sqrt(c * c + 8.0 * np.pi * m / (v * span))
        pair = [(0.5 * v * (sign * c + root)) ** 2 for sign in (-1.0, 1.0)]
        if min(pair) > omega_max:
            break
        poles += pair
        m += 1
    poles = np.sort(np.array(poles))
    return poles[poles <= omega_max]
