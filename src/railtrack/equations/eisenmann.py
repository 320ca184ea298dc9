"""Eisenmann's dynamic wheel load: an empirical factor from measurements on German track.

As Esveld gives it (C. Esveld, *Modern Railway Track*, 2nd ed., 2001, after
J. Eisenmann's measurements of the 1960s-70s; ``esveld2001`` in
book/references.bib): the wheel load scatters normally about the static
load Q with the standard deviation

    sigma / Q = n phi,
    n = 0.1 (very good track), 0.2 (good), 0.3 (poor),
    phi = 1 for V < 60 km/h,  1 + (V - 60) / 140 for 60 <= V <= 200 km/h,

and the load not exceeded with the probability of the interval Q -+ t sigma,

    Q_dyn = Q (1 + t n phi),   t = 1, 2, 3 for 68.3, 95.5, 99.7 %.

The factors t and n are checked against Balmaseda et al., "360.revista de
Alta Velocidad" no. 5, p. 302 (the page found by the project's search,
https://tecnica-vialibre.es/360rav/revistas/360AV05online/files/basic-html/page304.html);
the speed factor phi is the form the project's maintainers recall from
Esveld's book: no source we could read states it, so it is unchecked.  It
is a regression on measured loads: an order of magnitude beside a model,
not a check of it.
"""

from __future__ import annotations

import numpy as np

__all__ = ["TRACK_CONDITION", "eisenmann_speed_factor", "eisenmann_std_ratio",
           "eisenmann_dynamic_load"]

TRACK_CONDITION = {"very good": 0.1, "good": 0.2, "poor": 0.3}
"""n of the track's condition [-]."""


def eisenmann_speed_factor(speed: float) -> float:
    """phi [-] at the speed V [m/s] (module docstring); V above 200 km/h is refused.

    >>> eisenmann_speed_factor(200 / 3.6)
    2.0
    """
    speed = float(speed)
    kmh = 3.6 * speed
    if not (np.isfinite(speed) and speed >= 0):
        raise ValueError(f"speed must be finite and >= 0 [m/s]; got {speed!r}")
    if kmh > 200.0 + 1e-9:
        raise ValueError(f"Eisenmann's speed factor is given up to 200 km/h; got "
                         f"{kmh:.4g} km/h ({speed:.4g} m/s)")
    return 1.0 if kmh < 60.0 else 1.0 + (min(kmh, 200.0) - 60.0) / 140.0


def eisenmann_std_ratio(speed: float, condition: str = "good") -> float:
    """sigma / Q = n phi [-] at the speed V [m/s] on a track in this `condition`."""
    if condition not in TRACK_CONDITION:
        raise ValueError(f"condition must be one of {sorted(TRACK_CONDITION)}; got "
                         f"{condition!r}")
    return TRACK_CONDITION[condition] * eisenmann_speed_factor(speed)


def eisenmann_dynamic_load(load: float, speed: float, condition: str = "good",
                           t: int = 3) -> float:
    """Q_dyn = Q (1 + t n phi) [N] for the static wheel load Q [N], t = 1, 2 or 3.

    >>> round(eisenmann_dynamic_load(100e3, 50 / 3.6, "poor", 2) / 1e3, 6)    # kN
    160.0
    """
    if t not in (1, 2, 3):
        raise ValueError(f"t must be 1, 2 or 3 (68.3, 95.5, 99.7 %); got {t!r}")
    return float(load) * (1.0 + t * eisenmann_std_ratio(speed, condition))
