"""The vehicle above the wheels: a body on two bogies on four wheelsets, vertical and pitch.

One wagon: a body (mass m_c, pitch inertia J_c) on two secondary
suspensions (k_2, c_2 per bogie, both sides together) at +-a from its
centre, a = bogie spacing / 2; two bogies (m_b, J_b) each on two primary
suspensions (k_1, c_1 per wheelset, both axleboxes together) at +-b from the
bogie's centre, b = wheelbase / 2; four wheelsets of unsprung mass m_w.
Springs and dashpots are linear; the body and the bogies bounce and pitch,
the wheelsets bounce.  Left and right are alike, so the whole wagon is
described; on the one modelled rail each wheel carries half a wheelset's
load (the convention of `railtrack.Train` and `railtrack.Wheel`).

Its matrices and natural frequencies are in `railtrack.equations.vehicle_matrices`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .plausibility_check import check_plausible, quantities_to_si
from .train import STANDARD_GRAVITY, Train
from .validation import as_float64, require_non_negative, require_positive
from .wheel import HERTZ_UIC60, Wheel

__all__ = ["Vehicle"]


@dataclass(frozen=True)
class Vehicle:
    """A four-axle bogie wagon, vertical and pitch: 10 degrees of freedom.

    Parameters
    ----------
    body_mass, body_pitch_inertia : float
        m_c > 0 [kg], J_c > 0 [kg m^2].
    bogie_mass, bogie_pitch_inertia : float
        m_b > 0 [kg], J_b > 0 [kg m^2], each bogie.
    wheelset_mass : float
        m_w > 0 [kg], each wheelset (unsprung).
    secondary_stiffness, secondary_damping : float
        k_2 > 0 [N/m], c_2 >= 0 [N s/m], per bogie (both sides).
    primary_stiffness, primary_damping : float
        k_1 > 0 [N/m], c_1 >= 0 [N s/m], per wheelset (both axleboxes).
    bogie_spacing : float
        2a > 0 [m], between the bogie centres.
    wheelbase : float
        2b > 0 [m], between a bogie's wheelsets; < bogie_spacing.
    hertz_constant : float
        C_H > 0 [N/m^1.5] of each wheel on the rail (default `HERTZ_UIC60`):
        with it a Vehicle goes wherever a `Wheel` goes (``railtrack.solve(...,
        wheel=vehicle)``, ``simulate_time_domain(..., wheel=vehicle)``).

    Examples
    --------
    >>> car = Vehicle.manchester()
    >>> car.total_mass
    44482.0
    >>> car.wheelset_positions.tolist()                 # from the body's centre [m]
    [10.78, 8.22, -8.22, -10.78]
    """

    body_mass: float
    body_pitch_inertia: float
    bogie_mass: float
    bogie_pitch_inertia: float
    wheelset_mass: float
    secondary_stiffness: float
    secondary_damping: float
    primary_stiffness: float
    primary_damping: float
    bogie_spacing: float
    wheelbase: float
    hertz_constant: float = HERTZ_UIC60

    def __post_init__(self) -> None:
        quantities_to_si(self)
        units = dict(body_mass="kg", body_pitch_inertia="kg m^2", bogie_mass="kg",
                     bogie_pitch_inertia="kg m^2", wheelset_mass="kg",
                     secondary_stiffness="N/m", primary_stiffness="N/m",
                     bogie_spacing="m", wheelbase="m", hertz_constant="N/m^1.5")
        for name, unit in units.items():
            require_positive(name, getattr(self, name), unit)
        require_non_negative("secondary_damping", self.secondary_damping, "N s/m")
        require_non_negative("primary_damping", self.primary_damping, "N s/m")
        for name in (*units, "secondary_damping", "primary_damping"):
            if np.ndim(getattr(self, name)) != 0:
                raise TypeError(f"{name} must be a single number; got {getattr(self, name)!r}")
        if self.wheelbase >= self.bogie_spacing:
            raise ValueError(f"the wheelbase ({self.wheelbase} m) must be shorter than the "
                             f"bogie spacing ({self.bogie_spacing} m): the bogies would overlap")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def manchester(cls) -> Vehicle:
        """The Manchester benchmark passenger vehicle (Iwnicki 1998), vertical and pitch.

        Source: S. Iwnicki, "The Manchester Benchmarks for Rail Vehicle
        Simulation", Vehicle System Dynamics 30(3-4) (1998) 295-313,
        doi:10.1080/00423119808969454.  We could not read the paper; the
        values are as two independent transcriptions of it give them
        (D. Cantero's TTB-2D, GitHub DanielCanteroNTNU/TTB-2D, file
        TrainProp_Manchester_BenchMark.m; and a MATLAB vehicle-track code
        found by content search, repository not identified, listing the
        benchmark per axlebox and per bogie side): body 32 000 kg,
        1.97e6 kg m^2; bogie frame 2615 kg, 1476 kg m^2; wheelset 1813 kg;
        secondary vertical 430 kN/m and 20 kN s/m per bogie side; primary
        vertical 4 kN s/m per axlebox; half bogie spacing 9.5 m; half
        wheelbase 1.28 m.  Their one disagreement: the primary vertical
        stiffness per axlebox, 1.22 MN/m (the second, which lists every
        direction's value) or 1.20 MN/m (TTB-2D); 1.22 MN/m is taken.
        Per bogie and per wheelset (both sides) the values double.
        """
        return cls(body_mass=32000.0, body_pitch_inertia=1.97e6, bogie_mass=2615.0,
                   bogie_pitch_inertia=1476.0, wheelset_mass=1813.0,
                   secondary_stiffness=2 * 430e3, secondary_damping=2 * 20e3,
                   primary_stiffness=2 * 1.22e6, primary_damping=2 * 4e3,
                   bogie_spacing=2 * 9.5, wheelbase=2 * 1.28)

    @property
    def total_mass(self) -> float:
        """m_c + 2 m_b + 4 m_w [kg]."""
        return float(self.body_mass + 2 * self.bogie_mass + 4 * self.wheelset_mass)

    @property
    def bogie_positions(self) -> np.ndarray:
        """The bogie centres from the body's centre, leading first: [a, -a] [m]."""
        half = 0.5 * self.bogie_spacing
        return np.array([half, -half])

    @property
    def wheelset_positions(self) -> np.ndarray:
        """The wheelsets from the body's centre, leading first: [a+b, a-b, -a+b, -a-b] [m]."""
        a, b = 0.5 * self.bogie_spacing, 0.5 * self.wheelbase
        return np.array([a + b, a - b, -a + b, -a - b])

    def train(self, wagon_length: float, speed: float,
              gravity: float = STANDARD_GRAVITY) -> Train:
        """The `Train` of such wagons: its axles, and each wheel's static load [N].

        Axles at d = 0, 2b, 2a, 2a + 2b behind the first; each wheel on the
        modelled rail carries half its wheelset's load, (m_c + 2 m_b + 4 m_w) g / 8
        (the vehicle is symmetric: `railtrack.equations.vehicle_matrices`
        finds the same by statics).

        Examples
        --------
        >>> coach = Vehicle.manchester().train(26.4, 45.0)
        >>> list(coach.axle_positions), round(float(coach.axle_loads[0]) / 1e3, 2)
        ([0.0, 2.56, 19.0, 21.56], 54.55)
        """
        a2, b2 = float(self.bogie_spacing), float(self.wheelbase)
        load = self.static_wheel_load(gravity)
        return Train(wagon_length, (0.0, b2, a2, a2 + b2), (load,) * 4, speed)

    @property
    def unsprung_mass(self) -> float:
        """m_w / 2 [kg]: the wheel's share of its wheelset on the modelled rail."""
        return 0.5 * float(self.wheelset_mass)

    @property
    def contact(self) -> Wheel:
        """The wheel on the modelled rail as the contact sees it: m_w / 2 on C_H, no suspension.

        Its Hertz law is the vehicle's; the suspension above it is the vehicle's
        own business (`railtrack.equations.wheel_receptance`).
        """
        return Wheel(self.unsprung_mass, self.hertz_constant)

    def contact_force(self, compression) -> np.ndarray:
        """P = C_H max(delta, 0)^{3/2} [N] for the compression delta [m] (`Wheel`)."""
        return self.contact.contact_force(compression)

    def contact_stiffness(self, compression) -> np.ndarray:
        """dP/d delta [N/m] (`Wheel`)."""
        return self.contact.contact_stiffness(compression)

    def static_compression(self, load: float) -> float:
        """delta_0 = (Q / C_H)^{2/3} [m] under the wheel load Q [N] (`Wheel`)."""
        return self.contact.static_compression(load)

    def static_wheel_load(self, gravity: float = STANDARD_GRAVITY) -> float:
        """Each wheel's static load on the modelled rail, (m_c + 2 m_b + 4 m_w) g / 8 [N]."""
        return self.total_mass * float(gravity) / 8

    def check_train(self, train: Train, gravity: float = STANDARD_GRAVITY) -> None:
        """Raise ValueError unless `train`'s axles and wheel loads are this vehicle's.

        The axles must sit at 0, 2b, 2a, 2a + 2b behind the first (1e-9 m) and
        each wheel load be (m_c + 2 m_b + 4 m_w) g / 8 (relative 1e-6): the
        train `Vehicle.train` builds.

        Examples
        --------
        >>> car = Vehicle.manchester()
        >>> car.check_train(car.train(26.4, 45.0))           # silent: they agree
        """
        expected = self.train(train.wagon_length, train.speed, gravity)
        axles = np.asarray(train.axle_positions, dtype=float)
        want = np.asarray(expected.axle_positions, dtype=float)
        if axles.shape != want.shape or np.max(np.abs(axles - axles[0] - want)) > 1e-9:
            raise ValueError(f"the train's axle_positions {axles.tolist()} m are not the "
                             f"vehicle's {want.tolist()} m (0, 2b, 2a, 2a + 2b): build the "
                             f"train with vehicle.train(wagon_length, speed)")
        loads = np.asarray(train.axle_loads, dtype=float)
        load = self.static_wheel_load(gravity)
        if np.max(np.abs(loads - load)) > 1e-6 * load:
            raise ValueError(f"the train's axle_loads {loads.tolist()} N are not the vehicle's "
                             f"static wheel loads, {load:.6g} N each on the modelled rail "
                             f"((m_c + 2 m_b + 4 m_w) g / 8): build the train with "
                             f"vehicle.train(wagon_length, speed)")

    def wheel(self, hertz_constant: float | None = None) -> Wheel:
        """Today's `Wheel` on the modelled rail: what each wheel becomes under a fixed body.

        Half a wheelset (m_w / 2) on half its primary suspension (k_1 / 2,
        c_1 / 2) to a body that does not move: the limit of an infinitely
        heavy body and bogies.

        Examples
        --------
        >>> Vehicle.manchester().wheel().unsprung_mass
        906.5
        """
        hertz_constant = self.hertz_constant if hertz_constant is None else hertz_constant
        return Wheel(0.5 * self.wheelset_mass, hertz_constant, 0.5 * self.primary_stiffness,
                     0.5 * self.primary_damping)
