"""Round-off probe for the book's notebooks (``make test-roundoff``).

Python imports this module at start-up when its folder is on ``PYTHONPATH``.
With ``RAILTRACK_ROUNDOFF_PROBE=δ`` set, every `railtrack.Track` built in the
process has its masses, stiffnesses and dampings multiplied by ``1 + δ``.
A relative change of 1e-12 is far below any digit the book prints, so a
notebook whose compared outputs change under it prints a number decided by
round-off: the kind of number that differs between machines (BLAS kernels,
FFT plans, thread counts).  Geometry (sleeper spacing, wagon length) is left
alone: the time-domain ring needs a whole number of sleepers per wagon.
"""

import os

_DELTA = float(os.environ.get("RAILTRACK_ROUNDOFF_PROBE", "0") or 0.0)

if _DELTA:
    import railtrack.model.track as _track

    _PERTURBED = (
        "rail_linear_mass",
        "rail_bending_stiffness",
        "sleeper_mass",
        "pad_stiffness",
        "pad_damping",
    )
    _validated = _track.Track.__post_init__

    def _perturbed_post_init(self) -> None:
        _validated(self)
        for name in _PERTURBED:
            object.__setattr__(self, name, getattr(self, name) * (1.0 + _DELTA))

    _track.Track.__post_init__ = _perturbed_post_init
