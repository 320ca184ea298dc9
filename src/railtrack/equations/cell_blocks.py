"""The per-harmonic blocks of a cell solved in its Floquet modes, few sleepers differing (issue 28).

The Newton step, the linear guess and the truncation estimate of a cell
(`railtrack.solvers.cell_step`, `railtrack.solvers.cell_auto`) solve, for each
harmonic, ``B_n x_n = r_n`` with

    B_n = K1_n + K2_n diag(S_n),   S_{j,n} = -M_j omega_n^2 + Kbar_j + i omega_n Cbar_j,

the rail, pads and each sleeper's (mean) support.  Where every sleeper has
the same pad A_0 and support S_0, B_n is diagonal in the Floquet modes
(`railtrack.equations.cell_modes`): ``B0_n = F diag(den + (den / A_0 + num) S_0) F^H``.
A cell that differs from that at r sleepers only (one hanging sleeper, a
weld, a stiff transition) has B_n = B0_n + C_n P^T, C_n the difference of
those r columns, and Woodbury's identity solves it with two FFTs per
right-hand side and one r x r system per harmonic,

    x = z - Y (I + P^T Y)^{-1} P^T z,   z = B0^{-1} r,   Y = B0^{-1} C,

O(N log N + N r + r^3) per harmonic instead of the dense O(N^3).  Where many
sleepers differ (a random support), or where B0_n is singular while B_n is
not (the reference sleepers carry nothing at omega = 0), those harmonics are
solved densely.
"""

from __future__ import annotations

import numpy as np

from .cell_modes import CellOperators

__all__ = ["reference_sleeper", "solve_blocks", "WOODBURY_SHARE", "SINGULAR_MODE", "RESIDUAL",
           "BLOCK_ENTRIES"]

BLOCK_ENTRIES = 1_000_000
"""Array entries per group of harmonics (16 MB a complex array)."""
WOODBURY_SHARE = 1.0 / 3.0
"""Share of differing sleepers up to which Woodbury's identity is used (beyond, dense)."""
RESIDUAL = 1e-10
"""A harmonic whose Woodbury solution leaves a residual above RESIDUAL times the size of its
terms is solved again densely (LU leaves round-off, about 1e-16 of it)."""
SINGULAR_MODE = 1e-12
"""A harmonic whose reference modes have ``|d_s| <= SINGULAR_MODE max_s |d_s|`` is solved
densely: B0 is (nearly) singular there and Woodbury would amplify round-off."""


def reference_sleeper(pad: np.ndarray, support: np.ndarray) -> tuple[int, np.ndarray]:
    """The sleeper whose pad and support (W, N) most sleepers share, and those that differ.

    Returns
    -------
    reference : int
    differing : ndarray of int
        Sleepers whose pad or support differs from the reference's (exactly).
    """
    keys = [pad[:, j].tobytes() + support[:, j].tobytes() for j in range(pad.shape[1])]
    counts: dict[bytes, int] = {}
    for key in keys:
        counts[key] = counts.get(key, 0) + 1
    common = max(counts, key=counts.__getitem__)
    reference = keys.index(common)
    return reference, np.array([j for j, key in enumerate(keys) if key != common], dtype=int)


def _dense(ops: CellOperators, support: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """The blocks built densely and solved (the O(N^3) path), rhs (W, N, k).

    ``B = T^* [H(den) diag(1 + S/A) + H(num) diag(S)] T`` with ``T = diag(e^{i theta j})``
    and H(x) the plain circulant of ``fft(x)/N``: the twist is applied to the
    right-hand side and the solution, not to the N x N matrix.
    """
    n = support.shape[-1]
    j = np.arange(n)
    index = (j[:, None] - j[None, :]) % n
    blocks = (np.fft.fft(ops.denominator, axis=-1)[:, index] * (1.0 + support / ops.pad)[:, None, :]
              + np.fft.fft(ops.numerator, axis=-1)[:, index] * support[:, None, :]) / n
    blocks[ops.rest] = blocks[ops.rest].real
    return np.conj(ops.twist)[..., None] * np.linalg.solve(blocks, ops.twist[..., None] * rhs)


def _woodbury(ops: CellOperators, support: np.ndarray, rhs: np.ndarray, reference: int,
              differing: np.ndarray) -> np.ndarray:
    """The blocks solved in the modes with Woodbury over `differing` (module docstring)."""
    pad0, support0 = ops.pad[:, reference, None], support[:, reference, None]
    modes = ops.denominator + (ops.denominator / pad0 + ops.numerator) * support0
    with np.errstate(invalid="ignore"):
        size = np.max(np.abs(modes), axis=1, keepdims=True)
        bad = ~np.all(np.isfinite(modes) & (np.abs(modes) > SINGULAR_MODE * size), axis=1)
    modes = np.where(bad[:, None], 1.0, modes)
    out = ops.from_modes(ops.to_modes(rhs) / modes[..., None])
    if differing.size:
        first, second = ops.columns(differing)
        sub = support[:, differing]
        change = (first * (sub / ops.pad[:, differing] - support0 / pad0)[:, None, :]
                  + (second - first / ops.pad[:, None, differing]) * (sub - support0)[:, None, :])
        through = ops.from_modes(ops.to_modes(change) / modes[..., None])           # (W, N, r)
        capacitance = np.eye(differing.size) + through[:, differing, :]
        out = out - through @ np.linalg.solve(capacitance, out[:, differing, :])
        # Woodbury is exact, but a nearly singular B0 (an undamped reference track near
        # resonance) or capacitance amplifies round-off: where the residual shows it, dense
        zero = np.zeros_like(out)
        first = ops.apply(out, zero, real_at_rest=False)
        second = ops.apply(zero, support[..., None] * out, real_at_rest=False)
        scale = sum(np.abs(x).max(axis=(1, 2)) for x in (first, second, rhs))
        bad |= ~(np.abs(first + second - rhs).max(axis=(1, 2)) <= RESIDUAL * scale)
    if np.any(bad):
        out[bad] = _dense(ops.take(bad), support[bad], rhs[bad])
    return out


def solve_blocks(ops: CellOperators, support: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """``x_n = (K1_n + K2_n diag(S_n))^{-1} r_n`` for every harmonic (module docstring).

    Harmonics are taken in groups of about `BLOCK_ENTRIES` array entries, so
    that memory stays bounded however many are asked for.

    Parameters
    ----------
    ops : CellOperators
    support : ndarray, shape (W, N)
        S_{j,n} [N/m], each sleeper's support (inertia and mean foundation).
    rhs : ndarray, shape (W, N) or (W, N, k)
        r_n [N].

    Returns
    -------
    ndarray, shape of `rhs`
        x_n [m].  At omega = 0 the blocks are real; x is returned as solved
        (its imaginary part there is round-off of a real right-hand side).

    Raises
    ------
    numpy.linalg.LinAlgError
        If a block (dense path) or a capacitance system is singular.
    """
    vector = rhs.ndim == 2
    rhs = rhs[..., None] if vector else rhs
    n = support.shape[1]
    reference, differing = reference_sleeper(ops.pad, support)
    dense = differing.size > WOODBURY_SHARE * n
    width = n if dense else differing.size + rhs.shape[2] + 1
    step = max(1, BLOCK_ENTRIES // (n * width))
    out = np.empty(rhs.shape, dtype=complex)
    for start in range(0, rhs.shape[0], step):
        rows = slice(start, start + step)
        part = ops if step >= rhs.shape[0] else ops.take(rows)
        out[rows] = (_dense(part, support[rows], rhs[rows]) if dense else
                     _woodbury(part, support[rows], rhs[rows], reference, differing))
    return out[..., 0] if vector else out
