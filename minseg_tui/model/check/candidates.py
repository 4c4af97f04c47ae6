"""The causes the model check can name, as data.

Each candidate is the first-order model T w' = -w + K u plus one effect with one
parameter; its simulator (exact per constant-input stretch, K = 1) lives in
:mod:`.simulate` and is chosen by :func:`response`. The names are the JSON contract.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.simulate import (
    Stretches,
    first_order_pieces,
    second_pole_pieces,
)

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Candidate:
    """One cause: its contract name, its parameter (name, unit, search bounds) and what it is."""

    cause: str
    param: str
    unit: str
    lo: float
    hi: float
    integer: bool
    meaning: str
    log_scale: bool = False


CANDIDATES: tuple[Candidate, ...] = (
    Candidate(
        "coulomb_friction",
        "u_c",
        "V",
        0.0,
        1.5,
        False,
        "dry friction: the motor needs u_c volts to break away and stops in finite time",
    ),
    Candidate(
        "dead_time",
        "delay",
        "s",
        0.0,
        0.15,
        False,
        "a pure delay between the command and the motor",
    ),
    Candidate(
        "velocity_filter",
        "taps",
        "samples",
        1,
        40,
        True,
        "the measured speed is a moving average of the Euler velocity over N samples",
    ),
    Candidate(
        "coast_on_zero",
        "T_coast",
        "s",
        0.005,
        30.0,
        False,
        "at zero command the bridge is open and the wheel coasts with its own time constant",
        log_scale=True,
    ),
    Candidate(
        "second_pole",
        "T2",
        "s",
        0.0,
        0.12,
        False,
        "an unmodelled extra pole (for instance the armature's L/R) delays the torque",
    ),
)
"""Every cause besides ``none``, in the order they are tried."""

BY_CAUSE: dict[str, Candidate] = {c.cause: c for c in CANDIDATES}

NULL_VALUE: dict[str, float] = {
    "coulomb_friction": 0.0,
    "dead_time": 0.0,
    "velocity_filter": 1.0,
    "coast_on_zero": float("inf"),
    "second_pole": 0.0,
}
"""The parameter value at which each candidate is exactly the first-order model
(coast_on_zero reduces to it only when T_coast equals T; infinity marks "no value")."""


@dataclass(frozen=True)
class Effects:
    """A combination of effects (None / 0 / 1 = absent). Units: V, s, samples."""

    u_c: float = 0.0
    delay: float = 0.0
    taps: int = 1
    T_coast: float | None = None
    T2: float = 0.0

    @classmethod
    def of(cls, params: dict[str, float]) -> Effects:
        """From a {param name: value} mapping (candidate parameter names)."""
        kw: dict[str, float | int | None] = {}
        for name, value in params.items():
            kw[name] = int(round(value)) if name == "taps" else float(value)
        return cls(**kw)  # type: ignore[arg-type]


def angle(
    st: Stretches, t: FloatArray, T: float, fx: Effects, z0: float | None = 0.0
) -> FloatArray:
    """Angle at the instants ``t`` (s) for the first-order model with the effects ``fx`` (K = 1).

    ``z0`` is the initial speed (K = 1 units, V); None means steady state under the first
    input. The second pole cannot be combined with dry friction or coasting (no closed form here);
    it wins over them when both are asked for.
    """
    if z0 is None:  # in steady state under the first input when the log starts
        u0 = float(st.value[0])
        z0 = u0 - np.sign(u0) * min(fx.u_c, abs(u0))
    if fx.T2 > 0:
        pieces = second_pole_pieces(st, T, fx.T2, z0)
    else:
        # coasting is never faster than braking (T_coast = J/f > R J/(R f + k_v k_a) = T)
        tc = None if fx.T_coast is None else max(fx.T_coast, T)
        pieces = first_order_pieces(st, T, z0, u_c=fx.u_c, T_coast=tc)
    return pieces.angle(t - fx.delay)


def response(
    st: Stretches, t: FloatArray, ts: float, T: float, fx: Effects, z0: float | None = 0.0
) -> FloatArray:
    """The measured speed the model predicts on every row (K = 1), as the board measures it.

    The angle is also taken ``taps`` nominal periods before the first row, so a log that
    starts moving has the right speed on its first rows (0 for a log that starts at rest).
    """
    n = fx.taps
    before = t[0] - ts * np.arange(n, 0, -1)
    theta = angle(st, np.concatenate((before, t)), T, fx, z0)
    return (theta[n:] - theta[:-n]) / (n * ts)
