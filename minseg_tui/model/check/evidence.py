"""What the evidence sentences of the causes read off a log, and what a log needs to show
a cause.

Each cause's sentence is in its entry (:mod:`.effects`), every number read off the log in
hand: a sentence about step-downs needs a step-down in the log (:func:`falls`), a stop time
is where the measured speed stands still (:func:`shown_stop`). What a log cannot show is
said too (:class:`Needs`, :func:`cannot_judge`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.guess import rises

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
class Fall:
    """A fall: a step down while the wheel turned and the response after it (as a rise
    follows a rising edge; not the board's STOP). The row of the step, the speed before it
    (rad/s, the mean over the ``rows`` rows before the step), and when the measured speed
    first stood still for good within the stretch (s after the step; None when it still
    turns at the stretch's end)."""

    row: int
    speed: float
    after: float | None
    to_zero: bool
    rows: int


def falls(log: Log) -> list[Fall]:
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
        out.append(Fall(int(a), speed, after, u[a] == 0, rows))
    return out


BEFORE_S = 0.1
"""How far back the speed before a step-down is averaged (s): one-count readings scatter,
and an inferred step instant may fall a sample or two into the fall."""


def _before(log: Log, stretch: int) -> int:
    """Rows to average the speed before a step-down over: BEFORE_S, at most the last quarter of
    a stretch of ``stretch`` rows (the part that has settled), at least 3."""
    return max(3, min(round(BEFORE_S / log.ts), stretch // 4)) if stretch >= 3 else stretch


def before_s(log: Log, s: Fall) -> float:
    """The span (s) the speed before the step-down ``s`` was averaged over."""
    return float(log.t[s.row] - log.t[s.row - s.rows])


def stands_still(s: Fall) -> bool:
    """The wheel stands still within the stretch after the step-down ``s``."""
    return s.after is not None


def drops_to_zero(s: Fall) -> bool:
    """The command drops to zero at the step-down ``s``."""
    return s.to_zero


def shown_stop(log: Log, which: Callable[[Fall], bool] | None) -> Fall | None:
    """The step-down the evidence for a cause speaks of, and the close-up shows: the fastest
    of the step-downs ``which`` accepts (the cause's :attr:`~.effects.Candidate.stop`: for dry
    friction those after which the wheel stands still, for a coast the drops to zero); None
    for a cause shown at a rise (``which`` None), or when the log has no such step-down."""
    if which is None:
        return None
    stops = [s for s in falls(log) if which(s)]
    return max(stops, key=lambda x: abs(x.speed)) if stops else None


Lack = Literal["rise", "drop_to_zero", "two_levels", "one_size"]
"""What a log lacks to show a cause: a step up; a drop to zero while the wheel turns; a
second driven level or a step-down (one level only, or one size of voltage both ways)."""


@dataclass(frozen=True)
class Lacks:
    """What a log lacks to show a cause (``lack``), and for 'one_size' the one size of
    voltage it drives at, forward and reversed (V)."""

    lack: Lack
    size: float = 0.0


@dataclass(frozen=True)
class Needs:
    """What a log must hold for a cause to show in it at all (else it is not tried, and the
    report says why): ``has`` tells, ``lack`` says what is missing; the report lists the
    causes a log cannot show by ``rank``, then in the order they are tried."""

    rank: int
    lack: Lack
    has: Callable[[Log], bool]
    told: Callable[[Log], Lacks] | None = None
    """What is missing in this log's own terms, when one kind would not be true of every
    log."""

    def reason(self, log: Log) -> Lacks:
        """What ``log`` lacks to show the cause."""
        return self.told(log) if self.told is not None else Lacks(self.lack)


NEEDS_RISE = Needs(0, "rise", lambda log: bool(rises(log.u)))
NEEDS_DROP_TO_ZERO = Needs(
    1,
    "drop_to_zero",
    lambda log: any(s.to_zero for s in falls(log)),
)


def _one_size(log: Log) -> Lacks:
    """What a log without two driven levels holds: one level, or one size both ways."""
    if np.any(log.u > 0) and np.any(log.u < 0):
        return Lacks("one_size", float(np.max(np.abs(log.u))))
    return Lacks("two_levels")


NEEDS_TWO_LEVELS = Needs(
    2,
    "two_levels",
    lambda log: bool(falls(log)) or len({round(abs(float(v)), 9) for v in log.u if v != 0}) >= 2,
    _one_size,
)


def cannot_judge(log: Log, needs: Iterable[tuple[str, Needs | None]]) -> dict[str, Lacks]:
    """The causes this log cannot show at all, and why (they are not tried): of ``needs``,
    (cause, what it needs) in the order the causes are tried."""
    out = [(n.rank, i, c, n.reason(log)) for i, (c, n) in enumerate(needs) if n and not n.has(log)]
    return {c: why for _, _, c, why in sorted(out)}
