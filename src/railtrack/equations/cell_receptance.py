"""The receptance matrix of a repeating cell of N sleepers (issue 19), eq. (3) generalised.

The rail (EI, rho S) rests on sleepers at x_j = jL.  The track repeats every N
sleepers, Lambda = N L, and sleeper j + pN acts as sleeper j delayed by
pNL/v.  For a harmonic omega, sleeper j' + pN pushes the rail upward with
``R_j' e^{i omega (t - p Lambda / v)}``, and the rail above sleeper j moves by
``sum_j' eta_jj'(omega) R_j'`` with the Floquet sum over the cells

    eta_jj' = eta((j - j') L),   eta(d) = sum_p G(d - p Lambda) e^{-i theta p},

theta = omega Lambda / v, G the free beam's Green function
(``EI G'''' - rho S omega^2 G = delta``, ``G(x) = -(sin k_b|x| + e^{-k_b|x|}) /
(4 EI k_b^3)`` in the principal-value sense of eq. 3).  By Poisson's formula

    eta(d) = (1/(EI Lambda)) sum_r e^{-i kappa_r d} / (kappa_r^4 - k_b^4),
    kappa_r = (theta + 2 pi r) / Lambda

(the convention of `railtrack.equations.rail_field.offset_receptance`).
Summing the geometric series of each exponential of G over p gives, for
0 <= d <= Lambda, with k = k_b,

    4 EI k^3 eta(d) = [sin k(Lambda-d) + e^{-i theta} sin kd] / (cos k Lambda - cos theta)
                    - [sinh k(Lambda-d) + e^{-i theta} sinh kd] / (cosh k Lambda - cos theta),

and ``eta(d + Lambda) = e^{-i theta} eta(d)``: so ``eta_jj' = eta((j-j')L)``
for j >= j' and ``e^{i theta} eta((j - j' + N) L)`` for j < j'.  N = 1 and
d = 0 is eq. (3).  The matrix is Toeplitz and "theta-circulant", Hermitian for
real omega, and ``eta_j'j(omega) = eta_jj'(-omega)`` (reciprocity).

It is diagonalised by the cell's Floquet vectors ``v_s(j) = e^{-i phi_s j}``,
``phi_s = (theta + 2 pi s)/N = omega L/v + 2 pi s/N``, s = 0..N-1:
``eta v_s = lambda_s v_s``, where lambda_s is eq. (3) with q replaced by phi_s
(`railtrack.equations.cell_receptance_modes`).  Only lambda_0 = eta_E is infinite at omega = 0;
the train's load enters mode 0 alone (`cell_moving_load`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from .load import axle_factor
from .receptance import bending_wavenumber

__all__ = [
    "cell_moving_load",
    "cell_receptance",
    "cell_receptance_lattice_sum",
    "floquet_parts",
]


def _check_sleepers(sleepers: int) -> int:
    """N as a positive int, or a ValueError naming the value."""
    if isinstance(sleepers, bool) or int(sleepers) != sleepers or sleepers < 1:
        raise ValueError(f"sleepers (the cell's sleeper count N) must be an integer >= 1; "
                         f"got {sleepers!r}")
    return int(sleepers)


def _assemble(h: np.ndarray, theta: np.ndarray, n: int) -> np.ndarray:
    """eta_jj' from h[..., m] = eta(mL), m = 0..N-1, and the twist e^{i theta}."""
    j = np.arange(n)
    m = j[:, None] - j[None, :]
    twist = np.where(m < 0, np.exp(1j * theta)[..., None, None], 1.0)
    return h[..., m % n] * twist


def floquet_parts(k, theta, cell: float, d):
    """The two bracketed ratios of the closed form, 0 <= d <= Lambda (module docstring).

    ``trig = [sin k(Lambda-d) + e^{-i theta} sin kd] / (cos k Lambda - cos theta)`` and
    ``hyp`` the same with sinh, cosh, both scaled by 2 e^{-k Lambda} in numerator and
    denominator so that nothing overflows; ``4 EI k^3 eta(d) = trig - hyp``.  Also
    returns the two denominators (zero where eta is infinite).  Arguments broadcast.
    """
    back = np.exp(-1j * theta)
    kc = k * cell
    trig_den = -2.0 * np.sin(0.5 * (kc + theta)) * np.sin(0.5 * (kc - theta))
    hyp_den = np.expm1(-kc) ** 2 + 4.0 * np.exp(-kc) * np.sin(0.5 * theta) ** 2
    trig = (np.sin(k * (cell - d)) + back * np.sin(k * d)) / trig_den
    hyp = (-np.exp(-k * d) * np.expm1(-2.0 * k * (cell - d))
           - back * np.exp(-k * (cell - d)) * np.expm1(-2.0 * k * d)) / hyp_den
    return trig, hyp, trig_den, hyp_den


def cell_receptance(passage: Passage, omega: ArrayLike, sleepers: int) -> np.ndarray:
    """Receptance matrix eta_jj'(omega) of a cell of N sleepers, closed form [m/N].

    ``w_r(x_j, omega) = sum_j' eta_jj' R_j'`` (plus the moving-load term,
    `cell_moving_load`), with the formula of the module docstring (eq. 3 for
    N = 1).  The hyperbolic part is evaluated as its geometric series
    ``[e^{-kd}(1 - e^{-2k(Lambda-d)}) + e^{-i theta} e^{-k(Lambda-d)}(1 - e^{-2kd})]
    / [(1 - e^{-k Lambda})^2 + 4 e^{-k Lambda} sin^2(theta/2)]``, which never
    overflows, and ``cos k Lambda - cos theta`` as a product of sines.

    Parameters
    ----------
    passage : Passage
        Scalar-valued track and train (EI, rho S, L, v are used).
    omega : array_like
        Angular frequency [rad/s], any sign, any shape (...).
    sleepers : int
        N >= 1, the number of sleepers in the repeating cell.

    Returns
    -------
    ndarray, shape (..., N, N)
        Complex eta_jj' [m/N].  Singular where a free bending wave of the rail
        fits the cell's phase, ``cos(k_b N L) = cos(omega N L / v)`` (omega = 0
        among them); there, and only there, the entries are ``inf``.  Near
        omega = 0 every entry is dominated by ``eta_E e^{-i omega (j-j') L/v}/N``;
        use `cell_receptance_modes` for the finite parts.

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack.equations.receptance import rail_receptance
    >>> passage = Passage.paper()
    >>> omega = np.array([50.0, 500.0])
    >>> bool(np.allclose(cell_receptance(passage, omega, 1)[:, 0, 0],
    ...                  rail_receptance(passage, omega), rtol=1e-12))
    True
    >>> bool(np.allclose(cell_receptance(passage, omega, 3),
    ...                  cell_receptance_lattice_sum(passage, omega, 3), rtol=1e-8))
    True
    """
    n = _check_sleepers(sleepers)
    omega = np.asarray(omega, dtype=float)
    cell = n * passage.sleeper_spacing
    k = bending_wavenumber(passage, omega)[..., None]
    theta = omega * cell / passage.speed
    th = theta[..., None]
    d = np.arange(n) * passage.sleeper_spacing
    with np.errstate(divide="ignore", invalid="ignore"):
        trig, hyp, trig_den, hyp_den = floquet_parts(k, th, cell, d)
        h = (trig - hyp) / (4.0 * passage.rail_bending_stiffness * k**3)
    singular = ((trig_den == 0.0) | (hyp_den == 0.0) | (k == 0.0))[..., 0]
    out = _assemble(np.where(singular[..., None], 0.0, h), theta, n)
    out[singular] = np.inf
    return out


def cell_receptance_lattice_sum(passage: Passage, omega: ArrayLike, sleepers: int,
                                terms: int = 20_000) -> np.ndarray:
    """eta_jj' by the Poisson sum over kappa_r, entry by entry (a check of `cell_receptance`).

    ``eta_jj' = (1/(EI N L)) sum_{|r| <= terms} e^{-i kappa_r (j-j') L} / (kappa_r^4 - k_b^4)``,
    ``kappa_r = (omega N L / v + 2 pi r) / (N L)``, with no closed form and no
    use of the twist; the tail ``sum_{|r| > terms} (N L / 2 pi r)^4`` is added
    on the diagonal (off it the tail oscillates and is below 1e-13 relative).

    Parameters
    ----------
    passage : Passage
    omega : array_like, shape (W,)
        Angular frequency [rad/s].
    sleepers : int
        N >= 1.
    terms : int
        Wavenumbers on each side.

    Returns
    -------
    ndarray, shape (W, N, N)
        Complex eta_jj' [m/N].
    """
    n = _check_sleepers(sleepers)
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    cell = n * passage.sleeper_spacing
    r = np.arange(-terms, terms + 1)
    kappa = (omega[:, None] * cell / passage.speed + 2.0 * np.pi * r) / cell     # (W, R)
    weight = 1.0 / (kappa**4 - bending_wavenumber(passage, omega)[:, None] ** 4)
    out = np.empty((omega.size, n, n), dtype=complex)
    for m in range(-(n - 1), n):
        value = np.sum(weight * np.exp(-1j * kappa * m * passage.sleeper_spacing), axis=-1)
        if m == 0:
            value = value + 2.0 / (3.0 * terms**3) * (cell / (2.0 * np.pi)) ** 4
        for j in range(max(0, m), min(n, n + m)):
            out[:, j, j - m] = value
    return out / (passage.rail_bending_stiffness * cell)


def cell_moving_load(passage: Passage, omega: ArrayLike, sleepers: int) -> np.ndarray:
    """Fourier coefficients of the free rail's displacement at x_j = jL under the train [m].

    The rail_field convention (and eq. 6): at x = 0 the coefficient of
    harmonic omega_n is ``-sum_k Q_k e^{-i omega d_k/v} / (H EI [(omega/v)^4 - k_b^4])``
    (the same as ``-Gamma (1 + A eta_E) sum_k Q_k e^{-i omega d_k/v} / (H EI)``
    in `railtrack.equations.sleeper.rail_coefficients`); at x_j it is delayed
    by jL/v, a factor ``e^{-i omega j L/v}``: the load is the Floquet mode 0.

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Harmonic frequencies omega_n [rad/s], shape (...).
    sleepers : int
        N >= 1.

    Returns
    -------
    ndarray, shape (..., N)
        Complex [m], w positive upward.  Infinite at omega = 0 and where
        omega/v = k_b, like mode 0 of `cell_receptance_modes`: multiply both by
        ``(q^4 - a^4)`` (q = omega L/v, a = k_b L) to combine them finitely.

    Examples
    --------
    >>> import numpy as np
    >>> passage = Passage.paper()
    >>> w = cell_moving_load(passage, 100.0, 2)
    >>> bool(np.isclose(w[1], w[0] * np.exp(-1j * 100.0 * 0.6 / 45.0)))
    True
    """
    n = _check_sleepers(sleepers)
    omega = np.asarray(omega, dtype=float)
    quartic = (omega / passage.speed) ** 4 - bending_wavenumber(passage, omega) ** 4
    with np.errstate(divide="ignore", invalid="ignore"):
        origin = -axle_factor(passage, omega) / (
            passage.wagon_length * passage.rail_bending_stiffness * quartic)
    delay = np.exp(-1j * omega[..., None] * np.arange(n) * passage.sleeper_spacing
                   / passage.speed)
    out = np.where(quartic[..., None] == 0.0, 0.0, origin[..., None]) * delay
    out[quartic == 0.0] = -np.inf
    return out
