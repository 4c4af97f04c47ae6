"""The evidence for a finding, in words, every number read off the log in hand.

A sentence about step-downs needs a step-down in the log; a stop time is where the
measured speed stands still; coast words are only for a coast; a slope or a lag is
measured on the rises. What a log cannot show is said too (:func:`cannot_judge`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.guess import first_motion, levels_offset, rises, steepest_rate

if TYPE_CHECKING:  # the causes' words are registered with them (effects), which fit imports
    from minseg_tui.model.check.fit import Fit

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Log:
    """What the sentences are computed from: t (s), u (V), y the measured speed (rad/s, wild
    samples repaired), ts (s), noise: the speed's scatter (rad/s), zero: the largest speed
    that reads as standing still (rad/s), base_pred: the first-order model's speed (rad/s),
    smooth: the speed is a smooth signal, not a difference of counts; step: the step
    (rad/s) the speed's values come in when read off the data (None: not read off)."""

    t: FloatArray
    u: FloatArray
    y: FloatArray
    ts: float
    noise: float
    zero: float
    base_pred: FloatArray
    smooth: bool = False
    step: float | None = None


@dataclass(frozen=True)
class Stop:
    """A step down while the wheel turned: the row of the step, the speed before it (rad/s,
    the mean over the ``rows`` rows before the step), and when the measured speed first stood
    still for good within the stretch (s after the step; None when it still turns at the
    stretch's end)."""

    row: int
    speed: float
    after: float | None
    to_zero: bool
    rows: int


def falls(log: Log) -> list[Stop]:
    """Every step that lowers |u| while the wheel turns, and when the wheel stood still."""
    u, y, t = log.u, log.y, log.t
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate((change, [u.size]))
    out = []
    starts = np.concatenate(([0], change))
    for start, a, b in zip(starts[:-1], bounds[:-1], bounds[1:], strict=True):
        if abs(u[a]) >= abs(u[a - 1]):
            continue
        rows = _before(log, a - int(start))
        speed = float(np.mean(y[a - rows : a]))
        if abs(speed) <= max(log.zero, 3.0 * log.noise):
            continue
        still = np.abs(y[a:b]) <= log.zero
        # first row from which it stays still (at least 3 rows, to the end of the stretch)
        after = None
        run = np.flatnonzero(~still)
        last_moving = int(run[-1]) if run.size else -1
        if last_moving < b - a - 3:
            after = float(t[a + last_moving + 1] - t[a])
        out.append(Stop(int(a), speed, after, u[a] == 0, rows))
    return out


BEFORE_S = 0.1
"""How far back the speed before a step-down is averaged (s): one-count readings scatter,
and an inferred step instant may fall a sample or two into the fall."""


def _before(log: Log, stretch: int) -> int:
    """Rows to average the speed before a step-down over: BEFORE_S, at most the last quarter of
    a stretch of ``stretch`` rows (the part that has settled), at least 3."""
    return max(3, min(round(BEFORE_S / log.ts), stretch // 4)) if stretch >= 3 else stretch


def _before_s(log: Log, s: Stop) -> float:
    """The span (s) the speed before the step-down ``s`` was averaged over."""
    return float(log.t[s.row] - log.t[s.row - s.rows])


def ms(x: float) -> str:
    return f"{x * 1e3:.0f} ms"


def stands_still(s: Stop) -> bool:
    """The wheel stands still within the stretch after the step-down ``s``."""
    return s.after is not None


def drops_to_zero(s: Stop) -> bool:
    """The command drops to zero at the step-down ``s``."""
    return s.to_zero


def shown_stop(log: Log, which: Callable[[Stop], bool] | None) -> Stop | None:
    """The step-down the evidence for a cause speaks of, and the close-up shows: the fastest
    of the step-downs ``which`` accepts (the cause's :attr:`~.effects.Candidate.stop`: for dry
    friction those after which the wheel stands still, for a coast the drops to zero); None
    for a cause shown at a rise (``which`` None), or when the log has no such step-down."""
    if which is None:
        return None
    stops = [s for s in falls(log) if which(s)]
    return max(stops, key=lambda x: abs(x.speed)) if stops else None


def coulomb_words(log: Log, ext: Fit) -> str:
    uc = ext.params["u_c"]
    shown = shown_stop(log, stands_still)
    coast = "coast_on_zero" in ext.causes
    if shown is not None:
        s = shown
        after = s.after if s.after is not None else 0.0
        k = int(np.searchsorted(log.t, log.t[s.row] + after))
        k = min(k, log.t.size - 1)
        left = abs(float(log.base_pred[k]))
        how = "coasts and " if coast else ""
        text = (
            f"after the drive drops at t = {log.t[s.row]:.3f} s the wheel {how}stands still "
            f"{ms(after)} later (measured, from {abs(s.speed):.3g} rad/s, its mean over the "
            f"{ms(_before_s(log, s))} before the drop)"
        )
        if left > max(log.zero, 2.0 * log.noise):
            text += f", where the first-order model still turns at {left:.2f} rad/s"
        return text + f": dry friction stops a wheel in finite time (u_c = {uc:.3g} V)"
    off = levels_offset(log.u, log.y, ext.T, log.ts)
    text = (
        "the settled speeds are not proportional to the voltage"
        + (f": a straight line through them meets zero speed at {off:.2f} V" if off else "")
        + f"; dry friction with u_c = {uc:.3g} V does that (a voltage lost in the brushes or "
        "the driver looks the same in steady state)"
    )
    if not falls(log):
        text += "; the log has no step-down, so a finite stop cannot be seen"
    return text


def dead_time_words(log: Log, ext: Fit) -> str:
    d = ext.params["delay"]
    lags = first_motion(log.t, log.u, log.y, log.noise)
    seen = (
        f"after the step{'s' if len(lags) > 1 else ''} the measured speed first moves "
        f"{ms(float(np.median(lags)))} later"
        if lags
        else "the response starts late"
    )
    return (
        f"{seen}: a first-order response that starts {ms(d)} after the command fits "
        f"(a pure delay; an extra pole would start at once, only more slowly)"
    )


def filter_words(log: Log, ext: Fit, floor: float | None) -> str:
    n = int(ext.params["taps"])
    edges = int(np.count_nonzero(np.diff(log.u)))
    which = "every edge becomes" if edges > 1 else "the step becomes"
    ramp = f"{which} a ramp about {n} samples ({ms(n * log.ts)}) long"
    if log.smooth:
        return (
            f"{'the rises are' if edges > 1 else 'the rise is'} smoothed as an average of the "
            f"speed over {n} samples ({ms(n * log.ts)}) would smooth it; an extra pole in the "
            "motor would look alike in this smooth signal"
        )
    if floor is not None:
        return (
            f"the speed scatters only {log.noise:.3g} rad/s where one count per sample alone "
            f"gives a noise floor of {floor:.3g} rad/s, and {ramp}: the speed is an average "
            f"over {n} samples, which divides the encoder noise by {n}"
        )
    if log.step is not None:
        return (
            f"the speed's values come in steps of only {log.step:.3g} rad/s and it scatters "
            f"{log.noise:.3g} rad/s, and {ramp}: the speed is an average over {n} samples"
        )
    return f"{ramp}: the speed looks averaged over {n} samples"


def coast_words(log: Log, ext: Fit) -> str:
    tc = ext.params["T_coast"]
    s = shown_stop(log, drops_to_zero)
    if s is None:
        return f"the wheel runs down slowly at zero command (time constant {tc:.3g} s)"
    decel, span = _fall_rate(log, s)
    a, w0 = s.row, abs(s.speed)
    return (
        f"right after the command drops to 0 at t = {log.t[a]:.3f} s the speed falls at "
        f"{decel:.3g} rad/s^2 (a line through the speed from the row before the drop to the "
        f"first reading under half, {ms(span - float(log.t[a] - log.t[a - 1]))} after the "
        f"drop), where a braked motor (T = "
        f"{ms(ext.T)}) would fall at {w0 / ext.T:.3g} rad/s^2 at first: the bridge lets the "
        f"wheel coast, with a time constant of {tc:.3g} s at zero command"
    )


FALL_TO = 0.5
"""The share of the speed before a step-down that the fall rate is measured down to: far
enough that one-count readings (20 % of a slow wheel's speed) do not set the rate."""


def _fall_rate(log: Log, s: Stop) -> tuple[float, float]:
    """How fast the speed falls after the step-down ``s`` (rad/s^2, the slope of a straight
    line through the speed before it and the readings until the first under FALL_TO of it,
    40 at most) and the span that covers (s, from the row before the step)."""
    a, w0 = s.row, abs(s.speed)
    seg = np.abs(log.y[a : a + 40])
    below = np.flatnonzero(seg < FALL_TO * w0)
    n = min(max(int(below[0]) + 1 if below.size else seg.size, 2), seg.size)
    tt = log.t[a - 1 : a + n] - log.t[a - 1]
    slope = float(np.polyfit(tt, np.concatenate(([w0], seg[:n])), 1)[0]) if tt[-1] > 0 else 0.0
    return -slope, float(tt[-1])


def pole_words(log: Log, ext: Fit) -> str:
    t2 = ext.params["T2"]
    w = max(2, int(math.ceil(max(t2, ext.T / 2) / log.ts)))
    got, model = [], []
    for a, b in rises(log.u):
        if b - a <= w:
            continue
        got.append(abs(float(log.y[a + w - 1] - log.y[a - 1])))
        model.append(abs(float(log.base_pred[a + w - 1] - log.base_pred[a - 1])))
    text = "each rise starts with zero slope (an S-shaped start)"
    if log.smooth:
        text += " (in this smooth signal an average of the speed would look alike)"
    if got:
        text += (
            f": {ms(w * log.ts)} after the step the speed has risen {np.median(got):.3g} rad/s "
            f"where the first-order model rises {np.median(model):.3g} rad/s"
        )
    if ext.effects.pole_measured:
        where = [
            w
            for c, w in (
                ("coulomb_friction", "the wheel stops"),
                ("coast_on_zero", "it coasts"),
                ("current_limit", "the cap holds"),
            )
            if c in ext.causes
        ]
        return text + (
            f"; an extra pole of {ms(t2)} on the measurement (a compliant coupling to the "
            "encoder, or a first-order filter of the speed) lags what the encoder reads: on "
            f"the drive it fits worse where {' and where '.join(where) or 'the effects act'} "
            "(a pure delay would show a corner)"
        )
    return (
        text + f"; an extra pole of {ms(t2)} delays the torque (a pure delay would show a corner)"
    )


def limit_words(log: Log, ext: Fit) -> str:
    a = ext.params["a_max"]
    r = steepest_rate(log.t, log.u, log.y, 1.0)
    seen = f"the speed ramps at about {r:.3g} rad/s^2" if r else "the speed ramps"
    ups = rises(log.u)
    top = ""
    if ups:
        k, _ = ups[0]
        jump = abs(float(log.u[k] - log.u[k - 1]))
        top = (
            f"; the same motor without a cap would start at K u/T = "
            f"{abs(ext.K) * jump / ext.T:.3g} rad/s^2, steepest at once"
        )
    both = (
        " both ways (braking after a step down is capped too: the speed falls along a ramp "
        "as well, which a cap on accelerating alone does not fit as well)"
        if ext.effects.cap_both
        else ""
    )
    return (
        f"{seen} (the mean slope between 20 % and 70 % of the rise, measured) and then bends "
        f"into the plateau{top}: the drive caps the current{both}, a_max = {a:.3g} rad/s^2"
    )


@dataclass(frozen=True)
class Needs:
    """What a log must hold for a cause to show in it at all (else it is not tried, and the
    report says why): ``has`` tells, ``why`` says what is missing; the report lists the
    causes a log cannot show by ``rank``, then in the order they are tried."""

    rank: int
    why: str
    has: Callable[[Log], bool]


NEEDS_RISE = Needs(0, "the log has no step up to show it", lambda log: bool(rises(log.u)))
NEEDS_DROP_TO_ZERO = Needs(
    1,
    "the command never drops to zero while the wheel turns",
    lambda log: any(s.to_zero for s in falls(log)),
)
NEEDS_TWO_LEVELS = Needs(
    2,
    "the log has one driven level and no step-down",
    lambda log: bool(falls(log)) or len({round(abs(float(v)), 9) for v in log.u if v != 0}) >= 2,
)


def cannot_judge(log: Log, needs: Iterable[tuple[str, Needs | None]]) -> dict[str, str]:
    """The causes this log cannot show at all, and why (they are not tried): of ``needs``,
    (cause, what it needs) in the order the causes are tried."""
    out = [(n.rank, i, c, n.why) for i, (c, n) in enumerate(needs) if n and not n.has(log)]
    return {c: why for _, _, c, why in sorted(out)}
