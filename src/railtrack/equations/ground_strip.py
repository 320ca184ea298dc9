"""The equivalent stiffness of the ground under a strip along the track (2.5D).

A load P exp(i (k_x x - omega t)) per unit length [N/m], spread uniformly over
a strip |y| <= b/2 across the track, is the stress (P/b) rect(y/b); its
transform in y is P sinc(k_y b/2).  The ground's vertical displacement on the
strip's centre line y = 0 is then

    w = (P / 2 pi) int F(sqrt(k_x^2 + k_y^2), omega) sinc(k_y b/2) dk_y,

with F the surface flexibility of `railtrack.equations.ground_stiffness`, and
the equivalent stiffness per unit length is K_eq = P / w [N/m^2]
(Dieterman & Metrikine 1996).  The displacement is taken on the centre line
of the beam lying on the strip, the convention we read in their work (their
equations were not at hand to check it line by line).  ``average=True`` takes
instead the displacement averaged over the width, sinc^2 in the integral: the
choice for a body that moves as one across its width (a rigid sleeper, a slab).
``offset=y`` gives the ground's displacement on the line y beside the centre
line, the weight sinc(k_y b/2) cos(k_y y).

Quadrature.  The integrand is even in k_y.  For k_x > 0 the top stratum's
static flexibility F_inf = (1 - nu) / (mu* k) is split off and integrated in
closed form: with s = k_x b/2 and the integral of K_0 (Struve's functions,
`scipy.special.iti0k0`),

    int_0^inf sinc^2(k_y b/2) / k dk_y = IK0(2 s) / s - (1 - 2 s K_1(2 s)) / (2 s^2),
    int_0^inf sinc(k_y b/2) cos(k_y y) / k dk_y
        = [sgn(1 + c) IK0(|1 + c| s) + sgn(1 - c) IK0(|1 - c| s)] / (2 s),   c = 2 y / b,

(from int_0^inf cos(a t) / sqrt(s^2 + t^2) dt = K_0(a s), integrated twice
or once in a).  What is left, F - F_inf, falls like (omega / c k)^2 F_inf and
exp(-2 k h) with depth, so its quadrature stops near the surface waves and
the top stratum's thickness instead of at ten times k_x: the strip costs
about the same at every k_x.  8-point Gauss-Legendre panels on [0, Y] are
fine over the k_y that map to k between 0.98 omega/c_s of the half-space and
omega / (0.8 min c_s) (the surface-wave poles; k grows by a factor 1 + xi
from panel to panel), graded towards the P wave's branch point of the
half-space, graded geometrically near k_y = 0 (the 1/k peak as k_x -> 0)
and no wider than 2 pi / b for the sinc.  At k_x = 0 (omega != 0) the whole
F is integrated and, beyond Y, its static tail in closed form (sine and
cosine integrals).  Hysteretic damping keeps the poles off the real axis,
so some damping is required when omega != 0.  Measured against QUADPACK's
adaptive quadrature the result is good to about 1e-6 (the tests).
"""

from __future__ import annotations

import numpy as np
from scipy.special import iti0k0, k1, sici

from ..model.ground import Ground
from ..model.validation import require_finite, require_positive
from .ground_stiffness import surface_flexibility
from .ground_table import radial_flexibility

__all__ = ["strip_flexibility", "strip_stiffness", "static_strip_flexibility"]

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(8)
# panels no wider than 2 pi / b (a quarter of the sinc's period), k growing by xi from panel to
# panel across the surface-wave poles (a pole damped by xi is ~ xi k wide), and no wider than
# 0.2 omega / c_s below them: measured against QUADPACK within 1e-6 (tests/test_ground_strip.py)
_SINC_CAP, _POLE_STEP, _NEAR_CAP = 2.0, 1.0, 0.2


def _breakpoints(ground: Ground, kx: float, omega: float, width: float,
                 offset: float = 0.0, reach: float = 6.0) -> np.ndarray:
    """Panel ends on [0, Y] in k_y for one k_x (see the module's note)."""
    half, strata = ground.halfspace, ground.strata
    k_slow = abs(omega) / (0.8 * min(s.shear_wave_speed for s in strata))   # below every c_R
    k_fast = abs(omega) / half.shear_wave_speed
    # with F_inf split off (k_x > 0) the rest dies out past the surface waves and past ~12/h
    # (exp(-2 k h) of the top stratum's thickness h); unsplit (k_x = 0) F keeps its 1/k
    depth = 12.0 / ground.layers[0].thickness if ground.layers else 0.0
    end = max(120.0 / width, reach * k_slow, min(10.0 * kx, depth) if kx > 0 else 0.0)
    features = [abs(omega) / half.p_wave_speed, k_fast, k_slow]
    points = [0.0, end] + [np.sqrt(f * f - kx * kx) for f in features if f > kx]
    near = 0.0                                    # k_y below which the dynamic cap holds
    cap = _SINC_CAP * np.pi / (width + 2.0 * abs(offset))     # sin((b/2 + |y|) k_y) resolved
    if omega != 0.0:
        xi = max(min(s.damping_ratio for s in strata if s.damping_ratio > 0), 1e-3)
        # k from 0.98 k_fast to 1.02 k_slow in steps of xi k / 2: a pole's width is ~ xi k
        k = 0.98 * k_fast * (1.0 + _POLE_STEP * xi) ** np.arange(
            int(np.log(1.04 * k_slow / (0.98 * k_fast)) / np.log1p(_POLE_STEP * xi)) + 2)
        # and towards the P wave's branch point from both sides, in steps down to xi k / 4
        k_p = abs(omega) / half.p_wave_speed * (1.0 + np.outer([-1.0, 1.0],
                                                              0.25 * xi * 2.0 ** np.arange(8)))
        k = np.concatenate([k, k_p.ravel()])
        points += list(np.sqrt(k[k > kx] ** 2 - kx * kx))
        near = 1.5 * np.sqrt(max(k_slow**2 - kx * kx, 0.0)) + 0.5 * k_fast
        cap_near = min(cap, _NEAR_CAP * k_fast)
        # the fine cap ends at `near`: an interval from below it to far beyond (at small
        # omega, when the next point is set by k_x) would otherwise be cut at the fine cap
        # all the way (7.5 million panels at omega = 1e-6 rad/s)
        points.append(near)
    scale = max(kx, 1e-6 / width)                            # the width of the peak at k_y = 0
    points += list(scale * 1e-2 * 1.5 ** np.arange(int(np.log(end / (scale * 1e-2))
                                                          / np.log(1.5)) + 1))
    points = np.unique(np.clip(points, 0.0, end))
    caps = np.where(points[:-1] < near, cap_near if near else cap, cap)
    pieces = np.maximum(np.ceil(np.diff(points) / caps), 1).astype(int)
    # each interval cut into its pieces of equal width (np.linspace per interval, vectorised)
    panel = np.repeat(np.arange(pieces.size), pieces)
    step = np.arange(panel.size) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    edges = points[panel] + np.diff(points)[panel] * step / pieces[panel]
    return np.append(edges, end)


def _sine_tail(x, kxa, c):
    """c I2(x) - (k_x a)^2 c^3 I4(x) / 2, I_n(x) = int_x^inf sin t / t^n dt: the tail of
    sin(c a k_y) / (a k_y) times 1 / k to first order in (k_x / k_y)^2 (zero for c = 0)."""
    if c == 0:
        return np.zeros_like(x)
    i2 = np.sin(x) / x - sici(x)[1]
    i4 = np.sin(x) / (3 * x**3) + np.cos(x) / (6 * x * x) - i2 / 6.0
    return c * i2 - 0.5 * kxa**2 * c**3 * i4


def _check(ground: Ground, kx, omega, width):
    """|k_x| and omega broadcast to 1-D arrays, and the shape to give back."""
    require_positive("width", width, "m")
    kx, omega = np.broadcast_arrays(np.asarray(kx, dtype=float), np.asarray(omega, dtype=float))
    require_finite("kx", kx, "rad/m")
    require_finite("omega", omega, "rad/s")
    if np.any(omega != 0) and all(s.damping_ratio == 0 for s in ground.strata):
        raise ValueError("strip_flexibility needs some damping (damping_ratio > 0 in a layer or "
                         f"the half-space) at omega={omega[omega != 0].flat[0]} rad/s: undamped, "
                         "the surface waves' poles lie on the path of integration")
    if np.any((omega == 0) & (kx == 0)):
        raise ValueError("kx must be nonzero where omega=0: a static line load on a half-space "
                         "has no finite displacement")
    return np.abs(kx).ravel(), omega.ravel(), kx.shape


def strip_flexibility(ground: Ground, kx, omega, width: float,
                      average: bool = False, offset: float = 0.0) -> np.ndarray:
    """w / P [m^2/N] of the ground under a strip of width b loaded P exp(i (k_x x - omega t)).

    Parameters
    ----------
    ground : Ground
    kx : array_like
        Wavenumber along the track [rad/m].
    omega : array_like
        Circular frequency in the ground's frame [rad/s], broadcast with `kx`
        (for a load moving at v in the ground's frame, omega = Omega + k_x v).
    width : float
        b > 0 [m], the loaded width across the track.
    average : bool
        False: the displacement on the centre line (Dieterman & Metrikine
        1996); True: averaged over the width.
    offset : float
        y [m]: the displacement on the line at y from the centre line instead
        (the ground beside the track; weight sinc(k_y b/2) cos(k_y y)), only
        with ``average=False``.

    Returns
    -------
    ndarray, complex [m^2/N], the broadcast shape of `kx` and `omega`.

    Examples
    --------
    A wide strip at short waves is plane strain: w/P -> F(k_x) / b.

    >>> from railtrack.equations.ground_stiffness import surface_flexibility
    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0, 0.02)
    >>> ratio = strip_flexibility(ground, 2.0, 0.0, 100.0) * 100.0
    >>> round(float(ratio.real / surface_flexibility(ground, 2.0, 0.0).real), 2)
    1.0
    """
    kx, omega, shape_out = _check(ground, kx, omega, width)
    require_finite("offset", offset, "m")
    if average and offset != 0:
        raise ValueError(f"offset={offset!r} m needs average=False: the displacement averaged "
                         "over the strip is taken under the strip")
    # sinc alone falls like 1 / k_y, sinc^2 like 1 / k_y^2: the centre line's tail reaches further
    grids = [_breakpoints(ground, k, w, width, offset, 6.0 if average else 16.0)
             for k, w in zip(kx, omega)]
    nodes, weights, owner = [], [], []
    for i, edges in enumerate(grids):
        mid, half = 0.5 * (edges[1:] + edges[:-1]), 0.5 * np.diff(edges)
        nodes.append((mid[:, None] + half[:, None] * _NODES).ravel())
        weights.append((half[:, None] * _WEIGHTS).ravel())
        owner.append(np.full(nodes[-1].size, i))
    ky, weight, owner = map(np.concatenate, (nodes, weights, owner))
    shape = np.sinc(ky * width / (2.0 * np.pi))              # numpy's sinc is sin(pi x)/(pi x)
    shape = shape * shape if average else shape * np.cos(ky * offset)
    top = ground.strata[0]
    static = (1.0 - top.poisson_ratio) / (top.shear_modulus * top.damping_factor(omega))
    split = kx > 0
    k = np.hypot(kx[owner], ky)
    if np.all(omega == omega[0]):           # one frequency: F(k) from one table for all nodes
        flexibility = radial_flexibility(ground, k, float(omega[0]))
    else:
        flexibility = surface_flexibility(ground, k, omega[owner])
    flexibility = flexibility - np.where(split[owner], static[owner] / k, 0.0)
    values = flexibility * shape * weight
    total = np.bincount(owner, values.real, kx.size) + 1j * np.bincount(owner, values.imag,
                                                                         kx.size)
    x = np.array([g[-1] for g in grids]) * width / 2.0
    sigma = np.where(split, kx * width / 2.0, 1.0)
    if average:
        total += np.where(split, static * _static_average(sigma) + _dynamic_tail(
            ground, kx, omega, static, x, width), static * _average_tail(x, kx, width))
    else:
        c = 2.0 * offset / width
        closed = static * _static_line(sigma, c)
        # sin(a k) cos(y k) = [sin((a + y) k) + sin((a - y) k)] / 2, each term by
        tail = sum(0.5 * np.sign(c) * _sine_tail(x * abs(c), kx * width / 2.0, abs(c))
                   for c in (1.0 + c, 1.0 - c))
        total += np.where(split, closed, static * tail)
    return (total / np.pi).reshape(shape_out)


def _static_line(sigma, c):
    """int_0^inf sinc(t) cos(c t) / sqrt(sigma^2 + t^2) dt, sigma = k_x b / 2 > 0, c = 2 y / b
    (the module's note)."""
    return 0.5 * sum(np.sign(a) * iti0k0(abs(a) * sigma)[1] for a in (1 + c, 1 - c)) / sigma


def _static_average(sigma):
    """int_0^inf sinc^2(t) / sqrt(sigma^2 + t^2) dt, sigma = k_x b / 2 > 0 (the module's note)."""
    return iti0k0(2.0 * sigma)[1] / sigma - (1.0 - 2.0 * sigma * k1(2.0 * sigma)) / (
        2.0 * sigma * sigma)


def _average_tail(x, kx, width):
    """int_Y^inf sinc^2(k_y b/2) / k dk_y, x = b Y / 2: 1/k = 1/k_y - k_x^2 / (2 k_y^3) + ...,
    int_x^inf sin^2 t / t^3 dt, and int_x^inf sin^2 t / t^5 dt to O(x^-5)."""
    tail = np.sin(x) ** 2 / (2 * x * x) + np.sin(2 * x) / (2 * x) - sici(2 * x)[1]
    second = 1.0 / (8.0 * x**4) + np.sin(2 * x) / (4.0 * x**5)
    return tail - 0.5 * (kx * width / 2.0) ** 2 * second


def _dynamic_tail(ground, kx, omega, static, x, width):
    """int_Y^inf (F - F_inf) sinc^2 dk_y for F - F_inf ~ k^-3 beyond Y (sin^2 -> 1/2):
    (F - F_inf)(K) K^3 (2 / b^2) int_Y^inf k_y^-2 k^-3 dk_y, K = sqrt(k_x^2 + Y^2)."""
    end = 2.0 * x / width
    k = np.hypot(kx, end)
    rest = (surface_flexibility(ground, k, omega) - static / k) * k**3
    return rest * 2.0 / width**2 * _inverse_moment(kx, end)


def _inverse_moment(kx, end):
    """int_Y^inf k_y^-2 (k_x^2 + k_y^2)^(-3/2) dk_y in closed form (its series below k_x = Y/100,
    where the closed form cancels)."""
    k2 = kx**2 + end**2
    e2 = (kx / end) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        exact = (np.sqrt(k2) * (2 * end**2 + kx**2) - 2 * end * k2) / (end * kx**4 * k2)
    return np.where(e2 < 1e-4, (1.0 - e2) / (4.0 * end**4), exact)


def strip_stiffness(ground: Ground, kx, omega, width: float,
                    average: bool = False) -> np.ndarray:
    """K_eq = P / w [N/m^2], the ground's equivalent stiffness per unit length of track.

    The inverse of `strip_flexibility` (Dieterman & Metrikine 1996), same
    arguments: the stiffness a beam on the strip feels at wavenumber k_x and
    frequency omega, per unit length.

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0, 0.02)
    >>> k = strip_stiffness(ground, [0.5, 1.0], 0.0, 3.0)
    >>> bool(np.all(k.real > 0)), bool(k[1].real > k[0].real)
    (True, True)
    """
    return 1.0 / strip_flexibility(ground, kx, omega, width, average)


def static_strip_flexibility(ground: Ground, kx, omega, width: float,
                             average: bool = False, offset: float = 0.0) -> np.ndarray:
    """The part of `strip_flexibility` from the top stratum's static F_inf = (1 - nu) / (mu* k).

    Closed form (the module's note), for k_x != 0 [rad/m]; omega [rad/s] enters
    only through the hysteretic damping of mu*; ``offset`` y [m] as in
    `strip_flexibility`.  The rest, strip_flexibility minus this, falls like
    k_x^-3 at short waves.

    Examples
    --------
    >>> ground = Ground.homogeneous(100.0, 0.3, 1800.0, 0.02)
    >>> exact = strip_flexibility(ground, 50.0, 0.0, 2.5, average=True)
    >>> round(float(static_strip_flexibility(ground, 50.0, 0.0, 2.5, True).real / exact.real), 9)
    1.0
    """
    kx = np.abs(np.asarray(kx, dtype=float))
    if np.any(kx == 0):
        raise ValueError("kx must be nonzero: the static part of a line load is infinite at kx=0")
    top = ground.strata[0]
    static = (1.0 - top.poisson_ratio) / (top.shear_modulus * top.damping_factor(omega))
    sigma = kx * width / 2.0
    if average:
        return static * _static_average(sigma) / np.pi
    return static * _static_line(sigma, 2.0 * offset / width) / np.pi
