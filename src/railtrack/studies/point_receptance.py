"""The receptance of the rail above a sleeper to a harmonic force there (issue 20).

The Floquet–Bloch integral of eq. (3) over the phase between neighbouring
sleepers: the point receptance that `railtrack.studies.p2_force` fits its
equivalent track to.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..equations.hill import complex_receptance
from ..model.cell import SleeperCell
from ..model.foundations import as_foundation
from ..model.passage import Passage
from ..model.track import Track, require_non_negative

__all__ = ["point_receptance", "one_law"]


def one_law(passage, foundation, name: str = "passage"):
    """`foundation` as a law object (a callable wrapped), or a TypeError naming the argument.

    `passage` (called `name` in the message) must be a Track or a Passage.
    """
    if not isinstance(passage, (Track, Passage)):
        raise TypeError(f"{name} must be a railtrack Track or Passage; got {passage!r}")
    if isinstance(foundation, SleeperCell):
        raise TypeError(f"foundation must be one sleeper's law; got a SleeperCell of "
                        f"{foundation.sleepers} sleepers: pass one of them, cell.foundations[j]")
    return as_foundation(foundation)


def _support_stiffness(track, foundation, omega: np.ndarray) -> np.ndarray:
    """Pad in series with the sleeper mass on the foundation: force on the rail per rail w [N/m]."""
    k2, c2 = foundation.linearization()
    pad = track.pad_stiffness + 1j * omega * track.pad_damping
    below = k2 + 1j * omega * c2 - track.sleeper_mass * omega**2
    return pad * below / (pad + below)


def point_receptance(track, foundation, omega: ArrayLike, *, phases: int = 1024,
                     max_phases: int = 2**16, rtol: float = 1e-8) -> np.ndarray:
    """Receptance of the rail above a sleeper to a fixed harmonic force there [m/N].

    The force F e^{i omega t} on one rail seat is the Bloch integral of forces
    F e^{-i n theta} on all of them, each answered by eq. (3) at phase theta
    (`railtrack.equations.hill.complex_receptance`) and the support stiffness
    K (pad in series with the sleeper on the foundation):

        alpha(omega) = (1 / 2 pi) int_{-pi}^{pi} eta / (1 + K eta) d theta.

    The integrand is smooth and 2 pi periodic: the rectangle rule converges
    geometrically.  Its points sit a quarter step off theta = 0, so that the
    even and the odd ones are two rules the symmetry in theta does not make
    equal; `phases` doubles until they agree to `rtol`.

    Parameters
    ----------
    track : Track or Passage
        Rail, pads and sleepers (the speed plays no part).
    foundation : LinearFoundation
        Or any law, or a callable ``f(w, v)``, through its ``linearization()``
        (k2, eta2); one law, not a `railtrack.SleeperCell`.
    omega : array_like
        Angular frequency >= 0 [rad/s].

    Returns
    -------
    ndarray
        Complex alpha, the shape of `omega`, positive along the force.

    Raises
    ------
    ValueError
        If no rule up to `max_phases` converges: an (almost) undamped track
        whose free waves put poles on the path of integration.

    Examples
    --------
    >>> from railtrack import Track, LinearFoundation
    >>> round(1e-6 / float(point_receptance(Track.paper(), LinearFoundation.paper(), 0).real), 2)
    58.32
    """
    foundation = one_law(track, foundation, "track")
    require_non_negative("omega", omega, "rad/s")
    w = np.asarray(omega, dtype=float)[..., None]
    support = _support_stiffness(track, foundation, w)
    while True:
        theta = -np.pi + 2.0 * np.pi * (np.arange(phases) + 0.25) / phases
        with np.errstate(divide="ignore", invalid="ignore"):
            eta = complex_receptance(track, 1j * w, theta)
            g = np.where(np.isfinite(eta), eta / (1.0 + support * eta), 1.0 / support)
        even, odd = g[..., ::2].mean(axis=-1), g[..., 1::2].mean(axis=-1)
        gap = np.abs(even - odd) / np.abs(even + odd) * 2.0
        if np.all(np.isfinite(gap)) and np.all(gap <= rtol):
            return 0.5 * (even + odd)
        if 2 * phases > max_phases:
            worst = np.ravel(omega)[np.argmax(np.where(np.isfinite(gap), gap, np.inf))]
            raise ValueError(f"the Bloch integral of the point receptance has not converged at "
                             f"omega = {worst:.4g} rad/s with {phases} phases: give the pads "
                             "or the foundation some damping")
        phases *= 2
