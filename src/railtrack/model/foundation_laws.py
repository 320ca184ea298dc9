"""The closed-form foundation laws of Section 4: eqs. (22), (24) and (25).

`LinearFoundation` (eq. 22, and the ballasted track's single layer),
`BilinearFoundation` (eq. 24: stiffer in compression than in tension) and
`CubicFoundation` (eq. 25: a cubic stiffness term), each with the paper's
values (`paper`), and `PAPER_STIFFNESS` and `PAPER_DAMPING` that they
share.  Each has the ``force``, ``tangent`` and ``linearization`` that
`railtrack.model.foundations.Foundation` asks of a law; w is positive
upward, so the train compresses the foundation at w < 0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .plausibility_check import check_plausible, quantities_to_si
from .track import as_float64, require_non_negative, require_positive

__all__ = [
    "LinearFoundation",
    "BilinearFoundation",
    "CubicFoundation",
    "PAPER_STIFFNESS",
    "PAPER_DAMPING",
]

PAPER_DAMPING = 0.2e6
"""eta_2 of Section 4.1 [N s/m], used for all three laws of the paper."""
PAPER_STIFFNESS = 20e6
"""k_2 (and k_2^+) of Section 4 [N/m]."""


@dataclass(frozen=True)
class LinearFoundation:
    """Linear viscoelastic foundation f = k2 w + eta2 w', eq. (22).

    Parameters
    ----------
    stiffness : float
        k2 > 0 [N/m].
    damping : float
        eta2 >= 0 [N s/m].

    Examples
    --------
    >>> float(LinearFoundation.paper().force(-1e-3, 0.0))    # 1 mm down: the foundation pushes up
    -20000.0
    """

    stiffness: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("stiffness", self.stiffness, "N/m")
        require_non_negative("damping", self.damping, "N s/m")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def paper(cls) -> "LinearFoundation":
        """k2 = 20 MN/m, eta2 = 0.2 MN s/m (Section 4.1)."""
        return cls(PAPER_STIFFNESS, PAPER_DAMPING)

    @classmethod
    def ballasted(cls) -> "LinearFoundation":
        """Ballast and subgrade of Zhai, Wang & Lin (2004) in series: 49.6 MN/m, 20.4 kN s/m.

        The single-layer equivalent of `railtrack.model.ballast.single_layer`; for
        `railtrack.Track.ballasted()`.
        """
        from .ballast import ZHAI_2004 as z, single_layer

        layer = single_layer(z["ballast_mass"], z["ballast_stiffness"], z["ballast_damping"],
                             z["subgrade_stiffness"], z["subgrade_damping"])
        return cls(layer.stiffness, layer.damping)

    def force(self, w, v):
        return self.stiffness * np.asarray(w) + self.damping * np.asarray(v)

    def tangent(self, w, v):
        return _tangent_pair(np.broadcast_to(np.asarray(self.stiffness, dtype=float),
                                             np.broadcast_shapes(np.shape(w),
                                                                 np.shape(self.stiffness))),
                             self.damping, v)

    def linearization(self) -> tuple[float, float]:
        return float(self.stiffness), float(self.damping)


@dataclass(frozen=True)
class BilinearFoundation:
    """Foundation stiffer in compression than in tension, eq. (24).

    ``f = k2+ w + eta2 w'`` when w < 0 (compression) and
    ``f = k2- w + eta2 w'`` when w >= 0 (tension).  A tension stiffness of
    zero is a tensionless foundation: the sleeper lifts off freely.

    Parameters
    ----------
    compression_stiffness : float
        k2+ > 0 [N/m].
    tension_stiffness : float
        k2- >= 0 [N/m].
    damping : float
        eta2 >= 0 [N s/m].
    """

    compression_stiffness: float
    tension_stiffness: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("compression_stiffness", self.compression_stiffness, "N/m")
        require_non_negative("tension_stiffness", self.tension_stiffness, "N/m")
        require_non_negative("damping", self.damping, "N s/m")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def paper(cls, ratio: float = 0.5) -> "BilinearFoundation":
        """k2+ = 20 MN/m, k2- = ratio * k2+, eta2 = 0.2 MN s/m (Section 4.2)."""
        return cls(PAPER_STIFFNESS, ratio * PAPER_STIFFNESS, PAPER_DAMPING)

    @property
    def ratio(self) -> float:
        """e = k2- / k2+, the tension/compression ratio of Fig. 5."""
        return self.tension_stiffness / self.compression_stiffness

    def _stiffness(self, w):
        return np.where(
            np.asarray(w) < 0, self.compression_stiffness, self.tension_stiffness
        )

    def force(self, w, v):
        return self._stiffness(w) * np.asarray(w) + self.damping * np.asarray(v)

    def tangent(self, w, v):
        return _tangent_pair(self._stiffness(w), self.damping, v)

    def linearization(self) -> tuple[float, float]:
        # The train compresses the foundation on average.
        return float(self.compression_stiffness), float(self.damping)


@dataclass(frozen=True)
class CubicFoundation:
    """Foundation with a cubic stiffness term, f = eta2 w' + k2 w + eps k3 w^3, eq. (25).

    Parameters
    ----------
    stiffness : float
        k2 > 0 [N/m].
    cubic_stiffness : float
        k3 >= 0 [N/m^3].
    epsilon : float
        Nonlinearity parameter eps >= 0 [-].  eps = 0 is the linear law.
    damping : float
        eta2 >= 0 [N s/m].
    """

    stiffness: float
    cubic_stiffness: float
    epsilon: float = 1.0
    damping: float = 0.0

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("stiffness", self.stiffness, "N/m")
        require_non_negative("cubic_stiffness", self.cubic_stiffness, "N/m^3")
        require_non_negative("epsilon", self.epsilon)
        require_non_negative("damping", self.damping, "N s/m")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def paper(cls, epsilon: float = 0.8) -> "CubicFoundation":
        """k2 = 20 MN/m, k3 = 20 kN/mm^3 = 2e13 N/m^3, eta2 = 0.2 MN s/m (Section 4.3)."""
        return cls(PAPER_STIFFNESS, 2e13, epsilon, PAPER_DAMPING)

    def force(self, w, v):
        w = np.asarray(w)
        return (
            self.damping * np.asarray(v)
            + self.stiffness * w
            + self.epsilon * self.cubic_stiffness * w * w * w
        )

    def tangent(self, w, v):
        w = np.asarray(w)
        stiffness = self.stiffness + 3.0 * self.epsilon * self.cubic_stiffness * w * w
        return _tangent_pair(stiffness, self.damping, v)

    def linearization(self) -> tuple[float, float]:
        return float(self.stiffness), float(self.damping)


def _tangent_pair(stiffness, damping, v) -> tuple[np.ndarray, np.ndarray]:
    """(df/dw, df/dw') broadcast to one shape [N/m], [N s/m].

    The time-domain ring asks for this several times per step with w and v
    of one shape and a scalar damping: that case skips the broadcasting.
    """
    stiffness = np.asarray(stiffness, dtype=float)
    if np.ndim(damping) == 0 and stiffness.shape == np.shape(v):
        return stiffness, np.full(stiffness.shape, float(damping))
    shape = np.broadcast_shapes(stiffness.shape, np.shape(v), np.shape(damping))
    return (np.broadcast_to(stiffness, shape),
            np.broadcast_to(np.asarray(damping, dtype=float), shape))
