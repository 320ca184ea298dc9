"""The vehicle above the wheels on the finite-element ring: body and bogies integrated with the rail.

With a `railtrack.Vehicle` for ``wheel=``, every wagon of the ring carries
half a vehicle (the modelled rail's side: M/2, C/2, K/2 of
`railtrack.equations.vehicle_matrices`, its wheelsets' coordinates the
wheels of that wagon's four axles), integrated by the ring's own Newmark
rule (average acceleration, or HHT-alpha) in the coordinates q measured from
the vehicle's static state:

    M q'' + C q' + K q = B (P - Q),

B putting each contact force on its wheelset.  A step is
``A_v q_{n+1} = h + B (P_{n+1} - Q)``, A_v = K + (gamma / (beta dt)) C + M / ((1 - alpha) beta dt^2),
h from the state at the start of the step (with HHT the springs, dashpots
and contacts at t_{n+1} - alpha dt, as `railtrack.timedomain.ring_wheels`).
So the wheels move by z_{n+1} = z_hat + G P_{n+1}, G = B^T A_v^-1 B (J x J,
coupled within a wagon): the ring's contact solve
(`railtrack.timedomain.wheel_contacts.solve_contacts`) takes G where a lone
wheel has 1 / a_w.  The ring is the independent check of the harmonic
balance's `railtrack.equations.wheel_receptance`: the same springs and
dashpots, integrated in time instead of inverted per harmonic.

At rest a vehicle carries its static loads whatever its wheels' heights (it
is statically determinate, D(0) = 0): the wheels sit as a `Wheel` without a
primary suspension does, and the body and bogies follow them without
straining the suspension.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import block_diag

from ..equations.vehicle_matrices import WHEELSETS, vehicle_matrices
from .wheel_contacts import solve_contacts
from .ring_wheels import WheelStepper, attach_wheels

__all__ = ["VehicleStepper", "ring_vehicle_matrices", "attach_vehicle"]


def attach_vehicle(stepper, vehicle, profile, u, times, reference_stiffness, wagons: int = 1):
    """The vehicles at rest on the statically loaded ring: (u, VehicleStepper).

    A vehicle rests as a `Wheel` without a primary suspension does (P = Q,
    `railtrack.timedomain.ring_wheels.attach_wheels` with `Vehicle.contact`);
    arguments as there.
    """
    u, lone = attach_wheels(stepper, vehicle.contact, profile, u, times, reference_stiffness,
                            wagons)
    wheels = VehicleStepper(stepper, vehicle, lone.r, (lone.dofs, lone.shapes), lone.q, lone.z,
                            wagons, lone.compliance)
    wheels.uc = lone.uc
    return u, wheels


def ring_vehicle_matrices(vehicle, wagons: int):
    """(M, C, K) [kg, N s/m, N/m] of the ring's half vehicles, and the wheels' rows in q.

    Block-diagonal over the wagons, 10 coordinates each; the wheels' indices
    (J = 4 wagons,) follow the ring's axles (wagon by wagon, leading first).
    """
    blocks = [0.5 * part for part in vehicle_matrices(vehicle)]
    mass, damping, stiffness = (block_diag(*([part] * int(wagons))) for part in blocks)
    wheels = (10 * np.arange(int(wagons))[:, None]
              + np.arange(10)[WHEELSETS][None, :]).ravel()
    return mass, damping, stiffness, wheels


class VehicleStepper(WheelStepper):
    """`WheelStepper` with the wheels under half vehicles (module docstring).

    Parameters
    ----------
    stepper, profile_values, shapes, loads, compliance
        As `WheelStepper`.
    vehicle : Vehicle
    wheels_at_rest : ndarray, shape (J,)
        z of each wheel at rest on the loaded ring [m] (P = Q there).
    wagons : int
    """

    def __init__(self, stepper, vehicle, profile_values, shapes, loads, wheels_at_rest,
                 wagons: int, compliance=None):
        count = np.asarray(loads).size
        zero = np.zeros(count)
        super().__init__(stepper, vehicle.contact, profile_values, shapes, loads,
                         (wheels_at_rest, zero, zero, np.asarray(loads, float)), compliance)
        self.wheel = vehicle
        self.mass, self.damping, self.stiffness, self.rows = ring_vehicle_matrices(vehicle, wagons)
        size = self.mass.shape[0]
        self.spread = np.zeros((size, count))
        self.spread[self.rows, np.arange(count)] = 1.0                     # B
        # the body and bogies follow the wheels at rest without straining the springs
        rest = np.setdiff1d(np.arange(size), self.rows)
        self.x = np.zeros(size)
        self.x[self.rows] = wheels_at_rest
        self.x[rest] = -np.linalg.solve(self.stiffness[np.ix_(rest, rest)],
                                        self.stiffness[np.ix_(rest, self.rows)] @ wheels_at_rest)
        self.xv, self.xa = np.zeros(size), np.zeros(size)
        dt, alpha = stepper.dt, stepper.alpha
        self.inertia = 1.0 / ((1.0 - alpha) * stepper.newmark[1] * dt**2)
        matrix = self.stiffness + stepper.gain * self.damping + self.inertia * self.mass
        self.solved = np.linalg.solve(matrix, self.spread)                 # A_v^-1 B
        self.matrix = matrix
        self.coupling = self.spread.T @ self.solved                        # G [m/N]
        self.loads = np.asarray(loads, dtype=float)

    def period_change(self) -> float:
        """As `WheelStepper.period_change`, the balance being mean P = Q (D(0) = 0)."""
        current = self.contact_forces
        change = np.inf
        if self.previous is not None and np.all(np.isfinite(current)):
            peak = max(float(np.max(np.abs(current))), float(np.max(self.loads)))
            change = float(np.max(np.abs(current - self.previous))) / peak
        balance = current.mean(axis=0) - self.loads
        self.previous = current.copy()
        return max(change, float(np.max(np.abs(balance))) / float(np.max(self.loads)))

    def _vehicle_history(self) -> np.ndarray:
        """h: the vehicle's Newmark right-hand side from the state at the step's start [N]."""
        base = self.stepper
        dt, alpha, beta = base.dt, base.alpha, base.newmark[1]
        q, qv, qa = self.x, self.xv, self.xa
        history = (self.mass @ (self.inertia * (q + dt * qv + dt**2 * (0.5 - beta) * qa))
                   + self.damping @ (base.gain * q + base.rates[0] * qv + base.rates[1] * qa))
        if alpha != 0.0:
            start = self.spread @ (self.p - self.loads) - self.damping @ qv - self.stiffness @ q
            history = history + alpha / (1.0 - alpha) * start
        return history

    def step(self, u, v, a, index: int):
        """State (u, u', u'') of the ring at the end of the step ending at step `index`."""
        base = self.stepper
        previous = (index - 1) % self.r.shape[0]
        self.contact_forces[previous] = self.p
        self.wheel_displacements[previous] = self.x[self.rows]
        self.rail_under_wheels[previous] = self.uc
        sleepers = base.mesh.sleeper_dofs
        rhs = base.right_hand_side(u, v, a)
        if base.alpha != 0.0:   # HHT: the contact forces at the start of the step, where they were
            ratio = base.alpha / (1.0 - base.alpha)
            for j in range(self.loads.size):
                np.add.at(rhs, self.dofs[previous][j], -ratio * self.p[j] * self.shapes[previous][j])
        free = np.linalg.solve(self.matrix, self._vehicle_history() - self.spread @ self.loads)
        u_next, base.force, self.p, self.uc = solve_contacts(
            base.system, rhs, (self.dofs[index], self.shapes[index]), self.wheel,
            self.r[index] - free[self.rows], self.coupling,
            base._remainder(base.offset(u, v, a, sleepers)), (base.force, self.p),
            base.tol, base.iterations, None if self.compliance is None else self.compliance[index])
        q_next = free + self.solved @ self.p
        self.x, self.xv, self.xa = base.finish(self.x, self.xv, self.xa, q_next)
        self.z = self.x[self.rows]
        return base.finish(u, v, a, u_next)
