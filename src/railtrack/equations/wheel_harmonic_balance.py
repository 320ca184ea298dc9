"""Harmonic balance with wheels on Hertz springs: the residual (issue 20, first version).

The cell of N sleepers (`railtrack.equations.cell_harmonic_balance`) now
carries, instead of constant forces Q_k, the contact forces P_k(t) of the
wheels of `railtrack.model.wheel` (every wagon's wheel k alike).  With
Lambda = NL and G = H / Lambda a whole number (the wheels then meet the
cell's pattern G times a wagon period), P_k has harmonics p = G l only.

Unknowns: c_{j,n} (n = 0..m), P_{k,p} (p = G, 2G, .. <= m; P_{k,0} = Q_k, the
wheel's mean balance with an infinitely soft suspension) and each wheel's
mean height relative to the rail under it, y_k (below).

* Sleepers, harmonic n: ``R_n = K1_n c_n + K2_n p_n - g_n - W_n P``, g_n of
  `cell_operators` (the wheels' means) and, for each p != 0 (two-sided),
  ``W_n P = sum_k F[:, s] (-4 sqrt(N) (L/H) gap(a_n, Q) e^{i kappa_{p-n} d_k} P_{k,p})``,
  the free rail under the wheels' force harmonic p read at the sleepers and
  multiplied by the Floquet mode's denominator: s = -p/G (mod N),
  kappa_r = 2 pi r / H, Q = kappa_{p-n} L, and
  ``gap(a, Q) = (cos a - cos Q)(cosh a - cos Q) / ((Q^4 - a^4) cosh a)``, finite
  where Q = +-a.  For p = 0 it is g_n itself.
* Contacts, harmonic p = 0, G, 2G, ..: ``B_{k,p} = [C_H max(delta_k, 0)^{3/2}]_p - P_{k,p}``
  (B_{k,0} uses Q_k), delta_k = u_k + r(vt - d_k) - z_k by AFT, with
  the rail under the wheel u_k from the sleepers' reactions R = -p,
  ``sum_n sum_j' R_{j',n} e^{i kappa (d_k + x_j')} / (EI Lambda (kappa^4 - k_n^4))``,
  kappa = omega_n/v + 2 pi r/Lambda at wheel harmonic p = -r G, and from the
  wheels, ``sum_k' U_p(d_k' - d_k) (-P_{k',p})``
  (`railtrack.equations.wheel_train_receptance`), and the wheels
  ``z_p = A(omega_p) P_p`` (`railtrack.equations.wheel_receptance`: -1 / (m_w omega_p^2)
  for a `Wheel`, the suspension coupling a `Vehicle`'s four).  The mean p = 0 of the rail under the
  wheel contains the rail's rigid lift, infinite in each part and finite in
  their sum; it is left out, and y_k = z_k0 - u_k0 takes its place: delta is exact.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..model.passage import Passage
from ..model.profile_sum import felt_profile
from .cell_harmonic_balance import _forces, _synthesize, cell_operators
from .receptance import bending_wavenumber
from .wheel_receptance import wheel_receptance
from .wheel_train_receptance import wheel_train_receptance

__all__ = ["WheelSystem", "wheel_system", "wheel_residual", "wheel_loads", "rail_under_wheels",
           "compression", "profile_harmonics", "contact_gap", "wheels_under"]


def contact_gap(a: np.ndarray, q: np.ndarray) -> np.ndarray:
    """gap(a, Q) = (cos a - cos Q)(cosh a - cos Q) / ((Q^4 - a^4) cosh a), stably [-]."""
    cos_gap = 0.5 * np.sinc(0.5 * (a + q) / np.pi) * np.sinc(0.5 * (a - q) / np.pi)
    both = np.asarray(q**2 + a**2, dtype=float)
    safe = np.where(both == 0.0, 1.0, both)
    cosh_gap = np.where(both == 0.0, 0.5, 2.0 * (np.sinh(0.5 * a) ** 2 + np.sin(0.5 * q) ** 2)
                        / (safe * np.cosh(a)))
    return cos_gap * cosh_gap


class WheelSystem(NamedTuple):
    """The fixed matrices of `wheel_residual`; see `wheel_system`."""

    ops: object            # CellOperators at omega_n, n = 0..m
    grid: np.ndarray       # wheel harmonics p = G l, l = 1..lmax
    load_mode: np.ndarray  # (2 lmax,): the Floquet mode s = -p/G mod N that p = +grid, -grid loads
    load_gap: np.ndarray   # (m+1, 2 lmax): -4 sqrt(N) (L/H) gap(a_n, kappa_{p-n} L)
    wheel_phase: np.ndarray  # (2 lmax, K): e^{2 pi i p d_k / H}, p = +grid, -grid
    sleeper_shift: np.ndarray  # (m+1, K): e^{-2 pi i n d_k / H}, n = 0..m
    mode_basis: np.ndarray   # (m+1, N_j, N_s): e^{-i j (omega_n L/v + 2 pi s/N)} / sqrt(N)
    under_weight: np.ndarray   # (lmax, 2m+1): 1 / (EI Lambda (kappa^4 - k_n^4)), n = -m..m
    harmonic_phase: np.ndarray  # (2m+1, K): e^{2 pi i n d_k / H}, n = -m..m
    sleeper_phase: np.ndarray  # (2m+1, N): e^{i omega_n x_j / v}
    mode_of_wheel: np.ndarray  # (lmax,): r_l = p_l / G mod N
    between_wheels: np.ndarray  # (lmax, K, K): U_p(d_k' - d_k)
    wheel_receptance: np.ndarray  # (lmax, K, K): z_p = A P_p, A = -1/(m_w omega_p^2) for a Wheel
    samples: int
    sleeper_weight: np.ndarray  # (N,) [N], M_j g


def wheel_system(passage: Passage, cell, wheel, harmonics: int, samples: int) -> WheelSystem:
    """The linear parts of the residual for a cell, a wheel and m harmonics."""
    n_sl, m = cell.sleepers, int(harmonics)
    span, wagon, v = passage.sleeper_spacing, float(passage.wagon_length), float(passage.speed)
    cell_length = n_sl * span
    ratio = wagon / cell_length
    groups = int(round(ratio))
    if abs(ratio - groups) > 1e-9 or groups < 1:
        raise ValueError(f"the wagon length H = {wagon} m must be a whole number of cells "
                         f"(N L = {cell_length} m) for a periodic state with wheels")
    base = 2 * np.pi * v / wagon
    omega = base * np.arange(m + 1)
    sleeper_weight, rail_weight = cell.weights(passage)
    ops = cell_operators(passage, cell.pad_stiffness, cell.pad_damping, omega,
                         sleeper_weight=sleeper_weight, rail_weight=rail_weight)
    grid = groups * np.arange(1, m // groups + 1)
    positions = np.asarray(passage.axle_positions, dtype=float)
    j = np.arange(n_sl)
    a = bending_wavenumber(passage, omega) * span                         # (m+1,)
    signed = np.concatenate([grid, -grid])                                # two-sided p != 0
    kappa = 2 * np.pi * (signed[None, :] - np.arange(m + 1)[:, None]) / wagon   # (m+1, P)
    gap = contact_gap(a[:, None], kappa * span)
    mode = (-signed // groups) % n_sl                                      # s = -p/G mod N
    # e^{i kappa_{p-n} d_k} = e^{2 pi i p d_k/H} e^{-2 pi i n d_k/H}: W P and the rail under
    # the wheels become products of small matrices
    load_gap = -4.0 * np.sqrt(n_sl) * span / wagon * gap                   # (m+1, P)
    wheel_phase = np.exp(2j * np.pi * np.outer(signed, positions) / wagon)
    sleeper_shift = np.exp(-2j * np.pi * np.outer(np.arange(m + 1), positions) / wagon)
    shift = np.exp(-2j * np.pi * np.outer(j, j) / n_sl)                    # e^{-2 pi i j s / N}
    basis = (np.exp(-1j * omega[:, None] * (j * span)[None, :] / v)[:, :, None]
             * shift[None] / np.sqrt(n_sl))                                # (m+1, j, s)
    omega2 = base * np.arange(-m, m + 1)
    kb4 = bending_wavenumber(passage, omega2) ** 4
    ei = float(passage.rail_bending_stiffness)
    kap = omega2[None, :] / v - 2 * np.pi * (grid[:, None] / groups) / cell_length   # (L, 2m+1)
    with np.errstate(divide="ignore", invalid="ignore"):
        # (kap^2)^2, not kap**4: pow() on negative bases took 40-80 ms at m = 458
        weight = 1.0 / (ei * cell_length * (np.square(np.square(kap)) - kb4[None, :]))
    harmonic_phase = np.exp(2j * np.pi * np.outer(np.arange(-m, m + 1), positions) / wagon)
    sleeper_phase = np.exp(1j * omega2[:, None] * (j * span)[None, :] / v)
    offsets = positions[None, :] - positions[:, None]                      # d_k' - d_k
    between = wheel_train_receptance(passage, base * grid, offsets) if grid.size \
        else np.zeros((0, positions.size, positions.size), dtype=complex)
    mobility = wheel_receptance(wheel, base * grid, positions.size)
    return WheelSystem(ops, grid, mode, load_gap, wheel_phase, sleeper_shift, basis, weight,
                       harmonic_phase, sleeper_phase,
                       (grid // groups) % n_sl, between, mobility, int(samples),
                       np.asarray(sleeper_weight, dtype=float))


def rail_under_wheels(system: WheelSystem, reaction: np.ndarray) -> np.ndarray:
    """The rail under each wheel from the sleepers' reactions, harmonics p = grid [m].

    ``u_{k,p} = sum_n sum_j e^{i kappa (d_k + x_j)} R_{j,n} / (EI Lambda (kappa^4 - k_n^4))``,
    kappa = omega_n/v - 2 pi (p/G)/Lambda: with x_j = jL the sum over j is a
    discrete Fourier transform of ``e^{i omega_n x_j / v} R_{j,n}`` at index p/G mod N.

    With kappa d_k split as 2 pi (n - p) d_k / H, the sum over n is a product
    of a (lmax, 2m+1) and a (2m+1, K) matrix.

    Parameters
    ----------
    reaction : ndarray, shape (N, 2m+1)
        R_{j,n}, n = -m..m [N].

    Returns
    -------
    ndarray, shape (lmax, K)
    """
    spectrum = np.fft.fft(reaction * system.sleeper_phase.T, axis=0)      # (N, 2m+1)
    read = system.under_weight * spectrum[system.mode_of_wheel]           # (lmax, 2m+1)
    lmax = system.grid.size
    return np.conj(system.wheel_phase[:lmax]) * (read @ system.harmonic_phase)


def wheel_residual(passage: Passage, cell, wheel, profile, system: WheelSystem,
                   coefficients: np.ndarray, forces: np.ndarray, lift: np.ndarray,
                   foundation: np.ndarray | None = None):
    """Residuals (sleepers (m+1, N) [N], contacts (K, lmax+1) [N]) and the contact histories.

    Parameters
    ----------
    profile : callable or ndarray
        r(x) [m], or its harmonics under the wheels (`profile_harmonics`).
    coefficients : ndarray, shape (N, m+1)
        c_{j,n} [m].
    forces : ndarray, shape (K, lmax)
        P_{k,p} at p = grid [N].
    lift : ndarray, shape (K,)
        y_k = mean wheel height minus the rail's mean under it [m].
    foundation : ndarray, shape (N, m+1), optional
        F_{j,n}, the laws' force harmonics at `coefficients` where the caller
        has them (the sleepers' solve): the AFT is then not repeated [N].
    """
    ops, grid, samples = system.ops, system.grid, system.samples
    m = ops.omega.size - 1
    if foundation is None:
        w, v = _synthesize(coefficients, ops.omega, samples)
        spectrum = np.fft.rfft(_forces(cell, w, v), axis=-1)[:, :m + 1] / samples
    else:
        spectrum = foundation
    seat = -cell.sleeper_mass[:, None] * ops.omega**2 * coefficients + spectrum
    sleepers = (np.einsum("nab,bn->na", ops.first, coefficients)
                + np.einsum("nab,bn->na", ops.second, seat) - ops.load
                - wheel_loads(system, forces))
    pads = seat.copy()
    pads[:, 0] += system.sleeper_weight            # the pad also carries the sleeper's weight
    reaction = -np.concatenate([np.conj(pads[:, :0:-1]), pads], axis=1)   # (N, 2m+1), R = -p
    rail = (rail_under_wheels(system, reaction)
            - np.einsum("lkq,ql->kl", system.between_wheels, forces).T).T
    delta = compression(passage, profile, system, rail - wheels_under(system, forces), lift)
    hertz = wheel.contact_force(delta)
    harmonics = np.fft.rfft(hertz, axis=-1) / samples
    contacts = np.empty((forces.shape[0], grid.size + 1), dtype=complex)
    contacts[:, 0] = harmonics[:, 0].real - np.asarray(passage.axle_loads)
    contacts[:, 1:] = harmonics[:, grid] - forces
    return sleepers, contacts, delta, hertz


def wheels_under(system: WheelSystem, forces: np.ndarray) -> np.ndarray:
    """z_p = A(omega_p) P_p, the wheels' displacement harmonics (K, lmax) [m] under P (K, lmax)."""
    return np.einsum("lkq,ql->kl", system.wheel_receptance, forces)


def wheel_loads(system: WheelSystem, forces: np.ndarray) -> np.ndarray:
    """W_n P of the module docstring, (m+1, N) [N], for P_{k,p} (K, lmax) at p = grid.

    Each p loads one Floquet mode: the forces are summed per mode, then
    mapped to the sleepers.
    """
    two = np.concatenate([forces, np.conj(forces)], axis=1)               # (K, 2 lmax)
    by_p = system.load_gap * (system.sleeper_shift @ (system.wheel_phase.T * two))
    # p = +G i loads mode -i mod N, p = -G i mode i mod N (i = 1..lmax): fold i mod N
    lmax, n_sl = forces.shape[1], system.mode_basis.shape[2]
    plus, minus = _fold(by_p[:, :lmax], n_sl), _fold(by_p[:, lmax:], n_sl)
    by_mode = plus[:, ::-1] + np.roll(minus, 1, axis=1)
    # basis_{n,j,s} = e^{-i omega_n x_j/v} e^{-2 pi i j s/N} / sqrt(N): a DFT over s
    m = by_p.shape[0] - 1
    return (np.conj(system.sleeper_phase[m:]) * np.fft.fft(by_mode, axis=1)
            / np.sqrt(by_mode.shape[1]))


def _fold(values: np.ndarray, n: int) -> np.ndarray:
    """Columns i = 0..l-1 of (W, l) summed by i mod n: (W, n)."""
    rows, count = values.shape
    whole = count // n * n
    out = values[:, :whole].reshape(rows, -1, n).sum(axis=1) if whole \
        else np.zeros((rows, n), dtype=values.dtype)
    out[:, :count - whole] += values[:, whole:]
    return out


def profile_harmonics(passage: Passage, profile, grid: np.ndarray, samples: int) -> np.ndarray:
    """r(vt - d_k)'s mean and harmonics p = grid, (K, lmax+1) [m]: the profile the wheels feel.

    The harmonic balance keeps the profile's harmonics up to m, as it keeps
    the wheels' and sleepers': a wheel without mass then follows it exactly
    and presses with Q, at any m.  Sampled 4 ``samples`` times a period.
    """
    fine = 4 * int(samples)
    t = np.arange(fine) * float(passage.period) / fine
    positions = np.asarray(passage.axle_positions, dtype=float)
    # a wheel flat is felt by its own wheel only (`railtrack.model.profile_sum`)
    r = felt_profile(profile, float(passage.speed) * t[None, :] - positions[:, None],
                     positions.size)
    spectrum = np.fft.rfft(r, axis=-1) / fine
    return np.concatenate([spectrum[:, :1], spectrum[:, grid]], axis=1)


def compression(passage: Passage, profile, system: WheelSystem, fluctuation: np.ndarray,
                lift: np.ndarray) -> np.ndarray:
    """delta_k(t) [m] on the AFT samples from its harmonics p = grid (K, lmax) and y_k.

    The profile enters through its harmonics up to m: ``profile`` is r(x), or
    those harmonics already read by `profile_harmonics` (a solve reads them
    once: a random rail's sum over its wavenumbers took a third of a solve
    when read at every residual).
    """
    samples = system.samples
    rail_top = profile if isinstance(profile, np.ndarray) else profile_harmonics(
        passage, profile, system.grid, samples)
    spectrum = np.zeros((fluctuation.shape[0], samples // 2 + 1), dtype=complex)
    spectrum[:, system.grid] = (fluctuation + rail_top[:, 1:]) * samples
    return (np.fft.irfft(spectrum, samples, axis=-1) + np.asarray(lift)[:, None]
            + rail_top[:, :1].real)
