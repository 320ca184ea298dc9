"""Eq. (G2): the ground's lattice sum R_g (`railtrack.equations.ground_lattice`) in eq. (17).

The law acts on the relative displacement
d = w - u: f = f(d, d').  With u_n = R_g,n M G_n(d) (G_n the harmonics of
f / M, eq. 20), eq. (17) for the sleeper, operator_n w_n + G_n + F_n = 0,
becomes in the unknowns d_n

    operator_n d_n + (1 + M R_g,n operator_n) G_n(d) + F_n = 0,        (G2)

that is eq. (17) again with operator_n and F_n divided by the factor
phi_n = 1 + M R_g,n operator_n (`grounded_coefficients`).  phi_0 = 1, since
the pad and the rail carry no static load of their own (operator_0 = 0).
"""

from __future__ import annotations

import numpy as np

from .ground_lattice import TAIL_TERMS, TERMS, ground_receptance

__all__ = ["grounded_coefficients", "on_ground"]


def grounded_coefficients(operator: np.ndarray, load: np.ndarray, receptance: np.ndarray,
                          mass: float) -> tuple[np.ndarray, np.ndarray]:
    """operator_n / phi_n and F_n / phi_n of eq. (G2), phi_n = 1 + M R_g,n operator_n.

    Parameters
    ----------
    operator : ndarray
        omega_0^2 + i beta omega_n - omega_n^2 - P_n of eq. (17) [1/s^2].
    load : ndarray
        F_n of eq. (16) [m/s^2].
    receptance : ndarray
        R_g,n [m/N] (`ground_receptance`).
    mass : float
        M, the sleeper's mass [kg].

    Examples
    --------
    >>> grounded_coefficients(np.array([0.0, -2.0]), np.array([1.0, 1.0]),
    ...                       np.array([1.0, 0.25]), 2.0)[1]     # phi = 1, 0
    Traceback (most recent call last):
    ...
    ValueError: the factor 1 + M R_g operator of eq. (G2) vanishes at harmonic n = 1: the sleeper on the rail resonates on the ground alone; change m or the speed slightly
    """
    factor = 1.0 + mass * receptance * operator
    if not np.all(np.isfinite(factor)) or np.any(factor == 0):
        n = int(np.flatnonzero(~np.isfinite(factor) | (factor == 0))[0])
        raise ValueError(
            f"the factor 1 + M R_g operator of eq. (G2) vanishes at harmonic n = {n}: the "
            "sleeper on the rail resonates on the ground alone; change m or the speed slightly")
    return operator / factor, load / factor


def on_ground(passage, omega: np.ndarray, operator: np.ndarray, load: np.ndarray, ground,
              exact: int | None = None):
    """(operator, load, R_g) of eq. (G2) for harmonics omega; unchanged and None without ground.

    Harmonics n <= `exact` (default: all) take `TERMS` wavenumbers a side, the
    rest, which only estimate the truncation error, `TAIL_TERMS`.

    Examples
    --------
    >>> from railtrack import Track, Train, Passage
    >>> from railtrack.model.ground_protocol import WinklerGround
    >>> passage = Passage(Track.paper(), Train.paper())
    >>> op, f, r = on_ground(passage, np.array([0.0]), np.zeros(1), np.ones(1),
    ...                      WinklerGround(1e8, 0.25))
    >>> float(op[0].real), float(f[0].real), round(float(r[0].real) * 0.25e8, 12)   # R_g = 1 / (a s)
    (0.0, 1.0, 1.0)
    """
    if ground is None:
        return operator, load, None
    n = np.arange(len(omega))
    terms = np.where(n <= (n[-1] if exact is None else exact), TERMS, TAIL_TERMS)
    receptance = ground_receptance(ground, omega, float(passage.speed),
                                   float(passage.sleeper_spacing), terms)
    operator, load = grounded_coefficients(operator, load, receptance,
                                           float(passage.sleeper_mass))
    return operator, load, receptance
