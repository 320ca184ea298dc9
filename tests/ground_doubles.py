"""Test doubles of the ground (railtrack.model.ground_protocol.GroundCompliance) with known Green functions."""

import numpy as np

L = 0.6


class SmearedLayer:
    """C(k, omega) = 1 / (s0 + s2 k^2 - rho omega^2 - i omega eta): a membrane on springs,
    an elastic layer smeared along the track (a test double whose Green function is known)."""

    def __init__(self, s0=1e8, s2=1e7, rho=1500.0, eta=2e5, footprint=0.25):
        self.s0, self.s2, self.rho, self.eta, self.footprint = s0, s2, rho, eta, footprint

    def compliance(self, kx, omega):
        kx = np.asarray(kx, dtype=float)
        return 1.0 / (self.s0 + self.s2 * kx**2 - self.rho * omega**2 - 1j * omega * self.eta)

    def space_sum(self, omega, q, sleepers=400):
        """conj of sum_j e^{i j q} (footprint-averaged Green function between sleepers 0 and j).

        G(x) = e^{-gamma |x|} / (2 s2 gamma); averaged over two footprints a apart by jL it is
        G(jL) (sinh(gamma a/2) / (gamma a/2))^2, over one footprint with itself
        (gamma a - 1 + e^{-gamma a}) / (s2 gamma^3 a^2): `test_footprint_averages_by_sympy`.
        """
        gamma = np.sqrt((self.s0 - self.rho * omega**2 - 1j * omega * self.eta) / self.s2)
        gamma = gamma if gamma.real > 0 else -gamma
        z = gamma * self.footprint
        self_term = (z - 1 + np.exp(-z)) / (self.s2 * gamma**3 * self.footprint**2)
        j = np.arange(1, sleepers + 1)
        pair = np.exp(-gamma * j * L) / (2 * self.s2 * gamma) * (np.sinh(z / 2) / (z / 2)) ** 2
        total = self_term + np.sum(pair * 2 * np.cos(j * q))
        return np.conj(total)
