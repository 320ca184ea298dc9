"""The rail anywhere along a cell of N sleepers: displacement and curvature (issue 19).

For a harmonic omega_n > 0 the rail at x (0 <= x < Lambda = NL) carries the
cell's sleeper forces and the moving train,

    r_n(x) = -sum_j eta(x - jL) p_{j,n} + m_n(x),

with eta the Floquet sum over the cells of `railtrack.equations.cell_receptance`
at any offset 0 <= d <= Lambda (and ``eta(d) = e^{i theta} eta(d + Lambda)``
for d < 0), p_{j,n} the force the pad passes down to sleeper j, and
``m_n(x) = m_n(0) e^{-i omega_n x/v}`` the free rail under the train
(`cell_moving_load`).  Its curvature takes, for 0 <= d <= Lambda,

    4 EI k eta''(d) = -[sin k(Lambda-d) + e^{-i theta} sin kd] / (cos k Lambda - cos theta)
                      - [sinh k(Lambda-d) + e^{-i theta} sinh kd] / (cosh k Lambda - cos theta).

At omega = 0 both terms are infinite (a rigid translation of the rail is
free); there the rail is a beam of period Lambda under the uniform mean load
of the train and the point forces p_{j,0}, which balance, so

    r_0(x) = C + sum_j p_{j,0} Lambda^3 B4((x - jL)/Lambda) / (24 EI),

B4(u) = u^4 - 2u^3 + u^2 - 1/30 (the periodic Green function of
EI w'''' = delta, ``sum_{r != 0} e^{2 pi i r u}/(2 pi r)^4 = -B4(u)/24``), and C is set by
the rail above sleeper 0, ``r_0(0) = c_{0,0} + p_{0,0}/k1_0`` (the pad).  Beyond
the cell, ``r_n(x + Lambda) = e^{-i theta_n} r_n(x)``.  Where a free wave of
the rail fits the cell's phase (cos k Lambda = cos theta, a measure-zero set
of omega > 0) the two terms cancel: the coefficients are then computed with
that cancellation and lose digits in proportion.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from .cell_receptance import cell_moving_load, floquet_parts
from .positions import check_positions
from .receptance import bending_wavenumber

__all__ = ["cell_offset_receptance", "cell_rail_field_coefficients"]


def cell_offset_receptance(passage: Passage, omega: ArrayLike, sleepers: int, d: ArrayLike,
                           derivative: int = 0) -> np.ndarray:
    """eta(d) or eta''(d) of the module docstring for 0 <= d <= NL and omega > 0 [m/N], [1/(N m)].

    Parameters
    ----------
    passage : Passage
    omega : array_like, shape (W,)
        omega > 0 [rad/s].
    sleepers : int
        N >= 1.
    d : array_like, shape (X,)
        Offsets in [0, NL] [m].
    derivative : {0, 2}

    Returns
    -------
    ndarray, shape (X, W)

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack.equations.cell_receptance import cell_receptance
    >>> passage = Passage.paper()
    >>> eta = cell_offset_receptance(passage, [50.0], 3, [0.0, 0.6, 1.2])[:, 0]
    >>> bool(np.allclose(eta, cell_receptance(passage, np.array([50.0]), 3)[0, :, 0]))
    True
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    d = np.atleast_1d(np.asarray(d, dtype=float))[:, None]
    cell = sleepers * passage.sleeper_spacing
    if np.any(omega <= 0) or np.any((d < 0) | (d > cell * (1 + 1e-12))):
        raise ValueError("cell_offset_receptance needs omega > 0 and 0 <= d <= NL")
    if derivative not in (0, 2):
        raise ValueError(f"derivative must be 0 or 2; got {derivative!r}")
    k = bending_wavenumber(passage, omega)
    trig, hyp, _, _ = floquet_parts(k, omega * cell / passage.speed, cell, d)
    ei = passage.rail_bending_stiffness
    if derivative == 0:
        return (trig - hyp) / (4.0 * ei * k**3)
    return -(trig + hyp) / (4.0 * ei * k)


def _bernoulli4(u, derivative):
    if derivative == 0:
        return u**4 - 2 * u**3 + u**2 - 1.0 / 30.0
    return 12 * u**2 - 12 * u + 2.0


def _kernel_sums(k, theta, span: float, seat_force: np.ndarray) -> np.ndarray:
    """sum_j w(d_j) q_j for the four d-shapes of the kernel, per sleeper j0 behind x.

    With x between sleepers j0 and j0 + 1 (s = x - j0 L in [0, L]), sleeper
    j = j0 - r (mod N) is d = s + rL behind x, wrapped with e^{i theta} when
    j0 - r < 0.  Its kernel is a combination of cos kd, sin kd, e^{-kd} and
    e^{-k(Lambda-d)}, each a product of a factor of s and one of r (every
    factor <= 1: nothing overflows).  Returns the sums over r of the r
    factors (cos krL, sin krL, e^{-krL}, e^{-k(N-1-r)L}) times the twisted
    seat forces, shape (4, N, W): index j0.
    """
    n = seat_force.shape[0]
    r = np.arange(n)[:, None] * span * k                                  # (N, W) krL
    shapes = np.stack([np.cos(r), np.sin(r), np.exp(-r), np.exp(r - (n - 1) * span * k)])
    twist = np.exp(1j * theta)
    sums = np.empty((4, n, k.size), dtype=complex)
    for j0 in range(n):
        source = (j0 - np.arange(n)) % n                                  # sleeper j of each r
        q = seat_force[source] * np.where((np.arange(n) > j0)[:, None], twist, 1.0)
        sums[:, j0] = np.einsum("arw,rw->aw", shapes, q)
    return sums


def cell_rail_field_coefficients(passage: Passage, omega: ArrayLike, sleeper: np.ndarray,
                                 seat_force: np.ndarray, pad, x: ArrayLike, *,
                                 derivatives: tuple[int, ...] = (0, 2)):
    """Fourier coefficients of the rail's displacement and curvature at x along the cell.

    Parameters
    ----------
    passage : Passage
    omega : array_like, shape (W,)
        omega_n >= 0 [rad/s]; omega = 0 at most once (the mean).
    sleeper : ndarray, shape (N, W)
        c_{j,n} [m].
    seat_force : ndarray, shape (N, W)
        p_{j,n} = M_j s^2 c_{j,n} + F_{j,n} [N], the force the sleeper passes to
        its inertia and foundation (minus the rail-seat load): negative when
        the rail pushes the sleeper down.
    pad : ndarray, shape (N,)
        k1_j [N/m], for the rail above sleeper 0 at omega = 0.
    x : array_like, shape (X,)
        Positions from sleeper 0 in the direction of travel [m], finite and
        within the bound of `railtrack.equations.positions.check_positions`.
    derivatives : tuple of {0, 2}
        Which to return: 0 the displacement, 2 the curvature.

    Returns
    -------
    tuple of ndarray, shape (X, W) each
        Complex coefficients of w_r(x, t) [m] and/or of its x-curvature [1/m],
        in the order of `derivatives`.

    Raises
    ------
    ValueError
        For x so far that round-off leaves the phases no digits (`check_positions`).

    Notes
    -----
    The sum over the cell's sleepers, ``-sum_j eta(x - jL) p_{j,n}``, is
    separated (`_kernel_sums`) into N sums per harmonic, made once, and a few
    factors per x: the work and memory grow like X W, not X N W.
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    if any(d not in (0, 2) for d in derivatives):
        raise ValueError(f"derivatives must hold 0 and/or 2; got {derivatives!r}")
    n = sleeper.shape[0]
    span, cell = passage.sleeper_spacing, n * passage.sleeper_spacing
    x = np.atleast_1d(np.asarray(x, dtype=float))
    check_positions(passage, omega, x)
    wraps = np.floor(x / cell)
    inside = np.clip(x - wraps * cell, 0.0, cell)
    behind = np.minimum(np.floor(inside / span), n - 1).astype(int)         # j0
    s = np.clip(inside - behind * span, 0.0, span)[:, None]
    theta = omega * cell / passage.speed
    out = {d: np.zeros((x.size, omega.size), dtype=complex) for d in derivatives}
    moving = omega > 0
    if np.any(moving):
        w, phase = omega[moving], theta[moving]
        k = bending_wavenumber(passage, w)
        cos_, sin_, near, far = (a[behind] for a in _kernel_sums(k, phase, span,
                                                                seat_force[:, moving]))
        ks = s * k
        back, kc = np.exp(-1j * phase), k * cell
        trig_den = -2.0 * np.sin(0.5 * (kc + phase)) * np.sin(0.5 * (kc - phase))
        hyp_den = np.expm1(-kc) ** 2 + 4.0 * np.exp(-kc) * np.sin(0.5 * phase) ** 2
        cos_s, sin_s = np.cos(ks), np.sin(ks)
        cos_d = cos_s * cos_ - sin_s * sin_
        sin_d = sin_s * cos_ + cos_s * sin_
        trig = (np.sin(kc) * cos_d + (back - np.cos(kc)) * sin_d) / trig_den
        hyp = (-np.expm1(-kc - 1j * phase) * np.exp(-ks) * near
               + (np.expm1(-1j * phase) - np.expm1(-kc)) * np.exp(-(span - s) * k) * far
               ) / hyp_den
        load = cell_moving_load(passage, w, 1)[:, 0] * np.exp(-1j * inside[:, None] * w
                                                               / passage.speed)
        ei = passage.rail_bending_stiffness
        if 0 in out:
            out[0][:, moving] = load - (trig - hyp) / (4.0 * ei * k**3)
        if 2 in out:
            out[2][:, moving] = (trig + hyp) / (4.0 * ei * k) - (w / passage.speed) ** 2 * load
    rest = np.flatnonzero(omega == 0)
    if rest.size:
        p0 = seat_force[:, rest[0]].real
        ei = passage.rail_bending_stiffness
        offsets = inside[:, None] - np.arange(n) * span                      # (X, N)
        u = (offsets + (offsets < 0) * cell) / cell
        if 0 in out:
            at_zero = (np.arange(n) * -span) % cell / cell
            above = sleeper[0, rest[0]].real + p0[0] / pad[0]
            out[0][:, rest[0]] = cell**3 / (24 * ei) * (
                _bernoulli4(u, 0) - _bernoulli4(at_zero, 0)) @ p0 + above
        if 2 in out:
            out[2][:, rest[0]] = (cell / (24 * ei)) * _bernoulli4(u, 2) @ p0
    bloch = np.exp(-1j * np.outer(wraps, theta))
    return tuple(bloch * out[d] for d in derivatives)
