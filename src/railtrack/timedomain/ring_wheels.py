"""Wheels with mass and Hertz contact on the finite-element ring (issue 20).

With a `railtrack.model.wheel.Wheel`, every axle j of the ring's train is a
wheel DOF z_j (positive upward) instead of a constant force.  Its contact
point x_c = v t - d_j (mod the ring's length) lies in one rail element,
whose shape functions N(xi) (Hermite cubics, or a Timoshenko element's N_w:
`railtrack.timedomain.fem.rail_shapes`) give the rail's displacement there,
u_c = N . u_e, and spread the contact force on it, -P N (the consistent
load).  With the rail-top profile r(x) fixed on the ring
(`railtrack.model.profile`):

    delta_j = u_c,j + r(x_c,j) - z_j,      P_j = C_H max(delta_j, 0)^{3/2},
    m_w z_j'' + c_p z_j' + k_p z_j = P_j - Q_j.

A Newmark step (average acceleration, or HHT-alpha, as
`railtrack.timedomain.newmark`) is ``A u + U g + B P = b`` for the ring, B the
shape functions of the contact points at the end of the step, and
``a_w z = h_w + P - Q`` for the wheels (a_w = k_p + (2/dt) c_p + (4/dt^2) m_w
for average acceleration; HHT puts the spring, dashpot and contact forces at
t_{n+1} - alpha dt, the start of the step's share alpha / (1 - alpha) in h_w
and in b, where B is the contact points' shapes at the start of the step).  The unknowns that carry the
nonlinearity, y = (sleeper displacements w, compressions delta), satisfy

    y - y_hat + S' F(y) = 0,      S' = V^T A^-1 V + diag(0, 1/a_w),   V = [U, B],

with F = (g(w), P(delta)) and y_hat the response without them: Newton on
n_sleepers + n_wheels unknowns, Jacobian ``I + S' diag(F')``.  A^-1 U is
factored once (`CondensedSystem`); A^-1 B costs one back-substitution per
wheel and step, in the same call as the free response.

On a Timoshenko rail the wheel also sags the rail by g(xi) P inside its
element (`railtrack.timedomain.fem.contact_compliance`, a massless node at
the contact condensed statically): u_c = N . u_e - g P, g added to 1/a_w.
Without it the interpolation would miss the shear deflection under the
wheel, up to Q h / (4 kappa G A) mid-element, a spurious roughness of
wavelength h (5.7 um at 8 elements per span on UIC60).
"""

from __future__ import annotations

import numpy as np

from ..model.profile import smooth_rail
from ..model.vehicle import Vehicle
from ..model.wheel import Wheel
from .fem import contact_compliance, contact_shapes
from .newmark import CondensedSystem, NewmarkStepper, _sleeper_projector, evaluate_law
from .ring_contact import profile_on_ring
from .wheel_contacts import solve_contacts

__all__ = ["check_wheel_arguments", "attach_wheels", "WheelStepper", "solve_contacts"]


def check_wheel_arguments(wheel, profile, start, train=None) -> None:
    """Refuse a profile without a wheel, a wheel that is not a `Wheel` or `Vehicle`,
    a vehicle whose train is not its own (`Vehicle.check_train`), or a non-static start."""
    if wheel is None:
        if profile is not None:
            raise ValueError("a rail-top profile needs wheels to roll on it: pass wheel=Wheel(...) "
                             "(constant moving forces do not feel the profile)")
        return
    if not isinstance(wheel, (Wheel, Vehicle)):
        raise TypeError(f"wheel must be a railtrack.model.wheel.Wheel or a railtrack.Vehicle; "
                        f"got {type(wheel).__name__}")
    if isinstance(wheel, Vehicle) and train is not None:
        wheel.check_train(train)
    if not (isinstance(start, str) and start == "static"):
        raise ValueError("with wheels the ring starts from its static state only (start='static': "
                         f"the wheels at rest on the loaded track); got start={start!r}")


def attach_wheels(stepper: NewmarkStepper, wheel: Wheel, profile, u: np.ndarray, times,
                  reference_stiffness, wagons: int = 1):
    """The wheels at rest on the statically loaded ring: (u, WheelStepper).

    With no primary stiffness the wheel carries P = Q at rest, so the ring's
    static state `u` (under the constant forces Q) is kept and the wheel sits
    delta_0 = (Q / C_H)^{2/3} below the rail top: z = u_c + r - delta_0.  With
    k_p > 0 the wheel's rest is P = Q + k_p z, solved with the ring
    (`solve_contacts` on the static matrix K + k0 U U^T).

    Parameters
    ----------
    stepper : NewmarkStepper
    wheel : Wheel
        (A `Vehicle`: `railtrack.timedomain.ring_vehicle.attach_vehicle`.)
    profile : callable or None
        r(x) [m]; None is the smooth rail.
    u : ndarray, shape (n_dofs,)
        The ring's static state under the constant forces [m, rad].
    times : ndarray, shape (steps,)
        The steps of a period [s].
    reference_stiffness : float or ndarray
        k0 of the factored matrix [N/m] (one per sleeper for a cell).
    wagons : int
        Wagons on the ring (for messages).
    """
    mesh = stepper.mesh
    r = profile_on_ring(smooth_rail if profile is None else profile, mesh, times, wagons)
    dofs, shapes = contact_shapes(mesh, times)
    local = contact_compliance(mesh, times)          # None for Hermite elements
    loads = np.asarray(mesh.passage.axle_loads, dtype=float)
    if float(wheel.primary_stiffness) == 0.0:
        p = loads.copy()
        uc = np.einsum("jk,jk->j", shapes[0], u[dofs[0]])
        if local is not None:
            uc = uc - local[0] * p
        z = uc + r[0] - np.array([wheel.static_compression(q) for q in loads])
    else:
        k = float(wheel.primary_stiffness)
        system = CondensedSystem(mesh.stiffness + _sleeper_projector(mesh, reference_stiffness),
                                 mesh.sleeper_dofs)
        rest = np.zeros(mesh.n_sleepers)

        def remainder(w):
            force, slope, _ = evaluate_law(stepper.foundation, w, rest)
            return force - reference_stiffness * w, slope - reference_stiffness

        rhs = np.zeros(mesh.n_dofs) if stepper.constant is None else stepper.constant.copy()
        u, _, p, uc = solve_contacts(system, rhs, (dofs[0], shapes[0]), wheel, r[0] + loads / k, k,
                                     remainder, (rest, loads), stepper.tol, stepper.iterations,
                                     None if local is None else local[0])
        z = (p - loads) / k
    zero = np.zeros_like(z)
    wheels = WheelStepper(stepper, wheel, r, (dofs, shapes), loads, (z, zero, zero, p), local)
    wheels.uc = uc
    return u, wheels


class WheelStepper:
    """Newmark steps of the ring with one wheel per axle on Hertz springs (module docstring).

    Parameters
    ----------
    stepper : NewmarkStepper
        The ring's stepper (factored matrix, history operator, foundation);
        its moving wheel loads are not used: the wheels load the rail
        through their contact forces.
    wheel : railtrack.model.wheel.Wheel
    profile_values : ndarray, shape (steps, J)
        r(x_c) [m] under each wheel at each step of a period.
    shapes : (dofs, weights), shapes (steps, J, 4)
        `contact_shapes` at each step of a period.
    loads : ndarray, shape (J,)
        Q_j [N].
    state : (z, z', z'') and P, each shape (J,)
        The wheels' state and contact forces at t = 0 [m, m/s, m/s^2], [N].
    compliance : ndarray, shape (steps, J), optional
        g(xi) under each wheel at each step [m/N] (`contact_compliance`).

    Notes
    -----
    `step` records the state it starts from (step index ``index - 1``) in
    ``contact_forces``, ``wheel_displacements`` and ``rail_under_wheels``
    (u_c), shape (steps, J): after a period these hold the period just run.
    """

    def __init__(self, stepper: NewmarkStepper, wheel, profile_values, shapes, loads, state,
                 compliance=None):
        self.stepper, self.wheel, self.compliance = stepper, wheel, compliance
        self.r, (self.dofs, self.shapes) = profile_values, shapes
        self.q = np.asarray(loads, dtype=float)
        self.z, self.zv, self.za, self.p = (np.array(part, dtype=float) for part in state)
        dt, m, alpha = stepper.dt, float(wheel.unsprung_mass), stepper.alpha
        inertia = 4.0 / dt**2 if alpha == 0.0 else 1.0 / ((1.0 - alpha) * stepper.newmark[1] * dt**2)
        self.gain = float(wheel.primary_stiffness) + stepper.gain * float(wheel.primary_damping) \
            + inertia * m
        steps, count = self.r.shape
        self.contact_forces = np.empty((steps, count))
        self.wheel_displacements = np.empty((steps, count))
        self.rail_under_wheels = np.empty((steps, count))
        self.previous: np.ndarray | None = None
        self.uc = np.zeros(count)

    def period_change(self) -> float:
        """How far the last period is from a periodic one, for the wheels [-].

        The larger of max |P_k - P_{k-1}| / max |P_k| between the last two
        periods and the wheels' equilibrium over the last period,
        max_j |mean P_j - Q_j - k_p mean z_j| / max Q (zero for a periodic
        state: the means of z'' and z' vanish).  A wheel that has lost
        contact for good (P = 0 all period) is never periodic.
        """
        current = self.contact_forces
        change = np.inf
        if self.previous is not None and np.all(np.isfinite(current)):
            peak = max(float(np.max(np.abs(current))), float(np.max(self.q)))
            change = float(np.max(np.abs(current - self.previous))) / peak
        stiffness = float(self.wheel.primary_stiffness)
        balance = current.mean(axis=0) - self.q - stiffness * self.wheel_displacements.mean(axis=0)
        self.previous = current.copy()
        return max(change, float(np.max(np.abs(balance))) / float(np.max(self.q)))

    def _wheel_history(self) -> np.ndarray:
        """h_w: the wheels' Newmark right-hand side from the state at the start of the step [N]."""
        base, wheel = self.stepper, self.wheel
        dt, alpha = base.dt, base.alpha
        m, c = float(wheel.unsprung_mass), float(wheel.primary_damping)
        if alpha == 0.0:
            return (m * ((4.0 / dt**2) * self.z + (4.0 / dt) * self.zv + self.za)
                    + c * ((2.0 / dt) * self.z + self.zv))
        # HHT: the spring, dashpot and contact at t_{n+1} - alpha dt (`NewmarkStepper`).
        beta, k = base.newmark[1], float(wheel.primary_stiffness)
        inertia = m / ((1.0 - alpha) * beta * dt**2)
        start = self.p - self.q - c * self.zv - k * self.z
        return (inertia * (self.z + dt * self.zv + dt**2 * (0.5 - beta) * self.za)
                + c * (base.gain * self.z + base.rates[0] * self.zv + base.rates[1] * self.za)
                + alpha / (1.0 - alpha) * start)

    def step(self, u, v, a, index: int):
        """State (u, u', u'') of the ring at the end of the step ending at step `index`."""
        base = self.stepper
        previous = (index - 1) % self.r.shape[0]
        self.contact_forces[previous] = self.p
        self.wheel_displacements[previous] = self.z
        self.rail_under_wheels[previous] = self.uc
        sleepers = base.mesh.sleeper_dofs
        rhs = base.right_hand_side(u, v, a)
        if base.alpha != 0.0:   # HHT: the contact forces at the start of the step, where they were
            ratio = base.alpha / (1.0 - base.alpha)
            for j in range(self.q.size):
                np.add.at(rhs, self.dofs[previous][j], -ratio * self.p[j] * self.shapes[previous][j])
        history = self._wheel_history()
        u_next, base.force, self.p, self.uc = solve_contacts(
            base.system, rhs, (self.dofs[index], self.shapes[index]), self.wheel,
            self.r[index] - (history - self.q) / self.gain, self.gain,
            base._remainder(base.offset(u, v, a, sleepers)), (base.force, self.p),
            base.tol, base.iterations, None if self.compliance is None else self.compliance[index])
        z_next = (history + self.p - self.q) / self.gain
        self.z, self.zv, self.za = base.finish(self.z, self.zv, self.za, z_next)
        return base.finish(u, v, a, u_next)

    def outputs(self) -> dict[str, np.ndarray]:
        """The wheels' records of the last period for `TimeDomainSolution` (copies)."""
        return dict(contact_forces=self.contact_forces.copy(),
                    wheel_displacements=self.wheel_displacements.copy(),
                    rail_under_wheels=self.rail_under_wheels.copy(), wheel=self.wheel)
