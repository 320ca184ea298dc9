"""The ground's surface flexibility at many radial wavenumbers of one frequency, from a table.

The strip's quadrature (`railtrack.equations.ground_strip`) needs the surface
flexibility F(k, omega) of `railtrack.equations.ground_stiffness` at every
node k = sqrt(k_x^2 + k_y^2) of every k_x it integrates: tens of thousands of
nodes for the lattice sum of one harmonic, each a stiffness-matrix solve.
At one omega, F is a function of k alone, so it is computed once on a table
and the nodes read it by a quintic spline in ln k of k F (finite at both
ends: (1 - nu) / mu* at short waves, k F(0, omega) -> 0 at long ones).

The table is geometric, k growing by 4 % from node to node, and by
xi / 12 across the surface waves and the half-space's branch points
(k from 0.9 omega / c_P of the half-space to 1.5 omega / (0.8 c_min)), where
F has poles a hysteretic damping ratio xi wide, and by 1 % on either side
(from 0.5 omega / c_P, and up to 4 omega / (0.8 c_min)); a quintic spline
there is good to about 3e-8, where a cubic one needed steps of xi / 24 for
2e-7 (measured on three soils at 0 to 2000 rad/s).  It is checked where it is
weakest, halfway between nodes: at 64 such points the spline must agree
with F to 3e-7 of max |k F|, or every node is computed directly.  A table
that would not be smaller than a third of the nodes is not built.
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import make_interp_spline

from ..model.ground import Ground
from .ground_stiffness import surface_flexibility

__all__ = ["radial_flexibility"]

_STEP = 0.04             # the table's growth in k away from the surface waves
_NEAR_STEP = 0.01        # beside them (the poles' tails, the P wave's branch point)
_POLE_FRACTION = 1 / 12   # and across them, of the smallest damping ratio
_CHECKS = 64
_CHECK = 3e-7


def _table(ground: Ground, low: float, high: float, omega: float) -> np.ndarray:
    """Nodes of the table on [low, high] (the module's note)."""
    nodes = [np.geomspace(low, high, int(np.log(high / low) / np.log1p(_STEP)) + 2)]
    if omega != 0.0:
        xi = max(min(s.damping_ratio for s in ground.strata if s.damping_ratio > 0), 1e-3)
        slow = abs(omega) / (0.8 * ground.slowest_shear_wave_speed)
        # across the poles at xi / 8, and their tails at 0.5 % (a pole's tail falls like
        # 1 / (k - k_R): steps of 2 % a few tens of per cent from it are not enough)
        k_p = abs(omega) / ground.halfspace.p_wave_speed
        # the P wave's branch point reaches below 0.9 k_P (a cubic table of 2 % steps was
        # off by 5e-7 at 0.84 k_P), and a pole's tail beyond 1.5 k_slow
        for start, stop, step in ((0.5 * k_p, 0.9 * k_p, _NEAR_STEP),
                                  (0.9 * k_p, 1.5 * slow, _POLE_FRACTION * xi),
                                  (1.5 * slow, 4.0 * slow, _NEAR_STEP)):
            start, stop = max(start, low), min(stop, high)
            if stop > start:
                nodes.append(np.geomspace(start, stop,
                                          int(np.log(stop / start) / np.log1p(step)) + 2))
    return np.unique(np.concatenate(nodes))


def radial_flexibility(ground: Ground, k: np.ndarray, omega: float) -> np.ndarray:
    """F(k, omega) [m/Pa] at radial wavenumbers k > 0 [rad/m] of one omega [rad/s].

    Same values as `surface_flexibility` (to about 3e-7 of the largest
    |k F|), read from a checked table when that is cheaper (the module's
    note).

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0, 0.02)
    >>> k = np.linspace(0.1, 50.0, 20000)
    >>> table, exact = radial_flexibility(ground, k, 60.0), surface_flexibility(ground, k, 60.0)
    >>> bool(np.max(np.abs((table - exact) * k)) < 3e-7 * np.max(np.abs(exact * k)))
    True
    """
    k = np.asarray(k, dtype=float)
    low, high = float(k.min()), float(k.max())
    if high <= low * (1 + _STEP):
        return surface_flexibility(ground, k, omega)
    nodes = _table(ground, low, high, omega)
    if 3 * nodes.size > k.size or nodes.size < 12:           # a quintic spline needs > 5
        return surface_flexibility(ground, k, omega)
    values = nodes * surface_flexibility(ground, nodes, omega)
    spline = make_interp_spline(np.log(nodes), values, k=5)
    # halfway between nodes, spread over the table (the fine part included)
    picks = np.linspace(0, nodes.size - 2, _CHECKS).astype(int)
    middle = np.sqrt(nodes[picks] * nodes[picks + 1])
    error = np.abs(spline(np.log(middle)) - middle * surface_flexibility(ground, middle, omega))
    if np.max(error) > _CHECK * np.max(np.abs(values)):
        return surface_flexibility(ground, k, omega)
    return spline(np.log(k)) / k
