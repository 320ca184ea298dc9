"""The rail's beam elements in the finite-element ring: Euler–Bernoulli and Timoshenko.

The ring's rail (`railtrack.timedomain.fem`) is by default an Euler–Bernoulli
beam of Hermite cubic elements (`hermite_shape_functions`,
`beam_element_matrices`).  With a `railtrack.model.timoshenko.TimoshenkoRail`
it is a Timoshenko beam instead (the equations of `TimoshenkoRail`: shear
stiffness kappa G A, rotary inertia rho I), discretised by the standard
two-node element of Przemieniecki (Theory of Matrix Structural Analysis,
1968, sec. 5.6) with the consistent mass of Friedman & Kosmatka (Computers &
Structures 47, 1993, 473-481), the "interdependent interpolation element".
Its degrees of freedom are (w_a, psi_a, w_b, psi_b): the deflection w
(upward) and the rotation psi of the sections (dw/dx of the Euler–Bernoulli
element, to which it reduces) at its two ends.  Everything depends on the
element's shear parameter

    Phi = 12 EI / (kappa G A h^2),                                    (T1)

h the element's length.  The shape functions are the exact static solution
of the Timoshenko beam for given end values (w cubic, psi quadratic, the
shear strain w' - psi constant):

    N_w = [1 + Phi - Phi xi - 3 xi^2 + 2 xi^3,
           h (xi (1 + Phi/2) - xi^2 (2 + Phi/2) + xi^3),
           Phi xi + 3 xi^2 - 2 xi^3,
           h (-xi Phi/2 - xi^2 (1 - Phi/2) + xi^3)] / (1 + Phi),        (T2)
    N_psi = [6 (xi^2 - xi) / h, 1 + Phi - (4 + Phi) xi + 3 xi^2,
             -6 (xi^2 - xi) / h, -(2 - Phi) xi + 3 xi^2] / (1 + Phi),   (T3)

xi = x / h in [0, 1].  The stiffness ``int EI N_psi'^T N_psi' + kGA (N_w' -
N_psi)^T (N_w' - N_psi) dx`` and the consistent mass ``int rho S N_w^T N_w +
rho I N_psi^T N_psi dx`` are `timoshenko_element_matrices` (T4, T5).  Since
(T2) is the exact static deflection, the element carries any static nodal
load exactly, and the consistent load of a point force anywhere in it (the
wheels') gives exact nodal values: there is no shear locking, however large
Phi (on the UIC60 rail Phi = 54 at 8 elements per 0.6 m span).  That is why
the wheels of the ring (`railtrack.timedomain.fem.rail_shapes`) read and load
a Timoshenko rail through N_w and not the Hermite cubics: these would take
psi for dw/dx, although at such Phi most of the deflection within an element
is shear, and their loads would not be work-consistent with (T4, T5).  The
bending moment is EI psi' (`timoshenko_curvature_weights`).  The element's
shear strain is constant, so its frequencies converge as h^2 (the Hermite
element's as h^4).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.timoshenko import TimoshenkoRail

__all__ = [
    "hermite_shape_functions",
    "beam_element_matrices",
    "shear_parameter",
    "timoshenko_element_matrices",
    "timoshenko_shape_functions",
    "timoshenko_rotation_shapes",
    "timoshenko_curvature_weights",
    "timoshenko_point_compliance",
]


def hermite_shape_functions(xi: ArrayLike, length: float) -> np.ndarray:
    """Hermite cubics of a beam element at local coordinate xi in [0, 1].

    Parameters
    ----------
    xi : array_like
        Position in the element divided by its length [-].
    length : float
        Element length h [m].

    Returns
    -------
    ndarray, shape (..., 4)
        Weights of (w_a, theta_a, w_b, theta_b): the deflection at xi is their
        dot product with the nodal values.  The rotation shapes carry the
        factor h so that theta is dw/dx [rad].
    """
    xi = np.asarray(xi, dtype=float)
    xi2, xi3 = xi * xi, xi * xi * xi
    return np.stack(
        [
            1.0 - 3.0 * xi2 + 2.0 * xi3,
            length * (xi - 2.0 * xi2 + xi3),
            3.0 * xi2 - 2.0 * xi3,
            length * (xi3 - xi2),
        ],
        axis=-1,
    )


def beam_element_matrices(
    bending_stiffness: float, linear_mass: float, length: float
) -> tuple[np.ndarray, np.ndarray]:
    """Stiffness [N/m, N, N m] and consistent mass [kg, kg m, kg m^2] of one element, eq. (1).

    The classical 4 x 4 matrices of the Hermite cubic Euler–Bernoulli element
    for DOFs (w_a, theta_a, w_b, theta_b).  Between point forces the static
    beam deflection is a cubic, so nodal values of a static solution are
    exact; only the inertia is approximated.
    """
    h = length
    stiffness = bending_stiffness / h**3 * np.array(
        [
            [12.0, 6.0 * h, -12.0, 6.0 * h],
            [6.0 * h, 4.0 * h * h, -6.0 * h, 2.0 * h * h],
            [-12.0, -6.0 * h, 12.0, -6.0 * h],
            [6.0 * h, 2.0 * h * h, -6.0 * h, 4.0 * h * h],
        ]
    )
    mass = linear_mass * h / 420.0 * np.array(
        [
            [156.0, 22.0 * h, 54.0, -13.0 * h],
            [22.0 * h, 4.0 * h * h, 13.0 * h, -3.0 * h * h],
            [54.0, 13.0 * h, 156.0, -22.0 * h],
            [-13.0 * h, -3.0 * h * h, -22.0 * h, 4.0 * h * h],
        ]
    )
    return stiffness, mass


def shear_parameter(bending_stiffness: float, shear_stiffness: float, length: float) -> float:
    """Phi = 12 EI / (kappa G A h^2) of an element of length h [-], eq. (T1).

    Parameters
    ----------
    bending_stiffness : float
        EI [N m^2].
    shear_stiffness : float
        kappa G A [N].
    length : float
        h [m].
    """
    return 12.0 * float(bending_stiffness) / (float(shear_stiffness) * float(length) ** 2)


def timoshenko_element_matrices(
    bending_stiffness: float, linear_mass: float, rail: TimoshenkoRail, length: float
) -> tuple[np.ndarray, np.ndarray]:
    """Stiffness [N/m, N, N m] and consistent mass [kg, kg m, kg m^2] of one Timoshenko element.

    For DOFs (w_a, psi_a, w_b, psi_b), with Phi of eq. (T1) (Przemieniecki 1968;
    Friedman & Kosmatka 1993):

        K = EI / ((1 + Phi) h^3) [[12, 6h, -12, 6h], [6h, (4 + Phi) h^2, -6h, (2 - Phi) h^2],
                                 [-12, -6h, 12, -6h], [6h, (2 - Phi) h^2, -6h, (4 + Phi) h^2]], (T4)

        M = rho S h / (210 (1 + Phi)^2) M_w + rho I / (30 (1 + Phi)^2 h) M_psi,          (T5)

    M_w the translational matrix, quadratic in Phi, and M_psi the rotary one.
    Phi = 0 and rho I = 0 give `railtrack.timedomain.fem.beam_element_matrices`.

    Parameters
    ----------
    bending_stiffness : float
        EI [N m^2].
    linear_mass : float
        rho S [kg/m].
    rail : TimoshenkoRail
        kappa G A [N] and rho I [kg m].
    length : float
        h [m].
    """
    h = float(length)
    ei = float(bending_stiffness)
    phi = shear_parameter(ei, rail.shear_stiffness, h)
    stiffness = ei / ((1.0 + phi) * h**3) * np.array(
        [
            [12.0, 6.0 * h, -12.0, 6.0 * h],
            [6.0 * h, (4.0 + phi) * h * h, -6.0 * h, (2.0 - phi) * h * h],
            [-12.0, -6.0 * h, 12.0, -6.0 * h],
            [6.0 * h, (2.0 - phi) * h * h, -6.0 * h, (4.0 + phi) * h * h],
        ]
    )
    p2 = phi * phi
    a = 70.0 * p2 + 147.0 * phi + 78.0
    b = (35.0 * p2 + 77.0 * phi + 44.0) * h / 4.0
    c = 35.0 * p2 + 63.0 * phi + 27.0
    d = (35.0 * p2 + 63.0 * phi + 26.0) * h / 4.0
    e = (7.0 * p2 + 14.0 * phi + 8.0) * h * h / 4.0
    f = (7.0 * p2 + 14.0 * phi + 6.0) * h * h / 4.0
    translation = np.array([[a, b, c, -d], [b, e, d, -f], [c, d, a, -b], [-d, -f, -b, e]])
    g = (3.0 - 15.0 * phi) * h
    r = (10.0 * p2 + 5.0 * phi + 4.0) * h * h
    s = (5.0 * p2 - 5.0 * phi - 1.0) * h * h
    rotation = np.array([[36.0, g, -36.0, g], [g, r, -g, s], [-36.0, -g, 36.0, -g],
                         [g, s, -g, r]])
    scale = (1.0 + phi) ** 2
    mass = (float(linear_mass) * h / (210.0 * scale) * translation
            + float(rail.rotary_inertia) / (30.0 * scale * h) * rotation)
    return stiffness, mass


def timoshenko_shape_functions(xi: ArrayLike, length: float, phi: float) -> np.ndarray:
    """N_w of eq. (T2): weights of (w_a, psi_a, w_b, psi_b) giving the deflection at xi.

    Parameters
    ----------
    xi : array_like
        Position in the element over its length [-], in [0, 1].
    length : float
        h [m].
    phi : float
        Phi of eq. (T1) [-]; 0 gives the Hermite cubics.

    Returns
    -------
    ndarray, shape (..., 4)
        [-, m, -, m].
    """
    xi = np.asarray(xi, dtype=float)
    xi2, xi3 = xi * xi, xi * xi * xi
    h, half = float(length), 0.5 * phi
    return np.stack(
        [
            1.0 + phi - phi * xi - 3.0 * xi2 + 2.0 * xi3,
            h * ((1.0 + half) * xi - (2.0 + half) * xi2 + xi3),
            phi * xi + 3.0 * xi2 - 2.0 * xi3,
            h * (-half * xi - (1.0 - half) * xi2 + xi3),
        ],
        axis=-1,
    ) / (1.0 + phi)


def timoshenko_rotation_shapes(xi: ArrayLike, length: float, phi: float) -> np.ndarray:
    """N_psi of eq. (T3): weights of (w_a, psi_a, w_b, psi_b) giving the rotation psi at xi.

    Returns
    -------
    ndarray, shape (..., 4)
        [1/m, -, 1/m, -].
    """
    xi = np.asarray(xi, dtype=float)
    h, quad = float(length), xi * xi
    end = 6.0 * (quad - xi) / h
    return np.stack([end, 1.0 + phi - (4.0 + phi) * xi + 3.0 * quad, -end,
                     -(2.0 - phi) * xi + 3.0 * quad], axis=-1) / (1.0 + phi)


def timoshenko_curvature_weights(xi: float, length: float, phi: float) -> np.ndarray:
    """d N_psi / dx at xi: weights of (w_a, psi_a, w_b, psi_b) giving psi' [1/m^2, 1/m].

    EI psi' is the bending moment of the Timoshenko beam (sagging positive);
    at Phi = 0 these are the Hermite cubics' second derivatives.
    """
    h = float(length)
    return np.array([6.0 * (2.0 * xi - 1.0) / h**2, (6.0 * xi - 4.0 - phi) / h,
                     -6.0 * (2.0 * xi - 1.0) / h**2, (6.0 * xi - 2.0 + phi) / h]) / (1.0 + phi)


def timoshenko_point_compliance(xi: ArrayLike, length: float, bending_stiffness: float,
                                phi: float) -> np.ndarray:
    """g(xi): deflection [m/N] at a unit force at xi inside an element clamped at both ends.

    With eta = xi (1 - xi),

        g = h^3 eta (4 eta^2 + Phi (1 + eta) + Phi^2) / (12 EI (1 + Phi)),        (T6)

    the static condensation of a node at the force (two elements of lengths
    xi h and (1 - xi) h, exact statically): the part of the beam's static
    deflection under a force inside an element that the interpolation (T2)
    of the nodal values misses.  It vanishes at the nodes; Phi = 0 gives the
    Euler–Bernoulli h^3 eta^3 / (3 EI), and at mid-element
    g = h^3 / (192 EI) + h / (4 kappa G A), the clamped beam's central
    deflection.  For a wheel on a shear-flexible rail the shear part is what
    matters: with Q = 75 kN at h = 7.5 cm on UIC60, 5.7 um.

    Parameters
    ----------
    xi : array_like
        Position of the force in the element over its length [-], in [0, 1].
    length : float
        h [m].
    bending_stiffness : float
        EI [N m^2].
    phi : float
        Phi of eq. (T1) [-].
    """
    eta = np.asarray(xi, dtype=float) * (1.0 - np.asarray(xi, dtype=float))
    h = float(length)
    return (h**3 * eta * (4.0 * eta * eta + phi * (1.0 + eta) + phi * phi)
            / (12.0 * float(bending_stiffness) * (1.0 + phi)))
