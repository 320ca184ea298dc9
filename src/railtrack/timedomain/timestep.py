"""How fine the time step of the ring model must be, and how wrong a given one is.

`simulate_time_domain` integrates the ring of `railtrack.timedomain.fem` with the
average-acceleration Newmark scheme.  Two things decide whether a number of
steps per period T = H / v can work:

* `check_steps_per_period`: the ring is invariant under a shift of one span
  combined with the delay L / v, which the discrete model keeps only if L / v
  is a whole number of steps (`steps_per_period` a multiple of H / L); and
  the sleeper-passing frequency v / L, the load's own frequency, needs more
  than two steps per L / v (Nyquist) or the discrete model does not see the
  wheel move between sleepers at all;
* `estimate_step_error`: how far the periodic Newmark solution is from the
  exact one of the same mesh, for the track linearized about its static
  state.  Average acceleration is the trapezoidal rule, so its periodic
  response at harmonic k is the exact response at the warped frequency
  (2 / dt) tan(omega_k dt / 2), to the loads sampled at the steps (which
  aliases the harmonics above the Nyquist frequency).  Both responses are
  summed harmonic by harmonic on one span with the Floquet condition of the
  moving load (span j lags span 0 by j L / v), so the estimate costs a few
  thousand 9 x 9 solves (~0.03 s), not a run.  For a linear law it is the
  time-step error itself, on a mesh of `ESTIMATE_ELEMENTS` per span: on the
  paper's track, estimate / measured error = 0.99-1.04 from 90 to 960 steps
  per period (measured against harmonic balance, m = 200).  For a nonlinear
  law it is that of the linearization about the static state: 0.99-1.07 for
  the cubic law eq. (25) at eps = 0.8, but 0.35-0.8 for the tensionless
  eq. (24), whose lift-off the linearization does not see.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from .fem import ring_mesh, sleepers_on_ring, wheel_load_entries
from .newmark import reference_law
from ..model.passage import Passage

__all__ = [
    "TimeStepWarning",
    "MIN_STEPS_PER_SPAN",
    "ESTIMATE_ELEMENTS",
    "minimum_steps_per_period",
    "check_steps_per_period",
    "estimate_step_error",
    "check_step_error",
    "steps_for_error",
]

MIN_STEPS_PER_SPAN = 3
"""Fewest time steps per sleeper-passing time L / v: more than two (Nyquist)."""

ESTIMATE_ELEMENTS = 4
"""Elements per span of the mesh the time-step error is estimated on (at most)."""

_SAMPLES_PER_ELEMENT = 32
"""Samples of the wheel loads per element passage h / v for the exact spectrum."""


class TimeStepWarning(UserWarning):
    """The estimated time-step error of a time-domain run is larger than asked for."""


def minimum_steps_per_period(passage: Passage) -> int:
    """Fewest steps per period accepted: `MIN_STEPS_PER_SPAN` times H / L."""
    return MIN_STEPS_PER_SPAN * sleepers_on_ring(passage)


def check_steps_per_period(passage: Passage, steps_per_period: int) -> None:
    """Refuse a step count that cannot represent the moving load on the ring.

    Raises
    ------
    ValueError
        If `steps_per_period` is not a multiple of H / L, or gives fewer than
        `MIN_STEPS_PER_SPAN` steps per sleeper-passing time L / v.
    """
    sleepers = sleepers_on_ring(passage)
    span_time = float(passage.sleeper_spacing) / float(passage.speed)
    smallest = minimum_steps_per_period(passage)
    suggestion = max(smallest, sleepers * math.ceil(steps_per_period / sleepers))
    if steps_per_period % sleepers:
        raise ValueError(
            f"steps_per_period must be a multiple of H/L = {sleepers} (the sleepers on the ring) "
            f"so that the delay L/v = {1e3 * span_time:.4g} ms between neighbouring sleepers is a "
            f"whole number of steps; got {steps_per_period}. Use e.g. {suggestion}"
        )
    if steps_per_period < smallest:
        raise ValueError(
            f"steps_per_period = {steps_per_period} gives {steps_per_period // sleepers} time "
            f"step(s) per sleeper-passing time L/v = {1e3 * span_time:.4g} ms: the load's "
            f"sleeper-passing frequency v/L = {1.0 / span_time:.4g} Hz needs more than 2 (Nyquist). "
            f"Use steps_per_period >= {smallest} ({MIN_STEPS_PER_SPAN} per L/v, a multiple of "
            f"H/L = {sleepers}); the default 2400 is accurate to ~1e-6 of the peak on the "
            "paper's track"
        )


def _span_blocks(mesh, stiffness: float, damping: float):
    """K, C, M rows of span 0 against the columns of span j, for the spans j it touches.

    Span j owns rail nodes j e .. j e + e - 1 and sleeper j; the foundation
    (stiffness, damping) acts on sleeper 0's DOF, the last of the span.
    """
    e, n = mesh.elements_per_span, mesh.n_sleepers
    def dofs(j):
        return np.concatenate([2 * j * e + np.arange(2 * e), [2 * mesh.n_nodes + j]])
    rows, blocks = dofs(0), {}
    for j in sorted({0, 1 % n, (n - 1) % n}):
        columns = dofs(j)
        blocks[j] = [np.array(matrix[rows][:, columns].todense()) for matrix in
                     (mesh.stiffness, mesh.damping, mesh.mass)]
    blocks[0][0][-1, -1] += stiffness
    blocks[0][1][-1, -1] += damping
    return rows, blocks


def _span_response(blocks, n_sleepers, harmonics, omega, loads):
    """Sleeper-0 amplitude of harmonic k: [Z(omega)^-1 P_k] at the sleeper DOF, Z on one span."""
    phase = np.exp(-2j * np.pi * harmonics / n_sleepers)
    out = np.zeros(harmonics.size, complex)
    for start in range(0, harmonics.size, 4096):
        part = slice(start, start + 4096)
        w, lam = omega[part, None, None], phase[part, None, None]
        matrix = sum(lam**j * (k + 1j * w * c - w * w * m) for j, (k, c, m) in blocks.items())
        out[part] = np.linalg.solve(matrix, loads[part, :, None])[:, -1, 0]
    return out


def _span_loads(mesh, rows, samples: int) -> np.ndarray:
    """Fourier coefficients, k = 0 .. samples // 2, of the wheel loads on span 0 [N, N m]."""
    times = float(mesh.passage.period) * np.arange(samples) / samples
    dofs, values = wheel_load_entries(mesh, times)
    local = np.full(mesh.n_dofs, -1)
    local[rows] = np.arange(rows.size)
    where = local[dofs]
    record = np.zeros((samples, rows.size))
    steps = np.broadcast_to(np.arange(samples)[:, None], where.shape)
    keep = where >= 0
    np.add.at(record, (steps[keep], where[keep]), values[keep])
    return np.fft.rfft(record, axis=0) / samples


def estimate_step_error(
    passage: Passage,
    stiffness: float,
    damping: float,
    steps_per_period: int,
    elements_per_span: int = ESTIMATE_ELEMENTS,
) -> tuple[float, float]:
    """Time-step error of the periodic Newmark solution of the linearized ring.

    Parameters
    ----------
    passage : Passage
        H / L an integer and `steps_per_period` a multiple of it.
    stiffness, damping : float
        Linearized foundation under each sleeper [N/m], [N s/m].
    steps_per_period : int
        Newmark steps per period T = H / v.
    elements_per_span : int
        Mesh of the estimate (capped at `ESTIMATE_ELEMENTS`: the time-step
        error comes from the low modes, which a coarse mesh has right).

    Returns
    -------
    relative : float
        max over the steps of |w_Newmark - w_exact| at sleeper 0, divided by
        max |w_exact| [-].
    absolute : float
        The same error [m].

    Examples
    --------
    >>> relative, _ = estimate_step_error(Passage.paper(), 20e6, 0.2e6, 2400)
    >>> f"{relative:.1e}"
    '1.6e-06'
    """
    mesh = ring_mesh(passage, min(int(elements_per_span), ESTIMATE_ELEMENTS))
    n, period = mesh.n_sleepers, float(passage.period)
    rows, blocks = _span_blocks(mesh, stiffness, damping)
    fine = _SAMPLES_PER_ELEMENT * mesh.n_nodes
    # Far above the fine grid the error is second order: estimate it there and scale.
    steps = min(int(steps_per_period), fine)
    scale = (steps / steps_per_period) ** 2
    dt = period / steps

    exact_k = np.arange(fine // 2)  # the fine grid's Nyquist term is dropped: negligible
    exact = _span_response(blocks, n, exact_k, 2 * np.pi * exact_k / period,
                           _span_loads(mesh, rows, fine)[: exact_k.size])
    folded = np.zeros(steps, complex)
    np.add.at(folded, exact_k % steps, exact)
    np.add.at(folded, (-exact_k[1:]) % steps, np.conj(exact[1:]))
    w_exact = (steps * np.fft.ifft(folded)).real

    # Newmark sees the loads at the steps only; the Nyquist term of an even
    # count has tan(pi / 2) = infinity: no response.
    discrete_k = np.arange((steps + 1) // 2)
    warped = (2.0 / dt) * np.tan(np.pi * discrete_k / steps)
    sampled = _span_loads(mesh, rows, steps)[: discrete_k.size]
    coefficients = np.zeros(steps // 2 + 1, complex)
    coefficients[: discrete_k.size] = _span_response(blocks, n, discrete_k, warped, sampled)
    w_newmark = np.fft.irfft(steps * coefficients, steps)

    absolute = scale * float(np.max(np.abs(w_newmark - w_exact)))
    return absolute / float(np.max(np.abs(w_exact))), absolute


def steps_for_error(passage: Passage, steps_per_period: int, relative: float, target: float) -> int:
    """Steps per period for an error `target`, from one at `relative`, by the dt^2 law.

    Rounded up to a multiple of H / L and at least `minimum_steps_per_period`.
    """
    sleepers = sleepers_on_ring(passage)
    wanted = steps_per_period * math.sqrt(max(relative, 0.0) / target)
    return max(minimum_steps_per_period(passage), sleepers * math.ceil(wanted / sleepers))


def check_step_error(passage: Passage, foundation, w: float, steps: int, elements: int,
                     warn_above: float | None, stacklevel: int = 3) -> float:
    """`estimate_step_error` for the law linearized at w [m], warning above `warn_above`.

    The warning's `stacklevel` (default: the caller of the function that calls this).

    A law with no positive stiffness or a negative damping there is
    linearized as `railtrack.timedomain.newmark.reference_law` does.

    Returns
    -------
    float
        The relative estimate [-]; NaN if `warn_above` is None (not estimated).

    Warns
    -----
    TimeStepWarning
        If the estimate exceeds `warn_above`, with the steps that would meet it.
    """
    if warn_above is None:
        return float("nan")
    tangent = foundation.tangent(np.full(1, w), np.zeros(1))
    stiffness, damping = (float(np.ravel(x)[0]) for x in tangent)
    if not (np.isfinite(stiffness) and stiffness > 0 and np.isfinite(damping) and damping >= 0):
        stiffness, damping = reference_law(foundation)
    relative, absolute = estimate_step_error(passage, stiffness, damping, steps, elements)
    if relative > warn_above:
        wanted = steps_for_error(passage, steps, relative, warn_above)
        warnings.warn(
            f"steps_per_period = {steps} (dt = {1e3 * float(passage.period) / steps:.4g} ms): the "
            f"estimated time-step error is {100 * relative:.3g} % of the peak ({absolute:.3g} m), "
            f"above warn_step_error = {warn_above:g}; use steps_per_period >= {wanted} for less "
            "(the error falls as dt^2), or pass a larger warn_step_error, or None, to accept it",
            TimeStepWarning,
            stacklevel=stacklevel,
        )
    return relative
