"""The virtual MinSeg: the board's firmware behaviour (protocol 3) with the plant behind it.

:class:`VirtualBoard` is the firmware as a state machine on a board clock it does not
own: a driver moves it forward with :meth:`VirtualBoard.run_until` (board time in s) and
passes host bytes in with :meth:`VirtualBoard.feed`; the board's output lines collect in
an outbox read with :meth:`VirtualBoard.take_output`. Two drivers exist: the pyserial URL
``minseg://`` (real-time or virtual clock, :mod:`minseg_tui.device.url_handler.protocol_minseg`)
and the pseudo-terminal server (:mod:`minseg_tui.device.ptyserver`).

Semantics follow firmware/PROTOCOL.md and the firmware itself: both answer the
conformance script firmware/golden/conformance.txt byte for byte alike (the firmware in
simavr, this board in tests/device/test_conformance.py). Written down:

- ``V`` takes effect at the next sample instant, so the ``u_mV`` of every ``$S`` line is
  exactly the command in force from that sample on. ``STOP``, the watchdog and ``P``
  during a square wave stop the motor at once; the next ``$S`` shows 0.
- ``STEP`` starts at the next sample instant with edge 1 (high); each half period is
  ``half_ms / period`` samples rounded to nearest, halves up (at least 1), so every edge
  falls on a sample, and ``$OK,STEP`` reports the half period so used.
  The ``$S`` line of an edge comes before its ``$EV,STEP``.
- Lines are assembled as the firmware does: one ``\\r`` before ``\\n`` is dropped, a line
  of more than 80 bytes is refused whole with ``$ERR,ARGS``; a reset forgets a partial
  line. Commands are parsed by :func:`protocol.parse_command`, the firmware's parser.
- The first sample comes one sample period after ``$BOOT``; ``seq`` advances only while
  streaming.
- ``$EV,WDOG`` is sent once per silence, and only when there was something to stop
  (a non-zero command or a square wave).
- The shortest sample period is 1000 us here (the real board's floor is 2000 us).
- Duty = |u| / V_supply (the ``SUP`` setting, clamped to 1); the bridge then puts
  duty x the true supply (``PlantParams.v_supply``) into the driver model, so a wrong
  ``SUP`` setting shows as a wrong u_A, as on the real board.
- The extension ``METER`` answers ``$METER,<u_mV>,<i_uA>,<R_mohm>``: the multimeter.
- One motor connector, ``M1``: ``DIAG`` answers ``$DIAG,M1,<active>,M1:<AB>:<edges>``.
  ``DIR`` is kept across resets for the life of the board object (the firmware's EEPROM).
  As on the firmware, the count of ``$S`` lines stays 0 until the encoder counted 4 edges
  since reset (the connector becomes *active*), then follows the encoder.
- Wiring faults (:class:`Faults`: ``encoder_off``, ``encoder_reversed``, ``motor_off``,
  by name through ``fault=`` in the URL or ``minseg-tui sim --fault``) fail the ways a
  board at the bench does; :meth:`VirtualBoard.turn_by_hand` turns the wheel as a hand.
"""

from __future__ import annotations

import dataclasses
import math
import threading
import time
from collections import deque
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from minseg_tui.device import protocol as P
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import MeterReading, Plant, PlantParams, ZeroMode
from minseg_tui.quantities import NUMBER
from minseg_tui.units import KA_OVER_KV

FIRMWARE = "minseg-virtual 3.0.0"
BOARD = "Virtual"
CONNECTOR = "M1"
"""The virtual board's one motor connector."""
_GRAY = ("00", "10", "11", "01")  # encoder pins A, B at count mod 4 (x4 quadrature)
WATCHDOG_S = 1.0
PERIOD_LIMITS_US = (1000, 100000)
HALF_LIMITS_MS = (20, 60000)
N_LIMITS = (1, 1000)
SUPPLY_LIMITS_MV = (3000, 12000)


@dataclass
class Faults:
    """Faults to inject, for tests and practice. Probabilities are per output line.

    garbage: random bytes before a line; truncate: a line cut short; bad_checksum: a
    digit changed after the checksum was computed; drop: a sample line lost;
    silent: the board stops answering (no output at all, commands ignored).

    Wiring faults, as a board at the bench fails (named in ``WIRING_FAULTS``):
    encoder_off: the encoder cable is out (no edges, both pins read 1 with the pull-ups);
    encoder_reversed: the count falls for a positive voltage; motor_off: no motor on the
    driver (cable out, power switch off, the Task 5 jumper out with no meter in series):
    the wheel does not turn and no current flows.
    """

    garbage: float = 0.0
    truncate: float = 0.0
    bad_checksum: float = 0.0
    drop: float = 0.0
    silent: bool = False
    encoder_off: bool = False
    encoder_reversed: bool = False
    motor_off: bool = False


WIRING_FAULTS: dict[str, str] = {
    "encoder-off": "encoder_off",
    "encoder-reversed": "encoder_reversed",
    "motor-off": "motor_off",
}
"""The wiring faults by the name the URL (``fault=``) and ``minseg-tui sim --fault`` use,
to their field of :class:`Faults`."""


def wiring_faults(text: str) -> list[str]:
    """The fields of :class:`Faults` for a comma list of fault names (``encoder-off,motor-off``);
    raises ValueError naming a name that is not a fault."""
    out: list[str] = []
    for raw in text.split(","):
        name = raw.strip().lower()
        if not name:
            continue
        if name not in WIRING_FAULTS:
            raise ValueError(
                f"option fault: expected {', '.join(WIRING_FAULTS)} (or several, comma-separated), "
                f"got {raw.strip()!r}"
            )
        out.append(WIRING_FAULTS[name])
    return out


@dataclass
class VirtualSettings:
    """Everything about a virtual board: the plant, its seed and what the firmware reports.

    jitter_us: loop latency of each sample, uniform in [0, jitter_us] us (seeded);
    boot_ms: delay from reset to $BOOT, ms; micros0 / seq0: the board's micros() and
    sequence number at reset (to test uint32 wrap); proto: the protocol version it
    claims (set it wrong to test the handshake); sup_mV: SUP setting after reset, mV.
    """

    params: PlantParams = field(default_factory=PlantParams)
    seed: int = 0
    jitter_us: float = 40.0
    boot_ms: float = 0.0
    micros0: int = 0
    seq0: int = 0
    proto: int = P.PROTOCOL_VERSION
    sup_mV: int = 5000
    faults: Faults = field(default_factory=Faults)


def _clamp(v: int, lo: int, hi: int) -> int:
    return max(lo, min(hi, v))


# -- options by name: the URL query, the `sim` command line -----------------------------
@dataclass(frozen=True)
class Option:
    """A setting reachable by name: where it goes (dotted path), its type, help and the
    range it may take (lo..hi, in the unit of its help): beyond it the simulation would be
    no MinSeg, or would not run (a boot delay of 30 years, a seed numpy refuses)."""

    path: str
    kind: type
    help: str
    lo: float = 0.0
    hi: float = math.inf


_U32 = 2**32 - 1
OPTIONS: dict[str, Option] = {
    "seed": Option("seed", int, "random seed (noise, jitter, faults)", 0, 2**63 - 1),
    "R": Option("params.motor.R", float, "armature resistance R, ohm", 0.1, 100.0),
    "kv": Option(
        "params.motor.k_v", float, "back-emf constant k_v, V s/rad (k_a = 0.65 k_v)", 1e-3, 10.0
    ),
    "ka": Option("params.motor.k_a", float, "torque constant k_a, N m/A", 1e-3, 10.0),
    "f": Option("params.motor.f", float, "viscous friction f, N m s/rad", 0.0, 1.0),
    "J": Option("params.motor.J", float, "inertia J, kg m^2", 1e-7, 1.0),
    "coulomb": Option(
        "params.tau_c", float, "dry (Coulomb) friction torque, N m (0: none)", 0.0, 1.0
    ),
    "drop": Option("params.v_drop", float, "voltage the motor driver loses, V", 0.0, 5.0),
    "supply": Option("params.v_supply", float, "true supply voltage, V", 1.0, 24.0),
    "coast": Option("params.zero_mode", bool, "coast at zero command after reset (not brake)"),
    "deadtime": Option("params.dead_time", float, "dead time from command to motor, s", 0.0, 1.0),
    "pole": Option(
        "params.T2", float, "extra pole on the motor voltage, time constant s", 0.0, 1.0
    ),
    "jitter": Option("jitter_us", float, "loop latency of each sample, up to us", 0.0, 20000.0),
    "boot": Option("boot_ms", float, "delay from reset to $BOOT, ms", 0.0, 10000.0),
    "micros0": Option("micros0", int, "micros() at reset, us (to test wrap)", 0, _U32),
    "seq0": Option("seq0", int, "first sequence number (to test wrap)", 0, _U32),
    "proto": Option("proto", int, "protocol version the board claims", 0, 255),
    "garbage": Option(
        "faults.garbage", float, "fault: probability of garbage bytes per line", 0.0, 1.0
    ),
    "truncate": Option(
        "faults.truncate", float, "fault: probability of a truncated line", 0.0, 1.0
    ),
    "badcs": Option("faults.bad_checksum", float, "fault: probability of a bad checksum", 0.0, 1.0),
    "lose": Option("faults.drop", float, "fault: probability a sample line is lost", 0.0, 1.0),
}


def _out_of_range(name: str, opt: Option, value: float, raw: object) -> str | None:
    """Why ``value`` is outside the option's range (a ValueError message), or None."""
    if opt.lo <= value <= opt.hi:
        return None
    if opt.kind is int:
        # int(), not :.0f: 2**63 - 1 as a float is 2**63, a bound the option does not take
        return (
            f"option {name}: expected an integer from {int(opt.lo)} to {int(opt.hi)}, got {raw!r}"
        )
    if opt.path.startswith("faults."):
        return f"option {name}: expected a probability from 0 to 1, got {raw!r}"
    return f"option {name}: expected a number from {opt.lo:g} to {opt.hi:g}, got {raw!r}"


def settings_from(values: Mapping[str, str | float | int | bool]) -> VirtualSettings:
    """Settings from option names (see OPTIONS) to values; raises ValueError naming a bad one."""
    flat: dict[str, Any] = {}  # dotted path -> value of the option's kind
    for name, raw in values.items():
        if name == "fault":
            for fault in wiring_faults(str(raw)):
                flat[f"faults.{fault}"] = True
            continue
        opt = OPTIONS.get(name)
        if opt is None:
            known = ", ".join((*OPTIONS, "fault"))
            raise ValueError(f"unknown virtual board option {name!r} (known: {known})")
        v: Any
        try:
            if opt.kind is bool:
                v = raw if isinstance(raw, bool) else str(raw).lower() in ("1", "true", "yes", "")
            else:
                if isinstance(raw, str) and not NUMBER.match(raw.strip()):
                    raise ValueError(raw)  # 3_0, full-width digits: float() reads them
                v = opt.kind(raw)
        except (TypeError, ValueError):
            what = {int: "an integer", float: "a number", bool: "true or false"}[opt.kind]
            raise ValueError(f"option {name}: expected {what}, got {raw!r}") from None
        if opt.kind is float and not (math.isfinite(v) and v >= 0):
            raise ValueError(f"option {name}: expected a finite number, not negative, got {raw!r}")
        if opt.kind is not bool:
            problem = _out_of_range(name, opt, v, raw)
            if problem:
                raise ValueError(problem)
        if opt.path == "params.zero_mode":
            v = "coast" if v else "brake"
        flat[opt.path] = v
    motor = {k.split(".")[-1]: v for k, v in flat.items() if k.startswith("params.motor.")}
    if "k_v" in motor and "k_a" not in motor:
        motor["k_a"] = KA_OVER_KV * float(motor["k_v"])
    base = PlantParams()
    plant_kw = {
        k.split(".")[1]: v for k, v in flat.items() if k.startswith("params.") and "motor" not in k
    }
    params = dataclasses.replace(base, motor=dataclasses.replace(base.motor, **motor), **plant_kw)
    faults = Faults(**{k.split(".")[1]: v for k, v in flat.items() if k.startswith("faults.")})
    top = {k: v for k, v in flat.items() if "." not in k}
    return VirtualSettings(params=params, faults=faults, **top)


# -- the board --------------------------------------------------------------------------
@dataclass
class _SquareWaveRun:
    low: int
    high: int
    half: int  # samples per half period
    n: int
    i: int = 0  # samples since the start


class VirtualBoard:
    """The MinSeg firmware, simulated. Board time ``now`` in s since the board was made.

    Thread-safe: every public method takes the board's lock.
    """

    def __init__(self, settings: VirtualSettings | None = None) -> None:
        self.settings = settings or VirtualSettings()
        s = self.settings
        self.plant = Plant(s.params, seed=s.seed)
        self._rng = np.random.default_rng([s.seed, 1])  # loop jitter
        self._fault_rng = np.random.default_rng([s.seed, 2])
        self._hand_turns = 0
        self.lock = threading.RLock()
        self.changed = threading.Condition(self.lock)
        self.now = 0.0
        self.clock: Callable[[], float] | None = None
        """The real-time clock of whatever runs the board as host time passes (s of board
        time; set by the ``minseg://`` port and the pty server), None when it runs on its
        own virtual time: what moves it on only when it is read."""
        self._out = bytearray()
        self._inbuf = bytearray()
        self.lines_out = 0
        self.commands_in = 0
        self.truth: deque[P.SampleLine] = deque(maxlen=200_000)  # every sample, before faults
        self.plugged = True  # the USB cable (URL driver: opening an unplugged board fails)
        self.attached = False  # a port has it open (one program per board)
        self.enc_dir = "FWD"  # DIR: kept over resets, as the firmware's EEPROM
        self.motor_dir = "FWD"
        self._raw_seen = self._raw_count()
        self.reset()

    @property
    def faults(self) -> Faults:
        """The faults in force (change the fields at any time)."""
        return self.settings.faults

    # -- reset and time ------------------------------------------------------------------
    def reset(self) -> None:
        """A reset (power-up or DTR on open): firmware state back to defaults, motor off.

        The wheel keeps its physical state; the encoder count restarts at 0.
        """
        with self.lock:
            s = self.settings
            self.powered = True
            self._boot_at = self.now
            self._boot_due: float | None = self.now + s.boot_ms / 1000.0
            self.period_us = 25000
            self.sup_mV = s.sup_mV
            self.stream = True
            self.u_mV = 0
            self._pending_mV: int | None = None
            self._square_wave: _SquareWaveRun | None = None
            self._seq = s.seq0 & 0xFFFFFFFF
            self._count_base = 0  # the count when the reference below was taken
            self._raw_ref = self._raw_count()
            self._raw_seen = self._raw_count()
            self.edges = 0  # every edge of the encoder since reset
            self.active = False  # the connector counted 4 edges since reset
            self._last_host = self.now
            self._wdog_fired = False
            self._inbuf.clear()
            self._overlong = False
            self._out.clear()  # what was not yet sent is lost in a reset
            self._set_zero_mode("COAST" if s.params.zero_mode == "coast" else "BRAKE")
            self._drive(0)
            self._next_nominal = self._boot_due + self.period_us * 1e-6
            self._next_sample = self._next_nominal + self._jitter()

    def _jitter(self) -> float:
        j = self.settings.jitter_us
        return float(self._rng.uniform(0.0, j)) * 1e-6 if j > 0 else 0.0

    @property
    def booted(self) -> bool:
        """True once $BOOT has been sent (commands before it are lost, as in a bootloader)."""
        return self._boot_due is None

    def micros(self, t: float | None = None) -> int:
        """The board's micros() at board time t (default now): uint32, 4 us resolution."""
        tt = self.now if t is None else t
        us = math.floor((tt - self._boot_at) * 1e6 / 4.0 + 1e-6) * 4 + self.settings.micros0
        return us & 0xFFFFFFFF

    def next_event(self) -> float:
        """Board time of the next thing the board will do by itself, s."""
        with self.lock:
            if not self.powered:
                return math.inf
            t = self._boot_due if self._boot_due is not None else self._next_sample
            if self._watchdog_armed():
                t = min(t, self._last_host + WATCHDOG_S + 1e-6)
            return t

    def _watchdog_armed(self) -> bool:
        return not self._wdog_fired and (
            self.u_mV != 0 or self._square_wave is not None or bool(self._pending_mV)
        )

    def run_until(self, t: float, stop_on_output: bool = False) -> None:
        """Move board time forward to t (s), doing everything due on the way.

        With ``stop_on_output`` it stops early, at the first event that produced output.
        """
        with self.lock:
            while True:
                nxt = self.next_event()
                if nxt > t:
                    break
                self._advance_plant(nxt)
                self.now = max(self.now, nxt)
                before = len(self._out)
                self._do_event()
                if stop_on_output and len(self._out) > before:
                    self.changed.notify_all()
                    return
            if t > self.now:
                self._advance_plant(t)
                self.now = t
            if self._out:
                self.changed.notify_all()

    def _advance_plant(self, t: float) -> None:
        if t > self.plant.t:
            self.plant.advance(t - self.plant.t)
            self._count_edges()

    # -- the encoder ---------------------------------------------------------------------
    def _raw_count(self) -> int:
        """What the encoder's pins encode (x4): the wheel's count, the other way round when
        the encoder is wired reversed (fault)."""
        c = self.plant.count
        return -c if self.faults.encoder_reversed else c

    def _count_edges(self) -> None:
        raw = self._raw_count()
        if not self.faults.encoder_off:
            self.edges += abs(raw - self._raw_seen)
            if self.edges >= 4:
                self.active = True
        self._raw_seen = raw

    def _count_sign(self) -> int:
        if self.faults.encoder_off:
            return 0
        return -1 if self.enc_dir == "REV" else 1

    def _connector_count(self) -> int:
        """The encoder count of M1 (before the 'active' rule of $S lines)."""
        return self._count_base + self._count_sign() * (self._raw_count() - self._raw_ref)

    def _rebase_count(self, to: int) -> None:
        """Restart counting from ``to`` at the wheel's position now (Z, DIR, a fault)."""
        self._count_base = to
        self._raw_ref = self._raw_count()

    def pins(self) -> str:
        """The levels of the encoder's pins A and B now ("11" when it is unplugged)."""
        with self.lock:
            if self.faults.encoder_off:
                return "11"
            return _GRAY[self._raw_count() % 4]

    def set_wiring_fault(self, name: str, on: bool = True) -> None:
        """Make or mend a wiring fault (a field of :class:`Faults`: ``encoder_off``, ...),
        as a hand at the bench pulls or plugs a cable; the count keeps its value."""
        with self.lock:
            if name not in WIRING_FAULTS.values():
                raise ValueError(f"not a wiring fault: {name!r}")
            self._count_edges()
            count = self._connector_count()
            setattr(self.faults, name, on)
            self._rebase_count(count)
            self._raw_seen = self._raw_count()
            self._set_zero_mode(self.zero_mode)
            self._drive(self.u_mV)

    def turn_by_hand(self, revolutions: float) -> None:
        """Turn the wheel by hand by ``revolutions`` (positive: the way a positive voltage
        turns it), at once; the encoder sees every edge on the way. On a board run in real
        time, at the present moment: the board is first brought up to its clock, or the
        samples of the time since it was last read would all be made after the turn (a
        host that read late counted no turn at all)."""
        with self.lock:
            if self.clock is not None:
                self.run_until(self.clock())
            self.plant.theta += 2.0 * math.pi * revolutions
            self._count_edges()

    HAND_SPREAD = 0.015
    """How far a hand asked to turn the wheel once misses it, as a fraction of a
    revolution (one standard deviation; the lab's 5 % tolerance is over 3 of them)."""

    def hand_turn(self) -> float:
        """Turn the wheel once as a hand at the bench does, for the hand check on a board
        nobody can touch: one revolution, a little over or under it (seeded by the board's
        seed), either way round. The revolutions turned (signed)."""
        with self.lock:
            rng = np.random.default_rng([self.settings.seed, 3, self._hand_turns])
            self._hand_turns += 1
        revolutions = float(1.0 + self.HAND_SPREAD * rng.standard_normal())
        if rng.random() < 0.5:
            revolutions = -revolutions
        self.turn_by_hand(revolutions)
        return revolutions

    def _do_event(self) -> None:
        now = self.now
        if self._boot_due is not None and now >= self._boot_due:
            self._boot_due = None
            self._emit(P.Boot(FIRMWARE, self.settings.proto))
            return
        if self._watchdog_armed() and now >= self._last_host + WATCHDOG_S:
            self._wdog_fired = True
            self._square_wave = None
            self._pending_mV = None
            self.u_mV = 0
            self._drive(0)
            self._emit(P.EvWatchdog())
            return
        if now >= self._next_sample:
            self._sample()

    def _sample(self) -> None:
        count = self._connector_count() if self.active else 0
        count = ((count + 2**31) & 0xFFFFFFFF) - 2**31
        events: list[P.Message] = []
        wave = self._square_wave
        if wave is not None:
            if wave.i == 2 * wave.n * wave.half:
                self.u_mV = wave.low
                self._square_wave = None
                events.append(P.EvSquareWaveDone())
            elif wave.i % wave.half == 0:
                edge = wave.i // wave.half
                if edge % 2 == 0:
                    self.u_mV = wave.high
                    events.append(P.EvSquareWaveEdge(edge // 2 + 1, wave.n))
                else:
                    self.u_mV = wave.low
            wave.i += 1
        elif self._pending_mV is not None:
            self.u_mV = self._pending_mV
            self._pending_mV = None
        self._drive(self.u_mV)
        t_us = self.micros(self._next_sample)
        self.truth.append(P.SampleLine(self._seq, t_us, count, self.u_mV))
        if self.stream:
            if not (self.faults.drop and self._fault_rng.random() < self.faults.drop):
                self._emit(P.SampleLine(self._seq, t_us, count, self.u_mV))
            self._seq = (self._seq + 1) & 0xFFFFFFFF
        for ev in events:
            self._emit(ev)
        self._next_nominal += self.period_us * 1e-6
        self._next_sample = max(self._next_nominal + self._jitter(), self.now + 1e-9)

    # -- the motor driver ----------------------------------------------------------------
    def _drive(self, u_mV: int) -> None:
        """Duty = |u| / V_supply (setting), clamped to 1; the bridge gives duty x true supply,
        the other way round with DIR's motor REV; nothing with no motor on it (fault)."""
        duty = min(abs(u_mV) / self.sup_mV, 1.0)
        if self.faults.motor_off or not u_mV:
            self.plant.set_command(0.0)
            return
        sign = -1.0 if self.motor_dir == "REV" else 1.0
        self.plant.set_command(math.copysign(duty * self.plant.params.v_supply, sign * u_mV))

    def _set_zero_mode(self, mode: str) -> None:
        self.zero_mode = mode
        # a motor off the driver is an open circuit: no current, the wheel runs down freely
        coast = mode == "COAST" or self.faults.motor_off
        zm: ZeroMode = "coast" if coast else "brake"
        if self.plant.params.zero_mode != zm:
            self.plant.params = dataclasses.replace(self.plant.params, zero_mode=zm)

    # -- output --------------------------------------------------------------------------
    def _emit(self, msg: P.Message) -> None:
        if self.faults.silent:
            return
        line = P.format_line(msg)
        f, rng = self.faults, self._fault_rng
        if f.bad_checksum and rng.random() < f.bad_checksum:
            digits = [i for i, c in enumerate(line[:-3]) if c.isdigit()]
            if digits:
                i = digits[int(rng.integers(len(digits)))]
                line = line[:i] + str((int(line[i]) + 1) % 10) + line[i + 1 :]
        if f.truncate and rng.random() < f.truncate:
            line = line[: int(rng.integers(1, len(line)))]
        data = line.encode("ascii") + b"\n"
        if f.garbage and rng.random() < f.garbage:
            data = bytes(rng.integers(0, 256, int(rng.integers(1, 12))).astype(np.uint8)) + data
        self._out += data
        self.lines_out += 1

    def take_output(self, max_bytes: int | None = None) -> bytes:
        """Remove and return what the board has sent (up to max_bytes)."""
        with self.lock:
            n = len(self._out) if max_bytes is None else min(max_bytes, len(self._out))
            data = bytes(self._out[:n])
            del self._out[:n]
            return data

    @property
    def pending_output(self) -> int:
        """Bytes sent by the board and not yet taken."""
        return len(self._out)

    # -- input ---------------------------------------------------------------------------
    def feed(self, data: bytes) -> None:
        """Bytes from the host, received at board time ``now``; complete lines are served.

        The firmware's line assembler: at most MAX_LINE bytes and one trailing ``\\r`` are
        kept; a longer line is dropped whole and answered ``$ERR,ARGS`` at its newline.
        """
        with self.lock:
            if not self.powered or not self.booted or self.faults.silent:
                return  # a bootloader or a hung board hears nothing
            while data:
                nl = data.find(b"\n")
                chunk = data if nl < 0 else data[:nl]
                if not self._overlong:
                    if len(self._inbuf) + len(chunk) > P.MAX_LINE + 1:
                        self._overlong = True
                        self._inbuf.clear()
                    else:
                        self._inbuf += chunk
                if nl < 0:
                    break
                data = data[nl + 1 :]
                line = bytes(self._inbuf)
                self._inbuf.clear()
                if line.endswith(b"\r"):
                    line = line[:-1]
                if self._overlong or len(line) > P.MAX_LINE:
                    self._overlong = False
                    self._emit(P.Err("ARGS", ""))  # refused whole, nothing changes
                    continue
                self._serve(line)

    def _serve(self, raw: bytes) -> None:
        if not raw:
            return  # an empty line: no reply
        try:
            cmd = P.parse_command(raw)
            if isinstance(cmd, P.SquareWave | P.SetDirection) and self._square_wave is not None:
                raise P.ProtocolError("BUSY")
        except P.ProtocolError as exc:
            detail = "" if exc.code in ("CHECKSUM", "BUSY") else exc.detail
            self._emit(P.Err(exc.code, detail))  # refused: nothing changes, not the watchdog
            return
        self.commands_in += 1
        self._last_host = self.now
        self._wdog_fired = False
        reply = self._HANDLERS[type(cmd)](self, cmd)
        self._emit(reply)
        self.changed.notify_all()

    def _abort_square_wave(self) -> None:
        self._square_wave = None

    def _stop_now(self) -> None:
        """Zero command at once: no square wave, nothing pending, the bridge off."""
        self._square_wave = None
        self._pending_mV = None
        self.u_mV = 0
        self._drive(0)

    def _cmd_id(self, _c: P.Identify) -> P.Message:
        return P.Ident(
            FIRMWARE,
            self.settings.proto,
            BOARD,
            self.plant.params.cpr,
            self.period_us,
            self.sup_mV,
            self.zero_mode,
            self.enc_dir,
            self.motor_dir,
        )

    def _cmd_ping(self, _c: P.Ping) -> P.Message:
        return P.Ok("PING")

    def _cmd_v(self, c: P.SetVoltage) -> P.Message:
        mv = _clamp(c.mV, -self.sup_mV, self.sup_mV)
        self._abort_square_wave()
        self._pending_mV = mv
        return P.Ok("V", (str(mv),))

    def _cmd_square_wave(self, c: P.SquareWave) -> P.Message:
        lo = _clamp(c.low_mV, -self.sup_mV, self.sup_mV)
        hi = _clamp(c.high_mV, -self.sup_mV, self.sup_mV)
        half = _clamp(c.half_ms, *HALF_LIMITS_MS)
        n = _clamp(c.n, *N_LIMITS)
        # whole sample periods, nearest with halves up, at least one (as the firmware)
        samples = max(1, (half * 1000 + self.period_us // 2) // self.period_us)
        self._pending_mV = None
        self._square_wave = _SquareWaveRun(lo, hi, samples, n)
        used_ms = samples * self.period_us // 1000
        return P.Ok("STEP", (str(lo), str(hi), str(used_ms), str(n)))

    def _cmd_stop(self, _c: P.Stop) -> P.Message:
        self._stop_now()
        return P.Ok("STOP")

    def _cmd_p(self, c: P.SetPeriod) -> P.Message:
        clamped = _clamp(c.period_us, *PERIOD_LIMITS_US)
        us = (clamped + 500) // 1000 * 1000  # the nearest 1000 us, halves up
        if self._square_wave is not None:
            self._stop_now()  # P aborts a square wave and sets the command to 0
        last = self._next_nominal - self.period_us * 1e-6
        self.period_us = us
        self._next_nominal = max(last + us * 1e-6, self.now)
        self._next_sample = self._next_nominal + self._jitter()
        return P.Ok("P", (str(us),))

    def _cmd_z(self, _c: P.Zero) -> P.Message:
        self._rebase_count(0)
        return P.Ok("Z")

    def _cmd_dir(self, c: P.SetDirection) -> P.Message:
        count = self._connector_count()  # the switch does not change the count
        self.enc_dir, self.motor_dir = c.enc, c.motor
        self._rebase_count(count)
        self._drive(self.u_mV)
        return P.Ok("DIR", (c.enc, c.motor))

    def _cmd_diag(self, _c: P.ReadDiag) -> P.Message:
        state = P.ConnectorState(CONNECTOR, self.pins(), self.edges & 0xFFFFFFFF)
        return P.Diag(CONNECTOR, CONNECTOR if self.active else "NONE", (state,))

    def _cmd_sup(self, c: P.SetSupply) -> P.Message:
        self.sup_mV = lim = _clamp(c.mV, *SUPPLY_LIMITS_MV)
        self.u_mV = _clamp(self.u_mV, -lim, lim)  # what is in force and what will be
        if self._pending_mV is not None:
            self._pending_mV = _clamp(self._pending_mV, -lim, lim)
        if self._square_wave is not None:
            self._square_wave.low = _clamp(self._square_wave.low, -lim, lim)
            self._square_wave.high = _clamp(self._square_wave.high, -lim, lim)
        self._drive(self.u_mV)
        return P.Ok("SUP", (str(self.sup_mV),))

    def _cmd_zm(self, c: P.SetZeroMode) -> P.Message:
        self._set_zero_mode(c.mode)
        self._drive(self.u_mV)
        return P.Ok("ZM", (c.mode,))

    def _cmd_stream(self, c: P.SetStream) -> P.Message:
        self.stream = c.on
        return P.Ok("STREAM", ("1" if c.on else "0",))

    def _cmd_meter(self, _c: P.ReadMeter) -> P.Message:
        m = self.plant.multimeter()
        return P.Meter(round(m.u_A * 1000), round(m.i * 1e6), round(m.R * 1000))

    _HANDLERS: dict[type, Callable[[VirtualBoard, P.Message], P.Message]] = {
        P.Identify: _cmd_id,  # type: ignore[dict-item]
        P.Ping: _cmd_ping,  # type: ignore[dict-item]
        P.SetVoltage: _cmd_v,  # type: ignore[dict-item]
        P.SquareWave: _cmd_square_wave,  # type: ignore[dict-item]
        P.Stop: _cmd_stop,  # type: ignore[dict-item]
        P.SetPeriod: _cmd_p,  # type: ignore[dict-item]
        P.Zero: _cmd_z,  # type: ignore[dict-item]
        P.SetSupply: _cmd_sup,  # type: ignore[dict-item]
        P.SetZeroMode: _cmd_zm,  # type: ignore[dict-item]
        P.SetStream: _cmd_stream,  # type: ignore[dict-item]
        P.SetDirection: _cmd_dir,  # type: ignore[dict-item]
        P.ReadDiag: _cmd_diag,  # type: ignore[dict-item]
        P.ReadMeter: _cmd_meter,  # type: ignore[dict-item]
    }

    # -- the cable -----------------------------------------------------------------------
    def unplug(self) -> None:
        """Pull the USB cable: the board loses power (motor off), the port fails."""
        with self.lock:
            self.plugged = False
            self.powered = False
            self._square_wave = None
            self._pending_mV = None
            self.u_mV = 0
            self._drive(0)
            self._out.clear()
            self.changed.notify_all()

    def replug(self) -> None:
        """Plug the cable back in: the port can be opened again (opening resets the board)."""
        with self.lock:
            self.plugged = True
            self.changed.notify_all()

    # -- the multimeter ------------------------------------------------------------------
    def multimeter(self) -> MeterReading:
        """What a multimeter on M1A/M1B reads now: u_A (V), i (A), R (ohm)."""
        with self.lock:
            return self.plant.multimeter()


# -- clocks and the shared boards of the URL scheme ----------------------------------------
class RealTime:
    """Board time = host monotonic time, s, starting at ``start``; except that a stall of
    the host process (the board's thread not scheduled for longer than :attr:`MAX_STEP`, on a
    busy machine) pauses board time instead of skipping it. The virtual board runs in the
    host's process: a stalled process stops host and board alike, and a busy machine makes
    the board slower, never wrong (its watchdog does not take a stalled host for a silent
    one, nor does the link take the stalled board for a silent one)."""

    MAX_STEP = 0.2
    """The most board time moves between two readings of the clock, s (the board's thread
    reads it every few ms, the pty server every 50 ms at most)."""

    def __init__(self, start: float = 0.0) -> None:
        self.t0 = time.monotonic() - start
        self._last = start
        self._lock = threading.Lock()

    def __call__(self) -> float:
        """Board time now, s."""
        with self._lock:
            now = time.monotonic() - self.t0
            if now - self._last > self.MAX_STEP:  # a stall: the time beyond the step is lost
                self.t0 += now - self._last - self.MAX_STEP
                now = self._last + self.MAX_STEP
            self._last = max(self._last, now)
            return self._last


_NAMED: dict[str, VirtualBoard] = {}
_NAMED_LOCK = threading.Lock()


def named_board(name: str, settings: VirtualSettings | None = None) -> VirtualBoard:
    """The board called ``name`` in this process, made on first use (URL ``name=``).

    Reopening ``minseg://?name=x`` reaches the same board, as replugging a cable does.
    """
    with _NAMED_LOCK:
        board = _NAMED.get(name)
        if board is None:
            board = _NAMED[name] = VirtualBoard(settings)
        return board


def forget_board(name: str) -> None:
    """Drop a named board (tests use fresh names; this frees memory)."""
    with _NAMED_LOCK:
        _NAMED.pop(name, None)


__all__ = [
    "BOARD",
    "CONNECTOR",
    "FIRMWARE",
    "Faults",
    "MotorParams",
    "OPTIONS",
    "RealTime",
    "VirtualBoard",
    "VirtualSettings",
    "WIRING_FAULTS",
    "forget_board",
    "named_board",
    "settings_from",
    "wiring_faults",
]
