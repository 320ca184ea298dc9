"""Eigenvalues of an analytic matrix function inside a contour (Beyn's method).

A nonlinear eigenvalue problem T(z) p = 0, with T analytic inside a closed
contour Gamma (meromorphic will do: poles of T are no eigenvalues), has
finitely many eigenvalues inside.  Beyn's integral method (Beyn 2012,
Linear Algebra Appl. 436) finds them all at once from the moments

    A_k = (1 / 2 pi i) \\oint_Gamma z^k T(z)^{-1} V dz,   k = 0, 1,

of a random probe V with more columns than eigenvalues inside: A_0 has the
rank r of the eigenvalues inside, and with A_0 = U S W^* (rank r),
B = U^* A_1 W S^{-1} is an r x r matrix whose eigenvalues are the
eigenvalues of T inside Gamma and U times its eigenvectors are T's.  The
integrals are taken by the trapezoidal rule on an ellipse, which converges
geometrically.  `polish` then refines each eigenpair by Newton's method on
the bordered system, so that the quadrature's error does not stay in the
result.  `railtrack.solvers.floquet` applies both to Hill's matrix.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

__all__ = ["contour_eigenpairs", "polish"]

RANK_TOLERANCE = 1e-9
"""Singular values of A_0 below this fraction of the integrand's largest entry are noise."""


def contour_eigenpairs(matrix: Callable[[np.ndarray], np.ndarray], center: complex,
                       semi_axes: tuple[float, float], points: int = 16, columns: int = 8,
                       seed: int = 0) -> list[tuple[np.ndarray, np.ndarray]]:
    """Eigenvalues z and eigenvectors p of T(z) p = 0 inside an ellipse.

    Parameters
    ----------
    matrix : callable
        ``matrix(z)`` for the array of quadrature points z returns T(z) of
        shape ``batch + z.shape + (n, n)``: leading axes are separate
        problems, solved together.
    center : complex
        Centre of the ellipse.
    semi_axes : (float, float)
        Its semi-axes along the real and the imaginary axis.
    points : int
        Quadrature points on the ellipse.
    columns : int
        Columns of the random probe: at most this many eigenvalues are found
        (the probe grows, up to n, if the rank fills it).
    seed : int
        Seed of the probe (the result does not depend on it beyond round-off).

    Returns
    -------
    list of (values, vectors)
        For each problem of the batch (in C order), approximate eigenvalues,
        shape (r,), and eigenvectors, shape (n, r), to be refined by
        `polish`; some may lie just outside the ellipse.

    Examples
    --------
    >>> t = lambda z: np.array([[1.0, 2.0], [0.0, 3.0]]) - z[..., None, None] * np.eye(2)
    >>> [(values, _)] = contour_eigenpairs(t, 2.0, (1.5, 0.5), points=32, columns=2)
    >>> np.sort(values.real).round(10).tolist()
    [1.0, 3.0]
    """
    angle = 2.0 * np.pi * np.arange(points) / points
    z = center + semi_axes[0] * np.cos(angle) + 1j * semi_axes[1] * np.sin(angle)
    weights = (-semi_axes[0] * np.sin(angle) + 1j * semi_axes[1] * np.cos(angle)) / (1j * points)
    values = matrix(z)
    n = values.shape[-1]
    values = values.reshape((-1, points, n, n))
    rng = np.random.default_rng(seed)
    columns = min(columns, n)
    probe = np.empty((n, 0), dtype=complex)
    solved = np.empty(values.shape[:2] + (n, 0), dtype=complex)
    growing = np.arange(values.shape[0])
    while True:
        # Only the problems whose rank filled the probe are solved again, and only for
        # the probe's new columns: the columns solved before stay valid.
        extra = columns - probe.shape[1]
        new = rng.standard_normal((n, extra)) + 1j * rng.standard_normal((n, extra))
        probe = np.concatenate([probe, new], axis=1)
        grown = np.zeros(values.shape[:2] + (n, columns), dtype=complex)
        grown[..., : solved.shape[-1]] = solved
        grown[growing, ..., solved.shape[-1]:] = np.linalg.solve(
            values[growing], np.broadcast_to(new, (growing.size, points, n, extra)))
        solved = grown
        first = np.einsum("k,bkij->bij", weights, solved[growing])
        u_part, sigma_part, wh_part = np.linalg.svd(first, full_matrices=False)
        if growing.size == values.shape[0]:
            u, sigma, wh = u_part, sigma_part, wh_part
        else:
            u, sigma, wh = _widened(u, (-1,), columns), _widened(sigma, (-1,), columns), \
                _widened(wh, (-2, -1), columns)
            u[growing], sigma[growing], wh[growing] = u_part, sigma_part, wh_part
        # Against the integrand's own size, not A_0's: with no eigenvalue inside,
        # A_0 is quadrature noise and all of it must count as rank 0.
        scale = np.max(np.abs(solved), axis=(1, 2, 3))[:, None]
        ranks = np.sum(sigma > RANK_TOLERANCE * scale, axis=1)
        full = ranks >= columns
        if not full.any() or columns == n:
            break
        growing = np.flatnonzero(full)
        columns = min(2 * columns, n)
    second = np.einsum("k,bkij->bij", weights * z, solved)
    pairs = []
    for b, rank in enumerate(ranks):
        if rank == 0:
            pairs.append((np.empty(0, complex), np.empty((n, 0), complex)))
            continue
        left, right = u[b, :, :rank], wh[b, :rank].conj().T
        reduced = left.conj().T @ second[b] @ right / sigma[b, :rank]
        eigenvalues, eigenvectors = np.linalg.eig(reduced)
        pairs.append((eigenvalues, left @ eigenvectors))
    return pairs


def _widened(array: np.ndarray, axes: tuple[int, ...], columns: int) -> np.ndarray:
    """`array` padded with zeros along `axes` to `columns` entries (at most n)."""
    pad = [(0, 0)] * array.ndim
    for axis in axes:
        pad[axis] = (0, max(0, columns - array.shape[axis]))
    return np.pad(array, pad)


def polish(matrix: Callable[[np.ndarray], np.ndarray], values: np.ndarray, vectors: np.ndarray,
           derivative: Callable[[np.ndarray, np.ndarray], np.ndarray] | None = None,
           iterations: int = 6, tol: float = 1e-10, step: float = 1e-6
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Newton's method on T(z) p = 0, u^* p = 1, from approximate eigenpairs, all at once.

    Parameters
    ----------
    matrix : callable
        ``matrix(z, rows)`` returns T(z) for the candidates ``rows`` (an
        index array) at the points z of the same length, shape
        (len(rows), n, n): each candidate may stand for its own problem.
    values : ndarray, shape (r,)
    vectors : ndarray, shape (r, n)
        The approximate eigenpairs.
    derivative : callable, optional
        ``derivative(z, p, rows)`` returns T'(z_i) p_i, shape (len(rows), n); by default a
        central difference of `matrix` of width `step` (T is analytic, so its
        error is of order step^2).

    Returns
    -------
    values : ndarray, shape (r,)
    vectors : ndarray, shape (r, n)
        Each normalised to unit norm.
    residuals : ndarray, shape (r,)
        ||T(z) p|| / ||T(z)||_F at the result: small for a true eigenpair.

    Examples
    --------
    >>> t = lambda z, rows: np.array([[1.0, 2.0], [0.0, 3.0]]) - z[..., None, None] * np.eye(2)
    >>> z, p, residual = polish(t, np.array([0.9 + 0.1j]), np.array([[1.0, 0.1]]))
    >>> bool(abs(z[0] - 1) < 1e-12 and residual[0] < 1e-12)
    True
    """
    if derivative is None:
        def derivative(z, p, rows):
            ends = (matrix(z + step, rows), matrix(z - step, rows))
            return np.einsum("rij,rj->ri", ends[0] - ends[1], p) / (2.0 * step)
    values = np.array(values, dtype=complex)
    vectors = np.array(vectors, dtype=complex)
    vectors /= np.linalg.norm(vectors, axis=1, keepdims=True)
    anchor = vectors.conj()
    r, n = vectors.shape
    active = np.ones(r, dtype=bool)
    for _ in range(iterations):
        if not active.any():
            break
        rows = np.flatnonzero(active)
        z, p = values[rows], vectors[rows]
        at = matrix(z, rows)
        bordered = np.zeros((z.size, n + 1, n + 1), dtype=complex)
        bordered[:, :n, :n], bordered[:, :n, n], bordered[:, n, :n] = at, derivative(z, p, rows), \
            anchor[active]
        right = -np.concatenate([np.einsum("rij,rj->ri", at, p),
                                 np.sum(anchor[active] * p, axis=1, keepdims=True) - 1.0], axis=1)
        try:
            correction = np.linalg.solve(bordered, right[..., None])[..., 0]
        except np.linalg.LinAlgError:
            break
        vectors[active], values[active] = p + correction[:, :n], z + correction[:, n]
        done = np.abs(correction[:, n]) <= tol * np.maximum(1.0, np.abs(values[active]))
        active[np.flatnonzero(active)[done]] = False
    final = matrix(values, np.arange(r))
    vectors /= np.linalg.norm(vectors, axis=1, keepdims=True)
    residuals = np.linalg.norm(np.einsum("rij,rj->ri", final, vectors), axis=1) / \
        np.linalg.norm(final, axis=(1, 2))
    return values, vectors, residuals
