"""Newton's step with wheels by preconditioned GMRES, matrix-free (issue 28).

The contact residual's Jacobian (scaled by the largest Q) is ``(K C - I') / Q``:
C the track under the wheels (`railtrack.solvers.wheel_track`), K the Hertz
tangent 1.5 C_H delta^{1/2} (Toeplitz in the harmonics: applied on the AFT
samples, synthesis, times the tangent's samples, analysis; the exact
derivative of the sampled residual) and I' the identity on the force
unknowns (not on the lifts y_k).  Per wheel the unknowns are packed
``[y_k, Re P_{k,p}, Im P_{k,p}]``, p = grid.  Nothing of size (K (2l+1))^2
is formed: a step costs a few dozen products C x and K x.

The preconditioner takes the mean tangent kbar_k for K and C's blocks
p -> p (between the wheels): per harmonic a real 2K x 2K block
``kbar C_pp - I`` inverted once per Jacobian.  The tangent's swing about
its mean and the sleeper pattern's coupling of p to p +- N G are what GMRES
iterates on, a few per cent to tens of per cent: a handful of products.
"""

from __future__ import annotations

import numpy as np

from .wheel_track import track_response

__all__ = ["ContactJacobian", "gmres", "hertz_product"]

GMRES_RESTART = 200
"""Krylov vectors kept before a restart (a wheel off the rail over part of the period
makes the mean tangent a poor preconditioner: tens of products, which a restart
would stall)."""
GMRES_MOST = 600
"""Products at most per step: past it the step is returned as far as it got (Newton's
line search and residual judge it)."""


def hertz_product(tangent: np.ndarray, lift: np.ndarray, delta: np.ndarray,
                  grid: np.ndarray) -> np.ndarray:
    """K delta: harmonics 0 and p = grid of ``tangent(t) delta(t)``, packed (K, 2l+1).

    Parameters
    ----------
    tangent : ndarray, shape (K, S)
        dP/d delta on the AFT samples [N/m].
    lift, delta : ndarray, shapes (K,) and (K, l)
        delta's mean [m] and harmonics p = grid [m].

    The product on the samples is the exact derivative of the sampled
    residual: the Toeplitz matrix of the tangent's harmonics up to 2 max(grid),
    without forming it.
    """
    wheels, samples = tangent.shape
    spectrum = np.zeros((wheels, samples // 2 + 1), dtype=complex)
    spectrum[:, 0] = lift * samples
    spectrum[:, grid] = delta * samples
    product = tangent * np.fft.irfft(spectrum, samples, axis=-1)
    out = np.fft.rfft(product, axis=-1)[:, np.concatenate([[0], grid])] / samples
    return np.concatenate([out[:, :1].real, out[:, 1:].real, out[:, 1:].imag], axis=1)


class ContactJacobian:
    """``x -> (K C - I') x / scale`` and its preconditioner, on packed vectors.

    Parameters
    ----------
    system : WheelSystem
    operator : TrackOperator
        C's factorised track (`railtrack.solvers.wheel_track.track_operator`).
    tangent : ndarray, shape (K, S)
        Hertz's tangent dP/d delta on the AFT samples [N/m].
    scale : float
        The largest static wheel load Q [N].
    """

    def __init__(self, system, operator, tangent: np.ndarray, scale: float):
        self.system, self.operator, self.scale = system, operator, float(scale)
        self.tangent = np.asarray(tangent, dtype=float)
        self.wheels, self.lmax = self.tangent.shape[0], system.grid.size
        mean = np.mean(self.tangent, axis=1)
        self.mean = np.where(mean > 0.0, mean, np.max(mean, initial=0.0) or 1.0)
        rows = np.tile(self.mean, 2)[None, :, None]            # kbar of each row's wheel
        block = operator.diagonal * rows - np.eye(2 * self.wheels)
        self.inverse = np.linalg.inv(block) if self.lmax else block

    def unpack(self, x: np.ndarray):
        rows = x.reshape(self.wheels, 2 * self.lmax + 1)
        return rows[:, 0], rows[:, 1:self.lmax + 1] + 1j * rows[:, self.lmax + 1:]

    def apply(self, x: np.ndarray) -> np.ndarray:
        lift, forces = self.unpack(x)
        delta = track_response(self.system, self.operator, forces)
        out = hertz_product(self.tangent, lift, delta, self.system.grid)
        out[:, 1:] -= x.reshape(self.wheels, -1)[:, 1:]
        return out.ravel() / self.scale

    def precondition(self, x: np.ndarray) -> np.ndarray:
        """The inverse of the Jacobian's part diagonal in p (mean tangent, C_pp)."""
        lmax, k_w = self.lmax, self.wheels
        rows = x.reshape(k_w, 2 * lmax + 1)
        out = np.empty_like(rows)
        out[:, 0] = rows[:, 0] / self.mean
        parts = np.stack([rows[:, 1:lmax + 1], rows[:, lmax + 1:]])        # (2, K, l)
        stacked = np.transpose(parts, (2, 0, 1)).reshape(lmax, 2 * k_w)
        solved = (self.inverse @ stacked[..., None])[..., 0].reshape(lmax, 2, k_w)
        out[:, 1:lmax + 1], out[:, lmax + 1:] = solved[:, 0].T, solved[:, 1].T
        return out.ravel() * self.scale


def gmres(apply, precondition, rhs: np.ndarray, tol: float, *, restart: int = GMRES_RESTART,
          most: int = GMRES_MOST):
    """x with ||apply(x) - rhs|| <= tol ||rhs||, right-preconditioned GMRES.

    Right preconditioning keeps the true residual in view (not the
    preconditioned one); Givens rotations give the residual at every
    product.  Returns (x, relative residual, products).
    """
    b_norm = float(np.linalg.norm(rhs))
    x = np.zeros_like(rhs)
    if b_norm == 0.0:
        return x, 0.0, 0
    residual, products, relative = rhs.copy(), 0, 1.0
    while products < most and relative > tol:
        beta = float(np.linalg.norm(residual))
        basis, directions = [residual / beta], []
        hessenberg = np.zeros((restart + 1, restart))
        cosines, sines = np.zeros(restart), np.zeros(restart)
        target = np.zeros(restart + 1)
        target[0] = beta
        for j in range(restart):
            directions.append(precondition(basis[j]))
            w = apply(directions[j])
            products += 1
            for _ in range(2):                          # modified Gram-Schmidt, twice
                for i in range(j + 1):
                    dot = basis[i] @ w
                    hessenberg[i, j] += dot
                    w = w - dot * basis[i]
            norm = float(np.linalg.norm(w))
            for i in range(j):                          # the earlier rotations
                upper = hessenberg[i, j]
                hessenberg[i, j] = cosines[i] * upper + sines[i] * hessenberg[i + 1, j]
                hessenberg[i + 1, j] = -sines[i] * upper + cosines[i] * hessenberg[i + 1, j]
            radius = float(np.hypot(hessenberg[j, j], norm))
            cosines[j], sines[j] = hessenberg[j, j] / radius, norm / radius
            hessenberg[j, j] = radius
            target[j + 1] = -sines[j] * target[j]
            target[j] *= cosines[j]
            relative = abs(target[j + 1]) / b_norm
            if relative <= tol or norm <= 1e-14 * beta or products >= most:
                break
            basis.append(w / norm)
        size = len(directions)
        y = np.linalg.solve(np.triu(hessenberg[:size, :size]), target[:size])
        x = x + np.stack(directions, axis=1) @ y
        residual = rhs - apply(x)
        products += 1
        relative = float(np.linalg.norm(residual)) / b_norm
        if norm <= 1e-14 * beta:
            break
    return x, relative, products
