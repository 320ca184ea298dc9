"""The studies as `xarray.Dataset`: Sweep, Branch and RandomSupport, one entry per member.

A sweep of one field runs along a dimension named after it (``speed``),
of several along ``member`` with each field as a coordinate; a branch
along ``point`` (its parameter may turn back at a fold, so it is a
coordinate, not the index); a random-support study along ``draw``.  A
member that did not converge keeps NaN where it has no value, and its
stability reads "unknown", never "unstable".

* Sweep: converged, iterations, residual, truncation_error [1]; lowest,
  highest [m]; seat_load_peak, seat_load_lowest, foundation_force_peak,
  foundation_force_lowest [N]; stability (words) and
  dominant_multiplier_real, _imag where judged; the coefficients on
  ``(member, harmonic)``, n = -m..m [m].
* Branch: converged, residual, truncation_error [1], minimum_displacement
  [m], stability and dominant_multiplier_real, _imag once judged; the
  one-sided coefficients, n = 0..m [m]; fold_value, fold_index on ``fold``;
  change_value, _index, _kind, _frequency, _theta, _gains on ``change``.
* RandomSupport: factor [1] on ``(draw, sleeper)``; peak_seat_load [N],
  peak_moment [N m], converged, harmonics, stability per draw.

Rules as `railtrack.solvers.export`.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr

from ..model.passage import Passage
from ..solvers.export import (FIELD_UNITS, base_attrs, complex_parts, frame, input_attrs,
                              variable)

__all__ = ["sweep_dataset", "branch_dataset", "random_support_dataset", "study_frame"]


def _field(name: str, dims, values, what: str) -> tuple:
    return variable(dims, values, FIELD_UNITS.get(name, "1"),
                    f"{name.replace('_', ' ')} ({what})")


def _verdicts(dims, stable) -> dict:
    """Stability as words; a member never judged (None) is "unknown"."""
    if stable is None:
        return {}
    words = [{True: "stable", False: "unstable"}.get(state, "unknown") for state in stable]
    return {"stability": variable(dims, np.array(words), "1",
                                  "stability of the periodic state: stable, unstable or "
                                  "unknown (not converged, or not proven)")}


def sweep_dataset(result) -> xr.Dataset:
    """A `railtrack.Sweep`: every member's flags, extremes, stability and coefficients."""
    names = list(result.values)
    row = names[0] if len(names) == 1 else "member"
    coords = {name: _field(name, row, result.values[name], "swept") for name in names}
    if row == "member":
        coords["member"] = variable("member", np.arange(len(result)), "1", "index of the member")
    m = result.harmonics
    coords["harmonic"] = variable("harmonic", np.arange(-m, m + 1), "1",
                                  "harmonic number n of the wagon-passing frequency")
    data = {
        "converged": variable(row, np.asarray(result.converged, dtype=bool), "1",
                              "whether the solve reached its tolerance"),
        "iterations": variable(row, np.asarray(result.iterations, dtype=np.int32), "1",
                               "Newton steps taken"),
        "residual": variable(row, result.residual, "1", "final relative residual of eq. (17)"),
        "truncation_error": variable(row, result.truncation_error, "1",
                                     "estimated truncation error of the sleeper displacement"),
    }
    extremes = {
        "lowest": ("m", "lowest sleeper displacement over a period, positive upward"),
        "highest": ("m", "highest sleeper displacement over a period, positive upward"),
        "seat_load_peak": ("N", "largest rail-seat load over a period, compression positive"),
        "seat_load_lowest": ("N", "smallest rail-seat load over a period, compression "
                                  "positive"),
        "foundation_force_peak": ("N", "largest force on the foundation over a period, "
                                       "compression positive"),
        "foundation_force_lowest": ("N", "smallest force on the foundation over a period, "
                                         "compression positive"),
    }
    data.update({name: variable(row, getattr(result, name), unit, long_name)
                 for name, (unit, long_name) in extremes.items()})
    data.update(_verdicts(row, result.stable))
    if result.dominant_multiplier is not None:
        data.update(complex_parts("dominant_multiplier", row, result.dominant_multiplier, "1",
                                  "dominant Floquet multiplier per period (NaN: not known)"))
    data.update(complex_parts("sleeper_displacement_coefficient", (row, "harmonic"),
                              result.coefficients, "m",
                              "Fourier coefficient c_n of the sleeper displacement"))
    attrs = base_attrs("Sweep", "A sweep of periodic steady responses (railtrack)",
                       harmonics=m, swept=", ".join(names), members=len(result),
                       converged_members=int(np.sum(result.converged)))
    attrs.update(input_attrs(result.passage, result.foundation))
    return xr.Dataset(data, coords=coords, attrs=attrs)


def branch_dataset(branch, samples: int = 512) -> xr.Dataset:
    """A `railtrack.Branch`: each point's parameter, flags, lowest displacement, coefficients."""
    row = "point"
    m = branch.harmonics
    coords = {
        "point": variable(row, np.arange(len(branch)), "1", "index of the point along the branch"),
        branch.parameter: _field(branch.parameter, row, branch.values, "followed"),
        "harmonic": variable("harmonic", np.arange(m + 1), "1",
                             "harmonic number n (one-sided: c_-n = conj(c_n))"),
    }
    data = {
        "converged": variable(row, np.asarray(branch.converged, dtype=bool), "1",
                              "whether the point reached its tolerance"),
        "residual": variable(row, branch.residuals, "1", "relative residual of eq. (17)"),
        "truncation_error": variable(row, [branch.solution(i).truncation_error
                                           for i in range(len(branch))], "1",
                                     "estimated truncation error of the sleeper displacement"),
        "minimum_displacement": variable(row, branch.minimum_displacement(samples), "m",
                                         "lowest sleeper displacement over a period, "
                                         "positive upward"),
    }
    data.update(_verdicts(row, branch.stable))
    if branch.multipliers is not None:
        data.update(complex_parts("dominant_multiplier", row, branch.multipliers, "1",
                                  "dominant Floquet multiplier per period"))
    data.update(complex_parts("sleeper_displacement_coefficient", (row, "harmonic"),
                              branch.coefficients, "m",
                              "one-sided Fourier coefficient c_n of the sleeper displacement"))
    unit = FIELD_UNITS.get(branch.parameter, "1")
    if branch.folds:
        coords["fold"] = variable("fold", np.arange(len(branch.folds)), "1",
                                  "index of the fold, in the order met")
        data["fold_value"] = variable("fold", [f.value for f in branch.folds], unit,
                                      f"{branch.parameter} at the fold")
        data["fold_index"] = variable("fold", [f.index for f in branch.folds], "1",
                                      "the fold lies between this point and the next")
    if branch.changes:
        changes = branch.changes
        coords["change"] = variable("change", np.arange(len(changes)), "1",
                                    "index of the change of stability, in the order met")
        data.update({
            "change_value": variable("change", [c.value for c in changes], unit,
                                     f"{branch.parameter} where stability changes"),
            "change_index": variable("change", [c.index for c in changes], "1",
                                     "the change lies between this point and the next"),
            "change_kind": variable("change", np.array([c.kind for c in changes]), "1",
                                    "how stability changes"),
            "change_frequency": variable("change", [c.frequency for c in changes], "1",
                                         "arg(mu) / 2 pi of the crossing multiplier"),
            "change_theta": variable("change", [c.theta for c in changes], "rad",
                                     "Bloch phase per sleeper of the crossing"),
            "change_gains": variable("change", np.array([c.gains for c in changes], bool), "1",
                                     "whether the branch becomes stable there"),
        })
    attrs = base_attrs("Branch", f"A branch of periodic steady responses in "
                                 f"{branch.parameter} (railtrack)",
                       parameter=branch.parameter, harmonics=m, aft_samples=branch.samples,
                       message=branch.message, coefficient_scale=branch.coefficient_scale,
                       parameter_scale=branch.parameter_scale,
                       inputs_note=f"the problem at the branch's start; {branch.parameter} "
                                   "varies along point")
    attrs.update(input_attrs(Passage(branch.track, branch.train), branch.foundation))
    return xr.Dataset(data, coords=coords, attrs=attrs)


def random_support_dataset(study) -> xr.Dataset:
    """A `railtrack.RandomSupport`: each draw's factors, peaks, flags and stability."""
    draws, sleepers = np.shape(study.factors)
    coords = {"draw": variable("draw", np.arange(draws), "1", "index of the draw"),
              "sleeper": variable("sleeper", np.arange(sleepers), "1",
                                  "index of the sleeper in the cell")}
    data = {
        "factor": variable(("draw", "sleeper"), study.factors, "1",
                           "factor on the sleeper's foundation stiffness"),
        "peak_seat_load": variable("draw", study.peak_seat_load, "N",
                                   "largest rail-seat load over the cell and the period"),
        "peak_moment": variable("draw", study.peak_moment, "N m",
                                "largest sagging rail bending moment along the cell"),
        "converged": variable("draw", np.asarray(study.converged, dtype=bool), "1",
                              "whether the draw's solve reached its tolerance"),
        "harmonics": variable("draw", np.asarray(study.harmonics, dtype=np.int32), "1",
                              "harmonics m of the draw's solve"),
    }
    if np.size(study.stability):
        data["stability"] = variable("draw", np.asarray(study.stability, dtype=str), "1",
                                     "stability of the draw: stable, unstable or unknown")
    attrs = base_attrs("RandomSupport", "Random-support Monte Carlo over cells (railtrack)",
                       variation=study.variation, draws=draws, sleepers=sleepers,
                       converged_draws=int(np.sum(study.converged)))
    inputs = getattr(study, "inputs", None) or {}
    if inputs:
        attrs.update(input_attrs(Passage(inputs["track"], inputs["train"]),
                                 inputs["foundation"]))
        attrs.update(base_attrs("RandomSupport", attrs["title"], seed=inputs.get("seed"),
                                requested_harmonics=str(inputs.get("harmonics")),
                                stability_mode=str(inputs.get("stability"))))
    return xr.Dataset(data, coords=coords, attrs=attrs)


def study_frame(dataset: xr.Dataset) -> pd.DataFrame:
    """One row per member, point or draw (the dimension of ``converged``)."""
    return frame(dataset, dataset["converged"].dims[0])
