"""The manual's DC motor (equations 3.1-3.2 with L = 0) and its first-order form (3.7).

u_A = R i + k_v omega            (V)
k_a i = J omega' + f omega       (N m)
T omega' = -omega + K u_A,  T = R J / (R f + k_v k_a),  K = k_a / (R f + k_v k_a)
"""

from __future__ import annotations

from dataclasses import dataclass

from minseg_tui.units import KA_OVER_KV


@dataclass(frozen=True)
class FirstOrder:
    """T omega' = -omega + K u: time constant ``T`` in s, static gain ``K`` in rad/s per V."""

    T: float
    K: float

    def steady_state(self, u: float) -> float:
        """Final speed in rad/s for a constant input u (V)."""
        return self.K * u


@dataclass(frozen=True)
class MotorParams:
    """Physical parameters of the motor, referred to the wheel shaft.

    R: armature resistance (ohm); k_v: back-emf constant (V s/rad); k_a: torque constant
    (N m/A); f: viscous friction (N m s/rad); J: inertia (kg m^2).
    """

    R: float
    k_v: float
    k_a: float
    f: float
    J: float

    @property
    def damping(self) -> float:
        """R f + k_v k_a, in V N m s/(A rad) = N m s/rad * ohm: the denominator of T and K."""
        return self.R * self.f + self.k_v * self.k_a

    @property
    def T(self) -> float:
        """Time constant R J / (R f + k_v k_a) in s."""
        return self.R * self.J / self.damping

    @property
    def K(self) -> float:
        """Static gain k_a / (R f + k_v k_a) from u_A to omega, in rad/s per V."""
        return self.k_a / self.damping

    def first_order(self) -> FirstOrder:
        """The model of Task 14."""
        return FirstOrder(T=self.T, K=self.K)


def inertia_from_time_constant(T: float, R: float, f: float, k_v: float, k_a: float) -> float:
    """Task 13 / Preparation 15: J = T (R f + k_v k_a) / R in kg m^2, from T in s."""
    return T * (R * f + k_v * k_a) / R


PUBLISHED = MotorParams(R=5.26, k_v=0.495, k_a=KA_OVER_KV * 0.495, f=6.0e-4, J=1.32e-3)
"""Published MinSeg figures (Rensselaer lab materials): T about 0.043 s, K about 1.98 rad/s/V."""
