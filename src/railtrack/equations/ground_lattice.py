"""The ground under every sleeper in one harmonic: a lattice sum over wavenumbers, like eq. (3).

**Sleepers as one Bloch wave.**  Sleeper j sits at x_j = j L and, in the
steady state, repeats sleeper 0 with the delay j L / v (the paper's
periodic condition, eq. 2).  Its force on the ground, f_j(t) = f(t - j L / v)
with f = sum_n f_n e^{i omega_n t} (eq. 12's convention, f positive upward
as w; the sleeper pushes the ground with +f), has harmonic n

    f_{j,n} = f_n e^{-i j q_n},   q_n = omega_n L / v  (the phase of eq. 3).

**Lattice sum.**  The ground's compliance C(k, omega) is defined for a line
load e^{i(k x - omega t)} (`railtrack.model.ground_protocol`).  The real force's part
at e^{-i omega_n t} is conj(f_n) e^{+i j q_n}; spread uniformly over the
footprint |x - x_j| < a/2 it is, by Poisson's summation formula,

    sum_j e^{i j q} p(x - j L) = (1/L) sum_m sinc(kappa_m a/2) e^{i kappa_m x},
    kappa_m = (q + 2 pi m) / L,   sinc(z) = sin(z) / z,

a sum of waves e^{i(kappa_m x - omega t)}; kappa_0 = omega / v travels with
the train.  These are the rail's wavenumbers in eq. (3)
(`railtrack.equations.receptance.rail_receptance_lattice_sum`); there the
kernel 1 / (EI (kappa^4 - k_b^4)) is real and even, so no conjugate shows.  The ground answers each with C(kappa_m, omega), and the
displacement averaged over sleeper 0's footprint (another factor sinc) is
conj(f_n) S(omega_n), with

    S(omega) = (1/L) sum_m C(kappa_m, omega) sinc^2(kappa_m a / 2).

In eq. (12)'s convention (e^{+i omega_n t}) the ground under sleeper 0 thus
moves by

    u_n = R_g(omega_n) f_n,   R_g(omega) = conj S(omega)   [m/N].       (G1)

For C = c independent of k, Poisson's formula backwards gives
sum_m sinc^2(kappa_m a/2) = L / a for any q when a <= L (the footprint's
autocorrelation, width 2a, sees no neighbour), so R_g = conj(c) / a: the
Winkler limit, a spring a / c per sleeper.

**The tail.**  sinc^2 falls like k^-2 and a half-space's C like k^-1, so
the terms fall like |m|^-3 and a plain truncation at |m| <= M misses
O(M^-2).  On each side the two outermost terms fix a far field
C ~ C_inf + A / |k|.  The constant C_inf (mean of the two sides) is summed
exactly with the identity above, L/a minus the kept sinc^2; the A / |k| part
beyond M with sin^2 replaced by its mean 1/2, giving A / (2 pi a^2 k_M'^2)
per side with k_M' = |q +- 2 pi (M + 1/2)| / L.  What is left is O(M^-3) or
smaller for the grounds above (`lattice_sum` returns its estimate, the
change of the corrected sum from M/2 to M).

How R_g enters the harmonic balance, eq. (G2): `railtrack.equations.ground_balance`.
"""

from __future__ import annotations

import numpy as np

from ..model.ground_protocol import check_ground

__all__ = ["TERMS", "TAIL_TERMS", "lattice_sum", "lattice_sums", "ground_receptance"]

TERMS = 64
"""Wavenumbers kept on each side of the lattice sum (m = -M..M): R_g to about 1e-7."""
TAIL_TERMS = 16
"""M for the harmonics above m that only the truncation estimate uses: R_g to about 1e-5."""


def lattice_sum(compliance, omega: float, q: float, spacing: float, footprint: float,
                terms: int = TERMS) -> tuple[complex, float]:
    """S(omega) = (1/L) sum_m C(kappa_m, omega) sinc^2(kappa_m a/2) with its tail [m/N].

    Parameters
    ----------
    compliance : callable
        C(kx [rad/m], omega [rad/s]) [m^2/N], convention e^{i(k x - omega t)}.
    omega : float
        Frequency [rad/s].
    q : float
        Phase between neighbouring sleepers, omega L / v [rad]; S is 2 pi-periodic in q.
    spacing, footprint : float
        L and a [m], 0 < a <= L.
    terms : int
        M >= 4, wavenumbers kept on each side.

    Returns
    -------
    value : complex
        S, with the far-field tail of the module docstring added.
    error : float
        |S_M - S_{M/2}|, both tail-corrected: an estimate of the error [m/N].

    Examples
    --------
    >>> value, error = lattice_sum(lambda k, w: np.full(k.shape, 2e-9 + 0j), 100.0, 1.0,
    ...                            0.6, 0.25)
    >>> round(value.real / 8e-9, 12), error < 1e-20     # C / a, the Winkler limit
    (1.0, True)
    """
    value, error = lattice_sums(compliance, np.array([omega]), np.array([q]), spacing,
                                footprint, terms)
    return complex(value[0]), float(error[0])


def lattice_sums(compliance, omega: np.ndarray, q: np.ndarray, spacing: float,
                 footprint: float, terms: int = TERMS,
                 power: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """`lattice_sum` for several (omega, q) at once, shapes (H,): one compliance call each.

    ``power=1`` weighs C by one sinc(kappa_m a/2), not two: the displacement
    at the point x = 0 rather than averaged over the footprint (the ground
    beside the track, `railtrack.equations.ground_beside`).  The constant
    C_inf is summed exactly as for two (sum_m sinc(kappa_m a/2) = L/a, the
    footprint's pressure at its centre, for a < 2L); the A/|k| tail, whose
    terms change sign with sin(kappa_m a/2), is left out (it is within one
    term's size, O(M^-2)).

    Examples
    --------
    >>> values, errors = lattice_sums(lambda k, w: 1 / (1e8 + 1e7 * k**2 - 1j * w * 1e5),
    ...                               np.array([0.0, 500.0]), np.array([0.0, 2.0]), 0.6, 0.25)
    >>> values.shape, bool(np.all(errors < 1e-6 * np.abs(values)))
    ((2,), True)
    """
    if isinstance(terms, bool) or not isinstance(terms, (int, np.integer)) or terms < 4:
        raise ValueError(f"terms must be an integer >= 4; got {terms!r}")
    if power not in (1, 2):
        raise ValueError(f"power must be 1 (a point) or 2 (the footprint); got {power!r}")
    # S is 2 pi-periodic in q (relabel m): centre the window of kept wavenumbers on k = 0,
    # where C is largest, whatever the harmonic's phase q_n = 2 pi n L / H
    q = np.remainder(np.asarray(q, dtype=float) + np.pi, 2 * np.pi) - np.pi
    kappa = (q[:, None] + 2 * np.pi * np.arange(-terms, terms + 1)) / spacing
    values = np.empty(kappa.shape, dtype=complex)
    for row, (w, k) in enumerate(zip(np.asarray(omega, dtype=float), kappa)):
        returned = np.asarray(compliance(k, float(w)), dtype=complex)
        if returned.shape != k.shape:
            raise ValueError(f"ground.compliance(kx, omega) must return an array shaped like "
                             f"kx, {k.shape}; got shape {returned.shape}")
        if not np.all(np.isfinite(returned)):
            bad = int(np.flatnonzero(~np.isfinite(returned))[0])
            raise ValueError(
                f"ground.compliance is not finite at kx = {k[bad]:.6g} rad/m, omega = "
                f"{w:.6g} rad/s (a ground without a rigid base settles without bound "
                "under the infinite train's mean load at kx = 0, omega = 0)")
        values[row] = returned
    weights = np.sinc(kappa * footprint / (2 * np.pi)) ** power   # np.sinc(x) = sin(pi x)/(pi x)
    full = _corrected(kappa, values, weights, q, spacing, footprint, terms, terms, power)
    half = _corrected(kappa, values, weights, q, spacing, footprint, terms, terms // 2, power)
    return full, np.abs(full - half)


def _corrected(kappa, values, weights, q, spacing, a, terms, kept, power=2):
    """The sum over |m| <= kept plus the far-field tail fitted on its two outermost terms
    (for ``power=1`` the constant's only)."""
    inside = slice(terms - kept, terms + kept + 1)
    kept_sum = np.sum(values[:, inside] * weights[:, inside], axis=-1) / spacing
    far, amplitude = [], []
    for outer, inner in ((terms + kept, terms + kept - 1), (terms - kept, terms - kept + 1)):
        k2, k1 = np.abs(kappa[:, outer]), np.abs(kappa[:, inner])
        slope = (values[:, inner] - values[:, outer]) / (1 / k1 - 1 / k2)
        far.append(values[:, outer] - slope / k2)
        amplitude.append(slope)
    constant = 0.5 * (far[0] + far[1])
    tail = constant * (1 / a - np.sum(weights[:, inside], axis=-1) / spacing)
    for side, slope in zip((1, -1), amplitude if power == 2 else ()):
        edge = np.abs(q + side * 2 * np.pi * (kept + 0.5)) / spacing
        tail = tail + slope / (2 * np.pi * a**2 * edge**2)
    return kept_sum + tail


def ground_receptance(ground, omega: np.ndarray, speed: float, spacing: float,
                      terms: int = TERMS) -> np.ndarray:
    """R_g(omega_n) of eq. (G1): the ground's displacement under a sleeper per its force [m/N].

    Parameters
    ----------
    ground : GroundCompliance
        `railtrack.model.ground_protocol.GroundCompliance`, e.g.
        `railtrack.model.ground_protocol.WinklerGround`.
    omega : ndarray
        omega_n >= 0 [rad/s]; omega_0 = 0 is the mean.
    speed : float
        v [m/s].
    spacing : float
        L [m].
    terms : int or ndarray of int
        M, wavenumbers kept on each side (`lattice_sum`), or one M per omega.

    Returns
    -------
    ndarray, complex, shaped like omega
        In eq. (12)'s convention: u_n = R_g,n f_n.

    Raises
    ------
    ValueError
        A compliance that is not finite, or whose static value (omega = 0) is not real.

    Examples
    --------
    >>> from railtrack.model.ground_protocol import WinklerGround
    >>> r = ground_receptance(WinklerGround(1e8, 0.25, damping=1e5), np.array([0.0, 50.0]),
    ...                       50.0, 0.6)
    >>> np.allclose(1 / r, 0.25 * (1e8 + 1j * np.array([0.0, 50.0]) * 1e5))   # a (s + i w eta)
    True
    """
    check_ground(ground, spacing)
    omega = np.asarray(omega, dtype=float)
    flat, terms = omega.ravel(), np.broadcast_to(terms, omega.shape).ravel()
    sums = np.empty(flat.shape, dtype=complex)
    for count in np.unique(terms):
        these = terms == count
        sums[these] = lattice_sums(ground.compliance, flat[these], flat[these] * spacing / speed,
                                   spacing, float(ground.footprint), int(count))[0]
    sums = sums.reshape(omega.shape)
    static = omega == 0
    if np.any(np.abs(sums[static].imag) > 1e-9 * np.abs(sums[static])):
        raise ValueError("the ground's static compliance summed over the sleepers is not real "
                         f"({sums[static][0]!r} m/N): C(-k, 0) must be conj C(k, 0)")
    sums[static] = sums[static].real
    return np.conj(sums)
