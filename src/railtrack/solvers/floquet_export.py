"""A `railtrack.Floquet` result as an `xarray.Dataset`.

On ``multiplier`` (by decreasing modulus): multiplier_real, _imag and
multiplier_modulus [1], exponent_real, _imag [s-1], phase [rad], tail [1],
resolved; eigenvector_real, _imag on ``(multiplier, harmonic)`` where kept;
the phases asked for on ``base_phase`` [rad]; the verdict, the kind and
the dominant multiplier in the attributes.  Rules as
`railtrack.solvers.export`.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from .export import base_attrs, complex_parts, flag, variable

__all__ = ["floquet_dataset"]


def floquet_dataset(result) -> xr.Dataset:
    """A `railtrack.Floquet`: its multipliers, exponents, phases and what decides the verdict."""
    dims = "multiplier"
    data = complex_parts("multiplier", dims, result.multipliers, "1",
                         "Floquet multiplier mu per period")
    data["multiplier_modulus"] = variable(dims, np.abs(result.multipliers), "1",
                                          "modulus of the Floquet multiplier")
    data.update(complex_parts("exponent", dims, result.exponents, "s-1",
                              "Floquet exponent lambda"))
    data["phase"] = variable(dims, result.phases, "rad", "Bloch phase per sleeper")
    data["tail"] = variable(dims, result.tail, "1", "share of the eigenvector on the top "
                                                    "fifth of the harmonics")
    data["resolved"] = variable(dims, np.asarray(result.resolved, dtype=bool), "1",
                                "whether the truncation resolves the exponent")
    coords = {"multiplier": variable(dims, np.arange(len(result.multipliers)), "1",
                                     "index of the multiplier, by decreasing modulus"),
              "base_phase": variable("base_phase", result.base_phases, "rad",
                                     "Bloch phase asked for (each with its shifts)")}
    vectors = result.vectors
    if vectors is not None and np.size(vectors):
        m = (vectors.shape[1] - 1) // 2
        data.update(complex_parts("eigenvector", (dims, "harmonic"), vectors, "1",
                                  "eigenvector on harmonics -m..m, unit norm"))
        coords["harmonic"] = variable("harmonic", np.arange(-m, m + 1), "1",
                                      "harmonic number n of the wagon-passing frequency")
    attrs = base_attrs(
        "Floquet", "Floquet multipliers of a periodic solution (railtrack)",
        verdict=result.verdict, kind=result.kind, frequency=result.frequency,
        theta=result.theta, most_unstable=result.most_unstable, period=result.period,
        harmonics=result.harmonics, message=result.message, bound=result.bound,
        continued=flag(result.continued), ceiling=result.ceiling,
        dominant_multiplier_real=float(np.real(result.dominant)),
        dominant_multiplier_imag=float(np.imag(result.dominant)))
    return xr.Dataset(data, coords=coords, attrs=attrs)
