"""A small seeded generator of run logs for identify, written from the physics alone (not from
minseg_tui.model.synth or the check's simulator): a first-order motor T w' = -w + K u(t - D)
driven by a held command, its angle read by a 720-count encoder late by a busy loop, and the
speed the lab's Euler derivative of the counts over the nominal period. On top of that the
artefacts real logs have: a dead time D, switch-on glitch rows at the start, and a logging stall
after which the encoder value lags its timestamp.

The motor is linear, so the angle is the sum of the responses to each change of the command:
a change of dU volts acting from tau on adds K dU ((t - tau) - T (1 - exp(-(t - tau)/T))) rad.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.identify import Reading
from minseg_tui.model.runlog import RunLog

CPR = 720
Q = 2.0 * math.pi / CPR
V_DROP = 0.45
"""The driver's drop (V): u_A = u_req - V_DROP while driven."""

LEVELS = (2.0, 3.0, 4.0)


@dataclass(frozen=True)
class Generated:
    """A log and its truth: T (s), K (rad/s per V of u_A), the dead time D (s), the sample
    period ts (s), the glitch rows and the stall row (None without)."""

    log: RunLog
    T: float
    K: float
    D: float
    ts: float
    glitch_rows: tuple[int, ...]
    stall_row: int | None


def table(K: float = 10.0) -> list[Reading]:
    """The exact table for these logs: u_ss = u_req - V_DROP at each level, omega_ss = K u_ss
    (``K`` rad/s per V, the log's for a table that agrees with it) and a plausible i_ss (mA).
    K of Task 11 divides by u_ss only."""
    return [Reading(v, v - V_DROP, K * (v - V_DROP), 40.0 + 5.0 * v) for v in LEVELS]


def angle(
    t: NDArray[np.float64], changes: list[tuple[float, float]], T: float, K: float
) -> NDArray[np.float64]:
    """The motor's angle (rad) at times ``t`` (s) for command changes (instant s, dU V)."""
    th = np.zeros_like(t)
    for tau, du in changes:
        s = np.maximum(t - tau, 0.0)
        th += K * du * (s + T * np.expm1(-s / T))
    return th


def make(
    seed: int,
    ts: float = 0.025,
    T_range: tuple[float, float] = (0.06, 0.3),
    delay: float = 0.0,
    glitch: int = 0,
    stall: bool = False,
    late_us: float = 2000.0,
    stamped: bool = False,
    periods: int = 4,
    rest_rows: int | None = None,
    K: float | None = None,
) -> Generated:
    """One seeded log: rest, then four periods of a rising step to 2, 3 or 4 V (u_req) and back
    to 0 V, each half period 6 T long (at least 8 samples). ``delay``: dead time (s);
    ``glitch``: that many switch-on glitch rows at the start (speeds above the steady speed);
    ``stall``: one logging stall of 3-6 samples during a rise, after which the encoder value is
    read 0.3-0.8 sample periods before the row's timestamp; ``stamped``: add t_us; ``K``: the
    gain (rad/s per V) in place of the drawn one (the rest of the draw unchanged)."""
    rng = np.random.default_rng(seed)
    T = float(math.exp(rng.uniform(math.log(T_range[0]), math.log(T_range[1]))))
    drawn = float(rng.uniform(8.0, 16.0))
    K = drawn if K is None else K
    half = max(8, int(math.ceil(6.0 * T / ts)))
    rest = max(8, half // 2) if rest_rows is None else rest_rows
    cmd = [np.zeros(rest)]
    for _ in range(periods):
        cmd += [np.full(half, float(rng.choice(LEVELS))), np.zeros(half)]
    u_req = np.concatenate(cmd)
    n = u_req.size
    late = rng.uniform(0.0, late_us * 1e-6, n)
    t_read = np.arange(n) * ts + late  # when each count is read
    u_a = np.where(u_req > 0, u_req - V_DROP, 0.0)
    # this firmware sets the output right after the read: row k's command acts from t_read[k]
    change = np.flatnonzero(np.diff(np.concatenate(([0.0], u_a))))
    changes = [
        (float(t_read[k]) + delay, float(u_a[k] - (u_a[k - 1] if k else 0.0))) for k in change
    ]
    t_enc = t_read.copy()
    stall_row = None
    keep = np.ones(n, dtype=bool)
    if stall:
        first_rise = rest + int(rng.integers(0, periods)) * 2 * half
        k0 = first_rise + int(rng.integers(1, max(2, min(half - 8, int(2 * T / ts)))))
        gap = int(rng.integers(3, 7))
        keep[k0 : k0 + gap - 1] = False  # the loop stalled: those samples were never logged
        stall_row = k0 + gap - 1
        t_enc[stall_row] -= float(rng.uniform(0.3, 0.8)) * ts  # the count is older than its time
    phase = float(rng.uniform(0.0, 1.0))
    count = np.floor(angle(t_enc, changes, T, K) / Q + phase).astype(np.int64)
    rows = np.flatnonzero(keep)
    count, u_req, u_a, t_read = count[rows], u_req[rows], u_a[rows], t_read[rows]
    omega = np.concatenate(([0.0], np.diff(count) * Q / ts))  # the lab's Euler over Ts
    glitch_rows = tuple(range(glitch))
    top = K * (max(LEVELS) - V_DROP)
    for k in glitch_rows:
        omega[k] = float(rng.uniform(1.15, 2.0)) * top
    t = np.round(np.arange(n)[rows] * ts, 6)
    extra: dict[str, NDArray[np.generic]] = {"u_req": u_req}
    if stamped:
        extra["t_us"] = np.round(t_read * 1e6).astype(np.int64)
    log = RunLog(t=t, u=u_a, omega=omega, extra=extra, source=f"identgen seed {seed}")
    if stall_row is not None:
        stall_row = int(np.searchsorted(rows, stall_row))
    return Generated(log, T, K, delay, ts, glitch_rows, stall_row)
