"""The soil's surface beside the track: eq. (G1) at a point y from the centre line.

Harmonic n of the sleepers' forces, f_n e^{-i j q_n} on sleeper j
(`railtrack.equations.ground_lattice`), is a row of waves
e^{i(kappa_m x - omega t)} on the soil, each of amplitude
conj(f_n) sinc(kappa_m a/2) / L per unit length.  The strip answers each at
the line y with C_y(kappa_m, omega), its displacement on that line per unit
line load (`railtrack.equations.ground_layered.LayeredGround.surface_compliance`).
At the point (x = 0, y), the cross-section of sleeper 0, taken at a point and
not averaged over the footprint (one sinc, not two):

    S_y(omega) = (1/L) sum_m C_y(kappa_m, omega) sinc(kappa_m a / 2),
    u_n(y) = R_y(omega_n) f_n,   R_y = conj S_y   [m/N]               (G1y)

the book's eq. (16.6) with C -> C_y and sinc^2 -> sinc.  The lattice sum
is `lattice_sums` with ``power=1``.  Beyond the strip (|y| > b/2) C_y falls
exponentially in |k_x|, and a few wavenumbers carry the sum; under it the
terms fall like |m|^-2 with changing signs, and M = 64 leaves about one
term's size, which the returned estimate shows.

The mean: C_y(0, 0) = 0, as for the footprint, so u_0(y) is measured from
the mean level of the surface along the line y; the settlement of one line
against another under the infinite train's mean load (the trough across the
track) is not given.
"""

from __future__ import annotations

import numpy as np

from ..model.ground_protocol import check_ground
from ..model.validation import require_finite
from .ground_lattice import TERMS, lattice_sums

__all__ = ["surface_receptance"]


def surface_receptance(ground, omega: np.ndarray, speed: float, spacing: float,
                       offset: float, terms: int = TERMS) -> tuple[np.ndarray, np.ndarray]:
    """R_y(omega_n) of eq. (G1y): the surface at y beside sleeper 0 per its force [m/N].

    Parameters
    ----------
    ground : LayeredGround
        A ground with ``surface_compliance(kx, omega, offset)`` [m^2/N]
        besides the coupling's interface (`railtrack.model.ground_protocol`).
    omega : ndarray
        omega_n >= 0 [rad/s]; omega_0 = 0 is the mean.
    speed : float
        v [m/s].
    spacing : float
        L [m].
    offset : float
        y [m], the distance from the track's centre line (either side).
    terms : int
        M, wavenumbers kept on each side.

    Returns
    -------
    receptance : ndarray, complex, shaped like omega
        u_n(y) = R_y,n f_n in eq. (12)'s convention (e^{+i omega_n t}) [m/N].
    error : ndarray
        The lattice sum's error estimate, |S_M - S_{M/2}| [m/N].

    Raises
    ------
    TypeError
        A ground that gives no displacement beside the strip (a Winkler
        bed's springs have no neighbours to move).
    ValueError
        An offset that is not finite.

    Examples
    --------
    Three metres from the centre line the soil moves less than on it:

    >>> from railtrack.model.ground import Ground
    >>> from railtrack.equations.ground_layered import LayeredGround
    >>> soil = LayeredGround(Ground.homogeneous(100.0, 0.3, 1800.0, 0.05), 2.5, 0.25)
    >>> omega = np.array([5.0, 20.0])
    >>> on, _ = surface_receptance(soil, omega, 40.0, 0.6, 0.0)
    >>> off, error = surface_receptance(soil, omega, 40.0, 0.6, 3.0)
    >>> bool(np.all(np.abs(off) < np.abs(on))), bool(np.all(error < 1e-3 * np.abs(off)))
    (True, True)
    """
    check_ground(ground, spacing)
    if not callable(getattr(ground, "surface_compliance", None)):
        raise TypeError(
            f"{type(ground).__name__} gives no displacement beside the track: it needs "
            "surface_compliance(kx, omega, offset), as railtrack.LayeredGround has (a "
            "Winkler bed's springs move only under their own sleeper)")
    require_finite("offset", offset, "m")
    offset = float(offset)
    omega = np.asarray(omega, dtype=float)
    flat = omega.ravel()

    def compliance(kx, w):
        return ground.surface_compliance(kx, w, offset)

    sums, errors = lattice_sums(compliance, flat, flat * spacing / speed, spacing,
                                float(ground.footprint), terms, power=1)
    static = flat == 0
    sums[static] = sums[static].real          # C_y(-k, 0) = conj C_y(k, 0): a real sum
    return np.conj(sums).reshape(omega.shape), errors.reshape(omega.shape)
