"""The linearised equations about a periodic solution: Hill's matrix of eq. (17).

In the book's notation (chapter 11 and the notation table of chapter 1): a
periodic solution y(t) of eq. (17) is a travelling wave, sleeper j moves as
y(t - jL/v).  A small disturbance of it has the Floquet–Bloch form

    dy_j(t) = e^{lambda t} e^{i theta j} sum_n p_n e^{i n Omega (t - jL/v)},

with the Floquet exponent lambda, the Bloch phase theta per sleeper and
Omega = 2 pi v / H.  Harmonic n of the disturbance is then one complex
frequency, s_n = lambda + i n Omega, with the phase q = n Omega L / v - theta
from one sleeper to the next, and the rail answers it with the receptance of
eq. (3) continued to that complex frequency and phase (`complex_receptance`).
Eliminating the rail and the pad as in eqs. (4)-(8) leaves, for the sleeper,
the dynamic stiffness (the book's calligraphic S)

    S(s, q) = M s^2 + A(s) / (1 + A(s) eta(s, q)),     A(s) = k1 + eta1 s,

and linearising the foundation law f(w, w') about y adds the harmonics
M gamma_l, M nu_l of its tangent stiffness df/dw and damping df/dw' along y
(in the code below, K_l and C_l).  The disturbance exists where Hill's matrix

    H(lambda; theta)_{nn'} = delta_{nn'} S(s_n, q) + M gamma_{n-n'} + s_{n'} M nu_{n-n'},
    n, n' = -m..m,

is singular.  At lambda = 0, theta = 0 it is M times the Jacobian of eq. (17)
(`railtrack.equations.aft_jacobian`): s_n = i omega_n and q = omega_n L / v
are the paper's frequencies and phases.  `railtrack.solvers.floquet` finds
the exponents.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage

__all__ = ["complex_receptance", "condensed_stiffness", "tangent_toeplitz", "hill_matrix",
           "hill_derivative", "hill_matrix_slope", "bloch_phases"]

# eta(s, q) = L^3 [f1(a) + cos(q) f2(a)] / (4 EI G(a, q)) with a = k_b L,
# f1 = (sin a cosh a - sinh a cos a) / a^3 and f2 = (sinh a - sin a) / a^3:
# both are entire functions of a^4 = -rho S s^2 L^4 / EI, summed as series
# where the closed forms cancel (|a| small, including s -> 0).
_SERIES_TERMS = 12
_F1 = np.array([(-1) ** j * 4.0 ** (j + 1) / math.factorial(4 * j + 3)
                for j in range(_SERIES_TERMS)])
_F2 = np.array([2.0 / math.factorial(4 * j + 3) for j in range(_SERIES_TERMS)])
_SERIES_BELOW = 1.5
"""|a| under which f1 and f2 are summed as series (error < 1e-16 there)."""


def _polynomial(coefficients: np.ndarray, x: np.ndarray) -> np.ndarray:
    total = np.zeros_like(x)
    for c in coefficients[::-1]:
        total = total * x + c
    return total


def _bending_functions(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """f1(a), f2(a) of the receptance, by series for small |a|, closed form above."""
    large = np.abs(a) >= _SERIES_BELOW
    f1, f2 = np.empty_like(a), np.empty_like(a)
    # each form only where it is used: the Newton and contour loops call this often
    small = ~large
    if small.any():
        x = a[small] ** 4
        f1[small], f2[small] = _polynomial(_F1, x), _polynomial(_F2, x)
    if large.any():
        b = a[large]
        sin, cos, sinh, cosh = np.sin(b), np.cos(b), np.sinh(b), np.cosh(b)
        f1[large] = (sin * cosh - sinh * cos) / b**3
        f2[large] = (sinh - sin) / b**3
    return f1, f2


def _receptance_parts(passage: Passage, s: np.ndarray, q: np.ndarray):
    """N = f1 + cos(q) f2 and G = (cos a - cos q)(cosh a - cos q), both entire in s."""
    ratio = passage.rail_linear_mass / passage.rail_bending_stiffness
    a = np.sqrt(np.sqrt(-ratio * s * s + 0j)) * passage.sleeper_spacing  # any fourth root will do
    f1, f2 = _bending_functions(a)
    # differences of cosines as products of sines: no cancellation at small a or q;
    # sin(x +- y) expanded so that the functions of a (of s alone) are taken once
    # for every phase q broadcast against them
    half_a, half_q = 0.5 * a, 0.5 * q
    sin_a, cos_a, sin_q, cos_q = np.sin(half_a), np.cos(half_a), np.sin(half_q), np.cos(half_q)
    cos_gap = -2.0 * (sin_a * cos_q + cos_a * sin_q) * (sin_a * cos_q - cos_a * sin_q)
    cosh_gap = 2.0 * (np.sinh(half_a) ** 2 + sin_q**2)
    return f1 + np.cos(q) * f2, cos_gap * cosh_gap


def complex_receptance(passage: Passage, s: ArrayLike, q: ArrayLike) -> np.ndarray:
    """eta(s, q): eq. (3) at complex frequency s and phase q per sleeper [m/N].

    The rail's displacement above sleeper 0 when sleeper n pushes it with
    ``e^{s t} e^{-i n q}``: the closed form of eq. (3),

        eta = [sin a/(cos a - cos q) - sinh a/(cosh a - cos q)] / (4 k_b^3 EI),

    with ``k_b^4 = -rho S s^2 / EI`` and ``a = k_b L``.  At s = i omega and
    q = omega L / v it is the paper's eta_E(omega).  It depends on k_b only
    through k_b^4, so any fourth root serves.

    Parameters
    ----------
    passage : Passage
    s : array_like
        Complex frequency [1/s].
    q : array_like
        Phase from one sleeper to the next [rad], real.

    Returns
    -------
    ndarray
        Complex eta, broadcast of `s` and `q`; infinite at the free waves of
        the rail, where cos a = cos q.

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack.equations.receptance import rail_receptance
    >>> passage = Passage.paper()
    >>> omega = np.array([50.0, 500.0])
    >>> q = omega * passage.sleeper_spacing / passage.speed
    >>> np.allclose(complex_receptance(passage, 1j * omega, q), rail_receptance(passage, omega))
    True
    """
    s, q = np.asarray(s, dtype=complex), np.asarray(q, dtype=float)
    parts, gaps = _receptance_parts(passage, s, q)
    with np.errstate(divide="ignore", invalid="ignore"):
        return passage.sleeper_spacing**3 * parts / (4.0 * passage.rail_bending_stiffness * gaps)


def condensed_stiffness(passage: Passage, s: ArrayLike, q: ArrayLike) -> np.ndarray:
    """S(s, q) = M s^2 + A / (1 + A eta(s, q)): the sleeper with rail and pad condensed [N/m].

    The force on a sleeper per unit displacement e^{s t} of every sleeper,
    with phase q from one to the next, the foundation left out; written as
    ``M s^2 + 4 EI G A / (4 EI G + A L^3 N)`` (see `complex_receptance`),
    which is finite at the free waves of the rail.  At s = i omega_n,
    q = omega_n L / v it is M times the sleeper operator of eq. (17).

    Examples
    --------
    >>> from railtrack.equations.sleeper import rail_coupling, sleeper_operator
    >>> passage = Passage.paper()
    >>> omega = 300.0
    >>> d = condensed_stiffness(passage, 1j * omega, omega * passage.sleeper_spacing / passage.speed)
    >>> operator = sleeper_operator(passage, omega) - rail_coupling(passage, omega)
    >>> bool(np.isclose(d, passage.sleeper_mass * operator))
    True
    """
    s, q = np.asarray(s, dtype=complex), np.asarray(q, dtype=float)
    parts, gaps = _receptance_parts(passage, s, q)
    pad = passage.pad_stiffness + passage.pad_damping * s
    bending = 4.0 * passage.rail_bending_stiffness * gaps
    return passage.sleeper_mass * s**2 + bending * pad / (
        bending + pad * passage.sleeper_spacing**3 * parts)


def bloch_phases(passage: Passage, theta: float = 0.0) -> np.ndarray:
    """The phases theta + 2 pi j L / H, j = 0..H/L - 1, that one Hill matrix stands for [rad].

    The shift lambda -> lambda + i Omega of an exponent is the shift
    theta -> theta + 2 pi L / H of its Bloch phase, so the exponents at
    phase theta with any imaginary part are those of these phases with
    |Im lambda| <= Omega / 2.  H / L must be an integer.
    """
    sleepers = float(passage.wagon_length) / float(passage.sleeper_spacing)
    count = int(round(sleepers))
    if count < 1 or abs(sleepers - count) > 1e-9 * max(1.0, sleepers):
        raise ValueError(
            "Floquet multipliers need a whole number of sleepers per wagon, H/L an integer; "
            f"got H/L = {sleepers!r} (H = {float(passage.wagon_length)!r} m, "
            f"L = {float(passage.sleeper_spacing)!r} m)")
    return np.mod(theta + 2.0 * np.pi * np.arange(count) / count, 2.0 * np.pi)


def tangent_toeplitz(stiffness: np.ndarray, damping: np.ndarray) -> np.ndarray:
    """The matrices K_{k-j} and C_{k-j}, k, j = -m..m, stacked: shape (2, 2m+1, 2m+1).

    Parameters
    ----------
    stiffness, damping : ndarray, shape (4m+1,)
        K_l and C_l, l = -2m..2m: the harmonics of df/dw [N/m] and df/dw'
        [N s/m] along the solution (`railtrack.equations.aft_jacobian.tangent_harmonics`).
    """
    m = (np.size(stiffness) - 1) // 4
    k = np.arange(-m, m + 1)
    lag = (k[:, None] - k[None, :]) + 2 * m
    return np.stack([np.asarray(stiffness)[lag], np.asarray(damping)[lag]])


def hill_matrix(passage: Passage, toeplitz: np.ndarray, exponent: ArrayLike,
                theta: float) -> np.ndarray:
    """Hill's matrix H(lambda; theta) of the disturbances of a periodic solution [N/m].

    Parameters
    ----------
    passage : Passage
        Scalar-valued track and train.
    toeplitz : ndarray, shape (2, 2m+1, 2m+1)
        K_{k-j} and C_{k-j} (`tangent_toeplitz`).
    exponent : array_like
        lambda [1/s], complex; leading axes give a stack of matrices.
    theta : float or array_like
        Bloch phase per sleeper [rad]; an array broadcasts with `exponent`.

    Returns
    -------
    ndarray, shape broadcast(exponent, theta).shape + (2m+1, 2m+1)
        Rows and columns k, j = -m..m.
    """
    m = (toeplitz.shape[-1] - 1) // 2
    k = np.arange(-m, m + 1)
    omega = passage.fundamental_frequency
    s = np.asarray(exponent, dtype=complex)[..., None] + 1j * omega * k
    q = k * omega * passage.sleeper_spacing / passage.speed - np.asarray(theta)[..., None]
    # S(s, q) of s and q unbroadcast: the rail's bending functions depend on s alone,
    # shared by all the phases of a contour's stack
    stiffness = condensed_stiffness(passage, s, q)
    shape = np.broadcast_shapes(s.shape, q.shape)
    matrix = np.broadcast_to(s, shape)[..., None, :] * toeplitz[1]
    matrix += toeplitz[0]
    diagonal = np.arange(2 * m + 1)
    matrix[..., diagonal, diagonal] += stiffness
    return matrix


def hill_derivative(passage: Passage, toeplitz: np.ndarray, exponent: ArrayLike,
                    theta: ArrayLike, vector: np.ndarray, step: float = 1e-6) -> np.ndarray:
    """dH/dlambda times vectors [N s/m]: C_{k-j} exactly, D'(s_k, q_k) by a central difference.

    `exponent` and `theta` of shape (r,) and `vector` of shape (r, 2m+1)
    give r products.  D is analytic in s, so the difference of width
    `step` (relative to 1 + |s_k|) has an error of order step^2.
    """
    return _slope(passage, toeplitz, exponent, theta, step)[1] * vector + vector @ toeplitz[1].T


def hill_matrix_slope(passage: Passage, toeplitz: np.ndarray, exponent: ArrayLike,
                      theta: ArrayLike, step: float = 1e-6) -> tuple[np.ndarray, np.ndarray]:
    """Hill's matrix and dD/ds on its diagonal, from one evaluation of D at s and s +- h.

    For Newton's method, which needs both at each step (`hill_matrix`,
    `hill_derivative`): `exponent` and `theta` of shape (r,) give r matrices,
    shape (r, 2m+1, 2m+1) [N/m], and r diagonals, shape (r, 2m+1) [N s/m].
    """
    stiffness, slope = _slope(passage, toeplitz, exponent, theta, step)
    m = (toeplitz.shape[-1] - 1) // 2
    s = np.asarray(exponent, dtype=complex)[..., None] + 1j * passage.fundamental_frequency * \
        np.arange(-m, m + 1)
    matrix = s[..., None, :] * toeplitz[1]
    matrix += toeplitz[0]
    diagonal = np.arange(2 * m + 1)
    matrix[..., diagonal, diagonal] += stiffness
    return matrix, slope


def _slope(passage: Passage, toeplitz: np.ndarray, exponent: ArrayLike, theta: ArrayLike,
           step: float) -> tuple[np.ndarray, np.ndarray]:
    """D(s_k, q_k) and its central difference in s, from one call at s, s + h and s - h."""
    m = (toeplitz.shape[-1] - 1) // 2
    k = np.arange(-m, m + 1)
    omega = passage.fundamental_frequency
    s = np.asarray(exponent, dtype=complex)[..., None] + 1j * omega * k
    q = k * omega * passage.sleeper_spacing / passage.speed - np.asarray(theta)[..., None]
    h = step * (1.0 + np.abs(s))
    values = condensed_stiffness(passage, np.stack([s, s + h, s - h]), q)
    return values[0], (values[1] - values[2]) / (2 * h)
