"""Realistic run logs with hidden effects, for tests, benchmarks and a practice mode.

A log is what a MinSeg board records while a square wave of requested voltages drives
the motor: Ts = 0.025 s, the encoder's integer counts (720 per revolution), loop jitter
of the sample instants, the Euler velocity (theta_k - theta_k-1)/Ts with the nominal Ts
(or the lab's moving average of it). The plant is :func:`minseg_tui.model.plant.record`
with the effects' :class:`PlantParams`; everything else in it is first order.

Effects (the model check's cause names) and the range a parameter is drawn from; a log
holds one (``cause``), or two at once (``cause`` and ``also``). Each cause's realistic
range and the way it is made (a piece of the plant, the voltage the motor gets, or the
average the speed is measured over) sit in its entry of the check's registry
(:attr:`minseg_tui.model.check.effects.Candidate.hidden`); ``none`` is the plant without
dry friction that brakes at zero command.

Messiness a real log has, each optional: one wild sample (a misread count), a slow
creep of the speed after each rise, one step whose command reaches the motor between
two samples, and a hand on the wheel (a braking torque for 0.15-0.3 s in a settled driven
stretch). Everything random comes from one seeded generator.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.effects import BY_CAUSE, CANDIDATES
from minseg_tui.model.identify import Reading
from minseg_tui.model.motor import PUBLISHED
from minseg_tui.model.plant import Plant, PlantParams, Touch, record
from minseg_tui.model.runlog import RunLog

TS = 0.025
"""The board's sample period, s."""

PARAM_RANGES: dict[str, tuple[str, float, float]] = {
    c.cause: (c.param, c.hidden.lo, c.hidden.hi) for c in CANDIDATES if c.hidden is not None
}
"""Cause -> (parameter name, low, high): the realistic range a hidden effect is drawn from
(each cause's :attr:`~minseg_tui.model.check.effects.Candidate.hidden`)."""

CAUSES: tuple[str, ...] = ("none", *PARAM_RANGES)


@dataclass(frozen=True)
class SynthLog:
    """A generated run log and the truth behind it.

    t: board time, s; u: voltage applied to the motor (u_A as the board reports it), V;
    omega: measured speed, rad/s; count: encoder counts; u_req: requested voltage, V;
    omega_true: true wheel speed at each sample, rad/s; cause and param: the hidden
    effect (param None for ``none``); ts: nominal sample period, s; taps: the velocity
    filter's length (1 for the plain Euler velocity); wild_row, late_step_row, creep:
    the messiness put in (None/0 when absent); effects: every hidden effect and its
    parameter (cause and the second one, if any); touch: (start, end) of the hand on the
    wheel, s, or None.
    """

    t: NDArray[np.float64]
    u: NDArray[np.float64]
    omega: NDArray[np.float64]
    count: NDArray[np.int64]
    u_req: NDArray[np.float64]
    omega_true: NDArray[np.float64]
    cause: str
    param: float | None
    ts: float = TS
    taps: int = 1
    wild_row: int | None = None
    late_step_row: int | None = None
    creep: float = 0.0
    effects: dict[str, float] = field(default_factory=dict)
    touch: tuple[float, float] | None = None


def commands(
    rng: np.random.Generator,
    amplitudes: tuple[float, ...],
    duration: float,
    ts: float = TS,
    half_period: float = 1.0,
    lead: float = 0.25,
) -> NDArray[np.float64]:
    """Requested voltage per sample (V): rest, then steps 0 -> A -> 0 with A drawn from ``amplitudes``."""
    n = int(round(duration / ts))
    out = np.zeros(n)
    k = int(round(lead / ts))
    half = max(2, int(round(half_period / ts)))
    while k < n:
        out[k : k + half] = float(rng.choice(amplitudes))
        k += 2 * half
    return out


def plant_for(cause: str, param: float | None) -> PlantParams:
    """The plant that hides ``cause`` with parameter ``param`` (and nothing else)."""
    if cause == "none":
        return plant_with({})
    if param is None:
        raise ValueError(f"{cause} needs a parameter")
    return plant_with({cause: param})


def plant_with(effects: dict[str, float]) -> PlantParams:
    """The plant that hides every effect in ``effects`` ({cause: parameter}) at once."""
    p = PlantParams(tau_c=0.0, v_drop=0.45, v_supply=5.0, zero_mode="brake")
    for cause, param in effects.items():
        c = BY_CAUSE.get(cause)
        if c is None or c.hidden is None:
            raise ValueError(f"unknown cause {cause!r}")
        if c.hidden.plant is not None:  # else a property of the measurement, not of the plant
            p = c.hidden.plant(p, param)
    return p


def _driven(
    u_req: NDArray[np.float64], effects: dict[str, float], params: PlantParams
) -> NDArray[np.float64]:
    """The requests (V) that make the plant put on the motor what the causes acting on the
    input (an entry's ``drive``, not in the plant) make of the applied voltage; ``u_req``
    itself when there is none. The log keeps the applied voltage before them."""
    pieces = [
        (c.drive, v)
        for name, v in effects.items()
        if (c := BY_CAUSE[name]).drive is not None
        and c.hidden is not None
        and c.hidden.plant is None
    ]
    if not pieces:
        return u_req
    applied = np.array([params.u_applied(v) for v in u_req])
    for drive, v in pieces:
        applied = drive(applied, v)
    # the request that gives that voltage once the driver's own drop is taken off
    return np.where(applied != 0.0, np.sign(applied) * (np.abs(applied) + params.v_drop), 0.0)


def _draw(rng: np.random.Generator, cause: str) -> float:
    _, lo, hi = PARAM_RANGES[cause]
    hidden = BY_CAUSE[cause].hidden
    if hidden is not None and hidden.whole:
        return float(rng.integers(int(lo), int(hi) + 1))
    return float(rng.uniform(lo, hi))


def make_log(
    cause: str = "none",
    param: float | None = None,
    seed: int = 0,
    duration: float = 20.0,
    amplitudes: tuple[float, ...] = (2.0, 3.0, 4.0),
    jitter_us: float = 300.0,
    wild: bool = False,
    creep: float = 0.0,
    late_step: bool = False,
    half_period: float = 1.0,
    also: str | None = None,
    also_param: float | None = None,
    touch: bool = False,
) -> SynthLog:
    """A realistic log with ``cause`` hidden in it (param drawn from its range when None),
    and a second effect ``also`` (``also_param`` likewise) when given.

    ``wild``: one count misread by 15-60 counts in a steady stretch; ``creep``: the speed
    creeps up by this fraction (e.g. 0.05) over about a second after each rise; ``late_step``:
    one step's command reaches the motor 30-70 % of a sample period after its sample;
    ``touch``: a hand brakes the wheel for 0.15-0.3 s in a settled driven stretch, with a
    torque that would take 30-60 % of the speed there.
    """
    for c in (cause, also):
        if c is not None and c not in CAUSES:
            raise ValueError(f"unknown cause {c!r}; one of {', '.join(CAUSES)}")
    if also is not None and (also == cause or "none" in (cause, also)):
        raise ValueError("a second effect must be another cause than the first, and not none")
    rng = np.random.default_rng(seed)
    if cause != "none" and param is None:
        param = _draw(rng, cause)
    if also is not None and also_param is None:
        also_param = _draw(rng, also)
    effects: dict[str, float] = {}
    if cause != "none" and param is not None:
        effects[cause] = float(param)
    if also is not None and also_param is not None:
        effects[also] = float(also_param)
    params = plant_with(effects)
    u_req = commands(rng, amplitudes, duration, half_period=half_period)
    u_motor = _driven(u_req, effects, params)
    hand = _touch(rng, u_req, params, half_period) if touch else None
    if hand is not None:
        params = replace(params, touch=hand)
    late_row = None
    if late_step:
        edges = np.flatnonzero(np.diff(u_req) != 0) + 1
        late_row = int(edges[rng.integers(1, max(2, edges.size - 1))])
        frac = float(rng.uniform(0.3, 0.7))
        t, count, omega_true = _sample_late(params, u_motor, seed, jitter_us, late_row, frac)
    else:
        rec = record(params, u_motor, ts=TS, seed=seed, jitter_us=jitter_us)
        t, count, omega_true = rec.t, rec.count, rec.omega_true
    theta = count * (2.0 * math.pi / params.cpr)
    if creep:
        theta = _add_creep(np.asarray(theta, dtype=float), u_req, creep)
        count = np.floor(theta * params.cpr / (2.0 * math.pi) + 1e-9).astype(np.int64)
    wild_row = None
    if wild:
        steady = np.flatnonzero((u_req > 0) & (np.roll(u_req, 10) == u_req))
        steady = steady[(steady > 10) & (steady < u_req.size - 2)]
        wild_row = int(rng.choice(steady))
        count = count.copy()
        count[wild_row] += int(rng.choice([-1, 1]) * rng.integers(15, 61))
    # the speed is an average over a counted cause's length (1: the plain Euler velocity)
    taps = next((int(v) for c, v in effects.items() if BY_CAUSE[c].counted), 1)
    omega = _measured(count, params.cpr, taps)
    u = np.array([params.u_applied(v) for v in u_req])
    return SynthLog(
        t=t,
        u=u,
        omega=omega,
        count=count,
        u_req=u_req,
        omega_true=omega_true,
        cause=cause,
        param=None if param is None else float(param),
        taps=taps,
        wild_row=wild_row,
        late_step_row=late_row,
        creep=creep,
        effects=effects,
        touch=None if hand is None else (hand.start, hand.end),
    )


def _touch(
    rng: np.random.Generator, u_req: NDArray[np.float64], params: PlantParams, half: float
) -> Touch:
    """A hand on the wheel in a driven stretch (not the first): it starts 0.35 s or more
    after the step, lasts 0.15-0.3 s and ends 0.25 s or more before the next step."""
    ups = [int(k) for k in np.flatnonzero(np.diff(u_req) != 0) + 1 if u_req[k] > 0]
    k = ups[int(rng.integers(1, max(2, len(ups) - 1)))]
    length = float(rng.uniform(0.15, 0.30))
    start = k * TS + float(rng.uniform(0.35, max(0.36, half - 0.25 - length)))
    m = params.motor
    drive = m.k_a * params.u_applied(float(u_req[k])) / m.R
    return Touch(start, start + length, float(rng.uniform(0.3, 0.6)) * drive)


def _measured(count: NDArray[np.int64], cpr: int, taps: int) -> NDArray[np.float64]:
    """Euler velocity of the counts with the nominal Ts, averaged over ``taps`` samples, rad/s."""
    theta = count * (2.0 * math.pi / cpr)
    euler = np.zeros(theta.size)
    euler[1:] = np.diff(theta) / TS
    if taps <= 1:
        return euler
    c = np.concatenate(([0.0], np.cumsum(euler)))
    k = np.arange(1, euler.size + 1)
    return (c[k] - c[np.maximum(k - taps, 0)]) / taps


def _add_creep(
    theta: NDArray[np.float64], u_req: NDArray[np.float64], creep: float
) -> NDArray[np.float64]:
    """The angle of a wheel whose speed creeps up by ``creep`` (fraction) after each rise."""
    speed = np.diff(theta, prepend=theta[0])
    since = np.zeros(theta.size)
    for k in range(1, theta.size):
        since[k] = (
            since[k - 1] + 1 if u_req[k - 1] > 0 and u_req[k - 1] == u_req[max(k - 2, 0)] else 0
        )
    extra = creep * (1.0 - np.exp(-since * TS / 0.8)) * (u_req > 0)
    out: NDArray[np.float64] = theta[0] + np.cumsum(speed * (1.0 + extra))
    return out


def _sample_late(
    params: PlantParams,
    u_req: NDArray[np.float64],
    seed: int,
    jitter_us: float,
    late_row: int,
    frac: float,
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.float64]]:
    """As :func:`record`, but the command of sample ``late_row`` arrives ``frac`` Ts late."""
    n = u_req.size
    rng = np.random.default_rng(seed)
    plant = Plant(params, seed=seed)
    lateness = rng.uniform(0.0, jitter_us * 1e-6, n) if jitter_us > 0 else np.zeros(n)
    t = np.floor((np.arange(n) * TS + lateness) * 1e6 / 4.0) * 4 / 1e6
    count = np.empty(n, dtype=np.int64)
    omega = np.empty(n)
    for k in range(n):
        plant.advance(t[k] - plant.t)
        count[k] = plant.count
        omega[k] = plant.omega
        if k == late_row:
            plant.advance(frac * TS)
        plant.set_command(u_req[k])
    return t, count, omega


# -- logs for the identification of K and T (Tasks 10-15) ---------------------------------------

IDENT_LEVELS: tuple[float, ...] = (2.0, 3.0, 4.0)
"""Requested high levels of the identification logs' steps, V."""

IDENT_V_DROP = 0.45
"""The driver's voltage loss in the identification logs, V."""


@dataclass(frozen=True)
class IdentLog:
    """A first-order log for the identification and its truth: T (s) and K (rad/s per V
    of u_A), the plant it came from."""

    log: RunLog
    T: float
    K: float
    params: PlantParams


def identification_table() -> list[Reading]:
    """The exact Task 4-9 table of the identification logs' plant (before T is drawn: J does
    not enter it): u_req at IDENT_LEVELS, u_ss = u_req - IDENT_V_DROP, omega_ss = K u_ss and
    i_ss (mA) from the published motor."""
    m = PUBLISHED
    out = []
    for u in IDENT_LEVELS:
        u_ss = u - IDENT_V_DROP
        out.append(Reading(u, u_ss, m.K * u_ss, (u_ss - m.k_v * m.K * u_ss) / m.R * 1e3))
    return out


def identification_log(
    seed: int,
    ts: float = 0.025,
    T_range: tuple[float, float] = (0.08, 0.3),
    late_us: float = 2000.0,
    on_grid: bool = True,
    stamped: bool = True,
) -> IdentLog:
    """A seeded log as issue 11's side-by-side measures: the published MinSeg with T drawn
    from ``T_range`` (s, through J), no dry friction, braking at zero; 0.2 s at rest, then
    4 rises of 5 T to a level from IDENT_LEVELS and back to 0; the loop late by
    0-``late_us`` us, the command on the board's grid (``on_grid``) or right after the late
    read; the encoder starting anywhere within a count; the Euler speed over the nominal
    ``ts``. ``stamped``: t is the read instants and the log has t_us; else t = k ts."""
    rng = np.random.default_rng(seed)
    T = float(rng.uniform(*T_range))
    motor = replace(PUBLISHED, J=T * PUBLISHED.damping / PUBLISHED.R)
    params = PlantParams(motor=motor, tau_c=0.0, v_drop=IDENT_V_DROP, zero_mode="brake")
    half = max(4, round(5 * T / ts))
    parts = [np.zeros(max(4, round(0.2 / ts)))]
    for _ in range(4):
        parts += [np.full(half, float(rng.choice(IDENT_LEVELS))), np.zeros(half)]
    cmd = np.concatenate(parts)
    rec = record(params, cmd, ts, seed, late_us, command_on_grid=on_grid, encoder_phase=True)
    q = 2.0 * math.pi / params.cpr
    omega = np.concatenate(([0.0], np.diff(rec.count) * q / ts))
    extra: dict[str, NDArray[np.generic]] = {"u_req": cmd}
    if stamped:
        extra["t_us"] = rec.t_us
    t = rec.t if stamped else np.arange(cmd.size, dtype=np.float64) * ts
    log = RunLog(t=t, u=rec.u_A, omega=omega, extra=extra, source="synth")
    return IdentLog(log, T, motor.K, params)


__all__ = [
    "IDENT_LEVELS",
    "IDENT_V_DROP",
    "IdentLog",
    "identification_log",
    "identification_table",
    "CAUSES",
    "PARAM_RANGES",
    "TS",
    "SynthLog",
    "commands",
    "make_log",
    "plant_for",
    "plant_with",
]
