"""Section 2.2: the dynamics of a sleeper coupled to the rail, eqs. (4)–(8) and (14).

A sleeper of mass M sits under a pad (k1, eta1) and on the foundation
f(w, w').  Its equation of motion (eq. 4) is

    M w'' + eta1 w' + k1 w + f(w, w') = eta1 w_r'(0, t) + k1 w_r(0, t).

Eliminating the rail with eq. (3) gives eq. (8).  For a periodic response
w = sum c_n exp(i omega_n t) the rail's feedback on harmonic n is P_n c_n
(eq. 14/16).  This module holds the frequency-domain pieces: the pad's
dynamic stiffness A, the transfer Gamma of eq. (6), the coupling P of
eq. (16), the sleeper operator on the left of eq. (17) and the rail
displacement of eq. (6).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .receptance import bending_wavenumber, receptance_factors
from ..model.passage import Passage

__all__ = [
    "pad_stiffness",
    "load_transfer",
    "rail_coupling",
    "coupling_and_transfer",
    "sleeper_operator",
    "rail_coefficients",
]


def pad_stiffness(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """Dynamic stiffness of the rail pad, A(omega) = k1 + i omega eta1 (after eq. 5) [N/m]."""
    omega = np.asarray(omega, dtype=float)
    return passage.pad_stiffness + 1j * omega * passage.pad_damping


def _pad_rail_denominator(passage: Passage, omega: np.ndarray):
    """Factors of eq. (3) and the finite form of 1 + A eta_E (times eta_E's denominator)."""
    factors = receptance_factors(passage, omega)
    stiffness = pad_stiffness(passage, omega)
    combined = factors.denominator + stiffness * factors.numerator
    if not np.all(np.isfinite(combined)) or np.any(combined == 0):
        raise ValueError(_why_no_denominator(passage, omega, combined))
    return factors, stiffness, combined


def _why_no_denominator(passage: Passage, omega: np.ndarray, combined: np.ndarray) -> str:
    """The cause of a non-finite or zero 1 + A eta_E, in words, with the numbers."""
    omega = np.broadcast_to(omega, combined.shape)
    overflow = ~np.isfinite(combined)
    where = float(np.abs(omega[overflow if overflow.any() else combined == 0]).max())
    if overflow.any():
        reach = float(bending_wavenumber(passage, where)) * float(passage.sleeper_spacing)
        return (
            f"eq. (3) overflows at |omega| = {where:.4g} rad/s: k_b L = (rho S omega^2 / EI)^(1/4) "
            f"L = {reach:.3g}, whose powers exceed double precision (rail_bending_stiffness "
            f"EI = {float(passage.rail_bending_stiffness):.3g} N m^2, rail_linear_mass "
            f"rho S = {float(passage.rail_linear_mass):.3g} kg/m, sleeper_spacing "
            f"L = {float(passage.sleeper_spacing):.3g} m): check these inputs and their units"
        )
    if float(passage.pad_damping) == 0.0:
        return (
            f"1 + A(omega) eta_E(omega) vanishes at |omega| = {where:.4g} rad/s: the undamped "
            "track is exactly at resonance at this frequency; give pad_damping > 0"
        )
    return (
        f"1 + A(omega) eta_E(omega) vanishes at |omega| = {where:.4g} rad/s although "
        f"pad_damping = {float(passage.pad_damping):.3g} N s/m: the numerator and the "
        "denominator of eq. (3) are both zero there, exactly; change the speed or the "
        "track slightly"
    )


def load_transfer(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """Gamma(omega) = 1 / {(1 + A eta_E) [(omega/v)^4 - k_b^4]}, eq. (6) [m^4].

    Computed as ``4 EI L gap / (denominator + A numerator)`` from the
    factors of `railtrack.equations.receptance.receptance_factors`, which is finite at
    omega = 0 (value ``EI L / k1``) and where ``omega / v = k_b``, where both
    brackets of the printed formula are singular.
    """
    omega = np.asarray(omega, dtype=float)
    factors, _, combined = _pad_rail_denominator(passage, omega)
    return (
        4.0 * passage.rail_bending_stiffness * passage.sleeper_spacing * factors.gap / combined
    )


def rail_coupling(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """Rail–sleeper coupling P(omega) = A^2 eta_E / (M (1 + A eta_E)), eq. (16) [1/s^2].

    P_n = P(omega_n) is how strongly harmonic n of the sleeper's motion is fed
    back to it through the pad and the rail (which carries it to all the other
    sleepers).  At omega = 0 it equals k1 / M exactly.

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Angular frequency [rad/s].

    Returns
    -------
    ndarray
        Complex P, same shape as `omega`; ``P(-omega) = conj(P(omega))``.

    Examples
    --------
    >>> passage = Passage.paper()
    >>> float(rail_coupling(passage, 0.0).real) == passage.pad_stiffness / passage.sleeper_mass
    True
    """
    omega = np.asarray(omega, dtype=float)
    factors, stiffness, combined = _pad_rail_denominator(passage, omega)
    return stiffness**2 * factors.numerator / (passage.sleeper_mass * combined)


def coupling_and_transfer(passage: Passage, omega: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """`rail_coupling` and `load_transfer` together, sharing the work of eq. (3)."""
    omega = np.asarray(omega, dtype=float)
    factors, stiffness, combined = _pad_rail_denominator(passage, omega)
    coupling = stiffness**2 * factors.numerator / (passage.sleeper_mass * combined)
    transfer = (
        4.0 * passage.rail_bending_stiffness * passage.sleeper_spacing * factors.gap / combined
    )
    return coupling, transfer


def sleeper_operator(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """omega_0^2 + i beta omega - omega^2, the sleeper's own terms in eq. (17) [1/s^2].

    The Fourier transform of ``w'' + beta w' + omega_0^2 w`` divided by w.
    """
    omega = np.asarray(omega, dtype=float)
    return (
        passage.pad_natural_frequency_squared
        + 1j * passage.pad_damping_rate * omega
        - omega**2
    )


def rail_coefficients(
    passage: Passage, omega: ArrayLike, sleeper: ArrayLike, load: ArrayLike
) -> np.ndarray:
    """Fourier coefficients of the rail displacement above the sleeper, eq. (6) [m].

    For harmonic n, eq. (6) with the train load of eq. (10) reads
    ``r_n = (A eta_E/(1 + A eta_E)) c_n - Gamma Q (1 + e^{-i omega_n D/v}) / (H EI)``,
    which by eq. (16) is the compact ``r_n = M (P_n c_n - F_n) / A(omega_n)``:
    the pad force ``A (r_n - c_n)`` is what the rail gives the sleeper.

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Harmonic frequencies omega_n [rad/s].
    sleeper : array_like
        Sleeper coefficients c_n [m], same shape as `omega`.
    load : array_like
        Load coefficients F_n [m/s^2] (`railtrack.model.train.load_coefficients`).

    Returns
    -------
    ndarray
        Complex r_n [m].
    """
    omega = np.asarray(omega, dtype=float)
    coupling = rail_coupling(passage, omega)
    return (
        passage.sleeper_mass
        * (coupling * np.asarray(sleeper) - np.asarray(load))
        / pad_stiffness(passage, omega)
    )
