"""Where the wheels of the ring touch the rail, the profile there, and when they lose contact.

Helpers of `railtrack.timedomain.ring_wheels` (issue 20): the rail element
and Hermite weights under each wheel's contact point x_c = v t - d_j (mod
the ring's length), the rail-top profile r(x_c) (which must repeat with the
ring, or the steady state would not be periodic on it), and the loss of
contact read from a period of contact forces.
"""

from __future__ import annotations

import numpy as np

from ..model.profile_sum import felt_profile
from .fem import RingMesh, wheel_positions

__all__ = ["profile_on_ring", "loss_of_contact"]

_REPEAT_TOLERANCE = 1e-9
"""Largest |ring length / profile period - integer| accepted [-]."""


def profile_on_ring(profile, mesh: RingMesh, times, wagons: int = 1) -> np.ndarray:
    """r(x_c) [m] under every wheel at each time, shape (n_t, J); refuses a non-repeating profile.

    `wagons` is the number of wagons on the ring (for the message only).

    Raises
    ------
    ValueError
        If the profile has a ``period`` that does not divide the ring's length
        (`railtrack.model.profile.CosineDip`), does not repeat with the ring's
        length where the wheels pass, or returns non-finite values.

    Examples
    --------
    >>> from railtrack import Passage
    >>> from railtrack.model.profile import CosineDip
    >>> from railtrack.timedomain.fem import ring_mesh
    >>> profile_on_ring(CosineDip(1e-3, 1.0, 7.0), ring_mesh(Passage.paper(), 1), [0.0])
    Traceback (most recent call last):
    ...
    ValueError: the rail-top profile must repeat with the ring (length 18 m = 1 wagon(s) of 18 m): its period 7 m does not divide it (18 / 7 = 2.571); use a period of 18 m / k, or a ring of wagons such that wagons x 18 m is a multiple of 7 m
    """
    ring = float(mesh.passage.wagon_length)
    wagon = ring / wagons
    period = getattr(profile, "period", None)
    where = (f"the rail-top profile must repeat with the ring (length {ring:g} m = "
             f"{wagons} wagon(s) of {wagon:g} m)")
    if period is not None:
        ratio = ring / float(period)
        if abs(ratio - round(ratio)) > _REPEAT_TOLERANCE * max(1.0, ratio) or round(ratio) < 1:
            raise ValueError(
                f"{where}: its period {float(period):g} m does not divide it "
                f"({ring:g} / {float(period):g} = {ratio:.4g}); use a period of {ring:g} m / k, "
                f"or a ring of wagons such that wagons x {wagon:g} m is a multiple of "
                f"{float(period):g} m")
    x = wheel_positions(mesh.passage, times)
    per_wagon = x.shape[1] // wagons                   # a wheel flat: its own wheel only
    values = felt_profile(profile, x, per_wagon, axis=1)
    shifted = felt_profile(profile, x + ring, per_wagon, axis=1)
    if values.shape != x.shape or not np.all(np.isfinite(values)):
        raise ValueError(f"the rail-top profile must return finite values of x's shape {x.shape}; "
                         f"got shape {values.shape}")
    scale = max(float(np.max(np.abs(values))), 1e-12)
    if not np.allclose(shifted, values, rtol=0.0, atol=1e-9 * scale):
        raise ValueError(f"{where}: r(x + {ring:g} m) differs from r(x) by up to "
                         f"{float(np.max(np.abs(shifted - values))):.3g} m where the wheels pass")
    return values


def loss_of_contact(contact_forces: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Share of the period with P = 0 and the longest such stretch, per wheel.

    The record is one period of a periodic state, so a stretch running over
    the period's end continues at its start.

    Parameters
    ----------
    contact_forces : ndarray, shape (steps, J)
        P [N] at each step of one period.
    dt : float
        Time step [s].

    Returns
    -------
    share : ndarray, shape (J,)
        Steps with P = 0 over all steps [-].
    longest : ndarray, shape (J,)
        Longest run of consecutive steps with P = 0, times dt [s].

    Examples
    --------
    >>> P = np.array([[0.0], [1.0], [2.0], [0.0], [0.0]])
    >>> loss_of_contact(P, 0.5)
    (array([0.6]), array([1.5]))
    """
    lost = np.asarray(contact_forces) <= 0.0
    steps = lost.shape[0]
    share = lost.mean(axis=0)
    longest = np.zeros(lost.shape[1])
    for j in range(lost.shape[1]):
        if lost[:, j].all():
            longest[j] = steps
            continue
        run = best = 0
        for value in np.concatenate([lost[:, j], lost[:, j]]):  # twice: wrap-around
            run = run + 1 if value else 0
            best = max(best, run)
        longest[j] = min(best, steps)
    return share, longest * dt
