"""A simulation of the real MinSeg plant: the manual's motor plus what a real board adds.

What it models, beyond T omega' = -omega + K u_A:

- the motor driver's voltage loss: the requested u (V) becomes u_A at the motor terminals;
- dry (Coulomb) friction ``tau_c`` (N m) with sticking at zero speed;
- what the H-bridge does at zero command: ``brake`` (terminals shorted, u_A = 0) or
  ``coast`` (terminals open, i = 0, the wheel runs down on friction alone);
- an optional dead time (s) between command and motor, and an optional extra pole ``T2``
  (s) on the motor voltage (for instance the armature's L/R);
- an optional current limit ``i_max`` (A) of the driver: while the drive would push more
  current in the direction of motion, it gets i_max (the wheel ramps at a near-constant
  acceleration);
- an optional hand on the wheel (:class:`Touch`): a braking torque over a stretch of time;
- the encoder: 720 counts per wheel revolution, read as an integer count.

Loop jitter of the sample instants lives in :func:`record`, which plays a board sampling
the plant on its own clock. Everything random is drawn from a seeded generator.

Integration is exact for piecewise-constant input (closed-form exponentials between
events, the stop time of dry friction and the end of the current limit solved for); only
the extra pole is sub-stepped.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from minseg_tui.model.motor import PUBLISHED, MotorParams

ZeroMode = Literal["brake", "coast"]


@dataclass(frozen=True)
class Touch:
    """A hand on the wheel: a braking torque ``torque`` (N m, opposing the motion like dry
    friction) from ``start`` to ``end`` (s, plant time)."""

    start: float
    end: float
    torque: float


@dataclass(frozen=True)
class PlantParams:
    """Parameters of the simulated board + motor, in SI units.

    motor: R (ohm), k_v (V s/rad), k_a (N m/A), f (N m s/rad), J (kg m^2);
    tau_c: Coulomb friction torque, N m (0 for none);
    v_drop: voltage the driver loses, V (u_A = u - v_drop for |u| > v_drop);
    v_supply: supply voltage, V (|u_A| is at most v_supply - v_drop);
    zero_mode: "brake" or "coast" at zero command;
    dead_time: delay from command to motor, s; T2: extra pole on the motor voltage, s;
    cpr: encoder counts per wheel revolution; i_max: the driver's current limit, A (0 for
    none); touch: a hand on the wheel, or None.
    """

    motor: MotorParams = PUBLISHED
    tau_c: float = 7.3e-3
    v_drop: float = 0.45
    v_supply: float = 5.0
    zero_mode: ZeroMode = "brake"
    dead_time: float = 0.0
    T2: float = 0.0
    cpr: int = 720
    i_max: float = 0.0
    touch: Touch | None = None

    def __post_init__(self) -> None:
        m = self.motor
        if min(m.R, m.k_v, m.k_a, m.J) <= 0 or m.f < 0 or self.tau_c < 0:
            raise ValueError("R, k_v, k_a and J must be positive; f and tau_c not negative")
        if self.i_max < 0:
            raise ValueError("i_max must not be negative (0 for no current limit)")
        if self.dead_time < 0 or self.T2 < 0 or self.v_drop < 0 or self.cpr <= 0:
            raise ValueError("dead_time, T2 and v_drop must not be negative; cpr positive")
        if self.zero_mode not in ("brake", "coast"):
            raise ValueError("zero_mode is 'brake' or 'coast'")

    def u_applied(self, u_req: float) -> float:
        """Voltage u_A (V) the driver puts on the motor for a requested u (V), in steady state."""
        mag = min(max(abs(u_req) - self.v_drop, 0.0), max(self.v_supply - self.v_drop, 0.0))
        return math.copysign(mag, u_req) if mag > 0 else 0.0

    @property
    def u_coulomb(self) -> float:
        """Breakaway voltage u_A (V) that just balances dry friction at rest: tau_c R / k_a."""
        return self.tau_c * self.motor.R / self.motor.k_a

    def omega_ss(self, u_req: float) -> float:
        """Steady speed in rad/s for a constant request u (V) (0 when it cannot break away)."""
        u_a = self.u_applied(u_req)
        if abs(u_a) <= self.u_coulomb:
            return 0.0
        m = self.motor
        return m.K * (u_a - math.copysign(self.u_coulomb, u_a))


LEADS_OHM = 0.04
"""What the multimeter's leads and probe contacts add to a resistance it reads, ohm (the
mean that the one-sided noise of the earlier reading added)."""


@dataclass(frozen=True)
class MeterReading:
    """What a multimeter on M1A/M1B shows: u_A in V, i in A, R in ohm (rounded to its digits)."""

    u_A: float
    i: float
    R: float


class Plant:
    """The motor and wheel, advanced in time under a held command.

    Angles in rad, speeds in rad/s, time in s, voltages in V, currents in A.
    """

    def __init__(
        self, params: PlantParams | None = None, seed: int = 0, omega0: float = 0.0
    ) -> None:
        self.params = params or PlantParams()
        self.t = 0.0
        self.theta = 0.0
        self.omega = float(omega0)
        self.u_req = 0.0
        self._u_eff = 0.0  # motor voltage after the extra pole, V
        self._active = 0.0  # command that has reached the bridge (after the dead time), V
        self._pending: deque[tuple[float, float]] = deque()  # (time it arrives, command)
        self._rng = np.random.default_rng(seed)

    # -- what can be read -------------------------------------------------------------
    @property
    def count(self) -> int:
        """Encoder count (integer, x4 decoding) of the wheel angle."""
        return math.floor(self.theta * self.params.cpr / (2.0 * math.pi) + 1e-9)

    @property
    def coasting(self) -> bool:
        """True when the bridge is open (zero command in coast mode)."""
        return self._active == 0.0 and self.params.zero_mode == "coast"

    @property
    def u_A(self) -> float:
        """Voltage on the motor terminals now, V (the back-emf k_v omega when coasting)."""
        if self.coasting:
            return self.params.motor.k_v * self.omega
        return self._u_eff if self.params.T2 > 0 else self.params.u_applied(self._active)

    @property
    def current(self) -> float:
        """Armature current now, A (0 when coasting)."""
        if self.coasting:
            return 0.0
        m = self.params.motor
        return (self.u_A - m.k_v * self.omega) / m.R

    def multimeter(self) -> MeterReading:
        """A multimeter reading at 0.01 V, 0.1 mA and 0.1 ohm resolution: u_A and i with
        last-digit noise (the drive and the current ripple); R the motor's with the leads'
        :data:`LEADS_OHM` and a noise a tenth of its last digit, so it holds still as a
        meter on a resistor does once settled, its last digit flickering only on a value
        at a rounding edge (with noise half a digit wide and one-sided, 5.26 ohm read 5.3
        or 5.4 between readings)."""
        noise = self._rng.normal(0.0, 1.0, 3)
        u = round(self.u_A + 0.003 * noise[0], 2)
        i = round((self.current * 1e3 + 0.05 * noise[1]), 1) / 1e3
        r = round(self.params.motor.R + LEADS_OHM + 0.01 * noise[2], 1)
        return MeterReading(u_A=u, i=i, R=r)

    # -- driving it -------------------------------------------------------------------
    def set_command(self, u_req: float) -> None:
        """Request u (V) from now on; it reaches the motor after the dead time."""
        self.u_req = float(u_req)
        if self.params.dead_time > 0:
            self._pending.append((self.t + self.params.dead_time, self.u_req))
        else:
            self._active = self.u_req

    def advance(self, dt: float) -> None:
        """Advance the plant by dt seconds, holding the current command."""
        if dt < 0:
            raise ValueError("dt must not be negative")
        end = self.t + dt
        touch = self.params.touch
        while self.t < end - 1e-15:
            stop = end
            if self._pending and self._pending[0][0] < stop:
                stop = max(self._pending[0][0], self.t)
            if touch is not None:
                for edge in (touch.start, touch.end):
                    if self.t < edge < stop:
                        stop = edge
            if stop > self.t:
                self._evolve(stop - self.t)
            self.t = stop
            while self._pending and self._pending[0][0] <= self.t + 1e-15:
                self._active = self._pending.popleft()[1]
        self.t = end

    # -- the physics ------------------------------------------------------------------
    def _evolve(self, h: float) -> None:
        """Evolve over h seconds with the bridge state fixed."""
        p = self.params
        if self.coasting or p.T2 <= 0:
            self._pieces(h, self._target_voltage())
            if self.coasting:  # no current: the pole's voltage is the back-emf (the net torque 0)
                self._u_eff = self.omega / p.motor.K
            return
        target = p.u_applied(self._active)
        n = max(1, math.ceil(h / (p.T2 / 20.0)))
        sub = h / n
        decay = math.exp(-sub / p.T2)
        for _ in range(n):
            u0 = self._u_eff
            # mean of the motor voltage over the sub-step (exact for the pole itself)
            u_mean = target + (u0 - target) * (p.T2 / sub) * (1.0 - decay)
            self._pieces(sub, u_mean)
            self._u_eff = target + (u0 - target) * decay

    def _target_voltage(self) -> float:
        return self.params.u_applied(self._active)

    def _pieces(self, h: float, u: float) -> None:
        """Exact motion over h s with constant motor voltage u (V) and dry friction.

        omega' = -a omega + b_drive - c sgn(omega), solved in closed form; a zero crossing
        stops the wheel, which then sticks unless the drive overcomes dry friction.
        """
        p = self.params
        m = p.motor
        if self.coasting:
            a, b_drive = m.f / m.J, 0.0
        else:
            a, b_drive = m.damping / (m.R * m.J), m.k_a * u / (m.R * m.J)
        tau = p.tau_c
        if p.touch is not None and p.touch.start <= self.t < p.touch.end:
            tau += p.touch.torque
        c = tau / m.J
        left = h
        while left > 0:
            w0 = self.omega
            if w0 == 0.0:
                if abs(b_drive) <= c:  # sticks: drive cannot break away
                    return
                s = math.copysign(1.0, b_drive)
            else:
                s = math.copysign(1.0, w0)
            a_now, b, knee = a, b_drive - s * c, None
            if p.i_max > 0 and not self.coasting and s * (u - m.k_v * w0) / m.R > p.i_max:
                # the driver limits the current: torque k_a i_max until the back-emf takes over
                a_now, b = m.f / m.J, s * m.k_a * p.i_max / m.J - s * c
                knee = _time_to(w0, a_now, b, (u - s * m.R * p.i_max) / m.k_v)
            t_stop = _time_to_zero(w0, a_now, b, s)
            ends = [e for e in (t_stop, knee) if e is not None]
            step = min([left, *ends])
            w1, dtheta = _linear_motion(w0, a_now, b, step)
            self.theta += dtheta
            left -= step
            if t_stop is not None and step == t_stop:
                self.omega = 0.0
            else:
                self.omega = w1
            if knee is not None and step == knee:
                self.omega = (u - s * m.R * p.i_max * (1.0 - 1e-12)) / m.k_v


def _linear_motion(w0: float, a: float, b: float, h: float) -> tuple[float, float]:
    """Solution of w' = -a w + b over h s: (w(h), integral of w) in rad/s and rad."""
    if a * h < 1e-9:
        return w0 + b * h, w0 * h + 0.5 * b * h * h
    w_inf = b / a
    e = math.exp(-a * h)
    return w_inf + (w0 - w_inf) * e, w_inf * h + (w0 - w_inf) * (1.0 - e) / a


def _time_to(w0: float, a: float, b: float, target: float) -> float | None:
    """When w' = -a w + b, started at w0, reaches ``target`` (None: never)."""
    if a * 1.0 < 1e-12:
        return (target - w0) / b if b != 0 and (target - w0) / b >= 0 else None
    w_inf = b / a
    ratio = (target - w_inf) / (w0 - w_inf) if w0 != w_inf else 0.0
    if ratio <= 0 or ratio > 1:
        return None
    return -math.log(ratio) / a


def _time_to_zero(w0: float, a: float, b: float, s: float) -> float | None:
    """When w' = -a w + b, started at w0 moving in direction s, reaches 0 (None: never)."""
    if s * b >= 0:  # pushed on in the direction of motion: never stops
        return None
    if w0 == 0.0:
        return None
    if a < 1e-12:
        return -w0 / b
    w_inf = b / a
    ratio = -w_inf / (w0 - w_inf)
    if ratio <= 0 or ratio >= 1:
        return None
    return -math.log(ratio) / a


@dataclass
class Recording:
    """What a board sampling the plant would log, one entry per sample.

    t: sample time on the board's clock, s; t_us: the same in whole microseconds as the
    board's micros() gives it (4 us resolution); seq: sample number; count: encoder count;
    u_req: command in force from this sample on, V; u_A: motor voltage at the sample, V;
    omega_true: true wheel speed at the sample, rad/s; current: armature current, A.
    """

    t: NDArray[np.float64]
    t_us: NDArray[np.int64]
    seq: NDArray[np.int64]
    count: NDArray[np.int64]
    u_req: NDArray[np.float64]
    u_A: NDArray[np.float64]
    omega_true: NDArray[np.float64]
    current: NDArray[np.float64]
    params: PlantParams = field(default_factory=PlantParams)
    ts: float = 0.025


def record(
    params: PlantParams,
    commands: ArrayLike,
    ts: float = 0.025,
    seed: int = 0,
    jitter_us: float = 0.0,
    *,
    command_on_grid: bool = False,
    encoder_phase: bool = False,
) -> Recording:
    """Sample the plant as the board does: at k ts (+ loop latency), then apply commands[k].

    ``commands`` is the requested voltage (V) in force from each sample on. Loop latency
    is drawn uniformly from [0, jitter_us] microseconds for each sample (seeded): the
    board's timestamp records when the count was really read. With ``command_on_grid`` the
    command changes at k ts itself, before the late read (a loop whose timer sets the drive
    on time and reads the encoder when it gets to it), not right after the read (this
    firmware). With ``encoder_phase`` the encoder starts at a random fraction of a count
    (seeded), as a real one does, instead of exactly on a count's edge.
    """
    u = np.asarray(commands, dtype=float)
    n = u.size
    rng = np.random.default_rng(seed)
    plant = Plant(params, seed=seed)
    lateness = rng.uniform(0.0, jitter_us * 1e-6, n) if jitter_us > 0 else np.zeros(n)
    t = np.arange(n) * ts + lateness
    t_us = (np.floor(t * 1e6 / 4.0) * 4).astype(np.int64)
    t = t_us / 1e6
    if encoder_phase:
        plant.theta = float(rng.uniform(0.0, 2.0 * math.pi / params.cpr))
    count = np.empty(n, dtype=np.int64)
    u_a = np.empty(n)
    omega = np.empty(n)
    current = np.empty(n)
    for k in range(n):
        if command_on_grid:
            plant.advance(max(k * ts - plant.t, 0.0))
            plant.set_command(u[k])
        plant.advance(max(t[k] - plant.t, 0.0))
        count[k] = plant.count
        if not command_on_grid:
            plant.set_command(u[k])
        u_a[k] = plant.u_A
        omega[k] = plant.omega
        current[k] = plant.current
    return Recording(
        t=t,
        t_us=t_us,
        seq=np.arange(n, dtype=np.int64),
        count=count,
        u_req=u,
        u_A=u_a,
        omega_true=omega,
        current=current,
        params=params,
        ts=ts,
    )


def square_wave(
    low: float, high: float, half_period: int, periods: int, lead: int = 0, tail: int = 0
) -> NDArray[np.float64]:
    """Commands per sample for a board-timed square wave, in V.

    ``lead`` samples at ``low``, then ``periods`` times ``half_period`` samples at ``high``
    and ``half_period`` at ``low``, then ``tail`` more samples at ``low``.
    """
    one = np.concatenate((np.full(half_period, high), np.full(half_period, low)))
    return np.concatenate((np.full(lead, low), np.tile(one, periods), np.full(tail, low)))
