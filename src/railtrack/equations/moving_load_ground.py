"""The steady response of a beam on the ground to a load moving at constant speed (issue 31).

In the load's frame xi = x - v t the load P delta(xi) is (P / 2 pi) int
exp(i k (x - v t)) dk: each wavenumber k meets the ground at omega = k v in
the exp(i (k x - omega t)) convention of `railtrack.equations.ground_stiffness`.
With D(k, omega) of `railtrack.equations.beam_on_ground`,

    w(xi) = (P / 2 pi) int exp(i k xi) / D(k, k v) dk
          = (P / pi) int_0^inf Re[exp(i k xi) / D(k, k v)] dk,

since D(-k, -omega) is the conjugate of D(k, omega) (a real load gives a real
displacement).  The ground's own damping keeps D off zero at every speed.

Quadrature.  Gauss-Legendre panels of 8 points, log-spaced in k from
1e-5 k_c to 100 k_c with k_c = (mu / EI)^(1/4) (mu the top stratum's shear
modulus: the wavenumber where the beam's bending meets the ground's
stiffness), a panel [0, 1e-5 k_c] where 1/D is taken as constant (K_eq only
falls logarithmically as k -> 0), and beyond 100 k_c the beam's tail
int 1/(EI k^4) dk = 1 / (3 EI k^3).  `panels_per_decade` sets the resolution
of the resonance peak near the critical speed (its width ~ the damping).
"""

from __future__ import annotations

import math

import numpy as np

from ..model.ground import Ground
from ..model.validation import require_finite
from .beam_on_ground import beam_on_ground_stiffness

__all__ = ["moving_load_displacement"]

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(8)


def moving_load_displacement(ground: Ground, bending_stiffness: float, mass: float,
                             width: float, speeds, force: float = 1.0,
                             pad_stiffness: float = math.inf, positions=0.0,
                             average: bool = False, panels_per_decade: int = 8
                             ) -> np.ndarray:
    """w(xi) [m] of a beam on the ground under a load P moving at speed v, in the load's frame.

    Parameters
    ----------
    ground : Ground
        With damping_ratio > 0 somewhere when v > 0 (see `strip_stiffness`).
    bending_stiffness, mass, width, pad_stiffness, average
        As in `beam_on_ground_stiffness`: EI [N m^2], m [kg/m], b [m], k_p [N/m^2].
    speeds : array_like
        v >= 0 [m/s].
    force : float
        P [N], downward positive (w positive in the load's direction).
    positions : array_like
        xi [m] behind (< 0) or ahead of (> 0) the load.
    panels_per_decade : int
        Quadrature panels per decade of k.

    Returns
    -------
    ndarray [m], shape (len(speeds), len(positions)) for array arguments
    (scalars dropped).

    Examples
    --------
    A stiff thin layer on a stiff base is a Winkler bed k = M b / h; statically
    w(0) = P / (8 EI beta^3), beta = (k / 4 EI)^(1/4):

    >>> from railtrack.model.ground import SoilLayer
    >>> layer = SoilLayer(25.0, 0.3, 1600.0, thickness=0.02)   # M = 3.5 MPa
    >>> ground = Ground((layer,), SoilLayer(5000.0, 0.25, 2500.0))
    >>> bed = layer.constrained_modulus * 2.0 / 0.02
    >>> beta = (bed / (4 * 6.4e6)) ** 0.25
    >>> w = moving_load_displacement(ground, 6.4e6, 300.0, 2.0, 0.0, 1e5)
    >>> round(float(w) / (1e5 / (8 * 6.4e6 * beta**3)), 2)   # the layer's shear: -0.6 %
    0.99
    """
    require_finite("force", force, "N")
    require_finite("speeds", speeds, "m/s")
    require_finite("positions", positions, "m")
    v_in, xi_in = np.asarray(speeds, dtype=float), np.asarray(positions, dtype=float)
    if np.any(v_in < 0):
        raise ValueError(f"speeds must be >= 0 m/s (the load's direction is +x); got {v_in}")
    v, xi = np.atleast_1d(v_in).ravel(), np.atleast_1d(xi_in).ravel()
    k_c = (ground.strata[0].shear_modulus / bending_stiffness) ** 0.25
    edges = k_c * np.geomspace(1e-5, 100.0, 7 * panels_per_decade + 1)
    mid, half = 0.5 * (edges[1:] + edges[:-1]), 0.5 * np.diff(edges)
    k = (mid[:, None] + half[:, None] * _NODES).ravel()
    weight = (half[:, None] * _WEIGHTS).ravel()
    d = beam_on_ground_stiffness(ground, bending_stiffness, mass, width, k[None, :],
                                 k[None, :] * v[:, None], pad_stiffness, average)
    phase = np.exp(1j * k[:, None] * xi[None, :])                       # (k, xi)
    body = np.einsum("sk,kx->sx", weight / d, phase).real
    # [0, k_0]: 1/D nearly constant there; beyond k_N: the beam's bending alone
    start = edges[0] * (1.0 / d[:, :1]).real * np.sinc(edges[0] * xi / np.pi)[None, :]
    tail = 1.0 / (3.0 * bending_stiffness * edges[-1] ** 3) * (xi[None, :] == 0)
    w = force / np.pi * (body + start + tail)
    return w.reshape(v_in.shape + xi_in.shape)
