"""`railtrack.solve(..., ground=...)`: one sleeper's law on a compliant ground, by Newton.

The law acts between the sleeper and the ground's surface under it; the
ground couples all sleepers through its lattice sum R_g (eq. G1 of
`railtrack.equations.ground_lattice`).  The unknowns are the law's relative
displacement d_n, and the residual is eq. (17) with the operator and the
load divided by phi_n = 1 + M R_g,n operator_n (eq. G2 of
`railtrack.equations.ground_balance`): the same
`HarmonicSystem`, so the same residual, AFT Jacobian, Newton iteration,
tolerance, automatic m and truncation estimate as on a rigid ground
(`railtrack.solvers.solve`).  R_g is evaluated once per spectrum of
harmonics (`railtrack.solvers.truncation.track_spectrum`), not per Newton step.

Not on a ground (each refused with a ValueError naming it): the fixed point
and the closed form (eq. 21 and eq. 23 are the rigid ground's), cells of
differing sleepers and wheels (the ground would couple sleepers of
differing histories: a lattice sum per cell offset, not written yet), the
fallback along the speed (its systems are the rigid ground's) and the full
stability check (Floquet would need the ground's memory in time).
"""

from __future__ import annotations

import warnings

import numpy as np

from ..equations.harmonic_balance import nonlinear_coefficients, two_sided
from ..model.foundations import as_foundation
from ..model.ground_protocol import check_ground
from ..model.passage import Passage
from .auto_harmonics import (AUTO_ROUNDS, WARN_TRUNCATION, auto_stopped, first_system,
                             next_system, truncation_warning)
from .conditioning import check_conditioning
from .diagnosis import convergence_error
from .guards import (check_laws_at_rest, hold_to_accuracy,
                     require_scalar_fields, warn_if_displaced)
from .ground_solution import GroundSolution
from .methods import checked_harmonics_arguments, run_method
from .solution import ConvergenceWarning
from .speed_path import not_converged_advice
from .truncation import estimate_of

__all__ = ["solve_on_ground"]


class _Remembered:
    """The ground with its compliance remembered per (omega, kx): when "auto" grows m, the
    spectrum of eq. (G2) is evaluated again, and only the new harmonics cost a lattice sum;
    and a later solve on the same ground at the same speed (another law, load or m) costs
    no lattice sum at all (`_remembered`)."""

    def __init__(self, ground):
        self.footprint, self._ground, self._memo = ground.footprint, ground, {}

    def compliance(self, kx, omega):
        kx = np.asarray(kx, dtype=float)
        key = (float(omega), kx.shape, kx.tobytes())
        if key not in self._memo:
            if len(self._memo) >= _MEMO_SIZE:        # a long sweep of speeds: start again
                self._memo.clear()
            self._memo[key] = self._ground.compliance(kx, omega)
        return self._memo[key]


_MEMO_SIZE = 20000            # compliance arrays (~2 kB each) remembered per ground
_GROUNDS: dict = {}           # the last few grounds solved on, by value


def _remembered(ground) -> _Remembered:
    """The ground's memo, kept across solves for a frozen (hashable) ground, the last four."""
    try:
        hash(ground)
    except TypeError:                                  # a mutable ground: this solve only
        return _Remembered(ground)
    if ground not in _GROUNDS:
        if len(_GROUNDS) >= 4:
            del _GROUNDS[next(iter(_GROUNDS))]
        _GROUNDS[ground] = _Remembered(ground)
    return _GROUNDS[ground]


def _refuse(ground_options: dict) -> None:
    for name, value, allowed in (
            ("method", ground_options["method"], "newton"),
            ("stability", ground_options["stability"], ("quick", "off")),
            ("fallback", ground_options["fallback"], (None, False))):
        ok = value in allowed if isinstance(allowed, tuple) else value == allowed
        if not ok:
            raise ValueError(f"{name}={value!r} is not available on a ground (ground=...): "
                             f"use {allowed!r} (railtrack.solvers.ground_solve says why)")
    for name in ("wheel", "profile", "cell"):
        if ground_options[name]:
            raise ValueError(f"{name} is not available on a ground (ground=...) yet: one "
                             "sleeper's law only (railtrack.solvers.ground_solve says why)")


def solve_on_ground(track, train, foundation, ground, harmonics, method, *, methods, accuracy, tol,
                    max_iterations, split, samples, initial, strict, check_foundation,
                    fallback, stability, wheel, profile, cell) -> GroundSolution:
    """`railtrack.solve` on a ground: arguments as there; returns a `GroundSolution`.

    `methods` is `railtrack.solvers.solve.METHODS`, passed in by `solve`.

    ``initial`` (with an explicit m) holds the relative displacement's d_0..d_m.
    harmonics="auto" that stops short of `accuracy` returns ``converged=False``
    and an explicit m warns above 1 %, as in `railtrack.solve`.

    Examples
    --------
    >>> import railtrack as rt
    >>> from railtrack.model.ground_protocol import WinklerGround
    >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper(0.8),
    ...              ground=WinklerGround(2e8, 0.25))
    >>> bool(s.converged), s.truncation_error < 1e-3
    (True, True)
    """
    _refuse(dict(method=method, stability=stability, fallback=fallback, wheel=wheel is not None,
                 profile=profile is not None, cell=cell))
    passage = Passage(track, train)
    require_scalar_fields(track, train)
    check_conditioning(passage)
    check_ground(ground, float(passage.sleeper_spacing))
    automatic, accuracy, tol, max_iterations = checked_harmonics_arguments(
        harmonics, method, accuracy, tol, 1e-10, max_iterations, initial, samples, split)
    foundation = as_foundation(foundation)
    check_laws_at_rest([foundation], [float(passage.pad_stiffness)],
                       [float(passage.pad_damping)], check_foundation)

    remembered = _remembered(ground)
    m, target, spectrum, system, initial = first_system(
        passage, foundation, harmonics, automatic, method, accuracy, samples, initial, remembered)
    iterations = 0
    for _round in range(AUTO_ROUNDS + 1):
        outcome, _, _ = run_method(methods, method, system, tol, max_iterations, None, initial)
        iterations += outcome.iterations
        estimate, tail = estimate_of(system, outcome.coefficients, spectrum)
        if not automatic or not outcome.converged or tail is None:
            break
        grown = next_system(passage, foundation, method, m, target, estimate, accuracy,
                            outcome.coefficients, tail, spectrum, remembered)
        if grown is None or _round == AUTO_ROUNDS:     # the last round's m is the one solved
            break
        m, spectrum, system, initial = grown
        target = m

    message = outcome.message + "; on a ground (eq. G2), the stability look is not done"
    if automatic:
        message += (f"; harmonics='auto' chose m = {m} ({iterations} steps in all, "
                    f"estimated truncation error {estimate:.1e})")
    if not automatic and outcome.converged and estimate > WARN_TRUNCATION:
        warnings.warn(truncation_warning(passage, foundation, m, estimate), stacklevel=3)
    d = np.asarray(outcome.coefficients, dtype=complex)
    with np.errstate(over="ignore", invalid="ignore"):
        forces = nonlinear_coefficients(system, d, strict=False) * float(passage.sleeper_mass)
    u = spectrum.receptance[: m + 1] * forces
    solution = GroundSolution(
        passage=passage, foundation=foundation, harmonics=system.harmonics,
        coefficients=two_sided(d + u), method=method, converged=outcome.converged,
        iterations=iterations, residual_history=outcome.residual_history, message=message,
        samples=system.samples, truncation_error=estimate, ground=ground,
        ground_coefficients=two_sided(u), relative_coefficients=two_sided(d),
        force_coefficients=two_sided(forces))
    if strict and not solution.converged:
        raise convergence_error(method, outcome, solution, message)
    solution, short = hold_to_accuracy(solution, automatic, accuracy, strict, stacklevel=4,
                                       of="the peak sleeper displacement",
                                       stopped=auto_stopped(m))
    if solution.converged:
        warn_if_displaced(solution)
    budget_spent = max_iterations is not None and outcome.iterations >= max_iterations
    if not solution.converged and not budget_spent and not short:
        warnings.warn(ConvergenceWarning(not_converged_advice(
            method, message, passage, system.harmonics, stalled="line search" in outcome.message
            or False)), stacklevel=3)
    return solution
