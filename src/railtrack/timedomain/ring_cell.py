"""A cell of differing sleepers on the finite-element ring (issue 19).

A `railtrack.model.cell.SleeperCell` of N sleepers repeats along the track:
ring sleeper i is cell sleeper ``i mod N``, with its own mass M, pad k1,
eta1 and foundation law.  The ring is one wagon length H, or ``wagons``
wagons long (the train tiled, `ring_train`), so it carries the cell only if
N divides its ``wagons H / L`` sleepers; otherwise the track under the
train would not repeat with the ring and `ring_cell` refuses the cell.

`RingLaw` is the foundation of the whole ring as one law: it calls each
distinct law object of the cell once, on the vector of the ring sleepers
that carry it, so that a cell of 30 sleepers with one hanging sleeper costs
two law calls per Newton iteration, not thirty.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model.cell import SleeperCell
from ..model.foundations import LinearFoundation
from ..model.passage import Passage
from ..model.train import Train
from .newmark import reference_law

__all__ = ["ring_train", "RingLaw", "RingCell", "ring_cell", "contact_fraction"]


def ring_train(train: Train, wagons: int) -> Train:
    """`wagons` wagons of `train` as one wagon of length n H (the axles tiled); `train` if n = 1."""
    if isinstance(wagons, bool) or not isinstance(wagons, (int, np.integer)) or wagons < 1:
        raise ValueError(f"wagons must be an integer >= 1; got {wagons!r}")
    if wagons == 1:
        return train
    length = float(train.wagon_length)
    positions = (length * np.arange(wagons)[:, None] + np.asarray(train.axle_positions)).ravel()
    return Train(wagons * length, positions, np.tile(train.axle_loads, wagons), train.speed)


class RingLaw:
    """The foundation laws of all ring sleepers as one law on their vector.

    Parameters
    ----------
    groups : sequence of (law, ndarray of int)
        Each distinct law object and the ring sleepers it carries; together
        the indices are 0 .. n_sleepers - 1, each once.
    n_sleepers : int

    Notes
    -----
    ``force(w, v)`` and ``tangent(w, v)`` take arrays whose last axis is the
    ring's sleepers and call each law once, on its sleepers' columns.  A
    law that carries every sleeper gets ``w`` and ``v`` themselves, so a
    ring of one law computes exactly what that law computes.
    """

    def __init__(self, groups, n_sleepers: int):
        self.groups = tuple((law, np.asarray(index, dtype=int)) for law, index in groups)
        self.n_sleepers = int(n_sleepers)

    def _apply(self, method: str, w, v, outputs: int):
        w, v = np.asarray(w, dtype=float), np.asarray(v, dtype=float)
        shape = np.broadcast_shapes(w.shape, v.shape)
        if len(self.groups) == 1:
            return getattr(self.groups[0][0], method)(w, v)
        # called twice a Newton iteration of every time step: no copies where shapes agree
        if w.shape != shape:
            w = np.broadcast_to(w, shape)
        if v.shape != shape:
            v = np.broadcast_to(v, shape)
        result = [np.empty(shape) for _ in range(outputs)]
        for law, index in self.groups:
            values = getattr(law, method)(w[..., index], v[..., index])
            values = (values,) if outputs == 1 else values
            for out, value in zip(result, values):
                out[..., index] = value          # a scalar or a column broadcasts here
        return result[0] if outputs == 1 else tuple(result)

    def force(self, w, v):
        """f_i(w_i, w'_i) of every ring sleeper i [N] (last axis: the sleepers)."""
        return self._apply("force", w, v, 1)

    def tangent(self, w, v):
        """(df_i/dw, df_i/dw') of every ring sleeper i [N/m], [N s/m]."""
        return self._apply("tangent", w, v, 2)

    def reference(self) -> tuple[np.ndarray, np.ndarray]:
        """(k0_i, c0_i) of every ring sleeper: its law's `reference_law` [N/m], [N s/m]."""
        k0, c0 = np.empty(self.n_sleepers), np.empty(self.n_sleepers)
        for law, index in self.groups:
            k0[index], c0[index] = reference_law(law)
        return k0, c0

    def linearization(self) -> tuple[float, float]:
        """The mean of the sleepers' references (k0, c0), for messages [N/m], [N s/m]."""
        k0, c0 = self.reference()
        return float(np.mean(k0)), float(np.mean(c0))

    def __repr__(self) -> str:
        laws = ", ".join(f"{law!r} x {index.size}" for law, index in self.groups)
        return f"RingLaw({laws})"


@dataclass(frozen=True, eq=False)
class RingCell:
    """What the ring needs of a cell: per-sleeper values and the grouped law.

    Attributes
    ----------
    cell : SleeperCell
    copies : int
        Cells on the ring, n_sleepers / N.
    sleeper_mass, pad_stiffness, pad_damping : ndarray, shape (n_sleepers,)
        M, k1, eta1 of each ring sleeper [kg], [N/m], [N s/m].
    law : RingLaw
    uniform : bool
        True if every cell sleeper has the same law object, mass and pad:
        the ring is then the uniform ring of that law.
    """

    cell: SleeperCell
    copies: int
    sleeper_mass: np.ndarray
    pad_stiffness: np.ndarray
    pad_damping: np.ndarray
    law: RingLaw
    uniform: bool

    @property
    def sleepers(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(M_i, k1_i, eta1_i) for `railtrack.timedomain.fem.ring_mesh`."""
        return self.sleeper_mass, self.pad_stiffness, self.pad_damping

    def self_weight(self, mesh) -> np.ndarray | None:
        """Constant nodal loads of the rail's and sleepers' weight [N]; None without gravity.

        The rail's rho S g per metre is a uniform load: its consistent nodal
        loads are -rho S g h / 2 and -+rho S g h^2 / 12 at each end of an
        element, so on the closed ring every rail node carries -rho S g h and
        the moments cancel.  Sleeper i carries -M_i g (`SleeperCell.weights`).
        """
        gravity = float(getattr(self.cell, "gravity", 0.0))
        if gravity == 0.0:
            return None
        load = np.zeros(mesh.n_dofs)
        load[0:2 * mesh.n_nodes:2] = (-float(mesh.passage.rail_linear_mass) * gravity
                                      * mesh.element_length)
        load[mesh.sleeper_dofs] = -self.sleeper_mass * gravity
        return load

    def stand_in(self, passage: Passage, w: np.ndarray) -> tuple[Passage, LinearFoundation]:
        """A uniform track for the time-step error estimate: the cell's mean sleeper and pad
        on the mean tangent of the laws at the ring's sleeper displacements `w` [m].

        A tangent that is not finite and positive is replaced by the law's
        reference (`railtrack.timedomain.newmark.reference_law`), as for one law.
        """
        stiffness, damping = (np.broadcast_to(np.asarray(x, dtype=float), w.shape)
                              for x in self.law.tangent(w, np.zeros_like(w)))
        k0, c0 = self.law.reference()
        stiffness = np.where(np.isfinite(stiffness) & (stiffness > 0), stiffness, k0)
        damping = np.where(np.isfinite(damping) & (damping >= 0), damping, c0)
        mean = passage.replace(sleeper_mass=float(np.mean(self.sleeper_mass)),
                               pad_stiffness=float(np.mean(self.pad_stiffness)),
                               pad_damping=float(np.mean(self.pad_damping)))
        return mean, LinearFoundation(float(np.mean(stiffness)), float(np.mean(damping)))


def ring_cell(cell: SleeperCell, n_sleepers: int, wagons: int, per_wagon: int) -> RingCell:
    """Lay `cell` along a ring of `n_sleepers` sleepers (`wagons` wagons of `per_wagon` each).

    Raises
    ------
    ValueError
        If N does not divide `n_sleepers`, naming the ring and the wagon
        counts whose ring would carry the cell.
    """
    n = cell.sleepers
    if n_sleepers % n:
        fits = n // math.gcd(n, per_wagon)
        raise ValueError(
            f"a cell of N = {n} sleepers does not tile the ring of wagons = {wagons} "
            f"wagon(s), which carries wagons x H/L = {wagons} x {per_wagon} = {n_sleepers} "
            f"sleepers: N must divide {n_sleepers}. Pass wagons = a multiple of {fits} "
            f"(the ring of {fits} wagon(s) carries {fits * per_wagon} sleepers), or use a "
            f"cell whose size divides {n_sleepers}"
        )
    copies = n_sleepers // n
    position = np.arange(n_sleepers) % n
    laws: dict[int, tuple[object, list[int]]] = {}
    for j, law in enumerate(cell.foundations):
        laws.setdefault(id(law), (law, []))[1].append(j)
    groups = [(law, np.flatnonzero(np.isin(position, members))) for law, members in laws.values()]
    values = [np.tile(getattr(cell, name), copies)
              for name in ("sleeper_mass", "pad_stiffness", "pad_damping")]
    uniform = len(groups) == 1 and all(np.all(value == value[0]) for value in values)
    return RingCell(cell, copies, *values, RingLaw(groups, n_sleepers), uniform)


def contact_fraction(foundation_forces: np.ndarray, threshold: float = 0.0) -> np.ndarray:
    """Fraction of the period during which each sleeper's foundation pushes [-].

    Parameters
    ----------
    foundation_forces : ndarray, shape (steps_per_period, n_sleepers)
        Forces on the foundations over one period, positive in compression
        [N] (`TimeDomainSolution.foundation_forces`), sampled at equal steps.
    threshold : float
        A force above it counts as contact [N]; 0 by default.

    Returns
    -------
    ndarray, shape (n_sleepers,)
        The share of the steps with force > threshold: 1 for a sleeper always
        on its ballast, 0 for one that never touches it.

    Examples
    --------
    >>> contact_fraction(np.array([[1.0, 0.0], [2.0, 0.0], [0.0, 3.0], [4.0, 0.0]]))
    array([0.75, 0.25])
    """
    forces = np.asarray(foundation_forces, dtype=float)
    return np.mean(forces > threshold, axis=0)
