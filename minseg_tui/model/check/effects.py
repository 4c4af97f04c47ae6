"""The causes the model check can name, as data.

Each cause is one effect with one parameter on top of the first-order model
T w' = -w + K u; several can act at once (their simulation is :mod:`.simulate`). The
names and the parameter names are the JSON contract. The search range of a parameter
depends on the log (its steps, levels and time constant) and is worked out by
:func:`ranges`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.simulate import Effects

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Candidate:
    """One cause: contract name, its parameter (contract name, unit), the field of
    :class:`Effects` it sets, the value at which it is absent, and what it is."""

    cause: str
    param: str
    unit: str
    field: str
    null: float
    meaning: str
    log_scale: bool = False
    label: str = ""
    """The cause in a few words for people (the contract name is for programs)."""


CANDIDATES: tuple[Candidate, ...] = (
    Candidate(
        "coulomb_friction",
        "u_c",
        "V",
        "u_c",
        0.0,
        "dry friction: the motor needs u_c volts to break away, and a wheel left to itself stops "
        "in finite time",
        label="dry friction",
    ),
    Candidate(
        "dead_time",
        "delay",
        "s",
        "delay",
        0.0,
        "a pure delay between command and motor",
        label="dead time",
    ),
    Candidate(
        "velocity_filter",
        "taps",
        "samples",
        "taps",
        1.0,
        "the measured speed is a moving average of the Euler velocity over N samples",
        label="averaged speed (velocity filter)",
    ),
    Candidate(
        "coast_on_zero",
        "T_coast",
        "s",
        "T_coast",
        math.inf,
        "at zero command the bridge is open and the wheel coasts with its own time constant",
        log_scale=True,
        label="coasting at zero command",
    ),
    Candidate(
        "second_pole",
        "T2",
        "s",
        "T2",
        0.0,
        "an extra pole delays the torque (the armature's L/R, a driver's own lag) or lags the "
        "reading (a compliant coupling to the encoder, a first-order filter of the speed)",
        label="second pole",
    ),
    Candidate(
        "current_limit",
        "a_max",
        "rad/s^2",
        "rate",
        math.inf,
        "the drive caps the current, so the speed ramps at a_max (less what the wheel's own "
        "drag takes as it speeds up) until the back-EMF takes over (on some drives braking "
        "after a step down is capped too)",
        log_scale=True,
        label="current limit",
    ),
)
"""Every cause besides ``none``, in the order they are tried."""

BY_CAUSE: dict[str, Candidate] = {c.cause: c for c in CANDIDATES}

NAMES: tuple[str, ...] = tuple(c.cause for c in CANDIDATES)


def in_words(model: str) -> str:
    """A model or cause name in words: "first_order+coulomb_friction" -> "first order + dry
    friction"; ``none`` stays "none"."""
    return " + ".join(
        "first order" if p == "first_order" else (BY_CAUSE[p].label if p in BY_CAUSE else p)
        for p in model.split("+")
    )


UNITS: dict[str, str] = {"T": "s", "K": "rad/s/V", **{c.param: c.unit for c in CANDIDATES}}
"""Unit of every parameter a model reports."""


def effects_of(values: dict[str, float]) -> Effects:
    """Effects from {cause: value of its Effects field} (taps rounded)."""
    kw: dict[str, float | int] = {}
    for cause, value in values.items():
        f = BY_CAUSE[cause].field
        kw[f] = int(round(value)) if f == "taps" else float(value)
    return Effects(**kw)  # type: ignore[arg-type]


def field_value(fx: Effects, cause: str) -> float:
    """The value of the Effects field behind ``cause`` (the null value when absent)."""
    v = getattr(fx, BY_CAUSE[cause].field)
    return BY_CAUSE[cause].null if v is None else float(v)


def reported(cause: str, value: float, K: float) -> float:
    """The contract parameter of ``cause`` from its Effects field: a_max = |K| rate (rad/s^2);
    the others are the field itself."""
    return abs(K) * value if cause == "current_limit" else value


@dataclass(frozen=True)
class Range:
    """Search range of one cause's Effects field on this log (lo, hi), and its scale."""

    lo: float
    hi: float
    log_scale: bool


def ranges(t: FloatArray, u: FloatArray, ts: float, T: float) -> dict[str, Range]:
    """The search range of every cause on this log: u (V) at t (s), nominal period ts (s),
    first-order time constant T (s).

    u_c: up to the smallest level the log drives at; delay: up to 0.8 of the shortest stretch
    of constant input that follows a step; taps: up to 40 and the longest such stretch (an
    average longer than a short stretch still shows, as a ramp cut off by the next step); T_coast:
    from T to 30 s; T2: up to 3 T; rate (V/s): from 1/1000 of the largest step over T/10
    (beyond, the cap never holds).
    """
    levels = np.abs(u[u != 0])
    u_min = float(np.min(levels)) if levels.size else 1.0
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate((change, [u.size]))
    ends = np.append(t, t[-1] + ts)
    lengths = [float(ends[b] - t[a]) for a, b in zip(bounds[:-1], bounds[1:], strict=True)]
    inner = lengths[:-1] if len(lengths) > 1 else lengths  # the last one may be cut short
    shortest = min(inner) if inner else float(t[-1] - t[0])
    longest = max(inner) if inner else float(t[-1] - t[0])
    rows_long = max(2, int(round(longest / ts)))
    jump = float(np.max(np.abs(np.diff(u)))) if u.size > 1 else 1.0
    jump = max(jump, float(np.max(np.abs(u))), 1e-9)
    rate_hi = jump / (0.1 * T)
    return {
        "coulomb_friction": Range(0.0, 0.98 * u_min, False),
        "dead_time": Range(0.0, max(0.8 * shortest, 3.0 * ts), False),
        "velocity_filter": Range(1.0, float(min(40, rows_long)), False),
        "coast_on_zero": Range(max(0.5 * T, 0.002), 30.0, True),
        "second_pole": Range(0.0, 3.0 * T, False),
        "current_limit": Range(rate_hi / 1000.0, rate_hi, True),
    }
