"""The rail anywhere along a span: eq. (3) with an offset x.

The rail carries the sleeper reactions R(t - nL/v) at x = nL and the
moving wheel loads (eq. 2).  In the frequency domain (``f^(omega) =
int f(t) exp(-i omega t) dt``, as in eqs. 3 and 13) its displacement at x is

    w_r(x, omega) = R(omega) S(x, omega) - sum_j Q_j e^{-i omega D_j/v} e^{-i omega x/v}
                    / (v EI [(omega/v)^4 - k_b^4]),

with the offset lattice sum (Poisson summation, as for eq. 3)

    S(x, omega) = sum_n G(x - nL) e^{-i omega n L/v}
                = (1/(EI L)) sum_j e^{-i kappa_j x} / (kappa_j^4 - k_b^4),
    kappa_j = omega/v + 2 pi j/L.

The moving-load term is the x = 0 term delayed by x/v, a factor
``e^{-i omega x/v}``.  For 0 <= x <= L, with a = k_b L, q = omega L/v and
mu = 1/2 - x/L, partial fractions over the four roots of kappa^4 = k_b^4 give

    S = L^3 e^{-iq/2} / (2 a^3 EI) * {
          [cos(a mu) sin(a/2) cos(q/2) + i sin(a mu) cos(a/2) sin(q/2)] / (cos a - cos q)
        - [cosh(a mu) sinh(a/2) cos(q/2) + i sinh(a mu) cosh(a/2) sin(q/2)] / (cosh a - cos q) },

which is eq. (3) at x = 0; beyond a span ``S(x + L) = e^{-iq} S(x)``.  The
rail's response is then written as ``e^{-iq x/L} r_n(0)`` plus the reaction
times ``S(x) - e^{-iq x/L} S(0)``: the j = 0 wavenumber, which makes S
infinite at omega = 0 and at omega/v = k_b, cancels exactly in the
difference, so every coefficient here is finite there (`difference_kernels`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .lattice_tail import lattice_kernels
from .positions import MAX_PHASE_ROUNDOFF, check_positions
from .receptance import _sech, _sinc, _tanhc, bending_wavenumber, receptance_factors
from .sleeper import pad_stiffness, rail_coefficients
from ..model.passage import Passage
from .load import axle_factor, load_coefficients

__all__ = [
    "offset_receptance",
    "offset_receptance_lattice_sum",
    "difference_kernels",
    "rail_field_coefficients",
    "seat_load_coefficients",
    "MAX_PHASE_ROUNDOFF",
    "check_positions",
]

_SWITCH = 4.0     # |q^4 - a^4| below which the near-singular branch (lattice_tail) is used


def _expm1c(y):
    """(e^y - 1)/y with the value 1 at 0."""
    safe = np.where(y == 0, 1.0, y)
    return np.where(y == 0, 1.0, np.expm1(safe) / safe)


def _split(passage: Passage, x: ArrayLike):
    """x = k L + xi L with integer k and 0 <= xi < 1."""
    x = np.asarray(x, dtype=float)
    k = np.floor(x / passage.sleeper_spacing)
    return k, np.clip(x / passage.sleeper_spacing - k, 0.0, 1.0)


def _parts(passage: Passage, omega: np.ndarray, xi: np.ndarray):
    """a, q (signed), q^4 - a^4, gap, U and V for S = (U - V)/denominator, shape (X, W)."""
    span = passage.sleeper_spacing
    a = bending_wavenumber(passage, omega) * span
    q = omega * span / passage.speed
    r = np.sqrt(np.abs(omega)) * (
        passage.rail_bending_stiffness / passage.rail_linear_mass) ** 0.25 / passage.speed
    aq = np.abs(q)
    cos_gap = 0.5 * _sinc(0.5 * (a + aq)) * _sinc(0.5 * (a - aq))
    cosh_gap = (0.5 * _tanhc(0.5 * a) * _tanhc(a)
                + 0.5 * r**2 * _sinc(0.5 * aq) ** 2 * _sech(a)) / (1.0 + r**2)
    mu = 0.5 - np.asarray(xi, dtype=float)[:, None]
    m = np.abs(mu)
    phase = np.exp(-0.5j * q)
    # e^{-iq/2} [cos(a mu) sin(a/2) cos(q/2) + i sin(a mu) cos(a/2) sin(q/2)] / a
    trig = phase * (np.cos(a * mu) * np.cos(0.5 * q) * 0.5 * _sinc(0.5 * a)
                    + 1j * mu * _sinc(a * mu) * np.cos(0.5 * a) * np.sin(0.5 * q))
    # the same with cosh, sinh, divided by cosh a without overflow
    damp = 1.0 + np.exp(-2.0 * a)
    hyp = phase * (
        0.5 * (np.exp(a * (m - 0.5)) + np.exp(-a * (m + 0.5))) * _expm1c(-a) / damp
        * np.cos(0.5 * q)
        + 1j * mu * np.exp(-a * (m + 0.5)) * _expm1c(2.0 * a * m) * (1.0 + np.exp(-a)) / damp
        * np.sin(0.5 * q))
    u = 2.0 * trig * (1.0 + r**2) * cosh_gap
    v = 2.0 * hyp * (r**2 - 1.0) * cos_gap
    return a, q, q**4 - a**4, cos_gap * cosh_gap, u, v


def offset_receptance(passage: Passage, omega: ArrayLike, x: ArrayLike,
                      derivative: int = 0) -> np.ndarray:
    """S(x, omega), the closed form of the offset lattice sum, or d^2 S/dx^2 [m/N], [1/(N m)].

    Parameters
    ----------
    passage : Passage
    omega : array_like, shape (W,)
        Angular frequency [rad/s].
    x : array_like, shape (X,)
        Offset from the observed sleeper, towards +x [m], any real value.
    derivative : {0, 2}
        0 for S, 2 for its curvature ``sum_j -kappa_j^2 e^{-i kappa_j x} / (EI L (...))``.

    Returns
    -------
    ndarray, shape (X, W)
        Complex; infinite where eq. (3) is (omega = 0, cos k_b L = cos q).

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack.equations.receptance import rail_receptance
    >>> passage = Passage.paper()
    >>> omega = np.array([50.0, 500.0])
    >>> bool(np.allclose(offset_receptance(passage, omega, [0.0])[0],
    ...                  rail_receptance(passage, omega), rtol=1e-12))
    True
    >>> bool(np.allclose(offset_receptance(passage, omega, [0.2, 0.9]),
    ...                  offset_receptance_lattice_sum(passage, omega, [0.2, 0.9]), rtol=1e-8))
    True
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    k, xi = _split(passage, np.atleast_1d(x))
    a, q, _, _, u, v = _parts(passage, omega, xi)
    top = u - v if derivative == 0 else -(a**2) * (u + v) / passage.sleeper_spacing**2
    with np.errstate(divide="ignore", invalid="ignore"):
        value = top / receptance_factors(passage, omega).denominator
    return value * np.exp(-1j * q * k[:, None])


def offset_receptance_lattice_sum(passage: Passage, omega: ArrayLike, x: ArrayLike,
                                  derivative: int = 0, terms: int = 20_000) -> np.ndarray:
    """S(x, omega) or its curvature by the brute-force Poisson sum over kappa_j (a check).

    Sums ``(1/(EI L)) sum_{|j| <= terms} (-kappa_j^2)^(derivative/2) e^{-i kappa_j x}
    / (kappa_j^4 - k_b^4)``, kappa_j = omega/v + 2 pi j/L, with no closed form;
    the terms fall like j^-4 (j^-2 for the curvature).  Same shapes as
    `offset_receptance`.
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    x = np.atleast_1d(np.asarray(x, dtype=float))
    kappa = (omega[:, None] / passage.speed
             + 2.0 * np.pi * np.arange(-terms, terms + 1) / passage.sleeper_spacing)
    kb4 = (bending_wavenumber(passage, omega) ** 4)[:, None]
    weight = (-(kappa**2)) ** (derivative // 2) / (kappa**4 - kb4)
    out = np.empty((x.size, omega.size), dtype=complex)
    for i, xx in enumerate(x):
        out[i] = np.sum(weight * np.exp(-1j * kappa * xx), axis=-1)
    return out / (passage.rail_bending_stiffness * passage.sleeper_spacing)


def difference_kernels(passage: Passage, omega: ArrayLike, xi: ArrayLike):
    """Lambda and Lambda_2, the finite kernels of the rail between sleepers [-].

    With the denominator ``4 EI gap (q^4 - a^4) / L^3`` of eq. (3)
    (`railtrack.equations.receptance.receptance_factors`):

        S(x) - e^{-iq xi} S(0)          = L^3 Lambda   / (4 EI gap),
        S''(x) + (q/L)^2 e^{-iq xi} S(0) = L   Lambda_2 / (4 EI gap),

    xi = x/L in [0, 1].  The j = 0 wavenumber cancels from both, so they are
    finite at omega = 0 and where omega/v = k_b.  Evaluated from the closed
    form when ``|q^4 - a^4| >= 4`` (no cancellation), otherwise as
    ``4 gap e^{-iq xi} sum_{j != 0}`` with the analytic tail
    (`railtrack.equations.lattice_tail`); both agree with the brute-force sum to ~1e-12.

    Returns
    -------
    (ndarray, ndarray), each shape (X, W), complex.
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    xi = np.atleast_1d(np.asarray(xi, dtype=float))
    a, q, quartic, gap, u, v = _parts(passage, omega, xi)
    _, _, _, _, u0, v0 = _parts(passage, omega, np.zeros(1))
    shift = np.exp(-1j * q * xi[:, None])
    near = np.abs(quartic) < _SWITCH
    with np.errstate(divide="ignore", invalid="ignore"):
        lam = np.where(near, 0.0, (u - v - shift * (u0 - v0)) / quartic)
        lam2 = np.where(near, 0.0, (-(a**2) * (u + v) + q**2 * shift * (u0 - v0)) / quartic)
    if np.any(near):
        first, second = lattice_kernels(q[near], a[near], xi)
        lam[:, near] = 4.0 * gap[near] * shift[:, near] * first
        lam2[:, near] = 4.0 * gap[near] * shift[:, near] * second
    return lam, lam2


def _reaction_factor(passage: Passage, omega: np.ndarray, sleeper: np.ndarray) -> np.ndarray:
    """G = A [c (q^4 - a^4) + (sum_j Q_j e^{-i omega d_j/v}) L^4 / (H EI)]
    / (denominator + A numerator)."""
    span, ei = passage.sleeper_spacing, passage.rail_bending_stiffness
    factors = receptance_factors(passage, omega)
    stiffness = pad_stiffness(passage, omega)
    quartic = (omega * span / passage.speed) ** 4 - (bending_wavenumber(passage, omega) * span) ** 4
    load = axle_factor(passage, omega) * span**4 / (passage.wagon_length * ei)
    return stiffness * (sleeper * quartic + load) / (
        factors.denominator + stiffness * factors.numerator)


def seat_load_coefficients(passage: Passage, omega: ArrayLike, sleeper: ArrayLike) -> np.ndarray:
    """Fourier coefficients of the rail-seat load R = A (c_n - r_n), eq. (5) [N].

    R is the pad's push on the rail, upward, which is the pad's compression
    force on the sleeper.  Computed as ``4 EI gap G / L^3`` (see
    `_reaction_factor`), finite at the poles of eq. (3); R_0 = 2 Q L / H.
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    gap = receptance_factors(passage, omega).gap
    return (4.0 * passage.rail_bending_stiffness * gap / passage.sleeper_spacing**3
            * _reaction_factor(passage, omega, np.asarray(sleeper)))


def rail_field_coefficients(passage: Passage, omega: ArrayLike, sleeper: ArrayLike,
                            x: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Fourier coefficients of the rail's displacement and curvature at x [m], [1/m].

    ``r_n(x) = e^{-i q_n x/L} r_n(0) + G_n Lambda(x)`` and
    ``r''_n(x) = -(q_n/L)^2 e^{-i q_n x/L} r_n(0) + G_n Lambda_2(x) / L^2`` for
    0 <= x <= L (eq. 6 for r_n(0), `difference_kernels` for Lambda), and
    ``r_n(x + kL) = e^{-i k q_n} r_n(x)``, i.e. w_r(x + kL, t) = w_r(x, t - kL/v).

    Parameters
    ----------
    passage : Passage
    omega : array_like, shape (W,)
        Harmonic frequencies omega_n [rad/s].
    sleeper : array_like, shape (W,)
        Sleeper coefficients c_n [m].
    x : array_like, shape (X,)
        Offsets towards +x (the direction of travel) from the observed sleeper [m].

    Returns
    -------
    (ndarray, ndarray), shape (X, W) each
        Complex coefficients of w_r(x, t) [m] and of d^2 w_r / dx^2 [1/m].

    Raises
    ------
    ValueError
        For positions so far that round-off swamps the phases (`check_positions`).
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    sleeper = np.asarray(sleeper)
    check_positions(passage, omega, x)
    k, xi = _split(passage, np.atleast_1d(x))
    q = omega * passage.sleeper_spacing / passage.speed
    above = rail_coefficients(passage, omega, sleeper, load_coefficients(passage, omega))
    # Positions a whole number of spans apart share their kernels: evaluate
    # each offset within the span once (to 1e-12 of a span).
    rounded = np.round(xi / passage.sleeper_spacing, 12)
    _, first, inverse = np.unique(rounded, return_index=True, return_inverse=True)
    lam, lam2 = (kernel[inverse.ravel()]
                 for kernel in difference_kernels(passage, omega, xi[first]))
    factor = _reaction_factor(passage, omega, sleeper)
    shift = np.exp(-1j * q * xi[:, None])
    bloch = np.exp(-1j * q * k[:, None])
    displacement = shift * above + factor * lam
    curvature = -((q / passage.sleeper_spacing) ** 2) * shift * above + (
        factor * lam2 / passage.sleeper_spacing**2)
    return bloch * displacement, bloch * curvature
