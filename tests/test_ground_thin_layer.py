"""The layered ground's surface flexibility against the thin-layer method (a second method).

The thin-layer method (Kausel & Roesset's companion: finite elements in depth,
exact in x) cuts each stratum into sublayers with linear shape functions and
assembles k^2 A + i k B + G - omega^2 M from Hooke's law directly; a rigid
base is a fixed bottom node.  Its error is O(h^2) in the sublayer thickness
h, so two meshes (h and h/2) extrapolated by Richardson give O(h^4).  Nothing
of it is shared with `railtrack.equations.ground_stiffness` except the soil.
"""

import numpy as np
import pytest

from railtrack import plausibility
from railtrack.equations.ground_stiffness import surface_flexibility
from railtrack.model.ground import Ground, SoilLayer

TOP = SoilLayer(80.0, 0.3, 1700.0, 0.05, thickness=3.0)
MIDDLE = SoilLayer(200.0, 0.35, 1900.0, 0.03, thickness=4.0)
with plausibility("ignore"):                        # no rock is this stiff: meant
    ROCK = SoilLayer(200.0 * 1e8, 0.3, 2000.0)      # impedance ~1e8 times the soil's: rigid


def _thin_layers(strata, k, omega, per_metre):
    """w/p at the surface of `strata` on a rigid base, by linear thin layers."""
    lam_mu_rho_h = []
    for layer in strata:
        n = int(round(layer.thickness * per_metre))
        factor = complex(layer.damping_factor(omega))
        lam_mu_rho_h += [(layer.lame_lambda * factor, layer.shear_modulus * factor,
                          layer.density, layer.thickness / n)] * n
    size = 2 * (len(lam_mu_rho_h) + 1)
    total = np.zeros((size, size), dtype=complex)
    pick_x = np.array([[1, 0], [0, 0], [0, 1]])      # strains (e_xx, e_zz, g_xz) from d/dx
    pick_z = np.array([[0, 0], [0, 1], [1, 0]])      # ... and from d/dz
    for j, (lam, mu, rho, h) in enumerate(lam_mu_rho_h):
        d = np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]])
        # N = [(1 - s) I, s I] with s = z / h; the Galerkin form of the test field
        # N exp(-i k x) against u = N U exp(i k x) gives k^2 A + i k (C^T - C) + G
        n_n = h / 6 * np.array([[2, 1], [1, 2]])                     # int N_a N_b dz
        n_dn = 0.5 * np.array([[-1, 1], [-1, 1]])                    # int N_a N_b' dz
        dn_dn = np.array([[1, -1], [-1, 1]]) / h                     # int N_a' N_b' dz
        a = np.kron(n_n, pick_x.T @ d @ pick_x)
        c = np.kron(n_dn, pick_x.T @ d @ pick_z)
        g = np.kron(dn_dn, pick_z.T @ d @ pick_z)
        mass = rho * np.kron(n_n, np.eye(2))
        total[2 * j:2 * j + 4, 2 * j:2 * j + 4] += (k * k * a + 1j * k * (c.T - c) + g
                                                    - omega**2 * mass)
    load = np.zeros(size - 2, dtype=complex)
    load[1] = 1.0
    return np.linalg.solve(total[:-2, :-2], load)[1]                 # bottom node fixed


@pytest.mark.parametrize("k, omega", [(0.05, 0.0), (1.0, 0.0), (0.3, 60.0), (1.5, 120.0),
                                      (3.0, 200.0), (0.02, 150.0)])
def test_the_stiffness_matrices_agree_with_thin_layers(k, omega):
    strata = (TOP, MIDDLE)
    coarse, fine = (_thin_layers(strata, k, omega, n) for n in (20, 40))
    thin = (4 * fine - coarse) / 3
    ours = surface_flexibility(Ground(strata, ROCK), k, omega)
    assert abs(ours / thin - 1) < 2e-5
    # closer to the extrapolation than the finer mesh is: the agreement is not the mesh's luck
    assert abs(ours / thin - 1) < 0.1 * abs(fine / thin - 1)
