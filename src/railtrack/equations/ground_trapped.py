"""The ground's equivalent stiffness under a strip where no ground wave radiates (issue 31).

Where omega / |k_x| lies below the phase speed of the ground's fundamental
Rayleigh mode, the undamped integral of `railtrack.equations.ground_strip`
has no pole on its path and the half-space's branch points lie below k_x:
it is real and needs no damping.  This is the stiffness that the track's
dispersion on the ground and its critical speed are made of
(`railtrack.equations.beam_on_ground`).
"""

from __future__ import annotations

import numpy as np

from ..model.ground import Ground
from .ground_stiffness import surface_flexibility
from .ground_strip import _sine_tail

__all__ = ["trapped_strip_stiffness", "with_damping"]

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(8)


def with_damping(ground: Ground, xi: float) -> Ground:
    """`ground` with the damping ratio xi [-] in every stratum."""
    return ground.with_damping(xi)


def trapped_strip_stiffness(ground: Ground, kx, omega, width: float) -> np.ndarray:
    """K_eq [N/m^2] of the undamped ground where no ground wave radiates (real).

    The integral of `railtrack.equations.ground_strip` (centre line) with the
    ground's damping ignored, valid where omega / |k_x| is below the ground's
    fundamental mode's phase speed: the integrand is then smooth for k_y > 0
    (no pole, the half-space's branch points lie below k_x) but for the peak
    at k_y = 0 of width ~ k_x sqrt(2 (1 - v / c_R)), resolved by panels
    graded geometrically from 1e-5 k_x.  Panels no wider than pi / b carry
    the sinc; the tail beyond Y is the top stratum's static one in closed form.

    Examples
    --------
    >>> from railtrack.equations.ground_strip import strip_stiffness
    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0)
    >>> k = trapped_strip_stiffness(ground, 1.0, 50.0, 3.0)
    >>> from railtrack import plausibility
    >>> with plausibility("ignore"):        # xi = 1e-9, no soil's: the undamped limit
    ...     damped = strip_stiffness(with_damping(ground, 1e-9), 1.0, 50.0, 3.0)
    >>> bool(abs(k - damped.real) < 1e-6 * abs(k))
    True
    """
    kx, omega = np.broadcast_arrays(np.abs(np.asarray(kx, dtype=float)),
                                    np.asarray(omega, dtype=float))
    elastic = with_damping(ground, 0.0)
    c_min = min(s.shear_wave_speed for s in ground.strata)
    out = np.empty(kx.shape)
    for index in np.ndindex(kx.shape):
        k, w = kx[index], omega[index]
        end = max(120.0 / width, 10.0 * k, 3.0 * abs(w) / c_min)
        edges = np.concatenate([[0.0], k * np.geomspace(1e-5, 1.0, 41),
                                np.geomspace(k, end, 60),
                                np.arange(0.0, end, np.pi / width)])
        edges = np.unique(edges)
        pieces = np.maximum(np.ceil(np.diff(edges) / (np.pi / width)), 1).astype(int)
        edges = np.concatenate([np.linspace(a, b, n, endpoint=False)
                                for a, b, n in zip(edges[:-1], edges[1:], pieces)] + [[end]])
        mid, half = 0.5 * (edges[1:] + edges[:-1]), 0.5 * np.diff(edges)
        ky = (mid[:, None] + half[:, None] * _NODES).ravel()
        weight = (half[:, None] * _WEIGHTS).ravel()
        values = surface_flexibility(elastic, np.hypot(k, ky), w).real
        total = np.sum(values * np.sinc(ky * width / (2.0 * np.pi)) * weight)
        top = ground.strata[0]
        tail = _sine_tail(np.array([end * width / 2.0]), k * width / 2.0, 1.0)[0]
        out[index] = np.pi / (total + (1.0 - top.poisson_ratio) / top.shear_modulus * tail)
    return out
