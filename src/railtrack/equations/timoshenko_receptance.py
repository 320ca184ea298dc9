"""Eq. (3) for a Timoshenko rail: the receptance of a shear-deformable rail on periodic supports.

For a harmonic ``w, psi ~ e^{i(kappa x - omega t)}`` the two equations of
`railtrack.model.timoshenko.TimoshenkoRail` (force per length F upward) become

    [kGA kappa^2 - rho S omega^2,   i kappa kGA                 ] [W  ]   [F]
    [-i kappa kGA,                  EI kappa^2 + kGA - rho I omega^2] [Psi] = [0],

whose determinant over kGA is the dispersion relation (`timoshenko_dispersion`)

    D(kappa) = EI kappa^4 - (rho I + EI rho S / kGA) omega^2 kappa^2
               - rho S omega^2 + (rho I rho S / kGA) omega^4 = EI (kappa^2 - s_1)(kappa^2 - s_2),

and the rail's deflection per unit force (the Fourier transform of the point
force's Green function, `timoshenko_green_transform`)

    G^(kappa) = W / F = N(kappa^2) / (kGA D(kappa)),   N(s) = EI s + kGA - rho I omega^2.

s_1 > 0 always (a propagating bending wave); s_2 < 0 below the cut-off
omega_c = sqrt(kGA / rho I) (evanescent) and > 0 above it (a second, shear
wave).  The EB rail has s = +-k_b^2 and N / kGA = 1.

As in eq. (3), sleeper n pushes with the force delayed by nL/v, so the rail
above sleeper 0 moves by (Poisson's formula) ``eta = (1/L) sum_j G^(kappa_j)``,
kappa_j = (q + 2 pi j)/L, q = omega L / v.  Partial fractions over s_1, s_2
and ``(1/L) sum_j 1/(kappa_j^2 - s) = S(s) = sin(kL) / (2k (cos kL - cos q))``,
k = sqrt(s) (``sinh kL / (2k (cosh kL - cos q))`` for s = -k^2 < 0) give

    eta = [N(s_1) S(s_1) - N(s_2) S(s_2)] / (kGA EI (s_1 - s_2)).

With s = +-k_b^2 and N = kGA this is eq. (3).  The book's chapter "The wheel
on the rail" derives the dispersion relation and the partial fractions with
SymPy; `timoshenko_receptance_lattice_sum` is the independent check.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from ..model.timoshenko import TimoshenkoRail

__all__ = [
    "pinned_pinned_frequency",
    "timoshenko_dispersion",
    "timoshenko_green_transform",
    "timoshenko_receptance",
    "timoshenko_receptance_lattice_sum",
    "timoshenko_wavenumbers_squared",
]


def _coefficients(passage: Passage, rail: TimoshenkoRail):
    """EI, rho S, kGA, rho I, B = rho I + EI rho S / kGA, C = rho I rho S / kGA."""
    ei, rho_s = passage.rail_bending_stiffness, passage.rail_linear_mass
    kga, rho_i = rail.shear_stiffness, rail.rotary_inertia
    return ei, rho_s, kga, rho_i, rho_i + ei * rho_s / kga, rho_i * rho_s / kga


def timoshenko_dispersion(passage: Passage, rail: TimoshenkoRail, wavenumber: ArrayLike,
                          omega: ArrayLike) -> np.ndarray:
    """D(kappa, omega) of the Timoshenko rail, zero on its free waves [N/m^2].

    ``EI k^4 - (rho I + EI rho S/kGA) w^2 k^2 - rho S w^2 + (rho I rho S/kGA) w^4``.

    Parameters
    ----------
    passage : Passage
        EI and rho S are read from its track.
    rail : TimoshenkoRail
    wavenumber : array_like
        kappa [1/m].
    omega : array_like
        Angular frequency [rad/s]; broadcast with `wavenumber`.
    """
    ei, rho_s, _, _, b, c = _coefficients(passage, rail)
    k2 = np.asarray(wavenumber, dtype=float) ** 2
    w2 = np.asarray(omega, dtype=float) ** 2
    return ei * k2 * k2 - b * w2 * k2 - rho_s * w2 + c * w2 * w2


def timoshenko_wavenumbers_squared(passage: Passage, rail: TimoshenkoRail,
                                   omega: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """The roots s_1 >= s_2 of D in s = kappa^2 [1/m^2].

    ``s_1 = [B w^2 + sqrt(B^2 w^4 + 4 EI (rho S w^2 - C w^4))] / (2 EI)`` and, by
    Vieta, ``s_2 = (C w^4 - rho S w^2) / (EI s_1)`` (no cancellation above the
    cut-off).  The discriminant is ``w^2 [(rho I - EI rho S/kGA)^2 w^2 + 4 EI rho S]
    >= 0``: both roots are real.  Both are 0 at omega = 0.
    """
    ei, rho_s, _, _, b, c = _coefficients(passage, rail)
    w2 = np.asarray(omega, dtype=float) ** 2
    root = np.sqrt(w2 * ((b * b - 4.0 * ei * c) * w2 + 4.0 * ei * rho_s))
    s1 = (b * w2 + root) / (2.0 * ei)
    safe = np.where(s1 == 0.0, 1.0, s1)
    s2 = np.where(s1 == 0.0, 0.0, (c * w2 - rho_s) * w2 / (ei * safe))
    return s1, s2


def timoshenko_green_transform(passage: Passage, rail: TimoshenkoRail, wavenumber: ArrayLike,
                               omega: ArrayLike) -> np.ndarray:
    """G^(kappa) = (EI kappa^2 + kGA - rho I w^2) / (kGA D(kappa)) [m^2/N].

    The deflection W per force F of a load ``F e^{i(kappa x - omega t)}`` per
    length; its inverse Fourier transform is the rail's point-force receptance.
    ``inf`` on the free waves (D = 0).
    """
    _, _, kga, rho_i, _, _ = _coefficients(passage, rail)
    k2 = np.asarray(wavenumber, dtype=float) ** 2
    w2 = np.asarray(omega, dtype=float) ** 2
    with np.errstate(divide="ignore"):
        return (passage.rail_bending_stiffness * k2 + kga - rho_i * w2) / (
            kga * timoshenko_dispersion(passage, rail, wavenumber, omega))


def _periodic_sum(s: np.ndarray, q: np.ndarray, span: float) -> np.ndarray:
    """S(s) = (1/L) sum_j 1/(kappa_j^2 - s), kappa_j = (q + 2 pi j)/L, in closed form [m].

    ``sin(a) / (2k (cos a - cos q))`` for s = k^2 >= 0 and ``sinh(a) / (2k (cosh a
    - cos q))`` for s = -k^2 < 0, a = kL, written without overflow (e^{-a}
    forms) and finite at a = 0 (``L / (4 sin^2(q/2))``).  ``inf`` at a pole.
    """
    a = np.sqrt(np.abs(s)) * span
    half = np.sin(0.5 * q) ** 2
    # s >= 0: L sinc(a)/2 over cos a - cos q = -2 sin((a+q)/2) sin((a-q)/2)
    trig_den = -2.0 * np.sin(0.5 * (a + q)) * np.sin(0.5 * (a - q))
    # s < 0: sinh a/(cosh a - cos q) = (1 - e^{-2a}) / ((1 - e^{-a})^2 + 4 e^{-a} sin^2(q/2))
    safe = np.where(a == 0.0, 1.0, a)
    one_minus = np.where(a == 0.0, 1.0, -np.expm1(-2.0 * safe) / (2.0 * safe))
    hyp_den = np.expm1(-a) ** 2 + 4.0 * np.exp(-a) * half
    with np.errstate(divide="ignore", invalid="ignore"):
        trig = 0.5 * span * np.sinc(a / np.pi) / trig_den
        hyp = span * one_minus / hyp_den
    return np.where(s >= 0.0, trig, hyp)


def timoshenko_receptance(passage: Passage, rail: TimoshenkoRail, omega: ArrayLike) -> np.ndarray:
    """eta_T(omega): eq. (3) for the Timoshenko rail, in closed form [m/N].

    The displacement of the rail above a sleeper per unit force of every
    sleeper, sleeper n's force delayed by nL/v (the module docstring's
    ``[N(s_1) S(s_1) - N(s_2) S(s_2)] / (kGA EI (s_1 - s_2))``).

    Parameters
    ----------
    passage : Passage
        Scalar-valued track and train (EI, rho S, L and v are read).
    rail : TimoshenkoRail
    omega : array_like
        Angular frequency [rad/s], any sign (eta_T is even in omega).

    Returns
    -------
    ndarray
        Real eta_T, same shape as `omega`; ``inf`` at its poles, where a free
        wave fits the sleepers' phase, ``cos(sqrt(s_i) L) = cos(omega L / v)``
        (omega = 0 among them).  It agrees with the lattice sum to ~1e-15
        from omega = 1e-6 rad/s up (the 1/q^2 part dominates both near 0).

    Examples
    --------
    >>> import numpy as np
    >>> passage, rail = Passage.paper(), TimoshenkoRail.uic60()
    >>> omega = np.array([500.0, 6000.0, 40000.0])
    >>> bool(np.allclose(timoshenko_receptance(passage, rail, omega),
    ...                  timoshenko_receptance_lattice_sum(passage, rail, omega), rtol=1e-9))
    True
    """
    omega = np.asarray(omega, dtype=float)
    ei, _, kga, rho_i, _, _ = _coefficients(passage, rail)
    span = passage.sleeper_spacing
    q = omega * span / passage.speed
    s1, s2 = timoshenko_wavenumbers_squared(passage, rail, omega)
    n1 = ei * s1 + kga - rho_i * omega**2
    n2 = ei * s2 + kga - rho_i * omega**2
    p1, p2 = _periodic_sum(s1, q, span), _periodic_sum(s2, q, span)
    pole = ~np.isfinite(p1) | ~np.isfinite(p2) | (s1 == s2)
    with np.errstate(invalid="ignore", divide="ignore"):
        eta = (n1 * p1 - n2 * p2) / (kga * ei * (s1 - s2))
    return np.where(pole, np.inf, eta)


def timoshenko_receptance_lattice_sum(passage: Passage, rail: TimoshenkoRail, omega: ArrayLike,
                                      terms: int = 20_000) -> np.ndarray:
    """eta_T by Poisson summation, (1/L) sum_j G^(kappa_j) (a check of the closed form) [m/N].

    kappa_j = (omega L/v + 2 pi j)/L, |j| <= `terms`.  G^ decays only like
    1/(kGA kappa^2), so the tail is added in two parts: ``sum_{|j|>J}
    1/(kGA kappa_j^2)`` by the midpoint rule, ``(L^2 / (2 pi kGA)) [1/(q + 2 pi
    (J + 1/2)) + 1/(2 pi (J + 1/2) - q)]`` (error O(J^-3)), and the rest, about
    1/(EI kappa^4), as ``2 L^4 / (3 J^3 (2 pi)^4 EI)``.  No partial fractions.

    Parameters
    ----------
    passage : Passage
        Scalar-valued track and train.
    rail : TimoshenkoRail
    omega : array_like
        Angular frequency [rad/s].
    terms : int
        J, the number of wavenumbers on each side.

    Returns
    -------
    ndarray
        eta_T [m/N], same shape as `omega`.
    """
    omega = np.asarray(omega, dtype=float)
    span = passage.sleeper_spacing
    kga = rail.shear_stiffness
    q = omega * span / passage.speed
    j = np.arange(-terms, terms + 1)
    kappa = (q[..., None] + 2.0 * np.pi * j) / span
    with np.errstate(divide="ignore"):
        total = np.sum(timoshenko_green_transform(passage, rail, kappa, omega[..., None]),
                       axis=-1)
    edge = 2.0 * np.pi * (terms + 0.5)
    shear_tail = span**2 / (2.0 * np.pi * kga) * (1.0 / (q + edge) + 1.0 / (edge - q))
    bending_tail = 2.0 * span**4 / (3.0 * terms**3 * (2.0 * np.pi) ** 4
                                    * passage.rail_bending_stiffness)
    return (total + shear_tail + bending_tail) / span


def pinned_pinned_frequency(passage: Passage, rail: TimoshenkoRail | None = None) -> float:
    """The pinned-pinned frequency of the rail between sleepers [Hz].

    The mode with a node at every sleeper (q = pi, half a wavelength per bay,
    kappa = pi/L): where eta of eq. (3) at q = pi is infinite.  Euler–Bernoulli
    (``rail=None``): ``(pi/L)^2 sqrt(EI / rho S) / (2 pi)``.  Timoshenko: the
    lower root in omega^2 of D(pi/L, omega) = 0, the first frequency of a simply
    supported Timoshenko beam of span L,

        omega^2 = 2 EI k^4 / (P + sqrt(P^2 - 4 C EI k^4)),  P = rho S + B k^2,  k = pi/L,

    (the form of the small root that stays exact as C = rho I rho S / kGA -> 0).

    Parameters
    ----------
    passage : Passage
        EI, rho S and the sleeper spacing L are read.
    rail : TimoshenkoRail, optional
        Shear stiffness and rotary inertia; None for the Euler–Bernoulli rail.

    Examples
    --------
    >>> passage = Passage.paper()
    >>> round(pinned_pinned_frequency(passage)), round(pinned_pinned_frequency(
    ...     passage, TimoshenkoRail.uic60()))
    (1414, 1065)
    """
    ei, rho_s, span = (passage.rail_bending_stiffness, passage.rail_linear_mass,
                       passage.sleeper_spacing)
    k2 = (np.pi / span) ** 2
    if rail is None:
        return float(k2 * np.sqrt(ei / rho_s) / (2.0 * np.pi))
    _, _, _, _, b, c = _coefficients(passage, rail)
    p = rho_s + b * k2
    omega2 = 2.0 * ei * k2 * k2 / (p + np.sqrt(p * p - 4.0 * c * ei * k2 * k2))
    return float(np.sqrt(omega2) / (2.0 * np.pi))
